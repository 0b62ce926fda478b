//! The digital twin around the cell loop, as the session driver's station (`ergocell demo`): the
//! simulated cameras with the fault schedule, the twin robot's reports, both on the simulator's
//! clock, and the simulated robot's joint states handed to the outputs to be recorded as a real
//! cell's would be.
//!
//! Per frame: the cameras are polled, then the robot side's reports up to the frame's time are
//! handed over (each batch at its own time, as `run` steps on every report it receives), then the
//! frame's views with the fault schedule applied. Once the cell decides a class other than the
//! operator's own, the simulated operator reaches where that class's robot brings the part.
//!
//! The station prints nothing and reads no clock of its own: its lines go to the caller's `say`,
//! and the wall clock (for real time and the soak report's step times) and the process's memory
//! come from the caller ([`TwinHooks`]).

use std::time::{Duration, Instant};

use ergocell_cell::session::{
    trajectory_class, BackendError, CellLoop, CellOutputs, Input, LandmarkSource, Leg,
    ReportEffect, RobotCommand, RobotReport, RobotSink, SessionEvent, SessionMachine, SessionState,
    Station, Step, Timed,
};
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::TrajectoryClass;
use nalgebra::Point3;

use crate::controller::TwinRobot;
use crate::faults::{FaultPlayer, Silenced};
use crate::source::SimSource;
use crate::{Phase, SimError};

/// What the twin's station hands its outputs beyond the session's steps: the recording's camera
/// messages, controller events and the robot's joint states, and the status line's RULA.
pub trait TwinOutputs: CellOutputs {
    /// The frame's views at `now`, as the cameras published them.
    fn views(&mut self, rig: &CameraRig, now: i64, views: &[View2]);
    /// A robot report applied at `t`, and its effect.
    fn robot_report(&mut self, t: i64, report: &RobotReport, effect: &ReportEffect);
    /// The twin robot's joint positions at `now` (named by `joints`), serving `class`.
    fn robot_state(
        &mut self,
        now: i64,
        class: TrajectoryClass,
        joints: &[String],
        positions: Vec<f64>,
    );
    /// The newest frame's RULA, for the status line.
    fn rula_status(&self) -> String;
}

/// The twin's station's error.
#[derive(Debug, thiserror::Error)]
pub enum TwinError {
    /// The simulated cameras failed.
    #[error(transparent)]
    Cameras(#[from] BackendError),
    /// The simulated operator cannot reach the handover point of the class the cell decided.
    #[error("the simulated operator cannot reach the decided class's handover point")]
    Unreachable(#[source] SimError),
    /// The demo plays one session; the driver asked for another.
    #[error("the demo plays one session")]
    OneSession,
}

/// One class's handover point in the world (where the simulated operator reaches for the part).
#[derive(Debug, Clone, Copy)]
pub struct ClassHandover {
    pub class: TrajectoryClass,
    pub point: Point3<f64>,
}

/// The process's resident memory now, MiB (`None` where the system does not say).
pub type MemoryMib<'a> = Box<dyn Fn() -> Option<f64> + 'a>;

/// What the station asks its caller for.
pub struct TwinHooks<'a> {
    /// Where the station's lines go.
    pub say: Box<dyn FnMut(&str) + 'a>,
    /// The monotonic wall clock.
    pub wall: Box<dyn Fn() -> Instant + 'a>,
    /// Real time (the operator display shows the session as it happens): each frame waits for its
    /// wall-clock time, through this sleep.
    pub sleep: Option<Box<dyn Fn(Duration) + 'a>>,
    /// The soak report (`--soak-report`): its period in simulated time and the process's resident
    /// memory, MiB.
    pub soak: Option<(Duration, MemoryMib<'a>)>,
}

/// The twin's joint states: a KUKA driver's 250 Hz.
pub const JOINT_STATE_PERIOD_NANOS: i64 = 4_000_000;
/// Joint states stale after this long (`[ros] joint_state_timeout_s`'s default).
pub const JOINT_STATE_TIMEOUT_S: f64 = 0.1;

/// The twin's station (see the module's documentation).
pub struct TwinStation<'a> {
    source: SimSource,
    faults: FaultPlayer,
    handovers: Vec<ClassHandover>,
    /// The class whose robot serves the operator (their own until the cell decides another).
    served: TrajectoryClass,
    true_class: TrajectoryClass,
    joints: Vec<String>,
    rig: &'a CameraRig,
    start: i64,
    period_nanos: i64,
    /// The simulator's clock: the time of the frame now being played.
    now: i64,
    /// The frame's views, polled and waiting for the robot side's reports up to `now` to be
    /// handed over first.
    views: Option<Vec<View2>>,
    /// The last input handed over was the frame's views (the frame is done once it is stepped).
    frame_step: bool,
    class_change: bool,
    script: ScriptState,
    last_status: i64,
    soak: Option<Soak>,
    hooks: TwinHooks<'a>,
    wall_start: Instant,
    step_started: Instant,
}

/// Where the simulated operator's script is.
#[derive(Default)]
struct ScriptState {
    /// The script is over (the cell is empty).
    done: bool,
    /// The operator is down for the floor pick.
    picking: bool,
}

/// The twin's cell loop.
pub type TwinLoop<O> = CellLoop<TwinRobot, O>;

fn secs(t: i64, start: i64) -> f64 {
    (t - start) as f64 * 1e-9
}

impl<'a> TwinStation<'a> {
    /// The station playing `source` from `start` at `period_nanos` a frame, with `faults`; the
    /// operator is of `true_class` and reaches for the decided class's point among `handovers`;
    /// the twin robot's `joints` are recorded.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        source: SimSource,
        faults: FaultPlayer,
        handovers: Vec<ClassHandover>,
        true_class: TrajectoryClass,
        joints: Vec<String>,
        rig: &'a CameraRig,
        start: i64,
        period_nanos: i64,
        mut hooks: TwinHooks<'a>,
    ) -> Self {
        let soak = hooks.soak.as_ref().map(|(every, memory)| {
            let soak = Soak::new(*every, start);
            (hooks.say)(&soak_first_line(memory()));
            soak
        });
        let now = (hooks.wall)();
        Self {
            source,
            faults,
            handovers,
            served: true_class,
            true_class,
            joints,
            rig,
            start,
            period_nanos,
            now: start,
            views: None,
            frame_step: false,
            class_change: false,
            script: ScriptState::default(),
            last_status: start,
            soak,
            hooks,
            wall_start: now,
            step_started: now,
        }
    }

