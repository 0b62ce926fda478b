//! The twin's detector fitted to a real one.
//!
//! The real detector is measured view against view on a real recording
//! ([`ergocell_perception::detector_error`]): per landmark group, the persistent part and the jitter
//! of its error, relative to the person's image height. The twin is measured **the same way at the
//! same cameras**: a simulated person stands where the real one stood (the report's
//! [`PersonPlace`]), moving gently, seen by the real rig through the twin's detector, and the same
//! leave-one-view-out measurement runs on those detections. [`fit`] scales each group's persistent
//! and jitter σ of a [`RelativeNoise`] by the ratio of the real median to the twin's, and repeats:
//! the measurement's own biases (the other views' error in each residual, the window's share of the
//! jitter) are then the same on both sides. The fit runs on one seed; [`compare`] reports the result
//! on others.
//!
//! The fitted model is data the twin reads: [`DetectorModel`], a small TOML file
//! (`sim/detectors/`), applied to the default [`DetectorNoise`] by [`DetectorModel::apply`].

use ergocell_perception::detector_error::{
    self, DetectorErrorReport, ErrorStats, MeasureConfig, PersonPlace, GROUPS,
};
use ergocell_perception::{CameraRig, Frame2};
use nalgebra::Vector3;
use rand::SeedableRng as _;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::body::{Operator, Posture};
use crate::detector::{
    jitter_nanos, render_view, DetectorNoise, PersistentOffsets, RelativeNoise, NOISE_GROUPS,
};
use crate::SimError;

/// Format tag of a detector model file.
pub const DETECTOR_FORMAT: &str = "ergocell-detector/1";

/// A fitted detector, as the twin reads it from a file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DetectorModel {
    pub format: String,
    /// What it was fitted to and how (for people; nothing reads it).
    pub fitted_to: String,
    /// The pixel floor under the relative error (quantisation), pixels.
    pub pixel_sigma_px: f64,
    /// How much more an occluded landmark errs, from the real error of low-confidence detections.
    pub occluded_noise_scale: f64,
    /// The probability an occluded landmark is reported at all (BlazePose reports all 33: 1).
    pub occluded_report_probability: f64,
    /// The probability of a gross error per keypoint (the real share beyond 15 % of the height).
    pub outlier_probability: f64,
    /// The probability a camera's view is missing in a frame (the real frames without a person).
    pub drop_probability: f64,
    pub relative: RelativeNoise,
}

impl DetectorModel {
    /// Parses and checks a model file.
    pub fn from_toml_str(text: &str) -> Result<Self, SimError> {
        let model: Self =
            toml::from_str(text).map_err(|e| SimError::BadModel { why: e.to_string() })?;
        if model.format != DETECTOR_FORMAT {
            return Err(SimError::BadModel {
                why: format!("format `{}`, expected `{DETECTOR_FORMAT}`", model.format),
            });
        }
        model.apply(DetectorNoise::default()).validate()?;
        Ok(model)
    }

    /// The model as TOML, with a header saying what it is.
    pub fn to_toml(&self) -> Result<String, SimError> {
        let body = toml::to_string(self).map_err(|e| SimError::BadModel { why: e.to_string() })?;
        Ok(format!(
            "# The digital twin's pose-estimator model, fitted to a real detector measured view\n\
             # against view (`ergocell sim fit-detector`; docs/detector-error.md). Groups: face,\n\
             # shoulders and arms, hips, legs; sigmas per image coordinate, as fractions of the\n\
             # person's image height.\n{body}"
        ))
    }

    /// `noise` with this model's error in place of its independent pixel noise.
    pub fn apply(&self, noise: DetectorNoise) -> DetectorNoise {
        DetectorNoise {
            pixel_sigma_px: self.pixel_sigma_px,
            occluded_noise_scale: self.occluded_noise_scale,
            occluded_report_probability: self.occluded_report_probability,
            outlier_probability: self.outlier_probability,
            drop_probability: self.drop_probability,
            relative: Some(self.relative),
            ..noise
        }
    }
}

