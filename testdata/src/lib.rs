//! Where the tests find `../shared`, the folder of real data beside the repository (a 4-camera
//! MediaPipe recording, OpenCV's stereo sample, Pose2Sim's videos with their Qualisys calibration,
//! ANSUR II, the RULA reference; each data set's source and licence in its own `SOURCE.md`), and
//! what a test does when it is not there.
//!
//! A test that needs it starts with `if ergocell_testdata::skip_without("data/caliscope-4cam") {
//! return; }`. Without the folder the test is skipped and says so in one line naming the path, on
//! the terminal even when cargo captures the test's output; with `ERGOCELL_REQUIRE_SHARED` set (CI
//! sets it) a missing folder fails the test instead, naming the path. A dev-dependency only.
//!
//! The skips are counted. When a test binary that skipped something exits, it says after cargo's
//! own `test result:` line how many of its tests skipped and for which paths, and how many the whole
//! `cargo test` run has skipped so far; the run's last such line is its total. The run's tally is a
//! file in the temporary folder named after the `cargo` process that runs the binaries (its pid and
//! start time since boot), so two runs do not add up each other's skips (unless a temporary folder
//! kept across a reboot meets a new `cargo` with the same pid and start time). The files are small
//! and left for the system's cleaning of the temporary folder.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, Once, PoisonError};

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
    record_skip(relative);
    true
}

/// The paths this test binary's tests skipped for, one entry per skipped test.
static SKIPPED: Mutex<Vec<String>> = Mutex::new(Vec::new());
static AT_EXIT: Once = Once::new();

fn record_skip(relative: &str) {
    SKIPPED
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .push(relative.to_owned());
    AT_EXIT.call_once(|| {
        // SAFETY: `atexit` only stores the function pointer; `report_skips` is an `extern "C"`
        // function that never unwinds (it catches nothing that can panic: every write's error is
        // ignored, the lock's poison is taken over). std has no exit hook, and libtest returns from
        // `main` (or calls `exit`) after printing its result line, which is where the count belongs.
        #[allow(unsafe_code)]
        let registered = unsafe { libc::atexit(report_skips) } == 0;
        if !registered {
            let _ = writeln!(
                std::io::stderr(),
                "(the count of skipped tests cannot be printed at exit: atexit refused)"
            );
        }
    });
}

/// At the test binary's exit: its skips, and the run's so far.
extern "C" fn report_skips() {
    let skipped = std::mem::take(&mut *SKIPPED.lock().unwrap_or_else(PoisonError::into_inner));
    let _ = writeln!(
        std::io::stderr(),
        "{}",
        skip_summary(&skipped, run_tally(&skipped))
    );
}

/// One line: `skipped` (one path per skipped test) counted per path, and the run's total so far.
fn skip_summary(skipped: &[String], run_total: Option<usize>) -> String {
    let mut per_path: Vec<(&str, usize)> = Vec::new();
    for p in skipped {
        match per_path.iter_mut().find(|(q, _)| q == p) {
            Some((_, n)) => *n += 1,
            None => per_path.push((p, 1)),
        }
    }
    let paths = per_path
        .iter()
        .map(|(p, n)| format!("{n} for want of {}", shared(p).display()))
        .collect::<Vec<_>>()
        .join(", ");
    let run = run_total.map_or_else(String::new, |n| {
        format!("; {n} skipped so far in this cargo test run")
    });
    format!(
        "SKIPPED {} test(s) in this test binary ({paths}){run}",
        skipped.len()
    )
}

/// Adds this binary's skips to the run's tally file and returns the run's total; `None` when the
/// run cannot be told apart from another (no parent process start time) or the file fails.
fn run_tally(skipped: &[String]) -> Option<usize> {
    let parent = std::os::unix::process::parent_id();
    let started = parent_start_time(parent)?;
    let file = std::env::temp_dir().join(format!("ergocell-shared-skips-{parent}-{started}"));
    append_and_count(&file, skipped)
}

/// The parent's start time since boot (clock ticks, `/proc/<pid>/stat` field 22): with its pid, it
/// names one process for as long as the machine runs.
fn parent_start_time(pid: u32) -> Option<u64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The command name (field 2) may hold spaces and parentheses: count fields after its last ')'.
    let after = &stat[stat.rfind(')')? + 1..];
    after.split_whitespace().nth(19)?.parse().ok()
}

/// Appends one line per skip to `file` (one write: binaries run one after another) and counts the
/// file's lines.
fn append_and_count(file: &Path, skipped: &[String]) -> Option<usize> {
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(file)
        .ok()?;
    let lines: String = skipped.iter().flat_map(|p| [p.as_str(), "\n"]).collect();
    f.write_all(lines.as_bytes()).ok()?;
    drop(f);
    Some(std::fs::read_to_string(file).ok()?.lines().count())
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

    #[test]
    fn the_summary_counts_skips_per_path_and_names_the_run_total() {
        let skipped = [
            "data/a".to_owned(),
            "data/b".to_owned(),
            "data/a".to_owned(),
        ];
        let line = skip_summary(&skipped, Some(7));
        let a = shared("data/a").display().to_string();
        let b = shared("data/b").display().to_string();
        assert_eq!(
            line,
            format!(
                "SKIPPED 3 test(s) in this test binary (2 for want of {a}, 1 for want of {b}); 7 \
                 skipped so far in this cargo test run"
            )
        );
        assert_eq!(
            skip_summary(&skipped[..1], None),
            format!("SKIPPED 1 test(s) in this test binary (1 for want of {a})")
        );
    }

    #[test]
    fn the_run_tally_adds_up_across_binaries() {
        let file =
            std::env::temp_dir().join(format!("ergocell-skip-tally-test-{}", std::process::id()));
        let _ = std::fs::remove_file(&file);
        assert_eq!(append_and_count(&file, &["x".to_owned()]), Some(1));
        assert_eq!(
            append_and_count(&file, &["y".to_owned(), "z".to_owned()]),
            Some(3)
        );
        let _ = std::fs::remove_file(&file);
    }

    #[test]
    fn this_process_parent_has_a_start_time() {
        // Where the parent cannot be read (no /proc, pid 1 in a container, hidepid), the tally is
        // not kept and the count says so by leaving the run's total out.
        let parent = std::os::unix::process::parent_id();
        if parent == 0 || std::fs::read(format!("/proc/{parent}/stat")).is_err() {
            return;
        }
        let a = parent_start_time(std::os::unix::process::parent_id());
        assert!(a.is_some());
        assert_eq!(a, parent_start_time(std::os::unix::process::parent_id()));
    }
}
