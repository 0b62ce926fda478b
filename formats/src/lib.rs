//! Formats: readers and writers of the outside world's files, apart from the real-time fusion.
//!
//! - [`rig_file`]: ergocell's rig TOML, Anipose/Pose2Sim and caliscope calibration import;
//!   [`qualisys`]: Qualisys QTM's `.qca.txt` export.
//! - [`import`]: 2D keypoints from OpenPose JSON and caliscope CSV (BlazePose-33 order), into
//!   perception's [`ergocell_perception::Frame2`].
//! - [`landmarks_file`]: the fused 3D landmarks as CSV and TRC, written and read back.
//!
//! What it owns: the parsing, its bounds (nesting, sizes, finite numbers) and its refusals, each
//! naming the file and the field ([`error`]). What it must not do: I/O (callers pass file contents
//! and get text back), fusion or triangulation (that is `ergocell_perception`, which this crate sits
//! on and which knows nothing of files), anything of ROS or the robot.

pub mod error;
pub mod import;
pub mod landmarks_file;
pub mod qualisys;
pub mod rig_file;
