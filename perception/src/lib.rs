//! Perception: from calibrated cameras and 2D body landmarks to one fused 3D skeleton.
//!
//! The seed paper's steps II.A (calibration files, per-pair DLT) and II.B (multi-camera fusion) live
//! here, plus what a real cell needs around them:
//!
//! - [`camera`]: pinhole + Brown–Conrady camera model, projection, iterative undistortion.
//! - [`rig`]: M cameras in one world frame, grouped into stereo pairs.
//! - [`rig_file`]: ergocell's rig TOML, Anipose/Pose2Sim and caliscope calibration import;
//!   [`qualisys`]: Qualisys QTM's `.qca.txt` export.
//! - [`detections`], [`import`]: 2D keypoints (BlazePose-33 order), OpenPose JSON and caliscope CSV;
//!   [`video_geometry`]: a video that is not the calibrated image (scaled, letterboxed, cropped).
//! - [`triangulation`]: the paper's DLT (SVD) and the robust N-view triangulator.
//! - [`fusion`]: the paper's graph-Laplacian fusion (baseline) and ergocell's default fusion;
//!   [`body_prior`]: the learned-bone-length prior the default fusion adds.
//! - [`operator_gate`]: which views show the operator and which someone else (a single-person
//!   detector per camera, two people in the cell).
//! - [`temporal`]: time alignment of camera streams and a causal One-Euro filter;
//!   [`fixed_lag`]: a centred moving mean (no lag, at the price of latency).
//! - [`metrics`], [`landmarks_file`]: bone-length consistency and the 3D output formats;
//!   [`detector_error`]: the real detector's error, each view judged by the others.
//!
//! No I/O: callers pass file contents and get text back. Knows nothing of ROS or the robot.

pub mod body_prior;
pub mod camera;
pub mod camera_health;
pub mod detections;
pub mod detector_error;
pub mod error;
pub mod fixed_lag;
pub mod fusion;
pub mod import;
pub mod landmarks_file;
pub mod metrics;
pub mod operator_gate;
pub mod qualisys;
pub mod rig;
pub mod rig_file;
mod simd;
pub mod temporal;
pub mod triangulation;
pub mod video_geometry;
pub mod view_offset;

pub use camera::{Camera, CameraId, Distortion, Intrinsics};
pub use detections::{Frame2, Keypoint2, KeypointFormat, View2};
pub use error::PerceptionError;
pub use fusion::{FusedFrame, FusionEngine, FusionMethod};
pub use rig::{CameraIndex, CameraRig, StereoPair};
