//! The robot over ROS 2: commands out on the controller's trajectory topic or as FollowJointTrajectory
//! goals, positions in from `/joint_states`, and each report of the robot side (the controller's
//! answers, the monitor's notes, the KUKA driver's state) turned into the cell's
//! [`ergocell_cell::session::RobotReport`] ([`RobotInput`], [`feed`]). What a report means for the
//! session (a failure, readiness) is the cell's rule (`ergocell_cell::session::robot_side`), not
//! decided here.
//!
//! The transport is behind [`TrajectoryTopic`] (a ROS 2 publisher on a cell; a fake in tests) and
//! the FollowJointTrajectory task's channel, so the path is tested without DDS
//! (`tests/failure_table.rs`).

use std::sync::{Arc, Mutex};

use ergocell_bridge::action::GoalTolerances;
use ergocell_bridge::controller::GoalStatusEnum;
use ergocell_bridge::controller::{ControllerCommand, ControllerReport, GoalLabel};
use ergocell_bridge::msg::{
    ControllerEvent, ControllerEventKind, HardwareEvent, JointState, JointTrajectory,
};
use ergocell_bridge::transport::{Publisher, RosConfig};
use ergocell_cell::session::{
    BackendError, CellLoop, CellOutputs, DriverEvent, DriverStop, ExecutionWatch, GoalAnswer,
    GoalStatus, Leg, LegTrajectory, ResultCode, RobotCommand, RobotReport, RobotSink, RobotUnready,
};
use ergocell_robot::monitor::{MonitorCaps, MonitorLimits};

use crate::messages;
use crate::monitor::MonitorNote;

/// The controller's joint trajectory topic: every command in topic mode, and in action mode the
/// empty trajectory of a hold too (it overrides any active goal), beside the cancel.
pub trait TrajectoryTopic: Send + Sync {
    fn publish(&self, message: JointTrajectory) -> Result<(), BackendError>;

    /// Blocks until every command published so far is acknowledged by every matched reliable
    /// reader (the controller), or `max_wait` has passed: `true` when all were, and at once when no
    /// reliable reader is matched. A publish only queues the sample; a process that exits right
    /// after its last hold must wait here, or the hold may never leave the machine.
    fn delivered(&self, max_wait: std::time::Duration) -> Result<bool, BackendError>;
}

impl TrajectoryTopic for Publisher<JointTrajectory> {
    fn publish(&self, message: JointTrajectory) -> Result<(), BackendError> {
        Publisher::publish(self, message).map_err(|e| BackendError::Transport {
            channel: "ROS 2 joint trajectory",
            detail: format!("{e:?}"),
        })
    }

    fn delivered(&self, max_wait: std::time::Duration) -> Result<bool, BackendError> {
        Publisher::wait_for_acknowledgments(self, max_wait).map_err(|e| BackendError::Transport {
            channel: "ROS 2 joint trajectory",
            detail: format!("{e:?}"),
        })
    }
}

/// The robot side's events, published on `/ergocell/controller_events` and recorded, in order: the
/// robot sink and the monitor push, the cell's outputs drain.
pub type EventQueue = Arc<Mutex<Vec<ControllerEvent>>>;

/// The execution watch shared between the robot sink (which starts each leg) and the monitor task
/// (which judges every sample).
pub type SharedMonitor = Arc<Mutex<ExecutionWatch>>;

/// The controller's command port: its trajectory topic and, in action mode, the FollowJointTrajectory
/// task's channel.
pub struct CommandPort<T: TrajectoryTopic> {
    topic: Arc<T>,
    action: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
}

impl<T: TrajectoryTopic> CommandPort<T> {
    /// Holds the robot: `message` is the hold's empty trajectory
    /// ([`messages::command_message`] of a [`RobotCommand::Hold`]). In action mode the goal is
    /// cancelled too, so that either stops the robot: the cancel ends the goal the controller
    /// reports on, the empty trajectory overrides whatever it runs.
    pub fn hold(&self, message: JointTrajectory) -> Result<(), BackendError> {
        let cancel = self.action.as_ref().map(|commands| {
            commands
                .send(ControllerCommand::Cancel)
                .map_err(|_| controller_task_stopped())
        });
        self.topic.publish(message)?;
        cancel.unwrap_or(Ok(()))
    }
}

