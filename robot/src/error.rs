//! The crate's one error type. Every variant carries the evidence a reader needs to act on it.

use crate::pose::PoseSummary;

/// Everything that can go wrong in `ergocell_robot`.
///
/// Outcomes of validation are not errors: a rejected trajectory is a [`crate::ValidationReport`] with
/// `accepted == false`. [`RobotError::Rejected`] only appears when a caller asks for the
/// [`crate::LockedTrajectory`] of a rejected plan.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RobotError {
    /// The URDF text does not parse.
    #[error("URDF does not parse: {reason}")]
    Urdf { reason: String },
    /// The URDF parses but cannot be used as a serial arm.
    #[error("URDF is not a usable serial arm: {reason}")]
    UnsupportedUrdf { reason: String },
    /// A link named in the configuration is not in the URDF (or not on the base→flange chain).
    #[error("link `{link}` not found in the URDF ({context})")]
    UnknownLink { link: String, context: String },
    /// A joint has no usable position, velocity or effort limit.
    #[error("joint `{joint}` has an invalid limit: {reason}")]
    InvalidLimit { joint: String, reason: String },
    /// A vector has the wrong number of entries.
    #[error("{what}: expected {expected} values, got {got}")]
    DofMismatch {
        what: String,
        expected: usize,
        got: usize,
    },
    /// A configuration or trajectory file is malformed or out of its documented range.
    #[error("invalid configuration: {reason}")]
    Config { reason: String },
    /// No IK seed reached the target within tolerance.
    #[error(
        "target unreachable: target {target}, closest reachable {closest} \
         (position error {position_error_m:.4} m, orientation error {orientation_error_rad:.4} rad)"
    )]
    Unreachable {
        target: Box<PoseSummary>,
        closest: Box<PoseSummary>,
        position_error_m: f64,
        orientation_error_rad: f64,
    },
    /// A joint position is outside its limit.
    #[error("joint `{joint}` at {position_rad:.5} rad is outside its limit {limit_rad:.5} rad")]
    OutOfLimit {
        joint: String,
        position_rad: f64,
        limit_rad: f64,
    },
    /// The QP could not be set up (bad dimensions or settings); an unsolved QP is a rejection instead.
    #[error("QP setup failed: {reason}")]
    Qp { reason: String },
    /// Validation rejected the trajectory; the reasons are those of the report.
    #[error("trajectory {class} rejected: {}", reasons.join("; "))]
    Rejected { class: String, reasons: Vec<String> },
    /// A lock file does not parse or its own hash does not match its content.
    #[error("lock file for {class} is corrupt: {reason}")]
    LockCorrupt { class: String, reason: String },
    /// An input the lock depends on changed since the lock was written.
    #[error("{class}: {what} changed since the lock was written (locked sha256 {locked_sha256}, now {current_sha256})")]
    LockMismatch {
        class: String,
        what: String,
        locked_sha256: String,
        current_sha256: String,
    },
    /// No approval records the lock's hash.
    #[error("{class}: no approval for lock sha256 {lock_sha256} ({detail})")]
    NotApproved {
        class: String,
        lock_sha256: String,
        detail: String,
    },
    /// The approvals file holds less than the witness saw of it, or other entries: entries were
    /// deleted or edited, or it was restored from an older copy ([`crate::witness`]).
    #[error(
        "{class}: the approvals file {what} (witness line {witness_line}): entries were removed or \
         edited, or the file was restored from an older copy. Restore the newer file; an approval \
         or withdrawal once seen cannot be taken back by deleting it"
    )]
    RolledBack {
        class: String,
        /// What differs, e.g. "has 1 entries, but on 2026-12-05T00:13:00Z it had 2".
        what: String,
        witness_line: usize,
    },
    /// The witness cannot be read whole (a line ergocell did not write, or the file cannot be
    /// opened): a rollback cannot be ruled out, so the approvals it guards are refused
    /// ([`crate::witness`]). Line 0: the file as a whole.
    #[error(
        "the witness of the approvals cannot be read (line {line}: {why}): a rollback cannot be \
         ruled out, so no approval counts. ergocell only ever appends whole lines to it; another \
         line means it was written by someone else. Have the site's administrator inspect it"
    )]
    WitnessUnreadable { line: usize, why: String },
    /// An approval of the lock is there but cannot be trusted (bad signature, untrusted or revoked
    /// key, malformed time, …): the lock is refused.
    #[error("{class}: approval entry {entry} (approved by {approved_by}) refused: {reason}")]
    ApprovalRefused {
        class: String,
        /// 0-based index in the approvals file.
        entry: usize,
        /// The entry's name, control characters escaped.
        approved_by: String,
        reason: Box<crate::signing::ApprovalError>,
    },
    /// The robot is not where the trajectory starts.
    #[error("joint `{joint}` is at {current_rad:.4} rad but the trajectory starts at {start_rad:.4} rad")]
    StartMismatch {
        joint: String,
        current_rad: f64,
        start_rad: f64,
    },
    /// The session's trajectory is locked; a change was requested.
    #[error(
        "session trajectory is locked to {locked_class}; request for {requested_class} refused until the \
         session ends (operator gone and robot at home)"
    )]
    SessionLocked {
        locked_class: String,
        requested_class: String,
    },
}
