//! Digital twin of the cell: simulated operators, cameras and pose-estimator noise, with ground truth.
//!
//! The seed paper (Arvanitis et al., Sec. III.3) validates its pipeline in a Unity3D digital twin,
//! because only a simulator knows the true 3D landmarks. This crate is ergocell's, in Rust: it feeds
//! the *real* perception and ergonomics code; only the world is simulated.
//!
//! - [`body`]: operators of any stature from Drillis & Contini (1966) segment ratios (as tabulated by
//!   Winter), forward kinematics to all 33 BlazePose landmarks.
//! - [`reach`]: task-driven postures — the reach to a handover point is solved by a small
//!   optimisation of reach plus comfort, so a low handover bends the trunk and a high one raises the
//!   arm above the shoulder.
//! - [`cameras`]: synthetic rigs of any size (the reference rig comes from `config/rig.toml`, parsed
//!   by the caller).
//! - [`detector`]: 2D detections like a real pose estimator's — lens distortion via the perception
//!   camera model, pixel noise, self-occlusion, out-of-frame, outliers, dropped views, timestamp jitter;
//!   every level a documented parameter ([`DetectorNoise`]); or an error relative to the image
//!   height, persistent and jitter ([`RelativeNoise`]), as the real detector's is.
//! - [`detector_fit`]: that relative error fitted to a real detector measured view against view
//!   (`ergocell_perception::detector_error`), at the real cameras, and the model file the twin reads.
//! - [`experiments`]: the seed paper's Table 1 and Figs. 7–9, height estimation and RULA agreement,
//!   run through the real perception and ergonomics crates.
//! - [`seeds`]: each experiment summarised over many seeds, with its goals judged seed by seed.
//! - [`report`]: what `ergocell sim` prints and draws of each result, text and SVG figures as
//!   strings (the binary writes them).
//! - [`runs`]: `ergocell sim`'s runs from the inputs it read to what it writes: an experiment on one
//!   seed or over seeds with a progress callback, the handover-RULA curves, the detector fit.
//! - [`controller`]: the twin's robot side: a simulated joint trajectory controller and KUKA driver
//!   with its faults as data, run under the cell's own execution watch ([`controller::TwinRobot`]).
//! - [`demo`]: the demo's session as data (the operator's script at the cell's pace, a camera
//!   bumped out of calibration).
//! - [`faults`]: the demo's faults (silent cameras, a class change request, the robot side's
//!   faults) as a schedule timed from the cell's cycle, a file a user or a test can change.
//! - [`source`]: the simulator as the cell's landmark source ([`source::SimSource`]);
//!   [`station`]: the twin around the cell loop as the session driver's station (`ergocell demo`:
//!   the cameras with the fault schedule, the twin robot's reports, the operator following the
//!   decided class, the status and soak lines).
//! - [`session`]: the session script (walk in → idle → N handovers → walk out) and the simulation
//!   clock; each [`Tick`] carries the ground truth and every camera's [`View2`](ergocell_perception::View2).
//!
//! **Deterministic**: every random draw comes from `ChaCha8Rng` seeded by [`SimConfig::seed`] (motion
//! and detector noise on separate streams); the same seed gives the same numbers, bit for bit. The
//! simulator has its own clock (tick `k` at `k · frame_period_nanos`) and never reads wall time.
//! **No I/O**: callers pass parsed rigs and values, and write the reports and figures themselves.
//!
//! **Ground truth** per tick: the 33 true landmarks ([`GroundTruth::skeleton`]), the stature, the true
//! joint angles ([`Posture`]) and the phase; true RULA is `ergocell_ergonomics::RulaAssessor` run on
//! the true skeleton (as [`experiments`] does), so truth and pipeline are scored by the same code.
//!
//! # Example
//! ```
//! use ergocell_sim::{ring_rig, Operator, RingRigConfig, SessionScript, SimConfig, Simulation};
//! use nalgebra::Point3;
//!
//! // The reference cell: `rig_file::parse_rig(&std::fs::read_to_string("config/rig.toml")?, ..)`;
//! // here a synthetic 6-camera rig.
//! let rig = ring_rig(6, &RingRigConfig::default())?;
//! let operator = Operator::new(1.75)?;
//! let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055)); // c2's handover, world
//! script.cycles = 2;
//! let mut sim = Simulation::new(rig, operator, script, SimConfig::new(42))?;
//! while let Some(tick) = sim.step()? {
//!     let truth = &tick.truth; // Skeleton3, stature, joint angles, phase
//!     assert_eq!(truth.skeleton.observed_count(), 33);
//!     for view in &tick.frame.views {
//!         // per-camera 2D keypoints, each view with its own (jittered) stamp_nanos
//!         let _ = (view.camera, view.stamp_nanos, view.observed_count());
//!     }
//! }
//! # Ok::<(), ergocell_sim::SimError>(())
//! ```

pub mod band_reliability;
pub mod body;
pub mod cameras;
pub mod controller;
pub mod demo;
pub mod design;
pub mod design_report;
pub mod detector;
pub mod detector_fit;
pub mod experiments;
pub mod faults;
pub mod reach;
pub mod report;
pub mod runs;
pub mod seeds;
pub mod session;
pub mod source;
pub mod station;
pub mod tasks;
pub mod warning_trust;

pub use body::{ArmPosture, LegPosture, Operator, Posture};
pub use cameras::{ring_rig, RingRigConfig};
pub use detector::{DetectorNoise, RelativeNoise};
pub use reach::{solve_reach, ReachConfig, ReachSolution};
pub use session::{
    Bystander, CameraBump, FloorPick, GroundTruth, Habits, Phase, PickStage, SessionScript,
    SimConfig, Simulation, TaskStage, Tick,
};

/// Everything that can go wrong in the simulator.
#[derive(Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SimError {
    /// A parameter outside its valid range.
    #[error("parameter `{name}` = {value}: {why}")]
    BadParameter {
        name: &'static str,
        value: f64,
        why: &'static str,
    },
    /// The perception crate refused a camera, rig or frame.
    #[error(transparent)]
    Perception(#[from] ergocell_perception::PerceptionError),
    /// A skeleton could not be built (non-finite landmark).
    #[error(transparent)]
    Skeleton(#[from] ergocell_skeleton::SkeletonError),
    /// The ergonomics crate refused a configuration (experiments).
    #[error(transparent)]
    Ergonomics(#[from] ergocell_ergonomics::ErgonomicsError),
    /// The cell controller's pipeline could not be built on the rig (experiments).
    #[error(transparent)]
    Cell(#[from] ergocell_cell::CellError),
    /// A fault schedule that does not parse or names what the rig does not have.
    #[error("fault schedule {file}: {reason}")]
    Faults { file: String, reason: String },
    /// A robot fault with a value out of range (a fraction of a leg outside [0, 1), a speed outside
    /// (0, 1), a zero rate or distance, a wait beyond an hour).
    #[error("robot fault {fault}: a value out of range")]
    RobotFaultOutOfRange { fault: String },
    /// A robot fault naming a joint the robot does not have.
    #[error("robot fault {fault}: joint {joint} does not exist (the robot has {joints} joints, 0-based)")]
    NoSuchJoint {
        fault: String,
        joint: usize,
        joints: usize,
    },
    /// A detector model (file or fit) that cannot be used.
    #[error("detector model: {why}")]
    BadModel { why: String },
}