/// A person standing where `place` says, moving gently (arms, trunk, knees), seen by `rig` at
/// `rate_hz` for `frames` frames through `noise`. The world must be z-up (the twin's).
pub fn simulate_standing(
    rig: &CameraRig,
    place: &PersonPlace,
    noise: &DetectorNoise,
    rate_hz: f64,
    frames: usize,
    seed: u64,
) -> Result<Vec<Frame2>, SimError> {
    noise.validate()?;
    let up = Vector3::from(place.up);
    if up.z < 0.9 {
        return Err(SimError::BadParameter {
            name: "person up (z)",
            value: up.z,
            why: "the twin stands in a z-up world; this recording's person is not upright in it",
        });
    }
    if !(rate_hz.is_finite() && rate_hz > 0.0) {
        return Err(SimError::BadParameter {
            name: "rate_hz",
            value: rate_hz,
            why: "must be positive",
        });
    }
    // A stature whose mid-hip is as high as the real person's.
    let reference = Operator::new(1.75)?;
    let hip = |op: &Operator| {
        let k = op.kinematics(&Posture::default());
        0.5 * (k.points[23].z + k.points[24].z)
    };
    let stature = (1.75 * place.mid_hip_m[2] / hip(&reference)).clamp(1.4, 2.1);
    let person = Operator::new(stature)?;
    let heading = place.facing[1].atan2(place.facing[0]);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut persistent = noise
        .relative
        .as_ref()
        .map(|_| PersistentOffsets::new(rig.len(), seed));
    let period = (1e9 / rate_hz).round() as i64;
    let d = f64::to_radians;
    (0..frames)
        .map(|f| {
            let t_nanos = f as i64 * period;
            let t = t_nanos as f64 * 1e-9;
            let mut posture = Posture {
                position_m: [place.mid_hip_m[0], place.mid_hip_m[1]],
                heading_rad: heading,
                trunk_flexion_rad: d(6.0) * (0.3 * t).sin(),
                trunk_side_bend_rad: d(3.0) * (0.47 * t).sin(),
                ..Posture::default()
            };
            posture.left_arm.flexion_rad = d(30.0) * (0.4 * t).sin().abs();
            posture.right_arm.flexion_rad = d(30.0) * (0.4 * t + 1.3).sin().abs();
            posture.left_arm.abduction_rad = d(20.0) * (0.25 * t).sin().abs();
            posture.left_leg.knee_flexion_rad = d(10.0) * (0.5 * t).sin().abs();
            let kin = person.kinematics(&posture);
            let offsets = match (&noise.relative, &mut persistent) {
                (Some(r), Some(p)) => {
                    let centre = nalgebra::center(&kin.points[23], &kin.points[24]);
                    Some(p.at(t_nanos, r, rig.cameras(), &centre))
                }
                _ => None,
            };
            let views = rig
                .cameras()
                .iter()
                .enumerate()
                .map(|(k, camera)| {
                    let dt = jitter_nanos(noise, &mut rng);
                    render_view(
                        camera,
                        k,
                        t_nanos + dt,
                        &kin,
                        noise,
                        offsets.as_ref().and_then(|o| o.get(k)),
                        &mut rng,
                    )
                })
                .collect();
            Ok(Frame2 {
                stamp_nanos: t_nanos,
                views,
            })
        })
        .collect()
}

/// One group's real and twin error side by side.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitRow {
    pub group: String,
    pub real: ErrorStats,
    pub twin: ErrorStats,
}

impl FitRow {
    /// The largest relative gap between twin and real over the total's median and p90.
    pub fn worst_gap(&self) -> f64 {
        [
            (self.twin.total.p50, self.real.total.p50),
            (self.twin.total.p90, self.real.total.p90),
        ]
        .iter()
        .map(|(t, r)| if *r > 0.0 { (t - r).abs() / r } else { 0.0 })
        .fold(0.0, f64::max)
    }
}

/// The fitted model and how it compares.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fit {
    pub model: DetectorModel,
    /// Per group measured by the real report, on the fitting seed.
    pub rows: Vec<FitRow>,
}

/// How the twin is simulated for a fit or a comparison.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSettings {
    /// Simulated frames per seed (at the real recording's rate).
    pub frames: usize,
    /// Scaling rounds.
    pub iterations: usize,
    /// Correlation time of the landmarks' own offsets to start from, seconds; fitted to the real
    /// error's persistence ([`DetectorErrorReport::persistence`]) when it was measured at two
    /// lags at least.
    pub persistent_tau_s: f64,
    /// The pixel floor under the relative error, pixels.
    pub pixel_sigma_px: f64,
    /// Seeds the fit measures the twin on at once (from its seed on): more people's worth of
    /// offsets, a steadier fit.
    pub fit_seeds: u64,
    /// Fit an offset shared by each view's landmarks to the real per-view shift
    /// ([`RelativeNoise::view_shift_sigma`]); else every landmark's offset is its own.
    pub view_shift: bool,
    /// How alike near cameras' offsets are ([`RelativeNoise::view_correlation_deg`]); a rig of
    /// cameras far apart cannot measure it, so it is given.
    pub view_correlation_deg: f64,
}

impl Default for FitSettings {
    fn default() -> Self {
        Self {
            frames: 600,
            iterations: 6,
            persistent_tau_s: 2.0,
            pixel_sigma_px: 1.0,
            fit_seeds: 20,
            view_shift: true,
            view_correlation_deg: 0.0,
        }
    }
}

