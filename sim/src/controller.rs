//! The twin's robot side: a simulated joint trajectory controller with the KUKA driver's state
//! ([`SimController`]), its faults as data ([`RobotFault`]), and [`TwinRobot`], which runs it under
//! the cell's own execution watch exactly as the ROS 2 backend runs a real controller: every
//! command through one port, every joint state judged as it arrives, the first deviation held at
//! once, and every report handed to the cell loop as a [`RobotReport`] for the cell's rules to
//! decide on (`CellLoop::report`).
//!
//! The controller follows each goal from the moment it accepts it, through the leg's knots
//! (linearly between them, as `DummyRobot`), answers as a FollowJointTrajectory server does
//! (accepted, then succeeded at the leg's end; a hold cancels), reports joint states at its rate and
//! says "configured" and "control started" when it comes up. The faults are the ones CI's rclpy
//! peer plays against `ergocell run`, on the first leg the controller runs after the fault is armed:
//!
//! | fault | the controller | the cell (its rules) |
//! |---|---|---|
//! | `PathDeviation` | a joint drifts off the leg | the monitor's `Path` deviation: ends held |
//! | `Lag` | runs the leg slower | `Lagging`: ends held |
//! | `Stall` | stops dead partway | `Stalled`: ends held |
//! | `MotionAtRest` | a joint creeps after the leg | `MotionAtRest`: ends held |
//! | `GoalRejected` | rejects the goal | `GoalRejected`: ends held |
//! | `GoalAborted` | aborts partway, `PATH_TOLERANCE_VIOLATED` | `GoalEnded`: ends held |
//! | `LateAnswer` | does not answer the goal in time | `GoalUnanswered`: ends held |
//! | `DriverStops` | the driver stops (by a user, or by an error: an e-stop), the robot brakes | held while not ready |
//!
//! Deterministic: no randomness and no wall time; every time is the caller's clock.

use ergocell_cell::session::dummy::DummyRobot;
use ergocell_cell::session::{
    BackendError, DriverEvent, DriverStop, ExecutionWatch, GoalAnswer, GoalStatus, HoldReason, Leg,
    LegTrajectory, ResultCode, RobotCommand, RobotReport, RobotSink,
};
use serde::Deserialize;

use crate::SimError;

/// What goes wrong on the robot side, on the first leg the controller runs once armed.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum RobotFault {
    /// Joint `joint` (0 = the first of the lock) drifts off the leg at `rad_per_s` from its start.
    PathDeviation { joint: usize, rad_per_s: f64 },
    /// The leg runs at `speed` of its locked timing (0.8: 80 %).
    Lag { speed: f64 },
    /// The robot stops dead `at_fraction` of the way through the leg's time.
    Stall { at_fraction: f64 },
    /// `after_s` after the leg's end, joint `joint` creeps `rad` off where it stopped.
    MotionAtRest {
        joint: usize,
        rad: f64,
        after_s: f64,
    },
    /// The controller rejects the goal.
    GoalRejected,
    /// The controller aborts the goal `at_fraction` of the way through (path tolerance violated);
    /// the robot stops there.
    GoalAborted { at_fraction: f64 },
    /// The goal is not answered; the cell's client gives up after `waited_s`.
    LateAnswer { waited_s: f64 },
    /// The KUKA driver stops `at_fraction` of the way through the leg (`by = "by_user"`: control
    /// stopped, 4; `"by_error"`: an error such as an e-stop, 6) and the robot brakes where it is.
    DriverStops { by: DriverStop, at_fraction: f64 },
}

