//! The cell configuration: `config/cell.toml`, read once, strictly.
//!
//! One file holds every tunable of the cell. This module owns the whole document's shape: a
//! top-level table it does not know (a typo such as `[sesion]`) and a key it does not know inside
//! its own tables (`exit_radius = 1`) are refused with the file and the key's name; every value is
//! range-checked and a bad one is reported as `table.key = value: why`. Units are in the key names
//! (`_m`, `_s`, `_rad`, `_hz`); seconds become integer nanoseconds here and nowhere else.
//!
//! | table | owner | what |
//! |---|---|---|
//! | `[robot]` | `ergocell_robot` (validated through it) | URDF, base pose, limits — covered by the trajectory locks |
//! | `[station]` | `ergocell_robot` | the operator station's pose in the world — covered by the locks, and the session's station |
//! | `[monitor]` | `ergocell_robot` | the execution monitor's goal, rest, stall and stop limits — covered by the locks, recorded in each |
//! | `[ros]` | `ergocell_bridge` | topics, DDS domain (kept as an opaque table here: the core knows no ROS) |
//! | `[session]` | here | stale, hold, resume and departure bounds |
//! | `[pipeline]` | here | frame assembly, fusion method, One-Euro filter, the tracked gate, the operator gate |
//! | `[assessment]` (+ `.thresholds`, `.muscle`) | here → `ergonomics::AssessmentConfig` | RULA's measured adjustments, smoothing |
//! | `[task]` | `ergonomics::TaskConfig` | what cameras cannot see (force/load, wrist twist, support) |
//! | `[warnings]` | here → `ergonomics::WarningConfig` | dwell, hysteresis, score per region |
//! | `[height]` | here → `ergonomics::HeightConfig` | class thresholds and the decision rule |
//!
//! Every table but `[robot]` and `[station]` may be left out; a missing key takes the default the
//! crates document. The world's up vector is not configured here: it belongs to the rig (`up` in
//! the rig file), because it is a property of the calibration.

use ergocell_ergonomics::assess::{MuscleUseConfig, Thresholds};
use ergocell_ergonomics::height::{ClassThresholds, EarOffset, MIN_CALIBRATION_SESSIONS};
use ergocell_ergonomics::{AssessmentConfig, HeightConfig, TaskConfig, UpVector, WarningConfig};
use ergocell_perception::temporal::OneEuroParams;
use ergocell_perception::view_offset::ViewOffsetConfig;
use ergocell_perception::FusionMethod;
use ergocell_robot::config::StationConfig;
use serde::Deserialize;

use crate::pipeline::{OperatorZone, PipelineConfig, ReconstructionConfig};
use crate::session::SessionConfig;
use crate::CellError;

/// The whole cell configuration, parsed and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct CellSettings {
    /// `[station]`: the operator station (world frame).
    pub station: StationConfig,
    /// The session's bounds (`[session]`, the station from `[station]`).
    pub session: SessionConfig,
    pipeline: PipelineFile,
    assessment: AssessmentFile,
    task: TaskConfig,
    warnings: WarningsFile,
    height: HeightFile,
}

impl Default for CellSettings {
    /// Every default, the station at the world origin (what the shipped `config/cell.toml` says).
    fn default() -> Self {
        Self {
            station: StationConfig {
                xyz_m: [0.0, 0.0, 0.0],
                yaw_rad: 0.0,
            },
            session: SessionConfig::default(),
            pipeline: PipelineFile::default(),
            assessment: AssessmentFile::default(),
            task: TaskConfig::default(),
            warnings: WarningsFile::default(),
            height: HeightFile::default(),
        }
    }
}

impl CellSettings {
    /// Parses and checks `text`; `source` names the file in every error.
    pub fn from_toml_str(text: &str, source: &str) -> Result<Self, CellError> {
        let err = |reason: String| CellError::Config {
            file: source.to_owned(),
            reason,
        };
        let file: CellFile = toml::from_str(text).map_err(|e| err(e.to_string()))?;
        // [robot], [station] and [monitor] are the robot crate's: validated by it, as the locks read them.
        ergocell_robot::CellConfig::from_toml_str(text).map_err(|e| err(e.to_string()))?;
        let settings = Self {
            session: file.session.to_config(&file.station).map_err(err)?,
            station: file.station,
            pipeline: file.pipeline,
            assessment: file.assessment,
            task: file.task,
            warnings: file.warnings,
            height: file.height,
        };
        settings.check().map_err(err)?;
        Ok(settings)
    }

