//! The twin runs the robot side's rules as the real cell does: `ergocell_sim::controller`'s simulated
//! joint trajectory controller and KUKA driver, under the cell's own execution watch, handing every
//! report to `CellLoop::report`. Each fault of the table (the rclpy peer's faults in CI, and the
//! rows of `tests/failure_table.rs`) ends the session, or holds the robot, for the same typed reason
//! the ROS 2 backend's path gives, with the same holds sent.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use ergocell::session::{
    CellLoop, DriverStop, GoalStatus, HoldReason, Interruption, Leg, ResultCode, RobotCommand,
    RobotFailure, RobotUnready, SessionEnd, SessionState,
};
use ergocell_cell::CellSettings;
use ergocell_robot::monitor::Deviation;
use ergocell_robot::TrajectoryClass;
use ergocell_sim::controller::{RobotFault, SimController, TwinRobot};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

const MS: i64 = 1_000_000;
const FRAME: i64 = 100 * MS;
/// The KUKA driver's joint states: 250 Hz.
const SAMPLE: i64 = 4 * MS;

struct Twin {
    cell: CellLoop<TwinRobot, ()>,
    sim: Simulation,
    now: i64,
}

impl Twin {
    /// A 1.75 m operator (class c2) with `fault` armed for the robot's first leg.
    fn new(name: &str, fault: Option<RobotFault>) -> Self {
        let provider = common::demo_provider(&format!("twin-{name}"), Some(TrajectoryClass::C2));
        let approved = provider.verify(TrajectoryClass::C2).unwrap();
        let mut controller = SimController::new(
            approved.joint_names().to_vec(),
            approved.points()[0].positions_rad.clone(),
        );
        if let Some(f) = fault {
            controller.arm(0, f).unwrap();
        }
        let machine = ergocell::session::SessionMachine::from_settings(
            common::reference_rig(),
            &CellSettings::default(),
            Box::new(provider),
        )
        .unwrap();
        let robot = TwinRobot::new(controller, SAMPLE, 0.1);
        let cell = CellLoop::new(machine, robot, ()).with_driver_state();
        let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
        script.cycles = 1;
        let sim = Simulation::new(
            common::reference_rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(7),
        )
        .unwrap();
        Self { cell, sim, now: 0 }
    }

    /// Runs until `until` holds or the session ends, at most until `limit_nanos`: the robot side's
    /// reports handed to the loop and a step at each, and a step with the cameras' views every frame.
    fn run(&mut self, limit_nanos: i64, until: &dyn Fn(&Self) -> bool) -> bool {
        while self.now <= limit_nanos {
            while let Some((t, reports)) = self.cell.robot_mut().advance(self.now) {
                for r in reports {
                    self.cell.report(r);
                }
                self.cell.step(t, Vec::new());
            }
            let views = self
                .sim
                .step()
                .unwrap()
                .map(|t| t.frame.views)
                .unwrap_or_default();
            self.cell.step(self.now, views);
            if until(self) || self.cell.ended().is_some() {
                return until(self);
            }
            self.now += FRAME;
        }
        false
    }

    /// The robot side's failure the session ended for (robot held).
    fn failure(&mut self) -> RobotFailure {
        self.run(60_000 * MS, &|_| false);
        let ending = self.cell.ended().expect("the session ended");
        let Some(Interruption::RobotFailed { failure }) = ending.interruption() else {
            panic!("not ended by the robot side: {ending:?}");
        };
        let failure = failure.clone();
        assert!(!self.cell.machine().summary().ended);
        assert!(!self.holds().is_empty(), "the controller was told to hold");
        failure
    }

    fn deviation(&mut self) -> Deviation {
        let failure = self.failure();
        let RobotFailure::Deviation { deviation } = failure else {
            panic!("not the monitor's: {failure:?}");
        };
        // Held at once by the watch (through the controller's port), then by the session's end.
        assert_eq!(self.cell.robot().monitor_holds, 1);
        assert_eq!(self.holds().len(), 2, "{:?}", self.holds());
        deviation
    }

    /// When the controller received a hold.
    fn holds(&self) -> Vec<i64> {
        self.cell
            .robot()
            .controller
            .received
            .iter()
            .filter(|(_, c)| matches!(c, RobotCommand::Hold { .. }))
            .map(|(t, _)| *t)
            .collect()
    }
}

