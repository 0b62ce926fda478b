//! Perception: from calibrated cameras and 2D body landmarks to one fused 3D skeleton.
//!
//! The seed paper's steps II.A (calibration files, per-pair DLT) and II.B (multi-camera fusion) live
//! here, plus what a real cell needs around them:
//!
//! - [`camera`]: pinhole + Brown–Conrady camera model, projection, iterative undistortion.
//! - [`rig`]: M cameras in one world frame, grouped into stereo pairs.
//! - [`detections`]: 2D keypoints (BlazePose-33 order) and what an import dropped;
//!   [`video_geometry`]: a video that is not the calibrated image (scaled, letterboxed, cropped).
//! - [`triangulation`]: the paper's DLT (SVD) and the robust N-view triangulator.
//! - [`fusion`]: the paper's graph-Laplacian fusion (baseline) and ergocell's default fusion;
//!   [`body_prior`]: the learned-bone-length prior the default fusion adds.
//! - [`operator_gate`]: which views show the operator and which someone else (a single-person
//!   detector per camera, two people in the cell).
//! - [`temporal`]: time alignment of camera streams and a causal One-Euro filter;
//!   [`fixed_lag`]: a centred moving mean (no lag, at the price of latency).
//! - [`metrics`]: bone-length consistency, the run's tallies; [`report_text`]: `triangulate`'s
//!   summary and the detector-error tables as text;
//!   [`detector_error`]: the real detector's error, each view judged by the others.
//!
//! No I/O and no file formats: the outside world's files (rig and calibration files, OpenPose,
//! caliscope, landmark CSV and TRC) are read and written by `ergocell_formats`, which sits on this
//! crate. Knows nothing of ROS or the robot.

pub mod body_prior;
pub mod camera;
pub mod camera_health;
pub mod detections;
pub mod detector_error;
pub mod error;
pub mod fixed_lag;
pub mod fusion;
pub mod metrics;
pub mod operator_gate;
pub mod report_text;
pub mod rig;
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
