//! Frame-by-frame RULA for both sides, from the fused skeleton.
//!
//! [`RulaAssessor::assess`] takes one [`Skeleton3`] at a time (in time order) and returns a
//! [`FrameAssessment`]: the angles, and per side the worksheet that was scored, its breakdown, where
//! every input came from ([`InputSource`]) and whether the score is uncertain.
//!
//! - **Observed** inputs come from the landmarks of this frame ([`crate::angles`]); thresholds that turn
//!   angles into the worksheet's yes/no adjustments are in [`Thresholds`] (RULA gives none; ours are
//!   documented there).
//! - **Configured** inputs come from [`TaskConfig`]: force/load, wrist twist (cameras cannot see
//!   pronation), arm supported/leaning and seated-and-supported.
//! - **Smoothed**: the angles on short baselines (wrist, and those behind the yes/no adjustments)
//!   are scored as their median over the last [`AssessmentConfig::smoothing_window_nanos`]
//!   ([`AngleSmoother`]); [`FrameAssessment::angles`] are the angles as scored.
//! - **Time-series** input: muscle use, from [`MuscleUseTracker`] (posture held > 1 min, or an action
//!   repeated ≥ 4 times a minute), driven by the frames' `stamp_nanos` — never by a wall clock.
//! - **Held**: when a landmark is missing in this frame, the last observed value is used and the score
//!   is marked uncertain. With nothing to hold, a yes/no adjustment is scored as not present and the
//!   score is marked uncertain; a side without its upper arm or elbow angle (shoulder, elbow, wrist)
//!   is not scored (`None`, with the reason in [`FrameAssessment::unscored_reasons`]): "no score" is
//!   never presented as "safe".
//! - **Conservative**: the wrist's flexion needs the hand (index and pinky), which most 2D keypoint
//!   layouts in use do not have (OpenPose BODY_25 and BODY_25B, COCO-17, HALPE-26; see
//!   `ergocell_perception::detections::KeypointFormat`). A wrist that was never observed does not
//!   leave the side unscored: it is scored at the top flexion band, [`UNOBSERVED_WRIST_FLEXION_DEG`]
//!   (wrist score 3, the rule and its reasons are there), the input's source is
//!   [`InputSource::Conservative`], the score is uncertain and the reason says so.
//! - Low tracking confidence (any landmark used below [`AssessmentConfig::min_confidence`]) marks the
//!   score **uncertain**; it never changes (and so never lowers) the score.

use crate::confidence::{region_confidences, ConfidenceModel, RegionConfidences};
use std::collections::VecDeque;

use ergocell_skeleton::{Landmark, Skeleton3};
use serde::{Deserialize, Serialize};

use crate::activity::{Activity, ActivityConfig, ActivityTracker};
use crate::angles::{
    arm_landmarks, body_angles, BodyAngles, LegsObservation, SideAngles, UpVector,
};
use crate::height::median;
use crate::reba::{Coupling, RebaInput, RebaScores, MAX_LOAD_KG};
use crate::rula::{
    neck_band, score_worksheet, trunk_band, upper_arm_band, RulaInput, RulaScores, ScoringNote,
    WristTwist, WRIST_EDGES_DEG,
};
use crate::{ErgonomicsError, Side};

/// What the task is, as far as the cameras cannot tell.
// The worksheets' yes/no boxes are the methods'; they stay booleans in the public config format.
#[allow(clippy::struct_excessive_bools)]
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TaskConfig {
    /// RULA step 7, 0..=3.
    pub force_load_score_arm_wrist: u8,
    /// RULA step 13, 0..=3.
    pub force_load_score_neck_trunk_legs: u8,
    pub wrist_twist: WristTwist,
    pub arm_supported_or_leaning: bool,
    pub seated_well_supported: bool,
    /// The operator works seated (REBA's legs: sitting, no knee adjustment). RULA's
    /// `seated_well_supported` implies it.
    pub seated: bool,
    /// REBA's load, kilograms (its Score A adds 0 below 5 kg, 1 up to 10 kg, 2 above).
    pub reba_load_kg: f64,
    /// REBA: shock or rapid build-up of force (+1 on the load score).
    pub reba_load_shock_or_rapid_build_up: bool,
    /// REBA: how well the hand holds the load.
    pub reba_coupling: Coupling,
    /// REBA's third activity box: rapid large-range changes of posture or an unstable base (+1). The
    /// other two (static, repeated) come from the time series, as RULA's muscle use does.
    pub reba_rapid_changes_or_unstable_base: bool,
}

impl Default for TaskConfig {
    fn default() -> Self {
        Self {
            force_load_score_arm_wrist: 0,
            force_load_score_neck_trunk_legs: 0,
            wrist_twist: WristTwist::MidRange,
            arm_supported_or_leaning: false,
            seated_well_supported: false,
            seated: false,
            reba_load_kg: 0.0,
            reba_load_shock_or_rapid_build_up: false,
            reba_coupling: Coupling::Good,
            reba_rapid_changes_or_unstable_base: false,
        }
    }
}

/// Thresholds that turn measured angles into the worksheet's yes/no adjustments. RULA states none;
/// these defaults are ergocell's, chosen at about half a RULA band so that noise of a few degrees does
/// not toggle them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Thresholds {
    /// Upper arm abducted when its abduction exceeds this (default 20°).
    pub abduction_rad: f64,
    /// Shoulder raised when the shoulder-to-ear distance over the shoulder width falls below this
    /// (default 0.48; neutral adults are near 0.55 on Drillis & Contini geometry, a 5 cm shrug ≈ 0.47).
    pub shoulder_raise_ratio_below: f64,
    /// Lower arm out to the side when the wrist is this many shoulder widths outside the shoulder
    /// (default 0.5).
    pub out_to_side_shoulder_widths: f64,
    /// Wrist bent from the midline when |deviation| exceeds this (default 10°).
    pub wrist_deviation_rad: f64,
    /// Neck twisted when |twist| exceeds this (default 10°).
    pub neck_twist_rad: f64,
    /// Neck side-bending when the side bend exceeds this (default 10°).
    pub neck_side_bend_rad: f64,
    /// Trunk twisted when |twist| exceeds this (default 10°).
    pub trunk_twist_rad: f64,
    /// Trunk side-bending when |side bend| exceeds this (default 10°).
    pub trunk_side_bend_rad: f64,
    /// A foot is on the floor when its lowest point is within this of the floor (default 0.05 m).
    pub foot_on_floor_m: f64,
    /// Weight balanced when the hips are within this weight offset (0 centred, 1 over one foot;
    /// default 0.5).
    pub weight_offset_max: f64,
}

impl Default for Thresholds {
    fn default() -> Self {
        Self {
            abduction_rad: 20f64.to_radians(),
            shoulder_raise_ratio_below: 0.48,
            out_to_side_shoulder_widths: 0.5,
            wrist_deviation_rad: 10f64.to_radians(),
            neck_twist_rad: 10f64.to_radians(),
            neck_side_bend_rad: 10f64.to_radians(),
            trunk_twist_rad: 10f64.to_radians(),
            trunk_side_bend_rad: 10f64.to_radians(),
            foot_on_floor_m: 0.05,
            weight_offset_max: 0.5,
        }
    }
}

