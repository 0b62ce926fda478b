//! The session state machine (see the module docs of [`crate::session`]).

use ergocell_ergonomics::height::{serves_interval, ServedStatures};
use ergocell_ergonomics::warnings::WarningKind;
use ergocell_ergonomics::{HeightClass, HeightDecision, HeightStatus, UpVector};
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::{SessionLock, TrajectoryClass};
use ergocell_skeleton::{Landmark, Side, Skeleton3};
use nalgebra::Point3;

use super::end::{AbortReason, HoldReason, Interruption, SessionEnd};
use super::robot_side::RobotUnready;
use super::{
    leg_trajectory, trajectory_class, Leg, RobotCommand, RobotSink, SessionConfig, SessionEvent,
    SessionState, TrajectoryProvider,
};
use crate::config::CellSettings;
use crate::pipeline::{rig_up, FrameOutput, Pipeline, PipelineConfig, TrackedFrame};
use crate::CellError;

/// Per-camera health.
#[derive(Debug, Clone)]
struct CameraHealth {
    name: String,
    last_arrival_nanos: Option<i64>,
    sees_operator: bool,
    degraded: bool,
}

/// Where the robot is along the locked path, as far as the session knows.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Motion {
    /// Not commanded yet (at home).
    AtHome,
    Moving(Leg),
    /// At the handover point with the part: waiting for the operator to take it.
    AtHandover(Part),
}

/// The part at the handover point, as the cameras see the operator's hands (only while the robot
/// waits there).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Part {
    /// No hand has come to it yet.
    Offered,
    /// A hand came within the take radius; the part is taken when it leaves the release radius.
    InHand { hand: Side, closest_m: f64 },
    /// The hand that had it left the release radius: taken.
    Taken { hand: Side, closest_m: f64 },
}

/// Counts for the final summary.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct SessionSummary {
    pub frames_fused: u64,
    pub frames_tracked: u64,
    pub height_m: Option<f64>,
    pub height_uncertainty_m: Option<f64>,
    pub class: Option<TrajectoryClass>,
    pub lock_sha256: Option<String>,
    pub holds: u32,
    pub warnings_raised: u32,
    pub changes_refused: u32,
    pub camera_degradations: u32,
    /// Cameras found out of calibration by their reprojection residuals (left out of fusion).
    pub cameras_out_of_calibration: Vec<String>,
    pub max_action_level: u8,
    pub robot_commands: u32,
    /// Parts the operator took at the handover point (completed handovers: the cell's cycles).
    pub parts_taken: u32,
    /// The latest part taken: its number, the hand, and how close that hand's palm centre came to
    /// the handover point, metres.
    pub last_part: Option<PartTakenFacts>,
    pub ended: bool,
    /// How the session ended, in words ([`SessionSummary::end`]'s).
    pub end_reason: String,
    /// How the session ended, typed; `None` while it runs.
    pub end: Option<SessionEnd>,
}

/// One part the operator took at the handover point.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PartTakenFacts {
    /// 1 for the session's first part.
    pub part: u32,
    /// The operator's hand that took it.
    pub hand: Side,
    /// How close that hand's palm centre came to the handover point, metres.
    pub closest_m: f64,
}

/// The session state machine. One per operator session.
pub struct SessionMachine {
    config: SessionConfig,
    pairs: Vec<(usize, usize)>,
    pipeline: Pipeline,
    provider: Box<dyn TrajectoryProvider>,
    state: SessionState,
    cameras: Vec<CameraHealth>,
    decision: Option<HeightDecision>,
    lock: Option<SessionLock>,
    motion: Motion,
    /// Since when the robot stands at home between cycles (the next part is loaded meanwhile).
    at_home_since: Option<i64>,
    /// Why the robot is held, and its words.
    hold_reason: Option<(HoldReason, String)>,
    /// Why the robot side cannot be trusted to move right now (the driver not controlling, joint
    /// states stale), from the backend: the robot is held and nothing is sent until it clears.
    robot_unready: Option<RobotUnready>,
    tracking_back_since: Option<i64>,
    last_frame_stamp: Option<i64>,
    last_tracked: Option<(i64, Point3<f64>)>,
    operator_departed: bool,
    /// The operator has stood within `exit_radius_m` of the station this session: only then can
    /// they leave it (one still walking in has not departed).
    operator_arrived: bool,
    pairs_tracking: usize,
    first_step_nanos: Option<i64>,
    /// When the operator was first tracked (the height measurement started).
    measuring_since: Option<i64>,
    summary: SessionSummary,
}

