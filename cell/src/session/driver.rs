//! The session driver: runs sessions end to end, one after another, until one ends the program.
//!
//! `ergocell run` (ROS 2) and `ergocell demo` (the digital twin) each build a [`CellLoop`] (the
//! machine, the robot port, the outputs) and a [`Station`] (what the cell is wired to: the
//! landmark source and the robot side's reports, each input stamped by the station's clock), and
//! call [`Driver::run`]. Neither has a loop of its own. The driver owns the order of things, so
//! that no backend can get it wrong:
//!
//! 1. a stop asked for ([`StopRequest`]: Ctrl-C, SIGTERM) is handed to the loop, and the loop's
//!    early-end rules run at the station's clock ([`Station::now_nanos`]): a session that ends
//!    there ends before the station gathers another input;
//! 2. the station's next [`Input`]: camera views, the robot side's reports, or the clock's tick (a
//!    stop that came meanwhile is handed over too);
//! 3. each robot report is applied by the cell's rules ([`CellLoop::report`]), then the loop steps
//!    at the input's time (the early-end rules first, then the machine);
//! 4. at a session's end, the cell's rule ([`super::Ending::after`]) says whether the next operator
//!    may come (a fresh machine from the station) or the program stops, and with which status;
//! 5. a goal the controller still runs when the program stops is waited for through the station
//!    ([`Station::settle`]), so that its result is on record.
//!
//! A station that fails ends the session at once, held ([`Interruption::InputFailed`]), and its
//! error is returned with the outcome so far. The driver reads no clock of its own: the station's
//! clock stamps every input (the wall-anchored session clock in `run`, the simulator's in the
//! twin, a test's). It is
//! `async` so that a network station can await its inputs; a simulated one is ready at once and is
//! driven by any executor's `block_on`.

use std::future::Future;
use std::sync::Arc;

use ergocell_perception::View2;

use super::cell_loop::{AfterSession, CellLoop, CellOutputs, Ending, ExitStatus, Step};
use super::end::{HoldReason, Interruption, StopSignal};
use super::robot_side::{ReportEffect, RobotReport};
use super::{Leg, RobotCommand, RobotSink, SessionEvent, SessionMachine};
use crate::error::Cause;

/// What the station hands the driver next.
#[derive(Debug, Clone)]
pub enum Input {
    /// Camera views that arrived (possibly none: a camera message the inbox holds back).
    Views(Vec<View2>),
    /// The robot side's reports, in the order they came.
    Reports(Vec<RobotReport>),
    /// The clock's tick: a step with no views (frames whose fixed lag has passed are released,
    /// the staleness rules run).
    Tick,
}

/// An [`Input`] at the time the station's clock gave it, nanoseconds.
#[derive(Debug, Clone)]
pub struct Timed {
    pub at_nanos: i64,
    pub input: Input,
}

impl Timed {
    pub fn new(at_nanos: i64, input: Input) -> Self {
        Self { at_nanos, input }
    }
}

/// A station that could not give its input (a simulator error, a lost network node): its name and
/// its error. The driver ends the session held for it.
#[derive(Debug, Clone, thiserror::Error, serde::Serialize)]
#[error("{input} failed: {}", crate::error::chain(cause.as_ref()))]
pub struct InputError {
    pub input: &'static str,
    /// The station's error (its chain is in this error's message; the outcome file's `why`).
    #[serde(rename = "why", serialize_with = "crate::error::serialize_cause")]
    pub cause: Cause,
}

/// Whether a stop was asked for (a signal handler's flag, a test's).
pub trait StopRequest {
    fn requested(&self) -> Option<StopSignal>;
}

/// No stop is ever asked for.
impl StopRequest for () {
    fn requested(&self) -> Option<StopSignal> {
        None
    }
}

/// What the cell is wired to besides its robot port and outputs (which the [`CellLoop`] holds):
/// the landmark source and the robot side's reports, stamped by the station's clock, and what the
/// binary does beside the rules (what it says, records or simulates). Every method gets the loop,
/// so that a station can read the robot port (the twin's controller advances there) and the
/// outputs.
pub trait Station<R, O> {
    /// The station's error (the binary's `anyhow`, a test's own): kept in the session's end and
    /// returned by the driver as a shared [`Cause`].
    type Error: std::fmt::Display + Into<Box<dyn std::error::Error + Send + Sync>>;

    /// The station's name in an [`InputError`] ("ROS 2 inputs", "simulator").
    fn name(&self) -> &'static str;

