//! Whether the stated band probabilities are right: a reliability table of the controller's
//! per-region band probabilities ([`ergocell_ergonomics::confidence`]) against the truth, and the fit
//! of the confidence model's scale and floor on tuning seeds.
//!
//! Each sample is one region of one judged side ([`ergocell_ergonomics::warnings::judged`]) of one
//! frame at the station that the controller scored with a probability: the probability it stated,
//! and whether the truth's angle falls in the same band (the region's score at the truth's angle,
//! with the controller's worksheet adjustments held, equals the one at the controller's angle).
//!
//! - **Reliability.** Samples are binned by their stated probability in tenths; per bin, the mean
//!   stated probability against the share that was right. A bin of at least
//!   [`MIN_BIN_SAMPLES`] samples is calibrated when the two are within [`CALIBRATION_TOLERANCE`];
//!   of the samples stated at least [`SURE_PROBABILITY`] sure, at least that share must be right.
//! - **The fit.** Per region, the scale `k` and floor `f` of `σ = sqrt((k·σₚ)² + f²)` that minimise
//!   the log loss of the normal mass against the truth (a grid: the same samples, every candidate),
//!   then the recalibration: per bin of the mass, its mean against the share right, made monotone
//!   (pool adjacent violators); on the tuning seeds only, every [`FIT_STRIDE`]-th sample.

use ergocell_ergonomics::assess::{BodyRegion, FrameAssessment};
use ergocell_ergonomics::confidence::{
    band_probability, identity_recalibration, ConfidenceModel, ANGLED_REGIONS, RECALIBRATION_BINS,
    RECALIBRATION_EDGES, SURE_PROBABILITY,
};
use ergocell_ergonomics::rula::RulaInput;
use ergocell_ergonomics::warnings::{judged, region_angle, region_score_at};
use serde::Serialize;

/// A bin is judged only with at least this many samples.
pub const MIN_BIN_SAMPLES: usize = 500;
/// A judged bin's mean stated probability and observed share may differ by at most this.
pub const CALIBRATION_TOLERANCE: f64 = 0.05;
/// One in this many samples is kept for the fit.
pub const FIT_STRIDE: usize = 7;
/// Bins of the reliability table, tenths of probability.
const BINS: usize = 10;

/// One region of one frame, as the fit needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandSample {
    pub region: BodyRegion,
    /// The controller's worksheet (its adjustments are held when the truth's angle is scored).
    pub input: RulaInput,
    /// The controller's angle, degrees.
    pub angle_deg: f64,
    /// The spread propagated from the landmarks, degrees.
    pub propagated_sd_deg: f64,
    /// The truth's angle, degrees.
    pub truth_deg: f64,
}

impl BandSample {
    /// Whether the truth's angle scores the band the controller's did.
    pub fn right(&self) -> bool {
        region_score_at(self.region, &self.input, Some(self.truth_deg))
            == region_score_at(self.region, &self.input, Some(self.angle_deg))
    }
}

/// One bin of the reliability table.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ReliabilityBin {
    /// Stated probabilities in `[lo, hi)` (the last bin includes 1).
    pub lo: f64,
    pub hi: f64,
    pub samples: usize,
    /// Sum of the stated probabilities (the mean is `stated_sum / samples`).
    pub stated_sum: f64,
    /// Samples whose band was right.
    pub right: usize,
}

impl ReliabilityBin {
    /// The mean stated probability (NaN when empty).
    pub fn stated(&self) -> f64 {
        self.stated_sum / self.samples as f64
    }

    /// The share that was right (NaN when empty).
    pub fn observed(&self) -> f64 {
        self.right as f64 / self.samples as f64
    }

    /// Judged (enough samples) and within the tolerance.
    pub fn calibrated(&self) -> Option<bool> {
        (self.samples >= MIN_BIN_SAMPLES)
            .then(|| (self.stated() - self.observed()).abs() <= CALIBRATION_TOLERANCE)
    }
}

