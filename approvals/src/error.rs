//! The provider's error: why no verified trajectory could be given, with the file or the class and
//! the check that failed as fields.

use std::path::PathBuf;

use ergocell_robot::lock::VerifyFailure;
use ergocell_robot::signing::ApprovalError;
use ergocell_robot::{RobotError, TrajectoryClass};

use crate::anchor::TrustListError;
use crate::files::{Cause, FileError};

/// Why the trajectory provider could not give a verified trajectory, with the file or the class and
/// the check that failed as fields. The session turns any of them into "the robot does not move".
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum ProviderError {
    /// A file could not be read: missing, unreadable, too large, not text, or not among the files
    /// shipped in the binary. The cause names the path.
    #[error("{cause}")]
    Unreadable {
        path: PathBuf,
        #[source]
        cause: FileError,
    },
    /// A file of the robot's side (the cell, its URDF, a trajectory file, a lock) does not parse or
    /// holds an impossible value.
    #[error("{}: {cause}", path.display())]
    Invalid {
        path: PathBuf,
        #[source]
        cause: Box<RobotError>,
    },
    /// The classes' handover RULA curves do not parse or are not curves.
    #[error("{}: {cause}", path.display())]
    Curves {
        path: PathBuf,
        #[source]
        cause: Cause,
    },
    /// The robot's geometry for the recording's markers could not be built for `class`.
    #[error("robot geometry for the recording ({class}): {cause}")]
    Geometry {
        class: TrajectoryClass,
        #[source]
        cause: Box<RobotError>,
    },
    /// One of the cell's approvers' files could not be read. The cause names the path.
    #[error("{cause} (the cell's trusted approvers: config/approvers/ in the repository shows the format)")]
    ApproversUnreadable {
        path: PathBuf,
        #[source]
        cause: FileError,
    },
    /// The cell's trusted approvers (allowed signers, revocations, the authority's signature, the
    /// site's trust anchor) do not give a trust list.
    #[error("trusted approvers: {cause}")]
    TrustList {
        #[source]
        cause: Box<TrustListError>,
    },
    /// The class's lock or its approvals do not verify: every problem found, and the witness's
    /// finding when that failed too (a forged entry is also one the witness never saw).
    #[error("{failure}{}", witness.as_ref().map_or_else(String::new, |w| format!("\n  - {w}")))]
    NotVerified {
        failure: VerifyFailure,
        witness: Option<Box<ProviderError>>,
    },
    /// The approvals file disagrees with the cell's witness of the approvals seen before (an entry
    /// withdrawn or rolled back).
    #[error("{}: {cause}", path.display())]
    Witness {
        path: PathBuf,
        #[source]
        cause: Box<RobotError>,
    },
    /// An approval bears a time no approval can bear now.
    #[error("approval by {approver}: {cause}")]
    ApprovalTime {
        approver: String,
        #[source]
        cause: ApprovalError,
    },
    /// The demo could not lock `class` in memory, or the lock on disk is not what validation
    /// produces now.
    #[error("{class}: demo lock: {cause}")]
    DemoLock {
        class: TrajectoryClass,
        #[source]
        cause: Box<RobotError>,
    },
    /// The demo's throwaway key could not be made.
    #[error("the demo key: {cause}")]
    DemoKey {
        #[source]
        cause: Box<RobotError>,
    },
    /// The lock on disk was made from other inputs than the current trajectory file, URDF, cell or
    /// version.
    #[error("{class}: the lock on disk was made from other inputs than the current trajectory file, URDF, cell or version: re-lock it")]
    LockInputsChanged { class: TrajectoryClass },
    /// A demo approval would have been written into the repository's approvals folder.
    #[error("refusing to write a demo approval into {}: demo approvals live in a temporary folder", dir.display())]
    DemoApprovalsInRepository { dir: PathBuf },
    /// A demo approval was asked of a provider without the demo key.
    #[error("a demo approval needs the demo key")]
    NoDemoKey,
    /// A file the provider writes (a demo approval) could not be written.
    #[error("cannot write {}: {cause}", path.display())]
    Write {
        path: PathBuf,
        #[source]
        cause: Cause,
    },
}

/// Why a class cannot run, in a few words for the start-up summary (the full error says the rest).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// The lock verifies, but no approval of it stands (none yet, or withdrawn).
    NotApproved,
    /// The lock or its approvals do not verify (edited, superseded, a bad signature, …).
    NotVerified,
    /// The cell's approvers are not trusted (the authority's signature or anchor).
    ApproversNotTrusted,
    /// The approvals file was cut back or restored from an older copy (the witness saw more).
    RolledBack,
    /// The witness of the approvals cannot be read (a permissions fault, a line ergocell did not
    /// write): no approval counts until it can.
    WitnessUnreadable,
    /// An approval bears a time no approval can bear now.
    ApprovalTime,
    /// A file the class needs cannot be read or does not parse.
    Files,
    /// The demo's own locks or keys.
    Demo,
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::NotApproved => {
                "not approved (a safety engineer approves each class: docs/safety.md)"
            }
            Self::NotVerified => "the lock or its approvals do not verify",
            Self::ApproversNotTrusted => {
                "the cell's approvers are not trusted (the site authority's signature or anchor)"
            }
            Self::RolledBack => "the approvals file was cut back (the witness saw more of it)",
            Self::WitnessUnreadable => "the approvals' witness cannot be read",
            Self::ApprovalTime => "an approval bears a time no approval can bear now",
            Self::Files => "a file the class needs cannot be read or is invalid",
            Self::Demo => "the demo's lock or key could not be made",
        })
    }
}

impl ProviderError {
    /// Why the class cannot run, in a few words.
    pub fn refusal(&self) -> Refusal {
        match self {
            Self::NotVerified { failure, witness } => {
                let only_not_approved = !failure.problems.is_empty()
                    && failure
                        .problems
                        .iter()
                        .all(|p| matches!(p, RobotError::NotApproved { .. }));
                match witness.as_deref().map(Self::refusal) {
                    // The witness's finding names the cause (the file cut back, or the witness
                    // unreadable) when the chain alone shows nothing but a missing approval.
                    Some(w) if only_not_approved => w,
                    _ if only_not_approved => Refusal::NotApproved,
                    _ => Refusal::NotVerified,
                }
            }
            Self::Witness { cause, .. } => match **cause {
                RobotError::RolledBack { .. } => Refusal::RolledBack,
                _ => Refusal::WitnessUnreadable,
            },
            Self::TrustList { .. } => Refusal::ApproversNotTrusted,
            Self::ApprovalTime { .. } => Refusal::ApprovalTime,
            Self::LockInputsChanged { .. } => Refusal::NotVerified,
            Self::Unreadable { .. }
            | Self::ApproversUnreadable { .. }
            | Self::Invalid { .. }
            | Self::Curves { .. }
            | Self::Geometry { .. }
            | Self::Write { .. } => Refusal::Files,
            Self::DemoLock { .. }
            | Self::DemoKey { .. }
            | Self::DemoApprovalsInRepository { .. }
            | Self::NoDemoKey => Refusal::Demo,
        }
    }
}
