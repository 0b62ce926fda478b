//! `run`'s station: the cell's inputs on ROS 2, handed to the session driver
//! ([`ergocell_cell::session::Driver`]) one at a time, each stamped by the session clock.
//!
//! The camera topics go through the [`CameraInbox`] (each message checked into a view or rejected
//! and counted), the robot side's reports come from the monitor task, the FollowJointTrajectory task
//! and the driver's topics, and a 20 ms tick releases the frames whose fixed lag has passed. The
//! station records the camera messages, the joint states and the robot's markers as they arrive,
//! and times each step from its wake-up to the RULA state published (`--latency-report`,
//! [`StepLatency`]).
//!
//! It decides nothing: what a report means and when the robot is held are the cell loop's rules.
//! It prints nothing either: the lines it has to say go to the caller's `say`, and the next session's
//! machine and the robot's geometry come from the caller (the binary reads the files).

use std::time::Duration;

use ergocell_bridge::controller::ControllerReport;
use ergocell_bridge::msg::{BoolMsg, CameraLandmarks, HardwareEvent, JointState};
use ergocell_bridge::transport::Subscription;
use ergocell_cell::session::{
    CellLoop, CellOutputs, Input, OutputError, ReportEffect, RobotReport, SessionMachine, Station,
    Step, Timed,
};
use ergocell_robot::TrajectoryClass;
use futures::StreamExt as _;

use crate::cameras::CameraInbox;
use crate::clock::{instant, now_nanos, SessionClock};
use crate::console::{self, StepLatency};
use crate::messages;
use crate::monitor::MonitorNote;
use crate::outputs::RosOutputs;
use crate::recording::topics;
use crate::robot::{announce_driver, reports_of, RobotInput, RosRobot};
use crate::robot_markers::RobotGeometry;

/// A caller's error, kept as it is (its message is the session's).
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// The station's error: the next session's machine could not be made, or an output failed.
#[derive(Debug, thiserror::Error)]
pub enum StationError {
    /// The caller's machine for the next session (a trajectory that no longer verifies, …).
    #[error(transparent)]
    NextMachine(BoxError),
    /// Publishing or recording the controller's last reports failed.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// The outputs `run`'s station writes into: the ROS 2 publishers and the recording, and whatever
/// else the caller shows (the operator display).
pub trait RosCellOutputs: CellOutputs {
    /// The ROS 2 outputs and the recording.
    fn ros(&self) -> &RosOutputs;
    /// The ROS 2 outputs and the recording, to write into.
    fn ros_mut(&mut self) -> &mut RosOutputs;
    /// The next session began with `machine`.
    fn session_began(&self, _machine: &SessionMachine) {}
}

impl RosCellOutputs for RosOutputs {
    fn ros(&self) -> &RosOutputs {
        self
    }
    fn ros_mut(&mut self) -> &mut RosOutputs {
        self
    }
}

/// The cell loop on ROS 2.
pub type RosLoop<O> = CellLoop<RosRobot, O>;

type Items<'a, T> = futures::stream::LocalBoxStream<'a, Result<T, String>>;

/// What the station reads: the camera topics, the driver's topics (when `[ros] driver_state`), the
/// monitor task's notes and the controller task's reports.
pub struct StationInputs<'a> {
    pub cameras: &'a [Subscription<CameraLandmarks>],
    pub driver: Option<&'a (Subscription<BoolMsg>, Subscription<HardwareEvent>)>,
    pub notes: tokio::sync::mpsc::UnboundedReceiver<MonitorNote>,
    pub reports: tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
}

/// What the station asks its caller for: the machine of the next session, the robot's geometry for
/// a locked class (the recording's markers) and where its lines go.
pub struct StationHooks<'a> {
    pub next_machine: Box<dyn FnMut() -> Result<SessionMachine, BoxError> + 'a>,
    pub geometry: Box<dyn Fn(TrajectoryClass) -> Result<RobotGeometry, BoxError> + 'a>,
    pub say: Box<dyn FnMut(&str) + 'a>,
}