impl SessionMachine {
    /// A session on this rig with the cell file's settings. The rig's `up` is required (RULA and
    /// height need the world's vertical).
    pub fn from_settings(
        rig: CameraRig,
        settings: &CellSettings,
        provider: Box<dyn TrajectoryProvider>,
    ) -> Result<Self, CellError> {
        let pipeline = settings.pipeline(rig_up(&rig)?)?;
        Self::new(rig, settings.session, pipeline, provider)
    }

    /// A session on this rig with these configurations.
    pub fn new(
        rig: CameraRig,
        config: SessionConfig,
        mut pipeline: PipelineConfig,
        mut provider: Box<dyn TrajectoryProvider>,
    ) -> Result<Self, CellError> {
        // RULA and the height need the world's vertical: a rig without one cannot carry a session.
        rig_up(&rig)?;
        // The height decision chooses only a class whose trajectory serves the operator's whole
        // interval; a class whose bounds cannot be read serves no one (and `lock_trajectory` says
        // why if it is ever chosen).
        let served = HeightClass::ALL.map(|class| {
            provider
                .stature_bounds_m(trajectory_class(class))
                .map_or([0.5, 0.5], |(lo, hi)| [lo, hi])
        });
        pipeline.height.served_m = Some(ServedStatures::new(served)?);
        // Curves that cannot be read are a configuration error, not a silent fall-back.
        pipeline.height.handover_rula =
            provider.handover_rula().map_err(|e| CellError::Config {
                file: "the classes' handover RULA curves".to_owned(),
                reason: e.to_string(),
            })?;
        let pairs = rig.pairs().iter().map(|p| (p.left, p.right)).collect();
        let cameras = rig
            .cameras()
            .iter()
            .map(|c| CameraHealth {
                name: c.id.as_str().to_owned(),
                last_arrival_nanos: None,
                sees_operator: false,
                degraded: false,
            })
            .collect();
        Ok(Self {
            config,
            pairs,
            pipeline: Pipeline::new(rig, pipeline)?,
            provider,
            state: SessionState::WaitingForOperator,
            cameras,
            decision: None,
            lock: None,
            motion: Motion::AtHome,
            at_home_since: None,
            hold_reason: None,
            robot_unready: None,
            tracking_back_since: None,
            last_frame_stamp: None,
            last_tracked: None,
            operator_departed: false,
            operator_arrived: false,
            pairs_tracking: 0,
            first_step_nanos: None,
            measuring_since: None,
            summary: SessionSummary::default(),
        })
    }

    pub fn state(&self) -> SessionState {
        self.state
    }

    pub fn summary(&self) -> &SessionSummary {
        &self.summary
    }

    /// The height decision, once made.
    pub fn decision(&self) -> Option<&HeightDecision> {
        self.decision.as_ref()
    }

    /// The locked trajectory's hash, once locked.
    pub fn lock_sha256(&self) -> Option<&str> {
        self.lock
            .as_ref()
            .map(|l| l.trajectory().lock().lock_sha256.as_str())
    }

    /// The locked trajectory's class, once locked.
    pub fn locked_class(&self) -> Option<TrajectoryClass> {
        self.lock.as_ref().map(|l| l.trajectory().class())
    }

    /// Who approved the locked trajectory (oldest approval first), once locked.
    pub fn approved_by(&self) -> Vec<String> {
        self.lock.as_ref().map_or_else(Vec::new, |l| {
            l.trajectory()
                .approvals()
                .iter()
                .map(|a| a.approved_by.clone())
                .collect()
        })
    }

    /// Why the robot is held, if it is.
    pub fn hold_reason(&self) -> Option<&str> {
        self.hold_reason.as_ref().map(|(_, words)| words.as_str())
    }

    /// Cameras whose views are fresh.
    pub fn cameras_fresh(&self) -> usize {
        self.cameras.iter().filter(|c| !c.degraded).count()
    }

    /// Stereo pairs whose two cameras both see the operator (as of the last step).
    pub fn pairs_tracking(&self) -> usize {
        self.pairs_tracking
    }

    /// A request to change the trajectory class mid-session: refused once a trajectory is locked
    /// (the class comes from the height measured at session start, nothing else).
    pub fn request_class(&mut self, now_nanos: i64, requested: TrajectoryClass) -> SessionEvent {
        let reason = match self.lock.as_mut() {
            Some(lock) => match lock.request(requested) {
                Ok(_) => format!("class {requested} is already the locked class: nothing changes"),
                Err(e) => e.to_string(),
            },
            None => "no trajectory is locked yet: the class is decided by the height measurement \
                     only"
                .to_owned(),
        };
        self.summary.changes_refused += 1;
        tracing::warn!(%requested, %reason, "trajectory change request refused");
        SessionEvent::ChangeRefused {
            stamp_nanos: now_nanos,
            requested,
            reason,
        }
    }