/// How muscle use is derived from the time series (RULA step 6/13).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MuscleUseConfig {
    /// Out of the relaxed posture (without returning to it) longer than this is static (default 60 s).
    pub hold_nanos: i64,
    /// Window over which repetitions are counted (default 60 s).
    pub window_nanos: i64,
    /// Repetitions within the window that count as repeated (default 4).
    pub min_repetitions: usize,
    /// An excursion out of the relaxed posture counts once it lasted this long (default 0.8 s),
    /// so that noise at the relaxed limit is not counted as repetitions: RULA's repeated action is
    /// work done out of the relaxed posture, not a glance across its limit. Chosen on the twin's
    /// seeds 1–20 with [`Self::min_return_nanos`] (from 0.3 s and no return time): under the task
    /// mix and the detector fitted to real MediaPipe data grand-score κ went from 0.814 to 0.845
    /// (mean; κ > 0.84 on 3 → 12 seeds), most of the gain in group B's muscle use; on handovers
    /// alone at 3 px from 0.889 to 0.899 (18 → 19 seeds), and with the detector fitted to real
    /// data from 0.888 to 0.884 (18 → 17 seeds): the trade chosen for the task mix, where the
    /// operator's posture crosses the limits in earnest. At 1 s the handovers' own reaches, about a
    /// second above the limit, fell either side of it: 16 seeds at 3 px.
    pub min_excursion_nanos: i64,
    /// An excursion ends once the relaxed posture lasted this long (default 1 s): a return shorter
    /// than this (an angle wandering back across the relaxed limit for a moment) neither restarts
    /// the hold clock nor lets the next frame out count as a new repetition.
    pub min_return_nanos: i64,
}

impl Default for MuscleUseConfig {
    fn default() -> Self {
        Self {
            hold_nanos: 60_000_000_000,
            window_nanos: 60_000_000_000,
            min_repetitions: 4,
            min_excursion_nanos: 800_000_000,
            min_return_nanos: 1_000_000_000,
        }
    }
}

/// Everything the assessor needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AssessmentConfig {
    /// The world's up (from the cell config).
    pub up: UpVector,
    /// Floor height along `up`, metres; `None` = use the lowest foot landmark of each frame.
    pub floor_height_m: Option<f64>,
    /// Landmarks below this confidence make a score uncertain (default 0.5).
    pub min_confidence: f64,
    pub thresholds: Thresholds,
    pub task: TaskConfig,
    pub muscle: MuscleUseConfig,
    /// Each angle is scored as the median of its observations over this trailing window (default
    /// 0.5 s; 0 = this frame only). See [`AngleSmoother`].
    pub smoothing_window_nanos: i64,
    /// How the stated spread of each region's angle follows from the fused skeleton's
    /// ([`crate::confidence`]).
    pub confidence: ConfidenceModel,
}

impl AssessmentConfig {
    /// Defaults for everything but the up vector, which must always be given.
    pub fn new(up: UpVector) -> Self {
        Self {
            up,
            floor_height_m: None,
            min_confidence: 0.5,
            thresholds: Thresholds::default(),
            task: TaskConfig::default(),
            muscle: MuscleUseConfig::default(),
            smoothing_window_nanos: DEFAULT_SMOOTHING_WINDOW_NANOS,
            confidence: ConfidenceModel::default(),
        }
    }
}

/// Default of [`AssessmentConfig::smoothing_window_nanos`]: 0.5 s.
pub const DEFAULT_SMOOTHING_WINDOW_NANOS: i64 = 500_000_000;

/// Accessors of the angles [`AngleSmoother`] smooths: those behind ergocell's yes/no adjustments
/// (side bends, twists, abduction, shoulder raise, wrist deviation) and the wrist's flexion, all
/// measured on short baselines. The angles that move with the task — trunk and neck flexion, upper
/// arm, elbow, the wrist's lateral offset — are scored as observed: on the simulator a median of
/// them lags a reach or a glance by more than it removes noise.
/// Accessor of one field of [`BodyAngles`].
pub type AngleField = fn(&mut BodyAngles) -> &mut Option<f64>;
pub const SMOOTHED_FIELDS: [AngleField; 12] = [
    |a| &mut a.trunk_side_bend_rad,
    |a| &mut a.trunk_twist_rad,
    |a| &mut a.neck_side_bend_rad,
    |a| &mut a.neck_twist_rad,
    |a| &mut a.left.upper_arm_abduction_rad,
    |a| &mut a.left.shoulder_raise_ratio,
    |a| &mut a.left.wrist_flexion_rad,
    |a| &mut a.left.wrist_deviation_rad,
    |a| &mut a.right.upper_arm_abduction_rad,
    |a| &mut a.right.shoulder_raise_ratio,
    |a| &mut a.right.wrist_flexion_rad,
    |a| &mut a.right.wrist_deviation_rad,
];

/// A causal running median of each angle over a trailing time window (by the frames' stamps, never a
/// wall clock).
///
/// Several angles hang on short landmark baselines: the wrist's deviation and flexion on index and
/// pinky a few centimetres from the wrist, the neck's twist and side bend on the face. Per frame,
/// detector noise of a few pixels moves them by several degrees and flips ergocell's 10° thresholds
/// (and the wrist's 15° band edge) from one frame to the next. A median over the last `window_nanos`
/// (0.5 s by default: 5 frames at 10 Hz, 15 at 30 Hz) removes that frame-to-frame noise and single
/// bad frames, and follows a real change of posture within half a window. Applied per angle (see
/// [`SMOOTHED_FIELDS`]) to its observed values only: a missing value is not smoothed into existence
/// (holding is the assessor's job, and marks the score uncertain).
#[derive(Debug, Clone, Default)]
pub struct AngleSmoother {
    window_nanos: i64,
    history: VecDeque<(i64, BodyAngles)>,
}

impl AngleSmoother {
    /// `window_nanos ≤ 0` passes every frame through unchanged.
    pub fn new(window_nanos: i64) -> Self {
        Self {
            window_nanos: window_nanos.max(0),
            history: VecDeque::new(),
        }
    }

    /// Adds this frame's angles (stamps in time order) and returns them with every smoothed angle
    /// replaced by the median of its observations within the window ending at `stamp_nanos`.
    pub fn push(&mut self, stamp_nanos: i64, angles: &BodyAngles) -> BodyAngles {
        if self.window_nanos == 0 {
            return *angles;
        }
        self.history.push_back((stamp_nanos, *angles));
        while self
            .history
            .front()
            .is_some_and(|(t, _)| stamp_nanos.saturating_sub(*t) >= self.window_nanos)
        {
            self.history.pop_front();
        }
        let mut out = *angles;
        let mut values = Vec::with_capacity(self.history.len());
        for field in SMOOTHED_FIELDS {
            if field(&mut out).is_none() {
                continue;
            }
            values.clear();
            values.extend(
                self.history
                    .iter()
                    .filter_map(|(_, a)| *field(&mut a.clone())),
            );
            *field(&mut out) = median(&mut values);
        }
        out
    }
}

