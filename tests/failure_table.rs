//! The failure table of `docs/safety.md` ("What the cell does on each fault"), row by row, as deterministic tests of the
//! cell loop with the ROS 2 backend's robot side on a fake transport and an injected clock — no DDS.
//!
//! Each test runs a twin session (a 1.75 m operator, class c2) through `ergocell_cell`'s `CellLoop`
//! with `ergocell_ros_backend`'s `RosRobot` (its trajectory topic a fake that keeps what it was sent;
//! in action mode the FollowJointTrajectory task's channel read by the test) and the execution
//! monitor's `Judge` fed 250 Hz joint states from a simulated controller (`DummyRobot` following the
//! commands), which a fault then bends. The rclpy and Cyclone DDS stages of CI are the end-to-end
//! proof through real DDS; these pin each row's rule.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;
use std::sync::{Arc, Mutex};

mod common;

use ergocell::session::dummy::DummyRobot;
use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    AfterSession, CellLoop, DriverStop, ExitStatus, GoalStatus, HoldReason, Interruption, Leg,
    ResultCode, RobotCommand, RobotFailure, RobotSink, RobotUnready, SessionEnd, SessionEvent,
    SessionState, StopSignal,
};
use ergocell_bridge::controller::{ControllerCommand, ControllerReport, GoalStatusEnum};
use ergocell_bridge::msg::{ControllerEvent, HardwareEvent, Header, JointState, JointTrajectory};
use ergocell_bridge::transport::{RobotInterface, RosConfig};
use ergocell_cell::CellSettings;
use ergocell_perception::CameraRig;
use ergocell_robot::monitor::Deviation;
use ergocell_robot::TrajectoryClass;
use ergocell_ros_backend::monitor::Judge;
use ergocell_ros_backend::robot::{announce_driver, feed, RobotInput, RosRobot, TrajectoryTopic};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

const MS: i64 = 1_000_000;
/// Camera frames (the twin's 10 Hz).
const FRAME: i64 = 100 * MS;
/// Joint states (a KUKA driver's 250 Hz).
const SAMPLE: i64 = 4 * MS;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rig() -> CameraRig {
    common::reference_rig()
}

/// The repository's trajectories with a demo approval of c2 in a temp folder of its own.
fn provider(name: &str) -> FileTrajectories {
    common::demo_provider(&format!("failure-{name}"), Some(TrajectoryClass::C2))
}

fn ros(interface: RobotInterface, driver_state: bool) -> RosConfig {
    let text = std::fs::read_to_string(root().join("config/cell.toml")).unwrap();
    let mut ros = RosConfig::from_cell_toml(&text).unwrap();
    ros.robot_interface = interface;
    ros.driver_state = driver_state;
    ros
}

/// The controller's trajectory topic, as a list of what was published.
#[derive(Default)]
struct FakeTopic(Mutex<Vec<JointTrajectory>>);

impl TrajectoryTopic for FakeTopic {
    fn publish(&self, message: JointTrajectory) -> Result<(), ergocell::session::BackendError> {
        self.0.lock().unwrap().push(message);
        Ok(())
    }

    fn delivered(&self, _: std::time::Duration) -> Result<bool, ergocell::session::BackendError> {
        Ok(true)
    }
}

impl FakeTopic {
    /// Empty trajectories published (holds).
    fn holds(&self) -> usize {
        self.0
            .lock()
            .unwrap()
            .iter()
            .filter(|m| m.points.is_empty())
            .count()
    }
}

/// What the simulated controller sends as `/joint_states` at a time, from its true positions.
enum Sample {
    /// This joint state.
    Send(Vec<f64>),
    /// Nothing (the driver's joint states stop).
    Silent,
    /// A joint state with one joint missing.
    MissingJoint,
}

struct Harness {
    cell: CellLoop<RosRobot<FakeTopic>, ()>,
    judge: Judge<FakeTopic>,
    topic: Arc<FakeTopic>,
    action: Option<tokio::sync::mpsc::UnboundedReceiver<ControllerCommand>>,
    /// The simulated controller: follows every command the session sent.
    physics: DummyRobot,
    joints: Vec<String>,
    sim: Simulation,
    now: i64,
    events: Vec<SessionEvent>,
    /// When the current leg was sent (the controller starts it at once here).
    leg_sent: Option<(i64, Leg)>,
}

