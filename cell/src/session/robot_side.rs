//! The robot side's reports in the cell's own types, and the rules that decide what each one means
//! for the session. The ROS 2 backend turns its messages into a [`RobotReport`] and hands it to
//! [`CellLoop::report`](super::CellLoop::report); nothing about what a report means is decided
//! there.
//!
//! - **What counts as a controller failure** ([`GoalAnswer::failure`]): a goal rejected, unanswered,
//!   lost on the way, aborted, or ended with an error code. A canceled goal is not one (the cell
//!   cancels only when it holds). A failure ends the session, held ([`RobotFailure`]).
//! - **The execution monitor's verdict** ([`ergocell_robot::monitor::Deviation`], judged by
//!   `ergocell_robot::monitor::ExecutionMonitor`) is a failure too ([`RobotFailure::Deviation`]).
//! - **Readiness** ([`DriverState`], [`RobotUnready`]): the robot may move only while the KUKA
//!   driver is configured and controlling and its joint states are fresh; while either says no, the
//!   session holds and sends no goal, and resumes by its usual rules once both clear.
//!
//! Every reason carries its facts as fields; its words ([`fmt::Display`]) are for people, and no
//! program reads them back.

use std::fmt;

use ergocell_robot::monitor::Deviation;
use serde::Serialize;

use super::Leg;

/// A goal's final status as the controller reports it (`action_msgs/GoalStatus`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GoalStatus {
    Unknown,
    Accepted,
    Executing,
    Canceling,
    Succeeded,
    Canceled,
    Aborted,
}

impl GoalStatus {
    /// The status in the words of `action_msgs` (lower case): what the controller event carries.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Unknown => "unknown",
            Self::Accepted => "accepted",
            Self::Executing => "executing",
            Self::Canceling => "canceling",
            Self::Succeeded => "succeeded",
            Self::Canceled => "canceled",
            Self::Aborted => "aborted",
        }
    }
}

impl fmt::Display for GoalStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A joint trajectory controller's result code (`control_msgs/FollowJointTrajectory` result).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ResultCode {
    Successful,
    InvalidGoal,
    InvalidJoints,
    OldHeaderTimestamp,
    PathToleranceViolated,
    GoalToleranceViolated,
    /// A code the action does not define.
    Other {
        code: i32,
    },
}

impl ResultCode {
    pub const fn from_code(code: i32) -> Self {
        match code {
            0 => Self::Successful,
            -1 => Self::InvalidGoal,
            -2 => Self::InvalidJoints,
            -3 => Self::OldHeaderTimestamp,
            -4 => Self::PathToleranceViolated,
            -5 => Self::GoalToleranceViolated,
            code => Self::Other { code },
        }
    }

    pub const fn code(self) -> i32 {
        match self {
            Self::Successful => 0,
            Self::InvalidGoal => -1,
            Self::InvalidJoints => -2,
            Self::OldHeaderTimestamp => -3,
            Self::PathToleranceViolated => -4,
            Self::GoalToleranceViolated => -5,
            Self::Other { code } => code,
        }
    }
}

impl fmt::Display for ResultCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = match self {
            Self::Successful => "SUCCESSFUL",
            Self::InvalidGoal => "INVALID_GOAL",
            Self::InvalidJoints => "INVALID_JOINTS",
            Self::OldHeaderTimestamp => "OLD_HEADER_TIMESTAMP",
            Self::PathToleranceViolated => "PATH_TOLERANCE_VIOLATED",
            Self::GoalToleranceViolated => "GOAL_TOLERANCE_VIOLATED",
            Self::Other { .. } => "unknown error code",
        };
        write!(f, "{name} ({})", self.code())
    }
}

/// Which leg a report is about, in words ("home → handover"); "no leg" when it names none.
fn leg_words(leg: Option<Leg>) -> &'static str {
    leg.map_or("no leg", Leg::words)
}