/// Muscle use from the time series: static (out of the relaxed posture, without returning to it, for
/// longer than the hold time) or repeated (at least `min_repetitions` excursions out of the relaxed
/// posture within the window).
///
/// A relaxed posture held still (arm within 20° of hanging; neck and trunk within 20° of upright —
/// forwards or back, since RULA's trunk extension scores as erect and a neck a few degrees back is no
/// effort) is not counted as static loading. Band changes while out of the relaxed posture (an angle jittering
/// across a band edge, or work moving between bands) do not restart the hold clock: only a return
/// to the relaxed posture that lasts [`MuscleUseConfig::min_return_nanos`] does. Otherwise
/// measurement noise at any band edge, or an angle wandering back across the relaxed limit for a
/// moment, would hide a posture held for minutes or count one excursion as several.
#[derive(Debug, Clone)]
pub struct MuscleUseTracker {
    config: MuscleUseConfig,
    last_stamp: Option<i64>,
    excursion_since: Option<i64>,
    excursion_counted: bool,
    /// Since when the posture has been relaxed during an excursion (the return not yet long enough).
    returning_since: Option<i64>,
    onsets: VecDeque<i64>,
}

/// The tracker's verdict for one frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct MuscleUse {
    pub static_hold: bool,
    pub repeated: bool,
    /// Excursions counted in the current window.
    pub repetitions_in_window: usize,
}

impl MuscleUse {
    /// RULA's +1.
    pub fn applies(&self) -> bool {
        self.static_hold || self.repeated
    }
}

impl MuscleUseTracker {
    pub fn new(config: MuscleUseConfig) -> Self {
        Self {
            config,
            last_stamp: None,
            excursion_since: None,
            excursion_counted: false,
            returning_since: None,
            onsets: VecDeque::new(),
        }
    }

    /// Feeds one frame: `relaxed` says whether the posture is the relaxed one.
    pub fn update(
        &mut self,
        stamp_nanos: i64,
        relaxed: bool,
    ) -> Result<MuscleUse, ErgonomicsError> {
        if let Some(previous) = self.last_stamp {
            if stamp_nanos < previous {
                return Err(ErgonomicsError::TimeWentBackwards {
                    previous,
                    got: stamp_nanos,
                });
            }
        }
        self.last_stamp = Some(stamp_nanos);
        let static_hold = match (relaxed, self.excursion_since) {
            (true, None) => false,
            (true, Some(since)) => {
                // Still within the excursion until the return has lasted.
                let back = *self.returning_since.get_or_insert(stamp_nanos);
                if stamp_nanos.saturating_sub(back) >= self.config.min_return_nanos {
                    self.excursion_since = None;
                    self.excursion_counted = false;
                    self.returning_since = None;
                    false
                } else {
                    back.saturating_sub(since) > self.config.hold_nanos
                }
            }
            (false, _) => {
                self.returning_since = None;
                let since = *self.excursion_since.get_or_insert(stamp_nanos);
                if !self.excursion_counted
                    && stamp_nanos.saturating_sub(since) >= self.config.min_excursion_nanos
                {
                    self.onsets.push_back(since);
                    self.excursion_counted = true;
                }
                stamp_nanos.saturating_sub(since) > self.config.hold_nanos
            }
        };
        let oldest = stamp_nanos.saturating_sub(self.config.window_nanos);
        while self.onsets.front().is_some_and(|&t| t < oldest) {
            self.onsets.pop_front();
        }
        let n = self.onsets.len();
        Ok(MuscleUse {
            static_hold,
            repeated: n >= self.config.min_repetitions,
            repetitions_in_window: n,
        })
    }
}

/// Where a worksheet input came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InputSource {
    /// Measured from this frame's landmarks.
    Observed,
    /// Measured earlier; this frame lacked the landmarks.
    Held,
    /// Never observed; scored as "not present" (the score is uncertain).
    NotObserved,
    /// Never observed, and an angle has no "not present": scored at the worksheet band that cannot
    /// understate it (the score is uncertain). Only the wrist's flexion, see
    /// [`UNOBSERVED_WRIST_FLEXION_DEG`].
    Conservative,
    /// From the task config.
    Configured,
    /// From the time series of frames (muscle use).
    TimeSeries,
}

/// The source of each worksheet input, in [`RulaInput::FIELDS`] order.
pub type InputSources = [(&'static str, InputSource); 21];

/// The wrist flexion, degrees, at which a wrist that was never observed is scored: 15°, the lower edge
/// of RULA's top wrist band, so step 3 gives it **wrist score 3** ("15° or more, flexion or
/// extension"; McAtamney & Corlett, Applied Ergonomics 24(2), 1993, step 3; ergocell's band-edge
/// convention puts 15° in the higher band, see [`crate::rula`]). Its source is
/// [`InputSource::Conservative`].
///
/// The flexion needs the hand's index and pinky, which OpenPose BODY_25 and BODY_25B, COCO-17 and
/// HALPE-26 do not have; without this rule every frame of those layouts was left unscored. Why 15°:
/// - The flexion is an angle, and an angle has no "not present" to fall back on. Its lowest band
///   (score 1, exactly neutral) would present an unseen wrist as safe, which the assessor never does;
///   the top band is the worst the flexion can score, so the flexion part of the wrist score is never
///   understated.
/// - The radial/ulnar deviation (step 3's +1) is a yes/no adjustment, and the assessor scores every
///   adjustment it never observed as not present, marking the score uncertain (a neck twist without a
///   face, an abduction without an elbow). The wrist follows that rule: an unobserved wrist scores as
///   a wrist seen at 15° or more without deviation, 3, not the region's maximum 4 (a deviated wrist
///   is understated by that one point, as any unobserved adjustment is; the uncertain flag says so).
///   Assuming a deviation nobody saw would score every frame of these layouts at the wrist's worst.
/// - It counts in Table A and the grand score like an observed wrist, the side is marked uncertain
///   with the reason, and the wrist raises no posture warning ([`crate::warnings`]): a warning tells
///   the operator an angle and what to change, and nobody saw this one.
/// - A wrist observed earlier is held like any other input ([`InputSource::Held`]); this value is
///   only for a wrist with nothing to hold. When the hand is observed nothing changes.
pub const UNOBSERVED_WRIST_FLEXION_DEG: f64 = WRIST_EDGES_DEG[1];

/// The knee flexion, degrees, at which REBA scores knees that were never observed: beyond 60°, the
/// top knee band (+2 on the legs). As for the wrist ([`UNOBSERVED_WRIST_FLEXION_DEG`]), an unseen
/// angle is never scored as its safest band — occluded knees behind a bench are the common case, and
/// "straight" would lower the score; the REBA score is marked uncertain with the reason.
pub const UNOBSERVED_KNEE_FLEXION_DEG: f64 = 90.0;

/// One side's result for one frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SideAssessment {
    pub side: Side,
    /// The worksheet that was scored.
    pub input: RulaInput,
    pub scores: RulaScores,
    pub notes: Vec<ScoringNote>,
    pub sources: InputSources,
    pub muscle_use_arm_wrist: MuscleUse,
    pub muscle_use_neck_trunk_legs: MuscleUse,
    /// True when tracking confidence was low or inputs were held / not observed / scored
    /// conservatively. The score is still the full score: uncertain never means lower.
    pub uncertain: bool,
    pub uncertain_reasons: Vec<String>,
    /// REBA for the same side and frame, from the same angles (held, smoothed and sourced alike) plus
    /// the knees. See [`RebaAssessment`].
    pub reba: RebaAssessment,
    /// How sure each region's score is: its angle's stated spread and the probability that the
    /// band is right ([`crate::confidence`]).
    pub confidence: RegionConfidences,
    /// How far each yes/no adjustment's angle is past its threshold ([`AdjustmentMargins`]): for
    /// the warnings' rise margin. Derived from the angles; not serialised.
    #[serde(skip)]
    pub adjustment_margins: AdjustmentMargins,
}

/// How far the angle behind each of the worksheet's yes/no adjustments is past its threshold,
/// radians: positive when the adjustment applies, negative when it does not; `None` when the
/// angle was never observed (the adjustment is then scored as not present). The shoulder raise
/// (a ratio) and the forearm out to the side (shoulder widths) have no angle and are not listed.
///
/// An adjustment that applies by less than a degree is as likely measured not to apply: the
/// warnings rise only on adjustments past their threshold by the rise margin
/// ([`crate::warnings::WarningConfig::rise_margin_rad`]), as they do on the region's angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AdjustmentMargins {
    pub upper_arm_abducted: Option<f64>,
    pub wrist_bent_from_midline: Option<f64>,
    pub neck_twisted: Option<f64>,
    pub neck_side_bending: Option<f64>,
    pub trunk_twisted: Option<f64>,
    pub trunk_side_bending: Option<f64>,
}

