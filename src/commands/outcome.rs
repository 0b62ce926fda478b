//! `--outcome FILE` of `run` and `demo`: how the sessions ended, as JSON, for a program (CI, a
//! supervisor's script) rather than a person: the exit code, the last session's typed end, every
//! command sent to the robot with its typed reason, whether the execution monitor held the robot
//! itself, and the session's summary. Written when the sessions are over (on a stop signal too),
//! atomically, never over an input nor without `--force` over an existing file.

use std::path::Path;

use ergocell::session::{CommandSent, DriverError, Outcome, SessionEnd, SessionSummary};
use serde::Serialize;

use super::output;

/// The file's shape (its fields are its documentation).
#[derive(Serialize)]
struct OutcomeFile<'a> {
    /// The process's exit code by the cell's rule: 0 done, 1 a person must look, 130/143 a stop.
    exit_code: u8,
    /// Sessions ended, the last one included.
    sessions: u32,
    /// How the last session ended, typed (`kind` and its facts).
    end: &'a SessionEnd,
    /// Every command sent, in order: a goal's leg or a hold's typed reason.
    commands: &'a [CommandSent],
    /// Whether the execution monitor held the robot itself, at once on a deviation.
    monitor_held: bool,
    /// The last session's summary.
    summary: &'a SessionSummary,
}

/// Writes `outcome` to `path` (checked before the session by [`check`]).
pub fn write(
    path: &Path,
    force: bool,
    outcome: &Outcome,
    summary: &SessionSummary,
    monitor_held: bool,
) -> anyhow::Result<()> {
    let file = OutcomeFile {
        exit_code: outcome.status.code(),
        sessions: outcome.sessions,
        end: &outcome.ending.end,
        commands: &outcome.commands,
        monitor_held,
        summary,
    };
    let mut text = serde_json::to_string_pretty(&file)?;
    text.push('\n');
    Ok(output::write("--outcome", path, force, text.as_bytes())?)
}

/// The driver's result: the outcome, written to `path` when one is asked for. A station that
/// failed ended the session held; its outcome so far is written all the same and its error
/// returned.
pub fn written(
    result: Result<Outcome, DriverError>,
    path: Option<&Path>,
    force: bool,
    summary: &SessionSummary,
    monitor_held: bool,
) -> anyhow::Result<Outcome> {
    let write_to = |o: &Outcome| match path {
        Some(path) => write(path, force, o, summary, monitor_held),
        None => Ok(()),
    };
    match result {
        Ok(o) => {
            write_to(&o)?;
            Ok(o)
        }
        Err(e) => {
            // the station's error is the one to report; a failed write is said beside it
            if let Some(Err(w)) = e.outcome.as_ref().map(write_to) {
                eprintln!("error: the outcome was not written: {w:#}");
            }
            Err(anyhow::Error::new(StationFailed(e.error)))
        }
    }
}

/// The station's error as the driver returns it (shared with the session's end), for `anyhow`:
/// its message and its sources.
#[derive(Debug)]
struct StationFailed(ergocell::session::Cause);

impl std::fmt::Display for StationFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::error::Error for StationFailed {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.0.source()
    }
}

/// Before the session: `path` is no input, and exists only with `force`.
pub fn check(path: &Path, force: bool, inputs: &[(&str, &Path)]) -> anyhow::Result<()> {
    Ok(output::check("--outcome", path, force, inputs)?)
}
