//! Why the robot is held and how a session ended, as types: [`HoldReason`], [`SessionEnd`] and,
//! for a session that could not serve, [`AbortReason`], each with its facts as fields. The
//! summary's `end_reason` and the hold's reason on the wire are their words
//! ([`std::fmt::Display`]); programs and tests match the variants.

use std::fmt;

use ergocell_robot::{RobotError, TrajectoryClass};
use serde::{Serialize, Serializer};

use super::cell_loop::OutputError;
use super::driver::InputError;
use super::robot_side::{RobotFailure, RobotUnready};
use crate::error::ProviderError;

/// Why the session ended without serving: the robot is held and does not move.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum AbortReason {
    /// The operator's height was still undecided when the height timeout passed.
    HeightUndecided {
        /// The height timeout, seconds.
        after_s: f64,
        frames_seen: usize,
        upright_frames: usize,
        /// What the height measurement still misses, in its own words.
        missing: String,
    },
    /// The operator's ±2σ stature interval reaches outside the statures the class's trajectory was
    /// validated and is served for.
    StatureOutsideServed {
        class: TrajectoryClass,
        interval_m: [f64; 2],
        served_m: [f64; 2],
    },
    /// The class's served statures could not be read.
    StatureBoundsUnreadable {
        class: TrajectoryClass,
        #[serde(serialize_with = "as_text")]
        error: ProviderError,
    },
    /// The class's trajectory did not verify against its lock and approvals.
    NotVerified {
        class: TrajectoryClass,
        #[serde(serialize_with = "as_text")]
        error: ProviderError,
    },
    /// The robot is not at the locked trajectory's first knot.
    NotAtStart {
        #[serde(serialize_with = "as_text")]
        error: RobotError,
    },
    /// The robot reported no joint positions, so its start could not be checked.
    NoJointPositions,
}

fn as_text<T: fmt::Display, S: Serializer>(value: &T, s: S) -> Result<S::Ok, S::Error> {
    s.collect_str(value)
}

impl fmt::Display for AbortReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::HeightUndecided {
                after_s, missing, ..
            } => write!(
                f,
                "height undecided after {after_s:.0} s ({missing}): the cell cannot class this \
                 operator, so the robot does not move"
            ),
            Self::StatureOutsideServed {
                class,
                interval_m: [lo, hi],
                served_m: [min, max],
            } => write!(
                f,
                "operator stature {lo:.3}–{hi:.3} m reaches outside the statures class {class}'s \
                 trajectory was validated for ({min:.2}–{max:.2} m): the robot does not move; a \
                 trajectory for this stature must be derived, validated and approved first"
            ),
            Self::StatureBoundsUnreadable { class, error } => {
                write!(
                    f,
                    "cannot read the stature bounds of class {class}: {error}"
                )
            }
            Self::NotVerified { class, error } => {
                write!(f, "trajectory for class {class} not verified: {error}")
            }
            Self::NotAtStart { error } => {
                write!(f, "the robot is not at the trajectory's start: {error}")
            }
            Self::NoJointPositions => f.write_str(
                "no joint positions from the robot: cannot check the trajectory's start",
            ),
        }
    }
}

/// How the session ended.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum SessionEnd {
    /// The operator left and the robot is home: the normal end.
    OperatorLeft {
        /// Class change requests refused during the session (the trajectory stayed locked).
        changes_refused: usize,
    },
    /// The session could not serve; the robot was held.
    Aborted { reason: AbortReason },
    /// The session was ended early (a signal, the robot side or an output failed, the time
    /// limit); the robot was held.
    Interrupted { by: Interruption },
}

/// Why a session was ended early, before it could end by its own rules.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Interruption {
    /// An output failed (a recording that cannot be written: a cell that records must not run on
    /// unrecorded).
    OutputFailed { error: OutputError },
    /// An input failed (the simulator, the ROS 2 node): the cell cannot see what it must.
    InputFailed { error: InputError },
    /// The robot side failed: the controller refused, aborted or did not answer a goal, or the
    /// execution monitor saw a deviation.
    RobotFailed { failure: RobotFailure },
    /// A stop was asked for.
    Stopped { signal: StopSignal },
    /// The session's time limit passed.
    TimeLimit { limit_s: f64 },
}

impl fmt::Display for Interruption {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::OutputFailed { error } => write!(f, "{error}"),
            Self::InputFailed { error } => write!(f, "{error}"),
            Self::RobotFailed { failure } => write!(f, "{failure}"),
            Self::Stopped { signal } => f.write_str(signal.name()),
            Self::TimeLimit { limit_s } => write!(f, "the time limit of {limit_s:.1} s passed"),
        }
    }
}

/// The stop a person or a service manager asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StopSignal {
    /// Ctrl-C.
    Interrupt,
    /// systemd, `docker stop`, `timeout`.
    Terminate,
}

impl StopSignal {
    /// The signal's name as the console and the session's end reason show it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Interrupt => "Ctrl-C (SIGINT)",
            Self::Terminate => "SIGTERM",
        }
    }
}

impl SessionEnd {
    /// The normal end: the operator left with the robot at home.
    pub fn is_normal(&self) -> bool {
        matches!(self, Self::OperatorLeft { .. })
    }
}