    /// The per-frame pipeline's configuration on a rig whose vertical is `up`.
    pub fn pipeline(&self, up: UpVector) -> Result<PipelineConfig, CellError> {
        let p = &self.pipeline;
        let a = &self.assessment;
        let h = &self.height;
        let mut assessment = AssessmentConfig::new(up);
        assessment.floor_height_m = a.floor_height_m;
        assessment.min_confidence = a.min_confidence;
        assessment.thresholds = a.thresholds;
        assessment.task = self.task;
        assessment.muscle = MuscleUseConfig {
            hold_nanos: nanos(a.muscle.hold_s),
            window_nanos: nanos(a.muscle.window_s),
            min_repetitions: a.muscle.min_repetitions,
            min_excursion_nanos: nanos(a.muscle.min_excursion_s),
            min_return_nanos: nanos(a.muscle.min_return_s),
        };
        assessment.smoothing_window_nanos = nanos(a.smoothing_window_s);
        let mut height = HeightConfig::new(up);
        height.floor_height_m = h.floor_height_m.or(a.floor_height_m);
        height.thresholds = ClassThresholds::new(h.c1_below_m, h.c2_up_to_m)?;
        height.upright_max_knee_flexion_rad = h.upright_max_knee_flexion_rad;
        height.upright_max_hip_flexion_rad = h.upright_max_hip_flexion_rad;
        height.upright_max_trunk_tilt_rad = h.upright_max_trunk_tilt_rad;
        height.upright_max_neck_flexion_rad = h.upright_max_neck_flexion_rad;
        height.min_frames = h.min_frames;
        height.decision_sigmas = h.decision_sigmas;
        height.window_frames = h.window_frames;
        height.ear_offset = h.ear_offset().map_err(|reason| CellError::Config {
            file: "the cell configuration".to_owned(),
            reason,
        })?;
        Ok(PipelineConfig {
            reconstruction: ReconstructionConfig {
                fusion: p.fusion.method(),
                filter: p.filter.then_some(OneEuroParams {
                    min_cutoff_hz: p.filter_min_cutoff_hz,
                    beta: p.filter_beta_per_m,
                    derivative_cutoff_hz: p.filter_derivative_cutoff_hz,
                    max_gap_nanos: nanos(p.filter_max_gap_s),
                }),
                min_tracked_landmarks: p.min_tracked_landmarks,
                assembly_tolerance_nanos: nanos(p.assembly_tolerance_s),
                assembly_max_wait_nanos: nanos(p.assembly_max_wait_s),
                operator_zone: (p.operator_gate_radius_m > 0.0).then(|| OperatorZone {
                    station_torso_world: self.session.T_world_station
                        * nalgebra::Point3::new(0.0, 0.0, p.operator_gate_torso_height_m),
                    radius_m: p.operator_gate_radius_m,
                    memory_nanos: nanos(p.operator_gate_memory_s),
                }),
                view_offsets: (p.view_offset_time_constant_s > 0.0).then(|| ViewOffsetConfig {
                    time_constant_nanos: nanos(p.view_offset_time_constant_s),
                    ..ViewOffsetConfig::default()
                }),
                ..ReconstructionConfig::default()
            },
            assessment,
            warnings: WarningConfig {
                hysteresis_rad: self.warnings.hysteresis_rad,
                rise_margin_rad: self.warnings.rise_margin_rad,
                dwell_nanos: nanos(self.warnings.dwell_s),
                warn_at: self.warnings.warn_at,
            },
            height,
            fixed_lag_s: (p.fixed_lag_s > 0.0).then_some(p.fixed_lag_s),
        })
    }