/// Without a fault the session runs its legs and ends normally when the operator leaves: the
/// controller's answers and the watch's verdicts let a faithful robot through.
#[test]
fn without_a_fault_the_twin_serves_the_operator() {
    let mut twin = Twin::new("none", None);
    twin.run(60_000 * MS, &|_| false);
    let ending = twin.cell.ended().expect("the session ended");
    assert!(ending.end.is_normal(), "{ending:?}");
    assert!(!twin.cell.robot().watch().tripped());
    assert!(twin.holds().is_empty(), "{:?}", twin.holds());
    let legs: Vec<Leg> = twin
        .cell
        .robot()
        .controller
        .received
        .iter()
        .filter_map(|(_, c)| match c {
            RobotCommand::Execute { leg, .. } => Some(*leg),
            RobotCommand::Hold { .. } => None,
        })
        .collect();
    assert_eq!(legs, [Leg::ToHandover, Leg::ToHome]);
}

#[test]
fn a_joint_drifting_off_the_path_ends_the_session_held() {
    let mut twin = Twin::new(
        "drift",
        Some(RobotFault::PathDeviation {
            joint: 1,
            rad_per_s: 0.1,
        }),
    );
    let d = twin.deviation();
    assert!(
        matches!(&d, Deviation::Path { joint, error_rad, tolerance_rad, .. }
            if joint == "joint_2" && error_rad.abs() > *tolerance_rad),
        "{d:?}"
    );
}

#[test]
fn a_robot_late_on_the_path_ends_the_session_held() {
    let mut twin = Twin::new("lag", Some(RobotFault::Lag { speed: 0.8 }));
    let d = twin.deviation();
    assert!(
        matches!(d, Deviation::Lagging { behind_s, .. } if behind_s > 0.0),
        "{d:?}"
    );
}

#[test]
fn a_stall_ends_the_session_held() {
    let mut twin = Twin::new("stall", Some(RobotFault::Stall { at_fraction: 0.4 }));
    let d = twin.deviation();
    assert!(
        matches!(d, Deviation::Stalled { moved_rad, locked_moved_rad, .. } if moved_rad < locked_moved_rad),
        "{d:?}"
    );
}

#[test]
fn motion_at_rest_ends_the_session_held() {
    let mut twin = Twin::new(
        "rest",
        Some(RobotFault::MotionAtRest {
            joint: 0,
            rad: 0.02,
            after_s: 1.0,
        }),
    );
    let d = twin.deviation();
    assert!(
        matches!(&d, Deviation::MotionAtRest { joint, .. } if joint == "joint_1"),
        "{d:?}"
    );
}

#[test]
fn the_controller_refusing_aborting_or_not_answering_ends_the_session_held() {
    let leg = Some(Leg::ToHandover);
    let cases = [
        (RobotFault::GoalRejected, RobotFailure::GoalRejected { leg }),
        (
            RobotFault::GoalAborted { at_fraction: 0.5 },
            RobotFailure::GoalEnded {
                leg,
                status: GoalStatus::Aborted,
                result: ResultCode::PathToleranceViolated,
                error_string: "a joint beyond its path tolerance (simulated fault)".to_owned(),
            },
        ),
        (
            RobotFault::LateAnswer { waited_s: 5.0 },
            RobotFailure::GoalUnanswered { leg, waited_s: 5.0 },
        ),
    ];
    for (k, (fault, expected)) in cases.into_iter().enumerate() {
        let mut twin = Twin::new(&format!("controller-{k}"), Some(fault));
        assert_eq!(twin.failure(), expected);
        // The session's own hold: no monitor verdict came first.
        assert_eq!(twin.cell.robot().monitor_holds, 0);
        assert_eq!(twin.holds().len(), 1, "{:?}", twin.holds());
    }
}

/// A driver stopped by a user or by an error (an e-stop): the robot brakes, the session holds for
/// it (not ended: the driver may come back) and no monitor verdict follows the braking.
#[test]
fn the_driver_stopping_or_an_e_stop_holds_the_robot() {
    for by in [DriverStop::ByUser, DriverStop::ByError] {
        let mut twin = Twin::new(
            &format!("driver-{by:?}"),
            Some(RobotFault::DriverStops {
                by,
                at_fraction: 0.4,
            }),
        );
        assert!(twin.run(60_000 * MS, &|t| t.cell.machine().state()
            == SessionState::Held));
        let held_at = twin.now;
        twin.run(held_at + 3_000 * MS, &|_| false);
        assert!(twin.cell.ended().is_none(), "held, not ended");
        assert!(
            matches!(
                twin.cell.machine().held_for(),
                Some(HoldReason::RobotNotReady {
                    unready: RobotUnready::DriverStopped { by: b }
                }) if *b == by
            ),
            "{:?}",
            twin.cell.machine().held_for()
        );
        assert_eq!(twin.holds().len(), 1, "{:?}", twin.holds());
        assert!(
            !twin.cell.robot().watch().tripped(),
            "braking is not a deviation"
        );
        assert!(!matches!(
            twin.cell.machine().summary().end,
            Some(SessionEnd::Interrupted { .. })
        ));
    }
}