impl Harness {
    fn new(name: &str, interface: RobotInterface, driver_state: bool) -> Self {
        let provider = provider(name);
        let approved = provider.verify(TrajectoryClass::C2).unwrap();
        let joints = approved.joint_names().to_vec();
        let home = approved.points()[0].positions_rad.clone();
        let machine = ergocell::session::SessionMachine::from_settings(
            rig(),
            &CellSettings::default(),
            Box::new(provider),
        )
        .unwrap();
        let ros = ros(interface, driver_state);
        let topic = Arc::new(FakeTopic::default());
        let (action, rx) = match interface {
            RobotInterface::Topic => (None, None),
            RobotInterface::Action => {
                let (tx, rx) = tokio::sync::mpsc::unbounded_channel();
                (Some(tx), Some(rx))
            }
        };
        let robot = RosRobot::new(topic.clone(), action, ros);
        let judge = Judge::new(robot.monitor(), robot.latest(), robot.port());
        let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
        script.cycles = 1;
        let sim = Simulation::new(
            rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(7),
        )
        .unwrap();
        let mut cell = ergocell_ros_backend::robot::cell_loop(machine, robot, ());
        let readiness = cell.driver_readiness();
        announce_driver(&mut cell, 0, readiness);
        Self {
            cell,
            judge,
            topic,
            action: rx,
            physics: DummyRobot::new(joints.clone(), home),
            joints,
            sim,
            now: 0,
            events: Vec::new(),
            leg_sent: None,
        }
    }

    /// Runs the clock in 4 ms ticks until `until` holds or `limit_nanos`: a joint state every tick
    /// (bent by `sample`), the monitor's timer, and a cell step with the cameras' views every 100 ms.
    /// Returns whether `until` held.
    fn run(
        &mut self,
        limit_nanos: i64,
        sample: &mut dyn FnMut(&Self, i64, Vec<f64>) -> Sample,
        until: &dyn Fn(&Self) -> bool,
    ) -> bool {
        while self.now <= limit_nanos {
            if until(self) {
                return true;
            }
            let truth = self.physics.positions_at(self.now);
            match sample(self, self.now, truth) {
                Sample::Send(position) => self.joint_state(position, self.joints.clone()),
                Sample::MissingJoint => {
                    let truth = self.physics.positions_at(self.now);
                    self.joint_state(truth[1..].to_vec(), self.joints[1..].to_vec());
                }
                Sample::Silent => {}
            }
            if let Some(note) = self.judge.tick(self.now) {
                feed(&mut self.cell, self.now, RobotInput::Monitor(note));
            }
            if self.now % FRAME == 0 {
                let views = self
                    .sim
                    .step()
                    .unwrap()
                    .map(|t| t.frame.views)
                    .unwrap_or_default();
                let step = self.cell.step(self.now, views);
                for e in &step.events {
                    if let SessionEvent::RobotCommandSent { command, .. } = e {
                        self.physics.send(self.now, command).unwrap();
                        self.leg_sent = match command {
                            RobotCommand::Execute { leg, .. } => Some((self.now, *leg)),
                            RobotCommand::Hold { .. } => None,
                        };
                    }
                }
                self.events.extend(step.events);
            }
            self.now += SAMPLE;
        }
        until(self)
    }

    fn joint_state(&mut self, position: Vec<f64>, name: Vec<String>) {
        let js = JointState {
            header: Header::new(self.now, ""),
            name,
            position,
            ..JointState::default()
        };
        #[allow(clippy::disallowed_methods)]
        let arrival = std::time::Instant::now();
        for note in self.judge.sample(self.now, js, arrival, 0.0) {
            feed(&mut self.cell, self.now, RobotInput::Monitor(note));
        }
    }

    /// The KUKA driver's hardware event `event` (kuka_drivers' `HardwareEvent` numbers).
    fn driver_event(&mut self, now: i64, event: u8) {
        let e = HardwareEvent {
            robot_name: "lbr".to_owned(),
            event,
        };
        feed(&mut self.cell, now, RobotInput::DriverEvent(e));
    }

    /// Until the first leg (home → handover) has gone out, faithfully executed.
    fn until_first_leg(&mut self) {
        assert!(
            self.run(30_000 * MS, &mut |_, _, q| Sample::Send(q), &|h| h
                .leg_sent
                .is_some()),
            "no leg within 30 s; events: {:?}",
            self.transitions()
        );
    }