/// The robot over ROS 2, as the session's [`RobotSink`].
pub struct RosRobot<T: TrajectoryTopic = Publisher<JointTrajectory>> {
    topic: Arc<T>,
    /// Action mode: the FollowJointTrajectory task's commands.
    action: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
    /// The newest joint state (the monitor task writes it).
    latest: Arc<Mutex<Option<JointState>>>,
    /// The `[ros]` settings (the caps on the lock's tolerances and limits, the monitor switch).
    ros: RosConfig,
    monitor: SharedMonitor,
    events: EventQueue,
    /// A goal the controller accepted and has not finished.
    goal_outstanding: bool,
    /// After the monitor's deviation: sample arrival → cancel and hold published, milliseconds.
    held_after_ms: Option<f64>,
}

impl<T: TrajectoryTopic> RosRobot<T> {
    /// The robot on `topic`, with FollowJointTrajectory goals through `action` when the cell uses the
    /// action interface.
    pub fn new(
        topic: Arc<T>,
        action: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
        ros: RosConfig,
    ) -> Self {
        let timeout_s = ros.joint_state_timeout_s;
        Self {
            topic,
            action,
            latest: Arc::new(Mutex::new(None)),
            ros,
            monitor: Arc::new(Mutex::new(ExecutionWatch::new(timeout_s))),
            events: Arc::new(Mutex::new(Vec::new())),
            goal_outstanding: false,
            held_after_ms: None,
        }
    }

    /// Waits (at most `max_wait`) until every matched reliable reader of the trajectory topic (the
    /// controller) has acknowledged every command sent so far ([`TrajectoryTopic::delivered`]):
    /// called before the program exits, so that its last hold reaches the controller. `true` at once
    /// when no reliable reader is matched. In action mode the hold's empty trajectory is on the same
    /// topic; the goal's cancel goes through the action client and is not waited for here.
    pub fn commands_delivered(&self, max_wait: std::time::Duration) -> Result<bool, BackendError> {
        self.topic.delivered(max_wait)
    }

    /// After the monitor's deviation: how long from the bad sample's arrival to the hold, ms.
    pub fn held_after_ms(&self) -> Option<f64> {
        self.held_after_ms
    }

    /// The controller's command port, which every hold goes through (the session's, and the
    /// monitor task's at once on a deviation).
    pub fn port(&self) -> CommandPort<T> {
        CommandPort {
            topic: self.topic.clone(),
            action: self.action.clone(),
        }
    }

    pub fn monitor(&self) -> SharedMonitor {
        self.monitor.clone()
    }

    pub fn latest(&self) -> Arc<Mutex<Option<JointState>>> {
        self.latest.clone()
    }

    pub fn events(&self) -> EventQueue {
        self.events.clone()
    }

    fn push(&self, event: ControllerEvent) {
        if let Ok(mut q) = self.events.lock() {
            q.push(event);
        }
    }

    fn publish(&self, message: JointTrajectory) -> Result<(), BackendError> {
        self.topic.publish(message)
    }

    /// The leg's path tolerances: the lock's (derived when it was validated, signed off with it),
    /// each at most `[ros] path_tolerance_rad`. A leg without them is not sent.
    fn path_tolerances(&self, trajectory: &LegTrajectory) -> Result<Vec<f64>, BackendError> {
        let t = &trajectory.path_tolerance_rad;
        if t.len() != trajectory.joint_names.len() || !t.iter().all(|v| v.is_finite() && *v > 0.0) {
            return Err(BackendError::PathTolerances {
                given: t.clone(),
                joints: trajectory.joint_names.len(),
            });
        }
        let cap = self.ros.path_tolerance_rad;
        Ok(t.iter().map(|v| v.min(cap)).collect())
    }