/// The reliability of the stated band probabilities.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reliability {
    pub bins: Vec<ReliabilityBin>,
    /// Samples stated at least [`SURE_PROBABILITY`] sure, and of them, right.
    pub sure: usize,
    pub sure_right: usize,
    /// Per region ([`ANGLED_REGIONS`] order): samples and right ones, whatever was stated.
    pub region_samples: Vec<usize>,
    pub region_right: Vec<usize>,
}

impl Default for Reliability {
    fn default() -> Self {
        Self {
            bins: (0..BINS)
                .map(|i| ReliabilityBin {
                    lo: i as f64 / BINS as f64,
                    hi: (i + 1) as f64 / BINS as f64,
                    ..ReliabilityBin::default()
                })
                .collect(),
            sure: 0,
            sure_right: 0,
            region_samples: vec![0; ANGLED_REGIONS.len()],
            region_right: vec![0; ANGLED_REGIONS.len()],
        }
    }
}

impl Reliability {
    /// Counts one sample: the probability stated and whether the band was right.
    pub fn add(&mut self, region: BodyRegion, stated: f64, right: bool) {
        let bin = ((stated * BINS as f64).floor() as usize).min(BINS - 1);
        let b = &mut self.bins[bin];
        b.samples += 1;
        b.stated_sum += stated;
        b.right += usize::from(right);
        if stated >= SURE_PROBABILITY {
            self.sure += 1;
            self.sure_right += usize::from(right);
        }
        if let Some(i) = ConfidenceModel::slot(region) {
            self.region_samples[i] += 1;
            self.region_right[i] += usize::from(right);
        }
    }

    /// Adds another table's counts.
    pub fn merge(&mut self, other: &Reliability) {
        for (a, b) in self.bins.iter_mut().zip(&other.bins) {
            a.samples += b.samples;
            a.stated_sum += b.stated_sum;
            a.right += b.right;
        }
        self.sure += other.sure;
        self.sure_right += other.sure_right;
        for (a, b) in self.region_samples.iter_mut().zip(&other.region_samples) {
            *a += b;
        }
        for (a, b) in self.region_right.iter_mut().zip(&other.region_right) {
            *a += b;
        }
    }

    /// The share right of the samples stated at least 90 % sure (NaN without one).
    pub fn sure_share(&self) -> f64 {
        self.sure_right as f64 / self.sure as f64
    }

    /// The bins judged and off by more than the tolerance, in words (empty: calibrated).
    pub fn miscalibrated(&self) -> Vec<String> {
        self.bins
            .iter()
            .filter(|b| b.calibrated() == Some(false))
            .map(|b| {
                format!(
                    "{:.1}–{:.1}: stated {:.3}, observed {:.3} ({} samples)",
                    b.lo,
                    b.hi,
                    b.stated(),
                    b.observed(),
                    b.samples
                )
            })
            .collect()
    }
}

/// The samples of one controller frame against the truth's frame: every angled region of every
/// judged side that carries a probability.
pub fn frame_samples(
    controller: &FrameAssessment,
    truth: &FrameAssessment,
) -> Vec<(BandSample, f64)> {
    let mut out = Vec::new();
    for region in ANGLED_REGIONS {
        for (side, a) in judged(controller, region) {
            let Some(c) = a.confidence.get(region) else {
                continue;
            };
            let truth_side = match side {
                Some(s) => truth.side(s),
                None => truth.headline(),
            };
            let (Some(angle_deg), Some(truth_deg)) = (
                region_angle(region, &a.input),
                truth_side.and_then(|t| region_angle(region, &t.input)),
            ) else {
                continue;
            };
            out.push((
                BandSample {
                    region,
                    input: a.input,
                    angle_deg,
                    propagated_sd_deg: c.propagated_sd_deg,
                    truth_deg,
                },
                c.probability,
            ));
        }
    }
    out
}

/// The log loss of stating `p` for an outcome (clamped away from 0 and 1).
fn log_loss(p: f64, right: bool) -> f64 {
    let p = p.clamp(1e-6, 1.0 - 1e-6);
    -if right { p.ln() } else { (1.0 - p).ln() }
}