    fn transitions(&self) -> Vec<SessionState> {
        self.events
            .iter()
            .filter_map(|e| match e {
                SessionEvent::StateChanged { to, .. } => Some(*to),
                _ => None,
            })
            .collect()
    }

    fn ended(&self) -> bool {
        self.cell.ended().is_some()
    }

    /// The robot side's events (what the cell publishes and records on controller_events).
    fn controller_events(&self) -> Vec<(String, String)> {
        self.cell
            .robot()
            .events()
            .lock()
            .unwrap()
            .iter()
            .map(|e| (e.kind.clone(), e.text.clone()))
            .collect()
    }

    /// The robot side's failure the session ended for, held: an empty trajectory on the topic, the
    /// controller event of `kind` (the monitor's verdict, or the controller's answer) beside it, and
    /// the summary marking an abnormal end (exit 1).
    fn failure(&self, kind: &str) -> RobotFailure {
        let ending = self.cell.ended().expect("the session ended");
        let Some(Interruption::RobotFailed { failure }) = ending.interruption() else {
            panic!("not ended by the robot side: {ending:?}");
        };
        let summary = self.cell.machine().summary();
        assert!(!summary.ended, "an abnormal end: {}", summary.end_reason);
        assert!(
            matches!(
                summary.end,
                Some(SessionEnd::Interrupted {
                    by: Interruption::RobotFailed { .. }
                })
            ),
            "{:?}",
            summary.end
        );
        assert!(
            self.topic.holds() >= 1,
            "the empty trajectory was published"
        );
        // The controller event of the failure: the monitor's verdict in its own words, sample
        // stamped; a controller's answer as its kind.
        let events = self.cell.robot().events();
        let events = events.lock().unwrap();
        let said = events.iter().find(|e| e.kind == kind);
        assert!(said.is_some(), "{:?}", self.controller_events());
        if kind == "monitor" {
            let said = said.unwrap();
            assert_eq!(said.text, failure.to_string());
            assert!(said.sample_stamp.to_nanos() > 0, "{said:?}");
        }
        failure.clone()
    }

    /// The execution monitor's deviation the session ended for.
    fn deviation(&self) -> Deviation {
        match self.failure("monitor") {
            RobotFailure::Deviation { deviation } => deviation,
            other => panic!("not the monitor's: {other:?}"),
        }
    }

    /// The true positions of the current leg at leg time `t_s` (seconds since it was sent).
    fn leg_at(&self, t_s: f64) -> Vec<f64> {
        let (sent, _) = self.leg_sent.expect("a leg");
        self.physics.positions_at(sent + (t_s * 1e9) as i64)
    }
}

/// Rows "the controller rejects the goal, aborts it, ends it with an error code, or does not answer
/// in 5 s": each ends the session held (the goal cancelled, the empty trajectory published), the
/// controller's words as the reason.
#[test]
fn the_controller_refusing_aborting_or_not_answering_a_goal_ends_the_session_held() {
    let label = ergocell_ros_backend::robot::leg_label(Leg::ToHandover);
    let leg = Some(Leg::ToHandover);
    let cases = [
        (
            ControllerReport::Rejected {
                label: label.clone(),
            },
            RobotFailure::GoalRejected { leg },
            "rejected",
        ),
        (
            ControllerReport::Finished {
                label: label.clone(),
                status: GoalStatusEnum::Aborted,
                error_code: -4,
                error_string: "joint_2 out of its path tolerance".to_owned(),
                feedback_count: 3,
            },
            RobotFailure::GoalEnded {
                leg,
                status: GoalStatus::Aborted,
                result: ResultCode::PathToleranceViolated,
                error_string: "joint_2 out of its path tolerance".to_owned(),
            },
            "finished",
        ),
        (
            ControllerReport::NoResponse {
                label: label.clone(),
                waited_s: 5.0,
            },
            RobotFailure::GoalUnanswered { leg, waited_s: 5.0 },
            "no_response",
        ),
    ];
    for (k, (report, expected, kind)) in cases.into_iter().enumerate() {
        let mut h = Harness::new(&format!("controller-{k}"), RobotInterface::Action, false);
        h.until_first_leg();
        let rx = h.action.as_mut().unwrap();
        assert!(matches!(
            rx.try_recv(),
            Ok(ControllerCommand::Execute { .. })
        ));
        let now = h.now;
        feed(&mut h.cell, now, RobotInput::Controller(report));
        h.run(
            h.now + FRAME,
            &mut |_, _, q| Sample::Send(q),
            &Harness::ended,
        );
        assert_eq!(h.failure(kind), expected);
        let queue = h.cell.robot().events();
        let answer = queue
            .lock()
            .unwrap()
            .iter()
            .find(|e| e.kind == kind)
            .cloned()
            .unwrap();
        assert_eq!(
            (answer.leg_id, answer.leg.as_str()),
            (ControllerEvent::LEG_TO_HANDOVER, "home → handover"),
            "the leg as a field, and in words"
        );
        let rx = h.action.as_mut().unwrap();
        assert!(
            std::iter::from_fn(|| rx.try_recv().ok())
                .any(|c| matches!(c, ControllerCommand::Cancel)),
            "the goal was cancelled"
        );
    }
}

