//! Ergonomics: what the fused 3D skeleton means for the operator's body.
//!
//! - [`rula`]: the complete RULA worksheet (McAtamney & Corlett 1993) for one side, with the lookup
//!   tables kept as data ([`tables`]) and ergocell's written band-edge convention.
//! - [`posture_cost`]: a continuous posture cost beside RULA: the grand score, and inside it how far
//!   each angle lies into its band (ranks as RULA wherever RULA's scores differ).
//! - [`reba`]: the complete REBA worksheet (Hignett & McAtamney 2000) for one side, whole body: the
//!   legs and REBA's own trunk and neck bands, with the same band-edge convention as RULA.
//! - [`angles`]: joint angles from BlazePose-33 landmarks in a body frame built from the hips and
//!   shoulders, with the world's "up" taken from the cell config (never assumed).
//! - [`assess`]: a frame-by-frame RULA assessor for both sides: angles + task config + a time-series
//!   muscle-use tracker → a breakdown that says which inputs were observed and which configured, and
//!   marks low-confidence, held or conservatively scored inputs "uncertain" (never lower); a wrist the
//!   keypoint layout has no hand points for is scored conservatively, not left unscored.
//! - [`activity`]: what the operator is doing from the skeleton alone (walking, floor pick, in
//!   place): the task segments exposure is reported by.
//! - [`height`]: stature from upright frames with two anthropometric estimators, and the height class
//!   decision at session start; [`height_text`]: its estimate, decision and calibration as text.
//! - [`static_posture`]: trunk, neck and upper-arm postures held outside ISO 11226's acceptable zone, against
//!   its maximum holding times (the table used is cited there).
//! - [`warnings`]: per-region posture warnings with hysteresis and minimum dwell time.
//! - [`summary`]: a session's time-weighted shares per action level, body-region score and grand
//!   score — the one computation behind `ergocell rula track`'s summary and the offline review;
//!   [`summary_text`] lays it out as text, [`track_text`] each frame as text or JSON.
//! - [`export`]: spreadsheet exports (CSV): a row per assessed frame and the session summary, units in
//!   the column names.
//! - [`pose`]: synthetic skeletons posed to known angles, for tests and benchmarks: postures of the
//!   workspace's one body model (`ergocell_body`, the digital twin's too).
//!
//! Depends on [`ergocell_skeleton`], `ergocell_anthropometry` and `ergocell_body`; knows nothing of
//! cameras, ROS or the robot, and does no I/O:
//! the binary reads files and passes text or values in. Time comes in as `stamp_nanos` on each frame.
//! Angles are radians in code; degrees appear only at the methods' boundaries — the RULA and REBA
//! worksheets and ISO 11226's zones, all written in degrees — and in reports and messages.

pub mod activity;
pub mod angles;
pub mod assess;
pub mod confidence;
pub mod export;
pub mod height;
pub mod height_text;
pub mod pose;
pub mod posture_cost;
pub mod reba;
pub mod rula;
pub mod static_posture;
pub mod summary;
pub mod summary_text;
pub mod tables;
pub mod track_text;
pub mod warnings;

pub use angles::{BodyAngles, SideAngles, UpVector};
pub use assess::{AssessmentConfig, FrameAssessment, RulaAssessor, SideAssessment, TaskConfig};
pub use height::{HeightClass, HeightConfig, HeightDecision, HeightEstimator, HeightStatus};
pub use rula::{score_worksheet, RulaInput, RulaScores, WristTwist};
pub use warnings::{WarningConfig, WarningEvent, WarningKind, WarningTracker};

/// Which side of the body (the person's own left and right): the skeleton's, so a landmark's side
/// ([`ergocell_skeleton::Landmark::side`]) and a worksheet's side are one type.
pub use ergocell_skeleton::Side;

/// Everything that can go wrong in this crate. Outcomes (an undecided height class, an uncertain
/// score) are not errors; they are values.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ErgonomicsError {
    /// The embedded RULA tables do not have the published shape.
    #[error("RULA table {table} is malformed: expected {expected}")]
    TableShape {
        table: &'static str,
        expected: &'static str,
    },
    /// A worksheet entry of `rula score` input is malformed.
    #[error("worksheet entry {index}: field `{field}`: {reason}")]
    Worksheet {
        index: usize,
        field: String,
        reason: String,
    },
    /// The worksheet input is not a JSON array.
    #[error("worksheet input: {reason}")]
    WorksheetJson { reason: String },
    /// A CSV export could not be written.
    #[error("CSV export: {reason}")]
    Export { reason: String },
    /// A number is outside its allowed range.
    #[error("{field} = {value} is outside {min}..={max}")]
    OutOfRange {
        field: &'static str,
        value: f64,
        min: f64,
        max: f64,
    },
    /// A number is NaN or infinite.
    #[error("{field} is not finite ({value})")]
    NonFinite { field: &'static str, value: f64 },
    /// The configured up vector has no direction.
    #[error("up vector ({x}, {y}, {z}) has zero or non-finite length")]
    DegenerateUp { x: f64, y: f64, z: f64 },
    /// A parameter of the confidence model is negative or not finite.
    #[error("confidence model: the {region}'s {parameter} is {value}: must be finite and >= 0")]
    BadConfidenceModel {
        region: &'static str,
        parameter: &'static str,
        value: f64,
    },
    /// Frames must come in time order.
    #[error("frame at {got} ns arrived after a frame at {previous} ns: time went backwards")]
    TimeWentBackwards { previous: i64, got: i64 },
    /// Height class thresholds must be ordered.
    #[error("height class thresholds must satisfy 0 < c1_below_m ({c1_below_m}) <= c2_up_to_m ({c2_up_to_m})")]
    BadClassThresholds { c1_below_m: f64, c2_up_to_m: f64 },
    /// The ear offset cannot be calibrated from these sessions.
    #[error("height calibration: {0}")]
    Calibration(String),
    /// The classes' RULA-versus-stature curves are malformed.
    #[error("handover RULA curves: {0}")]
    HandoverRula(String),
}
