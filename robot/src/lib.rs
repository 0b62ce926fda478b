//! Robot: the KUKA arm's kinematics and the class-specific handover trajectories.
//!
//! Will hold (issue "Robot"): URDF loading through `urdf-rs`/`k`, forward and inverse kinematics, the
//! `clarabel` trajectory QP, the safety checks, and the `LockedTrajectory` that only validation can
//! build. Knows nothing of cameras or ROS.
