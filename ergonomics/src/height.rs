//! Operator stature and height class at session start.
//!
//! # Upright frames
//! Only frames where the operator stands upright are used: both knees within
//! [`HeightConfig::upright_max_knee_flexion_rad`] of straight (angle between thigh `knee − hip` and
//! shank `ankle − knee`), both hips within [`HeightConfig::upright_max_hip_flexion_rad`] of straight
//! (angle between the trunk axis `shoulder mid − hip mid` and `hip − knee`), the trunk axis within
//! [`HeightConfig::upright_max_trunk_tilt_rad`] of the world's up, and the head held up: the vector
//! from the shoulder midpoint to the ear midpoint within [`HeightConfig::upright_max_neck_flexion_rad`]
//! of the trunk axis (a bowed head lowers the eyes and biases both estimators low).
//!
//! # Two estimators (Drillis & Contini 1966, as tabulated by Winter, *Biomechanics and Motor Control
//! of Human Movement*; fractions of stature H, from the workspace's one table,
//! [`ergocell_anthropometry`])
//! - **Floor to eye**: eye height above the floor is 0.936 H, so `H = (eye − floor) / 0.936` — the
//!   eye height plus the eye-to-vertex offset of 0.064 H. The eye height is the mean of the left and
//!   right eye landmarks along up; the floor is the configured floor height along up or, when unknown,
//!   the lowest foot landmark (heel, foot index, ankle) of the frame.
//! - **Segment chain**: shank (knee − ankle, 0.246 H) + thigh (hip − knee, 0.245 H) + trunk (hip
//!   midpoint − shoulder midpoint, 0.288 H) + shoulder-to-eye along the trunk axis (0.936 − 0.818 =
//!   0.118 H) spans ankle to eye, 0.897 H (ankle height is 0.039 H). So `H = chain / 0.897`, each leg
//!   segment the mean of the sides seen. The three "verify" ratios of `robot.md` check out: they are
//!   the differences of the tabulated heights (0.530 − 0.285, 0.285 − 0.039, 0.818 − 0.530).
//!
//! A third, **posture-independent** estimator runs on every frame, upright or not: each limb and
//! trunk segment length divided by its ratio (upper arm 0.186 H, forearm 0.146 H, thigh 0.245 H,
//! shank 0.246 H, shoulder-to-hip per side 0.288 H), the median over the segments seen in a frame,
//! then the median over frames ([`HeightEstimator::segment_estimate`]). Shoulder and hip *widths* are
//! left out: BlazePose's shoulder and hip landmarks are joint centres, narrower than the biacromial
//! and bi-trochanteric breadths the ratios describe. It is reported (e.g. for a seated operator) but
//! never decides a class: the class is decided from upright frames only.
//!
//! The ratios are 1966 population means. We assume their person-to-person spread is 1.5 % of H for
//! the floor-to-eye ratio and 2.5 % for the segment chain (a chain of four ratios, and BlazePose's hip
//! landmark is not the greater trochanter); those are the estimators' model uncertainties.
//!
//! # Robust combination
//! Per estimator: the median over the upright frames of the window, with a statistical standard error
//! `1.2533 · 1.4826 · MAD / √n`; the estimator's σ combines it with the model uncertainty. The two
//! are combined by inverse-variance weighting; if they disagree by more than their combined σ, σ is
//! widened to half the disagreement.
//!
//! # Class decision
//! Classes: c1 below 1.68 m, c2 from 1.68 to 1.82 m inclusive, c3 above (thresholds configurable). A
//! class is decided when at least [`HeightConfig::min_frames`] upright frames were used and the
//! interval `H ± k·σ` (k = [`HeightConfig::decision_sigmas`]) lies inside one class — and only then:
//! an interval that straddles a boundary is undecided, however many frames agree (the frames share
//! the person's proportions and posture, so their agreement says nothing about the model's error; a
//! fall-back on frame agreement decided operators within 1 cm of a boundary while stating σ ≈ 2.2 cm,
//! against its own interval). Until then the estimator keeps measuring and says why (with the share
//! of frames that favour one class, for information). The decision is emitted once, as a
//! [`HeightDecision`].

use std::collections::VecDeque;

