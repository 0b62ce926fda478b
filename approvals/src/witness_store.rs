//! The cell's witness of the approvals files ([`ergocell_robot::witness`]) kept through the
//! [`CellFiles`] port: every reader of an approvals file (`trajectories verify`, `approve`,
//! `withdraw`, each session start) checks that the file extends what the witness saw, and records
//! what it sees beyond that. Who can delete the witness decides what it catches (see
//! docs/safety.md); where it lives is the caller's choice.

use std::path::{Path, PathBuf};

use ergocell_robot::lock::ApprovalsFile;
use ergocell_robot::witness::Witness;
use ergocell_robot::{RobotError, TrajectoryClass, TrustedSigners};

use crate::files::{CellFiles, FileError};

/// What the user should know of a check that still held: the check is as strong as what was read.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum WitnessNote {
    /// A line of the witness that does not parse was passed over.
    #[error("witness {}: {line} (passed over)", witness.display())]
    PassedOver { witness: PathBuf, line: String },
    /// What was seen could not be recorded.
    #[error("cannot record in the witness {}: {cause} (a later rollback of this file is not caught)", witness.display())]
    NotRecorded { witness: PathBuf, cause: FileError },
}

/// Checks the approvals file at `approvals_path` (parsed, its chain intact) against the witness at
/// `witness_path`, then records there what a `trusted` approver's signature vouches for of it, when
/// that is more than the witness knew ([`Witness::sighting_line`]), stamped `now_unix`. `Err` is the
/// refusal (the file was cut back, or the witness cannot be read: one bad byte must not switch it
/// off).
pub fn observe(
    files: &dyn CellFiles,
    witness_path: &Path,
    approvals_path: &Path,
    class: TrajectoryClass,
    file: &ApprovalsFile,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<WitnessNote>, RobotError> {
    let bytes = files
        .read_witness(witness_path)
        .map_err(|e| RobotError::WitnessUnreadable {
            line: 0,
            why: e.to_string(),
        })?;
    let witness = Witness::parse(&bytes)?;
    let mut notes: Vec<WitnessNote> = witness
        .unreadable
        .iter()
        .map(|line| WitnessNote::PassedOver {
            witness: witness_path.to_owned(),
            line: line.clone(),
        })
        .collect();
    // Keyed by the name the cell uses, links not resolved: keyed by the resolved path, a folder
    // swapped for a link to another holding an older copy was a file never seen. The resolved
    // name (the key used before) still binds.
    let key = files
        .absolute(approvals_path)
        .to_string_lossy()
        .into_owned();
    witness.check(&key, class, file)?;
    if let Some(resolved) = files
        .resolved(approvals_path)
        .map(|r| r.to_string_lossy().into_owned())
        .filter(|r| *r != key)
    {
        witness.check(&resolved, class, file)?;
    }
    let now =
        ergocell_robot::signing::rfc3339_utc(now_unix).unwrap_or_else(|_| "unknown".to_owned());
    if let Some(line) = witness.sighting_line(&key, class, file, trusted, &now) {
        if let Err(cause) = files.append_witness(witness_path, &line) {
            notes.push(WitnessNote::NotRecorded {
                witness: witness_path.to_owned(),
                cause,
            });
        }
    }
    Ok(notes)
}

/// [`observe`] for an approvals file as read: `None` (no file) is an empty chain, so one the witness
/// saw entries of is caught as deleted; a text that does not parse or whose chain is broken is not
/// checked here (`lock::verify` reports it).
pub fn observe_text(
    files: &dyn CellFiles,
    witness_path: &Path,
    approvals_path: &Path,
    class: TrajectoryClass,
    text: Option<&str>,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<Vec<WitnessNote>, RobotError> {
    let file = match text.map(ApprovalsFile::from_toml_str) {
        None => ApprovalsFile::default(),
        Some(Ok(file)) if file.check_chain().is_ok() => file,
        Some(_) => return Ok(Vec::new()),
    };
    observe(
        files,
        witness_path,
        approvals_path,
        class,
        &file,
        trusted,
        now_unix,
    )
}
