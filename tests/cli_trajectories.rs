//! `ergocell trajectories` end to end on a copy of the shipped cell in a temp dir: validate, lock,
//! verify (fails until approved, naming what is missing), approve, verify, then a one-byte edit of the
//! trajectory file makes verify fail.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let dest = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_dir(&path, &dest);
        } else {
            std::fs::copy(&path, &dest).unwrap();
        }
    }
}

/// A fresh cell: `config/` and the trajectory files (no locks, no approvals).
fn fresh_cell(name: &str) -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    copy_dir(&root.join("config"), &dir.join("config"));
    std::fs::create_dir_all(dir.join("trajectories")).unwrap();
    for class in ["c1", "c2", "c3"] {
        std::fs::copy(
            root.join(format!("trajectories/{class}.toml")),
            dir.join(format!("trajectories/{class}.toml")),
        )
        .unwrap();
    }
    dir
}

fn ergocell(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn validate_lock_approve_verify_and_a_one_byte_edit_fails_verify() {
    let dir = fresh_cell("trajectories_workflow");

    let (code, out, _) = ergocell(&dir, &["trajectories", "validate", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("class c2 — ACCEPTED") && out.contains("status Solved"),
        "{out}"
    );

    let (code, out, _) = ergocell(&dir, &["trajectories", "validate", "--json"]);
    assert_eq!(code, 0);
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json.as_array().unwrap().len(), 3);
    assert_eq!(json[1]["report"]["qp"]["status"], "Solved");

    // Verify before lock: fails, naming the missing lock.
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1);
    assert!(out.contains("no lock file"), "{out}");

    let (code, out, err) = ergocell(&dir, &["trajectories", "lock"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(dir.join("trajectories/locks/c2.lock.toml").exists());

    // Locked but not approved: verify fails and says what is missing; --allow-unapproved passes.
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify"]);
    assert_eq!(code, 1);
    assert!(
        out.contains("no approval for lock sha256") && out.contains("approve --class c1"),
        "{out}"
    );
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--allow-unapproved"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("NOT APPROVED"));

    let (code, out, err) = ergocell(
        &dir,
        &[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--by",
            "Test Engineer",
        ],
    );
    assert_eq!(code, 0, "{out}{err}");
    let approvals = std::fs::read_to_string(dir.join("trajectories/approvals/c2.toml")).unwrap();
    assert!(approvals.contains("approved_by = \"Test Engineer\""));
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("c2: OK") && out.contains("Test Engineer"),
        "{out}"
    );

    // One byte of the trajectory file: verify fails and names the file.
    let path = dir.join("trajectories/c2.toml");
    let mut bytes = std::fs::read(&path).unwrap();
    let at = bytes.iter().position(u8::is_ascii_digit).unwrap();
    bytes[at] = if bytes[at] == b'9' {
        b'8'
    } else {
        bytes[at] + 1
    };
    std::fs::write(&path, &bytes).unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("trajectory file trajectories/c2.toml changed"),
        "{out}"
    );

    // An edited trajectory cannot be approved either.
    let (code, _, err) = ergocell(
        &dir,
        &["trajectories", "approve", "--class", "c2", "--by", "X"],
    );
    assert_eq!(code, 1);
    assert!(err.contains("refusing to approve"), "{err}");
}

/// A lock whose samples were edited and whose `lock_sha256` was recomputed agrees with every hash, but
/// it does not hold what validation produces: it can be neither approved nor verified.
#[test]
fn a_hand_edited_and_rehashed_lock_is_neither_approved_nor_verified() {
    use ergocell_robot::lock::LockFile;
    use ergocell_robot::TrajectoryClass;

    let dir = fresh_cell("trajectories_forged_lock");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c1"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = ergocell(
        &dir,
        &[
            "trajectories",
            "verify",
            "--class",
            "c1",
            "--allow-unapproved",
        ],
    );
    assert_eq!(code, 0, "{out}");

    let path = dir.join("trajectories/locks/c1.lock.toml");
    let mut lock = LockFile::from_toml_str(
        TrajectoryClass::C1,
        &std::fs::read_to_string(&path).unwrap(),
    )
    .unwrap();
    lock.trajectory.point[40].velocities_rad_s[1] *= 1.5;
    lock.lock_sha256 = lock.content_sha256();
    std::fs::write(&path, lock.to_toml().unwrap()).unwrap();

    let (code, _, err) = ergocell(
        &dir,
        &["trajectories", "approve", "--class", "c1", "--by", "X"],
    );
    assert_eq!(code, 1);
    assert!(
        err.contains("does not hold the validated trajectory")
            && err.contains("refusing to approve"),
        "{err}"
    );
    assert!(!dir.join("trajectories/approvals/c1.toml").exists());
    let (code, out, _) = ergocell(
        &dir,
        &[
            "trajectories",
            "verify",
            "--class",
            "c1",
            "--allow-unapproved",
        ],
    );
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("c1: FAIL") && out.contains("point 40: velocities_rad_s[1]"),
        "{out}"
    );
}

#[test]
fn an_unknown_class_is_a_usage_error() {
    let dir = fresh_cell("trajectories_usage");
    let (code, _, err) = ergocell(&dir, &["trajectories", "validate", "--class", "c9"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown trajectory class"), "{err}");
}