impl RobotFault {
    /// Every value in range: fractions in [0, 1), rates and distances finite and not 0, a speed in
    /// (0, 1), waits and delays within an hour.
    pub fn check(&self) -> Result<(), SimError> {
        // Before the leg's end: a stall or a stop at its end would be no fault at all.
        let fraction = |v: f64| (0.0..1.0).contains(&v);
        let ok = match *self {
            Self::PathDeviation { rad_per_s, .. } => rad_per_s.is_finite() && rad_per_s != 0.0,
            Self::Lag { speed } => speed > 0.0 && speed < 1.0,
            Self::Stall { at_fraction }
            | Self::GoalAborted { at_fraction }
            | Self::DriverStops { at_fraction, .. } => fraction(at_fraction),
            Self::MotionAtRest { rad, after_s, .. } => {
                rad.is_finite() && rad != 0.0 && (0.0..=3600.0).contains(&after_s)
            }
            Self::GoalRejected => true,
            Self::LateAnswer { waited_s } => waited_s > 0.0 && waited_s <= 3600.0,
        };
        if ok {
            Ok(())
        } else {
            Err(SimError::RobotFaultOutOfRange {
                fault: format!("{self:?}"),
            })
        }
    }
}

/// The leg the controller is running.
#[derive(Debug, Clone)]
struct Running {
    leg: Option<Leg>,
    start_nanos: i64,
    duration_s: f64,
    fault: Option<RobotFault>,
    /// Leg time (seconds from its start) from which the fault acts: 0 for a fault armed before
    /// the leg, the time it was armed for one armed while it runs (a fault never acts backwards).
    fault_from_s: f64,
}

impl Running {
    /// Leg time (seconds) at which a fault striking `at_fraction` of the way acts: never before
    /// it was armed.
    fn strike_s(&self, at_fraction: f64) -> f64 {
        (at_fraction * self.duration_s).max(self.fault_from_s)
    }
}

/// A simulated joint trajectory controller and KUKA driver.
#[derive(Debug, Clone)]
pub struct SimController {
    joints: Vec<String>,
    /// Follows the goals (its start is the goal's acceptance; time warped by the faults here).
    physics: DummyRobot,
    running: Option<Running>,
    /// Creep after a leg's end (`MotionAtRest`): from when, which joint, how far.
    creep: Option<(i64, usize, f64)>,
    /// Reports due, with their times, in order.
    due: Vec<(i64, RobotReport)>,
    /// Faults armed, each for the next leg the controller runs.
    armed: Vec<RobotFault>,
    driver_up: bool,
    /// Every command received, with its time (the newest `history`).
    pub received: Vec<(i64, RobotCommand)>,
    history: usize,
}

impl SimController {
    /// A controller at rest at `positions_rad` (in the order of `joints`), its driver not up yet
    /// (it says "configured" and "control started" at the first [`SimController::reports`]).
    pub fn new(joints: Vec<String>, positions_rad: Vec<f64>) -> Self {
        Self {
            physics: DummyRobot::new(joints.clone(), positions_rad),
            joints,
            running: None,
            creep: None,
            due: Vec::new(),
            armed: Vec::new(),
            driver_up: false,
            received: Vec::new(),
            history: usize::MAX,
        }
    }

    /// Keeps only the newest `n` commands (a long shift sends thousands of legs).
    #[must_use]
    pub fn keeping_last(mut self, n: usize) -> Self {
        self.history = n.max(1);
        self
    }

    /// Whether this controller can play `fault`: its values in range ([`RobotFault::check`]) and
    /// every joint it names one the robot has.
    pub fn check(&self, fault: &RobotFault) -> Result<(), SimError> {
        fault.check()?;
        if let RobotFault::PathDeviation { joint, .. } | RobotFault::MotionAtRest { joint, .. } =
            *fault
        {
            if joint >= self.joints.len() {
                return Err(SimError::NoSuchJoint {
                    fault: format!("{fault:?}"),
                    joint,
                    joints: self.joints.len(),
                });
            }
        }
        Ok(())
    }

    /// `fault` happens from `now_nanos`: on the leg running now, for the faults that strike partway
    /// (at their fraction of the leg, or now if that has passed; a drift from now), or else on the
    /// next leg the controller is sent. A fault that cannot be played ([`SimController::check`]) is
    /// refused.
    pub fn arm(&mut self, now_nanos: i64, fault: RobotFault) -> Result<(), SimError> {
        self.check(&fault)?;
        let strikes_partway = matches!(
            fault,
            RobotFault::Stall { .. }
                | RobotFault::DriverStops { .. }
                | RobotFault::GoalAborted { .. }
                | RobotFault::PathDeviation { .. }
        );
        if let (Some(r), true) = (self.running.as_mut(), strikes_partway) {
            let t = (now_nanos - r.start_nanos) as f64 * 1e-9;
            // A leg past its end (its result not yet out) is as good as done: the next one.
            if r.fault.is_none() && t < r.duration_s {
                r.fault = Some(fault);
                r.fault_from_s = t.max(0.0);
                self.schedule_partway(fault);
                return Ok(());
            }
        }
        self.armed.push(fault);
        Ok(())
    }