    /// The station's clock now, nanoseconds (the wall-anchored session clock, the simulator's, a
    /// test's): the time the early-end rules are checked at before the next input, and a failure's.
    fn now_nanos(&mut self) -> i64;

    /// The next input, awaited (a network station) or at once (a simulated one); `Ok(None)`: an
    /// input that is not the cell's (a joint state the station only records), asked again.
    fn next(
        &mut self,
        cell: &mut CellLoop<R, O>,
    ) -> impl Future<Output = Result<Option<Timed>, Self::Error>>;

    /// A robot report was applied at `at_nanos` with `effect` (to say, publish or record).
    fn reported(
        &mut self,
        _cell: &mut CellLoop<R, O>,
        _at_nanos: i64,
        _report: &RobotReport,
        _effect: &ReportEffect,
    ) -> Result<(), Self::Error> {
        Ok(())
    }

    /// The loop stepped at `at_nanos` (on an input, or on the early-end rules alone before one).
    fn stepped(
        &mut self,
        _cell: &mut CellLoop<R, O>,
        _at_nanos: i64,
        _step: &Step,
    ) -> Result<(), Self::Error> {
        Ok(())
    }

    /// The machine for the next operator's session (the last one ended normally).
    fn next_machine(&mut self, cell: &mut CellLoop<R, O>) -> Result<SessionMachine, Self::Error>;

    /// The next session began (the loop holds its new machine).
    fn session_began(&mut self, _cell: &mut CellLoop<R, O>) {}

    /// After the program's last session, while the controller still runs a goal: its next reports,
    /// or `None` when the station stops waiting (its own time limit).
    fn settle(
        &mut self,
        _cell: &mut CellLoop<R, O>,
    ) -> impl Future<Output = Result<Option<Timed>, Self::Error>> {
        async { Ok(None) }
    }
}

/// How the driver's sessions ended.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The program's exit status by the cell's rule ([`super::Ending::after`]).
    pub status: ExitStatus,
    /// Sessions ended, the last one included.
    pub sessions: u32,
    /// The last session's ending.
    pub ending: Ending,
    /// Every command the sessions sent the robot, in order, when the loop keeps them
    /// ([`CellLoop::with_command_log`]): what a safety engineer compares between the twin and the
    /// cell.
    pub commands: Vec<CommandSent>,
}

/// A command a session sent the robot, as the outcome keeps it: a goal's leg, a hold's reason.
#[derive(Debug, Clone, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum CommandSent {
    Goal {
        stamp_nanos: i64,
        leg: Leg,
    },
    Hold {
        stamp_nanos: i64,
        reason: HoldReason,
    },
}

impl CommandSent {
    /// The command of a step's event, if it is one.
    pub fn of(event: &SessionEvent) -> Option<Self> {
        let SessionEvent::RobotCommandSent {
            stamp_nanos,
            command,
        } = event
        else {
            return None;
        };
        Some(match command {
            RobotCommand::Execute { leg, .. } => Self::Goal {
                stamp_nanos: *stamp_nanos,
                leg: *leg,
            },
            RobotCommand::Hold { reason } => Self::Hold {
                stamp_nanos: *stamp_nanos,
                reason: reason.clone(),
            },
        })
    }
}

/// The driver failed: the station's error. A failure during a session ended it held
/// ([`Interruption::InputFailed`]); one after a normal end (no machine for the next session) left
/// the robot at home.
#[derive(Debug, thiserror::Error)]
#[error("{}", crate::error::chain(error.as_ref()))]
pub struct DriverError {
    /// The station's error (downcast it to the station's type).
    pub error: Cause,
    /// The sessions as they ended: the last session's ending and the commands sent; the status
    /// is the program's (a person must look, unless a stop signal ended it).
    pub outcome: Option<Outcome>,
}

/// Runs sessions end to end on a [`CellLoop`].
pub struct Driver<R, O> {
    cell: CellLoop<R, O>,
    sessions_wanted: Option<u32>,
}

impl<R: RobotSink, O: CellOutputs> Driver<R, O> {
    /// `sessions_wanted`: the sessions to run (`None`: one after another until one ends otherwise
    /// than normally, or a stop).
    pub fn new(cell: CellLoop<R, O>, sessions_wanted: Option<u32>) -> Self {
        Self {
            cell,
            sessions_wanted,
        }
    }

    pub fn into_cell(self) -> CellLoop<R, O> {
        self.cell
    }