/// Row "a joint leaves its path tolerance": the monitor holds at once (before the loop steps), the
/// session ends.
#[test]
fn a_joint_leaving_its_path_tolerance_is_held_by_the_monitor_at_once() {
    let mut h = Harness::new("path", RobotInterface::Topic, false);
    h.until_first_leg();
    let holds_before = h.topic.holds();
    // joint_2 drifts at 0.1 rad/s from the leg's start.
    let (sent, _) = h.leg_sent.unwrap();
    let mut held_at = None;
    h.run(
        h.now + 2_000 * MS,
        &mut |h, now, mut q| {
            q[1] += 0.1 * (now - sent) as f64 * 1e-9;
            if held_at.is_none() && h.topic.holds() > holds_before {
                held_at = Some(now);
            }
            Sample::Send(q)
        },
        &Harness::ended,
    );
    match h.deviation() {
        Deviation::Path {
            joint,
            error_rad,
            tolerance_rad,
            ..
        } => {
            assert_eq!(joint, "joint_2");
            assert!(
                error_rad.abs() > tolerance_rad,
                "{error_rad} {tolerance_rad}"
            );
        }
        other => panic!("{other:?}"),
    }
    // The hold went out with the bad sample, before the cell loop's next step ended the session.
    let held_at = held_at.expect("held by the monitor");
    assert!(h.cell.ended().unwrap().stamp_nanos >= held_at);
}

/// Row "on the path but late".
#[test]
fn a_robot_late_on_the_locked_path_ends_the_session_held() {
    let mut h = Harness::new("lag", RobotInterface::Topic, false);
    h.until_first_leg();
    let (sent, _) = h.leg_sent.unwrap();
    h.run(
        h.now + 3_000 * MS,
        &mut |h, now, _| Sample::Send(h.leg_at(0.8 * (now - sent) as f64 * 1e-9)),
        &Harness::ended,
    );
    assert!(
        matches!(h.deviation(), Deviation::Lagging { behind_s, .. } if behind_s > 0.0),
        "{:?}",
        h.deviation()
    );
}

/// Row "the robot stands while the lock moves".
#[test]
fn a_robot_standing_while_the_lock_moves_is_named_stalled() {
    let mut h = Harness::new("stall", RobotInterface::Topic, false);
    h.until_first_leg();
    let (sent, _) = h.leg_sent.unwrap();
    h.run(
        h.now + 3_000 * MS,
        &mut |h, now, _| Sample::Send(h.leg_at(((now - sent) as f64 * 1e-9).min(1.5))),
        &Harness::ended,
    );
    assert!(
        matches!(h.deviation(), Deviation::Stalled { moved_rad, locked_moved_rad, .. } if moved_rad < locked_moved_rad),
        "{:?}",
        h.deviation()
    );
}

/// Row "not within goal_tolerance_rad goal_time_tolerance_s after the leg's end".
#[test]
fn a_leg_that_does_not_arrive_ends_the_session_held() {
    let mut h = Harness::new("goal", RobotInterface::Topic, false);
    h.until_first_leg();
    // joint_7 (path tolerance 0.05 rad) runs 0.03 rad short all along: on the path, never at the goal.
    h.run(
        h.now + 8_000 * MS,
        &mut |_, _, mut q| {
            q[6] -= 0.03;
            Sample::Send(q)
        },
        &Harness::ended,
    );
    assert!(
        matches!(h.deviation(), Deviation::Goal { ref joint, .. } if joint == "joint_7"),
        "{:?}",
        h.deviation()
    );
}

