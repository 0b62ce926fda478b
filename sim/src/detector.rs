//! 2D detections like a real pose estimator's (MediaPipe BlazePose on each camera's Jetson).
//!
//! Per camera and frame, [`DetectorNoise`] decides what the estimator reports:
//!
//! 1. **Dropped frames**: the camera's view is missing with probability
//!    [`DetectorNoise::drop_probability`] (a lost packet, a late Jetson).
//! 2. **Timestamp jitter**: each camera captures at the tick time plus a Gaussian offset of
//!    σ = [`DetectorNoise::stamp_jitter_sigma_nanos`] (clipped at 3σ); the body is posed *at that
//!    instant* and the view's `stamp_nanos` is that instant, as unsynchronised cameras do.
//! 3. **Projection** with the perception crate's camera model ([`Camera::project`]: pinhole +
//!    Brown–Conrady distortion), so detections are distorted pixels as the cameras deliver them.
//! 4. **Visibility** per landmark: behind the camera or outside the image → not reported; if fewer than
//!    [`DetectorNoise::min_landmarks_in_frame`] landmarks are in the image, the person is not
//!    detected at all (an empty view). **Self-occlusion**: a landmark whose line of sight to the camera
//!    crosses the torso (an elliptic cylinder from the hips to the shoulders, 0.17 H wide and
//!    0.126 H deep) or that sits on the far side of the head (face landmarks facing away) is occluded.
//!    BlazePose still guesses occluded landmarks with a low visibility score: each is reported with
//!    probability [`DetectorNoise::occluded_report_probability`], with a confidence drawn from
//!    [`DetectorNoise::occluded_confidence`] and [`DetectorNoise::occluded_noise_scale`] times the
//!    pixel noise.
//! 5. **Pixel noise**: isotropic Gaussian, σ = [`DetectorNoise::pixel_sigma_px`]; visible landmarks get a
//!    confidence drawn uniformly from [`DetectorNoise::visible_confidence`]. With a
//!    [`RelativeNoise`] (a model fitted to the real detector, [`crate::detector_fit`]) the error is
//!    instead relative to the person's image height in the view and has two parts, as the real
//!    detector's has: a **persistent** offset per camera and landmark that wanders slowly (an
//!    Ornstein–Uhlenbeck process, drawn from its own seeded stream so the default model's draws are
//!    untouched) and frame-to-frame **jitter**, both per landmark group.
//! 6. **Gross outliers**: with probability [`DetectorNoise::outlier_probability`] a keypoint jumps by
//!    a uniform [`DetectorNoise::outlier_offset_px`] in a random direction, keeping a normal
//!    confidence (the detector does not know it is wrong).
//!
//! Every draw comes from the caller's seeded `ChaCha8Rng`, in a fixed order: same seed, same pixels.

use ergocell_perception::{Camera, CameraIndex, Keypoint2, View2};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use serde::Serialize;

use crate::body::{Kinematics, Torso};
use crate::SimError;

/// Noise levels of the simulated pose estimator. Every field has a documented default.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DetectorNoise {
    /// Pixel noise σ of a visible keypoint, pixels (default 3.0: BlazePose on 1280×720 crops).
    pub pixel_sigma_px: f64,
    /// Confidence range of visible keypoints (default 0.75..0.99).
    pub visible_confidence: (f64, f64),
    /// Probability that an occluded keypoint is still reported (default 0.6).
    pub occluded_report_probability: f64,
    /// Confidence range of reported occluded keypoints (default 0.05..0.4).
    pub occluded_confidence: (f64, f64),
    /// Noise multiplier for reported occluded keypoints (default 4).
    pub occluded_noise_scale: f64,
    /// Probability of a gross outlier per reported keypoint (default 0.01).
    pub outlier_probability: f64,
    /// Range of an outlier's jump, pixels (default 30..150).
    pub outlier_offset_px: (f64, f64),
    /// Probability that a camera's whole view is dropped in a frame (default 0.02).
    pub drop_probability: f64,
    /// Capture-time jitter σ per camera and frame, nanoseconds (default 3 ms).
    pub stamp_jitter_sigma_nanos: f64,
    /// Fewer landmarks than this inside the image: the person is not detected (default 8).
    pub min_landmarks_in_frame: usize,
    /// How far above the anatomical tragion the detector puts both ear landmarks, along the world's
    /// up (z), metres (default 0): the offset a cell's `height calibrate` measures.
    #[serde(skip_serializing_if = "is_zero")]
    pub ear_offset_m: f64,
    /// The error relative to the image height, persistent and jitter (default `None`: the
    /// independent pixel noise above alone).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub relative: Option<RelativeNoise>,
}

