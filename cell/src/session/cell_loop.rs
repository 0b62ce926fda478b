//! The cell loop: the one place a session machine is stepped, whatever the backend.
//!
//! `ergocell run` (ROS 2) and `ergocell demo` (the digital twin) only compose it: the caller's
//! landmark source gives the views that arrived, [`CellLoop::step`] steps the machine on the caller's
//! clock (an injected time, never read here), the [`RobotSink`] takes the commands and the
//! [`CellOutputs`] (publisher, recorder, display, console — whatever the binary wires) see every
//! step's events. What the loop owns, so that no backend can forget it:
//!
//! - **The rules that end a session early, each holding the robot**, checked before every step in
//!   this order: an output that failed (a recording that cannot be written: a cell that records must
//!   not run on unrecorded; the failed output is the caller's to silence), the robot side failed (the
//!   controller refused, aborted or did not answer a goal; the execution monitor saw a deviation),
//!   a stop was asked for (Ctrl-C, SIGTERM), the time limit. The first one found is the reason.
//! - **The robot side's reports** ([`CellLoop::report`]): what each means is decided by the rules
//!   of [`super::robot_side`] (a failure ends the session, the first one being the reason).
//! - **The robot's readiness** (the driver configured and controlling, joint states fresh): while
//!   either side says no, the machine holds and sends no goal; it resumes by its usual rules.
//! - **The shutdown**: the hold is sent, the machine ends, and the outputs see the shutdown's events
//!   like any step's. An output that fails during a step ends the session at once, held.
//! - **What follows the end** ([`Ending::after`]): the next operator only after a normal end, and
//!   the program's exit status otherwise.

use ergocell_perception::View2;
use ergocell_robot::TrajectoryClass;

use super::driver::CommandSent;
use super::end::{Interruption, SessionEnd, StopSignal};
use super::robot_side::{DriverState, ReportEffect, RobotFailure, RobotReport, RobotUnready};
use super::{RobotSink, SessionEvent, SessionMachine, SessionState};

/// An output of the cell (a publisher, a recorder, a display): it sees every step's events.
pub trait CellOutputs {
    /// The events of one step (or of the shutdown) at `now_nanos`; `machine` is the machine after it.
    fn session_step(
        &mut self,
        now_nanos: i64,
        machine: &SessionMachine,
        events: &[SessionEvent],
    ) -> Result<(), OutputError>;

    /// An output that failed since the last call outside [`CellOutputs::session_step`] (e.g. a
    /// recorder whose write of a camera message failed); the loop ends the session held.
    fn take_failure(&mut self) -> Option<OutputError> {
        None
    }
}

/// No outputs (a test, a measurement).
impl CellOutputs for () {
    fn session_step(
        &mut self,
        _now_nanos: i64,
        _machine: &SessionMachine,
        _events: &[SessionEvent],
    ) -> Result<(), OutputError> {
        Ok(())
    }
}

/// An output that cannot go on: its name ("recording", "ROS 2 publisher") and its error.
#[derive(Debug, Clone, thiserror::Error, serde::Serialize)]
#[error("{output} failed: {}", crate::error::chain(cause.as_ref()))]
pub struct OutputError {
    pub output: &'static str,
    /// The output's error (its chain is in this error's message; the outcome file's `why`).
    #[serde(rename = "why", serialize_with = "crate::error::serialize_cause")]
    pub cause: crate::error::Cause,
}

/// How and when the session ended: the machine's own end, or an [`Interruption`] of the loop's
/// rules.
#[derive(Debug, Clone)]
pub struct Ending {
    pub end: SessionEnd,
    pub stamp_nanos: i64,
}

impl Ending {
    /// The interruption that ended the session early, if one did.
    pub fn interruption(&self) -> Option<&Interruption> {
        match &self.end {
            SessionEnd::Interrupted { by } => Some(by),
            _ => None,
        }
    }

    /// The cell's rule for what follows this ending, the `sessions_done`-th (1 for the first), when
    /// `sessions_wanted` sessions were asked for (`None`: one after another until stopped). Only a
    /// normal end (the operator left, the robot at home) lets the next operator in; any other end
    /// needs a person and stops the program, as a stop signal does.
    pub fn after(&self, sessions_done: u32, sessions_wanted: Option<u32>) -> AfterSession {
        match &self.end {
            SessionEnd::OperatorLeft { .. } => {
                if sessions_wanted.is_none_or(|n| sessions_done < n) {
                    AfterSession::NextSession
                } else {
                    AfterSession::Stop(ExitStatus::Done)
                }
            }
            SessionEnd::Interrupted {
                by: Interruption::Stopped { signal },
            } => AfterSession::Stop(ExitStatus::Stopped(*signal)),
            _ => AfterSession::Stop(ExitStatus::NeedsAPerson),
        }
    }
}