/// The scales tried by the fit.
const FIT_SCALES: [f64; 11] = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0];
/// The floors tried by the fit, degrees.
const FIT_FLOORS_DEG: [f64; 16] = [
    0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0,
];

/// A recalibration bin is fitted from at least this many samples (else the identity there).
pub const MIN_RECALIBRATION_SAMPLES: usize = 100;

/// The recalibration points of `(mass, right)` samples: per bin of [`RECALIBRATION_EDGES`], the
/// mean mass against the share right (the identity point for a bin of fewer than
/// [`MIN_RECALIBRATION_SAMPLES`]), the shares then made non-decreasing by pooling adjacent
/// violators, each bin weighted by its samples.
pub fn fit_recalibration(samples: &[(f64, bool)]) -> [[f64; 2]; RECALIBRATION_BINS] {
    let mut n = [0usize; RECALIBRATION_BINS];
    let mut mass = [0.0; RECALIBRATION_BINS];
    let mut right = [0usize; RECALIBRATION_BINS];
    for &(p, r) in samples {
        let bin = RECALIBRATION_EDGES[1..]
            .iter()
            .position(|e| p < *e)
            .unwrap_or(RECALIBRATION_BINS - 1);
        n[bin] += 1;
        mass[bin] += p;
        right[bin] += usize::from(r);
    }
    let mut points = identity_recalibration();
    let mut weight = [1.0; RECALIBRATION_BINS];
    for i in 0..RECALIBRATION_BINS {
        if n[i] >= MIN_RECALIBRATION_SAMPLES {
            points[i] = [mass[i] / n[i] as f64, right[i] as f64 / n[i] as f64];
            weight[i] = n[i] as f64;
        }
    }
    // pool adjacent violators: blocks of bins sharing one share, their weighted mean
    let mut blocks: Vec<(f64, f64, usize)> = Vec::new(); // (share, weight, bins)
    for i in 0..RECALIBRATION_BINS {
        blocks.push((points[i][1], weight[i], 1));
        while blocks.len() > 1 {
            let (b, a) = (blocks[blocks.len() - 1], blocks[blocks.len() - 2]);
            if a.0 <= b.0 {
                break;
            }
            blocks.pop();
            blocks.pop();
            let w = a.1 + b.1;
            blocks.push(((a.0 * a.1 + b.0 * b.1) / w, w, a.2 + b.2));
        }
    }
    let mut i = 0;
    for (share, _, bins) in blocks {
        for _ in 0..bins {
            points[i][1] = share;
            i += 1;
        }
    }
    points
}

/// Each angled region's root-mean-square reading error (the controller's angle minus the truth's),
/// degrees, in [`ANGLED_REGIONS`] order over `samples`; `None` for a region without samples. What a
/// design that must keep its postures measurable ([`crate::design`]) takes as the reading's spread.
pub fn read_error_rms_deg(samples: &[BandSample]) -> [Option<f64>; 5] {
    let mut sum = [(0.0, 0usize); 5];
    for s in samples {
        if let Some(i) = ConfidenceModel::slot(s.region) {
            let e = s.angle_deg - s.truth_deg;
            if e.is_finite() {
                sum[i].0 += e * e;
                sum[i].1 += 1;
            }
        }
    }
    sum.map(|(sq, n)| (n > 0).then(|| (sq / n as f64).sqrt()))
}