    /// The joints in the controller's order.
    pub fn joints(&self) -> &[String] {
        &self.joints
    }

    /// Where the robot is at `now_nanos`, in the controller's joint order.
    pub fn positions_at(&self, now_nanos: i64) -> Vec<f64> {
        let mut q = match &self.running {
            None => self.physics.positions_at(now_nanos),
            Some(r) => {
                let t = (now_nanos - r.start_nanos) as f64 * 1e-9;
                let warped = match r.fault {
                    Some(RobotFault::Lag { speed }) => t * speed,
                    Some(
                        RobotFault::Stall { at_fraction }
                        | RobotFault::GoalAborted { at_fraction }
                        | RobotFault::DriverStops { at_fraction, .. },
                    ) => t.min(r.strike_s(at_fraction)),
                    _ => t,
                };
                let mut q = self
                    .physics
                    .positions_at(r.start_nanos + (warped * 1e9) as i64);
                if let Some(RobotFault::PathDeviation { joint, rad_per_s }) = r.fault {
                    if let Some(x) = q.get_mut(joint) {
                        *x += rad_per_s * (t - r.fault_from_s).max(0.0);
                    }
                }
                q
            }
        };
        if let Some((from, joint, rad)) = self.creep {
            if now_nanos >= from {
                if let Some(x) = q.get_mut(joint) {
                    *x += rad;
                }
            }
        }
        q
    }

    /// The reports due by `now_nanos`, in order: the driver coming up (first call), the answers to
    /// goals, the driver's events.
    pub fn reports(&mut self, now_nanos: i64) -> Vec<(i64, RobotReport)> {
        if !self.driver_up {
            self.driver_up = true;
            self.due
                .insert(0, (now_nanos, RobotReport::DriverConfigured(true)));
            self.due.insert(
                1,
                (
                    now_nanos,
                    RobotReport::DriverEvent(DriverEvent::ControlStarted),
                ),
            );
        }
        let n = self.due.iter().take_while(|(t, _)| *t <= now_nanos).count();
        let out: Vec<(i64, RobotReport)> = self.due.drain(..n).collect();
        for (t, r) in &out {
            // The leg's end (it ran to its last knot, or was aborted partway) or the driver's stop
            // (the robot brakes where it is): the robot rests there.
            if matches!(
                r,
                RobotReport::Goal(GoalAnswer::Finished { .. })
                    | RobotReport::DriverEvent(DriverEvent::Stopped { .. })
            ) {
                self.stop(*t);
            }
        }
        out
    }

    /// The robot stays where it is at `at_nanos`.
    fn stop(&mut self, at_nanos: i64) {
        if self.running.is_none() {
            return;
        }
        let here = self.positions_at(at_nanos);
        // Where the robot rests, without the creep it may already show (the creep stays where it
        // crept to, on top of the rest).
        let mut base = here;
        if let Some((from, joint, rad)) = self.creep {
            if at_nanos >= from {
                if let Some(x) = base.get_mut(joint) {
                    *x -= rad;
                }
            }
        }
        let fault = self.running.take().and_then(|r| r.fault);
        if let Some(RobotFault::MotionAtRest {
            joint,
            rad,
            after_s,
        }) = fault
        {
            self.creep = Some((at_nanos + (after_s * 1e9) as i64, joint, rad));
        }
        self.physics = DummyRobot::new(self.joints.clone(), base);
    }

    fn push_due(&mut self, at_nanos: i64, report: RobotReport) {
        let k = self.due.partition_point(|(t, _)| *t <= at_nanos);
        self.due.insert(k, (at_nanos, report));
    }

