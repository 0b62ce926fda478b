//! The binary works from any directory: a command's default input (`config/cell.toml`,
//! `config/rig.toml`, `trajectories/`) that is not in the working directory is the one shipped in the
//! binary, with a note saying so; one that is there is always the one read; a path that names no
//! shipped file is an error when missing. `trajectories` (which writes beside its files) does not fall
//! back, and says where it looked.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::path::Path;
use std::process::Command;

use common::Scratch;

fn ergocell(dir: &Path, args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_missing_default_is_the_shipped_file_and_a_present_one_wins() {
    let dir = Scratch::new("anywhere");
    let (ok, out, err) = ergocell(&dir.0, &["security", "create-keystore", "--keystore", "ks"]);
    assert!(ok, "{out}\n{err}");
    assert!(
        err.contains("config/cell.toml is not in") && err.contains("shipped in the binary"),
        "{err}"
    );
    assert!(out.contains("for DDS domain 0"), "{out}");
    assert!(dir.0.join("ks/enclaves/ergocell/cell/cert.pem").exists());

    // A cell file in the working directory is read, not the shipped one (another domain here).
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let shipped = std::fs::read_to_string(root.join("config/cell.toml")).unwrap();
    assert!(shipped.contains("\ndomain_id = 0\n"));
    std::fs::create_dir_all(dir.0.join("config")).unwrap();
    std::fs::write(
        dir.0.join("config/cell.toml"),
        shipped.replace("\ndomain_id = 0\n", "\ndomain_id = 7\n"),
    )
    .unwrap();
    let (ok, out, err) = ergocell(
        &dir.0,
        &["security", "create-keystore", "--keystore", "ks7"],
    );
    assert!(ok, "{out}\n{err}");
    assert!(out.contains("for DDS domain 7"), "{out}");
    assert!(!err.contains("shipped"), "{err}");
}

#[test]
fn a_missing_path_that_names_no_shipped_file_is_an_error() {
    let dir = Scratch::new("anywhere-missing");
    let (ok, _, err) = ergocell(
        &dir.0,
        &[
            "security",
            "create-keystore",
            "--keystore",
            "ks",
            "--config",
            "site/cell.toml",
        ],
    );
    assert!(!ok);
    assert!(err.contains("cannot read site/cell.toml"), "{err}");
    assert!(!dir.0.join("ks").exists(), "nothing written");
}

#[test]
fn trajectories_does_not_fall_back_and_says_where_it_looked() {
    let dir = Scratch::new("anywhere-trajectories");
    let (ok, _, err) = ergocell(&dir.0, &["trajectories", "verify"]);
    assert!(!ok);
    assert!(
        err.contains("cannot read config/cell.toml (relative to")
            && err.contains("--trajectories-dir"),
        "{err}"
    );
}