    fn check(&self) -> Result<(), String> {
        let p = &self.pipeline;
        positive("pipeline.filter_min_cutoff_hz", p.filter_min_cutoff_hz)?;
        non_negative("pipeline.filter_beta_per_m", p.filter_beta_per_m)?;
        positive(
            "pipeline.filter_derivative_cutoff_hz",
            p.filter_derivative_cutoff_hz,
        )?;
        seconds("pipeline.filter_max_gap_s", p.filter_max_gap_s)?;
        seconds("pipeline.assembly_tolerance_s", p.assembly_tolerance_s)?;
        seconds("pipeline.assembly_max_wait_s", p.assembly_max_wait_s)?;
        landmarks("pipeline.min_tracked_landmarks", p.min_tracked_landmarks)?;
        non_negative("pipeline.operator_gate_radius_m", p.operator_gate_radius_m)?;
        non_negative(
            "pipeline.view_offset_time_constant_s",
            p.view_offset_time_constant_s,
        )?;
        seconds("pipeline.operator_gate_memory_s", p.operator_gate_memory_s)?;
        non_negative("pipeline.fixed_lag_s", p.fixed_lag_s)?;
        if p.fixed_lag_s > ergocell_perception::fixed_lag::MAX_HALF_WINDOW_S {
            return Err(format!(
                "pipeline.fixed_lag_s = {} is longer than {} s",
                p.fixed_lag_s,
                ergocell_perception::fixed_lag::MAX_HALF_WINDOW_S
            ));
        }
        finite(
            "pipeline.operator_gate_torso_height_m",
            p.operator_gate_torso_height_m,
        )?;
        let a = &self.assessment;
        if let Some(f) = a.floor_height_m {
            finite("assessment.floor_height_m", f)?;
        }
        unit_interval("assessment.min_confidence", a.min_confidence)?;
        seconds("assessment.smoothing_window_s", a.smoothing_window_s)?;
        seconds("assessment.muscle.hold_s", a.muscle.hold_s)?;
        seconds("assessment.muscle.window_s", a.muscle.window_s)?;
        seconds(
            "assessment.muscle.min_excursion_s",
            a.muscle.min_excursion_s,
        )?;
        seconds("assessment.muscle.min_return_s", a.muscle.min_return_s)?;
        let t = &a.thresholds;
        for (key, v) in [
            ("assessment.thresholds.abduction_rad", t.abduction_rad),
            (
                "assessment.thresholds.shoulder_raise_ratio_below",
                t.shoulder_raise_ratio_below,
            ),
            (
                "assessment.thresholds.out_to_side_shoulder_widths",
                t.out_to_side_shoulder_widths,
            ),
            (
                "assessment.thresholds.wrist_deviation_rad",
                t.wrist_deviation_rad,
            ),
            ("assessment.thresholds.neck_twist_rad", t.neck_twist_rad),
        ] {
            non_negative(key, v)?;
        }
        for (key, v) in [
            (
                "task.force_load_score_arm_wrist",
                self.task.force_load_score_arm_wrist,
            ),
            (
                "task.force_load_score_neck_trunk_legs",
                self.task.force_load_score_neck_trunk_legs,
            ),
        ] {
            if v > 3 {
                return Err(format!("{key} = {v}: RULA's force/load score is 0..=3"));
            }
        }
        let w = &self.warnings;
        angle("warnings.hysteresis_rad", w.hysteresis_rad)?;
        angle("warnings.rise_margin_rad", w.rise_margin_rad)?;
        seconds("warnings.dwell_s", w.dwell_s)?;
        for (i, &s) in w.warn_at.iter().enumerate() {
            if !(1..=6).contains(&s) {
                return Err(format!(
                    "warnings.warn_at[{i}] = {s}: a region score is 1..=6"
                ));
            }
        }
        let h = &self.height;
        stature("height.c1_below_m", h.c1_below_m)?;
        stature("height.c2_up_to_m", h.c2_up_to_m)?;
        if h.c1_below_m > h.c2_up_to_m {
            return Err(format!(
                "height.c1_below_m = {} is above height.c2_up_to_m = {}",
                h.c1_below_m, h.c2_up_to_m
            ));
        }
        if let Some(f) = h.floor_height_m {
            finite("height.floor_height_m", f)?;
        }
        for (key, v) in [
            (
                "height.upright_max_knee_flexion_rad",
                h.upright_max_knee_flexion_rad,
            ),
            (
                "height.upright_max_hip_flexion_rad",
                h.upright_max_hip_flexion_rad,
            ),
            (
                "height.upright_max_trunk_tilt_rad",
                h.upright_max_trunk_tilt_rad,
            ),
            (
                "height.upright_max_neck_flexion_rad",
                h.upright_max_neck_flexion_rad,
            ),
        ] {
            angle(key, v)?;
        }
        positive("height.decision_sigmas", h.decision_sigmas)?;
        for (key, v) in [
            ("height.min_frames", h.min_frames),
            ("height.window_frames", h.window_frames),
        ] {
            if v == 0 {
                return Err(format!("{key} = 0: at least one frame is needed"));
            }
        }
        h.ear_offset()?;
        Ok(())
    }
}

fn nanos(seconds: f64) -> i64 {
    (seconds * 1e9).round() as i64
}

fn finite(key: &str, v: f64) -> Result<(), String> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(format!("{key} = {v}: must be a finite number"))
    }
}

