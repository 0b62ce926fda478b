//! Where the cell keeps its witness of the approvals files ([`ergocell_robot::witness`]), and the
//! reading and appending of it.
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

use ergocell_robot::lock::ApprovalsFile;
use ergocell_robot::witness::Witness;
use ergocell_robot::{RobotError, TrajectoryClass, TrustedSigners};

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

/// The approvals file's name in the witness: its absolute path as the cell names it, symlinks
/// **not** resolved. Keyed by the resolved path, a folder swapped for a symlink to another folder
/// holding an older copy was a file the witness had never seen (a withdrawal revived).
fn key(approvals_path: &Path) -> String {
    std::path::absolute(approvals_path)
        .unwrap_or_else(|_| approvals_path.to_owned())
        .to_string_lossy()
        .into_owned()
}

/// The key the witness used before, the folder's links resolved: its sightings still bind.
fn resolved_key(approvals_path: &Path) -> Option<String> {
    let (dir, name) = (approvals_path.parent()?, approvals_path.file_name()?);
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    fs::canonicalize(dir)
        .ok()
        .map(|d| d.join(name).to_string_lossy().into_owned())
}

/// Checks the approvals file at `approvals_path` (parsed, its chain intact) against the witness,
/// then records there what a `trusted` approver's signature vouches for of it, when that is more
/// than the witness knew ([`Witness::sighting_line`]). `Err` is the refusal (the file
/// was cut back); the notes are for the user (lines of the witness passed over, a record that could
/// not be written): the check stays as strong as what was read.
pub fn observe(
    approvals_path: &Path,
    class: TrajectoryClass,
    file: &ApprovalsFile,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<String>, RobotError> {
    let path = witness_path(approvals_path.parent().unwrap_or_else(|| Path::new(".")));
    let mut notes = Vec::new();
    // A witness that cannot be read refuses: it would otherwise be switched off by one bad byte.
    let bytes = match crate::input::read(&path, crate::input::Kind::Config) {
        Ok(bytes) => bytes,
        Err(e) if e.is_not_found() => Vec::new(),
        Err(e) => {
            return Err(RobotError::WitnessUnreadable {
                line: 0,
                why: e.to_string(),
            })
        }
    };
    let witness = Witness::parse(&bytes)?;
    for line in &witness.unreadable {
        notes.push(format!("witness {}: {line} (passed over)", path.display()));
    }
    let key = key(approvals_path);
    witness.check(&key, class, file)?;
    if let Some(resolved) = resolved_key(approvals_path).filter(|r| *r != key) {
        witness.check(&resolved, class, file)?;
    }
    let now =
        ergocell_robot::signing::rfc3339_utc(now_unix).unwrap_or_else(|_| "unknown".to_owned());
    if let Some(line) = witness.sighting_line(&key, class, file, trusted, &now) {
        if let Err(e) = append(&path, &line) {
            notes.push(format!(
                "cannot record in the witness {}: {e} (a later rollback of this file is not caught)",
                path.display()
            ));
        }
    }
    Ok(notes)
}

/// [`observe`] for an approvals file as read: `None` (no file) is an empty chain, so one the witness
/// saw entries of is caught as deleted; a text that does not parse or whose chain is broken is not
/// checked here (`lock::verify` reports it).
pub fn observe_text(
    approvals_path: &Path,
    class: TrajectoryClass,
    text: Option<&str>,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<String>, RobotError> {
    let file = match text.map(ApprovalsFile::from_toml_str) {
        None => ApprovalsFile::default(),
        Some(Ok(file)) if file.check_chain().is_ok() => file,
        Some(_) => return Ok(Vec::new()),
    };
    observe(approvals_path, class, &file, trusted, now_unix)
}

/// Appends one line and syncs it. A new local witness folder gets a `.gitignore` first.
fn append(path: &Path, line: &str) -> std::io::Result<()> {
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