/// The twin measured like `real`, over `seeds` (each seed's session a stretch of its own, 1000 s
/// apart, so that no persistent window spans two).
fn twin_report(
    real: &DetectorErrorReport,
    rig: &CameraRig,
    noise: &DetectorNoise,
    settings: &FitSettings,
    seeds: &[u64],
) -> Result<DetectorErrorReport, SimError> {
    let place = real.person.as_ref().ok_or(SimError::BadModel {
        why: "the real report has no person place (no torso was triangulated)".to_owned(),
    })?;
    let rate = real.frame_rate_hz.unwrap_or(30.0);
    let mut frames = Vec::new();
    for (i, &seed) in seeds.iter().enumerate() {
        let shift = i as i64 * 1_000_000_000_000;
        frames.extend(
            simulate_standing(rig, place, noise, rate, settings.frames, seed)?
                .into_iter()
                .map(|mut f| {
                    f.stamp_nanos += shift;
                    for v in &mut f.views {
                        v.stamp_nanos += shift;
                    }
                    f
                }),
        );
    }
    let config = MeasureConfig {
        window_s: real.window_s,
        ..MeasureConfig::default()
    };
    Ok(detector_error::measure(rig, &frames, &config).report(rig, config.window_s))
}

fn rows(real: &DetectorErrorReport, twin: &DetectorErrorReport) -> Vec<FitRow> {
    real.groups
        .iter()
        .zip(&twin.groups)
        .map(|((name, r), (_, t))| FitRow {
            group: name.clone(),
            real: *r,
            twin: *t,
        })
        .collect()
}

/// Fits a [`RelativeNoise`] to `real` (measured on `rig`) on seeds `seed..seed + fit_seeds` (see
/// the module docs). Groups
/// the real recording did not measure keep their starting σ.
pub fn fit(
    real: &DetectorErrorReport,
    rig: &CameraRig,
    settings: &FitSettings,
    seed: u64,
) -> Result<Fit, SimError> {
    if real.groups.len() != NOISE_GROUPS || GROUPS.len() != NOISE_GROUPS {
        return Err(SimError::BadModel {
            why: format!(
                "the real report has {} landmark groups, the twin {NOISE_GROUPS}",
                real.groups.len()
            ),
        });
    }
    // Occluded (low-confidence) detections err this much more than the rest, when measured.
    let low = real.by_confidence.first().map(|b| b.total.p50);
    let occluded_noise_scale = match (low, real.confidence_error_spearman) {
        (Some(low), Some(_)) if low > 0.0 && real.all.total.p50 > 0.0 => {
            (low / real.all.total.p50).clamp(1.0, 6.0)
        }
        _ => DetectorNoise::default().occluded_noise_scale,
    };
    let fit_seeds: Vec<u64> = (0..settings.fit_seeds.max(1))
        .map(|i| seed.wrapping_add(i))
        .collect();
    let mut relative = RelativeNoise {
        persistent_sigma: [0.02; NOISE_GROUPS],
        jitter_sigma: [0.01; NOISE_GROUPS],
        persistent_tau_s: settings.persistent_tau_s,
        persistent_shape: [0.5; NOISE_GROUPS],
        view_shift_sigma: if settings.view_shift && real.view_structure.shift.count > 0 {
            0.02
        } else {
            0.0
        },
        view_shift_shape: 0.5,
        view_correlation_deg: settings.view_correlation_deg,
        // Beyond the measurement's gross-error line, as the real share was counted.
        outlier_height_fraction: [
            detector_error::GROSS_ERROR_FRACTION,
            2.0 * detector_error::GROSS_ERROR_FRACTION,
        ],
    };
    let cameras_seen: usize = real.cameras.iter().map(|c| c.frames_seen).sum();
    let cameras_missing: usize = real.cameras.iter().map(|c| c.frames_missing).sum();
    let drop_probability = cameras_missing as f64 / (cameras_seen + cameras_missing).max(1) as f64;
    let model = |relative: RelativeNoise| DetectorModel {
        format: DETECTOR_FORMAT.to_owned(),
        fitted_to: String::new(),
        pixel_sigma_px: settings.pixel_sigma_px,
        occluded_noise_scale,
        occluded_report_probability: 1.0,
        outlier_probability: real.gross_error_share.clamp(0.0, 0.2),
        drop_probability: drop_probability.clamp(0.0, 0.5),
        relative,
    };
    let scale = |real: f64, twin: f64| {
        if real > 0.0 && twin > 0.0 {
            (real / twin).clamp(0.25, 4.0)
        } else {
            1.0
        }
    };
    let spread = |q: &ergocell_perception::detector_error::Quantiles| {
        if q.p50 > 0.0 {
            (q.p90 / q.p50 - 1.0).max(1e-3)
        } else {
            1.0
        }
    };
    // The own offsets' time constant: the real error's decay over short lags, where the
    // landmark's own error dominates (at long lags what the other views' offsets leave in the
    // held-out point, a floor, does).
    if let Some(tau) = decay_time_s(&real.persistence) {
        relative.persistent_tau_s = tau.clamp(0.02, 60.0);
    }
    for _ in 0..settings.iterations {
        let noise = model(relative).apply(DetectorNoise::default());
        let report = twin_report(real, rig, &noise, settings, &fit_seeds)?;
        if relative.view_shift_sigma > 0.0 {
            // The shared offset to the real per-view shift, its shape to the shift's spread.
            let (r, t) = (&real.view_structure.shift, &report.view_structure.shift);
            relative.view_shift_sigma =
                (relative.view_shift_sigma * scale(r.p50, t.p50)).clamp(1e-4, 0.5);
            relative.view_shift_shape = (relative.view_shift_shape.max(0.02)
                * (spread(r) / spread(t)).clamp(0.5, 2.0))
            .clamp(0.0, 1.0);
        }
        for (g, ((_, r), (_, t))) in real.groups.iter().zip(&report.groups).enumerate() {
            if r.total.count == 0 {
                continue;
            }
            // The offset's size to the total's median, the jitter to the jitter's, the offset's
            // shape to the total's spread (p90 over median).
            relative.persistent_sigma[g] =
                (relative.persistent_sigma[g] * scale(r.total.p50, t.total.p50)).min(0.5);
            relative.jitter_sigma[g] =
                (relative.jitter_sigma[g] * scale(r.jitter.p50, t.jitter.p50)).min(0.5);
            relative.persistent_shape[g] = (relative.persistent_shape[g].max(0.02)
                * (spread(&r.total) / spread(&t.total)).clamp(0.5, 2.0))
            .clamp(0.0, 1.0);
        }
    }
    let noise = model(relative).apply(DetectorNoise::default());
    let twin = twin_report(real, rig, &noise, settings, &fit_seeds)?;
    Ok(Fit {
        model: model(relative),
        rows: rows(real, &twin),
    })
}