fn positive(key: &str, v: f64) -> Result<(), String> {
    finite(key, v)?;
    if v > 0.0 {
        Ok(())
    } else {
        Err(format!("{key} = {v}: must be greater than 0"))
    }
}

fn non_negative(key: &str, v: f64) -> Result<(), String> {
    finite(key, v)?;
    if v >= 0.0 {
        Ok(())
    } else {
        Err(format!("{key} = {v}: must not be negative"))
    }
}

fn unit_interval(key: &str, v: f64) -> Result<(), String> {
    if (0.0..=1.0).contains(&v) {
        Ok(())
    } else {
        Err(format!("{key} = {v}: must lie in 0..=1"))
    }
}

/// A duration in seconds: 0 to one hour (a larger one is a unit mistake, e.g. milliseconds).
fn seconds(key: &str, v: f64) -> Result<(), String> {
    if (0.0..=3600.0).contains(&v) {
        Ok(())
    } else {
        Err(format!("{key} = {v}: a duration in seconds, 0..=3600"))
    }
}

/// An angle in radians, 0 to π.
fn angle(key: &str, v: f64) -> Result<(), String> {
    if (0.0..=std::f64::consts::PI).contains(&v) {
        Ok(())
    } else {
        Err(format!(
            "{key} = {v}: an angle in radians, 0..=π (degrees given as radians?)"
        ))
    }
}

/// A human stature, 0.5–2.5 m.
fn stature(key: &str, v: f64) -> Result<(), String> {
    if (0.5..=2.5).contains(&v) {
        Ok(())
    } else {
        Err(format!(
            "{key} = {v}: a stature in metres, 0.5..=2.5 (centimetres given as metres?)"
        ))
    }
}

fn landmarks(key: &str, v: usize) -> Result<(), String> {
    if (1..=ergocell_skeleton::LANDMARK_COUNT).contains(&v) {
        Ok(())
    } else {
        Err(format!(
            "{key} = {v}: a landmark count, 1..={}",
            ergocell_skeleton::LANDMARK_COUNT
        ))
    }
}

// ---------------------------------------------------------------------------------------------
// The file's shape (serde). Defaults are the crates' documented defaults.

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CellFile {
    // [robot], [monitor] and [ros] are their owners' (validated by the robot crate, read by the bridge): named
    // here only so that `deny_unknown_fields` knows them.
    #[allow(dead_code)]
    robot: toml::Table,
    station: StationConfig,
    #[serde(default)]
    #[allow(dead_code)]
    ros: Option<toml::Table>,
    /// The execution monitor's limits: the robot crate's, validated by it and locked.
    #[serde(default)]
    #[allow(dead_code)]
    monitor: Option<toml::Table>,
    #[serde(default)]
    session: SessionFile,
    #[serde(default)]
    pipeline: PipelineFile,
    #[serde(default)]
    assessment: AssessmentFile,
    #[serde(default)]
    task: TaskConfig,
    #[serde(default)]
    warnings: WarningsFile,
    #[serde(default)]
    height: HeightFile,
}

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct SessionFile {
    camera_stale_s: f64,
    max_frame_age_s: f64,
    min_view_landmarks: usize,
    resume_after_s: f64,
    exit_radius_m: f64,
    at_knot_tolerance_rad: f64,
    height_timeout_s: f64,
    take_radius_m: f64,
    release_radius_m: f64,
    next_part_after_s: f64,
}

impl Default for SessionFile {
    fn default() -> Self {
        let d = SessionConfig::default();
        Self {
            camera_stale_s: d.camera_stale_nanos as f64 * 1e-9,
            max_frame_age_s: d.max_frame_age_nanos as f64 * 1e-9,
            min_view_landmarks: d.min_view_landmarks,
            resume_after_s: d.resume_after_nanos as f64 * 1e-9,
            exit_radius_m: d.exit_radius_m,
            at_knot_tolerance_rad: d.at_knot_tolerance_rad,
            height_timeout_s: d.height_timeout_nanos as f64 * 1e-9,
            take_radius_m: d.take_radius_m,
            release_radius_m: d.release_radius_m,
            next_part_after_s: d.next_part_after_nanos as f64 * 1e-9,
        }
    }
}

