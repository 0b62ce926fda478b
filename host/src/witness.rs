//! Where the cell keeps its witness of the approvals files ([`ergocell_robot::witness`]; checked
//! and extended by [`ergocell_approvals::witness_store`], appended to by
//! [`crate::provider::OsFiles`]).
//!
//! The witness is `witness.jsonl` in the folder the `ERGOCELL_STATE_DIR` environment variable names
//! (an installed cell: its state folder, `/var/lib/ergocell` under systemd's `StateDirectory=`), or
//! else in `.witness/` inside the approvals folder, with a `.gitignore` so that git never tracks it
//! and so never restores an old one with the old approvals. Every command that reads an approvals
//! file (`trajectories verify`, `approve`, `withdraw`, `run` at each session start) checks the file
//! extends what the witness saw and records what it sees beyond that.
//!
//! Who can delete the witness decides what it catches: in the approvals folder, a careless rollback
//! (a lock and its approvals checked out from git, an old backup copied back); on an append-only file
//! (`chattr +a`, set by root) in a folder the cell's account cannot write, a hostile one as well.

use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};

pub use ergocell_approvals::witness_store::WitnessNote;
use ergocell_robot::lock::ApprovalsFile;
use ergocell_robot::{RobotError, TrajectoryClass, TrustedSigners};

use crate::provider::OsFiles;

/// The environment variable naming the cell's state folder.
pub const STATE_DIR_ENV: &str = "ERGOCELL_STATE_DIR";

/// The witness's file name.
pub const WITNESS_FILE: &str = "witness.jsonl";

/// The witness's folder inside the approvals folder when no state folder is named.
pub const LOCAL_DIR: &str = ".witness";

/// The witness file for approvals kept in `approvals_dir`.
pub fn witness_path(approvals_dir: &Path) -> PathBuf {
    std::env::var_os(STATE_DIR_ENV)
        .filter(|d| !d.is_empty())
        .map_or_else(|| approvals_dir.join(LOCAL_DIR), PathBuf::from)
        .join(WITNESS_FILE)
}

/// The witness of the approvals file at `approvals_path` (its folder's, or the state folder's).
fn witness_beside(approvals_path: &Path) -> PathBuf {
    witness_path(approvals_path.parent().unwrap_or_else(|| Path::new(".")))
}

/// [`ergocell_approvals::witness_store::observe`] on this machine's witness for the approvals file
/// at `approvals_path`.
pub fn observe(
    approvals_path: &Path,
    class: TrajectoryClass,
    file: &ApprovalsFile,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<WitnessNote>, RobotError> {
    ergocell_approvals::witness_store::observe(
        &OsFiles::disk(),
        &witness_beside(approvals_path),
        approvals_path,
        class,
        file,
        trusted,
        now_unix,
    )
}

/// [`ergocell_approvals::witness_store::observe_text`] on this machine's witness.
pub fn observe_text(
    approvals_path: &Path,
    class: TrajectoryClass,
    text: Option<&str>,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<WitnessNote>, RobotError> {
    ergocell_approvals::witness_store::observe_text(
        &OsFiles::disk(),
        &witness_beside(approvals_path),
        approvals_path,
        class,
        text,
        trusted,
        now_unix,
    )
}

/// Appends one line and syncs it. A new local witness folder gets a `.gitignore` first.
pub(crate) fn append(path: &Path, line: &str) -> std::io::Result<()> {
    if let Some(dir) = path.parent() {
        if !dir.exists() {
            fs::create_dir_all(dir)?;
            if dir.file_name() == Some(LOCAL_DIR.as_ref()) {
                fs::write(
                    dir.join(".gitignore"),
                    "# ergocell's witness of the approvals: never tracked, so never restored from git.\n*\n",
                )?;
            }
        }
    }
    let mut file = fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    file.write_all(line.as_bytes())?;
    file.sync_data()
}