/// Row "motion while it should be at rest".
#[test]
fn motion_at_rest_after_a_leg_ends_the_session_held() {
    let mut h = Harness::new("rest", RobotInterface::Topic, false);
    h.until_first_leg();
    let (sent, _) = h.leg_sent.unwrap();
    // Faithful for the leg (5 s) and a second at rest, then joint_1 creeps 0.02 rad.
    let creep_from = sent + 6_000 * MS;
    h.run(
        h.now + 8_000 * MS,
        &mut |_, now, mut q| {
            if now >= creep_from {
                q[0] += 0.02;
            }
            Sample::Send(q)
        },
        &Harness::ended,
    );
    assert!(
        matches!(h.deviation(), Deviation::MotionAtRest { ref joint, .. } if joint == "joint_1"),
        "{:?}",
        h.deviation()
    );
}

/// Row "a joint state without every joint, or NaN".
#[test]
fn a_joint_state_missing_a_joint_or_with_nan_ends_the_session_held() {
    for (k, bad) in ["missing", "nan"].into_iter().enumerate() {
        let mut h = Harness::new(&format!("bad-{k}"), RobotInterface::Topic, false);
        h.until_first_leg();
        let from = h.now + 200 * MS;
        h.run(
            h.now + 1_000 * MS,
            &mut |_, now, mut q| match (now >= from, bad) {
                (false, _) => Sample::Send(q),
                (true, "missing") => Sample::MissingJoint,
                (true, _) => {
                    q[2] = f64::NAN;
                    Sample::Send(q)
                }
            },
            &Harness::ended,
        );
        assert!(
            matches!(h.deviation(), Deviation::BadSample { .. }),
            "{:?}",
            h.deviation()
        );
    }
}

/// Row "no /joint_states for joint_state_timeout_s": held, and the session resumes by the usual
/// rules once they are back.
#[test]
fn stale_joint_states_hold_the_robot_and_the_session_resumes_when_they_are_back() {
    let mut h = Harness::new("stale", RobotInterface::Topic, false);
    h.until_first_leg();
    // The leg runs to its end and the robot rests at the handover point; then 0.3 s of silence.
    let (sent, _) = h.leg_sent.unwrap();
    let silent = (sent + 6_000 * MS)..(sent + 6_300 * MS);
    assert!(h.run(
        sent + 6_300 * MS,
        &mut |_, now, q| if silent.contains(&now) {
            Sample::Silent
        } else {
            Sample::Send(q)
        },
        &|h| h.cell.machine().state() == SessionState::Held,
    ));
    assert!(!h.ended());
    assert!(
        matches!(
            h.cell.machine().held_for(),
            Some(HoldReason::RobotNotReady {
                unready: RobotUnready::JointStatesStale { timeout_s }
            }) if *timeout_s == 0.1
        ),
        "{:?}",
        h.cell.machine().held_for()
    );
    assert!(h.topic.holds() >= 1);
    assert!(h
        .controller_events()
        .iter()
        .any(|(kind, text)| kind == "monitor" && text.starts_with("joint states stale")));
    // Back: the session resumes (robot at the handover point, tracking on).
    assert!(
        h.run(h.now + 3_000 * MS, &mut |_, _, q| Sample::Send(q), &|h| h
            .cell
            .machine()
            .state()
            == SessionState::Working,)
    );
    assert!(h
        .controller_events()
        .iter()
        .any(|(_, text)| text == "joint states back"));
}