impl SessionFile {
    fn to_config(&self, station: &StationConfig) -> Result<SessionConfig, String> {
        seconds("session.camera_stale_s", self.camera_stale_s)?;
        seconds("session.max_frame_age_s", self.max_frame_age_s)?;
        seconds("session.resume_after_s", self.resume_after_s)?;
        positive("session.height_timeout_s", self.height_timeout_s)?;
        seconds("session.height_timeout_s", self.height_timeout_s)?;
        positive("session.exit_radius_m", self.exit_radius_m)?;
        landmarks("session.min_view_landmarks", self.min_view_landmarks)?;
        positive("session.at_knot_tolerance_rad", self.at_knot_tolerance_rad)?;
        if self.at_knot_tolerance_rad > 0.1 {
            return Err(format!(
                "session.at_knot_tolerance_rad = {}: above 0.1 rad (5.7°) the robot would count as \
                 at a trajectory's end while visibly away from it",
                self.at_knot_tolerance_rad
            ));
        }
        positive("session.take_radius_m", self.take_radius_m)?;
        positive("session.release_radius_m", self.release_radius_m)?;
        if self.release_radius_m <= self.take_radius_m {
            return Err(format!(
                "session.release_radius_m = {}: must be larger than session.take_radius_m = {} (a \
                 hand must leave the part's neighbourhood, not just its edge, for the part to count \
                 as taken)",
                self.release_radius_m, self.take_radius_m
            ));
        }
        seconds("session.next_part_after_s", self.next_part_after_s)?;
        for (i, v) in station.xyz_m.iter().enumerate() {
            finite(&format!("station.xyz_m[{i}]"), *v)?;
        }
        finite("station.yaw_rad", station.yaw_rad)?;
        let [sx, sy, sz] = station.xyz_m;
        Ok(SessionConfig {
            camera_stale_nanos: nanos(self.camera_stale_s),
            max_frame_age_nanos: nanos(self.max_frame_age_s),
            min_view_landmarks: self.min_view_landmarks,
            resume_after_nanos: nanos(self.resume_after_s),
            exit_radius_m: self.exit_radius_m,
            station_xy_m: [station.xyz_m[0], station.xyz_m[1]],
            at_knot_tolerance_rad: self.at_knot_tolerance_rad,
            height_timeout_nanos: nanos(self.height_timeout_s),
            T_world_station: ergocell_robot::station_pose([sx, sy, sz], station.yaw_rad),
            take_radius_m: self.take_radius_m,
            release_radius_m: self.release_radius_m,
            next_part_after_nanos: nanos(self.next_part_after_s),
        })
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
enum FusionName {
    /// ergocell's robust N-view fusion with the bone-length prior.
    #[default]
    Default,
    /// The seed paper's graph-Laplacian fusion (baseline).
    Paper,
}

impl FusionName {
    fn method(self) -> FusionMethod {
        match self {
            Self::Default => FusionMethod::Default,
            Self::Paper => FusionMethod::Paper,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct PipelineFile {
    fusion: FusionName,
    /// The causal One-Euro filter on (default) or off.
    filter: bool,
    filter_min_cutoff_hz: f64,
    filter_beta_per_m: f64,
    filter_derivative_cutoff_hz: f64,
    filter_max_gap_s: f64,
    min_tracked_landmarks: usize,
    assembly_tolerance_s: f64,
    assembly_max_wait_s: f64,
    /// A camera's view whose torso ray passes farther than this from where the operator is expected
    /// (the last tracked torso, else the station's) shows someone else and is left out of fusion;
    /// 0 = off. See `OperatorZone`.
    operator_gate_radius_m: f64,
    /// How long the last tracked torso stays where the operator is expected.
    operator_gate_memory_s: f64,
    /// Height of a standing operator's torso (mid shoulders and hips) above the station floor.
    operator_gate_torso_height_m: f64,
    /// Time constant over which each camera's persistent image offset is learnt from the fused
    /// skeleton and taken out of its views (`perception::view_offset`); 0 = off.
    view_offset_time_constant_s: f64,
    /// RULA on each frame's mean over ± this many seconds in place of the causal filter, every
    /// score and warning that much later (`perception::fixed_lag`); 0 = off: the causal filter.
    fixed_lag_s: f64,
}

impl Default for PipelineFile {
    fn default() -> Self {
        let f = OneEuroParams::default();
        let p = ReconstructionConfig::default();
        Self {
            fusion: FusionName::Default,
            filter: true,
            filter_min_cutoff_hz: f.min_cutoff_hz,
            filter_beta_per_m: f.beta,
            filter_derivative_cutoff_hz: f.derivative_cutoff_hz,
            filter_max_gap_s: f.max_gap_nanos as f64 * 1e-9,
            min_tracked_landmarks: p.min_tracked_landmarks,
            assembly_tolerance_s: p.assembly_tolerance_nanos as f64 * 1e-9,
            assembly_max_wait_s: p.assembly_max_wait_nanos as f64 * 1e-9,
            operator_gate_radius_m: OPERATOR_GATE_RADIUS_M,
            operator_gate_memory_s: 1.0,
            operator_gate_torso_height_m: 1.1,
            view_offset_time_constant_s: p
                .view_offsets
                .map_or(0.0, |v| v.time_constant_nanos as f64 * 1e-9),
            fixed_lag_s: crate::pipeline::DEFAULT_FIXED_LAG_S,
        }
    }
}

/// The default operator gate: a bystander 1.2 m from the operator is outside it from every camera of
/// the twin's ring, a torso moves far less between two frames (10 Hz), and a floor pick moves the
/// torso ≈ 0.4 m from its standing place only over a second or more (`sim/tests/bystander.rs`).
pub const OPERATOR_GATE_RADIUS_M: f64 = 0.5;

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct AssessmentFile {
    floor_height_m: Option<f64>,
    min_confidence: f64,
    smoothing_window_s: f64,
    thresholds: Thresholds,
    muscle: MuscleFile,
}

impl Default for AssessmentFile {
    fn default() -> Self {
        let up = UpVector::z();
        let a = AssessmentConfig::new(up);
        Self {
            floor_height_m: a.floor_height_m,
            min_confidence: a.min_confidence,
            smoothing_window_s: a.smoothing_window_nanos as f64 * 1e-9,
            thresholds: a.thresholds,
            muscle: MuscleFile::default(),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct MuscleFile {
    hold_s: f64,
    window_s: f64,
    min_repetitions: usize,
    min_excursion_s: f64,
    min_return_s: f64,
}

impl Default for MuscleFile {
    fn default() -> Self {
        let m = MuscleUseConfig::default();
        Self {
            hold_s: m.hold_nanos as f64 * 1e-9,
            window_s: m.window_nanos as f64 * 1e-9,
            min_repetitions: m.min_repetitions,
            min_excursion_s: m.min_excursion_nanos as f64 * 1e-9,
            min_return_s: m.min_return_nanos as f64 * 1e-9,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct WarningsFile {
    hysteresis_rad: f64,
    rise_margin_rad: f64,
    dwell_s: f64,
    warn_at: [u8; 6],
}

impl Default for WarningsFile {
    fn default() -> Self {
        let w = WarningConfig::default();
        Self {
            hysteresis_rad: w.hysteresis_rad,
            rise_margin_rad: w.rise_margin_rad,
            dwell_s: w.dwell_nanos as f64 * 1e-9,
            warn_at: w.warn_at,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct HeightFile {
    c1_below_m: f64,
    c2_up_to_m: f64,
    floor_height_m: Option<f64>,
    upright_max_knee_flexion_rad: f64,
    upright_max_hip_flexion_rad: f64,
    upright_max_trunk_tilt_rad: f64,
    upright_max_neck_flexion_rad: f64,
    min_frames: usize,
    decision_sigmas: f64,
    window_frames: usize,
    /// The ear landmark's offset from the tragion, measured by `ergocell height calibrate`
    /// (all three keys together, or none: uncalibrated).
    ear_offset_m: Option<f64>,
    ear_offset_sigma_m: Option<f64>,
    ear_offset_sessions: Option<usize>,
}

impl HeightFile {
    /// The configured ear offset: calibrated when the three keys are given, the default otherwise.
    fn ear_offset(&self) -> Result<EarOffset, String> {
        match (
            self.ear_offset_m,
            self.ear_offset_sigma_m,
            self.ear_offset_sessions,
        ) {
            (None, None, None) => Ok(EarOffset::default()),
            (Some(offset), Some(sigma), Some(sessions)) => {
                if sessions < MIN_CALIBRATION_SESSIONS {
                    return Err(format!(
                        "height.ear_offset_sessions = {sessions}: a calibration needs at least \
                         {MIN_CALIBRATION_SESSIONS} sessions (`ergocell height calibrate`)"
                    ));
                }
                EarOffset::calibrated(offset, sigma, sessions).map_err(|e| e.to_string())
            }
            _ => Err("height.ear_offset_m, height.ear_offset_sigma_m and \
                      height.ear_offset_sessions go together (`ergocell height calibrate` writes \
                      all three)"
                .to_owned()),
        }
    }
}

impl Default for HeightFile {
    fn default() -> Self {
        let h = HeightConfig::new(UpVector::z());
        Self {
            c1_below_m: h.thresholds.c1_below_m(),
            c2_up_to_m: h.thresholds.c2_up_to_m(),
            floor_height_m: h.floor_height_m,
            upright_max_knee_flexion_rad: h.upright_max_knee_flexion_rad,
            upright_max_hip_flexion_rad: h.upright_max_hip_flexion_rad,
            upright_max_trunk_tilt_rad: h.upright_max_trunk_tilt_rad,
            upright_max_neck_flexion_rad: h.upright_max_neck_flexion_rad,
            min_frames: h.min_frames,
            decision_sigmas: h.decision_sigmas,
            window_frames: h.window_frames,
            ear_offset_m: None,
            ear_offset_sigma_m: None,
            ear_offset_sessions: None,
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;

    const SHIPPED: &str = include_str!("../../config/cell.toml");

    #[test]
    fn the_shipped_file_gives_every_default() {
        let s = CellSettings::from_toml_str(SHIPPED, "config/cell.toml").unwrap();
        let up = UpVector::z();
        let mut p = s.pipeline(up).unwrap();
        let d = PipelineConfig::new(up);
        // the one difference: the cell gates the views of someone else by the station, which a bare
        // pipeline (triangulate, the experiments) has no station for
        let zone = p.reconstruction.operator_zone.take().unwrap();
        assert_eq!(
            zone,
            OperatorZone {
                station_torso_world: nalgebra::Point3::new(0.0, 0.0, 1.1),
                radius_m: OPERATOR_GATE_RADIUS_M,
                memory_nanos: 1_000_000_000,
            }
        );
        assert_eq!(p, d);
        assert_eq!(s.session, SessionConfig::default());
        assert_eq!(s, CellSettings::default());
    }

    #[test]
    fn a_typo_in_a_key_is_refused_with_its_name_and_the_file() {
        let text = SHIPPED.replace(
            "\n[station]\n",
            "\n[session]\nexit_radius = 1.5\n\n[station]\n",
        );
        let e = CellSettings::from_toml_str(&text, "my/cell.toml")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("my/cell.toml"), "{e}");
        assert!(e.contains("exit_radius"), "{e}");
        assert!(
            e.contains("exit_radius_m"),
            "the valid keys are listed: {e}"
        );
        // A typo'd table is refused too.
        let text = format!("{SHIPPED}\n[sesion]\nexit_radius_m = 1.5\n");
        let e = CellSettings::from_toml_str(&text, "my/cell.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("sesion"), "{e}");
    }

    #[test]
    fn a_bad_value_is_refused_naming_key_and_value() {
        for (table, bad, key) in [
            (
                "[session]\nexit_radius_m = -1.0",
                "-1",
                "session.exit_radius_m",
            ),
            (
                "[warnings]\ndwell_s = 2000000000",
                "2000000000",
                "warnings.dwell_s",
            ),
            ("[height]\nc1_below_m = 168.0", "168", "height.c1_below_m"),
            (
                "[task]\nforce_load_score_arm_wrist = 7",
                "7",
                "task.force_load_score_arm_wrist",
            ),
            ("[pipeline]\nfusion = \"best\"", "best", "fusion"),
            (
                "[pipeline]\nfixed_lag_s = -0.5",
                "-0.5",
                "pipeline.fixed_lag_s",
            ),
            (
                "[pipeline]\nfixed_lag_s = 90.0",
                "90",
                "pipeline.fixed_lag_s",
            ),
            (
                "[session]\ntake_radius_m = 0.3\nrelease_radius_m = 0.2",
                "0.2",
                "session.release_radius_m",
            ),
            (
                "[session]\nnext_part_after_s = -1",
                "-1",
                "session.next_part_after_s",
            ),
        ] {
            let text = SHIPPED.replace("\n[station]\n", &format!("\n{table}\n\n[station]\n"));
            let e = CellSettings::from_toml_str(&text, "cell.toml")
                .unwrap_err()
                .to_string();
            assert!(e.contains(key) && e.contains(bad), "{table}: {e}");
        }
    }

    #[test]
    fn a_turned_and_moved_station_puts_the_handover_point_in_one_place() {
        // Turned 0.3 rad about the vertical and shifted 0.2 m: the session's station pose and the
        // robot side's agree, and the point 0.6 m forward of the station lies along the turned
        // forward axis.
        let text = SHIPPED
            .replace("xyz_m = [0.0, 0.0, 0.0]", "xyz_m = [0.2, 0.0, 0.0]")
            .replace("yaw_rad = 0.0", "yaw_rad = 0.3");
        let s = CellSettings::from_toml_str(&text, "cell.toml").unwrap();
        let robot_side = ergocell_robot::CellConfig::from_toml_str(&text).unwrap();
        let station_m = [0.6, 0.1, 1.1];
        let session_side = ergocell_robot::handover_world(&s.session.T_world_station, station_m);
        assert!((session_side - robot_side.handover_world(station_m)).norm() < 1e-12);
        let (c, sn) = (0.3f64.cos(), 0.3f64.sin());
        let expected = nalgebra::Point3::new(0.2 + 0.6 * c - 0.1 * sn, 0.6 * sn + 0.1 * c, 1.1);
        assert!((session_side - expected).norm() < 1e-12, "{session_side}");
    }

    #[test]
    fn values_reach_the_configs_in_si_units() {
        let text = SHIPPED
            .replace(
                "\n[station]\n",
                "\n[session]\ncamera_stale_s = 0.25\nexit_radius_m = 1.5\n\n\
                 [warnings]\ndwell_s = 1.0\n\n[height]\nc1_below_m = 1.65\n\n\
                 [assessment]\nsmoothing_window_s = 0\n\n[station]\n",
            )
            .replace("xyz_m = [0.0, 0.0, 0.0]", "xyz_m = [0.3, -0.2, 0.0]");
        let s = CellSettings::from_toml_str(&text, "cell.toml").unwrap();
        assert_eq!(s.session.camera_stale_nanos, 250_000_000);
        // The station's pose places the lock's handover point (station frame) in the world.
        let p = s.session.T_world_station * nalgebra::Point3::new(0.4, 0.1, 1.0);
        assert!(
            (p - nalgebra::Point3::new(0.7, -0.1, 1.0)).norm() < 1e-12,
            "{p}"
        );
        assert_eq!(s.session.exit_radius_m, 1.5);
        assert_eq!(s.session.station_xy_m, [0.3, -0.2]);
        let p = s.pipeline(UpVector::z()).unwrap();
        assert_eq!(p.warnings.dwell_nanos, 1_000_000_000);
        assert_eq!(p.height.thresholds.c1_below_m(), 1.65);
        assert_eq!(p.assessment.smoothing_window_nanos, 0);
        // the fixed lag by default; 0 turns it off, another value sets it
        assert_eq!(p.fixed_lag_s, Some(0.55));
        for (value, lag) in [("0", None), ("0.3", Some(0.3))] {
            let text = SHIPPED.replace(
                "\n[station]\n",
                &format!("\n[pipeline]\nfixed_lag_s = {value}\n\n[station]\n"),
            );
            let s = CellSettings::from_toml_str(&text, "cell.toml").unwrap();
            assert_eq!(s.pipeline(UpVector::z()).unwrap().fixed_lag_s, lag);
        }
    }

    #[test]
    fn a_calibrated_ear_offset_is_read_whole_or_refused() {
        let with = |keys: &str| format!("{SHIPPED}\n[height]\n{keys}\n");
        let s = CellSettings::from_toml_str(
            &with("ear_offset_m = 0.012\near_offset_sigma_m = 0.004\near_offset_sessions = 5"),
            "cell.toml",
        )
        .unwrap();
        let o = s.pipeline(UpVector::z()).unwrap().height.ear_offset;
        assert_eq!(
            (o.offset_m, o.sigma_m, o.calibrated_sessions),
            (0.012, 0.004, Some(5))
        );
        // Uncalibrated by default.
        let d = CellSettings::from_toml_str(SHIPPED, "cell.toml").unwrap();
        assert_eq!(
            d.pipeline(UpVector::z())
                .unwrap()
                .height
                .ear_offset
                .calibrated_sessions,
            None
        );
        for (keys, why) in [
            ("ear_offset_m = 0.012", "go together"),
            (
                "ear_offset_m = 0.012\near_offset_sigma_m = 0.004\near_offset_sessions = 3",
                "at least 5",
            ),
            (
                "ear_offset_m = 12.0\near_offset_sigma_m = 0.004\near_offset_sessions = 5",
                "ear_offset_m",
            ),
            (
                "ear_offset_m = 0.01\near_offset_sigma_m = -1.0\near_offset_sessions = 5",
                "ear_offset_sigma_m",
            ),
        ] {
            let e = CellSettings::from_toml_str(&with(keys), "cell.toml").unwrap_err();
            assert!(e.to_string().contains(why), "{keys}: {e}");
        }
    }
}