/// The twin measured like a real recording: group by group, and the structure of its views'
/// persistent offsets (which the fit does not target: a check of the model's shape).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    pub rows: Vec<FitRow>,
    pub twin_structure: detector_error::ViewStructure,
    /// How long the twin's own error lasts, measured as the real one's.
    pub twin_persistence: Vec<detector_error::LagRow>,
}

/// How fast a landmark's own error is forgotten: −1 / the slope of ln(correlation) against the lag,
/// least squares over the lags up to 0.5 s whose correlation is within 0.03..0.97 (seconds; `None`
/// with fewer than two such lags; at most 600 s when it hardly decays).
pub fn decay_time_s(persistence: &[detector_error::LagRow]) -> Option<f64> {
    let points: Vec<(f64, f64)> = persistence
        .iter()
        .filter(|l| l.lag_s <= 0.5 && (0.03..=0.97).contains(&l.correlation))
        .map(|l| (l.lag_s, l.correlation.ln()))
        .collect();
    if points.len() < 2 {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    Some(if slope < -1.0 / 600.0 {
        -1.0 / slope
    } else {
        600.0
    })
}

/// The twin with `model`, measured like `real` on `seeds` pooled (one seed: that seed's rig-worth
/// of offsets; many: the model's spread), group by group.
pub fn compare(
    real: &DetectorErrorReport,
    rig: &CameraRig,
    model: &DetectorModel,
    settings: &FitSettings,
    seeds: &[u64],
) -> Result<Comparison, SimError> {
    compare_noise(
        real,
        rig,
        &model.apply(DetectorNoise::default()),
        settings,
        seeds,
    )
}

/// The twin with `noise` (the default independent pixel noise, say) measured like `real` on
/// `seeds` pooled.
pub fn compare_noise(
    real: &DetectorErrorReport,
    rig: &CameraRig,
    noise: &DetectorNoise,
    settings: &FitSettings,
    seeds: &[u64],
) -> Result<Comparison, SimError> {
    let twin = twin_report(real, rig, noise, settings, seeds)?;
    Ok(Comparison {
        rows: rows(real, &twin),
        twin_structure: twin.view_structure,
        twin_persistence: twin.persistence,
    })
}

/// How far the twin's worst measured group is from the real recording, as a share of the real
/// figure ([`FitRow::worst_gap`] over the groups the recording measured).
pub fn worst_measured_gap(rows: &[FitRow]) -> f64 {
    rows.iter()
        .filter(|r| r.real.total.count > 0)
        .map(FitRow::worst_gap)
        .fold(0.0, f64::max)
}

/// The gap a fitted model must stay within, per measured group: 20 % of the real figure.
pub const FIT_GAP_GOAL: f64 = 0.2;

/// A fitted model judged on reporting seeds it was not fitted on: seed by seed (one rig-worth of
/// offsets each), pooled (the model's error, not one draw of its offsets), and the default
/// independent pixel noise measured the same way on the first seed, for comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Evaluation {
    pub seeds: Vec<u64>,
    /// Each reporting seed and its rows.
    pub per_seed: Vec<(u64, Vec<FitRow>)>,
    pub pooled: Comparison,
    /// The independent pixel noise's rows (first reporting seed).
    pub independent: Vec<FitRow>,
    /// On how many seeds every measured group is within [`FIT_GAP_GOAL`].
    pub seeds_within: usize,
    pub pooled_gap: f64,
    /// The seed with the largest gap, and the gap.
    pub worst_seed: (u64, f64),
}

