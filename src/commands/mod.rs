//! A module per subcommand (`review.rs` also holds `report`). Each exposes
//! its `Args` (clap) and a function taking them, returning `anyhow::Result<()>`.
//! Shared by them: `output` (output files: `--force`, never an input) and `signals` (SIGINT and
//! SIGTERM).

pub mod calibrate;
pub mod demo;
pub mod exposure;
pub mod height;
pub mod outcome;
pub use ergocell::output;
pub mod reba;
pub mod replay;
pub mod review;
pub mod ros_node;
pub mod rula;
pub mod run;
pub mod security;
pub mod signals;
pub mod sim;
pub mod sim_warnings;
pub mod trajectories;
pub mod triangulate;

/// Bad input from the user (a malformed file, a wrong flag value): exit code 2, as `clap` does.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct UsageError(pub String);

/// Exit code for an error: 130 / 143 for a command stopped by SIGINT / SIGTERM (robot held,
/// recording closed: [`signals::Stopped`]), 2 for bad input (a [`UsageError`], an input file
/// that cannot be read: [`ergocell::input::InputError`], an output refused:
/// [`ergocell::output::OutputError::Refused`]), 1 for everything else.
pub fn exit_code(err: &anyhow::Error) -> u8 {
    if let Some(stopped) = err
        .chain()
        .find_map(<dyn std::error::Error>::downcast_ref::<signals::Stopped>)
    {
        stopped.signal.exit_code()
    } else if err.chain().any(|e| {
        e.is::<UsageError>()
            || e.is::<ergocell::input::InputError>()
            || e.downcast_ref::<ergocell::output::OutputError>()
                .is_some_and(ergocell::output::OutputError::is_refusal)
    }) {
        2
    } else {
        1
    }
}

/// `--operator`'s parser: a pseudonymous id ([`ergocell_bridge::session_info::OperatorId`]).
pub fn parse_operator(s: &str) -> Result<ergocell_bridge::session_info::OperatorId, String> {
    ergocell_bridge::session_info::OperatorId::new(s).map_err(|e| e.to_string())
}

/// `--start-time`'s parser: RFC 3339 → nanoseconds since the Unix epoch.
pub fn parse_start_time(s: &str) -> Result<i64, String> {
    let t = chrono::DateTime::parse_from_rfc3339(s)
        .map_err(|e| format!("{s:?} is not an RFC 3339 time such as 2026-11-30T06:00:00Z ({e})"))?;
    t.timestamp_nanos_opt()
        .filter(|&n| n > 0)
        .ok_or_else(|| format!("{s:?} is outside 1970..2262"))
}
