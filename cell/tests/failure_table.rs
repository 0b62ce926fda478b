//! The failure table at the library level: the session driver (`Driver`) run to a session's end on
//! a scripted station: the twin's cameras (`ergocell_sim`), changed by each row's camera fault,
//! and its robot side (`ergocell_sim::controller::TwinRobot`: a simulated joint
//! trajectory controller and KUKA driver under the cell's `ExecutionWatch`), deterministic, on an
//! injected clock, each row asserting the typed outcome. The lock and its approvals are the
//! approvals crate's in-memory cell (`ergocell_approvals::fixture`: the shipped c2 trajectory
//! planned and locked in memory, approved by a test engineer under a test authority), verified by
//! the same provider `run` uses.
//!
//! | row | the cell |
//! |---|---|
//! | a joint drifts off the locked path | ends held: `RobotFailed { Deviation::Path }` |
//! | the robot stalls | ends held: `RobotFailed { Deviation::Stalled }` |
//! | the controller answers late | ends held: `RobotFailed { GoalUnanswered }` |
//! | the driver stops (an error, an e-stop) | held: `RobotNotReady { DriverStopped }`, not ended |
//! | the lock was never approved, or its approval withdrawn | ends, the robot never moves: `Aborted { NotVerified { NotVerified { NotApproved } } }` |
//! | the approvals file rolled back (a withdrawal deleted) | ends, the robot never moves: `Aborted { NotVerified { Witness { RolledBack } } }` |
//! | tracking lost (every camera silent) | held: `CamerasLost`, resumes at an end of the path when the cameras are back |
//! | one camera lost | reported (`CameraDegraded`), not held |
//! | the cameras' clock jumps back | held: `CamerasLost` (frames too old to move the robot by) |
//! | a stop signal (Ctrl-C) | ends held: `Stopped { Interrupt }`, exit status 130 |
//! | an input fails (the simulator) | ends held: `InputFailed`, the station's error returned |
//! | no machine for the next operator | the program stops for a person: exit status 1 after a normal end |
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::cell::Cell;
use std::rc::Rc;
use std::sync::OnceLock;

use ergocell_approvals::fixture::{self, Fixture};
use ergocell_cell::session::{
    AbortReason, CellLoop, CommandSent, Driver, DriverError, DriverStop, ExitStatus, HoldReason,
    Input, InputError, Interruption, Leg, Outcome, ProviderError, RobotCommand, RobotFailure,
    RobotUnready, SessionEnd, SessionEvent, SessionMachine, SessionState, Station, Step,
    StopRequest, StopSignal, Timed,
};
use ergocell_cell::CellSettings;
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::monitor::Deviation;
use ergocell_robot::{ApprovedTrajectory, RobotError, TrajectoryClass};
use ergocell_sim::controller::{RobotFault, SimController, TwinRobot};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

const MS: i64 = 1_000_000;
const FRAME: i64 = 100 * MS;
const SAMPLE: i64 = 4 * MS;
const CLASS: TrajectoryClass = TrajectoryClass::C2;

/// The shipped c2 trajectory as the in-memory cell approves it (`ergocell_approvals::fixture`).
fn approved() -> &'static ApprovedTrajectory {
    static A: OnceLock<ApprovedTrajectory> = OnceLock::new();
    A.get_or_init(|| {
        Fixture::approved(CLASS)
            .unwrap()
            .provider(fixture::a_day_later)
            .verify(CLASS)
            .unwrap()
    })
}

/// What the approvals file of c2 holds when the session starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Approvals {
    /// Alice's approval of the current lock.
    Approved,
    /// None: the lock was never approved.
    Unapproved,
    /// Alice's approval, then bob's withdrawal.
    Withdrawn,
    /// The withdrawal deleted after the cell's witness saw it (the file rolled back).
    RolledBack,
}