    /// The simulator's clock now, nanoseconds.
    pub fn now(&self) -> i64 {
        self.now
    }

    /// The soak report's last line, at the end (`None` without `--soak-report`).
    pub fn soak_last_line(&mut self) -> Option<String> {
        let elapsed_h = secs(self.now, self.start) / 3600.0;
        let memory = self.hooks.soak.as_ref().map(|(_, m)| m())?;
        Some(self.soak.as_mut()?.line(elapsed_h, memory))
    }

    fn say(&mut self, line: &str) {
        (self.hooks.say)(line);
    }

    /// A line stamped with the session's time.
    fn say_at(&mut self, now: i64, what: &str) {
        let line = format!("  t={:5.1} s  {what}", secs(now, self.start));
        self.say(&line);
    }
}

impl<O: TwinOutputs> Station<TwinRobot, O> for TwinStation<'_> {
    type Error = TwinError;

    fn name(&self) -> &'static str {
        "simulator"
    }

    fn now_nanos(&mut self) -> i64 {
        self.now
    }

    /// Per frame: the cameras polled, then the robot side's reports up to the frame's time (each
    /// batch at its own time, as `run` steps on every report it receives), then the frame's views
    /// with the fault schedule applied.
    async fn next(&mut self, cell: &mut TwinLoop<O>) -> Result<Option<Timed>, TwinError> {
        let now = self.now;
        if self.views.is_none() {
            if let Some(sleep) = &self.hooks.sleep {
                // real time: the page shows the session as it happens
                let due = Duration::from_nanos(u64::try_from(now - self.start).unwrap_or(0));
                let elapsed = (self.hooks.wall)().saturating_duration_since(self.wall_start);
                if let Some(wait) = due.checked_sub(elapsed) {
                    sleep(wait);
                }
            }
            self.step_started = (self.hooks.wall)();
            self.views = Some(self.poll(now)?);
        }
        if let Some((t, reports)) = cell.robot_mut().advance(now) {
            self.frame_step = false;
            return Ok(Some(Timed::new(t, Input::Reports(reports))));
        }
        let mut views = self.views.take().unwrap_or_default();
        self.class_change = self.apply_faults(cell, now, &mut views);
        cell.outputs_mut().views(self.rig, now, &views);
        self.frame_step = true;
        Ok(Some(Timed::new(now, Input::Views(views))))
    }

    /// Handed to the outputs (recorded as a real cell records its controller's events), and said.
    fn reported(
        &mut self,
        cell: &mut TwinLoop<O>,
        t: i64,
        report: &RobotReport,
        effect: &ReportEffect,
    ) -> Result<(), TwinError> {
        cell.outputs_mut().robot_report(t, report, effect);
        if let Some(failure) = &effect.failure {
            self.say_at(t, &format!("robot: {failure}"));
        }
        if let Some(readiness) = &effect.driver_readiness {
            let state = readiness.as_ref().map_or_else(
                || "configured and controlling".to_owned(),
                ToString::to_string,
            );
            self.say_at(t, &format!("driver: {state}"));
        }
        Ok(())
    }

    fn stepped(&mut self, cell: &mut TwinLoop<O>, at: i64, step: &Step) -> Result<(), TwinError> {
        self.follow_decision(&step.events, at)?;
        // the frame's own step (not a report batch's, nor the early-end rules' alone) ends it
        if !std::mem::take(&mut self.frame_step) {
            return Ok(());
        }
        let now = self.now;
        if cell.machine().state() == SessionState::Working {
            // The first call counts: the moment the faults are timed from.
            self.faults.working(now);
        }
        // A supervisor asks for another class mid-session (the schedule's request): refused.
        if std::mem::take(&mut self.class_change) {
            let other = if cell.machine().summary().class == Some(TrajectoryClass::C3) {
                TrajectoryClass::C1
            } else {
                TrajectoryClass::C3
            };
            cell.request_class(now, other);
        }
        if let Some(position) = cell.robot_mut().joint_positions(now, &self.joints) {
            cell.outputs_mut()
                .robot_state(now, self.served, &self.joints, position);
        }
        if now - self.last_status >= STATUS_PERIOD_NANOS {
            self.last_status = now;
            let m = cell.machine();
            let line = format!(
                "{:<18} cameras {}/{}  pairs tracking {}  {}",
                m.state().name(),
                m.cameras_fresh(),
                self.rig.len(),
                m.pairs_tracking(),
                cell.outputs().rula_status()
            );
            self.say_at(now, &line);
        }
        self.soak_step(now);
        self.now += self.period_nanos;
        Ok(())
    }

    fn next_machine(&mut self, _cell: &mut TwinLoop<O>) -> Result<SessionMachine, TwinError> {
        Err(TwinError::OneSession)
    }
}