/// Judges `model` against `real` on `seeds` (not empty) as [`Evaluation`] describes; `independent`
/// is the default noise it is compared with.
pub fn evaluate(
    real: &DetectorErrorReport,
    rig: &CameraRig,
    model: &DetectorModel,
    settings: &FitSettings,
    seeds: &[u64],
    independent: &DetectorNoise,
) -> Result<Evaluation, SimError> {
    let Some(&first) = seeds.first() else {
        return Err(SimError::BadParameter {
            name: "seeds",
            value: 0.0,
            why: "a fit is judged on at least one reporting seed",
        });
    };
    let mut per_seed = Vec::new();
    for &seed in seeds {
        per_seed.push((seed, compare(real, rig, model, settings, &[seed])?.rows));
    }
    let pooled = compare(real, rig, model, settings, seeds)?;
    let independent = compare_noise(real, rig, independent, settings, &[first])?.rows;
    let seeds_within = per_seed
        .iter()
        .filter(|(_, rows)| worst_measured_gap(rows) <= FIT_GAP_GOAL)
        .count();
    let worst_seed = per_seed
        .iter()
        .map(|(seed, rows)| (*seed, worst_measured_gap(rows)))
        .fold((first, 0.0), |w, s| if s.1 > w.1 { s } else { w });
    Ok(Evaluation {
        seeds: seeds.to_vec(),
        pooled_gap: worst_measured_gap(&pooled.rows),
        per_seed,
        pooled,
        independent,
        seeds_within,
        worst_seed,
    })
}

/// What a fitted model says it was fitted to (its `fitted_to`): the real recording (`real_label`
/// names it), its frames and rate, the cameras (`cameras` as the user named them, `camera_count` of
/// them), the seed fitted on and the fit's frames and rounds.
pub fn fitted_to(
    real_label: &str,
    real: &DetectorErrorReport,
    cameras: &str,
    camera_count: usize,
    seed: u64,
    settings: &FitSettings,
) -> String {
    format!(
        "{}: {} frames at {:.0} Hz on {} ({} cameras); fitted on seed {}, {} frames, {} rounds",
        real_label,
        real.frames,
        real.frame_rate_hz.unwrap_or(0.0),
        cameras,
        camera_count,
        seed,
        settings.frames,
        settings.iterations
    )
}

/// One reporting seed of a [`FitRecord`]: its rows and their worst measured gap.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeedRows<'a> {
    pub seed: u64,
    pub worst_gap: f64,
    pub rows: &'a [FitRow],
}

/// What `sim fit-detector` keeps of a fit (`detector_fit.json`, beside its setup): the model, the
/// seed fitted on and its rows, each reporting seed's rows, the pooled rows and their worst gap,
/// the views' structure and the error's persistence real and twin, and the independent noise's rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitRecord<'a> {
    pub model: &'a DetectorModel,
    pub fit_seed: u64,
    pub fit_rows: &'a [FitRow],
    pub report_seeds: Vec<SeedRows<'a>>,
    pub seeds_within_20_percent: usize,
    pub pooled_rows: &'a [FitRow],
    pub pooled_worst_gap: f64,
    pub real_structure: &'a detector_error::ViewStructure,
    pub twin_structure: &'a detector_error::ViewStructure,
    pub real_persistence: &'a [detector_error::LagRow],
    pub twin_persistence: &'a [detector_error::LagRow],
    pub independent_noise_rows: &'a [FitRow],
}