/// The cell's files in memory, with c2 locked and its approvals as `approvals`, and the provider
/// `run` would use on them.
fn provider(approvals: Approvals) -> ergocell_approvals::FileTrajectories {
    let f = match approvals {
        Approvals::Unapproved => {
            let f = Fixture::new().unwrap();
            f.lock(CLASS).unwrap();
            f
        }
        _ => Fixture::approved(CLASS).unwrap(),
    };
    let p = f.provider(fixture::a_day_later);
    if approvals != Approvals::Approved && approvals != Approvals::Unapproved {
        p.verify(CLASS).unwrap();
        let approved_only = f.approvals(CLASS).unwrap();
        f.withdraw(CLASS, fixture::BOB, &f.bob, "2026-01-01T02:00:00Z")
            .unwrap();
        assert!(p.verify(CLASS).is_err(), "withdrawn");
        if approvals == Approvals::RolledBack {
            f.put_approvals(CLASS, &approved_only).unwrap();
        }
    }
    p
}

fn rig() -> CameraRig {
    let text = include_str!("../../config/rig.toml");
    ergocell_formats::rig_file::parse_rig(text, "config/rig.toml")
        .unwrap()
        .0
}

/// What the cameras deliver: the views as simulated, or changed by a fault, given the time and
/// when the session started working (`None`: not yet).
type Cameras = Box<dyn Fn(i64, Option<i64>, Vec<View2>) -> Vec<View2>>;

/// The cameras as simulated.
fn as_simulated() -> Cameras {
    Box::new(|_, _, views| views)
}

/// The session as it went, step by step.
#[derive(Default)]
struct Timeline {
    events: Vec<SessionEvent>,
    /// Each step's time, state and hold reason.
    states: Vec<(i64, SessionState, Option<HoldReason>)>,
}

impl Timeline {
    fn working_since(&self) -> Option<i64> {
        self.events.iter().find_map(|e| match e {
            SessionEvent::StateChanged {
                to: SessionState::Working,
                stamp_nanos,
                ..
            } => Some(*stamp_nanos),
            _ => None,
        })
    }

    /// The steps from `from` on.
    fn after(&self, from: i64) -> impl Iterator<Item = &(i64, SessionState, Option<HoldReason>)> {
        self.states.iter().filter(move |(t, ..)| *t >= from)
    }
}

/// The table's station: the twin's cameras (through `cameras`) every frame and its robot side's
/// reports at their times, on the test's clock (frames every 100 ms).
struct Script {
    sim: Simulation,
    now: i64,
    views: Option<Vec<View2>>,
    frame_step: bool,
    cameras: Cameras,
    timeline: Timeline,
    /// A simulator failure at this time (the station's error).
    fail_at: Option<i64>,
    /// The time of the last input (what the stop request reads).
    clock: Rc<Cell<i64>>,
}

/// The station failed (the table's scripted simulator error).
#[derive(Debug, thiserror::Error)]
#[error("scripted simulator failure at {at_nanos} ns")]
struct ScriptFailed {
    at_nanos: i64,
}

impl Station<TwinRobot, ()> for Script {
    type Error = ScriptFailed;