    /// The leg's other monitor limits and goal tolerances: the lock's, tightened by what `[ros]`
    /// sets ([`MonitorLimits::tightened`]: never loosened). A leg whose limits are out of range is
    /// not sent.
    pub fn monitor_limits(
        &self,
        trajectory: &LegTrajectory,
    ) -> Result<MonitorLimits, BackendError> {
        trajectory
            .monitor
            .check()
            .map_err(|cause| BackendError::Monitor { cause })?;
        Ok(trajectory.monitor.tightened(&MonitorCaps {
            goal_tolerance_rad: self.ros.goal_tolerance_rad,
            goal_time_tolerance_s: self.ros.goal_time_tolerance_s,
            rest_tolerance_rad: self.ros.rest_tolerance_rad,
            stop_time_s: self.ros.stop_time_s,
        }))
    }

    /// Starts watching `trajectory` (a leg just sent).
    fn watch_leg(
        &mut self,
        now_nanos: i64,
        label: &str,
        trajectory: &LegTrajectory,
        path_rad: &[f64],
        limits: &MonitorLimits,
    ) -> Result<(), BackendError> {
        let mut guard = self
            .monitor
            .lock()
            .map_err(|_| BackendError::MonitorTaskFailed)?;
        guard
            .leg_sent(now_nanos, label, trajectory, path_rad, limits)
            .map_err(|cause| BackendError::Monitor { cause })
    }

    fn with_monitor(&self, f: impl FnOnce(&mut ExecutionWatch)) {
        if let Ok(mut g) = self.monitor.lock() {
            f(&mut g);
        }
    }
}

/// A leg as the controller's reports and events name it: the message's constant and the words.
pub fn leg_label(leg: Leg) -> GoalLabel {
    let leg_id = match leg {
        Leg::ToHandover => ControllerEvent::LEG_TO_HANDOVER,
        Leg::ToHome => ControllerEvent::LEG_TO_HOME,
    };
    GoalLabel {
        leg_id,
        text: leg.words().to_owned(),
    }
}

/// Not about a leg (the monitor's and the driver's events).
pub fn no_leg() -> GoalLabel {
    GoalLabel {
        leg_id: ControllerEvent::LEG_NONE,
        text: String::new(),
    }
}