/// Landmark groups of [`RelativeNoise`], as the real measurement reports them
/// ([`ergocell_perception::detector_error::GROUPS`]): face, shoulders and arms, hips, legs.
pub const NOISE_GROUPS: usize = 4;

/// The group index of a landmark (0 face, 1 shoulders and arms, 2 hips, 3 legs).
pub fn noise_group(landmark: usize) -> usize {
    match landmark {
        0..=10 => 0,
        11..=22 => 1,
        23..=24 => 2,
        _ => 3,
    }
}

/// A detector error relative to the person's image height in the view (the vertical extent of the
/// landmarks in the image), per landmark group: what [`crate::detector_fit`] fits to a real
/// detector measured view against view.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RelativeNoise {
    /// σ per image coordinate of the persistent offset of a camera's landmark, as a fraction of the
    /// image height, per group.
    pub persistent_sigma: [f64; NOISE_GROUPS],
    /// σ per image coordinate of the frame-to-frame jitter, fraction of the image height, per group.
    pub jitter_sigma: [f64; NOISE_GROUPS],
    /// Correlation time of the persistent offset, seconds: it wanders as an Ornstein–Uhlenbeck
    /// process of this time constant (a pose held, the offset held).
    pub persistent_tau_s: f64,
    /// Shape of the persistent offset's size, per group, 0..=1: 1 is a 2-D Gaussian (its length
    /// Rayleigh-distributed, p90 1.8 × the median), 0 a fixed length (σ·√(π/2), the Gaussian's mean
    /// length) in a random direction; between, a blend of the two lengths. The real detector's
    /// offsets vary less in size than a Gaussian's.
    pub persistent_shape: [f64; NOISE_GROUPS],
    /// σ per image coordinate of an offset a camera's landmarks share, fraction of the image height
    /// (default 0): the whole view displaced, as a small calibration or synchronisation error of that
    /// camera displaces it. Fixed for the session.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub view_shift_sigma: f64,
    /// Shape of the shared offset's size, 0..=1, as [`RelativeNoise::persistent_shape`].
    #[serde(default, skip_serializing_if = "is_zero")]
    pub view_shift_shape: f64,
    /// How alike the persistent offsets of two cameras are by the angle between them as the person
    /// sees them, degrees (default 0: independent). Two cameras a few degrees apart see nearly the
    /// same picture, and a detector errs alike on alike pictures: the offsets are one 3-D offset per
    /// landmark seen from each camera, correlated between cameras as exp(−c²/2ℓ²) of the chord `c`
    /// between their unit directions from the person, ℓ the chord of this angle.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub view_correlation_deg: f64,
    /// A gross outlier's jump as fractions of the image height, `[low, high]` (default `[0, 0]`:
    /// [`DetectorNoise::outlier_offset_px`] in pixels instead). The real detector's gross errors
    /// are counted beyond 15 % of the height.
    #[serde(default, skip_serializing_if = "is_zero_pair")]
    pub outlier_height_fraction: [f64; 2],
}

#[allow(clippy::trivially_copy_pass_by_ref)] // serde's skip_serializing_if passes a reference
fn is_zero_pair(x: &[f64; 2]) -> bool {
    x[0] == 0.0 && x[1] == 0.0
}