    fn name(&self) -> &'static str {
        "scripted twin"
    }

    fn now_nanos(&mut self) -> i64 {
        self.now
    }

    async fn next(
        &mut self,
        cell: &mut CellLoop<TwinRobot, ()>,
    ) -> Result<Option<Timed>, ScriptFailed> {
        if self.fail_at.is_some_and(|at| self.now >= at) {
            return Err(ScriptFailed { at_nanos: self.now });
        }
        if self.views.is_none() {
            let views = self
                .sim
                .step()
                .unwrap()
                .map(|t| t.frame.views)
                .unwrap_or_default();
            self.views = Some((self.cameras)(
                self.now,
                self.timeline.working_since(),
                views,
            ));
        }
        if let Some((t, reports)) = cell.robot_mut().advance(self.now) {
            self.frame_step = false;
            self.clock.set(t);
            return Ok(Some(Timed::new(t, Input::Reports(reports))));
        }
        self.frame_step = true;
        self.clock.set(self.now);
        Ok(Some(Timed::new(
            self.now,
            Input::Views(self.views.take().unwrap_or_default()),
        )))
    }

    fn stepped(
        &mut self,
        cell: &mut CellLoop<TwinRobot, ()>,
        at: i64,
        step: &Step,
    ) -> Result<(), ScriptFailed> {
        self.timeline.events.extend(step.events.iter().cloned());
        let m = cell.machine();
        self.timeline
            .states
            .push((at, m.state(), m.held_for().cloned()));
        if std::mem::take(&mut self.frame_step) {
            self.now += FRAME;
        }
        Ok(())
    }

    fn next_machine(
        &mut self,
        _: &mut CellLoop<TwinRobot, ()>,
    ) -> Result<SessionMachine, ScriptFailed> {
        Err(ScriptFailed { at_nanos: self.now })
    }
}

/// A stop asked for once the session has run to `at_nanos` (a test's Ctrl-C).
struct StopAt {
    at_nanos: i64,
    now: Rc<Cell<i64>>,
}

impl StopRequest for StopAt {
    fn requested(&self) -> Option<StopSignal> {
        (self.now.get() >= self.at_nanos).then_some(StopSignal::Interrupt)
    }
}

/// One row: the driver run to the end of one session (at most 60 s), on a 1.75 m operator (class
/// c2) with `fault` armed for the robot's first leg.
struct Row {
    approvals: Approvals,
    fault: Option<RobotFault>,
    cameras: Cameras,
    fail_at: Option<i64>,
    stop_at: Option<i64>,
    /// Sessions asked for (`None`: one after another).
    sessions: Option<u32>,
}

/// How a row went: the driver's outcome (or its error), the timeline and the robot.
struct Ran {
    outcome: Result<Outcome, DriverError>,
    timeline: Timeline,
    robot: TwinRobot,
    end: Option<SessionEnd>,
}

impl Ran {
    fn interruption(&self) -> Option<&Interruption> {
        match &self.end {
            Some(SessionEnd::Interrupted { by }) => Some(by),
            _ => None,
        }
    }

    fn failure(&self) -> RobotFailure {
        match self.interruption() {
            Some(Interruption::RobotFailed { failure }) => failure.clone(),
            other => panic!("{other:?}"),
        }
    }

    fn status(&self) -> ExitStatus {
        self.outcome.as_ref().expect("the driver ran").status
    }
}

impl Row {
    fn new() -> Self {
        Self {
            approvals: Approvals::Approved,
            fault: None,
            cameras: as_simulated(),
            fail_at: None,
            stop_at: None,
            sessions: Some(1),
        }
    }

    fn fault(fault: RobotFault) -> Self {
        Self {
            fault: Some(fault),
            ..Self::new()
        }
    }

    fn run(self) -> Ran {
        let a = approved();
        let mut controller = SimController::new(
            a.joint_names().to_vec(),
            a.points()[0].positions_rad.clone(),
        );
        if let Some(f) = self.fault {
            controller.arm(0, f).unwrap();
        }
        let machine = SessionMachine::from_settings(
            rig(),
            &CellSettings::default(),
            Box::new(provider(self.approvals)),
        )
        .unwrap();
        let robot = TwinRobot::new(controller, SAMPLE, 0.1);
        let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
        script.cycles = 1;
        let sim = Simulation::new(
            rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(7),
        )
        .unwrap();
        let cell = CellLoop::new(machine, robot, ())
            .with_command_log()
            .with_driver_state()
            .with_deadline(60_000 * MS, 60.0);
        let mut station = Script {
            sim,
            now: 0,
            views: None,
            frame_step: false,
            cameras: self.cameras,
            timeline: Timeline::default(),
            fail_at: self.fail_at,
            clock: Rc::default(),
        };
        let mut driver = Driver::new(cell, self.sessions);
        let stop = StopAt {
            at_nanos: self.stop_at.unwrap_or(i64::MAX),
            now: station.clock.clone(),
        };
        let outcome = ready(driver.run(&mut station, &stop));
        let (machine, robot, ()) = driver.into_cell().into_parts();
        Ran {
            outcome,
            timeline: station.timeline,
            robot,
            end: machine.summary().end.clone(),
        }
    }
}