/// Row "driver not configured or control not started (before a goal)": held, no goal sent until it
/// is; then the session goes on.
#[test]
fn no_goal_is_sent_until_the_driver_is_configured_and_controlling() {
    let mut h = Harness::new("driver", RobotInterface::Topic, true);
    assert_eq!(
        h.cell.machine().robot_unready(),
        None,
        "the readiness reaches the machine at its next step"
    );
    let locked = h.run(20_000 * MS, &mut |_, _, q| Sample::Send(q), &|h| {
        h.cell.machine().state() == SessionState::Held
    });
    assert!(locked, "{:?}", h.transitions());
    assert!(
        matches!(
            h.cell.machine().held_for(),
            Some(HoldReason::RobotNotReady {
                unready: RobotUnready::DriverSilent
            })
        ),
        "{:?}",
        h.cell.machine().held_for()
    );
    // Two more seconds: still no goal.
    h.run(h.now + 2_000 * MS, &mut |_, _, q| Sample::Send(q), &|_| {
        false
    });
    assert!(h.leg_sent.is_none(), "no goal before the driver is ready");
    let now = h.now;
    feed(&mut h.cell, now, RobotInput::DriverConfigured(true));
    h.run(h.now + 1_000 * MS, &mut |_, _, q| Sample::Send(q), &|_| {
        false
    });
    assert!(h.leg_sent.is_none(), "configured but control not started");
    assert!(
        matches!(
            h.cell.machine().held_for(),
            Some(HoldReason::RobotNotReady {
                unready: RobotUnready::ControlNotStarted
            })
        ),
        "{:?}",
        h.cell.machine().held_for()
    );
    let now = h.now;
    h.driver_event(now, HardwareEvent::CONTROL_STARTED);
    h.until_first_leg();
    assert!(h
        .controller_events()
        .iter()
        .any(|(kind, text)| kind == "driver" && text == "configured and controlling"));
}

/// Row "driver event 4 or 6": held.
#[test]
fn the_driver_stopping_holds_the_robot() {
    for (event, by) in [
        (HardwareEvent::CONTROL_STOPPED, DriverStop::ByUser),
        (HardwareEvent::ERROR, DriverStop::ByError),
    ] {
        let mut h = Harness::new(&format!("driver-{event}"), RobotInterface::Topic, true);
        feed(&mut h.cell, 0, RobotInput::DriverConfigured(true));
        h.driver_event(0, HardwareEvent::CONTROL_STARTED);
        h.until_first_leg();
        let now = h.now;
        h.driver_event(now, event);
        assert!(
            h.run(h.now + 1_000 * MS, &mut |_, _, q| Sample::Send(q), &|h| h
                .cell
                .machine()
                .state()
                == SessionState::Held,)
        );
        assert!(
            matches!(
                h.cell.machine().held_for(),
                Some(HoldReason::RobotNotReady {
                    unready: RobotUnready::DriverStopped { by: b }
                }) if *b == by
            ),
            "{:?}",
            h.cell.machine().held_for()
        );
        assert!(h.topic.holds() >= 1);
        assert!(!h.ended(), "held, not ended");
    }
}

/// The loop's own rules beside the table: Ctrl-C ends held with its cause; a stop is not a robot
/// failure.
#[test]
fn a_stop_ends_the_session_held_with_its_own_cause() {
    let mut h = Harness::new("stop", RobotInterface::Topic, false);
    h.until_first_leg();
    h.cell.stop(StopSignal::Terminate);
    h.run(
        h.now + FRAME,
        &mut |_, _, q| Sample::Send(q),
        &Harness::ended,
    );
    let ending = h.cell.ended().unwrap();
    assert!(
        matches!(
            ending.interruption(),
            Some(Interruption::Stopped {
                signal: StopSignal::Terminate
            })
        ),
        "{ending:?}"
    );
    assert!(h.topic.holds() >= 1);
    let summary = h.cell.machine().summary();
    assert_eq!(summary.end_reason, "interrupted: SIGTERM (robot held)");
    // Ended: the robot sink gets nothing more.
    let sent = h.topic.0.lock().unwrap().len();
    h.run(h.now + 1_000 * MS, &mut |_, _, q| Sample::Send(q), &|_| {
        false
    });
    assert_eq!(h.topic.0.lock().unwrap().len(), sent);
}

/// An output that fails from its `fail_at`-th step on (a recording on a full disk).
struct FailingOutputs {
    steps: usize,
    fail_at: usize,
    /// Steps seen after the failure (must stay 0 but for the shutdown's).
    after: usize,
}

impl ergocell::session::CellOutputs for FailingOutputs {
    fn session_step(
        &mut self,
        _now: i64,
        _machine: &ergocell::session::SessionMachine,
        _events: &[SessionEvent],
    ) -> Result<(), ergocell::session::OutputError> {
        self.steps += 1;
        if self.steps > self.fail_at {
            self.after += 1;
        }
        if self.steps == self.fail_at {
            return Err(ergocell::session::OutputError {
                output: "recording",
                cause: std::sync::Arc::new(std::io::Error::from_raw_os_error(28)),
            });
        }
        Ok(())
    }
}