impl RelativeNoise {
    /// Checks every value is finite and non-negative, the time constant positive.
    pub fn validate(&self) -> Result<(), SimError> {
        for &v in self.persistent_shape.iter().chain([&self.view_shift_shape]) {
            if !(0.0..=1.0).contains(&v) {
                return Err(SimError::BadParameter {
                    name: "persistent_shape",
                    value: v,
                    why: "must be within 0..=1",
                });
            }
        }
        for &v in self
            .persistent_sigma
            .iter()
            .chain(&self.jitter_sigma)
            .chain([&self.view_shift_sigma])
        {
            if !(v.is_finite() && (0.0..=0.5).contains(&v)) {
                return Err(SimError::BadParameter {
                    name: "relative noise sigma",
                    value: v,
                    why: "must be finite, within 0..=0.5 of the image height",
                });
            }
        }
        let [lo, hi] = self.outlier_height_fraction;
        if !(lo.is_finite() && hi.is_finite() && 0.0 <= lo && lo <= hi && hi <= 2.0) {
            return Err(SimError::BadParameter {
                name: "outlier_height_fraction",
                value: lo,
                why: "must be ordered, within 0..=2 of the image height",
            });
        }
        if !(0.0..=180.0).contains(&self.view_correlation_deg) {
            return Err(SimError::BadParameter {
                name: "view_correlation_deg",
                value: self.view_correlation_deg,
                why: "must be within 0..=180 degrees",
            });
        }
        if !(self.persistent_tau_s.is_finite() && self.persistent_tau_s > 0.0) {
            return Err(SimError::BadParameter {
                name: "persistent_tau_s",
                value: self.persistent_tau_s,
                why: "must be finite and > 0",
            });
        }
        Ok(())
    }
}

/// The persistent offsets of every camera's landmarks (fractions of the image height), evolving as
/// [`RelativeNoise`] says, from a stream of draws of their own.
///
/// The state is a standard 3-D Gaussian per camera and landmark (an Ornstein–Uhlenbeck process) and
/// one per camera for the shared view shift (fixed). Each tick the cameras' states are mixed by the
/// Cholesky factor of their correlation (by viewing direction, [`RelativeNoise::view_correlation_deg`];
/// the identity when 0) and each camera sees its mixed 3-D offset along its image axes: a 2-D
/// standard Gaussian per camera, alike between cameras that look alike. Then shaped and scaled.
#[derive(Debug, Clone)]
pub(crate) struct PersistentOffsets {
    offsets: Vec<[Vector3<f64>; LANDMARK_COUNT]>,
    shifts: Vec<Vector3<f64>>,
    rng: ChaCha8Rng,
    last_nanos: Option<i64>,
}

/// Scales a standard 2-D Gaussian `o` to an offset of σ `sigma` whose length is blended between
/// its own (shape 1) and the Gaussian's mean length (shape 0).
fn shaped(o: nalgebra::Vector2<f64>, shape: f64, sigma: f64) -> nalgebra::Vector2<f64> {
    // the Gaussian's mean length, √(π/2)
    const MEAN_LENGTH: f64 = 1.253_314_137_315_500_3;
    let length = o.norm();
    let blended = (1.0 - shape) * MEAN_LENGTH + shape * length;
    let direction = if length > 0.0 {
        o / length
    } else {
        nalgebra::Vector2::new(1.0, 0.0)
    };
    direction * (blended * sigma)
}