    /// The reports of a fault that strikes partway through the running leg.
    fn schedule_partway(&mut self, fault: RobotFault) {
        let Some(r) = self.running.as_ref() else {
            return;
        };
        let (start, leg, running) = (r.start_nanos, r.leg, r.clone());
        let at = |f: f64| start + (running.strike_s(f) * 1e9) as i64;
        match fault {
            RobotFault::Stall { .. } | RobotFault::PathDeviation { .. } => {
                // the goal never finishes: the monitor judges it first
                self.due
                    .retain(|(_, r)| !matches!(r, RobotReport::Goal(GoalAnswer::Finished { .. })));
            }
            RobotFault::GoalAborted { at_fraction } => {
                self.due
                    .retain(|(_, r)| !matches!(r, RobotReport::Goal(GoalAnswer::Finished { .. })));
                self.push_due(
                    at(at_fraction),
                    RobotReport::Goal(GoalAnswer::Finished {
                        leg,
                        status: GoalStatus::Aborted,
                        result: ResultCode::PathToleranceViolated,
                        error_string: "a joint beyond its path tolerance (simulated fault)"
                            .to_owned(),
                        feedback_count: 0,
                    }),
                );
            }
            RobotFault::DriverStops { by, at_fraction } => {
                self.due
                    .retain(|(_, r)| !matches!(r, RobotReport::Goal(GoalAnswer::Finished { .. })));
                self.push_due(
                    at(at_fraction),
                    RobotReport::DriverEvent(DriverEvent::Stopped { by }),
                );
            }
            _ => {}
        }
    }

    fn execute(&mut self, now_nanos: i64, leg: Leg, trajectory: &LegTrajectory) {
        let leg = Some(leg);
        let fault = (!self.armed.is_empty()).then(|| self.armed.remove(0));
        match fault {
            Some(RobotFault::GoalRejected) => {
                self.push_due(now_nanos, RobotReport::Goal(GoalAnswer::Rejected { leg }));
                return;
            }
            Some(RobotFault::LateAnswer { waited_s }) => {
                self.push_due(
                    now_nanos + (waited_s * 1e9) as i64,
                    RobotReport::Goal(GoalAnswer::Unanswered { leg, waited_s }),
                );
                return;
            }
            _ => {}
        }
        self.stop(now_nanos);
        let here = self.positions_at(now_nanos);
        self.creep = None;
        let mut physics = DummyRobot::new(self.joints.clone(), here);
        // The dummy follows a command from the time it receives it: the goal's acceptance.
        let command = RobotCommand::Execute {
            leg: Leg::ToHandover,
            lock_sha256: String::new(),
            trajectory: trajectory.clone(),
        };
        if physics.send(now_nanos, &command).is_err() {
            return;
        }
        self.physics = physics;
        let duration_s = trajectory.duration_s();
        self.running = Some(Running {
            leg,
            start_nanos: now_nanos,
            duration_s,
            fault: None,
            fault_from_s: 0.0,
        });
        self.push_due(now_nanos, RobotReport::Goal(GoalAnswer::Accepted { leg }));
        let lag = match fault {
            Some(RobotFault::Lag { speed }) if speed > 0.0 => 1.0 / speed,
            _ => 1.0,
        };
        self.push_due(
            now_nanos + (duration_s * lag * 1e9) as i64,
            RobotReport::Goal(GoalAnswer::Finished {
                leg,
                status: GoalStatus::Succeeded,
                result: ResultCode::Successful,
                error_string: String::new(),
                feedback_count: 0,
            }),
        );
        if let Some(f) = fault {
            if let Some(r) = self.running.as_mut() {
                r.fault = Some(f);
            }
            self.schedule_partway(f);
        }
    }