impl AdjustmentMargins {
    /// `input` with each listed adjustment that applies by less than `margin_rad` set to not
    /// present; the others as they are.
    pub fn settled(&self, input: &RulaInput, margin_rad: f64) -> RulaInput {
        let keep =
            |applies: bool, past: Option<f64>| applies && past.is_none_or(|m| m >= margin_rad);
        RulaInput {
            upper_arm_abducted: keep(input.upper_arm_abducted, self.upper_arm_abducted),
            wrist_bent_from_midline: keep(
                input.wrist_bent_from_midline,
                self.wrist_bent_from_midline,
            ),
            neck_twisted: keep(input.neck_twisted, self.neck_twisted),
            neck_side_bending: keep(input.neck_side_bending, self.neck_side_bending),
            trunk_twisted: keep(input.trunk_twisted, self.trunk_twisted),
            trunk_side_bending: keep(input.trunk_side_bending, self.trunk_side_bending),
            ..*input
        }
    }
}

/// One side's REBA (Hignett & McAtamney 2000, [`crate::reba`]) beside its RULA, from the same
/// observations:
/// - trunk, neck, upper arm, elbow and wrist angles and the yes/no adjustments are RULA's inputs of
///   this frame ("twisted or side-bent" is either of RULA's two; the wrist's "deviated or twisted" is
///   RULA's bent-from-midline or a configured twist other than mid-range);
/// - legs: bilateral weight bearing is RULA's "legs supported and balanced" (both feet on the floor,
///   the hips over them), or walking ([`crate::activity`]), or seated (the task config's `seated`
///   or `seated_well_supported`); the knee flexion is the **more flexed knee** of the two (the
///   worksheet scores the legs once), held when missing like any angle and, when neither knee was
///   ever observed, scored beyond 60° ([`UNOBSERVED_KNEE_FLEXION_DEG`]) with the score uncertain;
/// - load, shock, coupling and "rapid changes or unstable base" from [`TaskConfig`];
/// - activity "static" (a part held > 1 min) and "repeated" (> 4 times a minute) from the same
///   time-series trackers as RULA's muscle use, either group A or B.
///
/// Uncertain when any input it uses is (RULA's reasons for those inputs, and the knees').
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RebaAssessment {
    pub input: RebaInput,
    pub scores: RebaScores,
    pub uncertain: bool,
    pub uncertain_reasons: Vec<String>,
}

impl SideAssessment {
    /// Where the worksheet input `field` (a [`RulaInput::FIELDS`] name) came from; `None` for an
    /// unknown name.
    pub fn source(&self, field: &str) -> Option<InputSource> {
        self.sources
            .iter()
            .find(|(name, _)| *name == field)
            .map(|(_, source)| *source)
    }
}

/// The angle values (degrees) at which an angle's RULA contribution changes, for drawing over its
/// distribution: the band edges of the worksheet ([`crate::rula`]) and the adjustment thresholds of
/// `thresholds` (± for the symmetric ones). `angle` is a joint-angle name as recorded —
/// `trunk_flexion`, `neck_twist`, `left_upper_arm_abduction`, … (a `left_`/`right_` prefix is
/// ignored). `None` for an unknown name.
pub fn score_edges_deg(angle: &str, thresholds: &Thresholds) -> Option<Vec<f64>> {
    use crate::rula::{
        LOWER_ARM_EDGES_DEG, NECK_EDGES_DEG, TRUNK_EDGES_DEG, UPPER_ARM_EDGES_DEG, WRIST_EDGES_DEG,
    };
    let name = angle
        .strip_prefix("left_")
        .or_else(|| angle.strip_prefix("right_"))
        .unwrap_or(angle);
    let sym = |rad: f64| vec![-rad.to_degrees(), rad.to_degrees()];
    Some(match name {
        "trunk_flexion" => TRUNK_EDGES_DEG.to_vec(),
        "trunk_side_bend" => sym(thresholds.trunk_side_bend_rad),
        "trunk_twist" => sym(thresholds.trunk_twist_rad),
        "neck_flexion" => NECK_EDGES_DEG.to_vec(),
        // Unsigned: either side is positive.
        "neck_side_bend" => vec![thresholds.neck_side_bend_rad.to_degrees()],
        "neck_twist" => sym(thresholds.neck_twist_rad),
        "upper_arm_flexion" => UPPER_ARM_EDGES_DEG.to_vec(),
        "upper_arm_abduction" => vec![thresholds.abduction_rad.to_degrees()],
        "elbow_flexion" => LOWER_ARM_EDGES_DEG.to_vec(),
        "wrist_flexion" => WRIST_EDGES_DEG.to_vec(),
        "wrist_deviation" => sym(thresholds.wrist_deviation_rad),
        _ => return None,
    })
}

/// Both sides of one frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameAssessment {
    pub stamp_nanos: i64,
    /// The angles as scored (after [`AngleSmoother`]).
    pub angles: BodyAngles,
    /// `None` when the side could not be scored at all (the reason is in `unscored_reasons`).
    pub left: Option<SideAssessment>,
    pub right: Option<SideAssessment>,
    pub unscored_reasons: Vec<String>,
}

impl FrameAssessment {
    /// One side.
    pub fn side(&self, side: Side) -> Option<&SideAssessment> {
        match side {
            Side::Left => self.left.as_ref(),
            Side::Right => self.right.as_ref(),
        }
    }

    /// The worse side (higher grand score; ties go to the uncertain one, then the right), the
    /// headline of the frame. See [`headline_side`].
    pub fn headline(&self) -> Option<&SideAssessment> {
        let key = |s: &SideAssessment| (s.scores.final_score, s.uncertain);
        headline_side(self.left.as_ref().map(key), self.right.as_ref().map(key))
            .and_then(|side| self.side(side))
    }
}

/// Which side is a frame's headline, from each scored side's `(grand score, uncertain)` (`None`: not
/// scored): the higher grand score; on a tie the uncertain side, then the right. The one rule for
/// [`FrameAssessment::headline`] and for summaries read back from a recording
/// ([`crate::summary`]).
pub fn headline_side(left: Option<(u8, bool)>, right: Option<(u8, bool)>) -> Option<Side> {
    match (left, right) {
        (Some(l), Some(r)) => Some(if l > r { Side::Left } else { Side::Right }),
        (Some(_), None) => Some(Side::Left),
        (None, Some(_)) => Some(Side::Right),
        (None, None) => None,
    }
}