    /// The robot side's readiness (the cell loop's rules, [`super::robot_side`]): `Some(why)` while
    /// the robot must not move (its driver is not configured or not controlling, its joint states
    /// are stale). From the next step a session that has locked its trajectory holds the robot for
    /// `why` and sends no goal; once it clears, the session resumes by its usual rules (tracking back
    /// for `resume_after_nanos`, the robot at home or at the handover point, the lock still
    /// verified).
    pub fn set_robot_unready(&mut self, why: Option<RobotUnready>) {
        if why != self.robot_unready {
            if let Some(w) = &why {
                tracing::warn!(reason = %w, "robot not ready");
            } else {
                tracing::info!("robot ready");
            }
            self.robot_unready = why;
        }
    }

    /// Why the robot side is not ready, if it is not.
    pub fn robot_unready(&self) -> Option<&RobotUnready> {
        self.robot_unready.as_ref()
    }

    /// Ctrl-C, a failure of the robot side or an output, the time limit: hold the robot and end
    /// the session.
    pub fn shutdown(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        by: Interruption,
    ) -> Vec<SessionEvent> {
        let mut events = Vec::new();
        if self.state == SessionState::SessionEnded {
            return events;
        }
        let why = by.to_string();
        let end = SessionEnd::Interrupted { by };
        let command = RobotCommand::Hold {
            reason: HoldReason::Ended { end: end.clone() },
        };
        self.send(now_nanos, robot, command, &mut events);
        // Said by the caller (the signal, the failure): not logged again here.
        self.hold_reason = Some((HoldReason::Ended { end: end.clone() }, why.clone()));
        self.summary.end_reason = end.to_string();
        self.summary.end = Some(end);
        self.transition(now_nanos, SessionState::SessionEnded, &why, &mut events);
        events
    }

    /// One step at `now_nanos` with the views that arrived since the last step.
    pub fn step(
        &mut self,
        now_nanos: i64,
        views: Vec<View2>,
        robot: &mut dyn RobotSink,
    ) -> Vec<SessionEvent> {
        let mut events = Vec::new();
        if self.state == SessionState::SessionEnded {
            return events;
        }
        // Camera health from arrivals.
        for view in &views {
            if let Some(c) = self.cameras.get_mut(view.camera) {
                c.last_arrival_nanos = Some(now_nanos);
                c.sees_operator = view.observed_count() >= self.config.min_view_landmarks;
            }
        }
        self.update_camera_health(now_nanos, &mut events);
        for output in self.pipeline.push_views(now_nanos, views) {
            match output {
                Ok(output) => self.on_frame(now_nanos, output, &mut events),
                Err(e) => tracing::warn!(error = %e, "frame not fused"),
            }
        }
        // Frames whose fixed-lag window closed on the clock: scored now, not when a later frame
        // completes (the cameras' messages come with the edge's and the network's delay).
        for scored in self.pipeline.release_due(now_nanos) {
            self.on_scored_frame(scored, &mut events);
        }
        self.pairs_tracking = self
            .pairs
            .iter()
            .filter(|(l, r)| {
                [*l, *r].iter().all(|&k| {
                    self.cameras
                        .get(k)
                        .is_some_and(|c| !c.degraded && c.sees_operator)
                })
            })
            .count();
        self.supervise(now_nanos, robot, &mut events);
        events
    }

    fn update_camera_health(&mut self, now_nanos: i64, events: &mut Vec<SessionEvent>) {
        let since = *self.first_step_nanos.get_or_insert(now_nanos);
        let bound = self.config.camera_stale_nanos;
        for c in &mut self.cameras {
            // A camera silent since the session started is as stale as one that stopped.
            let stale = now_nanos - c.last_arrival_nanos.unwrap_or(since) > bound;
            if stale && !c.degraded {
                c.degraded = true;
                c.sees_operator = false;
                self.summary.camera_degradations += 1;
                let why = if c.last_arrival_nanos.is_some() {
                    format!(
                        "no view for more than {} ms: fusion continues without it",
                        bound / 1_000_000
                    )
                } else {
                    format!(
                        "no view at all since the session started ({} ms ago): fusion continues \
                         without it (is the camera's node, `ergocell-edge publish`, running on this \
                         ROS 2 domain and network?)",
                        (now_nanos - since) / 1_000_000
                    )
                };
                // an event: `run` and `demo` print it, the recording keeps it
                tracing::debug!(camera = %c.name, %why, "camera degraded");
                events.push(SessionEvent::CameraDegraded {
                    stamp_nanos: now_nanos,
                    camera: c.name.clone(),
                    why,
                });
            } else if !stale && c.degraded {
                c.degraded = false;
                // Views arrive again; a camera out of calibration stays out of fusion, so it is not
                // "restored" (its out-of-calibration event said so, and the summary names it).
                if !self.summary.cameras_out_of_calibration.contains(&c.name) {
                    tracing::debug!(camera = %c.name, "camera restored");
                    events.push(SessionEvent::CameraRestored {
                        stamp_nanos: now_nanos,
                        camera: c.name.clone(),
                    });
                }
            }
        }
    }