    fn hold(&mut self, now_nanos: i64) {
        if let Some(r) = self.running.as_ref() {
            let leg = r.leg;
            self.due.retain(|(_, r)| !matches!(r, RobotReport::Goal(_)));
            self.push_due(
                now_nanos,
                RobotReport::Goal(GoalAnswer::CancelRequested { leg }),
            );
            self.push_due(
                now_nanos,
                RobotReport::Goal(GoalAnswer::Finished {
                    leg,
                    status: GoalStatus::Canceled,
                    result: ResultCode::Successful,
                    error_string: String::new(),
                    feedback_count: 0,
                }),
            );
        }
        self.stop(now_nanos);
    }

    /// A command from the cell.
    pub fn command(&mut self, now_nanos: i64, command: &RobotCommand) {
        match command {
            RobotCommand::Execute {
                leg, trajectory, ..
            } => self.execute(now_nanos, *leg, trajectory),
            RobotCommand::Hold { .. } => self.hold(now_nanos),
        }
        self.received.push((now_nanos, command.clone()));
        let excess = self.received.len().saturating_sub(self.history);
        self.received.drain(..excess);
    }
}

/// The twin's robot side: the simulated controller under the cell's execution watch, as the
/// session's [`RobotSink`].
#[derive(Debug)]
pub struct TwinRobot {
    pub controller: SimController,
    watch: ExecutionWatch,
    sample_period_nanos: i64,
    last_sample_nanos: Option<i64>,
    /// Holds the watch sent at once on a deviation (the port's, not the session's).
    pub monitor_holds: u32,
}

impl TwinRobot {
    /// `controller` reporting joint states every `sample_period_nanos`, stale after `timeout_s`.
    pub fn new(controller: SimController, sample_period_nanos: i64, timeout_s: f64) -> Self {
        Self {
            controller,
            watch: ExecutionWatch::new(timeout_s),
            sample_period_nanos: sample_period_nanos.max(1),
            last_sample_nanos: None,
            monitor_holds: 0,
        }
    }

    pub fn watch(&self) -> &ExecutionWatch {
        &self.watch
    }

    /// The robot side's next reports by `now_nanos` and their time: the controller's answers and
    /// the driver's events, and the watch's verdict on every joint state up to then (a deviation
    /// holds the robot at once, as the ROS 2 monitor task does). `None` once nothing more is due by
    /// `now_nanos`. The caller hands each report to `CellLoop::report` and steps the loop at that
    /// time, as `ergocell run` steps on every report it receives.
    pub fn advance(&mut self, now_nanos: i64) -> Option<(i64, Vec<RobotReport>)> {
        let mut t = self
            .last_sample_nanos
            .map_or(now_nanos, |last| last + self.sample_period_nanos);
        while t <= now_nanos {
            let mut out = Vec::new();
            for (at, report) in self.controller.reports(t) {
                if matches!(report, RobotReport::Goal(GoalAnswer::Accepted { .. })) {
                    // The controller starts an accepted goal now.
                    self.watch.leg_started(at);
                }
                out.push(report);
            }
            let q = self.controller.positions_at(t);
            for report in self.watch.sample(t, Some(&q)) {
                if let RobotReport::Deviation(deviation) = &report {
                    // held at once, through the port, before the loop's next step
                    let hold = RobotCommand::Hold {
                        reason: HoldReason::deviation(deviation.clone()),
                    };
                    self.controller.command(t, &hold);
                    self.monitor_holds += 1;
                }
                out.push(report);
            }
            out.extend(self.watch.tick(t));
            self.last_sample_nanos = Some(t);
            if !out.is_empty() {
                return Some((t, out));
            }
            t += self.sample_period_nanos;
        }
        None
    }
}

impl RobotSink for TwinRobot {
    fn send(&mut self, now_nanos: i64, command: &RobotCommand) -> Result<(), BackendError> {
        if let RobotCommand::Execute {
            leg, trajectory, ..
        } = command
        {
            let label = leg.words();
            self.watch
                .leg_sent(
                    now_nanos,
                    label,
                    trajectory,
                    &trajectory.path_tolerance_rad,
                    &trajectory.monitor,
                )
                .map_err(|cause| BackendError::Monitor { cause })?;
        } else {
            self.watch.held(now_nanos);
        }
        self.controller.command(now_nanos, command);
        Ok(())
    }

