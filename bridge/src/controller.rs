//! The FollowJointTrajectory client's task: runs each goal the session sends on the controller and
//! reports what the controller said (accepted or rejected, feedback, the result), so the session can
//! hold the robot with the controller's own reason.
//!
//! One goal at a time, as the joint trajectory controller executes them: a new goal supersedes the
//! running one (the controller preempts it; its result is not waited for); a cancel request cancels
//! the running goal and waits for its result. A controller that does not answer the goal request
//! within the response timeout is reported as such: with no answer, the robot is not known to run
//! anything, and the session holds.

use std::time::Duration;

use futures::StreamExt as _;
use ros2_client::action::ActionClient;
pub use ros2_client::action_msgs::GoalStatusEnum;
use ros2_client::builtin_interfaces::Time;
use tokio::sync::mpsc;

use crate::action::{
    error_code_name, FeedbackView, FollowJointTrajectoryGoal, FollowJointTrajectoryResult,
};

/// The FollowJointTrajectory action client, Feedback layout `F`.
pub type FjtClient<F> = ActionClient<FollowJointTrajectoryGoal, FollowJointTrajectoryResult, F>;

/// What the session asks of the controller.
#[derive(Debug, Clone)]
pub enum ControllerCommand {
    /// Run this goal (`label` names it in reports, e.g. the leg).
    Execute {
        label: GoalLabel,
        goal: Box<FollowJointTrajectoryGoal>,
    },
    /// Cancel the running goal, if any.
    Cancel,
}

/// What a goal is about, in the reports and their messages: the leg as the message's constant
/// (`ControllerEvent::LEG_*`, for programs) and in words (for people; what `{label}` prints).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GoalLabel {
    pub leg_id: u8,
    pub text: String,
}

impl std::fmt::Display for GoalLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}

/// What the controller said.
#[derive(Debug, Clone, PartialEq)]
pub enum ControllerReport {
    Accepted {
        label: GoalLabel,
    },
    Rejected {
        label: GoalLabel,
    },
    /// No answer to the goal request within the timeout.
    NoResponse {
        label: GoalLabel,
        waited_s: f64,
    },
    /// The goal could not be sent or its result not read.
    Failed {
        label: GoalLabel,
        reason: String,
    },
    /// ergocell asked the controller to cancel the running goal.
    CancelRequested {
        label: GoalLabel,
    },
    /// Feedback: the first message, then every 25th.
    Feedback {
        label: GoalLabel,
        count: u64,
        max_error_rad: Option<f64>,
    },
    /// The goal's end: its status (succeeded, aborted, canceled, …) and the result. What it means
    /// for the session is the cell's rule (`ergocell_cell::session::GoalAnswer::failure`).
    Finished {
        label: GoalLabel,
        status: GoalStatusEnum,
        error_code: i32,
        error_string: String,
        feedback_count: u64,
    },
}

impl ControllerReport {
    /// Whether a goal is still running after this report (accepted, or sending feedback).
    pub fn goal_running(&self) -> bool {
        matches!(self, Self::Accepted { .. } | Self::Feedback { .. })
    }

    /// One line for the operator's terminal and the log.
    pub fn describe(&self) -> String {
        match self {
            Self::Accepted { label } => format!("goal accepted ({label})"),
            Self::Rejected { label } => format!("goal REJECTED ({label})"),
            Self::NoResponse { label, waited_s } => {
                format!("no answer to the goal ({label}) within {waited_s:.1} s")
            }
            Self::Failed { label, reason } => format!("goal ({label}) failed: {reason}"),
            Self::CancelRequested { label } => format!("cancel requested ({label})"),
            Self::Feedback {
                label,
                count,
                max_error_rad,
            } => format!(
                "feedback #{count} ({label}): largest joint error {}",
                max_error_rad.map_or_else(|| "not given".to_owned(), |e| format!("{e:.4} rad"))
            ),
            Self::Finished {
                label,
                status,
                error_code,
                error_string,
                feedback_count,
            } => format!(
                "goal {} ({label}): {} after {feedback_count} feedback messages",
                status_name(*status),
                result_text(*error_code, error_string)
            ),
        }
    }
}

/// `PATH_TOLERANCE_VIOLATED (-4): <error_string>` (no `: …` when the string is empty).
fn result_text(error_code: i32, error_string: &str) -> String {
    let name = error_code_name(error_code);
    if error_string.is_empty() {
        format!("{name} ({error_code})")
    } else {
        format!("{name} ({error_code}): {error_string}")
    }
}