/// The lower Cholesky factor of the cameras' offset correlation, seen from `centre`; `None` when
/// they are independent.
fn correlation_factor(
    cameras: &[Camera],
    centre: &Point3<f64>,
    angle_deg: f64,
) -> Option<nalgebra::DMatrix<f64>> {
    if angle_deg <= 0.0 || cameras.len() < 2 {
        return None;
    }
    let directions: Vec<Vector3<f64>> = cameras
        .iter()
        .map(|c| {
            (c.position_world() - centre)
                .try_normalize(1e-9)
                .unwrap_or_else(Vector3::z)
        })
        .collect();
    let chord = 2.0 * (angle_deg.to_radians() / 2.0).sin();
    let n = cameras.len();
    let k = nalgebra::DMatrix::from_fn(n, n, |i, j| {
        let d = (directions[i] - directions[j]).norm_squared();
        (-d / (2.0 * chord * chord)).exp() + if i == j { 1e-9 } else { 0.0 }
    });
    let l = k.cholesky()?.l();
    // Rows of unit length: each camera's offset keeps its σ.
    Some(nalgebra::DMatrix::from_fn(n, n, |i, j| {
        l[(i, j)] / l.row(i).norm().max(1e-12)
    }))
}

impl PersistentOffsets {
    /// Offsets for `cameras` cameras drawn from their stationary distribution.
    pub(crate) fn new(cameras: usize, seed: u64) -> Self {
        use rand::SeedableRng as _;
        // Its own stream: the default model's draws stay what they were.
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5045_5253_4953_5400);
        let offsets = (0..cameras)
            .map(|_| std::array::from_fn(|_| gaussian3(&mut rng)))
            .collect();
        let shifts = (0..cameras).map(|_| gaussian3(&mut rng)).collect();
        Self {
            offsets,
            shifts,
            rng,
            last_nanos: None,
        }
    }

    /// Moves every offset on to `t_nanos` (exact OU step) and returns each camera's, for the person
    /// at `centre` seen by `cameras` (the same cameras, in order, as [`PersistentOffsets::new`]
    /// counted).
    pub(crate) fn at(
        &mut self,
        t_nanos: i64,
        noise: &RelativeNoise,
        cameras: &[Camera],
        centre: &Point3<f64>,
    ) -> Vec<[nalgebra::Vector2<f64>; LANDMARK_COUNT]> {
        let dt = self
            .last_nanos
            .map_or(0.0, |last| (t_nanos - last).max(0) as f64 * 1e-9);
        self.last_nanos = Some(t_nanos);
        if dt > 0.0 {
            let a = (-dt / noise.persistent_tau_s).exp();
            let b = (1.0 - a * a).sqrt();
            for camera in &mut self.offsets {
                for o in camera.iter_mut() {
                    *o = *o * a + gaussian3(&mut self.rng) * b;
                }
            }
        }
        let n = self.offsets.len().min(cameras.len());
        let factor = correlation_factor(&cameras[..n], centre, noise.view_correlation_deg);
        let mix = |states: &dyn Fn(usize) -> Vector3<f64>, i: usize| -> Vector3<f64> {
            match &factor {
                Some(l) => (0..=i).map(|j| states(j) * l[(i, j)]).sum(),
                None => states(i),
            }
        };
        (0..n)
            .map(|i| {
                let rotation = cameras[i].T_camera_world.rotation;
                let axes = |v: Vector3<f64>| {
                    let c = rotation * v;
                    nalgebra::Vector2::new(c.x, c.y)
                };
                let shift = if noise.view_shift_sigma > 0.0 {
                    shaped(
                        axes(mix(&|j| self.shifts[j], i)),
                        noise.view_shift_shape,
                        noise.view_shift_sigma,
                    )
                } else {
                    nalgebra::Vector2::zeros()
                };
                std::array::from_fn(|l| {
                    let g = noise_group(l);
                    shaped(
                        axes(mix(&|j| self.offsets[j][l], i)),
                        noise.persistent_shape[g],
                        noise.persistent_sigma[g],
                    ) + shift
                })
            })
            .collect()
    }
}

fn gaussian3(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    Vector3::new(gaussian(rng), gaussian(rng), gaussian(rng))
}