/// Frame-by-frame RULA for both sides. Keeps the last observed angles (to hold over short gaps) and
/// the muscle-use trackers.
#[derive(Debug, Clone)]
pub struct RulaAssessor {
    config: AssessmentConfig,
    held: BodyAngles,
    muscle_a: [MuscleUseTracker; 2],
    muscle_b: MuscleUseTracker,
    smoother: AngleSmoother,
    last_stamp: Option<i64>,
    /// Per side (`[left, right]`), whether the upper arm currently counts as extended backwards
    /// (see [`UPPER_ARM_SIGN_BAND`]).
    arm_backward: [bool; 2],
    /// Walking, for REBA's legs.
    activity: ActivityTracker,
}

/// Hysteresis of the upper arm's flexion/extension sign, in units of
/// [`crate::SideAngles::upper_arm_backwardness`]: once counted as flexion, an arm counts as extension
/// only when its backwardness exceeds this, and back only below its negative — about ±10° of
/// direction around the back/side diagonal, where a hanging arm's sign otherwise flips with the
/// detector's noise. The score is the same either way below 45° of elevation; above it extension
/// scores lower, so starting from flexion never understates.
pub const UPPER_ARM_SIGN_BAND: f64 = 0.25;

const TRUNK_LANDMARKS: [Landmark; 4] = [
    Landmark::LeftHip,
    Landmark::RightHip,
    Landmark::LeftShoulder,
    Landmark::RightShoulder,
];
const HEAD_LANDMARKS: [Landmark; 3] = [Landmark::LeftEar, Landmark::RightEar, Landmark::Nose];
const FOOT_LANDMARKS: [Landmark; 6] = [
    Landmark::LeftAnkle,
    Landmark::RightAnkle,
    Landmark::LeftHeel,
    Landmark::RightHeel,
    Landmark::LeftFootIndex,
    Landmark::RightFootIndex,
];

/// Why a side's wrist was scored conservatively: the hand landmarks this frame lacks (none of them
/// ever observed, or the wrist would be held), and the score given.
fn unobserved_wrist_reason(skeleton: &Skeleton3, side: Side, wrist_score: u8) -> String {
    let [_, elbow, wrist, index, pinky, _] = arm_landmarks(side);
    let missing: Vec<String> = [elbow, wrist, index, pinky]
        .iter()
        .filter(|lm| skeleton.get(**lm).is_none())
        .map(ToString::to_string)
        .collect();
    let what = if missing.is_empty() {
        "hand landmarks degenerate (index and pinky on the forearm's line)".to_owned()
    } else {
        format!("no {}", missing.join(", "))
    };
    format!(
        "wrist_flexion_deg: wrist never observed ({what}; keypoint layouts without hand points, \
         e.g. OpenPose BODY_25/BODY_25B, COCO-17, HALPE-26, have no index or pinky): wrist scored \
         conservatively as {wrist_score} (flexion taken as {UNOBSERVED_WRIST_FLEXION_DEG}° or more, \
         RULA's top wrist band; deviation as not present)"
    )
}

/// "`lm` confidence 0.31 below 0.50" for each of `landmarks` observed below `min`.
fn low_confidence<'a>(
    skeleton: &'a Skeleton3,
    landmarks: impl IntoIterator<Item = &'a Landmark> + 'a,
    min: f64,
) -> impl Iterator<Item = String> + 'a {
    landmarks.into_iter().filter_map(move |lm| {
        let e = skeleton.get(*lm)?;
        (e.confidence < min).then(|| format!("{lm} confidence {:.2} below {min:.2}", e.confidence))
    })
}

fn merge(held: Option<f64>, now: Option<f64>) -> (Option<f64>, InputSource) {
    match (now, held) {
        (Some(v), _) => (Some(v), InputSource::Observed),
        (None, Some(v)) => (Some(v), InputSource::Held),
        (None, None) => (None, InputSource::NotObserved),
    }
}