/// `fit` (made on `fit_seed`) against `real`, judged by `evaluation`, as [`FitRecord`] keeps it.
pub fn record<'a>(
    fit: &'a Fit,
    fit_seed: u64,
    real: &'a DetectorErrorReport,
    evaluation: &'a Evaluation,
) -> FitRecord<'a> {
    FitRecord {
        model: &fit.model,
        fit_seed,
        fit_rows: &fit.rows,
        report_seeds: evaluation
            .per_seed
            .iter()
            .map(|(seed, rows)| SeedRows {
                seed: *seed,
                worst_gap: worst_measured_gap(rows),
                rows,
            })
            .collect(),
        seeds_within_20_percent: evaluation.seeds_within,
        pooled_rows: &evaluation.pooled.rows,
        pooled_worst_gap: evaluation.pooled_gap,
        real_structure: &real.view_structure,
        twin_structure: &evaluation.pooled.twin_structure,
        real_persistence: &real.persistence,
        twin_persistence: &evaluation.pooled.twin_persistence,
        independent_noise_rows: &evaluation.independent,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cameras::{ring_rig, RingRigConfig};

    fn known() -> RelativeNoise {
        RelativeNoise {
            persistent_sigma: [0.02, 0.015, 0.025, 0.018],
            jitter_sigma: [0.004, 0.008, 0.004, 0.008],
            persistent_tau_s: 2.0,
            persistent_shape: [0.5; NOISE_GROUPS],
            view_shift_sigma: 0.0,
            view_shift_shape: 0.0,
            view_correlation_deg: 0.0,
            outlier_height_fraction: [0.0, 0.0],
        }
    }

    /// [`known`] with an offset shared by each view's landmarks.
    fn known_shifted() -> RelativeNoise {
        RelativeNoise {
            view_shift_sigma: 0.02,
            view_shift_shape: 0.5,
            ..known()
        }
    }

    /// Cameras of `rig` as a slice, for the offsets.
    fn cameras(n: usize) -> Vec<ergocell_perception::Camera> {
        ring_rig(n, &RingRigConfig::default())
            .unwrap()
            .cameras()
            .to_vec()
    }

    fn small() -> FitSettings {
        FitSettings {
            frames: 240,
            iterations: 5,
            fit_seeds: 3,
            ..FitSettings::default()
        }
    }

    /// A report of no frames at 30 Hz, nothing measured.
    fn empty_report() -> DetectorErrorReport {
        DetectorErrorReport {
            frames: 0,
            frame_rate_hz: Some(30.0),
            window_s: 1.0,
            person: None,
            all: ErrorStats::default(),
            groups: Vec::new(),
            landmarks: Vec::new(),
            cameras: Vec::new(),
            by_confidence: Vec::new(),
            by_view_angle_deg: Vec::new(),
            confidence_error_spearman: None,
            gross_error_share: 0.0,
            view_structure: detector_error::ViewStructure::default(),
            persistence: Vec::new(),
        }
    }

    /// A "real" report made by the twin itself with a known model, on seeds the fit never sees.
    fn real_from_twin(rig: &CameraRig, relative: RelativeNoise) -> DetectorErrorReport {
        let place = PersonPlace {
            mid_hip_m: [0.0, 0.0, 0.9],
            facing: [1.0, 0.0, 0.0],
            up: [0.0, 0.0, 1.0],
        };
        let skeleton = DetectorErrorReport {
            person: Some(place),
            ..empty_report()
        };
        let model = DetectorModel {
            format: DETECTOR_FORMAT.to_owned(),
            fitted_to: String::new(),
            pixel_sigma_px: 1.0,
            occluded_noise_scale: 1.0,
            occluded_report_probability: 1.0,
            outlier_probability: 0.0,
            drop_probability: 0.0,
            relative,
        };
        let noise = model.apply(DetectorNoise::default());
        twin_report(&skeleton, rig, &noise, &small(), &[900, 901, 902]).unwrap()
    }

    #[test]
    fn a_fit_to_the_twins_own_measurement_recovers_its_error() {
        let rig = ring_rig(4, &RingRigConfig::default()).unwrap();
        let real = real_from_twin(&rig, known());
        assert!(real.all.total.count > 10_000, "{:?}", real.all);
        let settings = FitSettings {
            view_shift: false,
            ..small()
        };
        let fit = fit(&real, &rig, &settings, 1).unwrap();
        // Every group's median and p90 within 20 % of the "real" on the fitting seeds…
        for row in &fit.rows {
            assert!(row.worst_gap() < 0.2, "{row:?}");
        }
        // …and the persistent σ (what the error mostly is) near the one that made it.
        for (g, (&got, &want)) in fit
            .model
            .relative
            .persistent_sigma
            .iter()
            .zip(&known().persistent_sigma)
            .enumerate()
        {
            assert!(
                (got / want - 1.0).abs() < 0.3,
                "group {g}: {got} for {want}"
            );
        }
        // On a seed the fit never saw, too.
        let rows = compare(&real, &rig, &fit.model, &small(), &[77])
            .unwrap()
            .rows;
        assert!(rows.iter().all(|r| r.worst_gap() < 0.25), "{rows:?}");
    }

    #[test]
    fn a_fit_recovers_an_offset_shared_by_each_view() {
        let rig = ring_rig(6, &RingRigConfig::default()).unwrap();
        let real = real_from_twin(&rig, known_shifted());
        let quick = FitSettings {
            frames: 150,
            iterations: 4,
            fit_seeds: 2,
            ..small()
        };
        let fit = fit(&real, &rig, &quick, 1).unwrap();
        let got = fit.model.relative.view_shift_sigma;
        assert!((got / 0.02 - 1.0).abs() < 0.3, "shared σ {got} for 0.02");
        // The landmarks' own offsets are what is left: the face's, largest, is near its own σ.
        let face = fit.model.relative.persistent_sigma[0];
        assert!(
            (face / 0.02 - 1.0).abs() < 0.4,
            "face's own σ {face} for 0.02"
        );
        // Fitted without a shared offset, the own offsets take all of it (larger than they are).
        let flat = super::fit(
            &real,
            &rig,
            &FitSettings {
                view_shift: false,
                ..quick
            },
            1,
        )
        .unwrap();
        assert_eq!(flat.model.relative.view_shift_sigma, 0.0);
        assert!(flat.model.relative.persistent_sigma[1] > 1.3 * 0.015);
    }

    #[test]
    fn near_cameras_err_alike_and_far_ones_on_their_own() {
        // Cameras 3 cm and 90° apart around a person at the origin.
        let rig = ring_rig(4, &RingRigConfig::default()).unwrap();
        let mut near = rig.cameras()[0].clone();
        let far = rig.cameras()[2].clone();
        let shift = near.T_camera_world.rotation * nalgebra::Vector3::new(0.03, 0.0, 0.0);
        near.T_camera_world.translation.vector -= shift;
        let cams = vec![rig.cameras()[0].clone(), near, far];
        let centre = nalgebra::Point3::new(0.0, 0.0, 0.9);
        let noise = RelativeNoise {
            view_correlation_deg: 10.0,
            ..known_shifted()
        };
        let (mut near_gap, mut far_gap, mut size) = (0.0, 0.0, 0.0);
        for seed in 0..20 {
            let mut offsets = PersistentOffsets::new(3, seed);
            let o = offsets.at(0, &noise, &cams, &centre);
            for l in 0..33 {
                near_gap += (o[0][l] - o[1][l]).norm();
                far_gap += (o[0][l] - o[2][l]).norm();
                size += o[0][l].norm();
            }
        }
        assert!(near_gap < 0.1 * size, "near {near_gap} of {size}");
        assert!(far_gap > 0.8 * size, "far {far_gap} of {size}");
        // Independent (0°): the near camera's offsets are its own.
        let mut offsets = PersistentOffsets::new(3, 1);
        let o = offsets.at(0, &known_shifted(), &cams, &centre);
        let gap: f64 = (0..33).map(|l| (o[0][l] - o[1][l]).norm()).sum();
        let own: f64 = (0..33).map(|l| o[0][l].norm()).sum();
        assert!(gap > 0.8 * own, "{gap} {own}");
    }

    #[test]
    fn a_model_file_round_trips_and_bad_ones_are_refused() {
        let model = DetectorModel {
            format: DETECTOR_FORMAT.to_owned(),
            fitted_to: "a test".to_owned(),
            pixel_sigma_px: 1.0,
            occluded_noise_scale: 1.8,
            occluded_report_probability: 1.0,
            outlier_probability: 0.02,
            drop_probability: 0.0,
            relative: known(),
        };
        let text = model.to_toml().unwrap();
        assert_eq!(DetectorModel::from_toml_str(&text).unwrap(), model);
        let other = text.replace("ergocell-detector/1", "ergocell-detector/9");
        assert!(DetectorModel::from_toml_str(&other)
            .unwrap_err()
            .to_string()
            .contains("ergocell-detector/9"));
        let nan = text.replace("persistent_tau_s = 2.0", "persistent_tau_s = nan");
        assert!(DetectorModel::from_toml_str(&nan).is_err());
        let shape = text.replace("persistent_shape = [0.5,", "persistent_shape = [1.5,");
        assert_ne!(shape, text);
        assert!(DetectorModel::from_toml_str(&shape).is_err());
        assert!(DetectorModel::from_toml_str("format = ").is_err());
    }

    #[test]
    fn a_fixed_length_offset_has_its_length_and_a_gaussian_one_its_spread() {
        let mut fixed = known();
        fixed.persistent_shape = [0.0; NOISE_GROUPS];
        let mut offsets = PersistentOffsets::new(3, 5);
        let cams = cameras(3);
        let centre = nalgebra::Point3::new(0.0, 0.0, 0.9);
        for step in 0..50 {
            for camera in offsets.at(step * 100_000_000, &fixed, &cams, &centre) {
                for (l, o) in camera.iter().enumerate() {
                    let want = fixed.persistent_sigma[crate::detector::noise_group(l)] * 1.2533;
                    assert!(
                        (o.norm() - want).abs() < 1e-4 * want.max(1e-9) + 1e-9,
                        "{o:?}"
                    );
                }
            }
        }
        // Shape 1: Gaussian, σ per coordinate over many cameras and landmarks.
        let mut gaussian = known();
        gaussian.persistent_shape = [1.0; NOISE_GROUPS];
        let mut offsets = PersistentOffsets::new(64, 6);
        let cams = cameras(64);
        let face: Vec<f64> = offsets
            .at(0, &gaussian, &cams, &centre)
            .iter()
            .flat_map(|c| c[..=10].iter().flat_map(|o| [o.x, o.y]))
            .collect();
        let sd = (face.iter().map(|x| x * x).sum::<f64>() / face.len() as f64).sqrt();
        assert!((sd / 0.02 - 1.0).abs() < 0.08, "{sd}");
    }

    #[test]
    fn fitted_to_names_the_recording_the_cameras_and_the_fit() {
        let real = DetectorErrorReport {
            frames: 1234,
            frame_rate_hz: Some(29.97),
            ..empty_report()
        };
        assert_eq!(
            fitted_to("real.json", &real, "calib.toml", 4, 7, &small()),
            "real.json: 1234 frames at 30 Hz on calib.toml (4 cameras); fitted on seed 7, 240 frames, 5 rounds"
        );
        let unknown_rate = DetectorErrorReport {
            frame_rate_hz: None,
            ..real
        };
        assert!(fitted_to("r", &unknown_rate, "6", 6, 1, &small()).contains(" at 0 Hz on 6 "));
    }

    #[test]
    fn a_record_keeps_each_reporting_seed_with_its_own_worst_gap() {
        let stats = |p50: f64| {
            let mut s = ErrorStats::default();
            s.total.count = 10;
            s.total.p50 = p50;
            s.total.p90 = 2.0 * p50;
            s
        };
        let row = |real: f64, twin: f64| FitRow {
            group: "face".to_owned(),
            real: stats(real),
            twin: stats(twin),
        };
        let fit = Fit {
            model: DetectorModel {
                format: DETECTOR_FORMAT.to_owned(),
                fitted_to: String::new(),
                pixel_sigma_px: 1.0,
                occluded_noise_scale: 1.0,
                occluded_report_probability: 1.0,
                outlier_probability: 0.0,
                drop_probability: 0.0,
                relative: known(),
            },
            rows: vec![row(0.02, 0.021)],
        };
        let (near, far) = (vec![row(0.02, 0.022)], vec![row(0.02, 0.03)]);
        let comparison = Comparison {
            rows: vec![row(0.02, 0.025)],
            twin_structure: detector_error::ViewStructure::default(),
            twin_persistence: Vec::new(),
        };
        let evaluation = Evaluation {
            seeds: vec![101, 102],
            per_seed: vec![(101, near), (102, far)],
            pooled: comparison,
            independent: vec![row(0.02, 0.01)],
            seeds_within: 1,
            pooled_gap: 0.25,
            worst_seed: (102, 0.5),
        };
        let real = empty_report();
        let r = record(&fit, 5, &real, &evaluation);
        assert_eq!(r.fit_seed, 5);
        assert_eq!(r.report_seeds.len(), 2);
        assert_eq!(r.report_seeds[1].seed, 102);
        assert!((r.report_seeds[0].worst_gap - 0.1).abs() < 1e-12);
        assert!((r.report_seeds[1].worst_gap - 0.5).abs() < 1e-12);
        assert_eq!(r.report_seeds[1].rows, &evaluation.per_seed[1].1[..]);
        assert_eq!(r.independent_noise_rows, &evaluation.independent[..]);
        // the file's keys, as `detector_fit.json` has always held them
        let v = serde_json::to_value(&r).unwrap();
        let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
        assert_eq!(
            keys,
            [
                "fit_rows",
                "fit_seed",
                "independent_noise_rows",
                "model",
                "pooled_rows",
                "pooled_worst_gap",
                "real_persistence",
                "real_structure",
                "report_seeds",
                "seeds_within_20_percent",
                "twin_persistence",
                "twin_structure"
            ]
        );
    }
}