/// Joint values in radians as printed and published: "0.0187, 0.0194, …".
pub fn radians_list(values: &[f64]) -> String {
    values
        .iter()
        .map(|t| format!("{t:.4}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The FollowJointTrajectory task is gone: nothing can be sent to the controller.
fn controller_task_stopped() -> BackendError {
    BackendError::ControllerTaskStopped
}

/// A controller event of `kind` about `leg` with `text`.
pub fn controller_event(
    now_nanos: i64,
    kind: ControllerEventKind,
    leg: &GoalLabel,
    text: String,
) -> ControllerEvent {
    ControllerEvent {
        header: ergocell_bridge::msg::Header::new(now_nanos, ""),
        kind: kind.name().to_owned(),
        leg: leg.text.clone(),
        leg_id: leg.leg_id,
        text,
        max_error: f64::NAN,
        ..ControllerEvent::default()
    }
}

impl<T: TrajectoryTopic> RobotSink for RosRobot<T> {
    /// A goal is running on the controller (accepted, no result yet).
    fn goal_outstanding(&self) -> bool {
        self.goal_outstanding
    }

    fn send(&mut self, now_nanos: i64, command: &RobotCommand) -> Result<(), BackendError> {
        let message = messages::command_message(command, now_nanos);
        match command {
            RobotCommand::Execute {
                leg,
                lock_sha256: _,
                trajectory,
            } => {
                let label = leg_label(*leg);
                // No tolerances, no monitor: the leg is not sent (the robot does not move).
                let path_rad = self.path_tolerances(trajectory)?;
                let limits = self.monitor_limits(trajectory)?;
                if self.ros.monitor_execution {
                    self.watch_leg(now_nanos, &label.text, trajectory, &path_rad, &limits)?;
                }
                match &self.action {
                    None => {
                        self.publish(message)?;
                        // The controller starts a topic trajectory on receipt.
                        self.with_monitor(|m| m.leg_started(now_nanos));
                    }
                    Some(commands) => commands
                        .send(ControllerCommand::Execute {
                            label: label.clone(),
                            goal: Box::new(ergocell_bridge::action::goal(
                                message,
                                &path_rad,
                                GoalTolerances {
                                    path_position_rad: self.ros.path_tolerance_rad,
                                    goal_position_rad: limits.goal_tolerance_rad,
                                    goal_time_s: limits.goal_time_tolerance_s,
                                },
                            )),
                        })
                        .map_err(|_| controller_task_stopped())?,
                }
                self.push(controller_event(
                    now_nanos,
                    ControllerEventKind::GoalSent,
                    &label,
                    format!(
                        "{} points over {:.2} s; path tolerances {} rad",
                        trajectory.points.len(),
                        trajectory.duration_s(),
                        radians_list(&path_rad)
                    ),
                ));
                Ok(())
            }
            RobotCommand::Hold { .. } => {
                self.with_monitor(|m| m.held(now_nanos));
                self.port().hold(message)
            }
        }
    }

    fn joint_positions(&mut self, _now_nanos: i64, names: &[String]) -> Option<Vec<f64>> {
        self.latest
            .lock()
            .ok()?
            .as_ref()
            .and_then(|js| js.positions_for(names))
    }
}

/// The cell loop on the ROS 2 robot: with `[ros] driver_state`, the robot may move only once the
/// KUKA driver says it is configured and controlling (`CellLoop::with_driver_state`). `run` and the
/// failure table build it here, so neither can forget it.
pub fn cell_loop<T: TrajectoryTopic, O: CellOutputs>(
    machine: ergocell_cell::session::SessionMachine,
    robot: RosRobot<T>,
    outputs: O,
) -> CellLoop<RosRobot<T>, O> {
    let driver_state = robot.ros.driver_state;
    let cell = CellLoop::new(machine, robot, outputs);
    if driver_state {
        cell.with_driver_state()
    } else {
        cell
    }
}

/// The leg a goal's label names (its `ControllerEvent::LEG_*` constant).
pub fn leg_of(label: &GoalLabel) -> Option<Leg> {
    match label.leg_id {
        ControllerEvent::LEG_TO_HANDOVER => Some(Leg::ToHandover),
        ControllerEvent::LEG_TO_HOME => Some(Leg::ToHome),
        _ => None,
    }
}

/// `action_msgs`' goal status in the cell's type.
pub fn goal_status(status: GoalStatusEnum) -> GoalStatus {
    match status {
        GoalStatusEnum::Unknown => GoalStatus::Unknown,
        GoalStatusEnum::Accepted => GoalStatus::Accepted,
        GoalStatusEnum::Executing => GoalStatus::Executing,
        GoalStatusEnum::Canceling => GoalStatus::Canceling,
        GoalStatusEnum::Succeeded => GoalStatus::Succeeded,
        GoalStatusEnum::Canceled => GoalStatus::Canceled,
        GoalStatusEnum::Aborted => GoalStatus::Aborted,
    }
}

/// The FollowJointTrajectory task's report in the cell's types (what it means is the cell's rule).
pub fn goal_answer(report: &ControllerReport) -> GoalAnswer {
    match report {
        ControllerReport::Accepted { label } => GoalAnswer::Accepted { leg: leg_of(label) },
        ControllerReport::Rejected { label } => GoalAnswer::Rejected { leg: leg_of(label) },
        ControllerReport::NoResponse { label, waited_s } => GoalAnswer::Unanswered {
            leg: leg_of(label),
            waited_s: *waited_s,
        },
        ControllerReport::Failed { label, reason } => GoalAnswer::Lost {
            leg: leg_of(label),
            transport: reason.clone(),
        },
        ControllerReport::CancelRequested { label } => {
            GoalAnswer::CancelRequested { leg: leg_of(label) }
        }
        ControllerReport::Feedback {
            label,
            count,
            max_error_rad,
        } => GoalAnswer::Feedback {
            leg: leg_of(label),
            count: *count,
            max_error_rad: *max_error_rad,
        },
        ControllerReport::Finished {
            label,
            status,
            error_code,
            error_string,
            feedback_count,
        } => GoalAnswer::Finished {
            leg: leg_of(label),
            status: goal_status(*status),
            result: ResultCode::from_code(*error_code),
            error_string: error_string.clone(),
            feedback_count: *feedback_count,
        },
    }
}

/// kuka_drivers' hardware event in the cell's type.
pub fn driver_event(e: &HardwareEvent) -> DriverEvent {
    match e.event {
        HardwareEvent::CONTROL_STARTED => DriverEvent::ControlStarted,
        HardwareEvent::CONTROL_STOPPED => DriverEvent::Stopped {
            by: DriverStop::ByUser,
        },
        HardwareEvent::ERROR => DriverEvent::Stopped {
            by: DriverStop::ByError,
        },
        code => DriverEvent::Other { code },
    }
}

/// What the robot side reports to the cell loop.
#[derive(Debug)]
pub enum RobotInput {
    /// The execution monitor's task.
    Monitor(MonitorNote),
    /// The FollowJointTrajectory task: the controller's answer, feedback or result.
    Controller(ControllerReport),
    /// The driver's `is_configured`.
    DriverConfigured(bool),
    /// The driver's hardware event.
    DriverEvent(HardwareEvent),
}

/// The robot side's input in the cell's types: the reports whose meaning is the cell's rule
/// (`CellLoop::report`, applied by the session driver), a controller event kept for every report
/// worth keeping, and the line to print for a person, if any. A joint-state sample is the monitor
/// task's alone: no report.
pub fn reports_of<T: TrajectoryTopic>(
    robot: &mut RosRobot<T>,
    now_nanos: i64,
    input: RobotInput,
) -> (Vec<RobotReport>, Option<String>) {
    match input {
        RobotInput::Monitor(note) => match note {
            MonitorNote::Sample(..) => (Vec::new(), None),
            MonitorNote::Deviation {
                deviation,
                event,
                held_after_ms,
            } => {
                let line = format!(
                    "{} — cancelled and held {held_after_ms:.3} ms after the sample arrived",
                    event.text
                );
                robot.held_after_ms = Some(held_after_ms);
                robot.push(event);
                (vec![RobotReport::Deviation(deviation)], Some(line))
            }
            MonitorNote::Stale { event, timeout_s } => {
                let line = event.text.clone();
                robot.push(event);
                (
                    vec![RobotReport::JointStatesStale { timeout_s }],
                    Some(line),
                )
            }
            MonitorNote::Back(event) => {
                robot.push(event);
                (vec![RobotReport::JointStatesBack], None)
            }
        },
        RobotInput::Controller(report) => {
            tracing::info!(?report, "controller");
            robot.goal_outstanding = report.goal_running();
            if matches!(report, ControllerReport::Accepted { .. }) {
                // The controller starts an accepted goal now.
                robot.with_monitor(|m| m.leg_started(now_nanos));
            }
            let line = format!("controller: {}", report.describe());
            let report = RobotReport::Goal(goal_answer(&report));
            if let Some(event) = messages::robot_report_message(now_nanos, &report) {
                robot.push(event);
            }
            (vec![report], Some(line))
        }
        RobotInput::DriverConfigured(configured) => {
            (vec![RobotReport::DriverConfigured(configured)], None)
        }
        RobotInput::DriverEvent(e) => (
            vec![RobotReport::DriverEvent(driver_event(&e))],
            Some(format!("driver: {} ({})", e.describe(), e.robot_name)),
        ),
    }
}

/// [`reports_of`] applied to `cell` at once (a test's or a tool's own loop; `run` hands the
/// reports to the session driver): the lines to print.
pub fn feed<T: TrajectoryTopic, O: CellOutputs>(
    cell: &mut CellLoop<RosRobot<T>, O>,
    now_nanos: i64,
    input: RobotInput,
) -> Option<String> {
    let (reports, line) = reports_of(cell.robot_mut(), now_nanos, input);
    let mut lines: Vec<String> = line.into_iter().collect();
    for report in reports {
        let effect = cell.report(report);
        lines.extend(announce_readiness(
            cell.robot(),
            now_nanos,
            effect.driver_readiness,
        ));
    }
    (!lines.is_empty()).then(|| lines.join("\n  "))
}

/// The driver's readiness, when it changed (`Some(None)`: now ready), published as a controller
/// event and said.
pub fn announce_driver<T: TrajectoryTopic, O: CellOutputs>(
    cell: &mut CellLoop<RosRobot<T>, O>,
    now_nanos: i64,
    readiness: Option<Option<RobotUnready>>,
) -> Option<String> {
    announce_readiness(cell.robot(), now_nanos, readiness)
}

/// [`announce_driver`] on the robot port alone.
pub fn announce_readiness<T: TrajectoryTopic>(
    robot: &RosRobot<T>,
    now_nanos: i64,
    readiness: Option<Option<RobotUnready>>,
) -> Option<String> {
    let why = readiness?;
    let event = messages::driver_readiness_message(now_nanos, why.as_ref());
    let text = event.text.clone();
    robot.push(event);
    Some(format!("driver: {text}"))
}

/// The FollowJointTrajectory task's command channel, `None` with the topic interface.
pub type ControllerCommands = Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>;

/// The FollowJointTrajectory task (with `robot_interface = "action"`), spawned on the current tokio
/// runtime with the Feedback layout of `[ros] distro`: its command channel for [`RosRobot::new`] and
/// its reports for the station. With the topic interface there is no task: no channel, and reports
/// that never come.
pub fn spawn_controller(
    node: &mut ergocell_bridge::transport::RosNode,
    ros: &RosConfig,
) -> Result<
    (
        ControllerCommands,
        tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
    ),
    ergocell_bridge::BridgeError,
> {
    use ergocell_bridge::action::{FeedbackLayout, FeedbackWithIndex, FeedbackWithoutIndex};
    use ergocell_bridge::controller::run_controller;
    let (reports_tx, reports) = tokio::sync::mpsc::unbounded_channel::<ControllerReport>();
    if ros.robot_interface == ergocell_bridge::transport::RobotInterface::Topic {
        return Ok((None, reports));
    }
    let (tx, rx) = tokio::sync::mpsc::unbounded_channel();
    let timeout = std::time::Duration::from_secs(5);
    let name = &ros.follow_joint_trajectory_action;
    if ros.feedback_layout() == Some(FeedbackLayout::WithIndex) {
        let client = node.follow_joint_trajectory_client::<FeedbackWithIndex>(name)?;
        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
    } else {
        let client = node.follow_joint_trajectory_client::<FeedbackWithoutIndex>(name)?;
        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
    }
    Ok((Some(tx), reports))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;
    use ergocell_cell::session::LegPoint;

    struct NoTopic;

    impl TrajectoryTopic for NoTopic {
        fn publish(&self, _: JointTrajectory) -> Result<(), BackendError> {
            Ok(())
        }

        fn delivered(&self, _: std::time::Duration) -> Result<bool, BackendError> {
            Ok(true)
        }
    }

    fn leg(monitor: MonitorLimits) -> LegTrajectory {
        let point = |t: f64, q: f64| LegPoint {
            positions_rad: vec![q, q],
            velocities_rad_s: vec![0.0, 0.0],
            accelerations_rad_s2: vec![0.0, 0.0],
            time_from_start_s: t,
        };
        LegTrajectory {
            joint_names: vec!["joint_1".into(), "joint_2".into()],
            points: vec![point(0.0, 0.0), point(1.0, 0.1)],
            path_tolerance_rad: vec![0.02, 0.03],
            monitor,
        }
    }

    /// The monitor's limits and the goal's tolerances are the lock's; `[ros]` may lower each one it
    /// names and a looser `[ros]` value leaves the lock's. The lock's own values (not the defaults)
    /// are chosen so that reading them from anywhere else shows. A leg with a limit out of range is
    /// not sent.
    #[test]
    fn the_monitor_and_the_goal_take_the_locks_limits_tightened_never_loosened_by_ros() {
        let locked = MonitorLimits {
            goal_tolerance_rad: 0.004,
            goal_time_tolerance_s: 0.7,
            rest_tolerance_rad: 0.006,
            stall_window_s: 0.2,
            stop_time_s: 0.4,
        };
        // the stall window is the lock's alone: `[ros]` cannot name it
        let tighter = MonitorLimits {
            goal_tolerance_rad: 0.002,
            goal_time_tolerance_s: 0.3,
            rest_tolerance_rad: 0.003,
            stall_window_s: locked.stall_window_s,
            stop_time_s: 0.25,
        };
        let keys = |m: &MonitorLimits| {
            format!(
                "goal_tolerance_rad = {}\ngoal_time_tolerance_s = {}\nrest_tolerance_rad = {}\n\
                 stop_time_s = {}\n",
                m.goal_tolerance_rad, m.goal_time_tolerance_s, m.rest_tolerance_rad, m.stop_time_s
            )
        };
        let looser = MonitorLimits {
            goal_tolerance_rad: 0.5,
            goal_time_tolerance_s: 5.0,
            rest_tolerance_rad: 0.5,
            stall_window_s: locked.stall_window_s,
            stop_time_s: 4.0,
        };
        for (extra, expected) in [
            (String::new(), locked),
            (keys(&tighter), tighter),
            (keys(&looser), locked),
        ] {
            let ros = RosConfig::from_cell_toml(&format!(
                "[ros]\ncameras = [\"a\"]\nrobot_interface = \"action\"\n{extra}"
            ))
            .unwrap();
            let (tx, mut rx) = tokio::sync::mpsc::unbounded_channel();
            let mut robot = RosRobot::new(Arc::new(NoTopic), Some(tx), ros);
            robot
                .send(
                    0,
                    &RobotCommand::Execute {
                        leg: Leg::ToHandover,
                        lock_sha256: "a".repeat(64),
                        trajectory: leg(locked),
                    },
                )
                .unwrap();
            let settings = robot
                .monitor()
                .lock()
                .unwrap()
                .monitor()
                .unwrap()
                .settings()
                .clone();
            assert_eq!(settings, expected.settings(vec![0.02, 0.03]), "{extra}");
            let Ok(ControllerCommand::Execute { goal, .. }) = rx.try_recv() else {
                panic!("no goal sent");
            };
            let goal_rad: Vec<f64> = goal.goal_tolerance.iter().map(|t| t.position).collect();
            assert_eq!(goal_rad, vec![expected.goal_tolerance_rad; 2]);
            // a Duration holds whole nanoseconds
            assert!(
                (goal.goal_time_tolerance.as_secs_f64() - expected.goal_time_tolerance_s).abs()
                    < 1e-9
            );
            let path: Vec<f64> = goal.path_tolerance.iter().map(|t| t.position).collect();
            assert_eq!(path, vec![0.02, 0.03]);
        }
        let ros =
            RosConfig::from_cell_toml("[ros]\ncameras = [\"a\"]\nrobot_interface = \"action\"\n")
                .unwrap();
        let (tx, mut rx) = tokio::sync::mpsc::unbounded_channel();
        let mut robot = RosRobot::new(Arc::new(NoTopic), Some(tx), ros);
        let bad = MonitorLimits {
            goal_time_tolerance_s: f64::NAN,
            ..locked
        };
        let sent = robot.send(
            0,
            &RobotCommand::Execute {
                leg: Leg::ToHandover,
                lock_sha256: "a".repeat(64),
                trajectory: leg(bad),
            },
        );
        assert!(sent.is_err());
        assert!(rx.try_recv().is_err(), "nothing sent");
    }
}