#[allow(clippy::trivially_copy_pass_by_ref)] // serde's skip_serializing_if passes a reference
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl Default for DetectorNoise {
    fn default() -> Self {
        Self {
            pixel_sigma_px: 3.0,
            visible_confidence: (0.75, 0.99),
            occluded_report_probability: 0.6,
            occluded_confidence: (0.05, 0.4),
            occluded_noise_scale: 4.0,
            outlier_probability: 0.01,
            outlier_offset_px: (30.0, 150.0),
            drop_probability: 0.02,
            stamp_jitter_sigma_nanos: 3.0e6,
            min_landmarks_in_frame: 8,
            ear_offset_m: 0.0,
            relative: None,
        }
    }
}

impl DetectorNoise {
    /// A perfect detector: no noise, no outliers, no drops, no jitter, occluded keypoints still reported
    /// exactly (for tests of the camera model).
    pub fn none() -> Self {
        Self {
            pixel_sigma_px: 0.0,
            visible_confidence: (1.0, 1.0),
            occluded_report_probability: 1.0,
            occluded_confidence: (1.0, 1.0),
            occluded_noise_scale: 1.0,
            outlier_probability: 0.0,
            outlier_offset_px: (0.0, 0.0),
            drop_probability: 0.0,
            stamp_jitter_sigma_nanos: 0.0,
            min_landmarks_in_frame: 0,
            ear_offset_m: 0.0,
            relative: None,
        }
    }

    /// Checks every field is finite, probabilities in 0..=1, ranges ordered.
    pub fn validate(&self) -> Result<(), SimError> {
        let bad = |name: &'static str, value: f64, why: &'static str| {
            Err(SimError::BadParameter { name, value, why })
        };
        for (name, v) in [
            ("pixel_sigma_px", self.pixel_sigma_px),
            ("occluded_noise_scale", self.occluded_noise_scale),
            ("stamp_jitter_sigma_nanos", self.stamp_jitter_sigma_nanos),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return bad(name, v, "must be finite and >= 0");
            }
        }
        for (name, v) in [
            (
                "occluded_report_probability",
                self.occluded_report_probability,
            ),
            ("outlier_probability", self.outlier_probability),
            ("drop_probability", self.drop_probability),
        ] {
            if !(0.0..=1.0).contains(&v) {
                return bad(name, v, "a probability must be within 0..=1");
            }
        }
        for (name, (lo, hi), max) in [
            ("visible_confidence", self.visible_confidence, 1.0),
            ("occluded_confidence", self.occluded_confidence, 1.0),
            ("outlier_offset_px", self.outlier_offset_px, f64::MAX),
        ] {
            if !(lo.is_finite() && hi.is_finite() && 0.0 <= lo && lo <= hi && hi <= max) {
                return bad(name, lo, "range must be ordered, finite and within bounds");
            }
        }
        if let Some(relative) = &self.relative {
            relative.validate()?;
        }
        if !(self.ear_offset_m.is_finite() && self.ear_offset_m.abs() <= 0.1) {
            return bad(
                "ear_offset_m",
                self.ear_offset_m,
                "must be finite and within ±0.1 m",
            );
        }
        Ok(())
    }
}

pub(crate) fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    rng.sample(StandardNormal)
}

/// The capture-time offset of one camera in one frame, nanoseconds.
pub(crate) fn jitter_nanos(noise: &DetectorNoise, rng: &mut ChaCha8Rng) -> i64 {
    let z: f64 = gaussian(rng).clamp(-3.0, 3.0);
    (z * noise.stamp_jitter_sigma_nanos).round() as i64
}

