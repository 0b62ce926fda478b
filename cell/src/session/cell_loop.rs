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
//! - **The robot's readiness** (the driver configured and controlling, joint states fresh): while
//!   either side says no, the machine holds and sends no goal; it resumes by its usual rules.
//! - **The shutdown**: the hold is sent, the machine ends, and the outputs see the shutdown's events
//!   like any step's. An output that fails during a step ends the session at once, held.

use ergocell_perception::View2;
use ergocell_robot::TrajectoryClass;

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

/// An output that cannot go on: its name ("recording", "ROS 2 publisher") and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{output} failed: {why}")]
pub struct OutputError {
    pub output: &'static str,
    pub why: String,
}

/// Why the loop ended the session.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EndCause {
    /// The machine ended the session itself (the operator left, or it could not go on: its summary
    /// says which).
    Session,
    /// An output failed ([`OutputError`]).
    OutputFailed,
    /// The robot side failed ([`CellLoop::robot_failed`]).
    RobotFailed,
    /// A stop was asked for ([`CellLoop::stop`]).
    Stopped,
    /// The time limit ([`CellLoop::with_deadline`]) passed.
    TimeLimit,
}

/// How and when the session ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ending {
    pub cause: EndCause,
    /// The reason as the machine recorded it (the hold's reason for an early end).
    pub reason: String,
    pub stamp_nanos: i64,
}

/// What one [`CellLoop::step`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// The events of the step (or of the shutdown), as the outputs saw them.
    pub events: Vec<SessionEvent>,
    /// Set once the session has ended (and on every step after).
    pub ended: Option<Ending>,
}

/// The robot side's readiness, as its two reporters last said it.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
struct Readiness {
    driver: Option<String>,
    joint_states: Option<String>,
}

/// One session's loop: the machine, the robot sink, the outputs and the early-end rules.
pub struct CellLoop<R, O> {
    machine: SessionMachine,
    robot: R,
    outputs: O,
    deadline: Option<(i64, String)>,
    robot_failure: Option<String>,
    stop: Option<String>,
    readiness: Readiness,
    ended: Option<Ending>,
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
        }
    }

    /// Ends the session, holding the robot, at the first step after `at_nanos`, with `why`.
    #[must_use]
    pub fn with_deadline(mut self, at_nanos: i64, why: impl Into<String>) -> Self {
        self.deadline = Some((at_nanos, why.into()));
        self
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

    /// The robot side failed (`why`: the controller's reason, the monitor's verdict): the session
    /// ends, held, at the next step. The first failure is the reason; later ones are dropped.
    pub fn robot_failed(&mut self, why: impl Into<String>) {
        self.robot_failure.get_or_insert_with(|| why.into());
    }

    /// A stop was asked for (`why`: "SIGINT", "SIGTERM"): the session ends, held, at the next step.
    pub fn stop(&mut self, why: impl Into<String>) {
        self.stop.get_or_insert_with(|| why.into());
    }

    /// The robot driver's readiness (`Some(why)` while it is not configured or not controlling).
    pub fn set_driver_unready(&mut self, why: Option<String>) {
        self.readiness.driver = why;
    }

    /// Whether the joint states are fresh (`Some(why)` while they are stale).
    pub fn set_joint_states_stale(&mut self, why: Option<String>) {
        self.readiness.joint_states = why;
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
        let unready = self
            .readiness
            .driver
            .clone()
            .or_else(|| self.readiness.joint_states.clone());
        self.machine.set_robot_unready(unready);
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
        let (cause, why) = self.early_end(now_nanos)?;
        Some(self.end(now_nanos, cause, &why))
    }

    /// Ends the session now, holding the robot, for `cause` with `why` (a caller's own reason: the
    /// rules of [`CellLoop::step`] cover the usual ones).
    pub fn end(&mut self, now_nanos: i64, cause: EndCause, why: &str) -> Step {
        if self.ended.is_some() {
            return self.ended_step();
        }
        let events = self.machine.shutdown(now_nanos, &mut self.robot, why);
        if let Err(e) = self.outputs.session_step(now_nanos, &self.machine, &events) {
            // Already ending: the failure is reported, the robot is held either way.
            tracing::error!(error = %e, "an output failed while the session was ending");
        }
        self.ended = Some(Ending {
            cause,
            reason: why.to_owned(),
            stamp_nanos: now_nanos,
        });
        Step {
            events,
            ended: self.ended.clone(),
        }
    }

    /// The first reason to end now, in the rules' order.
    fn early_end(&mut self, now_nanos: i64) -> Option<(EndCause, String)> {
        if let Some(e) = self.outputs.take_failure() {
            return Some((EndCause::OutputFailed, e.to_string()));
        }
        if let Some(why) = self.robot_failure.take() {
            return Some((EndCause::RobotFailed, why));
        }
        if let Some(why) = self.stop.clone() {
            return Some((EndCause::Stopped, why));
        }
        match &self.deadline {
            Some((at, why)) if now_nanos > *at => Some((EndCause::TimeLimit, why.clone())),
            _ => None,
        }
    }

    /// The outputs see `events`; an output that fails ends the session at once, held.
    fn deliver(&mut self, now_nanos: i64, events: Vec<SessionEvent>) -> Step {
        if let Err(e) = self.outputs.session_step(now_nanos, &self.machine, &events) {
            let mut step = self.end(now_nanos, EndCause::OutputFailed, &e.to_string());
            let mut all = events;
            all.append(&mut step.events);
            step.events = all;
            return step;
        }
        if self.machine.state() == SessionState::SessionEnded {
            self.ended = Some(Ending {
                cause: EndCause::Session,
                reason: self.machine.summary().end_reason.clone(),
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