    /// Runs until the cell's rule stops the program; the typed outcome.
    pub async fn run<S: Station<R, O>>(
        &mut self,
        station: &mut S,
        stop: &dyn StopRequest,
    ) -> Result<Outcome, DriverError> {
        let mut sessions = 0u32;
        let (status, ending) = loop {
            // A stop asked for, the time limit, an output that failed: the session ends before the
            // station gathers its next input.
            if let Some(signal) = stop.requested() {
                self.cell.stop(signal);
            }
            let now = station.now_nanos();
            let (at, step) = if let Some(step) = self.cell.check(now) {
                (now, step)
            } else {
                let timed = match station.next(&mut self.cell).await {
                    Ok(Some(t)) => t,
                    Ok(None) => continue,
                    Err(error) => return Err(self.failed(station, sessions, error)),
                };
                let at = timed.at_nanos;
                // a signal that came while the station waited
                if let Some(signal) = stop.requested() {
                    self.cell.stop(signal);
                }
                let views = match timed.input {
                    Input::Views(views) => views,
                    Input::Tick => Vec::new(),
                    Input::Reports(reports) => {
                        if let Err(error) = self.apply(station, at, reports) {
                            return Err(self.failed(station, sessions, error));
                        }
                        Vec::new()
                    }
                };
                (at, self.cell.step(at, views))
            };
            if let Err(error) = station.stepped(&mut self.cell, at, &step) {
                return Err(self.failed(station, sessions, error));
            }
            let Some(ending) = step.ended else {
                continue;
            };
            sessions += 1;
            match ending.after(sessions, self.sessions_wanted) {
                AfterSession::NextSession => match station.next_machine(&mut self.cell) {
                    Ok(machine) => {
                        self.cell.next_session(machine);
                        station.session_began(&mut self.cell);
                    }
                    // The last session ended normally (the robot home): there is nothing to hold,
                    // and the program stops for a person all the same.
                    Err(error) => {
                        return Err(DriverError {
                            error: Arc::from(error.into()),
                            outcome: Some(self.failed_outcome(sessions, ending)),
                        })
                    }
                },
                AfterSession::Stop(status) => break (status, ending),
            }
        };
        // A goal the controller accepted and has not finished: its result is waited for, so the
        // last leg's result is on record.
        while self.cell.robot().goal_outstanding() {
            match station.settle(&mut self.cell).await {
                Ok(Some(Timed {
                    at_nanos,
                    input: Input::Reports(reports),
                })) => {
                    if let Err(error) = self.apply(station, at_nanos, reports) {
                        tracing::error!(%error, "after the session, a robot report could not be kept");
                    }
                }
                Ok(Some(_)) => {}
                Ok(None) => break,
                Err(error) => {
                    tracing::error!(%error, "after the session, the controller's answer was not waited for");
                    break;
                }
            }
        }
        Ok(Outcome {
            status,
            ..self.outcome(sessions, ending)
        })
    }

    /// The outcome of `sessions` sessions, the last one ending with `ending`, by the cell's rule.
    fn outcome(&mut self, sessions: u32, ending: Ending) -> Outcome {
        let status = match ending.after(sessions, Some(sessions)) {
            AfterSession::Stop(status) => status,
            AfterSession::NextSession => ExitStatus::Done,
        };
        Outcome {
            status,
            sessions,
            ending,
            commands: self.cell.take_commands(),
        }
    }

    /// Each report applied by the cell's rules, in order, and shown to the station.
    fn apply<S: Station<R, O>>(
        &mut self,
        station: &mut S,
        at_nanos: i64,
        reports: Vec<RobotReport>,
    ) -> Result<(), S::Error> {
        for report in reports {
            let effect = self.cell.report(report.clone());
            station.reported(&mut self.cell, at_nanos, &report, &effect)?;
        }
        Ok(())
    }

    /// The station failed: the session ends now, held, at the station's time.
    fn failed<S: Station<R, O>>(
        &mut self,
        station: &mut S,
        sessions: u32,
        error: S::Error,
    ) -> DriverError {
        let at = station.now_nanos();
        let error: Cause = Arc::from(error.into());
        let step = self.cell.interrupt(
            at,
            Interruption::InputFailed {
                error: InputError {
                    input: station.name(),
                    cause: error.clone(),
                },
            },
        );
        let outcome = step
            .ended
            .map(|ending| self.failed_outcome(sessions + 1, ending));
        DriverError { error, outcome }
    }

    /// The outcome when the driver fails: the program stops for a person, even after a normal end
    /// (a stop signal keeps its own status).
    fn failed_outcome(&mut self, sessions: u32, ending: Ending) -> Outcome {
        let mut outcome = self.outcome(sessions, ending);
        if outcome.status == ExitStatus::Done {
            outcome.status = ExitStatus::NeedsAPerson;
        }
        outcome
    }
}
