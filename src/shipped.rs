//! The shipped configuration, embedded in the binary: the reference cell's rig, cell file, robot
//! URDF, the trusted approvers' files (trusting no one), the three class trajectories and their locks, as they were in the repository at build time.
//!
//! They are the defaults of the commands that need a cell (`ergocell demo`), so the binary works
//! from any directory and after `cargo install --path .`. An explicit path always wins, and a
//! missing explicit path is an error (never a silent fall-back to these). Approvals are never
//! shipped: a safety engineer signs a lock off on site.

/// `(path relative to the repository root, contents)`.
pub const FILES: &[(&str, &str)] = &[
    ("config/rig.toml", include_str!("../config/rig.toml")),
    ("config/cell.toml", include_str!("../config/cell.toml")),
    (
        "config/robots/iiwa14_r820.urdf",
        include_str!("../config/robots/iiwa14_r820.urdf"),
    ),
    (
        "config/approvers/allowed_signers",
        include_str!("../config/approvers/allowed_signers"),
    ),
    (
        "config/approvers/revoked_keys",
        include_str!("../config/approvers/revoked_keys"),
    ),
    (
        "trajectories/c1.toml",
        include_str!("../trajectories/c1.toml"),
    ),
    (
        "trajectories/c2.toml",
        include_str!("../trajectories/c2.toml"),
    ),
    (
        "trajectories/c3.toml",
        include_str!("../trajectories/c3.toml"),
    ),
    (
        "trajectories/locks/c1.lock.toml",
        include_str!("../trajectories/locks/c1.lock.toml"),
    ),
    (
        "trajectories/locks/c2.lock.toml",
        include_str!("../trajectories/locks/c2.lock.toml"),
    ),
    (
        "trajectories/locks/c3.lock.toml",
        include_str!("../trajectories/locks/c3.lock.toml"),
    ),
];

/// The shipped rig file's path (as named in messages).
pub const RIG: &str = "config/rig.toml";
/// The shipped cell file's path.
pub const CELL: &str = "config/cell.toml";
/// The shipped trajectories folder.
pub const TRAJECTORIES: &str = "trajectories";

/// The shipped file at `path` (relative, `/`-separated after normalising `.` and `\`), if any.
pub fn file(path: &std::path::Path) -> Option<&'static str> {
    let parts: Vec<String> = path
        .components()
        .filter_map(|c| match c {
            std::path::Component::Normal(s) => Some(s.to_string_lossy().into_owned()),
            _ => None,
        })
        .collect();
    let key = parts.join("/");
    FILES.iter().find(|(p, _)| *p == key).map(|(_, text)| *text)
}

/// How a command names a shipped file in its messages.
pub fn label(path: &str) -> String {
    format!("{path} (shipped in the binary)")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_file_is_found_by_its_path_and_the_urdf_by_the_cells_reference() {
        for (p, text) in FILES {
            assert_eq!(file(std::path::Path::new(p)), Some(*text));
        }
        let urdf = std::path::Path::new(CELL)
            .parent()
            .map(|d| d.join("robots/iiwa14_r820.urdf"));
        assert!(urdf.and_then(|p| file(&p)).is_some());
        assert!(file(std::path::Path::new("config/nothing.toml")).is_none());
    }
}