/// `run`'s station (see the module's documentation).
pub struct RosStation<'a> {
    cameras: Items<'a, CameraLandmarks>,
    configured: Items<'a, BoolMsg>,
    hardware: Items<'a, HardwareEvent>,
    notes: tokio::sync::mpsc::UnboundedReceiver<MonitorNote>,
    reports: tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
    tick: tokio::time::Interval,
    clock: SessionClock,
    inbox: CameraInbox,
    markers: Markers,
    latency: StepLatency,
    hooks: StationHooks<'a>,
    /// When the step now under way was woken (a camera message or the tick).
    woken: Option<std::time::Instant>,
    /// How long the controller's last answer is waited for after the last session.
    settle_until: Option<tokio::time::Instant>,
}

impl<'a> RosStation<'a> {
    /// The station over `inputs`, the camera messages checked by `inbox`, on `clock`.
    pub fn new(
        inputs: StationInputs<'a>,
        inbox: CameraInbox,
        clock: SessionClock,
        hooks: StationHooks<'a>,
    ) -> Self {
        fn items<M: 'static + serde::de::DeserializeOwned>(s: &Subscription<M>) -> Items<'_, M> {
            s.async_stream()
                .map(|r| r.map(|(m, _)| m).map_err(|e| format!("{e:?}")))
                .boxed_local()
        }
        let (configured, hardware) = match inputs.driver {
            Some((c, h)) => (items(c), items(h)),
            None => (
                futures::stream::pending().boxed_local(),
                futures::stream::pending().boxed_local(),
            ),
        };
        Self {
            cameras: futures::stream::select_all(inputs.cameras.iter().map(items)).boxed_local(),
            configured,
            hardware,
            notes: inputs.notes,
            reports: inputs.reports,
            tick: tokio::time::interval(Duration::from_millis(20)),
            clock,
            inbox,
            markers: Markers::default(),
            latency: StepLatency::default(),
            hooks,
            woken: None,
            settle_until: None,
        }
    }

    /// Camera messages rejected so far (malformed, unknown camera, out of the image).
    pub fn rejected(&self) -> u64 {
        self.inbox.rejected()
    }

    /// Each step's time from its wake-up to the RULA state published.
    pub fn latency(&self) -> &StepLatency {
        &self.latency
    }

    fn say(&mut self, line: Option<String>) {
        if let Some(line) = line {
            (self.hooks.say)(&format!("  {line}"));
        }
    }

    /// The robot side's input in the cell's reports, its line said.
    fn robot_input<O: RosCellOutputs>(
        &mut self,
        cell: &mut RosLoop<O>,
        now: i64,
        input: RobotInput,
    ) -> Input {
        let (reports, line) = reports_of(cell.robot_mut(), now, input);
        self.say(line);
        Input::Reports(reports)
    }
}