/// What the controller answered about a goal (one leg of the locked trajectory).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum GoalAnswer {
    Accepted {
        leg: Option<Leg>,
    },
    Rejected {
        leg: Option<Leg>,
    },
    /// No answer to the goal request within `waited_s`.
    Unanswered {
        leg: Option<Leg>,
        waited_s: f64,
    },
    /// The goal could not be sent, its result not read, or a cancel not answered: the transport's
    /// own account of it.
    Lost {
        leg: Option<Leg>,
        transport: String,
    },
    /// The cell asked the controller to cancel the running goal (it holds).
    CancelRequested {
        leg: Option<Leg>,
    },
    /// Feedback while the goal runs.
    Feedback {
        leg: Option<Leg>,
        count: u64,
        max_error_rad: Option<f64>,
    },
    /// The goal's end.
    Finished {
        leg: Option<Leg>,
        status: GoalStatus,
        result: ResultCode,
        /// The controller's own words about the result (may be empty).
        error_string: String,
        feedback_count: u64,
    },
}

impl GoalAnswer {
    /// The rule for what a controller answer means: the failure that ends the session held, if
    /// this answer is one. Rejected, unanswered, lost and aborted goals are; so is a goal that ended
    /// with an error code. A canceled goal is not (the cell cancels only when it holds).
    pub fn failure(&self) -> Option<RobotFailure> {
        match self {
            Self::Rejected { leg } => Some(RobotFailure::GoalRejected { leg: *leg }),
            Self::Unanswered { leg, waited_s } => Some(RobotFailure::GoalUnanswered {
                leg: *leg,
                waited_s: *waited_s,
            }),
            Self::Lost { leg, transport } => Some(RobotFailure::GoalLost {
                leg: *leg,
                transport: transport.clone(),
            }),
            Self::Finished {
                leg,
                status,
                result,
                error_string,
                ..
            } if *status != GoalStatus::Canceled
                && (*status != GoalStatus::Succeeded || *result != ResultCode::Successful) =>
            {
                Some(RobotFailure::GoalEnded {
                    leg: *leg,
                    status: *status,
                    result: *result,
                    error_string: error_string.clone(),
                })
            }
            _ => None,
        }
    }

    /// Whether a goal is still running after this answer (accepted, or sending feedback).
    pub fn goal_running(&self) -> bool {
        matches!(self, Self::Accepted { .. } | Self::Feedback { .. })
    }
}

/// Why the robot side failed: the session ends, held.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RobotFailure {
    /// The execution monitor's verdict on a joint state (the backend held the robot at once).
    Deviation {
        deviation: Deviation,
    },
    GoalRejected {
        leg: Option<Leg>,
    },
    GoalUnanswered {
        leg: Option<Leg>,
        waited_s: f64,
    },
    GoalLost {
        leg: Option<Leg>,
        transport: String,
    },
    /// The goal ended other than succeeded with no error, or canceled.
    GoalEnded {
        leg: Option<Leg>,
        status: GoalStatus,
        result: ResultCode,
        error_string: String,
    },
}

impl fmt::Display for RobotFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Deviation { deviation } => write!(f, "{deviation}"),
            Self::GoalRejected { leg } => {
                write!(f, "the controller rejected the goal ({})", leg_words(*leg))
            }
            Self::GoalUnanswered { leg, waited_s } => write!(
                f,
                "the controller did not answer the goal ({}) within {waited_s:.1} s",
                leg_words(*leg)
            ),
            Self::GoalLost { leg, transport } => {
                write!(f, "the goal ({}) failed: {transport}", leg_words(*leg))
            }
            Self::GoalEnded {
                leg,
                status,
                result,
                error_string,
            } => {
                write!(
                    f,
                    "the controller {status} the goal ({}): {result}",
                    leg_words(*leg)
                )?;
                if error_string.is_empty() {
                    Ok(())
                } else {
                    write!(f, ": {error_string}")
                }
            }
        }
    }
}