/// The status in `action_msgs`' words, lower case: the `status` of the controller event.
pub fn status_name(s: GoalStatusEnum) -> &'static str {
    match s {
        GoalStatusEnum::Unknown => "unknown",
        GoalStatusEnum::Accepted => "accepted",
        GoalStatusEnum::Executing => "executing",
        GoalStatusEnum::Canceling => "canceling",
        GoalStatusEnum::Succeeded => "succeeded",
        GoalStatusEnum::Canceled => "canceled",
        GoalStatusEnum::Aborted => "aborted",
    }
}

/// Runs goals from `commands` on `client` until `commands` closes, reporting on `reports`.
pub async fn run_controller<F>(
    client: FjtClient<F>,
    mut commands: mpsc::UnboundedReceiver<ControllerCommand>,
    reports: mpsc::UnboundedSender<ControllerReport>,
    response_timeout: Duration,
) where
    F: ros2_client::Message + FeedbackView + 'static,
{
    let report = |r: ControllerReport| {
        // The session is gone when nobody listens: nothing left to tell.
        let _ = reports.send(r);
    };
    let mut pending: Option<ControllerCommand> = None;
    loop {
        let command = match pending.take() {
            Some(c) => c,
            None => match commands.recv().await {
                Some(c) => c,
                None => return,
            },
        };
        let ControllerCommand::Execute { label, goal } = command else {
            continue; // a cancel with no goal running
        };
        let goal_id =
            match tokio::time::timeout(response_timeout, client.async_send_goal(*goal)).await {
                Err(_) => {
                    report(ControllerReport::NoResponse {
                        label,
                        waited_s: response_timeout.as_secs_f64(),
                    });
                    continue;
                }
                Ok(Err(e)) => {
                    report(ControllerReport::Failed {
                        label,
                        reason: format!("sending the goal: {e:?}"),
                    });
                    continue;
                }
                Ok(Ok((_, response))) if !response.accepted => {
                    report(ControllerReport::Rejected { label });
                    continue;
                }
                Ok(Ok((id, _))) => {
                    report(ControllerReport::Accepted {
                        label: label.clone(),
                    });
                    id
                }
            };
        let result = client.async_request_result(goal_id);
        tokio::pin!(result);
        let feedback = client.feedback_stream(goal_id);
        tokio::pin!(feedback);
        let mut count = 0u64;
        loop {
            tokio::select! {
                r = &mut result => {
                    report(match r {
                        Ok((status, res)) => ControllerReport::Finished {
                            label: label.clone(),
                            status,
                            error_code: res.error_code,
                            error_string: res.error_string,
                            feedback_count: count,
                        },
                        Err(e) => ControllerReport::Failed {
                            label: label.clone(),
                            reason: format!("reading the result: {e:?}"),
                        },
                    });
                    break;
                }
                Some(f) = feedback.next() => {
                    if let Ok(f) = f {
                        count += 1;
                        if count == 1 || count.is_multiple_of(25) {
                            report(ControllerReport::Feedback {
                                label: label.clone(),
                                count,
                                max_error_rad: f.max_position_error_rad(),
                            });
                        }
                    }
                }
                c = commands.recv() => match c {
                    None => return,
                    Some(ControllerCommand::Cancel) => {
                        report(ControllerReport::CancelRequested { label: label.clone() });
                        let cancel = client.async_cancel_goal(goal_id, Time::ZERO);
                        if tokio::time::timeout(response_timeout, cancel).await.is_err() {
                            report(ControllerReport::Failed {
                                label: label.clone(),
                                reason: "the controller did not answer the cancel request".to_owned(),
                            });
                        }
                        // Keep waiting for the result (canceled).
                    }
                    Some(next @ ControllerCommand::Execute { .. }) => {
                        pending = Some(next);
                        break;
                    }
                },
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A finished goal is said with its status and its result code's name, number and words.
    #[test]
    fn a_finished_goal_is_described_with_its_status_and_result() {
        let label = GoalLabel {
            leg_id: crate::msg::ControllerEvent::LEG_TO_HANDOVER,
            text: "home → handover".to_owned(),
        };
        let aborted = ControllerReport::Finished {
            label,
            status: GoalStatusEnum::Aborted,
            error_code: -4,
            error_string: "joint_2 0.3 rad off".into(),
            feedback_count: 10,
        };
        assert_eq!(
            aborted.describe(),
            "goal aborted (home → handover): PATH_TOLERANCE_VIOLATED (-4): joint_2 0.3 rad off \
             after 10 feedback messages"
        );
        assert!(!aborted.goal_running());
    }
}
