//! The failure table at the library level: the cell loop driven by the twin's cameras
//! (`ergocell_sim`) and its robot side (`ergocell_sim::controller::TwinRobot`: a simulated joint
//! trajectory controller and KUKA driver under the cell's `ExecutionWatch`), deterministic, on an
//! injected clock, each row asserting the typed outcome. The trajectory is the shipped c2 one,
//! planned, locked and approved in memory (the robot crate's test approvers).
//!
//! | row | the cell |
//! |---|---|
//! | a joint drifts off the locked path | ends held: `RobotFailed { Deviation::Path }` |
//! | the robot stalls | ends held: `RobotFailed { Deviation::Stalled }` |
//! | the controller answers late | ends held: `RobotFailed { GoalUnanswered }` |
//! | the driver stops (an error, an e-stop) | held: `RobotNotReady { DriverStopped }`, not ended |
//! | the lock does not verify (unapproved, withdrawn, rolled back) | ends, the robot never moves: `Aborted { NotVerified }` |
//! | tracking lost (every camera silent) | held: `CamerasLost`, resumes at an end of the path when the cameras are back |
//! | one camera lost | reported (`CameraDegraded`), not held |
//! | the cameras' clock jumps back | held: `CamerasLost` (frames too old to move the robot by) |
#![allow(clippy::unwrap_used, clippy::expect_used)]

#[path = "../../robot/tests/common/mod.rs"]
mod robot_fixture;

use std::sync::OnceLock;

use ergocell_cell::session::{
    AbortReason, CellLoop, DriverStop, HoldReason, Interruption, Leg, ProviderError, RobotCommand,
    RobotFailure, RobotUnready, SessionEnd, SessionEvent, SessionMachine, SessionState,
    TrajectoryProvider,
};
use ergocell_cell::CellSettings;
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::lock::{self, ApprovalsFile, LockFile, VerifyFailure, VerifyInputs};
use ergocell_robot::monitor::Deviation;
use ergocell_robot::{
    plan_and_validate, ApprovedTrajectory, PlanInputs, RobotError, TrajectoryClass, TrajectorySpec,
};
use ergocell_sim::controller::{RobotFault, SimController, TwinRobot};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

const MS: i64 = 1_000_000;
const FRAME: i64 = 100 * MS;
const SAMPLE: i64 = 4 * MS;
const CLASS: TrajectoryClass = TrajectoryClass::C2;

/// The shipped c2 trajectory, planned, locked, approved by a test approver and verified, once.
fn approved() -> &'static (ApprovedTrajectory, (f64, f64)) {
    static A: OnceLock<(ApprovedTrajectory, (f64, f64))> = OnceLock::new();
    A.get_or_init(|| {
        let s = robot_fixture::shipped();
        let text = robot_fixture::spec_text(CLASS);
        let spec = TrajectorySpec::from_toml_str(&text).unwrap();
        let hashes = robot_fixture::hashes(&s, &text);
        let locked = plan_and_validate(&PlanInputs {
            model: &s.model,
            cell: &s.cell,
            spec: &spec,
            hashes: &hashes,
        })
        .unwrap()
        .into_locked()
        .unwrap();
        let lock = LockFile::from_locked(&locked);
        let t = robot_fixture::signers();
        let mut approvals = ApprovalsFile::default();
        approvals
            .approve(
                &lock,
                robot_fixture::ALICE,
                "2026-01-01T00:00:00Z",
                &t.trusted,
                &t.alice,
            )
            .unwrap();
        let approved = lock::verify(&VerifyInputs {
            class: CLASS,
            lock_toml: &lock.to_toml().unwrap(),
            current_inputs: &hashes,
            model: &s.model,
            approvals_toml: Some(&approvals.to_toml().unwrap()),
            trusted: &t.trusted,
        })
        .unwrap();
        (approved, spec.stature.served_m())
    })
}

/// c2's approved trajectory, or (`verifies = false`) a lock whose approval is gone.
struct Provider {
    verifies: bool,
}

