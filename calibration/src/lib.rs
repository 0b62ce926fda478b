//! `ergocell_calibration`: camera and stereo calibration from checkerboard images, in pure Rust —
//! step A of the seed paper's Algorithm 1 (single-camera, then stereo calibration; the first camera
//! is the world origin, Sec. II.A.1–2).
//!
//! - [`detect`]: inner-corner detection (ChESS X-corners, lattice growth, OpenCV-style
//!   `cornerSubPix`), strict validation, a [`detect::Rejection`] with the reason for a bad view;
//! - [`intrinsics`]: Zhang's closed form (TPAMI 2000) + Levenberg–Marquardt refinement of
//!   `fx fy cx cy k1 k2 p1 p2 k3` and the board poses, RMS and per-view errors (OpenCV's
//!   `calibrateCamera` model and definitions);
//! - [`rig`]: stereo pairs and rigs chained into the first camera's frame, joint refinement
//!   (OpenCV's `stereoCalibrate` for two cameras).
//!
//! The camera model is `ergocell_perception`'s, so the result is a [`ergocell_perception::CameraRig`]
//! that `rig_file::to_ergocell_toml` / `to_anipose_toml` write. This crate decodes images from
//! bytes and reads no files; it lives apart from perception so the real-time path never links an
//! image decoder.

pub mod board;
pub mod detect;
pub mod error;
pub mod gray;
pub mod intrinsics;
pub mod linalg;
pub mod lm;
pub mod model;
pub mod place;
pub mod report;
pub mod rig;

pub use board::BoardSpec;
pub use detect::{detect_checkerboard, Detection, OrientationSource, Rejection};
pub use error::{CalibrationError, Result};
pub use gray::GrayImage;
pub use intrinsics::{calibrate_camera, CameraCalibration, SolveOptions};
pub use rig::{calibrate_rig, calibrate_stereo, CameraViews, RigCalibration, RigOptions};