use ergocell_anthropometry::{from_heights, EYE_HEIGHT, FOREARM, SHANK, THIGH, TRUNK, UPPER_ARM};
use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Point3, Vector3};
use serde::{Deserialize, Serialize};

use crate::angles::UpVector;
use crate::ErgonomicsError;

/// Ankle-to-eye chain over stature: shank 0.246 + thigh 0.245 + trunk 0.288 + shoulder-to-eye 0.118.
pub const CHAIN_RATIO: f64 = SHANK + THIGH + TRUNK + from_heights::EYE_ABOVE_SHOULDER;
/// Assumed relative spread of the eye-height ratio between people.
pub const EYE_MODEL_REL_SIGMA: f64 = 0.015;
/// Assumed relative spread of the chain ratio between people.
pub const CHAIN_MODEL_REL_SIGMA: f64 = 0.025;
/// Assumed relative spread of a single segment's ratio between people.
pub const SEGMENT_MODEL_REL_SIGMA: f64 = 0.04;

/// Segments of the posture-independent estimator and their lengths as fractions of stature
/// (Drillis & Contini 1966).
pub const SEGMENT_RATIOS: [(Landmark, Landmark, f64); 10] = [
    (Landmark::LeftShoulder, Landmark::LeftElbow, UPPER_ARM),
    (Landmark::RightShoulder, Landmark::RightElbow, UPPER_ARM),
    (Landmark::LeftElbow, Landmark::LeftWrist, FOREARM),
    (Landmark::RightElbow, Landmark::RightWrist, FOREARM),
    (Landmark::LeftHip, Landmark::LeftKnee, THIGH),
    (Landmark::RightHip, Landmark::RightKnee, THIGH),
    (Landmark::LeftKnee, Landmark::LeftAnkle, SHANK),
    (Landmark::RightKnee, Landmark::RightAnkle, SHANK),
    (Landmark::LeftShoulder, Landmark::LeftHip, TRUNK),
    (Landmark::RightShoulder, Landmark::RightHip, TRUNK),
];

/// Height class thresholds, validated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClassThresholds {
    c1_below_m: f64,
    c2_up_to_m: f64,
}

impl ClassThresholds {
    /// c1 < `c1_below_m` ≤ c2 ≤ `c2_up_to_m` < c3.
    pub fn new(c1_below_m: f64, c2_up_to_m: f64) -> Result<Self, ErgonomicsError> {
        if !(c1_below_m.is_finite() && c2_up_to_m.is_finite() && c1_below_m > 0.0)
            || c1_below_m > c2_up_to_m
        {
            return Err(ErgonomicsError::BadClassThresholds {
                c1_below_m,
                c2_up_to_m,
            });
        }
        Ok(Self {
            c1_below_m,
            c2_up_to_m,
        })
    }

    pub fn c1_below_m(&self) -> f64 {
        self.c1_below_m
    }

    pub fn c2_up_to_m(&self) -> f64 {
        self.c2_up_to_m
    }
}

impl Default for ClassThresholds {
    /// The paper's classes: c1 < 1.68 m, 1.68 ≤ c2 ≤ 1.82 m, c3 > 1.82 m.
    fn default() -> Self {
        Self {
            c1_below_m: 1.68,
            c2_up_to_m: 1.82,
        }
    }
}

/// The operator's height class.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HeightClass {
    C1,
    C2,
    C3,
}

impl HeightClass {
    /// The class of a stature (c2 inclusive at both ends).
    pub fn of(height_m: f64, t: &ClassThresholds) -> HeightClass {
        if height_m < t.c1_below_m {
            HeightClass::C1
        } else if height_m <= t.c2_up_to_m {
            HeightClass::C2
        } else {
            HeightClass::C3
        }
    }

    pub const fn name(self) -> &'static str {
        match self {
            HeightClass::C1 => "c1",
            HeightClass::C2 => "c2",
            HeightClass::C3 => "c3",
        }
    }
}

