//! Offline ergonomics review (the seed paper's fourth contribution): a session recording turned into
//! what an ergonomics expert reads — the fused skeleton over time with each joint coloured by its RULA
//! band, the grand score and action level of both sides, the warnings, per-region score shares, the
//! distribution of every joint angle and the session facts (height, class, locked trajectory,
//! approvers).
//!
//! - [`read`]: an MCAP recording (bytes, or streamed from a reader) → the ergocell messages in it. A file cut short (a crash, a
//!   partial copy) is read up to its last complete chunk and says so; a foreign MCAP or a file that is
//!   not MCAP at all is refused with what could be read.
//!   Recordings made before a message carried a fact as a field are read in one module, `legacy`:
//!   the older layouts, and the only facts read from words (a leg's, a part taken's).
//! - [`analysis`]: the messages → [`ReviewData`], the JSON the page renders (`version` 1).
//! - [`findings`]: the report's first page — time at each action level, the worst moments, and per
//!   body region what was found and the warnings' advice for it.
//! - [`overview`]: a long recording (a shift) in bounded memory: read twice, streamed; its numbers
//!   over every frame, its page the overview and the worst moments.
//! - [`exposure`]: many recordings, streamed, → exposure per operator, day and week, task segment
//!   and robot class (seconds that add up across sessions).
//! - [`exposure_csv`]: the exposure as CSV files — a row per group (shares, hours) and a row per
//!   session and segment (seconds).
//! - [`store`]: those sessions as Parquet, for SQL in DuckDB (or Spark, Trino) — no engine here.
//! - [`export`]: the session as spreadsheet files — a row per frame, and the summary in `ergocell
//!   rula track`'s layout.
//! - [`text`]: what the commands say about the recordings on the console — a line per session
//!   reviewed, the other sessions of a recording of several, each recording `exposure` read.
//! - [`page`]: the page itself — the HTML shell around the browser bundle built from `web/`
//!   (three.js + uPlot, vendored, so it works offline), linked for `ergocell review`'s server, or
//!   everything inlined into one file for `ergocell report`.
//!
//! No I/O here: the binary reads the file and serves the page.

pub mod analysis;
pub mod export;
pub mod exposure;
pub mod exposure_csv;
pub mod findings;
mod legacy;
pub mod overview;
pub mod page;
pub mod read;
pub mod store;
pub mod text;

pub use analysis::{analyse, ReviewData, SessionReview};
pub use read::{read_recording, Recording};

/// Why a recording cannot be reviewed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ReviewError {
    /// Not an MCAP file (or nothing of it is readable).
    #[error("not a readable MCAP file: {reason}")]
    NotMcap { reason: String },
    /// An MCAP file without ergocell's topics. `channels` lists what it does hold.
    #[error("an MCAP file, but not an ergocell session recording: none of its {message_count} messages is on an ergocell topic (it has {channels})")]
    Foreign {
        message_count: u64,
        channels: String,
    },
    /// A spreadsheet export could not be written.
    #[error("writing the CSV export: {reason}")]
    Export { reason: String },
}