/// True when the line of sight from `p` to `eye` crosses the torso cylinder (beyond 2 cm from `p`).
pub(crate) fn torso_occludes(torso: &Torso, p: &Point3<f64>, eye: &Point3<f64>) -> bool {
    let inv = torso.R_world_trunk.inverse();
    let a = inv * (p - torso.base);
    let b = inv * (eye - torso.base);
    let d = b - a;
    let len = d.norm();
    if len < 1e-9 {
        return false;
    }
    let t_start = (0.02 / len).min(1.0);
    // Scaled cross-section: x = depth (forward), y = width.
    let (ax, ay) = (a.x / torso.half_depth_m, a.y / torso.half_width_m);
    let (dx, dy) = (d.x / torso.half_depth_m, d.y / torso.half_width_m);
    let qa = dx * dx + dy * dy;
    let qb = 2.0 * (ax * dx + ay * dy);
    let qc = ax * ax + ay * ay - 1.0;
    let (mut lo, mut hi) = if qa < 1e-12 {
        if qc < 0.0 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            return false;
        }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc <= 0.0 {
            return false;
        }
        let s = disc.sqrt();
        ((-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa))
    };
    lo = lo.max(t_start);
    hi = hi.min(1.0);
    // Along the trunk axis: 0 <= z(t) <= length.
    if d.z.abs() < 1e-12 {
        if a.z < 0.0 || a.z > torso.length_m {
            return false;
        }
    } else {
        let t0 = (0.0 - a.z) / d.z;
        let t1 = (torso.length_m - a.z) / d.z;
        lo = lo.max(t0.min(t1));
        hi = hi.min(t0.max(t1));
    }
    lo < hi
}

/// True when a face landmark faces away from the camera (the head hides it).
fn head_hides(head_centre: &Point3<f64>, p: &Point3<f64>, eye: &Point3<f64>) -> bool {
    let normal: Vector3<f64> = p - head_centre;
    normal.dot(&(eye - p)) < 0.0
}

