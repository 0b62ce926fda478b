//! The perception crate's one error type.

use crate::camera::CameraId;

/// Everything that can go wrong in perception, with the offending values.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum PerceptionError {
    /// A calibration or detection file could not be parsed; `source_name` is the file (or stream)
    /// and `field` the offending field.
    #[error("{source_name}: field `{field}`: {message}")]
    Parse {
        source_name: String,
        field: String,
        message: String,
    },
    /// A camera parameter is non-finite or physically impossible.
    #[error("camera `{camera}`: {field} = {value:?} is invalid ({why})")]
    BadCameraParameter {
        camera: CameraId,
        field: &'static str,
        value: f64,
        why: &'static str,
    },
    /// Two cameras share an id.
    #[error("camera id `{0}` appears more than once in the rig")]
    DuplicateCamera(CameraId),
    /// A stereo pair or detection names a camera the rig does not have.
    #[error("unknown camera `{0}`")]
    UnknownCamera(String),
    /// A stereo pair uses the same camera twice.
    #[error("stereo pair `{0}` uses the same camera on both sides")]
    DegeneratePair(String),
    /// The rig has no cameras.
    #[error("the rig has no cameras")]
    EmptyRig,
    /// Fusion needs at least two cameras; the rig has fewer.
    #[error("the rig has {cameras} camera(s); fusing a 3D skeleton needs at least 2")]
    TooFewCameras { cameras: usize },
    /// Two cameras have (nearly) the same centre: no baseline, nothing can be triangulated from them.
    #[error(
        "cameras `{first}` and `{second}` are {distance_m:.6} m apart (closer than {limit_m} m): \
         coincident centres, no baseline to triangulate from"
    )]
    CoincidentCameras {
        first: CameraId,
        second: CameraId,
        distance_m: f64,
        limit_m: f64,
    },
    /// Two camera centres are farther apart than one cell's cameras can be.
    #[error(
        "cameras `{first}` and `{second}` are {distance_m:.1} m apart (more than {limit_m} m): one \
         cell's cameras are metres apart, so the calibration is not in metres (millimetres?); \
         ergocell reads metres"
    )]
    RigTooLarge {
        first: CameraId,
        second: CameraId,
        distance_m: f64,
        limit_m: f64,
    },
    /// The point the cameras' optical axes converge on is behind every camera.
    #[error(
        "every camera faces away from where the cameras' optical axes meet ({x:.2}, {y:.2}, {z:.2}) m: \
         no camera would see the operator. Are the extrinsics inverted (each camera's pose in the \
         world, camera→world, given where world→camera is expected)?"
    )]
    CamerasFaceAway { x: f64, y: f64, z: f64 },
    /// A point is behind the camera (or on its centre plane): it has no image.
    #[error("point is behind camera `{camera}` (depth {depth_m} m)")]
    BehindCamera { camera: CameraId, depth_m: f64 },
    /// The iterative undistortion did not converge (pixel far outside the lens model's valid range).
    #[error("camera `{camera}`: undistortion of pixel ({u}, {v}) did not converge")]
    UndistortionDiverged { camera: CameraId, u: f64, v: f64 },
    /// A pixel coordinate is NaN or infinite.
    #[error("non-finite pixel ({u}, {v})")]
    NonFinitePixel { u: f64, v: f64 },
    /// A confidence outside 0..=1 (or NaN).
    #[error("confidence {0} outside 0..=1")]
    BadConfidence(f64),
    /// Fewer than two usable views of a point.
    #[error("{views} usable view(s); triangulation needs at least 2")]
    TooFewViews { views: usize },
    /// The linear system of a triangulation is degenerate (e.g. all rays parallel).
    #[error("degenerate triangulation (rays parallel or point at infinity)")]
    Degenerate,
    /// The views constrain the point too weakly to be used (nearly parallel rays, e.g. a narrow
    /// stereo pair far away with a wrong detection): its position uncertainty exceeds the limit.
    #[error("triangulated point too uncertain: σ {sigma_m:.2} m > {limit_m:.2} m")]
    Unconstrained { sigma_m: f64, limit_m: f64 },
    /// An unsupported model or format was asked for.
    #[error("unsupported: {0}")]
    Unsupported(String),
}

/// Shorthand for results of this crate.
pub type Result<T, E = PerceptionError> = std::result::Result<T, E>;