/// Height estimation settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeightConfig {
    pub up: UpVector,
    /// Floor height along `up`, metres; `None` = the lowest foot landmark of each frame.
    pub floor_height_m: Option<f64>,
    pub thresholds: ClassThresholds,
    /// Default 20°.
    pub upright_max_knee_flexion_rad: f64,
    /// Default 20°.
    pub upright_max_hip_flexion_rad: f64,
    /// Default 10°.
    pub upright_max_trunk_tilt_rad: f64,
    /// Default 15° (checked when both ears are seen).
    pub upright_max_neck_flexion_rad: f64,
    /// Upright frames needed before any decision (default 15).
    pub min_frames: usize,
    /// Half-width of the decision interval in σ (default 2).
    pub decision_sigmas: f64,
    /// Upright frames kept (the most recent; default 600).
    pub window_frames: usize,
}

impl HeightConfig {
    /// Defaults for everything but the up vector, which must always be given.
    pub fn new(up: UpVector) -> Self {
        Self {
            up,
            floor_height_m: None,
            thresholds: ClassThresholds::default(),
            upright_max_knee_flexion_rad: 20f64.to_radians(),
            upright_max_hip_flexion_rad: 20f64.to_radians(),
            upright_max_trunk_tilt_rad: 10f64.to_radians(),
            upright_max_neck_flexion_rad: 15f64.to_radians(),
            min_frames: 15,
            decision_sigmas: 2.0,
            window_frames: 600,
        }
    }
}

/// One estimator's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EstimatorResult {
    pub name: &'static str,
    pub height_m: f64,
    /// One standard deviation, statistical and model combined.
    pub sigma_m: f64,
    pub frames: usize,
}

/// The combined estimate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeightEstimate {
    pub height_m: f64,
    /// One standard deviation.
    pub uncertainty_m: f64,
    /// Upright frames used.
    pub frames_used: usize,
    pub estimators: Vec<EstimatorResult>,
}

/// How a class was decided.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "basis", rename_all = "snake_case")]
pub enum DecisionBasis {
    /// `height ± k·σ` lies inside the class (the only rule).
    Interval { sigmas: f64 },
}

/// The class decision event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeightDecision {
    pub stamp_nanos: i64,
    pub class: HeightClass,
    pub estimate: HeightEstimate,
    pub basis: DecisionBasis,
}

/// Where the estimator is.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum HeightStatus {
    /// Still measuring; `why` says what is missing.
    Measuring {
        frames_seen: usize,
        upright_frames: usize,
        estimate: Option<HeightEstimate>,
        why: String,
    },
    Decided(HeightDecision),
}

/// Per-frame estimates of one upright frame.
#[derive(Debug, Clone, Copy, PartialEq)]
struct FrameEstimate {
    eye: Option<f64>,
    chain: Option<f64>,
}

impl FrameEstimate {
    fn combined(&self) -> Option<f64> {
        match (self.eye, self.chain) {
            (Some(a), Some(b)) => Some(0.5 * (a + b)),
            (a, b) => a.or(b),
        }
    }
}

/// Statures a person can have, metres: a per-frame estimate outside is not used (it is a unit or
/// calibration error, not an operator).
pub const HUMAN_STATURE_M: std::ops::RangeInclusive<f64> = 0.5..=2.5;

/// Accumulates frames and decides the class once.
#[derive(Debug, Clone)]
pub struct HeightEstimator {
    config: HeightConfig,
    frames_seen: usize,
    window: VecDeque<FrameEstimate>,
    decision: Option<HeightDecision>,
    /// Per frame (any posture): the median of the segment-based statures.
    segment_frames: VecDeque<f64>,
    /// Per segment of [`SEGMENT_RATIOS`]: its stature estimates over the window.
    segment_values: Vec<VecDeque<f64>>,
    /// Upright frames whose stature was outside [`HUMAN_STATURE_M`], and the last such value.
    impossible_frames: usize,
    last_impossible_m: Option<f64>,
}

fn mid(a: Point3<f64>, b: Point3<f64>) -> Point3<f64> {
    Point3::from((a.coords + b.coords) * 0.5)
}

fn angle(a: Vector3<f64>, b: Vector3<f64>) -> Option<f64> {
    let (na, nb) = (a.norm(), b.norm());
    (na > 1e-9 && nb > 1e-9).then(|| (a.dot(&b) / (na * nb)).clamp(-1.0, 1.0).acos())
}