/// The driver's future on a station that is always ready: done at the first poll.
fn ready<T>(future: impl std::future::Future<Output = T>) -> T {
    let mut future = std::pin::pin!(future);
    let mut context = std::task::Context::from_waker(std::task::Waker::noop());
    match future.as_mut().poll(&mut context) {
        std::task::Poll::Ready(out) => out,
        std::task::Poll::Pending => panic!("a scripted station never waits"),
    }
}

#[test]
fn a_joint_drifting_off_the_path_ends_the_session_held() {
    let ran = Row::fault(RobotFault::PathDeviation {
        joint: 1,
        rad_per_s: 0.1,
    })
    .run();
    let f = ran.failure();
    assert!(
        matches!(&f, RobotFailure::Deviation { deviation: Deviation::Path { joint, .. } } if joint == "joint_2"),
        "{f:?}"
    );
    assert_eq!(ran.robot.monitor_holds, 1);
    assert_eq!(ran.status(), ExitStatus::NeedsAPerson);
}

#[test]
fn a_stall_ends_the_session_held() {
    let ran = Row::fault(RobotFault::Stall { at_fraction: 0.4 }).run();
    // the commands the outcome keeps: the first leg, then the one hold, for the stall
    let commands = &ran.outcome.as_ref().unwrap().commands;
    assert!(
        matches!(
            commands.as_slice(),
            [
                CommandSent::Goal {
                    leg: Leg::ToHandover,
                    ..
                },
                CommandSent::Hold {
                    reason: HoldReason::Ended {
                        end: SessionEnd::Interrupted {
                            by: Interruption::RobotFailed {
                                failure: RobotFailure::Deviation {
                                    deviation: Deviation::Stalled { .. }
                                }
                            }
                        }
                    },
                    ..
                }
            ]
        ),
        "{commands:?}"
    );
    let f = ran.failure();
    assert!(
        matches!(
            f,
            RobotFailure::Deviation {
                deviation: Deviation::Stalled { .. }
            }
        ),
        "{f:?}"
    );
    assert_eq!(ran.status(), ExitStatus::NeedsAPerson);
}

#[test]
fn a_late_controller_answer_ends_the_session_held() {
    let ran = Row::fault(RobotFault::LateAnswer { waited_s: 5.0 }).run();
    assert_eq!(
        ran.failure(),
        RobotFailure::GoalUnanswered {
            leg: Some(Leg::ToHandover),
            waited_s: 5.0
        }
    );
}

#[test]
fn a_driver_error_or_an_e_stop_holds_the_robot_until_the_driver_is_back() {
    for by in [DriverStop::ByUser, DriverStop::ByError] {
        let ran = Row::fault(RobotFault::DriverStops {
            by,
            at_fraction: 0.4,
        })
        .run();
        // Held from the stop on, for that reason, and never ended by it: the session runs into its
        // time limit with the robot held.
        let held = ran
            .timeline
            .states
            .iter()
            .position(|(_, s, _)| *s == SessionState::Held)
            .expect("held");
        let (from, ..) = ran.timeline.states[held];
        assert!(ran
            .timeline
            .after(from)
            .take_while(|(_, s, _)| *s != SessionState::SessionEnded)
            .all(|(_, s, why)| *s == SessionState::Held
                && matches!(why, Some(HoldReason::RobotNotReady {
                    unready: RobotUnready::DriverStopped { by: b }
                }) if *b == by)));
        assert!(
            matches!(ran.interruption(), Some(Interruption::TimeLimit { .. })),
            "{:?}",
            ran.end
        );
    }
}