    /// One frame out of the pipeline: the session's bookkeeping and events.
    fn on_frame(&mut self, now_nanos: i64, output: FrameOutput, events: &mut Vec<SessionEvent>) {
        if let Some(o) = &output.out_of_calibration {
            if let Some(c) = self.cameras.get(o.camera) {
                let why = format!(
                    "out of calibration (bumped?): its views lie {:.1} px from the fused skeleton, \
                     the other cameras' {:.1} px (medians over {} frames); left out of fusion for \
                     the rest of the session: recalibrate it",
                    o.residual_px, o.others_px, o.frames
                );
                tracing::warn!(camera = %c.name, %why, "camera out of calibration");
                self.summary.camera_degradations += 1;
                self.summary.cameras_out_of_calibration.push(c.name.clone());
                events.push(SessionEvent::CameraDegraded {
                    stamp_nanos: now_nanos,
                    camera: c.name.clone(),
                    why,
                });
            }
        }
        self.last_frame_stamp = Some(
            self.last_frame_stamp
                .map_or(output.stamp_nanos, |s| s.max(output.stamp_nanos)),
        );
        self.summary.frames_fused += 1;
        if let Some(operator) = &output.operator {
            self.summary.frames_tracked += 1;
            if let Some(hips) = mid_hip(operator) {
                self.last_tracked = Some((output.stamp_nanos, hips));
            }
            self.on_operator(now_nanos, operator, output.height, events);
        }
        // RULA, with a fixed lag of earlier frames (`PipelineConfig::fixed_lag_s`).
        for scored in output.tracked {
            self.on_scored_frame(scored, events);
        }
    }

    /// The operator tracked in this frame: the session starts, the height decision, the part.
    fn on_operator(
        &mut self,
        now_nanos: i64,
        skeleton: &Skeleton3,
        height: Option<HeightDecision>,
        events: &mut Vec<SessionEvent>,
    ) {
        if self.state == SessionState::WaitingForOperator {
            self.measuring_since = Some(now_nanos);
            self.transition(
                now_nanos,
                SessionState::MeasuringHeight,
                "operator tracked",
                events,
            );
        }
        // The pipeline measures the height on the unfiltered skeleton until its first decision,
        // which is final: the class is decided at session start only.
        if let (SessionState::MeasuringHeight, Some(decision)) = (self.state, height) {
            self.on_height_decided(now_nanos, decision, events);
        }
        self.watch_part(skeleton);
    }

    /// A tracked frame scored: RULA in every state once an operator is tracked.
    fn on_scored_frame(&mut self, tracked: TrackedFrame, events: &mut Vec<SessionEvent>) {
        for w in tracked.warnings {
            if w.kind == WarningKind::Raised {
                self.summary.warnings_raised += 1;
            }
            tracing::info!(message = %w.message, "posture warning");
            events.push(SessionEvent::Warning(w));
        }
        let assessment = match tracked.assessment {
            Ok(a) => {
                if let Some(h) = a.headline() {
                    self.summary.max_action_level =
                        self.summary.max_action_level.max(h.scores.action_level);
                }
                Some(a)
            }
            Err(e) => {
                tracing::warn!(error = %e, "frame not assessed");
                None
            }
        };
        events.push(SessionEvent::Frame {
            stamp_nanos: tracked.skeleton.stamp_nanos,
            skeleton: Box::new(tracked.skeleton),
            assessment: assessment.map(Box::new),
        });
    }

