//! Where the tests find `../shared`, the folder of real data beside the repository (a 4-camera
//! MediaPipe recording, OpenCV's stereo sample, Pose2Sim's videos with their Qualisys calibration,
//! ANSUR II, the RULA reference; each data set's source and licence in its own `SOURCE.md`), and
//! what a test does when it is not there.
//!
//! A test that needs it starts with `if ergocell_testdata::skip_without("data/caliscope-4cam") {
//! return; }`. Without the folder the test is skipped and says so in one line naming the path, on
//! the terminal even when cargo captures the test's output; with `ERGOCELL_REQUIRE_SHARED` set (CI
//! sets it) a missing folder fails the test instead, naming the path. A dev-dependency only: it
//! does no other I/O.

use std::io::Write as _;
use std::path::PathBuf;

/// Set (to anything) where a missing shared folder is a failure, not a skip (CI).
pub const REQUIRE_ENV: &str = "ERGOCELL_REQUIRE_SHARED";

/// The shared folder: `../shared` beside the repository.
pub fn shared_root() -> PathBuf {
    let repo = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    repo.parent().map_or_else(
        || PathBuf::from("../shared"),
        |r| r.parent().unwrap_or(r).join("shared"),
    )
}

/// `relative` inside the shared folder, e.g. `data/caliscope-4cam`.
pub fn shared(relative: &str) -> PathBuf {
    shared_root().join(relative)
}

/// True when `relative` is not in the shared folder and the test should return: says so in one
/// line on standard error (written past cargo's capture), or panics naming the path when
/// [`REQUIRE_ENV`] is set.
///
/// # Panics
/// When the path is missing and [`REQUIRE_ENV`] is set: there a missing data set is a failure.
pub fn skip_without(relative: &str) -> bool {
    let path = shared(relative);
    if path.exists() {
        return false;
    }
    assert!(
        std::env::var_os(REQUIRE_ENV).is_none(),
        "{}: missing, and {REQUIRE_ENV} is set (the shared data folder must sit beside the repository)",
        path.display()
    );
    // Straight to the stream, not through eprintln!: cargo test shows it without --nocapture.
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED (no shared data): {} is missing (the shared data folder beside the repository)",
        path.display()
    );
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shared_folder_is_beside_the_repository() {
        let root = shared_root();
        assert_eq!(root.file_name().and_then(|n| n.to_str()), Some("shared"));
        let repo = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        assert_eq!(root.parent(), repo.parent().and_then(|r| r.parent()));
        if skip_without("") {
            return;
        }
        assert!(root.is_dir());
    }
}