impl RulaAssessor {
    pub fn new(config: AssessmentConfig) -> Result<Self, ErgonomicsError> {
        config.confidence.validate()?;
        for (field, v) in [
            (
                "task.force_load_score_arm_wrist",
                config.task.force_load_score_arm_wrist,
            ),
            (
                "task.force_load_score_neck_trunk_legs",
                config.task.force_load_score_neck_trunk_legs,
            ),
        ] {
            if v > 3 {
                return Err(ErgonomicsError::OutOfRange {
                    field,
                    value: f64::from(v),
                    min: 0.0,
                    max: 3.0,
                });
            }
        }
        let load = config.task.reba_load_kg;
        if !(0.0..=MAX_LOAD_KG).contains(&load) {
            return Err(ErgonomicsError::OutOfRange {
                field: "task.reba_load_kg",
                value: load,
                min: 0.0,
                max: MAX_LOAD_KG,
            });
        }
        if config.smoothing_window_nanos < 0 {
            return Err(ErgonomicsError::OutOfRange {
                field: "smoothing_window_nanos",
                value: config.smoothing_window_nanos as f64,
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        if !(0.0..=1.0).contains(&config.min_confidence) {
            return Err(ErgonomicsError::OutOfRange {
                field: "min_confidence",
                value: config.min_confidence,
                min: 0.0,
                max: 1.0,
            });
        }
        Ok(Self {
            config,
            held: BodyAngles::default(),
            muscle_a: [
                MuscleUseTracker::new(config.muscle),
                MuscleUseTracker::new(config.muscle),
            ],
            muscle_b: MuscleUseTracker::new(config.muscle),
            smoother: AngleSmoother::new(config.smoothing_window_nanos),
            last_stamp: None,
            arm_backward: [false; 2],
            activity: ActivityTracker::new(ActivityConfig::default(), &config.up)?,
        })
    }

    pub fn config(&self) -> &AssessmentConfig {
        &self.config
    }

    /// Scores one frame. Frames must come in time order.
    pub fn assess(&mut self, skeleton: &Skeleton3) -> Result<FrameAssessment, ErgonomicsError> {
        let stamp = skeleton.stamp_nanos;
        if let Some(previous) = self.last_stamp {
            if stamp < previous {
                return Err(ErgonomicsError::TimeWentBackwards {
                    previous,
                    got: stamp,
                });
            }
        }
        self.last_stamp = Some(stamp);
        let mut observed = body_angles(skeleton, &self.config.up, self.config.floor_height_m);
        for (side, backward) in [&mut observed.left, &mut observed.right]
            .into_iter()
            .zip(self.arm_backward.iter_mut())
        {
            let Some(flexion) = side.upper_arm_flexion_rad else {
                continue;
            };
            *backward = match side.upper_arm_backwardness {
                Some(m) if m > UPPER_ARM_SIGN_BAND => true,
                Some(m) if m < -UPPER_ARM_SIGN_BAND => false,
                Some(_) => *backward,
                // above shoulder level, straight down: as the frame says
                None => flexion < 0.0,
            };
            side.upper_arm_flexion_rad = Some(if *backward {
                -flexion.abs()
            } else {
                flexion.abs()
            });
        }
        let angles = self.smoother.push(stamp, &observed);
        let th = self.config.thresholds;
        let task = self.config.task;

        // Group B (shared by both sides).
        let (trunk, trunk_src) = merge(self.held.trunk_flexion_rad, angles.trunk_flexion_rad);
        let (trunk_tw, trunk_tw_src) = merge(self.held.trunk_twist_rad, angles.trunk_twist_rad);
        let (trunk_sb, trunk_sb_src) =
            merge(self.held.trunk_side_bend_rad, angles.trunk_side_bend_rad);
        let (neck, neck_src) = merge(self.held.neck_flexion_rad, angles.neck_flexion_rad);
        let (neck_tw, neck_tw_src) = merge(self.held.neck_twist_rad, angles.neck_twist_rad);
        let (neck_sb, neck_sb_src) = merge(self.held.neck_side_bend_rad, angles.neck_side_bend_rad);
        let (legs, legs_src) = match (angles.legs, self.held.legs) {
            (Some(l), _) => (Some(l), InputSource::Observed),
            (None, Some(l)) => (Some(l), InputSource::Held),
            (None, None) => (None, InputSource::NotObserved),
        };

        let mut unscored_reasons = Vec::new();
        let group_b = trunk
            .zip(neck)
            .map(|(t, n)| (t.to_degrees(), n.to_degrees()));
        if group_b.is_none() {
            unscored_reasons.push(format!(
                "{} never observed (needs hips, shoulders and both ears)",
                if trunk.is_none() { "trunk" } else { "neck" }
            ));
        }
        let muscle_b = match group_b {
            Some((t_deg, n_deg)) => {
                // Within 20° of upright, either way: a head held a few degrees back is relaxed
                // (RULA scores any extension 4, but that is the posture score, not muscle use).
                let nb = neck_band(n_deg.abs());
                let tb = trunk_band(t_deg, task.seated_well_supported);
                let relaxed = nb <= 2 && tb <= 2;
                Some(self.muscle_b.update(stamp, relaxed)?)
            }
            None => None,
        };

        // Standing: both feet on the floor and the hips over the feet. Seated (task config): the seat
        // carries the weight, so both feet on the floor is what "supported and balanced" asks.
        let legs_ok = legs.is_some_and(|l: LegsObservation| {
            l.left_foot_lift_m <= th.foot_on_floor_m
                && l.right_foot_lift_m <= th.foot_on_floor_m
                && (task.seated_well_supported || l.weight_offset <= th.weight_offset_max)
        });

        // REBA's knees: the more flexed of the two (each held when missing).
        let (knee_l, knee_l_src) = merge(
            self.held.left.knee_flexion_rad,
            angles.left.knee_flexion_rad,
        );
        let (knee_r, knee_r_src) = merge(
            self.held.right.knee_flexion_rad,
            angles.right.knee_flexion_rad,
        );
        let knee_reasons: Vec<String> = [("left", knee_l_src), ("right", knee_r_src)]
            .into_iter()
            .filter_map(|(side, src)| match src {
                InputSource::Held => Some(format!(
                    "{side}_knee_flexion: landmarks missing, last value held"
                )),
                InputSource::NotObserved => Some(format!(
                    "{side}_knee_flexion: never observed (needs hip, knee and ankle); with no knee seen, REBA scores them as flexed beyond 60° ({UNOBSERVED_KNEE_FLEXION_DEG}°)"
                )),
                _ => None,
            })
            .collect();
        let knee_deg = match (knee_l, knee_r) {
            (Some(l), Some(r)) => l.max(r).to_degrees(),
            (Some(k), None) | (None, Some(k)) => k.to_degrees(),
            (None, None) => UNOBSERVED_KNEE_FLEXION_DEG,
        };
        // REBA's legs score 1 for walking too (RULA's "supported and balanced" does not).
        let walking = self.activity.update(skeleton) == Some(Activity::Walking);

        let seated = task.seated || task.seated_well_supported;
        let mut out = FrameAssessment {
            stamp_nanos: stamp,
            angles,
            left: None,
            right: None,
            unscored_reasons: Vec::new(),
        };
        for side in Side::BOTH {
            let now = *angles.side(side);
            let held = *self.held.side(side);
            let (ua, ua_src) = merge(held.upper_arm_flexion_rad, now.upper_arm_flexion_rad);
            let (abd, abd_src) = merge(held.upper_arm_abduction_rad, now.upper_arm_abduction_rad);
            let (raise, raise_src) = merge(held.shoulder_raise_ratio, now.shoulder_raise_ratio);
            let (el, el_src) = merge(held.elbow_flexion_rad, now.elbow_flexion_rad);
            let (lat, lat_src) = merge(held.wrist_lateral_offset_m, now.wrist_lateral_offset_m);
            let (wf, wf_src) = merge(held.wrist_flexion_rad, now.wrist_flexion_rad);
            let (wd, wd_src) = merge(held.wrist_deviation_rad, now.wrist_deviation_rad);
            let (Some((t_deg, n_deg)), Some(ua), Some(el), Some(mb)) = (group_b, ua, el, muscle_b)
            else {
                if group_b.is_some() {
                    unscored_reasons.push(format!(
                        "{} arm never observed (needs shoulder, elbow and wrist)",
                        side.name()
                    ));
                }
                continue;
            };
            // Never observed: the top flexion band (see `UNOBSERVED_WRIST_FLEXION_DEG`).
            let (wf_deg, wf_src) = match wf {
                Some(wf) => (wf.to_degrees(), wf_src),
                None => (UNOBSERVED_WRIST_FLEXION_DEG, InputSource::Conservative),
            };
            let shoulder_width = angles
                .shoulder_width_m
                .or(self.held.shoulder_width_m)
                .unwrap_or(0.0);
            let out_limit = shoulder_width * (0.5 + th.out_to_side_shoulder_widths);
            let across_or_out = lat.is_some_and(|x| x < 0.0 || x > out_limit);
            let ua_deg = ua.to_degrees();
            let el_deg = el.to_degrees();
            let relaxed_a = upper_arm_band(ua_deg) == 1;
            let i = match side {
                Side::Left => 0,
                Side::Right => 1,
            };
            let ma = self.muscle_a[i].update(stamp, relaxed_a)?;
            let input = RulaInput {
                upper_arm_flexion_deg: ua_deg,
                shoulder_raised: raise.is_some_and(|r| r < th.shoulder_raise_ratio_below),
                upper_arm_abducted: abd.is_some_and(|a| a > th.abduction_rad),
                arm_supported_or_leaning: task.arm_supported_or_leaning,
                lower_arm_flexion_deg: el_deg,
                lower_arm_across_midline_or_out_to_side: across_or_out,
                wrist_flexion_deg: wf_deg,
                wrist_bent_from_midline: wd.is_some_and(|d| d.abs() > th.wrist_deviation_rad),
                wrist_twist: task.wrist_twist,
                muscle_use_arm_wrist: ma.applies(),
                force_load_score_arm_wrist: task.force_load_score_arm_wrist,
                neck_flexion_deg: n_deg,
                neck_twisted: neck_tw.is_some_and(|x| x.abs() > th.neck_twist_rad),
                neck_side_bending: neck_sb.is_some_and(|x| x > th.neck_side_bend_rad),
                trunk_flexion_deg: t_deg,
                trunk_seated_well_supported: task.seated_well_supported,
                trunk_twisted: trunk_tw.is_some_and(|x| x.abs() > th.trunk_twist_rad),
                trunk_side_bending: trunk_sb.is_some_and(|x| x.abs() > th.trunk_side_bend_rad),
                legs_supported_and_balanced: legs_ok,
                muscle_use_neck_trunk_legs: mb.applies(),
                force_load_score_neck_trunk_legs: task.force_load_score_neck_trunk_legs,
            };
            let result = score_worksheet(&input)?;
            let cfg = InputSource::Configured;
            let ts = InputSource::TimeSeries;
            let sources: InputSources = [
                ("upper_arm_flexion_deg", ua_src),
                ("shoulder_raised", raise_src),
                ("upper_arm_abducted", abd_src),
                ("arm_supported_or_leaning", cfg),
                ("lower_arm_flexion_deg", el_src),
                ("lower_arm_across_midline_or_out_to_side", lat_src),
                ("wrist_flexion_deg", wf_src),
                ("wrist_bent_from_midline", wd_src),
                ("wrist_twist", cfg),
                ("muscle_use_arm_wrist", ts),
                ("force_load_score_arm_wrist", cfg),
                ("neck_flexion_deg", neck_src),
                ("neck_twisted", neck_tw_src),
                ("neck_side_bending", neck_sb_src),
                ("trunk_flexion_deg", trunk_src),
                ("trunk_seated_well_supported", cfg),
                ("trunk_twisted", trunk_tw_src),
                ("trunk_side_bending", trunk_sb_src),
                ("legs_supported_and_balanced", legs_src),
                ("muscle_use_neck_trunk_legs", ts),
                ("force_load_score_neck_trunk_legs", cfg),
            ];
            let mut reasons: Vec<String> = sources
                .iter()
                .filter_map(|(name, src)| match src {
                    InputSource::Held => {
                        Some(format!("{name}: landmarks missing, last value held"))
                    }
                    InputSource::NotObserved => {
                        Some(format!("{name}: never observed, scored as not present"))
                    }
                    InputSource::Conservative => Some(unobserved_wrist_reason(
                        skeleton,
                        side,
                        result.scores.wrist_score,
                    )),
                    InputSource::Observed | InputSource::Configured | InputSource::TimeSeries => {
                        None
                    }
                })
                .collect();
            let arm = arm_landmarks(side);
            let used = TRUNK_LANDMARKS
                .iter()
                .chain(&HEAD_LANDMARKS)
                .chain(&FOOT_LANDMARKS)
                .chain(&arm);
            reasons.extend(low_confidence(skeleton, used, self.config.min_confidence));
            let reba_input = RebaInput {
                trunk_flexion_deg: t_deg,
                trunk_twisted_or_side_bent: input.trunk_twisted || input.trunk_side_bending,
                neck_flexion_deg: n_deg,
                neck_twisted_or_side_bent: input.neck_twisted || input.neck_side_bending,
                legs_bilateral_walking_or_sitting: legs_ok || walking || seated,
                seated,
                knee_flexion_deg: knee_deg,
                load_kg: task.reba_load_kg,
                load_shock_or_rapid_build_up: task.reba_load_shock_or_rapid_build_up,
                upper_arm_flexion_deg: ua_deg,
                upper_arm_abducted_or_rotated: input.upper_arm_abducted,
                shoulder_raised: input.shoulder_raised,
                arm_supported_or_leaning: task.arm_supported_or_leaning,
                lower_arm_flexion_deg: el_deg,
                wrist_flexion_deg: wf_deg,
                wrist_deviated_or_twisted: input.wrist_bent_from_midline
                    || task.wrist_twist != WristTwist::MidRange,
                coupling: task.reba_coupling,
                activity_static: ma.static_hold || mb.static_hold,
                activity_repeated: ma.repeated || mb.repeated,
                activity_rapid_change_or_unstable: task.reba_rapid_changes_or_unstable_base,
            };
            let reba_scores = crate::reba::score_worksheet(&reba_input)?;
            let mut reba_reasons: Vec<String> = reasons
                .iter()
                .filter(|r| !r.starts_with("lower_arm_across_midline_or_out_to_side"))
                .chain(&knee_reasons)
                .cloned()
                .collect();
            reba_reasons.extend(low_confidence(
                skeleton,
                &[Landmark::LeftKnee, Landmark::RightKnee],
                self.config.min_confidence,
            ));
            let reba = RebaAssessment {
                input: reba_input,
                scores: reba_scores,
                uncertain: !reba_reasons.is_empty(),
                uncertain_reasons: reba_reasons,
            };
            let mut assessment = SideAssessment {
                side,
                input,
                scores: result.scores,
                notes: result.notes,
                sources,
                muscle_use_arm_wrist: ma,
                muscle_use_neck_trunk_legs: mb,
                uncertain: !reasons.is_empty(),
                uncertain_reasons: reasons,
                reba,
                confidence: RegionConfidences::default(),
                adjustment_margins: AdjustmentMargins {
                    upper_arm_abducted: abd.map(|a| a - th.abduction_rad),
                    wrist_bent_from_midline: wd.map(|d| d.abs() - th.wrist_deviation_rad),
                    neck_twisted: neck_tw.map(|x| x.abs() - th.neck_twist_rad),
                    neck_side_bending: neck_sb.map(|x| x - th.neck_side_bend_rad),
                    trunk_twisted: trunk_tw.map(|x| x.abs() - th.trunk_twist_rad),
                    trunk_side_bending: trunk_sb.map(|x| x.abs() - th.trunk_side_bend_rad),
                },
            };
            assessment.confidence =
                region_confidences(skeleton, &assessment, &self.config.confidence);
            match side {
                Side::Left => out.left = Some(assessment),
                Side::Right => out.right = Some(assessment),
            }
        }
        out.unscored_reasons = unscored_reasons;
        self.remember(&angles);
        Ok(out)
    }

    fn remember(&mut self, now: &BodyAngles) {
        fn keep(held: &mut Option<f64>, now: Option<f64>) {
            if now.is_some() {
                *held = now;
            }
        }
        fn keep_side(held: &mut SideAngles, now: &SideAngles) {
            keep(&mut held.upper_arm_flexion_rad, now.upper_arm_flexion_rad);
            keep(
                &mut held.upper_arm_abduction_rad,
                now.upper_arm_abduction_rad,
            );
            keep(&mut held.shoulder_raise_ratio, now.shoulder_raise_ratio);
            keep(&mut held.elbow_flexion_rad, now.elbow_flexion_rad);
            keep(&mut held.wrist_flexion_rad, now.wrist_flexion_rad);
            keep(&mut held.wrist_deviation_rad, now.wrist_deviation_rad);
            keep(&mut held.wrist_lateral_offset_m, now.wrist_lateral_offset_m);
            keep(&mut held.knee_flexion_rad, now.knee_flexion_rad);
        }
        let h = &mut self.held;
        keep(&mut h.trunk_flexion_rad, now.trunk_flexion_rad);
        keep(&mut h.trunk_side_bend_rad, now.trunk_side_bend_rad);
        keep(&mut h.trunk_twist_rad, now.trunk_twist_rad);
        keep(&mut h.neck_flexion_rad, now.neck_flexion_rad);
        keep(&mut h.neck_side_bend_rad, now.neck_side_bend_rad);
        keep(&mut h.neck_twist_rad, now.neck_twist_rad);
        keep(&mut h.shoulder_width_m, now.shoulder_width_m);
        if now.legs.is_some() {
            h.legs = now.legs;
        }
        keep_side(&mut h.left, &now.left);
        keep_side(&mut h.right, &now.right);
    }
}

/// The RULA body regions, the one table of them: summaries ([`crate::summary`]), warnings
/// ([`crate::warnings`]), the simulator's experiments and the offline review all use it. The arm
/// regions are scored per side ([`BodyRegion::is_sided`]); neck, trunk and legs once for the body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyRegion {
    UpperArm,
    LowerArm,
    Wrist,
    Neck,
    Trunk,
    Legs,
}

impl BodyRegion {
    pub const ALL: [BodyRegion; 6] = [
        BodyRegion::UpperArm,
        BodyRegion::LowerArm,
        BodyRegion::Wrist,
        BodyRegion::Neck,
        BodyRegion::Trunk,
        BodyRegion::Legs,
    ];

    /// Snake-case name.
    pub const fn name(self) -> &'static str {
        match self {
            BodyRegion::UpperArm => "upper_arm",
            BodyRegion::LowerArm => "lower_arm",
            BodyRegion::Wrist => "wrist",
            BodyRegion::Neck => "neck",
            BodyRegion::Trunk => "trunk",
            BodyRegion::Legs => "legs",
        }
    }

    /// The name in words: "upper arm".
    pub const fn words(self) -> &'static str {
        match self {
            BodyRegion::UpperArm => "upper arm",
            BodyRegion::LowerArm => "lower arm",
            BodyRegion::Wrist => "wrist",
            BodyRegion::Neck => "neck",
            BodyRegion::Trunk => "trunk",
            BodyRegion::Legs => "legs",
        }
    }

