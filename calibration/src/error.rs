//! The calibration crate's one error type: bad input and failed solves. A rejected checkerboard
//! view is an outcome ([`crate::detect::Rejection`]), not an error.

use ergocell_perception::PerceptionError;

/// Everything that can go wrong in calibration, with the offending values.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum CalibrationError {
    /// The image bytes could not be decoded (not a JPEG/PNG, truncated, …).
    #[error("cannot decode image `{name}`: {message}")]
    Decode { name: String, message: String },
    /// The board description is invalid, e.g. `--board 1x6` or a non-positive square size.
    #[error("invalid board {cols}x{rows} with {square_m} m squares: {why}")]
    BadBoard {
        cols: usize,
        rows: usize,
        square_m: f64,
        why: &'static str,
    },
    /// A board size string is not `COLSxROWS`.
    #[error("board size `{0}` is not COLSxROWS (inner corners), e.g. 9x6")]
    BadBoardSpec(String),
    /// Fewer usable views than calibration needs.
    #[error("{what}: {usable} usable views, at least {needed} needed")]
    TooFewViews {
        what: String,
        usable: usize,
        needed: usize,
    },
    /// A view's corner list does not have one point per board corner.
    #[error("view {view}: {got} corners, the board has {expected}")]
    CornerCount {
        view: usize,
        got: usize,
        expected: usize,
    },
    /// Views of one camera come from images of different sizes.
    #[error("camera `{camera}`: image {view} is {got_w}x{got_h} px, earlier images are {want_w}x{want_h} px")]
    ImageSizeMismatch {
        camera: String,
        view: usize,
        got_w: u32,
        got_h: u32,
        want_w: u32,
        want_h: u32,
    },
    /// None of a camera's images could be decoded.
    #[error("camera `{camera}`: no image could be decoded")]
    NoImageDecoded { camera: String },
    /// The closed-form initialisation found no physical camera (degenerate views: all boards parallel).
    #[error("closed-form initialisation failed: {0}")]
    Initialisation(String),
    /// The views do not determine the camera (e.g. every board parallel to the image plane): the
    /// estimate ran off to an implausible value.
    #[error("the views do not determine the camera: {field} = {value} is implausible for a {width_px}x{height_px} px image (tilt the board between views)")]
    Degenerate {
        field: &'static str,
        value: f64,
        width_px: u32,
        height_px: u32,
    },
    /// Rig cameras cannot be put in one frame: a camera shares no frame with the others.
    #[error("camera `{0}` shares no checkerboard view with the rest of the rig")]
    Disconnected(String),
    /// A points file for `calibrate place` does not parse or holds an impossible value.
    #[error("{source_name}: {why}")]
    BadPoints { source_name: String, why: String },
    /// A camera a measured point names is in no group, or in more than one.
    #[error(
        "camera `{camera}` is in {groups} of the groups being placed (it must be in exactly one)"
    )]
    PlaceCamera { camera: String, groups: usize },
    /// A group saw too few measured points with two of its cameras to start its pose, or they lie on
    /// one line.
    #[error("cameras {cameras}: {triangulated} measured points seen by two of them, at least {needed} not on one line needed")]
    TooFewPoints {
        cameras: String,
        triangulated: usize,
        needed: usize,
    },
    /// A group of one camera: its pose needs points seen by two of its cameras.
    #[error(
        "camera `{camera}` is alone in its group: place a stereo pair (a group needs two cameras)"
    )]
    GroupOfOne { camera: String },
    /// A measured point lies behind a camera that is said to see it.
    #[error("point `{point}` would be behind camera `{camera}`, which is said to see it: a wrong camera id, point or sign")]
    BehindCamera { camera: String, point: String },
    /// The placed group does not fit its sightings.
    #[error("cameras {cameras}: reprojection RMS {rms_px:.1} px after placing, more than {limit_px} px (worst point `{worst_point}`): a wrong camera id, measurement or click")]
    PoorFit {
        cameras: String,
        rms_px: f64,
        limit_px: f64,
        worst_point: String,
    },
    /// The camera model rejected the estimate (non-finite or non-positive parameters).
    #[error(transparent)]
    Camera(#[from] PerceptionError),
}

/// Result with [`CalibrationError`].
pub type Result<T> = std::result::Result<T, CalibrationError>;