/// Renders one camera's view of a posed body. `kin` is the body at the view's capture instant;
/// `offsets` the camera's persistent offsets when `noise.relative` is set.
pub(crate) fn render_view(
    camera: &Camera,
    index: CameraIndex,
    stamp_nanos: i64,
    kin: &Kinematics,
    noise: &DetectorNoise,
    offsets: Option<&[nalgebra::Vector2<f64>; LANDMARK_COUNT]>,
    rng: &mut ChaCha8Rng,
) -> View2 {
    let eye = camera.position_world();
    // Project everything first: the person is detected only if enough of them is in the image.
    let mut pixels = [None; LANDMARK_COUNT];
    let mut in_frame = 0;
    for lm in Landmark::ALL {
        let mut p = kin.points[lm.index()];
        if matches!(lm, Landmark::LeftEar | Landmark::RightEar) {
            p.z += noise.ear_offset_m;
        }
        if let Ok(px) = camera.project(&p) {
            if camera.in_image(&px) {
                pixels[lm.index()] = Some(px);
                in_frame += 1;
            }
        }
    }
    // The person's image height: the vertical extent of their landmarks in the image.
    let (top, bottom) = pixels
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.y), hi.max(p.y))
        });
    let height_px = if bottom > top { bottom - top } else { 0.0 };
    let mut view = View2::empty(index, stamp_nanos);
    // Draw the same number of random values per landmark whatever happens, so one landmark's fate
    // does not shift every later draw (noise settings change only what they control).
    for lm in Landmark::ALL {
        let z_u = gaussian(rng);
        let z_v = gaussian(rng);
        let u_report = rng.random::<f64>();
        let u_conf = rng.random::<f64>();
        let u_outlier = rng.random::<f64>();
        let u_angle = rng.random::<f64>();
        let u_jump = rng.random::<f64>();
        let Some(px) = pixels[lm.index()] else {
            continue;
        };
        if in_frame < noise.min_landmarks_in_frame {
            continue;
        }
        let p = kin.points[lm.index()];
        let occluded = torso_occludes(&kin.torso, &p, &eye)
            || (lm.index() <= Landmark::MouthRight.index()
                && head_hides(&kin.head_centre, &p, &eye));
        // Frame-to-frame noise per coordinate, and the persistent offset (pixels).
        let (jitter, offset) = match (&noise.relative, offsets) {
            (Some(r), Some(o)) => {
                let j = r.jitter_sigma[noise_group(lm.index())] * height_px;
                (
                    (noise.pixel_sigma_px.powi(2) + j * j).sqrt(),
                    o[lm.index()] * height_px,
                )
            }
            _ => (noise.pixel_sigma_px, nalgebra::Vector2::zeros()),
        };
        let (sigma, conf_range) = if occluded {
            if u_report >= noise.occluded_report_probability {
                continue;
            }
            (
                jitter * noise.occluded_noise_scale,
                noise.occluded_confidence,
            )
        } else {
            (jitter, noise.visible_confidence)
        };
        let confidence = conf_range.0 + (conf_range.1 - conf_range.0) * u_conf;
        let (mut u, mut v) = (px.x + offset.x + sigma * z_u, px.y + offset.y + sigma * z_v);
        if u_outlier < noise.outlier_probability {
            let (lo, hi) = match &noise.relative {
                Some(r) if !is_zero_pair(&r.outlier_height_fraction) => (
                    r.outlier_height_fraction[0] * height_px,
                    r.outlier_height_fraction[1] * height_px,
                ),
                _ => noise.outlier_offset_px,
            };
            let jump = lo + (hi - lo) * u_jump;
            let angle = std::f64::consts::TAU * u_angle;
            u += jump * angle.cos();
            v += jump * angle.sin();
        }
        if let Ok(k) = Keypoint2::new(u, v, confidence) {
            view.set(lm, Some(k));
        }
    }
    view
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::{Operator, Posture};
    use nalgebra::Rotation3;

    fn torso() -> Torso {
        Torso {
            base: Point3::new(0.0, 0.0, 0.9),
            R_world_trunk: Rotation3::identity(),
            length_m: 0.5,
            half_depth_m: 0.1,
            half_width_m: 0.15,
        }
    }

    #[test]
    fn the_torso_hides_what_is_behind_it() {
        let t = torso();
        let front = Point3::new(3.0, 0.0, 1.1);
        // a point behind the back, seen from the front: hidden
        assert!(torso_occludes(&t, &Point3::new(-0.2, 0.0, 1.1), &front));
        // a point in front of the chest: visible
        assert!(!torso_occludes(&t, &Point3::new(0.2, 0.0, 1.1), &front));
        // above the shoulders: visible
        assert!(!torso_occludes(
            &t,
            &Point3::new(-0.2, 0.0, 1.6),
            &Point3::new(3.0, 0.0, 1.6)
        ));
        // from the side, the far shoulder is hidden, the near one not
        let side = Point3::new(0.0, 3.0, 1.3);
        assert!(torso_occludes(&t, &Point3::new(0.0, -0.2, 1.3), &side));
        assert!(!torso_occludes(&t, &Point3::new(0.0, 0.2, 1.3), &side));
    }

    #[test]
    fn noise_parameters_are_validated() {
        assert!(DetectorNoise::default().validate().is_ok());
        assert!(DetectorNoise::none().validate().is_ok());
        let bad = DetectorNoise {
            drop_probability: 1.5,
            ..DetectorNoise::default()
        };
        assert!(bad.validate().is_err());
        let bad = DetectorNoise {
            pixel_sigma_px: f64::NAN,
            ..DetectorNoise::default()
        };
        assert!(bad.validate().is_err());
    }

    #[test]
    fn a_camera_behind_the_operator_loses_the_face() {
        let op = Operator::new(1.75).unwrap();
        let kin = op.kinematics(&Posture::default());
        let cam = crate::cameras::look_at_camera(
            "back",
            Point3::new(-3.0, 0.0, 1.6),
            Point3::new(0.0, 0.0, 1.0),
            crate::cameras::default_intrinsics(),
            crate::cameras::default_distortion(),
        )
        .unwrap();
        let noise = DetectorNoise {
            occluded_report_probability: 0.0,
            ..DetectorNoise::none()
        };
        let mut rng = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        let v = render_view(&cam, 0, 0, &kin, &noise, None, &mut rng);
        assert!(v.get(Landmark::Nose).is_none());
        assert!(v.get(Landmark::LeftShoulder).is_some());
        assert!(v.get(Landmark::LeftHeel).is_some());
    }
}