    /// The sides it is scored on: left and right for the arm regions, `None` (the body) for the others.
    pub const fn sides(self) -> &'static [Option<Side>] {
        if self.is_sided() {
            &[Some(Side::Left), Some(Side::Right)]
        } else {
            &[None]
        }
    }

    /// Whether the region is scored per side.
    pub const fn is_sided(self) -> bool {
        matches!(
            self,
            BodyRegion::UpperArm | BodyRegion::LowerArm | BodyRegion::Wrist
        )
    }

    /// The highest score RULA gives the region, every adjustment included (see [`crate::rula`]):
    /// upper arm 6, lower arm 3, wrist 4, neck 6, trunk 6, legs 2. The lowest is 1.
    pub const fn max_score(self) -> u8 {
        match self {
            BodyRegion::UpperArm | BodyRegion::Neck | BodyRegion::Trunk => 6,
            BodyRegion::LowerArm => 3,
            BodyRegion::Wrist => 4,
            BodyRegion::Legs => 2,
        }
    }

    /// The region whose score a landmark stands for (the review colours each joint by it), and the
    /// side whose worksheet scores it: the landmark's own side ([`Landmark::side`]) for the arm
    /// regions, `None` for neck, trunk and legs (scored once for the body). Face → neck, shoulders →
    /// upper arm, elbows → lower arm, wrists and hands → wrist, hips → trunk, knees, ankles and feet →
    /// legs.
    pub const fn of_landmark(landmark: Landmark) -> (BodyRegion, Option<Side>) {
        use Landmark as L;
        let region = match landmark {
            L::Nose
            | L::LeftEyeInner
            | L::LeftEye
            | L::LeftEyeOuter
            | L::RightEyeInner
            | L::RightEye
            | L::RightEyeOuter
            | L::LeftEar
            | L::RightEar
            | L::MouthLeft
            | L::MouthRight => BodyRegion::Neck,
            L::LeftShoulder | L::RightShoulder => BodyRegion::UpperArm,
            L::LeftElbow | L::RightElbow => BodyRegion::LowerArm,
            L::LeftWrist
            | L::RightWrist
            | L::LeftPinky
            | L::RightPinky
            | L::LeftIndex
            | L::RightIndex
            | L::LeftThumb
            | L::RightThumb => BodyRegion::Wrist,
            L::LeftHip | L::RightHip => BodyRegion::Trunk,
            L::LeftKnee
            | L::RightKnee
            | L::LeftAnkle
            | L::RightAnkle
            | L::LeftHeel
            | L::RightHeel
            | L::LeftFootIndex
            | L::RightFootIndex => BodyRegion::Legs,
        };
        let side = if region.is_sided() {
            landmark.side()
        } else {
            None
        };
        (region, side)
    }

    /// The region's score (after adjustments) in a breakdown.
    pub fn score(self, s: &RulaScores) -> u8 {
        match self {
            BodyRegion::UpperArm => s.upper_arm_score,
            BodyRegion::LowerArm => s.lower_arm_score,
            BodyRegion::Wrist => s.wrist_score,
            BodyRegion::Neck => s.neck_score,
            BodyRegion::Trunk => s.trunk_score,
            BodyRegion::Legs => s.legs_score,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rula::{score_worksheet, RulaInput, GRAND_SCORE_MAX};

    #[test]
    fn every_landmark_stands_for_the_region_of_its_body_part_on_its_own_side() {
        use Landmark as L;
        let of = BodyRegion::of_landmark;
        assert_eq!(
            of(L::LeftShoulder),
            (BodyRegion::UpperArm, Some(Side::Left))
        );
        assert_eq!(
            of(L::RightShoulder),
            (BodyRegion::UpperArm, Some(Side::Right))
        );
        assert_eq!(of(L::LeftElbow), (BodyRegion::LowerArm, Some(Side::Left)));
        assert_eq!(of(L::RightWrist), (BodyRegion::Wrist, Some(Side::Right)));
        assert_eq!(of(L::LeftPinky), (BodyRegion::Wrist, Some(Side::Left)));
        assert_eq!(of(L::RightThumb), (BodyRegion::Wrist, Some(Side::Right)));
        assert_eq!(of(L::Nose), (BodyRegion::Neck, None));
        assert_eq!(of(L::MouthLeft), (BodyRegion::Neck, None));
        assert_eq!(of(L::LeftHip), (BodyRegion::Trunk, None));
        assert_eq!(of(L::RightFootIndex), (BodyRegion::Legs, None));
        for lm in Landmark::ALL {
            let (region, side) = of(lm);
            assert_eq!(side.is_some(), region.is_sided(), "{lm}");
            if region.is_sided() {
                assert_eq!(side, lm.side(), "{lm}");
            }
            let (mirror_region, mirror_side) = of(lm.mirrored());
            assert_eq!(mirror_region, region, "{lm}");
            assert_eq!(mirror_side, side.map(Side::other), "{lm}");
        }
    }

    #[test]
    fn the_worst_worksheet_reaches_every_regions_maximum_and_the_neutral_one_its_minimum() {
        let worst = RulaInput {
            upper_arm_flexion_deg: 120.0,
            shoulder_raised: true,
            upper_arm_abducted: true,
            lower_arm_flexion_deg: 120.0,
            lower_arm_across_midline_or_out_to_side: true,
            wrist_flexion_deg: 30.0,
            wrist_bent_from_midline: true,
            neck_flexion_deg: -5.0,
            neck_twisted: true,
            neck_side_bending: true,
            trunk_flexion_deg: 70.0,
            trunk_twisted: true,
            trunk_side_bending: true,
            legs_supported_and_balanced: false,
            ..RulaInput::neutral()
        };
        let scores = score_worksheet(&worst).unwrap().scores;
        for region in BodyRegion::ALL {
            assert_eq!(region.score(&scores), region.max_score(), "{region:?}");
        }
        assert_eq!(scores.final_score, GRAND_SCORE_MAX);
        let neutral = score_worksheet(&RulaInput::neutral()).unwrap().scores;
        for region in BodyRegion::ALL {
            assert_eq!(region.score(&neutral), 1, "{region:?}");
        }
    }
}