/// The loop's rules beside the table: an output that fails (the recording) ends the session at
/// once, held; the time limit ends it held with its own cause.
#[test]
fn a_failed_output_or_the_time_limit_ends_the_session_held() {
    for fail_at in [Some(120), None] {
        let p = provider(&format!("outputs-{fail_at:?}"));
        let approved = p.verify(TrajectoryClass::C2).unwrap();
        let robot = DummyRobot::new(
            approved.joint_names().to_vec(),
            approved.points()[0].positions_rad.clone(),
        );
        let machine = ergocell::session::SessionMachine::from_settings(
            rig(),
            &CellSettings::default(),
            Box::new(p),
        )
        .unwrap();
        let outputs = FailingOutputs {
            steps: 0,
            fail_at: fail_at.unwrap_or(usize::MAX),
            after: 0,
        };
        let mut cell = CellLoop::new(machine, robot, outputs).with_deadline(20_000 * MS, 20.0);
        let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
        script.cycles = 3;
        let mut sim = Simulation::new(
            rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(7),
        )
        .unwrap();
        let mut now = 0;
        while cell.ended().is_none() {
            let views = sim
                .step()
                .unwrap()
                .map(|t| t.frame.views)
                .unwrap_or_default();
            cell.step(now, views);
            now += FRAME;
        }
        let ending = cell.ended().unwrap().clone();
        let last = cell.robot().received.last().map(|(_, c)| c.clone());
        assert!(
            matches!(last, Some(RobotCommand::Hold { .. })),
            "held: {last:?}"
        );
        if let Some(n) = fail_at {
            let Some(Interruption::OutputFailed { error }) = ending.interruption() else {
                panic!("{ending:?}");
            };
            assert_eq!(error.output, "recording");
            assert_eq!(
                error
                    .cause
                    .downcast_ref::<std::io::Error>()
                    .and_then(std::io::Error::raw_os_error),
                Some(28),
                "the disk full"
            );
            assert_eq!(ending.stamp_nanos, (n as i64 - 1) * FRAME, "at once");
            assert_eq!(
                cell.outputs().after,
                1,
                "only the shutdown's events after it"
            );
        } else {
            assert!(
                matches!(
                    ending.interruption(),
                    Some(Interruption::TimeLimit { limit_s }) if *limit_s == 20.0
                ),
                "{ending:?}"
            );
            assert_eq!(ending.stamp_nanos, 20_000 * MS + FRAME);
        }
        assert!(!cell.machine().summary().ended);
    }
}

/// An output that fails on the very step the operator leaves: the session's end is the output's
/// failure, not the normal end the loop could not finish, and no next session follows it.
#[test]
fn an_output_failing_as_the_operator_leaves_ends_the_program_not_the_session_only() {
    let run = |fail_at: usize| {
        let p = provider(&format!("outputs-leaving-{fail_at}"));
        let approved = p.verify(TrajectoryClass::C2).unwrap();
        let robot = DummyRobot::new(
            approved.joint_names().to_vec(),
            approved.points()[0].positions_rad.clone(),
        );
        let machine = ergocell::session::SessionMachine::from_settings(
            rig(),
            &CellSettings::default(),
            Box::new(p),
        )
        .unwrap();
        let outputs = FailingOutputs {
            steps: 0,
            fail_at,
            after: 0,
        };
        let mut cell = CellLoop::new(machine, robot, outputs);
        let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
        script.cycles = 1;
        let mut sim = Simulation::new(
            rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(7),
        )
        .unwrap();
        let mut now = 0;
        while cell.ended().is_none() && now < 120_000 * MS {
            let views = sim
                .step()
                .unwrap()
                .map(|t| t.frame.views)
                .unwrap_or_default();
            cell.step(now, views);
            now += FRAME;
        }
        let steps = cell.outputs().steps;
        (cell.ended().unwrap().clone(), steps)
    };
    let (normal, steps) = run(usize::MAX);
    assert!(normal.end.is_normal(), "{normal:?}");
    assert_eq!(normal.after(1, None), AfterSession::NextSession);
    let (failed, _) = run(steps);
    assert!(
        matches!(
            failed.interruption(),
            Some(Interruption::OutputFailed { .. })
        ),
        "{failed:?}"
    );
    assert_eq!(
        failed.after(1, None),
        AfterSession::Stop(ExitStatus::NeedsAPerson)
    );
}
