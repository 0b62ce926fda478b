//! The cell controller's core, with no I/O and no ROS: the one per-frame pipeline, the session
//! state machine that owns it, and the cell configuration.
//!
//! - [`pipeline`]: camera views → fused skeleton → filtered skeleton → RULA → warnings, and the
//!   height at session start. Wired once, here; the session and the digital twin's experiments run
//!   [`Pipeline`], the offline commands its stages.
//! - [`session`]: the state machine from "waiting for an operator" to "session ended": height class,
//!   the locked trajectory, holds and resumes, the operator's departure; the session driver
//!   ([`session::Driver`]) that runs sessions end to end for `run` and `demo` on a
//!   [`session::Station`]. Backends behind traits ([`session::Station`], [`session::RobotSink`],
//!   [`session::CellOutputs`], [`session::TrajectoryProvider`]) speak this
//!   crate's types; the ROS 2 backend (`ergocell_ros_backend::messages`) converts them to ROS
//!   messages at its boundary.
//! - [`config`]: `config/cell.toml`, every tunable of the session, pipeline, assessment and task and
//!   the station, strictly parsed (`deny_unknown_fields`) with errors that name the file, the key and
//!   the value.
//!
//! **The failure table** (`cargo test -p ergocell_cell --test failure_table`, `tests/failure_table.rs`):
//! the session driver run to a session's end on a scripted station of the twin's cameras and robot
//! side (the simulated controller and KUKA driver under [`session::ExecutionWatch`]), each row
//! asserting its typed outcome and exit status: a joint off the locked
//! path and a stall end the session held (`RobotFailed` with the `Deviation`); a late controller
//! answer ends it (`GoalUnanswered`); the driver stopping (by a user, or an error such as an e-stop)
//! holds the robot (`RobotNotReady`); a lock that does not verify ends the session before the robot
//! moves (`Aborted { NotVerified }`); tracking lost holds (`CamerasLost`) and resumes at an end of the
//! path; one camera lost is reported and the robot works on; the cameras' clock jumping back holds;
//! a stop signal ends it held with exit status 130; an input that fails ends it held
//! (`InputFailed`) and returns the station's error; a next session that cannot start stops the
//! program for a person (exit status 1).
//!
//! Dependencies: perception, ergonomics, robot, skeleton. Not ROS (`ergocell_bridge`), not the
//! simulator; `.ci/deps` checks it.

pub mod config;
pub mod error;
pub mod pipeline;
pub mod session;

pub use config::CellSettings;
pub use error::{BackendError, CellError, ProviderError};
pub use pipeline::{
    Assessment, FrameOutput, OperatorZone, Pipeline, PipelineConfig, Reconstructed, Reconstruction,
    ReconstructionConfig, TrackedFrame,
};