/// What follows a session's end ([`Ending::after`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AfterSession {
    /// Wait for the next operator, on the same robot and outputs.
    NextSession,
    /// Stop the program.
    Stop(ExitStatus),
}

/// How the program ends after its sessions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExitStatus {
    /// The sessions asked for ended normally: exit 0.
    Done,
    /// A session did not end normally (it could not serve, the robot side or an output failed, the
    /// time limit passed): the robot is held and a person must look: exit 1.
    NeedsAPerson,
    /// A stop signal, the robot held: 128 + the signal's number (130 for SIGINT, 143 for SIGTERM).
    Stopped(StopSignal),
}

impl ExitStatus {
    /// The process exit code.
    pub const fn code(self) -> u8 {
        match self {
            Self::Done => 0,
            Self::NeedsAPerson => 1,
            Self::Stopped(StopSignal::Interrupt) => 130,
            Self::Stopped(StopSignal::Terminate) => 143,
        }
    }
}

/// What one [`CellLoop::step`] did.
#[derive(Debug, Clone)]
pub struct Step {
    /// The events of the step (or of the shutdown), as the outputs saw them.
    pub events: Vec<SessionEvent>,
    /// Set once the session has ended (and on every step after).
    pub ended: Option<Ending>,
}

/// The robot side's readiness: the driver's state (when the backend reads it) and the joint
/// states' freshness.
#[derive(Debug, Clone, Default, PartialEq)]
struct Readiness {
    driver: Option<DriverState>,
    joint_states: Option<RobotUnready>,
}

impl Readiness {
    fn unready(&self) -> Option<RobotUnready> {
        self.driver
            .as_ref()
            .and_then(DriverState::unready)
            .or_else(|| self.joint_states.clone())
    }
}

/// One session's loop: the machine, the robot sink, the outputs and the early-end rules.
pub struct CellLoop<R, O> {
    machine: SessionMachine,
    robot: R,
    outputs: O,
    deadline: Option<(i64, f64)>,
    robot_failure: Option<RobotFailure>,
    stop: Option<StopSignal>,
    readiness: Readiness,
    ended: Option<Ending>,
    /// Every command sent, when kept ([`CellLoop::with_command_log`]).
    commands: Option<Vec<CommandSent>>,
}

impl<R: RobotSink, O: CellOutputs> CellLoop<R, O> {
    pub fn new(machine: SessionMachine, robot: R, outputs: O) -> Self {
        Self {
            machine,
            robot,
            outputs,
            deadline: None,
            robot_failure: None,
            stop: None,
            readiness: Readiness::default(),
            ended: None,
            commands: None,
        }
    }

    /// Keeps every command the machine sends (from every step, a refused class change and the
    /// shutdown alike), for [`CellLoop::take_commands`]: the outcome a program reads. Off by
    /// default, so that a cell running for weeks keeps nothing it was not asked to.
    #[must_use]
    pub fn with_command_log(mut self) -> Self {
        self.commands = Some(Vec::new());
        self
    }

    /// The commands kept since the last call (none without [`CellLoop::with_command_log`]).
    pub fn take_commands(&mut self) -> Vec<CommandSent> {
        self.commands
            .as_mut()
            .map(std::mem::take)
            .unwrap_or_default()
    }

    fn log_commands(&mut self, events: &[SessionEvent]) {
        if let Some(log) = self.commands.as_mut() {
            log.extend(events.iter().filter_map(CommandSent::of));
        }
    }

    /// Ends the session, holding the robot, at the first step after `at_nanos`
    /// ([`Interruption::TimeLimit`] with `limit_s`, the limit as the caller set it).
    #[must_use]
    pub fn with_deadline(mut self, at_nanos: i64, limit_s: f64) -> Self {
        self.deadline = Some((at_nanos, limit_s));
        self
    }

    /// [`Self::with_deadline`] `limit_s` seconds after `start_nanos`.
    #[must_use]
    pub fn with_time_limit(self, start_nanos: i64, limit_s: f64) -> Self {
        let at = start_nanos.saturating_add((limit_s * 1e9).round() as i64);
        self.with_deadline(at, limit_s)
    }