impl fmt::Display for SessionEnd {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::OperatorLeft { changes_refused } => write!(
                f,
                "operator left, robot at home ({changes_refused} change request(s) refused during \
                 the session)"
            ),
            Self::Aborted { reason } => write!(f, "aborted: {reason}"),
            Self::Interrupted { by } => write!(f, "interrupted: {by} (robot held)"),
        }
    }
}

/// Why the robot is held (the session goes on, and resumes by its rules once the reason clears).
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum HoldReason {
    /// Frames arrive, but no stereo pair sees the operator.
    NoStereoPair { cameras_fresh: usize },
    /// No camera frame is recent enough to move the robot by (every camera silent, or their clocks
    /// far from the cell's).
    CamerasLost { max_frame_age_ms: i64 },
    /// The robot side is not ready (its driver not configured or not controlling, its joint states
    /// stale).
    RobotNotReady { unready: RobotUnready },
    /// The trajectory locked for this session is not the one the files give now.
    LockChanged { locked: String, now: String },
    /// The locked trajectory no longer verifies against its files and approvals.
    LockNoLongerVerifies {
        #[serde(serialize_with = "as_text")]
        error: ProviderError,
    },
    /// Tracking is back, but the robot stopped between the locked trajectory's ends.
    StoppedBetweenEnds,
    /// The session was aborted or interrupted; the robot stays held.
    Ended { end: SessionEnd },
}

impl HoldReason {
    /// The execution monitor's hold, sent at once on a deviation: the session ends for it
    /// ([`Interruption::RobotFailed`]).
    pub fn deviation(deviation: ergocell_robot::monitor::Deviation) -> Self {
        Self::Ended {
            end: SessionEnd::Interrupted {
                by: Interruption::RobotFailed {
                    failure: RobotFailure::Deviation { deviation },
                },
            },
        }
    }

    /// What the operator is told on the display: what happened in their terms and what to do.
    /// The [`fmt::Display`] words are the integrator's (the hold command, the console, the
    /// recording).
    pub fn for_operator(&self) -> &'static str {
        match self {
            Self::NoStereoPair { .. } => "the cameras lost you: step back into view at the station",
            Self::CamerasLost { .. } => {
                "camera system fault: no recent camera pictures; wait, and call your supervisor if it stays"
            }
            Self::RobotNotReady { .. } => "the robot is not ready: call your supervisor",
            Self::LockChanged { .. } | Self::LockNoLongerVerifies { .. } => {
                "the robot's approved path was changed: call your supervisor"
            }
            Self::StoppedBetweenEnds => {
                "the robot stopped partway: a trained person must bring it home with the pendant"
            }
            Self::Ended { .. } => "the session stopped: call your supervisor",
        }
    }
}

impl fmt::Display for HoldReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoStereoPair { cameras_fresh } => write!(
                f,
                "fewer than one stereo pair sees the operator ({cameras_fresh} cameras fresh)"
            ),
            Self::CamerasLost { max_frame_age_ms } => write!(
                f,
                "cameras lost: no camera frame newer than {max_frame_age_ms} ms"
            ),
            Self::RobotNotReady { unready } => write!(f, "{unready}"),
            Self::Ended {
                end: SessionEnd::Aborted { reason },
            } => write!(f, "{reason}"),
            Self::Ended {
                end: SessionEnd::Interrupted { by },
            } => write!(f, "session interrupted: {by}"),
            Self::Ended { end } => write!(f, "{end}"),
            Self::LockChanged { locked, now } => write!(
                f,
                "the lock changed during the session ({locked} → {now}): staying held"
            ),
            Self::LockNoLongerVerifies { error } => write!(
                f,
                "the locked trajectory no longer verifies: {error}; staying held"
            ),
            Self::StoppedBetweenEnds => f.write_str(
                "tracking back, but the robot stopped between the locked trajectory's ends: bring \
                 it home with the pendant; the session resumes once /joint_states match home",
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The operator reads what happened in their terms and what to do: every hold has its own
    /// words, none of them the integrator's vocabulary, and a lost operator is told apart from
    /// cameras that stopped sending.
    #[test]
    fn the_operator_is_told_each_hold_in_their_terms() {
        let holds = [
            HoldReason::NoStereoPair { cameras_fresh: 4 },
            HoldReason::CamerasLost {
                max_frame_age_ms: 500,
            },
            HoldReason::RobotNotReady {
                unready: RobotUnready::JointStatesStale { timeout_s: 0.1 },
            },
            HoldReason::LockChanged {
                locked: "a".repeat(64),
                now: "b".repeat(64),
            },
            HoldReason::StoppedBetweenEnds,
            HoldReason::Ended {
                end: SessionEnd::Interrupted {
                    by: Interruption::Stopped {
                        signal: StopSignal::Terminate,
                    },
                },
            },
        ];
        let words: Vec<&str> = holds.iter().map(HoldReason::for_operator).collect();
        for (hold, said) in holds.iter().zip(&words) {
            for jargon in [
                "stereo",
                " ms",
                "joint states",
                "lock",
                "trajectory",
                "SIGTERM",
            ] {
                assert!(
                    !said.contains(jargon),
                    "{hold:?} tells the operator {said:?}"
                );
            }
            assert!(
                said.contains(": "),
                "{said:?}: what happened, then what to do"
            );
            assert_ne!(*said, hold.to_string());
        }
        let distinct: std::collections::BTreeSet<&str> = words.iter().copied().collect();
        assert_eq!(distinct.len(), words.len());
    }
}
