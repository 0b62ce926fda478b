//! The shipped configuration, embedded in the binary: the reference cell's rig, cell file, robot
//! URDF, the trusted approvers' files (trusting no one), the three class trajectories, their locks and
//! the classes' handover RULA curves, as they were in the repository at build time.
//!
//! They are the defaults of the commands that need a cell (`ergocell demo` always; `run`, `replay`,
//! `security`, `sim`, `rula` and `height` when their default path is not in the working directory,
//! with a note on stderr), so the binary works from any directory and after `cargo install --path .`.
//! A file that exists is always the one read, and a path that names no shipped file is an error when
//! missing (never a silent fall-back). Approvals are never shipped: a safety engineer signs a lock
//! off on site.

/// `(path relative to the repository root, contents)`.
pub const FILES: &[(&str, &str)] = &[
    ("config/rig.toml", include_str!("../../config/rig.toml")),
    ("config/cell.toml", include_str!("../../config/cell.toml")),
    (
        "config/robots/iiwa14_r820.urdf",
        include_str!("../../config/robots/iiwa14_r820.urdf"),
    ),
    (
        "config/approvers/allowed_signers",
        include_str!("../../config/approvers/allowed_signers"),
    ),
    (
        "config/approvers/revoked_keys",
        include_str!("../../config/approvers/revoked_keys"),
    ),
    (
        "trajectories/c1.toml",
        include_str!("../../trajectories/c1.toml"),
    ),
    (
        "trajectories/c2.toml",
        include_str!("../../trajectories/c2.toml"),
    ),
    (
        "trajectories/c3.toml",
        include_str!("../../trajectories/c3.toml"),
    ),
    (
        "trajectories/handover_rula.toml",
        include_str!("../../trajectories/handover_rula.toml"),
    ),
    (
        "trajectories/locks/c1.lock.toml",
        include_str!("../../trajectories/locks/c1.lock.toml"),
    ),
    (
        "trajectories/locks/c2.lock.toml",
        include_str!("../../trajectories/locks/c2.lock.toml"),
    ),
    (
        "trajectories/locks/c3.lock.toml",
        include_str!("../../trajectories/locks/c3.lock.toml"),
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

/// Whether `path` falls back to the shipped file of that name: relative, absent from the working
/// directory, and shipped. This is how a command's default (`config/cell.toml`, `config/rig.toml`,
/// `trajectories`) works from any directory; a path that exists is always the one read.
pub fn falls_back(path: &std::path::Path) -> bool {
    path.is_relative() && !path.exists() && file(path).is_some()
}

/// Whether the folder `dir` falls back to the shipped trajectories (relative, absent, and the
/// shipped folder's name).
pub fn dir_falls_back(dir: &std::path::Path) -> bool {
    dir.is_relative() && !dir.exists() && file(&dir.join("c1.toml")).is_some()
}

/// A command's input file: the file at `path`, or when [`falls_back`] the shipped one (and a note on
/// stderr says so). Returns the text and the name to use in messages.
pub fn read_or_shipped(
    path: &std::path::Path,
) -> Result<(String, String), crate::input::InputError> {
    if let Some(text) = file(path).filter(|_| falls_back(path)) {
        eprintln!(
            "note: {} is not in {}: using the one shipped in the binary",
            path.display(),
            working_dir()
        );
        return Ok((text.to_owned(), label(&path.display().to_string())));
    }
    let text = crate::input::read_text(path, crate::input::Kind::Config)?;
    Ok((text, path.display().to_string()))
}

/// The working directory, as messages name it.
pub fn working_dir() -> String {
    std::env::current_dir().map_or_else(
        |_| "the working directory".to_owned(),
        |d| d.display().to_string(),
    )
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