#[test]
fn a_lock_unapproved_withdrawn_or_rolled_back_ends_the_session_and_the_robot_never_moves() {
    for approvals in [
        Approvals::Unapproved,
        Approvals::Withdrawn,
        Approvals::RolledBack,
    ] {
        let ran = Row {
            approvals,
            ..Row::new()
        }
        .run();
        let Some(SessionEnd::Aborted {
            reason:
                AbortReason::NotVerified {
                    class: TrajectoryClass::C2,
                    error,
                },
        }) = &ran.end
        else {
            panic!("{approvals:?}: {:?}", ran.end);
        };
        match (approvals, error) {
            // Never approved, or its approval withdrawn: no standing approval of this lock.
            (
                Approvals::Unapproved | Approvals::Withdrawn,
                ProviderError::NotVerified {
                    failure,
                    witness: None,
                },
            ) => assert!(
                matches!(
                    failure.problems.as_slice(),
                    [RobotError::NotApproved { .. }]
                ),
                "{approvals:?}: {failure}"
            ),
            // The withdrawal deleted: the chain is intact, the witness saw more.
            (Approvals::RolledBack, ProviderError::Witness { cause, .. }) => assert!(
                matches!(**cause, RobotError::RolledBack { .. }),
                "{cause:?}"
            ),
            (approvals, error) => panic!("{approvals:?}: {error:?}"),
        }
        assert!(
            ran.robot
                .controller
                .received
                .iter()
                .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })),
            "{approvals:?}: the robot was sent a motion"
        );
        assert_eq!(ran.status(), ExitStatus::NeedsAPerson, "{approvals:?}");
    }
}

#[test]
fn tracking_lost_holds_the_robot_and_the_session_resumes_when_the_cameras_are_back() {
    // Once the first leg (5 s) has brought the part: a robot held at an end of the locked path
    // resumes (one stopped between its ends waits for the pendant).
    let silent_from = |working: Option<i64>| working.map(|w| w + 5_300 * MS);
    let ran = Row {
        cameras: Box::new(move |now, working, views| match silent_from(working) {
            Some(from) if (from..from + 1_000 * MS).contains(&now) => Vec::new(),
            _ => views,
        }),
        ..Row::new()
    }
    .run();
    let from = silent_from(ran.timeline.working_since()).expect("working");
    let held = ran
        .timeline
        .after(from)
        .find(|(_, s, _)| *s == SessionState::Held)
        .expect("held");
    assert!(
        matches!(held.2, Some(HoldReason::CamerasLost { .. })),
        "{held:?}"
    );
    assert!(ran
        .timeline
        .after(held.0)
        .any(|(_, s, _)| *s == SessionState::Working));
    // and the session then ends as it should: the operator left
    assert_eq!(ran.status(), ExitStatus::Done);
}

#[test]
fn one_camera_lost_is_reported_and_the_robot_keeps_working() {
    let ran = Row {
        cameras: Box::new(|now, working, views| match working {
            Some(w) if now >= w => views.into_iter().filter(|v| v.camera != 0).collect(),
            _ => views,
        }),
        ..Row::new()
    }
    .run();
    assert!(ran
        .timeline
        .events
        .iter()
        .any(|e| matches!(e, SessionEvent::CameraDegraded { .. })));
    let w = ran.timeline.working_since().expect("working");
    assert!(ran
        .timeline
        .after(w)
        .all(|(_, s, _)| *s != SessionState::Held));
    assert_eq!(ran.status(), ExitStatus::Done);
}