fn mean_of(values: &[f64]) -> Option<f64> {
    (!values.is_empty()).then(|| values.iter().sum::<f64>() / values.len() as f64)
}

/// The median (mean of the middle two for an even count); sorts `v`.
pub(crate) fn median(v: &mut [f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    })
}

/// Median and its standard error (from the MAD) of a sample.
fn robust_location(values: &[f64]) -> Option<(f64, f64)> {
    let mut v = values.to_vec();
    let m = median(&mut v)?;
    let mut dev: Vec<f64> = v.iter().map(|x| (x - m).abs()).collect();
    let mad = median(&mut dev)?;
    let se = 1.2533 * 1.4826 * mad / (v.len() as f64).sqrt();
    Some((m, se))
}

impl HeightEstimator {
    pub fn new(config: HeightConfig) -> Self {
        Self {
            config,
            frames_seen: 0,
            window: VecDeque::new(),
            decision: None,
            segment_frames: VecDeque::new(),
            segment_values: vec![VecDeque::new(); SEGMENT_RATIOS.len()],
            impossible_frames: 0,
            last_impossible_m: None,
        }
    }

    fn push_segments(&mut self, s: &Skeleton3) {
        let cap = self.config.window_frames.max(1);
        let mut this_frame = Vec::new();
        for (k, (a, b, ratio)) in SEGMENT_RATIOS.iter().enumerate() {
            if let Some(len) = s.bone_length_m(*a, *b).filter(|l| *l > 0.0) {
                let h = len / ratio;
                this_frame.push(h);
                let v = &mut self.segment_values[k];
                v.push_back(h);
                while v.len() > cap {
                    v.pop_front();
                }
            }
        }
        if let Some(m) = median(&mut this_frame) {
            self.segment_frames.push_back(m);
            while self.segment_frames.len() > cap {
                self.segment_frames.pop_front();
            }
        }
    }

    /// The posture-independent segment-length estimate over the window (any posture). Its σ combines
    /// the statistical error over frames, the disagreement between segments (MAD of the per-segment
    /// medians over √segments) and the model spread of one segment ratio.
    pub fn segment_estimate(&self) -> Option<EstimatorResult> {
        let frames: Vec<f64> = self.segment_frames.iter().copied().collect();
        let (h, se) = robust_location(&frames)?;
        let mut per_segment: Vec<f64> = self
            .segment_values
            .iter()
            .filter_map(|v| {
                let mut v: Vec<f64> = v.iter().copied().collect();
                median(&mut v)
            })
            .collect();
        let k = per_segment.len() as f64;
        let m = median(&mut per_segment)?;
        let mut dev: Vec<f64> = per_segment.iter().map(|x| (x - m).abs()).collect();
        let dispersion = 1.4826 * median(&mut dev)? / k.sqrt();
        Some(EstimatorResult {
            name: "segment_lengths",
            height_m: h,
            sigma_m: se.hypot(dispersion).hypot(SEGMENT_MODEL_REL_SIGMA * h),
            frames: frames.len(),
        })
    }

    /// Whether a frame shows the operator standing upright (see the module docs). `None` when the
    /// landmarks needed are missing.
    pub fn is_upright(&self, s: &Skeleton3) -> Option<bool> {
        let c = &self.config;
        let hips = mid(
            s.position(Landmark::LeftHip)?,
            s.position(Landmark::RightHip)?,
        );
        let shoulders = mid(
            s.position(Landmark::LeftShoulder)?,
            s.position(Landmark::RightShoulder)?,
        );
        let trunk = shoulders - hips;
        if angle(trunk, c.up.vector())? > c.upright_max_trunk_tilt_rad {
            return Some(false);
        }
        if let (Some(el), Some(er)) = (
            s.position(Landmark::LeftEar),
            s.position(Landmark::RightEar),
        ) {
            if angle(mid(el, er) - shoulders, trunk)? > c.upright_max_neck_flexion_rad {
                return Some(false);
            }
        }
        for (hip, knee, ankle) in [
            (Landmark::LeftHip, Landmark::LeftKnee, Landmark::LeftAnkle),
            (
                Landmark::RightHip,
                Landmark::RightKnee,
                Landmark::RightAnkle,
            ),
        ] {
            let (h, k, a) = (s.position(hip)?, s.position(knee)?, s.position(ankle)?);
            if angle(k - h, a - k)? > c.upright_max_knee_flexion_rad {
                return Some(false);
            }
            if angle(trunk, h - k)? > c.upright_max_hip_flexion_rad {
                return Some(false);
            }
        }
        Some(true)
    }

