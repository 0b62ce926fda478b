//! Robot: the KUKA arm's kinematics and the class-specific handover trajectories.
//!
//! * [`RobotModel`]: a URDF (parsed by `urdf-rs` 0.9, converted to a `k` 0.32 chain) reduced to an
//!   immutable serial arm with position, velocity and effort limits read from the URDF itself; forward
//!   kinematics and the geometric Jacobian.
//! * [`ik::solve_ik`]: damped-least-squares IK with joint limits, many iterations and several seeds, and
//!   an [`RobotError::Unreachable`] error naming the target and the closest pose reached.
//! * [`config`]: the `[robot]`/`[station]` tables of `config/cell.toml` and the trajectory files.
//! * [`qp`]: the joint-space trajectory QP solved with `clarabel`.
//! * [`validate::plan_and_validate`]: IK + QP + every check, a [`ValidationReport`], and a
//!   [`LockedTrajectory`] only when the QP is `Solved` and every check passes.
//! * [`lock`]: lock files, approvals, verification, the [`lock::ApprovedTrajectory`] the controller may
//!   send and the per-session [`lock::SessionLock`].
//! * [`monitor`]: the execution monitor (joint states against the lock, while the robot runs) and
//!   the path tolerances derived from the lock.
//! * [`signing`]: who may approve (OpenSSH allowed signers, revoked keys) and the exact bytes an
//!   approval's SSH signature covers.
//! * [`review`]: what the review commands decide and say: the re-validation of a lock, the
//!   sign-off an approve or a withdraw appends, and their report lines.
//! * [`authority`]: the site's approvers authority, whose signature makes the approvers' files count
//!   (the trust anchor outside the project folder).
//! * [`witness`]: what the cell has seen of each approvals file, so that one cut back (a deleted
//!   withdrawal, a rollback from a backup) is refused.
//!
//! The library reads no files: it parses strings, and the binary reads files and the clock. It knows
//! nothing of cameras, ergonomics or ROS. The lock is a software guarantee on top of the robot's own
//! safety controller, never a replacement for it.
//!
//! Units: metres, radians, seconds (degrees only in the text report). Transforms are named by frames:
//! `T_cell_base` is the base's pose in the cell.

// Checks are written `!(value <= limit)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod authority;
pub mod config;
mod error;
pub mod ik;
pub mod layout;
pub mod lock;
pub mod model;
pub mod monitor;
pub mod pose;
pub mod qp;
pub mod review;
pub mod signing;
pub mod validate;
pub mod witness;

pub use config::{handover_world, station_pose, CellConfig, TrajectoryClass, TrajectorySpec};
pub use error::RobotError;
pub use layout::{TrajectoryFile, TrajectoryLayout};
pub use lock::{ApprovedTrajectory, LockFile, SessionLock};
pub use model::{JointLimits, RobotModel};
pub use signing::TrustedSigners;
pub use validate::{
    plan_and_validate, InputHashes, LockedTrajectory, PlanInputs, TrustFiles, Validation,
    ValidationReport,
};