/// The confidence model that minimises each region's log loss over `samples` (a grid of scales and
/// floors; a region without samples keeps `start`'s values). Also returns each region's sample
/// count.
pub fn fit(samples: &[BandSample], start: &ConfidenceModel) -> (ConfidenceModel, Vec<usize>) {
    let mut model = *start;
    let mut counts = vec![0; ANGLED_REGIONS.len()];
    for (i, region) in ANGLED_REGIONS.iter().enumerate() {
        let mine: Vec<(&BandSample, bool)> = samples
            .iter()
            .filter(|s| s.region == *region)
            .map(|s| (s, s.right()))
            .collect();
        counts[i] = mine.len();
        if mine.is_empty() {
            continue;
        }
        let mut best = (f64::INFINITY, model.scale[i], model.floor_rad[i]);
        for k in FIT_SCALES {
            for f_deg in FIT_FLOORS_DEG {
                let loss: f64 = mine
                    .iter()
                    .map(|(s, right)| {
                        let sd = ((k * s.propagated_sd_deg).powi(2) + f_deg * f_deg).sqrt();
                        log_loss(
                            band_probability(s.region, &s.input, s.angle_deg, sd),
                            *right,
                        )
                    })
                    .sum();
                if loss < best.0 {
                    best = (loss, k, f_deg.to_radians());
                }
            }
        }
        model.scale[i] = best.1;
        model.floor_rad[i] = best.2;
        let f_deg = best.2.to_degrees();
        let masses: Vec<(f64, bool)> = mine
            .iter()
            .map(|(s, right)| {
                let sd = ((best.1 * s.propagated_sd_deg).powi(2) + f_deg * f_deg).sqrt();
                (
                    band_probability(s.region, &s.input, s.angle_deg, sd),
                    *right,
                )
            })
            .collect();
        model.recalibration[i] = fit_recalibration(&masses);
    }
    (model, counts)
}

/// The confidence model fitted to a set of samples ([`fit`]), with what the report says of it.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfidenceFit {
    pub model: ConfidenceModel,
    /// Samples per angled region, [`ANGLED_REGIONS`] order.
    pub counts: Vec<usize>,
    /// Each angled region's reading error RMS, degrees ([`read_error_rms_deg`]).
    pub read_error_rms_deg: [Option<f64>; 5],
}