/// The status line's period: 5 s of simulated time.
const STATUS_PERIOD_NANOS: i64 = 5_000_000_000;

impl TwinStation<'_> {
    /// The simulated cameras' views at `now`; once the script is over the cell is empty and the
    /// cameras keep publishing "nobody".
    fn poll(&mut self, now: i64) -> Result<Vec<View2>, TwinError> {
        if !self.script.done {
            match self.source.poll(now)? {
                Some(views) => {
                    // The simulator's ground truth: when the operator bends down and stands up.
                    let picking = self
                        .source
                        .last_tick
                        .as_ref()
                        .is_some_and(|t| matches!(t.truth.phase, Phase::FloorPick { .. }));
                    if picking != self.script.picking {
                        self.script.picking = picking;
                        self.say_at(
                            now,
                            if picking {
                                "(simulator) operator bends down for the dropped part (floor pick)"
                            } else {
                                "(simulator) operator stands back up with the part"
                            },
                        );
                    }
                    return Ok(views);
                }
                None => self.script.done = true,
            }
        }
        Ok((0..self.rig.len()).map(|k| View2::empty(k, now)).collect())
    }

    /// The fault schedule at `now`: silenced cameras' views dropped; whether a class change request
    /// is due; a robot fault due is armed on the twin's controller. The robot's arrival with each
    /// part is a moment the schedule is timed from.
    fn apply_faults<O: TwinOutputs>(
        &mut self,
        cell: &mut TwinLoop<O>,
        now: i64,
        views: &mut Vec<View2>,
    ) -> bool {
        if let Some((
            sent,
            RobotCommand::Execute {
                leg: Leg::ToHandover,
                trajectory,
                ..
            },
        )) = cell.robot().controller.received.last()
        {
            let arrived = sent + (trajectory.duration_s() * 1e9).round() as i64;
            self.faults
                .arrived_with_part(cell.machine().summary().parts_taken + 1, arrived);
        }
        let fault = self.faults.step(now);
        for f in fault.robot {
            self.say_at(now, &format!("(simulator) robot fault armed: {f:?}"));
            // Each was checked against the robot before the session started.
            if let Err(e) = cell.robot_mut().controller.arm(now, f) {
                self.say(&format!("  (simulator) robot fault not played: {e}"));
            }
        }
        if fault.silenced != Silenced::None {
            views.retain(|v| {
                self.rig
                    .camera(v.camera)
                    .is_none_or(|c| !fault.silenced.drops(c.id.as_str()))
            });
        }
        fault.class_change_request
    }

    /// Once the cell decides a class other than the operator's own, the simulated operator reaches
    /// where that class's robot brings the part.
    fn follow_decision(&mut self, events: &[SessionEvent], now: i64) -> Result<(), TwinError> {
        for e in events {
            let SessionEvent::ClassDecided { class, .. } = e else {
                continue;
            };
            let decided = trajectory_class(*class);
            if decided == self.true_class {
                continue;
            }
            let Some(h) = self.handovers.iter().find(|h| h.class == decided).copied() else {
                continue;
            };
            let moved = self
                .source
                .simulation_mut()
                .retarget_handover(h.point, now)
                .map_err(TwinError::Unreachable)?;
            self.served = decided;
            let line = format!(
                "(simulator) the operator (class {}) reaches for class {decided}'s handover point ({moved} cycle(s))",
                self.true_class
            );
            self.say_at(now, &line);
        }
        Ok(())
    }

    /// The soak report's accounting of the frame's step; a line when one is due.
    fn soak_step(&mut self, now: i64) {
        let step = (self.hooks.wall)().saturating_duration_since(self.step_started);
        let Some(soak) = self.soak.as_mut() else {
            return;
        };
        soak.steps_us.push(step.as_secs_f64() * 1e6);
        if now < soak.next_nanos {
            return;
        }
        soak.next_nanos += soak.every_nanos;
        let memory = self.hooks.soak.as_ref().and_then(|(_, m)| m());
        let line = soak.line(secs(now, self.start) / 3600.0, memory);
        self.say(&line);
    }
}

