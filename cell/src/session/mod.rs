//! The cell controller's session: one operator, from walking in to leaving.
//!
//! ```text
//! WaitingForOperator → MeasuringHeight → ClassDecided → TrajectoryLocked → Working → SessionEnded
//!                                                              │              ▲ │
//!                                                              └──► Held ◄────┘ └► (Held ⇄ Working)
//! ```
//!
//! [`SessionMachine`] is driven by the caller: each [`SessionMachine::step`] gets the time (an injected
//! clock: the simulator's, a test's or the wall clock at the binary's boundary), the camera views that
//! arrived since the last step, and a [`RobotSink`]. The machine owns one
//! [`Pipeline`](crate::pipeline::Pipeline): every frame is fused, filtered, assessed and measured
//! there, nowhere else. Backends speak this crate's own types: a [`RobotSink`] (commands out, joint
//! positions in; the ROS 2 backend's `RosRobot`, the twin's `TwinRobot`, the tests' [`dummy::DummyRobot`]),
//! the robot side's reports ([`RobotReport`], judged by the rules of [`robot_side`] and the
//! [`ExecutionWatch`]) and the camera views,
//! which the simulator and the tests' scripts give as a [`LandmarkSource`] and `ergocell run` hands
//! to the loop as they arrive over ROS 2. No ROS message crosses into the core (the ROS 2 backend,
//! `ergocell_ros_backend::messages`, converts at its boundary). Trajectories come only through a
//! [`TrajectoryProvider`], which verifies the lock and its approval on every call.
//!
//! The robot is **held** (goal cancelled: on ROS an empty `JointTrajectory`) when fewer than one
//! stereo pair sees the operator or the newest frame is older than
//! [`SessionConfig::max_frame_age_nanos`]. A hold is a software hold through the controller's normal
//! interface, not an emergency stop.

pub mod approval_summary;
pub mod cell_loop;
pub mod driver;
pub mod dummy;
pub mod end;
mod machine;
pub mod robot_side;
pub mod watch;

pub use cell_loop::{AfterSession, CellLoop, CellOutputs, Ending, ExitStatus, OutputError, Step};
pub use driver::{
    CommandSent, Driver, DriverError, Input, InputError, Outcome, Station, StopRequest, Timed,
};
pub use end::{AbortReason, HoldReason, Interruption, SessionEnd, StopSignal};
pub use machine::{PartTakenFacts, SessionMachine, SessionSummary};
pub use robot_side::{
    DriverEvent, DriverState, DriverStop, GoalAnswer, GoalStatus, ReportEffect, ResultCode,
    RobotFailure, RobotReport, RobotUnready,
};
pub use watch::ExecutionWatch;

use ergocell_ergonomics::height::{DecisionBasis, HandoverRula};
use ergocell_ergonomics::{FrameAssessment, HeightClass, WarningEvent};
use ergocell_perception::View2;
use ergocell_robot::monitor::MonitorLimits;
use ergocell_robot::{ApprovedTrajectory, TrajectoryClass};
use ergocell_skeleton::Skeleton3;
use nalgebra::Isometry3;

pub use crate::error::{BackendError, Cause, ProviderError};

/// The session's states.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SessionState {
    WaitingForOperator,
    MeasuringHeight,
    ClassDecided,
    TrajectoryLocked,
    Working,
    /// The robot is held (tracking lost or frames stale); resumes only when tracking is back and the
    /// locked trajectory still verifies.
    Held,
    SessionEnded,
}

impl SessionState {
    /// Snake-case name (the `state` field of `ergocell_msgs/SessionState`).
    pub const fn name(self) -> &'static str {
        match self {
            Self::WaitingForOperator => "waiting_for_operator",
            Self::MeasuringHeight => "measuring_height",
            Self::ClassDecided => "class_decided",
            Self::TrajectoryLocked => "trajectory_locked",
            Self::Working => "working",
            Self::Held => "held",
            Self::SessionEnded => "session_ended",
        }
    }
}

impl std::fmt::Display for SessionState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Which way along the locked path a trajectory goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Leg {
    /// Home → handover: the locked trajectory as stored.
    ToHandover,
    /// Handover → home: the locked trajectory time-reversed (same path, same samples, velocities
    /// negated; every limit the validator checked is symmetric, and both ends are at rest).
    ToHome,
}

impl Leg {
    /// The leg in words, as the console, the monitor and the controller events say it.
    pub const fn words(self) -> &'static str {
        match self {
            Self::ToHandover => "home → handover",
            Self::ToHome => "handover → home",
        }
    }
}

/// One knot of a trajectory leg, in the order of [`LegTrajectory::joint_names`].
#[derive(Debug, Clone, PartialEq)]
pub struct LegPoint {
    pub positions_rad: Vec<f64>,
    pub velocities_rad_s: Vec<f64>,
    pub accelerations_rad_s2: Vec<f64>,
    /// Time from the leg's start, seconds.
    pub time_from_start_s: f64,
}