    fn joint_positions(&mut self, now_nanos: i64, names: &[String]) -> Option<Vec<f64>> {
        let here = self.controller.positions_at(now_nanos);
        names
            .iter()
            .map(|n| {
                let i = self.controller.joints().iter().position(|m| m == n)?;
                here.get(i).copied()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use ergocell_cell::session::LegPoint;

    const S: i64 = 1_000_000_000;

    /// Two joints from 0 to 1 rad in 1 s.
    fn leg() -> LegTrajectory {
        let point = |t: f64| LegPoint {
            positions_rad: vec![t, t],
            velocities_rad_s: vec![0.0, 0.0],
            accelerations_rad_s2: vec![0.0, 0.0],
            time_from_start_s: t,
        };
        LegTrajectory {
            joint_names: vec!["a".into(), "b".into()],
            points: (0..=10).map(|k| point(f64::from(k) * 0.1)).collect(),
            ..LegTrajectory::default()
        }
    }

    fn running() -> SimController {
        let mut c = SimController::new(vec!["a".into(), "b".into()], vec![0.0, 0.0]);
        c.command(
            0,
            &RobotCommand::Execute {
                leg: Leg::ToHandover,
                lock_sha256: String::new(),
                trajectory: leg(),
            },
        );
        c
    }

    fn near(a: &[f64], b: &[f64]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
    }

    /// A fault armed while a leg runs acts from then on, never backwards: a stall armed past its
    /// fraction stops the robot where it is, a drift starts from zero.
    #[test]
    fn a_fault_armed_partway_acts_from_then_on() {
        let mut c = running();
        let before = c.positions_at(S * 6 / 10);
        c.arm(S * 6 / 10, RobotFault::Stall { at_fraction: 0.4 })
            .unwrap();
        assert!(near(&c.positions_at(S * 6 / 10), &before));
        assert!(
            near(&c.positions_at(S * 9 / 10), &before),
            "stopped where it was"
        );

        let mut c = running();
        let before = c.positions_at(S / 2);
        c.arm(
            S / 2,
            RobotFault::PathDeviation {
                joint: 1,
                rad_per_s: 0.1,
            },
        )
        .unwrap();
        assert!(near(&c.positions_at(S / 2), &before), "no jump when armed");
        let later = c.positions_at(S * 7 / 10);
        assert!((later[1] - later[0] - 0.02).abs() < 1e-9, "{later:?}");
    }

    /// Motion at rest creeps the joint by its distance once the leg has ended and `after_s` passed,
    /// even with no wait at all.
    #[test]
    fn motion_at_rest_creeps_after_the_leg() {
        let mut c = SimController::new(vec!["a".into(), "b".into()], vec![0.0, 0.0]);
        c.arm(
            0,
            RobotFault::MotionAtRest {
                joint: 0,
                rad: 0.02,
                after_s: 0.0,
            },
        )
        .unwrap();
        c.command(
            0,
            &RobotCommand::Execute {
                leg: Leg::ToHandover,
                lock_sha256: String::new(),
                trajectory: leg(),
            },
        );
        let answers = c.reports(2 * S);
        assert!(answers
            .iter()
            .any(|(_, r)| matches!(r, RobotReport::Goal(GoalAnswer::Finished { .. }))));
        assert!(near(&c.positions_at(2 * S), &[1.02, 1.0]));
    }

    /// Faults that would be none, or name a joint the robot lacks, are refused.
    #[test]
    fn faults_that_would_be_none_or_name_no_joint_are_refused() {
        for bad in [
            RobotFault::Stall { at_fraction: 1.0 },
            RobotFault::Lag { speed: 1.0 },
            RobotFault::PathDeviation {
                joint: 0,
                rad_per_s: 0.0,
            },
            RobotFault::LateAnswer { waited_s: 0.0 },
        ] {
            assert!(bad.check().is_err(), "{bad:?}");
        }
        let c = SimController::new(vec!["a".into()], vec![0.0]);
        assert!(c
            .check(&RobotFault::PathDeviation {
                joint: 1,
                rad_per_s: 0.1
            })
            .is_err());
    }
}