/// How the KUKA driver stopped controlling (kuka_drivers' hardware events).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DriverStop {
    /// `CONTROL_STOPPED` (4): stopped by a user (the pendant, the smartHMI).
    ByUser,
    /// `ERROR` (6): stopped by an error (an e-stop, a safety stop, a drive fault).
    ByError,
}

/// A hardware event of the KUKA driver, as far as readiness is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum DriverEvent {
    ControlStarted,
    Stopped {
        by: DriverStop,
    },
    /// Any other event (command accepted, control mode switched, a code not known here).
    Other {
        code: u8,
    },
}

/// Why the robot may not move now (it is held and sent no goal until this clears).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RobotUnready {
    /// No `is_configured` from the driver yet.
    DriverSilent,
    DriverNotConfigured,
    /// Configured, but the driver has not said "control started".
    ControlNotStarted,
    DriverStopped {
        by: DriverStop,
    },
    /// No joint state for longer than `timeout_s`.
    JointStatesStale {
        timeout_s: f64,
    },
}

impl fmt::Display for RobotUnready {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::DriverSilent => f.write_str("waiting for the KUKA driver: no is_configured yet"),
            Self::DriverNotConfigured => f.write_str("the KUKA driver is not configured"),
            Self::ControlNotStarted => {
                f.write_str("waiting for the KUKA driver: control not started")
            }
            Self::DriverStopped {
                by: DriverStop::ByUser,
            } => f.write_str("the KUKA driver reports: stopped by user (4)"),
            Self::DriverStopped {
                by: DriverStop::ByError,
            } => f.write_str("the KUKA driver reports: stopped by error (6)"),
            Self::JointStatesStale { timeout_s } => {
                write!(f, "joint states stale (none for more than {timeout_s} s)")
            }
        }
    }
}

/// The KUKA driver's state, from its `is_configured` and hardware events: the readiness rule.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DriverState {
    configured: Option<bool>,
    controlling: bool,
    /// How it stopped, since the last "control started".
    stopped: Option<DriverStop>,
}

impl DriverState {
    pub fn on_configured(&mut self, configured: bool) {
        self.configured = Some(configured);
    }

    pub fn on_event(&mut self, event: DriverEvent) {
        match event {
            DriverEvent::ControlStarted => {
                self.controlling = true;
                self.stopped = None;
            }
            DriverEvent::Stopped { by } => {
                self.controlling = false;
                self.stopped = Some(by);
            }
            DriverEvent::Other { .. } => {}
        }
    }

    /// Why no goal may be sent now, if none may.
    pub fn unready(&self) -> Option<RobotUnready> {
        match self.configured {
            None => return Some(RobotUnready::DriverSilent),
            Some(false) => return Some(RobotUnready::DriverNotConfigured),
            Some(true) => {}
        }
        if let Some(by) = self.stopped {
            return Some(RobotUnready::DriverStopped { by });
        }
        (!self.controlling).then_some(RobotUnready::ControlNotStarted)
    }
}

/// A report from the robot side, in the cell's types.
#[derive(Debug, Clone, PartialEq)]
pub enum RobotReport {
    /// The controller's answer about a goal.
    Goal(GoalAnswer),
    /// The execution monitor found the execution off the locked trajectory (the backend held the
    /// robot at once, without waiting for the loop).
    Deviation(Deviation),
    /// No joint state for longer than `timeout_s`.
    JointStatesStale { timeout_s: f64 },
    /// Joint states again after a stale spell.
    JointStatesBack,
    /// The driver's `is_configured`.
    DriverConfigured(bool),
    /// The driver's hardware event.
    DriverEvent(DriverEvent),
}