    fn frame_estimate(&self, s: &Skeleton3) -> FrameEstimate {
        let up = &self.config.up;
        let eyes: Vec<Point3<f64>> = [Landmark::LeftEye, Landmark::RightEye]
            .iter()
            .filter_map(|l| s.position(*l))
            .collect();
        let eye_mid = match eyes.as_slice() {
            [a, b] => Some(mid(*a, *b)),
            [a] => Some(*a),
            _ => None,
        };
        let floor = self.config.floor_height_m.or_else(|| {
            [
                Landmark::LeftHeel,
                Landmark::RightHeel,
                Landmark::LeftFootIndex,
                Landmark::RightFootIndex,
                Landmark::LeftAnkle,
                Landmark::RightAnkle,
            ]
            .iter()
            .filter_map(|l| s.position(*l))
            .map(|p| up.height_of(&p))
            .min_by(f64::total_cmp)
        });
        let eye = eye_mid
            .zip(floor)
            .map(|(e, f)| (up.height_of(&e) - f) / EYE_HEIGHT)
            .filter(|h| *h > 0.0);

        let shank: Vec<f64> = [
            (Landmark::LeftKnee, Landmark::LeftAnkle),
            (Landmark::RightKnee, Landmark::RightAnkle),
        ]
        .iter()
        .filter_map(|(a, b)| s.bone_length_m(*a, *b))
        .collect();
        let thigh: Vec<f64> = [
            (Landmark::LeftHip, Landmark::LeftKnee),
            (Landmark::RightHip, Landmark::RightKnee),
        ]
        .iter()
        .filter_map(|(a, b)| s.bone_length_m(*a, *b))
        .collect();
        let chain = (|| {
            let hips = mid(
                s.position(Landmark::LeftHip)?,
                s.position(Landmark::RightHip)?,
            );
            let shoulders = mid(
                s.position(Landmark::LeftShoulder)?,
                s.position(Landmark::RightShoulder)?,
            );
            let trunk = shoulders - hips;
            let t = trunk / trunk.norm().max(1e-9);
            let head = (eye_mid? - shoulders).dot(&t);
            let total = mean_of(&shank)? + mean_of(&thigh)? + trunk.norm() + head;
            Some(total / CHAIN_RATIO).filter(|h| *h > 0.0)
        })();
        FrameEstimate { eye, chain }
    }

    /// Feeds one frame. Returns the class decision the first time it is made.
    pub fn push(&mut self, s: &Skeleton3) -> Option<HeightDecision> {
        self.frames_seen += 1;
        self.push_segments(s);
        if self.is_upright(s) == Some(true) {
            let e = self.frame_estimate(s);
            if let Some(h) = e.combined().filter(|h| !HUMAN_STATURE_M.contains(h)) {
                // A physically impossible stature (a calibration in millimetres, a scaled file):
                // never used, never classed; the status says so.
                self.impossible_frames += 1;
                self.last_impossible_m = Some(h);
            } else if e.combined().is_some() {
                self.window.push_back(e);
                while self.window.len() > self.config.window_frames.max(1) {
                    self.window.pop_front();
                }
            }
        }
        if self.decision.is_some() {
            return None;
        }
        let decision = self.try_decide(s.stamp_nanos);
        self.decision.clone_from(&decision);
        decision
    }