    fn on_height_decided(
        &mut self,
        now_nanos: i64,
        decision: HeightDecision,
        events: &mut Vec<SessionEvent>,
    ) {
        let e = &decision.estimate;
        self.summary.height_m = Some(e.height_m);
        self.summary.height_uncertainty_m = Some(e.uncertainty_m);
        self.summary.class = Some(trajectory_class(decision.class));
        tracing::info!(
            height_m = e.height_m,
            uncertainty_m = e.uncertainty_m,
            class = decision.class.name(),
            "height class decided"
        );
        events.push(SessionEvent::ClassDecided {
            stamp_nanos: now_nanos,
            height_m: e.height_m,
            uncertainty_m: e.uncertainty_m,
            class: decision.class,
            basis: decision.basis,
            probability: decision.probability,
            expected_rula_cost: decision.expected_rula_cost,
        });
        let reason = format!(
            "stature {:.3} ± {:.3} m → class {} (probability {:.2}{})",
            e.height_m,
            e.uncertainty_m,
            decision.class.name(),
            decision.probability,
            decision
                .expected_rula_cost
                .map_or(String::new(), |c| format!(", expected RULA cost {c:+.2}"))
        );
        self.decision = Some(decision);
        self.transition(now_nanos, SessionState::ClassDecided, &reason, events);
    }

    /// Locking, holding, resuming, ending.
    fn supervise(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        events: &mut Vec<SessionEvent>,
    ) {
        if self.state == SessionState::MeasuringHeight {
            self.check_height_timeout(now_nanos, robot, events);
        }
        if self.state == SessionState::ClassDecided {
            self.lock_trajectory(now_nanos, robot, events);
        }
        if !matches!(
            self.state,
            SessionState::TrajectoryLocked | SessionState::Working | SessionState::Held
        ) {
            return;
        }
        let Some(lock) = self.lock.as_ref() else {
            return;
        };
        let names = lock.trajectory().joint_names().to_vec();
        let points = lock.trajectory().points();
        let (Some(first), Some(last)) = (points.first(), points.last()) else {
            return;
        };
        let (home, handover) = (first.positions_rad.clone(), last.positions_rad.clone());
        let position = robot.joint_positions(now_nanos, &names);
        let near = |target: &[f64]| {
            position.as_ref().is_some_and(|p| {
                p.len() == target.len()
                    && p.iter()
                        .zip(target)
                        .all(|(a, b)| (a - b).abs() <= self.config.at_knot_tolerance_rad)
            })
        };
        let (at_home, at_handover) = (near(&home), near(&handover));
        match self.motion {
            Motion::Moving(Leg::ToHandover) if at_handover => {
                self.motion = Motion::AtHandover(Part::Offered);
            }
            Motion::Moving(Leg::ToHome) if at_home => {
                self.motion = Motion::AtHome;
                self.at_home_since = Some(now_nanos);
            }
            _ => {}
        }
        // The robot side not ready: held, nothing sent, until it is (then the usual resume rules).
        if let Some(unready) = self.robot_unready.clone() {
            self.tracking_back_since = None;
            let reason = HoldReason::RobotNotReady { unready };
            if self.state == SessionState::Held {
                self.set_hold(reason);
            } else {
                self.hold(now_nanos, robot, reason, events);
            }
            return;
        }

        // Has the operator left? Last tracked farther than `exit_radius_m` from the station (still in
        // view or not) after having stood within it. Lost from view nearer than that is a loss of
        // tracking: the robot is held. One still walking in (the height can be measured on the way)
        // has not left.
        let frame_age = self.last_frame_stamp.map(|s| now_nanos - s);
        let frames_fresh = frame_age.is_some_and(|a| a <= self.config.max_frame_age_nanos);
        if !self.operator_departed && self.state != SessionState::TrajectoryLocked {
            if let Some((_, p)) = self.last_tracked {
                let [sx, sy] = self.config.station_xy_m;
                let d = (p.x - sx).hypot(p.y - sy);
                if d <= self.config.exit_radius_m {
                    self.operator_arrived = true;
                } else if self.operator_arrived {
                    self.operator_departed = true;
                    tracing::info!(distance_m = d, "operator left the station");
                }
            }
        }
        let tracking_ok = self.operator_departed || (self.pairs_tracking >= 1 && frames_fresh);

        if !tracking_ok {
            self.tracking_back_since = None;
            if self.state != SessionState::Held {
                let reason = if frames_fresh {
                    HoldReason::NoStereoPair {
                        cameras_fresh: self.cameras_fresh(),
                    }
                } else {
                    // Every camera silent, or the cameras' clocks far from the cell's: either way no
                    // frame is recent enough to move the robot by.
                    HoldReason::CamerasLost {
                        max_frame_age_ms: self.config.max_frame_age_nanos / 1_000_000,
                    }
                };
                self.hold(now_nanos, robot, reason, events);
            }
            return;
        }
        if self.state == SessionState::Held {
            let since = *self.tracking_back_since.get_or_insert(now_nanos);
            if now_nanos - since < self.config.resume_after_nanos {
                return;
            }
            self.try_resume(now_nanos, at_home, at_handover, robot, events);
            return;
        }
        if self.state == SessionState::TrajectoryLocked {
            self.start_leg(now_nanos, Leg::ToHandover, robot, events);
            self.transition(
                now_nanos,
                SessionState::Working,
                "trajectory sent: home → handover",
                events,
            );
            return;
        }
        // Working: the cell's cycle. Home → handover → the operator takes the part → home → the
        // next part, until the operator leaves; then home and the session ends.
        match self.motion {
            Motion::AtHandover(_) if self.operator_departed => {
                self.start_leg(now_nanos, Leg::ToHome, robot, events);
            }
            Motion::AtHandover(Part::Taken { hand, closest_m }) => {
                // Counted once the way home is sent (a failed send is tried again next step);
                // the event goes before the command, as it happened.
                let at = events.len();
                self.start_leg(now_nanos, Leg::ToHome, robot, events);
                if self.motion == Motion::Moving(Leg::ToHome) {
                    self.summary.parts_taken += 1;
                    let part = self.summary.parts_taken;
                    self.summary.last_part = Some(PartTakenFacts {
                        part,
                        hand,
                        closest_m,
                    });
                    tracing::info!(part, hand = hand.name(), closest_m, "part taken");
                    events.insert(
                        at,
                        SessionEvent::PartTaken {
                            stamp_nanos: now_nanos,
                            part,
                            hand,
                            closest_m,
                        },
                    );
                }
            }
            Motion::AtHome if self.operator_departed => {
                self.end_session(now_nanos, at_home, events);
            }
            Motion::AtHome => {
                let since = *self.at_home_since.get_or_insert(now_nanos);
                if now_nanos - since >= self.config.next_part_after_nanos {
                    self.at_home_since = None;
                    self.start_leg(now_nanos, Leg::ToHandover, robot, events);
                }
            }
            // Waiting for the operator to take the part, or on the way.
            Motion::AtHandover(_) | Motion::Moving(_) => {}
        }
    }