#[test]
fn the_cameras_clock_jumping_back_holds_the_robot() {
    let jump_from = |working: Option<i64>| working.map(|w| w + 500 * MS);
    let ran = Row {
        cameras: Box::new(move |now, working, views| {
            let jumped = jump_from(working).is_some_and(|from| now >= from);
            views
                .into_iter()
                .map(|mut v| {
                    if jumped {
                        v.stamp_nanos -= 5_000 * MS;
                    }
                    v
                })
                .collect()
        }),
        ..Row::new()
    }
    .run();
    let from = jump_from(ran.timeline.working_since()).expect("working");
    let held = ran
        .timeline
        .after(from)
        .find(|(_, s, _)| *s == SessionState::Held)
        .expect("held");
    assert!(
        matches!(held.2, Some(HoldReason::CamerasLost { .. })),
        "{held:?}"
    );
}

#[test]
fn a_stop_signal_ends_the_session_held_with_its_exit_status() {
    let ran = Row {
        stop_at: Some(10_000 * MS),
        ..Row::new()
    }
    .run();
    assert!(
        matches!(
            ran.interruption(),
            Some(Interruption::Stopped {
                signal: StopSignal::Interrupt
            })
        ),
        "{:?}",
        ran.end
    );
    assert_eq!(ran.status(), ExitStatus::Stopped(StopSignal::Interrupt));
    assert_eq!(ran.status().code(), 130);
    // the shutdown's hold was sent
    assert!(matches!(
        ran.robot.controller.received.last(),
        Some((_, RobotCommand::Hold { .. }))
    ));
}

#[test]
fn an_input_that_fails_ends_the_session_held_and_returns_its_error() {
    let ran = Row {
        fail_at: Some(12_000 * MS),
        ..Row::new()
    }
    .run();
    let error = ran.outcome.as_ref().expect_err("the station failed");
    assert_eq!(
        error
            .error
            .downcast_ref::<ScriptFailed>()
            .map(|e| e.at_nanos),
        Some(12_000 * MS)
    );
    // the outcome as far as it went: ended held, at the station's time, the hold the last command
    let outcome = error.outcome.as_ref().expect("the session had started");
    assert_eq!(outcome.status, ExitStatus::NeedsAPerson);
    assert_eq!(outcome.ending.stamp_nanos, 12_000 * MS);
    assert!(matches!(
        outcome.commands.last(),
        Some(CommandSent::Hold {
            reason: HoldReason::Ended {
                end: SessionEnd::Interrupted {
                    by: Interruption::InputFailed { .. }
                }
            },
            ..
        })
    ));
    let Some(Interruption::InputFailed {
        error: InputError {
            input: "scripted twin",
            cause,
        },
    }) = ran.interruption()
    else {
        panic!("{:?}", ran.end);
    };
    // The session's end holds the station's own error, the one the driver returned.
    assert_eq!(
        cause.downcast_ref::<ScriptFailed>().map(|e| e.at_nanos),
        Some(12_000 * MS)
    );
    // The outcome file names it under `why`, as its chain.
    let end = serde_json::to_value(&outcome.ending.end).unwrap();
    assert_eq!(
        end["by"]["error"]["why"],
        serde_json::json!(format!("scripted simulator failure at {} ns", 12_000 * MS))
    );
    assert!(matches!(
        ran.robot.controller.received.last(),
        Some((_, RobotCommand::Hold { .. }))
    ));
}

#[test]
fn no_machine_for_the_next_operator_stops_the_program_for_a_person() {
    // One session after another: the operator leaves normally, and the station has no machine
    // for the next one (the scripted station's error).
    let ran = Row {
        sessions: None,
        ..Row::new()
    }
    .run();
    let error = ran.outcome.as_ref().expect_err("no next machine");
    let outcome = error.outcome.as_ref().expect("one session ended");
    assert!(
        matches!(outcome.ending.end, SessionEnd::OperatorLeft { .. }),
        "{:?}",
        outcome.ending
    );
    assert_eq!(
        (outcome.sessions, outcome.status),
        (1, ExitStatus::NeedsAPerson)
    );
}