    /// The current estimate over the upright frames of the window.
    pub fn estimate(&self) -> Option<HeightEstimate> {
        let eye: Vec<f64> = self.window.iter().filter_map(|e| e.eye).collect();
        let chain: Vec<f64> = self.window.iter().filter_map(|e| e.chain).collect();
        let mut estimators = Vec::new();
        for (name, values, rel) in [
            ("floor_to_eye", &eye, EYE_MODEL_REL_SIGMA),
            ("segment_chain", &chain, CHAIN_MODEL_REL_SIGMA),
        ] {
            if let Some((h, se)) = robust_location(values) {
                estimators.push(EstimatorResult {
                    name,
                    height_m: h,
                    sigma_m: se.hypot(rel * h),
                    frames: values.len(),
                });
            }
        }
        if estimators.is_empty() {
            return None;
        }
        let weights: Vec<f64> = estimators
            .iter()
            .map(|e| 1.0 / e.sigma_m.max(1e-6).powi(2))
            .collect();
        let wsum: f64 = weights.iter().sum();
        let height_m = estimators
            .iter()
            .zip(&weights)
            .map(|(e, w)| e.height_m * w)
            .sum::<f64>()
            / wsum;
        let mut uncertainty_m = 1.0 / wsum.sqrt();
        if let [a, b] = estimators.as_slice() {
            let spread = (a.height_m - b.height_m).abs();
            if spread > a.sigma_m.hypot(b.sigma_m) {
                uncertainty_m = uncertainty_m.max(0.5 * spread);
            }
        }
        Some(HeightEstimate {
            height_m,
            uncertainty_m,
            frames_used: self.window.len(),
            estimators,
        })
    }

    fn try_decide(&self, stamp_nanos: i64) -> Option<HeightDecision> {
        let c = &self.config;
        if self.window.len() < c.min_frames {
            return None;
        }
        let estimate = self.estimate()?;
        let t = &c.thresholds;
        let k = c.decision_sigmas;
        let lo = HeightClass::of(estimate.height_m - k * estimate.uncertainty_m, t);
        let hi = HeightClass::of(estimate.height_m + k * estimate.uncertainty_m, t);
        // A straddling interval is undecided: the session's safe handling takes over.
        (lo == hi).then_some(HeightDecision {
            stamp_nanos,
            class: lo,
            estimate,
            basis: DecisionBasis::Interval { sigmas: k },
        })
    }

    /// The most common class among per-frame estimates and its share.
    fn agreement(&self) -> Option<(HeightClass, f64)> {
        let t = &self.config.thresholds;
        let classes: Vec<HeightClass> = self
            .window
            .iter()
            .filter_map(FrameEstimate::combined)
            .map(|h| HeightClass::of(h, t))
            .collect();
        let n = classes.len();
        [HeightClass::C1, HeightClass::C2, HeightClass::C3]
            .into_iter()
            .map(|c| (c, classes.iter().filter(|x| **x == c).count()))
            .max_by_key(|(_, k)| *k)
            .filter(|_| n > 0)
            .map(|(c, k)| (c, k as f64 / n as f64))
    }

    /// Where the estimator stands.
    pub fn status(&self) -> HeightStatus {
        if let Some(d) = &self.decision {
            return HeightStatus::Decided(d.clone());
        }
        let c = &self.config;
        let upright = self.window.len();
        let estimate = self.estimate();
        let why = if let (Some(h), true) = (self.last_impossible_m, upright < c.min_frames) {
            format!(
                "{} upright frames gave a physically impossible stature (e.g. {h:.3} m, outside \
                 {:.1}–{:.1} m: landmarks in millimetres, or a mis-scaled calibration?): not used",
                self.impossible_frames,
                HUMAN_STATURE_M.start(),
                HUMAN_STATURE_M.end()
            )
        } else if upright < c.min_frames {
            format!(
                "{upright} upright frames of {} needed (stand straight, facing the cameras)",
                c.min_frames
            )
        } else if let Some(e) = &estimate {
            let k = c.decision_sigmas;
            let agree = self.agreement().map_or(String::new(), |(cl, f)| {
                format!("; {:.0}% of frames say {}", f * 100.0, cl.name())
            });
            format!(
                "{:.3} ± {:.3} m ({k}σ) straddles a class boundary ({:.2} / {:.2} m){agree}: undecided",
                e.height_m,
                k * e.uncertainty_m,
                c.thresholds.c1_below_m,
                c.thresholds.c2_up_to_m,
            )
        } else {
            "no usable estimate".to_owned()
        };
        HeightStatus::Measuring {
            frames_seen: self.frames_seen,
            upright_frames: upright,
            estimate,
            why,
        }
    }
}