    /// The operator's hands against the part the robot offers at the handover point: once a hand's
    /// palm centre comes within `take_radius_m`, the part is in the operator's hand; once both hands
    /// are seen farther than `release_radius_m` again, it is taken (acted on by `supervise`, which
    /// sends the robot home). A hand the cameras do not see is not counted as away. Only while the
    /// robot waits at the handover point.
    fn watch_part(&mut self, skeleton: &Skeleton3) {
        let (Motion::AtHandover(part), Some(point)) = (self.motion, self.handover_world()) else {
            return;
        };
        let distance = |marks| palm_centre(skeleton, marks).map(|p| (p - point).norm());
        let hands = [
            (
                Side::Left,
                distance([
                    Landmark::LeftWrist,
                    Landmark::LeftIndex,
                    Landmark::LeftPinky,
                ]),
            ),
            (
                Side::Right,
                distance([
                    Landmark::RightWrist,
                    Landmark::RightIndex,
                    Landmark::RightPinky,
                ]),
            ),
        ];
        let nearest = hands
            .iter()
            .filter_map(|&(hand, d)| Some((hand, d?)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let both_away = hands
            .iter()
            .all(|(_, d)| d.is_some_and(|d| d > self.config.release_radius_m));
        self.motion = Motion::AtHandover(match (part, nearest) {
            (Part::Offered, Some((hand, d))) if d <= self.config.take_radius_m => {
                Part::InHand { hand, closest_m: d }
            }
            (Part::InHand { hand, closest_m }, _) if both_away => Part::Taken { hand, closest_m },
            (Part::InHand { hand, closest_m }, Some((h, d))) if h == hand => Part::InHand {
                hand,
                closest_m: closest_m.min(d),
            },
            (other, _) => other,
        });
    }

    /// The documented safe handling of an operator the cell cannot class: once the height is still
    /// undecided `height_timeout_nanos` after the operator was first tracked (their interval
    /// straddles a class boundary, or they never stood upright), the session ends and the robot
    /// does not move.
    fn check_height_timeout(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        events: &mut Vec<SessionEvent>,
    ) {
        let Some(since) = self.measuring_since else {
            return;
        };
        if now_nanos - since < self.config.height_timeout_nanos {
            return;
        }
        let reason = match self.pipeline.height_status() {
            HeightStatus::Measuring {
                why,
                frames_seen,
                upright_frames,
                ..
            } => AbortReason::HeightUndecided {
                after_s: self.config.height_timeout_nanos as f64 * 1e-9,
                frames_seen,
                upright_frames,
                missing: why,
            },
            HeightStatus::Decided(_) => return,
        };
        self.abort(now_nanos, robot, reason, events);
    }

    fn lock_trajectory(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        events: &mut Vec<SessionEvent>,
    ) {
        let Some(decision) = self.decision.as_ref() else {
            return;
        };
        let class = trajectory_class(decision.class);
        let [lo_m, hi_m] = decision.interval_m;
        // A class's trajectory suits the statures it was validated and is served for: the
        // operator's whole interval must lie inside them. Outside, the robot does not move.
        match self.provider.stature_bounds_m(class) {
            Ok((min_m, max_m)) if serves_interval([min_m, max_m], decision.interval_m) => {}
            Ok((min_m, max_m)) => {
                let reason = AbortReason::StatureOutsideServed {
                    class,
                    interval_m: [lo_m, hi_m],
                    served_m: [min_m, max_m],
                };
                self.abort(now_nanos, robot, reason, events);
                return;
            }
            Err(error) => {
                let reason = AbortReason::StatureBoundsUnreadable { class, error };
                self.abort(now_nanos, robot, reason, events);
                return;
            }
        }
        match self.provider.verify(class) {
            Ok(approved) => {
                let names = approved.joint_names().to_vec();
                if let Some(current) = robot.joint_positions(now_nanos, &names) {
                    if let Err(error) =
                        approved.check_start(&current, self.config.at_knot_tolerance_rad)
                    {
                        self.abort(now_nanos, robot, AbortReason::NotAtStart { error }, events);
                        return;
                    }
                } else {
                    self.abort(now_nanos, robot, AbortReason::NoJointPositions, events);
                    return;
                }
                let sha = approved.lock().lock_sha256.clone();
                let approved_by = approved
                    .approvals()
                    .iter()
                    .map(|a| a.approved_by.clone())
                    .collect();
                tracing::info!(%class, lock_sha256 = %sha, "trajectory verified and locked");
                self.summary.lock_sha256 = Some(sha.clone());
                events.push(SessionEvent::TrajectoryLocked {
                    stamp_nanos: now_nanos,
                    class,
                    lock_sha256: sha.clone(),
                    approved_by,
                });
                self.lock = Some(SessionLock::start(approved));
                self.transition(
                    now_nanos,
                    SessionState::TrajectoryLocked,
                    &format!("class {class} verified against its approval, locked ({sha})"),
                    events,
                );
            }
            Err(error) => {
                self.abort(
                    now_nanos,
                    robot,
                    AbortReason::NotVerified { class, error },
                    events,
                );
            }
        }
    }

    fn start_leg(
        &mut self,
        now_nanos: i64,
        leg: Leg,
        robot: &mut dyn RobotSink,
        events: &mut Vec<SessionEvent>,
    ) {
        let Some(lock) = self.lock.as_ref() else {
            return;
        };
        let approved = lock.trajectory();
        let command = RobotCommand::Execute {
            leg,
            lock_sha256: approved.lock().lock_sha256.clone(),
            trajectory: leg_trajectory(approved, leg),
        };
        if self.send(now_nanos, robot, command, events) {
            self.motion = Motion::Moving(leg);
        }
    }

    fn hold(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        reason: HoldReason,
        events: &mut Vec<SessionEvent>,
    ) {
        let why = reason.to_string();
        let command = RobotCommand::Hold {
            reason: reason.clone(),
        };
        self.send(now_nanos, robot, command, events);
        self.summary.holds += 1;
        self.hold_reason = Some((reason, why.clone()));
        tracing::warn!(reason = %why, "robot held");
        self.transition(now_nanos, SessionState::Held, &why, events);
    }

    fn try_resume(
        &mut self,
        now_nanos: i64,
        at_home: bool,
        at_handover: bool,
        robot: &mut dyn RobotSink,
        events: &mut Vec<SessionEvent>,
    ) {
        let Some(lock) = self.lock.as_ref() else {
            return;
        };
        let class = lock.trajectory().class();
        let locked_sha = lock.trajectory().lock().lock_sha256.clone();
        // The locked trajectory must still verify (files, approvals) and be the same one.
        match self.provider.verify(class) {
            Ok(a) if a.lock().lock_sha256 == locked_sha => {}
            Ok(a) => {
                self.set_hold(HoldReason::LockChanged {
                    locked: locked_sha,
                    now: a.lock().lock_sha256.clone(),
                });
                return;
            }
            Err(error) => {
                self.set_hold(HoldReason::LockNoLongerVerifies { error });
                return;
            }
        }
        let (motion, reason) = if at_home {
            (
                Motion::AtHome,
                "tracking back, trajectory still verified: robot at home",
            )
        } else if at_handover {
            // A part already in the operator's hand when the robot was held stays so.
            let part = match self.motion {
                Motion::AtHandover(part) => part,
                _ => Part::Offered,
            };
            (
                Motion::AtHandover(part),
                "tracking back, trajectory still verified: robot at the handover point",
            )
        } else {
            // Stopped between knots: resuming from there would be a motion nobody validated.
            self.set_hold(HoldReason::StoppedBetweenEnds);
            return;
        };
        self.motion = motion;
        self.hold_reason = None;
        self.tracking_back_since = None;
        self.transition(now_nanos, SessionState::Working, reason, events);
        if motion == Motion::AtHome && !self.operator_departed {
            self.start_leg(now_nanos, Leg::ToHandover, robot, events);
        }
    }

    /// The locked trajectory's handover point in the world (the lock stores it in the station's
    /// frame), once locked.
    fn handover_world(&self) -> Option<Point3<f64>> {
        let lock = self.lock.as_ref()?.trajectory().lock();
        Some(ergocell_robot::handover_world(
            &self.config.T_world_station,
            lock.summary.handover_station_m,
        ))
    }

    /// The robot stays held for `reason` (said once, when the reason's words change).
    fn set_hold(&mut self, reason: HoldReason) {
        let why = reason.to_string();
        if self.hold_reason() != Some(why.as_str()) {
            tracing::warn!(reason = %why, "robot stays held");
            self.hold_reason = Some((reason, why));
        }
    }

    /// Why the robot is held, typed; `None` while it is not.
    pub fn held_for(&self) -> Option<&HoldReason> {
        self.hold_reason.as_ref().map(|(reason, _)| reason)
    }

    fn end_session(&mut self, now_nanos: i64, at_home: bool, events: &mut Vec<SessionEvent>) {
        let Some(lock) = self.lock.take() else {
            return;
        };
        match lock.end(self.operator_departed, at_home) {
            Ok(refused) => {
                self.summary.ended = true;
                let end = SessionEnd::OperatorLeft {
                    changes_refused: refused.len(),
                };
                self.summary.end_reason = end.to_string();
                self.summary.end = Some(end);
                let reason = self.summary.end_reason.clone();
                self.transition(now_nanos, SessionState::SessionEnded, &reason, events);
            }
            Err((lock, _)) => self.lock = Some(*lock),
        }
    }

    fn abort(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        reason: AbortReason,
        events: &mut Vec<SessionEvent>,
    ) {
        let why = reason.to_string();
        tracing::error!(reason = %why, "session aborted");
        let end = SessionEnd::Aborted { reason };
        let command = RobotCommand::Hold {
            reason: HoldReason::Ended { end: end.clone() },
        };
        self.send(now_nanos, robot, command, events);
        self.hold_reason = Some((HoldReason::Ended { end: end.clone() }, why.clone()));
        self.summary.end_reason = end.to_string();
        self.summary.end = Some(end);
        self.transition(now_nanos, SessionState::SessionEnded, &why, events);
    }

    /// Sends a command; a failed send is logged and the robot is assumed not to have moved.
    fn send(
        &mut self,
        now_nanos: i64,
        robot: &mut dyn RobotSink,
        command: RobotCommand,
        events: &mut Vec<SessionEvent>,
    ) -> bool {
        match robot.send(now_nanos, &command) {
            Ok(()) => {
                self.summary.robot_commands += 1;
                events.push(SessionEvent::RobotCommandSent {
                    stamp_nanos: now_nanos,
                    command,
                });
                true
            }
            Err(e) => {
                tracing::error!(error = %e, "robot command not sent");
                false
            }
        }
    }

    fn transition(
        &mut self,
        now_nanos: i64,
        to: SessionState,
        reason: &str,
        events: &mut Vec<SessionEvent>,
    ) {
        let from = self.state;
        if from == to {
            return;
        }
        self.state = to;
        tracing::info!(%from, %to, %reason, stamp_nanos = now_nanos, "session state");
        events.push(SessionEvent::StateChanged {
            stamp_nanos: now_nanos,
            from,
            to,
            reason: reason.to_owned(),
        });
    }

    /// The world's up vector the session uses.
    pub fn up(&self) -> &UpVector {
        &self.pipeline.config().assessment.up
    }
}

/// A hand's palm centre: the mean of its wrist, index and pinky landmarks (all three fused).
fn palm_centre(s: &Skeleton3, marks: [Landmark; 3]) -> Option<Point3<f64>> {
    let mut sum = nalgebra::Vector3::zeros();
    for m in marks {
        sum += s.position(m)?.coords;
    }
    Some(Point3::from(sum / 3.0))
}

fn mid_hip(s: &Skeleton3) -> Option<Point3<f64>> {
    let l = s.position(Landmark::LeftHip)?;
    let r = s.position(Landmark::RightHip)?;
    Some(nalgebra::center(&l, &r))
}