/// [`fit`] of `samples` from `start`, with the samples' reading errors.
pub fn fit_confidence(samples: &[BandSample], start: &ConfidenceModel) -> ConfidenceFit {
    let (model, counts) = fit(samples, start);
    ConfidenceFit {
        model,
        counts,
        read_error_rms_deg: read_error_rms_deg(samples),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bin_is_judged_from_500_samples_and_the_sure_share_counts_from_90_percent() {
        let mut r = Reliability::default();
        // 600 samples stated 0.95 sure, 540 of them right: observed 0.90, off by 0.05 — calibrated
        for k in 0..600 {
            r.add(BodyRegion::Neck, 0.95, k < 540);
        }
        // 100 samples stated 0.35, all wrong: too few to judge
        for _ in 0..100 {
            r.add(BodyRegion::Trunk, 0.35, false);
        }
        assert_eq!(r.bins[9].samples, 600);
        assert_eq!(r.bins[9].calibrated(), Some(true));
        assert_eq!(r.bins[3].calibrated(), None);
        assert_eq!((r.sure, r.sure_right), (600, 540));
        assert!((r.sure_share() - 0.9).abs() < 1e-12);
        assert!(r.miscalibrated().is_empty());
        // 61 more wrong ones at 0.95: observed 540/661 = 0.817, off by 0.13
        for _ in 0..61 {
            r.add(BodyRegion::Neck, 0.95, false);
        }
        assert_eq!(r.bins[9].calibrated(), Some(false));
        assert_eq!(r.miscalibrated().len(), 1);
        let mut pooled = Reliability::default();
        pooled.merge(&r);
        pooled.merge(&r);
        assert_eq!(pooled.bins[9].samples, 2 * 661);
        assert_eq!(pooled.region_samples[3], 2 * 661);
        // a probability of exactly 1 lands in the last bin
        pooled.add(BodyRegion::Neck, 1.0, true);
        assert_eq!(pooled.bins[9].samples, 2 * 661 + 1);
    }

    #[test]
    fn the_fit_finds_the_spread_the_errors_were_drawn_with() {
        use rand::{Rng, SeedableRng};
        use rand_distr::{Distribution, Normal};
        // neck angles spread over its bands, truth = angle + N(0, 6°): the fit picks a spread near 6°
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let noise = Normal::new(0.0, 6.0).unwrap();
        let samples: Vec<BandSample> = (0..4000)
            .map(|_| {
                let truth: f64 = rng.random_range(-10.0..40.0);
                BandSample {
                    region: BodyRegion::Neck,
                    input: RulaInput::neutral(),
                    angle_deg: truth + noise.sample(&mut rng),
                    propagated_sd_deg: 0.0,
                    truth_deg: truth,
                }
            })
            .collect();
        let (model, counts) = fit(&samples, &ConfidenceModel::default());
        assert_eq!(counts[3], 4000);
        // the reading error's RMS is the drawn spread, and only the neck has one
        let rms = read_error_rms_deg(&samples);
        let neck = rms[3].unwrap();
        assert!((neck - 6.0).abs() < 0.3, "RMS {neck}°");
        assert!(rms.iter().enumerate().all(|(i, r)| (i == 3) == r.is_some()));
        let floor = model.floor_rad[3].to_degrees();
        assert!((5.0..=7.0).contains(&floor), "fitted floor {floor}°");
        // the other regions had no samples: unchanged
        assert_eq!(model.floor_rad[0], ConfidenceModel::default().floor_rad[0]);
        // the spread is right, but the truths are spread evenly: a mass near ½ (an angle on an
        // edge) is right about as often as it says, so the recalibration stays near the identity
        for [mass, stated] in model.recalibration[3] {
            assert!((stated - mass).abs() < 0.08, "{:?}", model.recalibration[3]);
        }
    }

    #[test]
    fn the_recalibration_maps_each_bin_to_its_share_right_and_never_falls() {
        let mut samples = Vec::new();
        // 200 samples at mass 0.55, 150 right (0.75); 200 at 0.65, 120 right (0.6: a violator)
        samples.extend((0..200).map(|k| (0.55, k < 150)));
        samples.extend((0..200).map(|k| (0.65, k < 120)));
        // 50 at 0.75: too few, the identity point
        samples.extend((0..50).map(|k| (0.75, k < 10)));
        let points = fit_recalibration(&samples);
        // the two violating bins pooled: (150 + 120) / 400
        assert!((points[1][1] - 0.675).abs() < 1e-12, "{points:?}");
        assert!((points[2][1] - 0.675).abs() < 1e-12);
        assert!((points[1][0] - 0.55).abs() < 1e-12);
        // the thin bin keeps its middle, 0.75
        assert!((points[3][0] - 0.75).abs() < 1e-12 && (points[3][1] - 0.75).abs() < 1e-12);
        assert!(points.windows(2).all(|w| w[0][1] <= w[1][1]));
        let mut model = ConfidenceModel::default();
        model.recalibration[0] = points;
        assert!(model.validate().is_ok());
    }

    #[test]
    fn without_samples_the_fit_keeps_its_start_and_states_no_reading_error() {
        let start = ConfidenceModel::default();
        let f = fit_confidence(&[], &start);
        assert_eq!(f.model, start);
        assert_eq!(f.counts, vec![0; ANGLED_REGIONS.len()]);
        assert_eq!(f.read_error_rms_deg, [None; 5]);
        // one trunk sample 3° off: the trunk's count and error, nobody else's
        let trunk = BandSample {
            region: BodyRegion::Trunk,
            input: RulaInput::neutral(),
            angle_deg: 13.0,
            propagated_sd_deg: 1.0,
            truth_deg: 10.0,
        };
        let f = fit_confidence(&[trunk], &start);
        let i = ConfidenceModel::slot(BodyRegion::Trunk).unwrap();
        assert_eq!(f.counts[i], 1);
        assert_eq!(f.counts.iter().sum::<usize>(), 1);
        assert!((f.read_error_rms_deg[i].unwrap() - 3.0).abs() < 1e-12);
        assert_eq!(f.read_error_rms_deg.iter().flatten().count(), 1);
    }
}