    /// The robot may move only while the KUKA driver is configured and controlling (its
    /// `is_configured` and hardware events, [`RobotReport::DriverConfigured`] and
    /// [`RobotReport::DriverEvent`]): until it says so, the session holds.
    #[must_use]
    pub fn with_driver_state(mut self) -> Self {
        self.readiness.driver = Some(DriverState::default());
        self
    }

    /// The driver's readiness (`Some(None)`: ready), when the loop reads the driver's state.
    pub fn driver_readiness(&self) -> Option<Option<RobotUnready>> {
        self.readiness.driver.as_ref().map(DriverState::unready)
    }

    pub fn machine(&self) -> &SessionMachine {
        &self.machine
    }

    pub fn robot(&self) -> &R {
        &self.robot
    }

    pub fn robot_mut(&mut self) -> &mut R {
        &mut self.robot
    }

    pub fn outputs(&self) -> &O {
        &self.outputs
    }

    pub fn outputs_mut(&mut self) -> &mut O {
        &mut self.outputs
    }

    /// The ending, once the session has ended.
    pub fn ended(&self) -> Option<&Ending> {
        self.ended.as_ref()
    }

    /// The loop's parts back (the machine, the robot, the outputs).
    pub fn into_parts(self) -> (SessionMachine, R, O) {
        (self.machine, self.robot, self.outputs)
    }

    /// A report from the robot side, applied by the rules of [`super::robot_side`]: a failure ends
    /// the session, held, at the next step (the first failure is the reason; later ones are
    /// dropped); the driver's state and stale joint states hold the robot until they clear.
    pub fn report(&mut self, report: RobotReport) -> ReportEffect {
        let mut effect = ReportEffect::default();
        let driver_before = self.driver_readiness();
        match report {
            RobotReport::Goal(answer) => effect.failure = answer.failure(),
            RobotReport::Deviation(deviation) => {
                effect.failure = Some(RobotFailure::Deviation { deviation });
            }
            RobotReport::JointStatesStale { timeout_s } => {
                self.readiness.joint_states = Some(RobotUnready::JointStatesStale { timeout_s });
            }
            RobotReport::JointStatesBack => self.readiness.joint_states = None,
            RobotReport::DriverConfigured(configured) => {
                if let Some(d) = self.readiness.driver.as_mut() {
                    d.on_configured(configured);
                }
            }
            RobotReport::DriverEvent(event) => {
                if let Some(d) = self.readiness.driver.as_mut() {
                    d.on_event(event);
                }
            }
        }
        let driver_after = self.driver_readiness();
        if driver_after != driver_before {
            effect.driver_readiness = driver_after;
        }
        if let Some(failure) = &effect.failure {
            if self.ended.is_none() {
                self.robot_failure.get_or_insert_with(|| failure.clone());
            }
        }
        effect
    }

    /// A stop was asked for: the session ends, held, at the next step.
    pub fn stop(&mut self, signal: StopSignal) {
        self.stop.get_or_insert(signal);
    }

    /// The next session on the same robot and outputs (after the last one ended normally).
    pub fn next_session(&mut self, machine: SessionMachine) -> SessionMachine {
        self.ended = None;
        std::mem::replace(&mut self.machine, machine)
    }

    /// A mid-session request for another class: always refused once locked; the event goes to the
    /// outputs like a step's.
    pub fn request_class(&mut self, now_nanos: i64, class: TrajectoryClass) -> Step {
        if self.ended.is_some() {
            return self.ended_step();
        }
        let event = self.machine.request_class(now_nanos, class);
        self.deliver(now_nanos, vec![event])
    }

    /// One step at `now_nanos` with the views that arrived since the last one: first the early-end
    /// rules (a reason found ends the session, held, instead of stepping), then the robot's
    /// readiness, then the machine; the outputs see the events.
    pub fn step(&mut self, now_nanos: i64, views: Vec<View2>) -> Step {
        if let Some(step) = self.check(now_nanos) {
            return step;
        }
        self.machine.set_robot_unready(self.readiness.unready());
        let events = self.machine.step(now_nanos, views, &mut self.robot);
        self.deliver(now_nanos, events)
    }

    /// The early-end rules alone, at `now_nanos`: `Some` (the shutdown's step) once the session has
    /// ended, by one of them now or before. A caller that gathers its inputs at a cost (polls the
    /// cameras, records them) checks first; [`CellLoop::step`] checks itself.
    pub fn check(&mut self, now_nanos: i64) -> Option<Step> {
        if self.ended.is_some() {
            return Some(self.ended_step());
        }
        let by = self.early_end(now_nanos)?;
        Some(self.interrupt(now_nanos, by))
    }