/// A leg of the locked trajectory, as the robot must run it (`ergocell_ros_backend::messages` turns it
/// into the controller's message).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LegTrajectory {
    pub joint_names: Vec<String>,
    pub points: Vec<LegPoint>,
    /// The execution monitor's path tolerance per joint, radians: the lock's, derived when it was
    /// validated and signed off with it (the backend may only tighten it).
    pub path_tolerance_rad: Vec<f64>,
    /// The execution monitor's other limits and the goal's tolerances: the lock's, signed off with
    /// it (the backend may only tighten them, [`MonitorLimits::tightened`]).
    pub monitor: MonitorLimits,
}

impl LegTrajectory {
    /// The leg's duration, seconds (0 for an empty leg).
    pub fn duration_s(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.time_from_start_s)
    }
}

/// A command to the robot controller.
#[derive(Debug, Clone)]
pub enum RobotCommand {
    /// Follow this trajectory (the locked one, or its time reversal).
    Execute {
        leg: Leg,
        lock_sha256: String,
        trajectory: LegTrajectory,
    },
    /// Cancel the goal: the robot stops where it is. Not an emergency stop. `reason` is why, typed
    /// (its words are its `Display`).
    Hold { reason: HoldReason },
}

/// What happened in a step: logged with `tracing`, recorded, shown.
#[derive(Debug, Clone)]
pub enum SessionEvent {
    StateChanged {
        stamp_nanos: i64,
        from: SessionState,
        to: SessionState,
        reason: String,
    },
    ClassDecided {
        stamp_nanos: i64,
        height_m: f64,
        uncertainty_m: f64,
        class: HeightClass,
        /// How it was chosen: inside one class, or across a boundary.
        basis: DecisionBasis,
        /// The probability that `class` is the operator's true class.
        probability: f64,
        /// Expected RULA grand score with `class` minus with the true class (`None` without the
        /// classes' RULA curves).
        expected_rula_cost: Option<f64>,
    },
    TrajectoryLocked {
        stamp_nanos: i64,
        class: TrajectoryClass,
        lock_sha256: String,
        approved_by: Vec<String>,
    },
    /// A mid-session request for another trajectory class, refused.
    ChangeRefused {
        stamp_nanos: i64,
        requested: TrajectoryClass,
        reason: String,
    },
    /// The cell's cycle: the operator took the part at the handover point (a hand came to the
    /// point while the robot held the part there, then left it); the robot goes home for the next.
    PartTaken {
        stamp_nanos: i64,
        /// 1 for the session's first part.
        part: u32,
        /// The operator's hand that took it.
        hand: ergocell_skeleton::Side,
        /// How close that hand's palm centre came to the handover point, metres.
        closest_m: f64,
    },
    CameraDegraded {
        stamp_nanos: i64,
        camera: String,
        why: String,
    },
    CameraRestored {
        stamp_nanos: i64,
        camera: String,
    },
    RobotCommandSent {
        stamp_nanos: i64,
        command: RobotCommand,
    },
    Warning(WarningEvent),
    /// One fused frame (for recording and displays).
    Frame {
        stamp_nanos: i64,
        skeleton: Box<Skeleton3>,
        assessment: Option<Box<FrameAssessment>>,
    },
}

/// Bounds of the session (`[session]` of the cell file; the station from `[station]`). Times in
/// integer nanoseconds, distances in metres. The per-frame pipeline's tunables are in
/// [`PipelineConfig`](crate::pipeline::PipelineConfig).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SessionConfig {
    /// A camera whose last view arrived longer ago than this is stale (degraded, reported).
    pub camera_stale_nanos: i64,
    /// The robot is held when the newest fused frame is older than this (the stated bound). Frame
    /// age is this clock minus the cameras' capture stamps: on a real cell the camera computers and
    /// the cell PC must be time-synchronised (chrony/PTP) well inside this bound.
    pub max_frame_age_nanos: i64,
    /// A view "sees the operator" with at least this many landmarks.
    pub min_view_landmarks: usize,
    /// Tracking must be back this long before a held robot resumes.
    pub resume_after_nanos: i64,
    /// An operator lost from view farther than this from the station (horizontally) has left the
    /// cell; lost nearer, it is a tracking loss (the robot is held).
    pub exit_radius_m: f64,
    /// Station position in the world (x, y), metres.
    pub station_xy_m: [f64; 2],
    /// Joint tolerance for "the robot is at the trajectory's start / end", radians.
    pub at_knot_tolerance_rad: f64,
    /// An operator whose height is still undecided this long after they were first tracked (their
    /// stated interval straddles a class boundary, or they never stood upright) ends the session:
    /// the robot does not move, and the reason says why.
    pub height_timeout_nanos: i64,
    /// The station's pose in the world (`[station]`): places the lock's handover point, which the
    /// lock stores in the station's frame.
    pub T_world_station: Isometry3<f64>,
    /// The cell's cycle: the part at the handover point counts as in the operator's hand once a
    /// tracked hand (its palm centre: wrist, index and pinky) comes within this of the point…
    pub take_radius_m: f64,
    /// …and as taken once that hand is farther than this again: the robot then goes home.
    pub release_radius_m: f64,
    /// Back home, the robot brings the next part after this long (its gripper takes the part from
    /// the feeder), unless the operator has left.
    pub next_part_after_nanos: i64,
}