impl<O: RosCellOutputs> Station<RosRobot, O> for RosStation<'_> {
    type Error = StationError;

    fn name(&self) -> &'static str {
        "ROS 2 inputs"
    }

    fn now_nanos(&mut self) -> i64 {
        self.clock.now()
    }

    /// One camera message, robot-side report or 20 ms tick.
    async fn next(&mut self, cell: &mut RosLoop<O>) -> Result<Option<Timed>, StationError> {
        enum Woke {
            Camera(CameraLandmarks),
            Robot(RobotInput),
            Tick,
        }
        let woke = tokio::select! {
            Some(item) = self.cameras.next() => match item {
                Ok(m) => Woke::Camera(m),
                Err(e) => {
                    tracing::warn!(error = %e, "camera read error");
                    return Ok(None);
                }
            },
            Some(note) = self.notes.recv() => {
                if let MonitorNote::Sample(js, now) = &note {
                    self.markers.record(cell, js, *now, &self.hooks.geometry);
                    return Ok(None);
                }
                Woke::Robot(RobotInput::Monitor(note))
            }
            Some(report) = self.reports.recv() => Woke::Robot(RobotInput::Controller(report)),
            Some(Ok(m)) = self.configured.next() => Woke::Robot(RobotInput::DriverConfigured(m.data)),
            Some(Ok(m)) = self.hardware.next() => Woke::Robot(RobotInput::DriverEvent(m)),
            _ = self.tick.tick() => Woke::Tick,
        };
        // The step starts now, woken by a camera message or the clock's tick (which releases the
        // frames whose fixed lag has passed): the latency report times it to the RULA state.
        self.woken = Some(instant());
        let now = self.clock.now();
        if let Some(step) = self.clock.wall_step(now_nanos(), now) {
            (self.hooks.say)(&console::wall_step_line(step));
            tracing::warn!(step_s = step as f64 * 1e-9, "wall clock stepped");
        }
        // Flushed on the clock, not only when messages arrive (kill -9 loses at most a second).
        cell.outputs_mut()
            .ros_mut()
            .recording
            .with(|rec| rec.tick(now));
        let input = match woke {
            Woke::Camera(m) => {
                cell.outputs_mut()
                    .ros_mut()
                    .recording
                    .with(|rec| rec.write(&topics::camera(&m.camera_id), now, &m));
                Input::Views(self.inbox.accept(&m).into_iter().collect())
            }
            Woke::Robot(input) => self.robot_input(cell, now, input),
            Woke::Tick => Input::Tick,
        };
        Ok(Some(Timed::new(now, input)))
    }

    fn reported(
        &mut self,
        cell: &mut RosLoop<O>,
        at: i64,
        _report: &RobotReport,
        effect: &ReportEffect,
    ) -> Result<(), StationError> {
        let line = announce_driver(cell, at, effect.driver_readiness.clone());
        self.say(line);
        Ok(())
    }

    fn stepped(
        &mut self,
        cell: &mut RosLoop<O>,
        _at: i64,
        _step: &Step,
    ) -> Result<(), StationError> {
        if cell.outputs().ros().published_frame {
            if let Some(woken) = self.woken.take() {
                self.latency.push(woken.elapsed());
            }
        }
        Ok(())
    }

    fn next_machine(&mut self, cell: &mut RosLoop<O>) -> Result<SessionMachine, StationError> {
        let summary = console::session_summary(cell.machine(), self.inbox.rejected());
        (self.hooks.say)(&summary);
        (self.hooks.next_machine)().map_err(StationError::NextMachine)
    }

    fn session_began(&mut self, cell: &mut RosLoop<O>) {
        cell.outputs().session_began(cell.machine());
        (self.hooks.say)("next session: waiting for an operator");
    }

    /// The controller's reports for at most 2 s after the last session, each published at once.
    async fn settle(&mut self, cell: &mut RosLoop<O>) -> Result<Option<Timed>, StationError> {
        let until = *self
            .settle_until
            .get_or_insert_with(|| tokio::time::Instant::now() + Duration::from_secs(2));
        let Ok(Some(report)) = tokio::time::timeout_at(until, self.reports.recv()).await else {
            return Ok(None);
        };
        let now = self.clock.now();
        let input = self.robot_input(cell, now, RobotInput::Controller(report));
        cell.outputs_mut().ros_mut().flush_events(now)?;
        Ok(Some(Timed::new(now, input)))
    }
}

/// The recording's joint states and, once a class is locked, the TCP and handover markers (at most
/// 20 Hz).
#[derive(Default)]
struct Markers {
    geometry: Option<(TrajectoryClass, RobotGeometry)>,
    last_nanos: Option<i64>,
}

/// The markers' period: 20 Hz.
const MARKER_PERIOD_NANOS: i64 = 50_000_000;

impl Markers {
    fn record<O: RosCellOutputs>(
        &mut self,
        cell: &mut RosLoop<O>,
        js: &JointState,
        now: i64,
        geometry: &dyn Fn(TrajectoryClass) -> Result<RobotGeometry, BoxError>,
    ) {
        let class = cell.machine().locked_class();
        let recording = &mut cell.outputs_mut().ros_mut().recording;
        if !recording.is_on() {
            return;
        }
        recording.with(|rec| rec.write(topics::JOINT_STATES, now, js));
        if self.geometry.as_ref().map(|(c, _)| *c) != class {
            self.geometry = class.and_then(|c| match geometry(c) {
                Ok(g) => Some((c, g)),
                Err(e) => {
                    tracing::warn!(error = %e, "no robot markers in the recording");
                    None
                }
            });
        }
        let Some((_, g)) = self.geometry.as_ref() else {
            return;
        };
        if self
            .last_nanos
            .is_some_and(|t| now - t < MARKER_PERIOD_NANOS)
        {
            return;
        }
        if let Some(p) = g.tcp_world(js) {
            self.last_nanos = Some(now);
            let m = messages::robot_markers_message(now, Some(p), Some(g.handover_world()));
            recording.with(|rec| rec.write(topics::ROBOT_MARKERS, now, &m));
        }
    }
}