    /// Ends the session now, holding the robot, for `by` (the loop's own rules, or a caller's
    /// reason: an input that failed); the shutdown's step. A session already ended keeps its
    /// ending.
    pub fn interrupt(&mut self, now_nanos: i64, by: Interruption) -> Step {
        if self.ended.is_some() {
            return self.ended_step();
        }
        let events = self
            .machine
            .shutdown(now_nanos, &mut self.robot, by.clone());
        self.log_commands(&events);
        if let Err(e) = self.outputs.session_step(now_nanos, &self.machine, &events) {
            // Already ending: the failure is reported, the robot is held either way.
            tracing::error!(error = %e, "an output failed while the session was ending");
        }
        // The interruption is the ending, even when the machine had just ended by itself in the
        // same step (an output that failed on the operator's departure): what follows is decided by
        // the interruption, never by a normal end the loop could not finish.
        self.ended = Some(Ending {
            end: SessionEnd::Interrupted { by },
            stamp_nanos: now_nanos,
        });
        Step {
            events,
            ended: self.ended.clone(),
        }
    }

    /// The first reason to end now, in the rules' order.
    fn early_end(&mut self, now_nanos: i64) -> Option<Interruption> {
        if let Some(error) = self.outputs.take_failure() {
            return Some(Interruption::OutputFailed { error });
        }
        if let Some(failure) = self.robot_failure.take() {
            return Some(Interruption::RobotFailed { failure });
        }
        if let Some(signal) = self.stop {
            return Some(Interruption::Stopped { signal });
        }
        match self.deadline {
            Some((at, limit_s)) if now_nanos > at => Some(Interruption::TimeLimit { limit_s }),
            _ => None,
        }
    }

    /// The outputs see `events`; an output that fails ends the session at once, held.
    fn deliver(&mut self, now_nanos: i64, events: Vec<SessionEvent>) -> Step {
        self.log_commands(&events);
        if let Err(e) = self.outputs.session_step(now_nanos, &self.machine, &events) {
            let mut step = self.interrupt(now_nanos, Interruption::OutputFailed { error: e });
            let mut all = events;
            all.append(&mut step.events);
            step.events = all;
            return step;
        }
        if self.machine.state() == SessionState::SessionEnded && self.ended.is_none() {
            self.ended = self.machine.summary().end.clone().map(|end| Ending {
                end,
                stamp_nanos: now_nanos,
            });
        }
        Step {
            events,
            ended: self.ended.clone(),
        }
    }

    fn ended_step(&self) -> Step {
        Step {
            events: Vec::new(),
            ended: self.ended.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::session::robot_side::RobotFailure;

    fn ending(end: SessionEnd) -> Ending {
        Ending {
            end,
            stamp_nanos: 0,
        }
    }

    /// Only a normal end lets the next operator in, until the sessions asked for are done; every
    /// other end stops with its status.
    #[test]
    fn the_next_session_follows_only_a_normal_end_and_every_other_end_has_its_exit_code() {
        let left = ending(SessionEnd::OperatorLeft { changes_refused: 0 });
        assert_eq!(left.after(1, None), AfterSession::NextSession);
        assert_eq!(left.after(1, Some(2)), AfterSession::NextSession);
        assert_eq!(left.after(2, Some(2)), AfterSession::Stop(ExitStatus::Done));
        let failed = ending(SessionEnd::Interrupted {
            by: Interruption::RobotFailed {
                failure: RobotFailure::GoalRejected { leg: None },
            },
        });
        let limit = ending(SessionEnd::Interrupted {
            by: Interruption::TimeLimit { limit_s: 5.0 },
        });
        for e in [&failed, &limit] {
            assert_eq!(
                e.after(1, None),
                AfterSession::Stop(ExitStatus::NeedsAPerson)
            );
        }
        for (signal, code) in [(StopSignal::Interrupt, 130), (StopSignal::Terminate, 143)] {
            let stopped = ending(SessionEnd::Interrupted {
                by: Interruption::Stopped { signal },
            });
            let AfterSession::Stop(status) = stopped.after(1, None) else {
                panic!("a stop goes on");
            };
            assert_eq!((status, status.code()), (ExitStatus::Stopped(signal), code));
        }
        assert_eq!(
            (ExitStatus::Done.code(), ExitStatus::NeedsAPerson.code()),
            (0, 1)
        );
    }
}