/// What a report changed, for the backend to say and publish.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ReportEffect {
    /// The session ends, held, for this (the first failure is the reason; later ones are kept
    /// here but change nothing).
    pub failure: Option<RobotFailure>,
    /// The driver's readiness changed to this (`None`: ready).
    pub driver_readiness: Option<Option<RobotUnready>>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn finished(status: GoalStatus, code: i32) -> GoalAnswer {
        GoalAnswer::Finished {
            leg: Some(Leg::ToHandover),
            status,
            result: ResultCode::from_code(code),
            error_string: String::new(),
            feedback_count: 3,
        }
    }

    /// Which answers are failures, row by row: the rule the session ends by.
    #[test]
    fn rejected_unanswered_lost_aborted_or_errored_goals_are_failures_and_a_cancel_is_not() {
        let leg = Some(Leg::ToHome);
        let rows: Vec<(GoalAnswer, Option<RobotFailure>)> = vec![
            (GoalAnswer::Accepted { leg }, None),
            (
                GoalAnswer::Rejected { leg },
                Some(RobotFailure::GoalRejected { leg }),
            ),
            (
                GoalAnswer::Unanswered { leg, waited_s: 5.0 },
                Some(RobotFailure::GoalUnanswered { leg, waited_s: 5.0 }),
            ),
            (
                GoalAnswer::Lost {
                    leg,
                    transport: "reading the result: timeout".to_owned(),
                },
                Some(RobotFailure::GoalLost {
                    leg,
                    transport: "reading the result: timeout".to_owned(),
                }),
            ),
            (GoalAnswer::CancelRequested { leg }, None),
            (
                GoalAnswer::Feedback {
                    leg,
                    count: 25,
                    max_error_rad: Some(0.001),
                },
                None,
            ),
            (finished(GoalStatus::Succeeded, 0), None),
            (finished(GoalStatus::Canceled, 0), None),
            (finished(GoalStatus::Canceled, -4), None),
            (
                finished(GoalStatus::Succeeded, -5),
                Some(RobotFailure::GoalEnded {
                    leg: Some(Leg::ToHandover),
                    status: GoalStatus::Succeeded,
                    result: ResultCode::GoalToleranceViolated,
                    error_string: String::new(),
                }),
            ),
            (
                finished(GoalStatus::Aborted, -4),
                Some(RobotFailure::GoalEnded {
                    leg: Some(Leg::ToHandover),
                    status: GoalStatus::Aborted,
                    result: ResultCode::PathToleranceViolated,
                    error_string: String::new(),
                }),
            ),
            (
                finished(GoalStatus::Aborted, 0),
                Some(RobotFailure::GoalEnded {
                    leg: Some(Leg::ToHandover),
                    status: GoalStatus::Aborted,
                    result: ResultCode::Successful,
                    error_string: String::new(),
                }),
            ),
        ];
        for (answer, expected) in rows {
            assert_eq!(answer.failure(), expected, "{answer:?}");
        }
    }

    #[test]
    fn result_codes_round_trip_and_unknown_codes_keep_their_number() {
        for code in -7..=2 {
            assert_eq!(ResultCode::from_code(code).code(), code);
        }
        assert_eq!(ResultCode::from_code(-9), ResultCode::Other { code: -9 });
    }

    /// Readiness needs a configured driver that has started control and not stopped since.
    #[test]
    fn the_driver_is_ready_only_configured_and_controlling() {
        let mut d = DriverState::default();
        assert_eq!(d.unready(), Some(RobotUnready::DriverSilent));
        d.on_event(DriverEvent::ControlStarted);
        assert_eq!(d.unready(), Some(RobotUnready::DriverSilent));
        d.on_configured(false);
        assert_eq!(d.unready(), Some(RobotUnready::DriverNotConfigured));
        d.on_configured(true);
        assert_eq!(d.unready(), None);
        d.on_event(DriverEvent::Other { code: 5 });
        assert_eq!(d.unready(), None);
        for by in [DriverStop::ByUser, DriverStop::ByError] {
            d.on_event(DriverEvent::Stopped { by });
            assert_eq!(d.unready(), Some(RobotUnready::DriverStopped { by }));
            d.on_event(DriverEvent::ControlStarted);
            assert_eq!(d.unready(), None);
        }
        let mut fresh = DriverState::default();
        fresh.on_configured(true);
        assert_eq!(fresh.unready(), Some(RobotUnready::ControlNotStarted));
    }
}