/// The soak report's accumulator: step wall times since the last line.
struct Soak {
    every_nanos: i64,
    next_nanos: i64,
    steps_us: Vec<f64>,
}

fn memory_text(mib: Option<f64>) -> String {
    mib.map_or("n/a".to_owned(), |m| format!("{m:.1}"))
}

fn soak_first_line(memory_mib: Option<f64>) -> String {
    format!("  soak: t=  0.00 h  RSS {} MiB", memory_text(memory_mib))
}

impl Soak {
    /// A report every `every` of simulated time from `start`.
    fn new(every: Duration, start: i64) -> Self {
        let every_nanos = i64::try_from(every.as_nanos()).unwrap_or(i64::MAX);
        Self {
            every_nanos,
            next_nanos: start.saturating_add(every_nanos),
            steps_us: Vec::new(),
        }
    }

    /// The line: the memory, the steps' p50, p99 and largest wall time since the last line; the
    /// steps are then forgotten.
    fn line(&mut self, elapsed_h: f64, memory_mib: Option<f64>) -> String {
        self.steps_us.sort_by(f64::total_cmp);
        let q = |p: f64| ergocell_perception::metrics::rank_quantile(&self.steps_us, p);
        let line = format!(
            "  soak: t={elapsed_h:6.2} h  RSS {} MiB  step p50 {:.0} µs  p99 {:.0} µs  max {:.0} µs  ({} steps)",
            memory_text(memory_mib),
            q(0.5),
            q(0.99),
            q(1.0),
            self.steps_us.len()
        );
        self.steps_us.clear();
        line
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_soak_line_states_the_quantiles_of_the_steps_since_the_last_line() {
        let mut soak = Soak::new(Duration::from_mins(1), 0);
        assert_eq!(soak.next_nanos, 60_000_000_000);
        soak.steps_us.extend([300.0, 100.0, 200.0]);
        assert_eq!(
            soak.line(1.5, Some(42.31)),
            "  soak: t=  1.50 h  RSS 42.3 MiB  step p50 200 µs  p99 300 µs  max 300 µs  (3 steps)"
        );
        assert!(soak.steps_us.is_empty());
        assert_eq!(
            soak.line(2.0, None),
            "  soak: t=  2.00 h  RSS n/a MiB  step p50 NaN µs  p99 NaN µs  max NaN µs  (0 steps)"
        );
    }
}