impl TrajectoryProvider for Provider {
    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        if self.verifies && class == CLASS {
            return Ok(approved().0.clone());
        }
        Err(ProviderError::NotVerified {
            failure: VerifyFailure {
                class,
                problems: vec![RobotError::NotApproved {
                    class: class.to_string(),
                    lock_sha256: approved().0.lock().lock_sha256.clone(),
                    detail: "the approval was withdrawn".to_owned(),
                }],
            },
            witness: None,
        })
    }

    fn stature_bounds_m(&mut self, _: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        Ok(approved().1)
    }
}

fn rig() -> CameraRig {
    let text = robot_fixture::read("config/rig.toml");
    ergocell_perception::rig_file::parse_rig(&text, "config/rig.toml")
        .unwrap()
        .0
}

/// What the cameras deliver at a time: the views as simulated, or changed by a fault.
type Cameras = dyn Fn(i64, Vec<View2>) -> Vec<View2>;

struct Table {
    cell: CellLoop<TwinRobot, ()>,
    sim: Simulation,
    now: i64,
    events: Vec<SessionEvent>,
}

impl Table {
    /// A 1.75 m operator (class c2); `fault` armed for the robot's first leg.
    fn new(verifies: bool, fault: Option<RobotFault>) -> Self {
        let (a, _) = approved();
        let mut controller = SimController::new(
            a.joint_names().to_vec(),
            a.points()[0].positions_rad.clone(),
        );
        if let Some(f) = fault {
            controller.arm(0, f).unwrap();
        }
        let machine = SessionMachine::from_settings(
            rig(),
            &CellSettings::default(),
            Box::new(Provider { verifies }),
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
        Self {
            cell: CellLoop::new(machine, robot, ()).with_driver_state(),
            sim,
            now: 0,
            events: Vec::new(),
        }
    }

    /// Steps until `until` holds or the session ends (at most `limit_nanos`): the robot side's
    /// reports to the cell and a step at each, the cameras' views (through `cameras`) every frame.
    fn run(&mut self, limit_nanos: i64, cameras: &Cameras, until: &dyn Fn(&Self) -> bool) -> bool {
        while self.now <= limit_nanos {
            while let Some((t, reports)) = self.cell.robot_mut().advance(self.now) {
                for r in reports {
                    self.cell.report(r);
                }
                let step = self.cell.step(t, Vec::new());
                self.events.extend(step.events);
            }
            let views = self
                .sim
                .step()
                .unwrap()
                .map(|t| t.frame.views)
                .unwrap_or_default();
            let step = self.cell.step(self.now, cameras(self.now, views));
            self.events.extend(step.events);
            if until(self) || self.cell.ended().is_some() {
                return until(self);
            }
            self.now += FRAME;
        }
        false
    }

    fn failure(&mut self) -> RobotFailure {
        self.run(60_000 * MS, &|_, v| v, &|_| false);
        let ending = self.cell.ended().expect("ended");
        match ending.interruption() {
            Some(Interruption::RobotFailed { failure }) => failure.clone(),
            other => panic!("{other:?}"),
        }
    }

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
}

#[test]
fn a_joint_drifting_off_the_path_ends_the_session_held() {
    let mut t = Table::new(
        true,
        Some(RobotFault::PathDeviation {
            joint: 1,
            rad_per_s: 0.1,
        }),
    );
    let f = t.failure();
    assert!(
        matches!(&f, RobotFailure::Deviation { deviation: Deviation::Path { joint, .. } } if joint == "joint_2"),
        "{f:?}"
    );
    assert_eq!(t.cell.robot().monitor_holds, 1);
}

#[test]
fn a_stall_ends_the_session_held() {
    let mut t = Table::new(true, Some(RobotFault::Stall { at_fraction: 0.4 }));
    let f = t.failure();
    assert!(
        matches!(
            f,
            RobotFailure::Deviation {
                deviation: Deviation::Stalled { .. }
            }
        ),
        "{f:?}"
    );
}

#[test]
fn a_late_controller_answer_ends_the_session_held() {
    let mut t = Table::new(true, Some(RobotFault::LateAnswer { waited_s: 5.0 }));
    assert_eq!(
        t.failure(),
        RobotFailure::GoalUnanswered {
            leg: Some(Leg::ToHandover),
            waited_s: 5.0
        }
    );
}

#[test]
fn a_driver_error_or_an_e_stop_holds_the_robot_until_the_driver_is_back() {
    for by in [DriverStop::ByUser, DriverStop::ByError] {
        let mut t = Table::new(
            true,
            Some(RobotFault::DriverStops {
                by,
                at_fraction: 0.4,
            }),
        );
        assert!(t.run(60_000 * MS, &|_, v| v, &|t| t.cell.machine().state()
            == SessionState::Held));
        t.run(t.now + 3_000 * MS, &|_, v| v, &|_| false);
        assert!(t.cell.ended().is_none());
        assert!(
            matches!(
                t.cell.machine().held_for(),
                Some(HoldReason::RobotNotReady {
                    unready: RobotUnready::DriverStopped { by: b }
                }) if *b == by
            ),
            "{:?}",
            t.cell.machine().held_for()
        );
    }
}

#[test]
fn a_lock_that_does_not_verify_ends_the_session_and_the_robot_never_moves() {
    let mut t = Table::new(false, None);
    t.run(60_000 * MS, &|_, v| v, &|_| false);
    let s = t.cell.machine().summary();
    assert!(
        matches!(
            &s.end,
            Some(SessionEnd::Aborted {
                reason: AbortReason::NotVerified {
                    class: TrajectoryClass::C2,
                    ..
                }
            })
        ),
        "{:?}",
        s.end
    );
    assert!(t
        .cell
        .robot()
        .controller
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
}

#[test]
fn tracking_lost_holds_the_robot_and_the_session_resumes_when_the_cameras_are_back() {
    let mut t = Table::new(true, None);
    assert!(t.run(60_000 * MS, &|_, v| v, &|t| t.working_since().is_some()));
    // Once the first leg (5 s) has brought the part: a robot held at an end of the locked path
    // resumes (one stopped between its ends waits for the pendant).
    let from = t.working_since().unwrap() + 5_300 * MS;
    let silent = move |now: i64, views: Vec<View2>| {
        if (from..from + 1_000 * MS).contains(&now) {
            Vec::new()
        } else {
            views
        }
    };
    assert!(
        t.run(from + 1_000 * MS, &silent, &|t| t.cell.machine().state()
            == SessionState::Held)
    );
    assert!(
        matches!(
            t.cell.machine().held_for(),
            Some(HoldReason::CamerasLost { .. })
        ),
        "{:?}",
        t.cell.machine().held_for()
    );
    assert!(
        t.run(t.now + 5_000 * MS, &silent, &|t| t.cell.machine().state()
            == SessionState::Working)
    );
}

#[test]
fn one_camera_lost_is_reported_and_the_robot_keeps_working() {
    let mut t = Table::new(true, None);
    assert!(t.run(60_000 * MS, &|_, v| v, &|t| t.working_since().is_some()));
    let without_the_first =
        |_: i64, views: Vec<View2>| views.into_iter().filter(|v| v.camera != 0).collect();
    t.run(t.now + 3_000 * MS, &without_the_first, &|_| false);
    assert!(t
        .events
        .iter()
        .any(|e| matches!(e, SessionEvent::CameraDegraded { .. })));
    assert_eq!(t.cell.machine().state(), SessionState::Working);
}

#[test]
fn the_cameras_clock_jumping_back_holds_the_robot() {
    let mut t = Table::new(true, None);
    assert!(t.run(60_000 * MS, &|_, v| v, &|t| t.working_since().is_some()));
    let from = t.now + 500 * MS;
    let jumped = move |now: i64, views: Vec<View2>| {
        views
            .into_iter()
            .map(|mut v| {
                if now >= from {
                    v.stamp_nanos -= 5_000 * MS;
                }
                v
            })
            .collect()
    };
    assert!(
        t.run(t.now + 3_000 * MS, &jumped, &|t| t.cell.machine().state()
            == SessionState::Held)
    );
    assert!(
        matches!(
            t.cell.machine().held_for(),
            Some(HoldReason::CamerasLost { .. })
        ),
        "{:?}",
        t.cell.machine().held_for()
    );
}