impl Default for SessionConfig {
    fn default() -> Self {
        Self {
            camera_stale_nanos: 500_000_000,
            max_frame_age_nanos: 500_000_000,
            min_view_landmarks: 10,
            resume_after_nanos: 500_000_000,
            exit_radius_m: 1.0,
            station_xy_m: [0.0, 0.0],
            at_knot_tolerance_rad: 0.01,
            height_timeout_nanos: 20_000_000_000,
            T_world_station: Isometry3::identity(),
            take_radius_m: 0.15,
            release_radius_m: 0.30,
            next_part_after_nanos: 1_000_000_000,
        }
    }
}

/// Camera landmarks in: whatever arrived by `now_nanos`.
pub trait LandmarkSource {
    /// The views that arrived since the last poll, or `None` once the source has ended.
    fn poll(&mut self, now_nanos: i64) -> Result<Option<Vec<View2>>, BackendError>;
}

/// Robot commands out, joint positions in.
pub trait RobotSink {
    /// Sends a command to the controller.
    fn send(&mut self, now_nanos: i64, command: &RobotCommand) -> Result<(), BackendError>;
    /// The robot's joint positions in the order of `names` (from `/joint_states`, mapped by name);
    /// `None` if unknown.
    fn joint_positions(&mut self, now_nanos: i64, names: &[String]) -> Option<Vec<f64>>;
    /// Whether the controller still runs a goal it accepted (its result not yet in): the driver
    /// waits for it after the last session. A port that cannot tell says no.
    fn goal_outstanding(&self) -> bool {
        false
    }
}

/// Verified trajectories: every call re-reads and re-verifies the lock and its approval.
pub trait TrajectoryProvider {
    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError>;
    /// The statures `(min_m, max_m)` the class's trajectory was validated and is served for (its
    /// trajectory file's served range, covered by the lock's hash): the class's own statures
    /// widened by what the height decision can reach across a boundary.
    fn stature_bounds_m(&mut self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError>;
    /// The classes' RULA-versus-stature curves at their handover points (measured on the digital
    /// twin, shipped beside the trajectories), which the height decision weighs across a class
    /// boundary; `None`: there are none, and the decision takes the most probable class.
    fn handover_rula(&mut self) -> Result<Option<HandoverRula>, ProviderError> {
        Ok(None)
    }
}

/// The cell's own files, through the approvals crate's port ([`ergocell_approvals::provider`]).
impl TrajectoryProvider for ergocell_approvals::FileTrajectories {
    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        ergocell_approvals::FileTrajectories::verify(self, class)
    }

    fn stature_bounds_m(&mut self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        ergocell_approvals::FileTrajectories::stature_bounds_m(self, class)
    }

    fn handover_rula(&mut self) -> Result<Option<HandoverRula>, ProviderError> {
        ergocell_approvals::FileTrajectories::handover_rula(self)
    }
}

/// The trajectory class a height class selects.
pub fn trajectory_class(class: HeightClass) -> TrajectoryClass {
    match class {
        HeightClass::C1 => TrajectoryClass::C1,
        HeightClass::C2 => TrajectoryClass::C2,
        HeightClass::C3 => TrajectoryClass::C3,
    }
}

/// One leg of the locked trajectory.
pub fn leg_trajectory(approved: &ApprovedTrajectory, leg: Leg) -> LegTrajectory {
    let points = approved.points();
    let total_s = points.last().map_or(0.0, |p| p.time_s);
    let convert = |p: &ergocell_robot::lock::LockPoint, time_s: f64, sign: f64| LegPoint {
        positions_rad: p.positions_rad.clone(),
        velocities_rad_s: p.velocities_rad_s.iter().map(|v| sign * v).collect(),
        accelerations_rad_s2: p.accelerations_rad_s2.clone(),
        time_from_start_s: time_s,
    };
    let points = match leg {
        Leg::ToHandover => points.iter().map(|p| convert(p, p.time_s, 1.0)).collect(),
        Leg::ToHome => points
            .iter()
            .rev()
            .map(|p| convert(p, total_s - p.time_s, -1.0))
            .collect(),
    };
    LegTrajectory {
        joint_names: approved.joint_names().to_vec(),
        points,
        path_tolerance_rad: approved.path_tolerance_rad().to_vec(),
        monitor: approved.monitor_limits(),
    }
}
