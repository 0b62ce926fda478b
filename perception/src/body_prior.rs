//! A body-model prior for fusion: the operator's bones do not change length during a session, and
//! the face landmarks (ears, eyes, nose, mouth) sit on one rigid skull.
//!
//! Each landmark triangulated by the [`crate::triangulation::RobustTriangulator`] comes with an
//! information matrix `Λ` that says how well the cameras pin it down in each direction — for a point
//! seen along nearly parallel rays, depth is poorly known. The skeleton knows more: the distance
//! between shoulder and elbow is the same in every frame. This module learns each rigid bone's length
//! causally (the median of the lengths triangulated so far in the session, before any correction,
//! freed of the lengthening that noise across the bone causes: [`BonePrior::length_m`]) and then,
//! per frame, solves
//!
//! `min Σ_i (x_i − x̂_i)ᵀ Λ_i (x_i − x̂_i) + Σ_bones (‖x_a − x_b‖ − L_ab)² / σ_L²`
//!
//! by block Gauss–Seidel (each landmark's 3×3 Gauss–Newton step with its neighbours fixed, a few
//! sweeps). The rigid pairs are the limb and trunk bones of [`BONES`] and nineteen head pairs: the ears
//! are occluded in most views (a detector still reports them, with low confidence and large errors),
//! and the neck angle RULA scores hangs on them; the skull's distances hold them to the nose, eyes and
//! mouth. Every one of the seven face landmarks is tied to at least five others, so the face is a rigid
//! graph (7 points have 15 shape degrees of freedom; 19 distances fix them) and a badly seen ear is
//! placed by where the well-seen eyes, nose and mouth put the skull. (On the digital twin at 3 px the
//! neck flexion's error s.d. went from 3.4° with nine head pairs to 2.0°.) Likewise each hand's wrist,
//! index, pinky and thumb (all six pairs): the wrist angles RULA scores hang on landmarks 2–8 cm
//! apart (twin, 3 px: the working wrist's deviation error s.d. 8.8° → 4.3°). A real hand is less
//! rigid than the twin's — fingers closing on a part shorten the wrist–finger distances — which the
//! prior's softness (`sigma_m`) and its sliding median only partly absorb.
//! Directions the cameras measure well hardly move; poorly measured directions are pulled
//! to a configuration with consistent bone lengths. With exact measurements every bone already has its
//! learned length and nothing moves. Causal (uses only past and present frames) and deterministic.
//!
//! This is the anthropometric-model step that marker-less motion capture pipelines perform offline
//! (scaled rigid-segment models in OpenSim inverse kinematics), done online and softly.

use std::collections::VecDeque;

use ergocell_skeleton::{Landmark, BONES, LANDMARK_COUNT};
use nalgebra::{Matrix3, Point3, Vector3};

use crate::triangulation::Sym3;

/// Landmark pairs whose distance the prior keeps: the rigid limb and trunk bones of [`BONES`], and
/// the head (ears, eyes, nose and mouth are fixed on the skull).
const RIGID: [(Landmark, Landmark); 43] = {
    use Landmark as L;
    [
        BONES[0],
        BONES[1],
        BONES[2],
        BONES[3],
        BONES[4],
        BONES[5],
        BONES[6],
        BONES[7],
        BONES[8],
        BONES[9],
        BONES[10],
        BONES[11],
        (L::LeftEar, L::RightEar),
        (L::Nose, L::LeftEar),
        (L::Nose, L::RightEar),
        (L::LeftEye, L::RightEye),
        (L::LeftEye, L::LeftEar),
        (L::RightEye, L::RightEar),
        (L::MouthLeft, L::MouthRight),
        (L::Nose, L::MouthLeft),
        (L::Nose, L::MouthRight),
        (L::LeftEar, L::RightEye),
        (L::RightEar, L::LeftEye),
        (L::LeftEar, L::MouthLeft),
        (L::RightEar, L::MouthRight),
        (L::LeftEye, L::MouthLeft),
        (L::RightEye, L::MouthRight),
        (L::Nose, L::LeftEye),
        (L::Nose, L::RightEye),
        (L::LeftEar, L::MouthRight),
        (L::RightEar, L::MouthLeft),
        (L::LeftWrist, L::LeftIndex),
        (L::LeftWrist, L::LeftPinky),
        (L::LeftWrist, L::LeftThumb),
        (L::LeftIndex, L::LeftPinky),
        (L::LeftIndex, L::LeftThumb),
        (L::LeftPinky, L::LeftThumb),
        (L::RightWrist, L::RightIndex),
        (L::RightWrist, L::RightPinky),
        (L::RightWrist, L::RightThumb),
        (L::RightIndex, L::RightPinky),
        (L::RightIndex, L::RightThumb),
        (L::RightPinky, L::RightThumb),
    ]
};

/// The landmarks (MediaPipe indices) that are an end of some pair in [`RIGID`].
const BONE_LANDMARKS: [usize; 25] = [
    0, 2, 5, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
];

/// Settings of the bone-length prior.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BonePriorParams {
    /// Standard deviation of a bone's length about its learned value, metres (how much the joint
    /// centres a detector reports may wander along the bone).
    pub sigma_m: f64,
    /// Lengths needed before a bone's prior is used.
    pub min_samples: usize,
    /// Most recent lengths kept per bone (the median is over these).
    pub window: usize,
    /// Gauss–Seidel sweeps per frame.
    pub sweeps: usize,
}

impl Default for BonePriorParams {
    /// 1.5 cm about the median of the last 600 frames (20 s at 30 Hz), used from the 10th frame on;
    /// 6 sweeps (the caliscope figures change by < 0.02 percentage points beyond that).
    fn default() -> Self {
        Self {
            sigma_m: 0.015,
            min_samples: 10,
            window: 600,
            sweeps: 6,
        }
    }
}

/// How many of the sorted `values` are `≤ x`: where `x` goes after its equals. The same number
/// as `partition_point(|v| *v <= x)`, counted in one pass the compiler vectorizes (a binary search
/// is a chain of dependent loads: it was most of [`BonePrior::observe`]'s time).
fn count_le(values: &[f64], x: f64) -> usize {
    values.iter().map(|v| usize::from(*v <= x)).sum()
}

/// A multiset of lengths kept sorted in blocks of at most [`SortedWindow::MAX_BLOCK`] values: an
/// insertion or removal moves at most one block's values (≤ 512 bytes) rather than half the window
/// (a window of 600 in one sorted `Vec` moved ≈ 2.4 kB per insertion and per removal, 43 pairs of
/// each per frame: 17 % of the fusion's time); the median walks the blocks' lengths.
#[derive(Debug, Clone, Default)]
struct SortedWindow {
    /// Globally sorted: every value of block `k` ≤ every value of block `k + 1`; no block empty.
    blocks: Vec<Vec<f64>>,
    /// `blocks[k]`'s last (largest) value, side by side so a search touches one array.
    lasts: Vec<f64>,
    /// Emptied blocks kept for reuse (no allocation once the window is warm).
    spare: Vec<Vec<f64>>,
    len: usize,
}

impl SortedWindow {
    const MAX_BLOCK: usize = 64;

    fn len(&self) -> usize {
        self.len
    }

    fn insert(&mut self, x: f64) {
        if self.blocks.is_empty() {
            let mut b = self.spare.pop().unwrap_or_default();
            b.push(x);
            self.blocks.push(b);
            self.lasts.push(x);
            self.len = 1;
            return;
        }
        // after any equal values (a bone's length repeats exactly when a frame does): the last
        // block they reach, at its end — no values moved
        let k = count_le(&self.lasts, x).min(self.blocks.len() - 1);
        let block = &mut self.blocks[k];
        let at = count_le(block, x);
        block.insert(at, x);
        self.len += 1;
        if block.len() > Self::MAX_BLOCK {
            let mut upper = self.spare.pop().unwrap_or_default();
            upper.extend_from_slice(&block[Self::MAX_BLOCK / 2..]);
            block.truncate(Self::MAX_BLOCK / 2);
            let lower_last = block[Self::MAX_BLOCK / 2 - 1];
            let upper_last = upper[upper.len() - 1];
            self.blocks.insert(k + 1, upper);
            self.lasts[k] = lower_last;
            self.lasts.insert(k + 1, upper_last);
        } else {
            self.lasts[k] = block[block.len() - 1];
        }
    }

    /// Removes one copy of `x` (the last, so a run of equal values loses its end and nothing
    /// moves); false (nothing removed) when `x` is not held.
    fn remove(&mut self, x: f64) -> bool {
        // blocks before `k` end at or below x: the last copy is in block k or ends block k − 1
        let k = count_le(&self.lasts, x);
        let found = self
            .blocks
            .get(k)
            .and_then(|b| {
                let i = count_le(b, x);
                (i > 0 && b[i - 1] == x).then(|| (k, i - 1))
            })
            .or_else(|| {
                let prev = k.checked_sub(1)?;
                (self.lasts[prev] == x).then(|| (prev, self.blocks[prev].len() - 1))
            });
        let Some((k, i)) = found else {
            return false;
        };
        let block = &mut self.blocks[k];
        block.remove(i);
        self.len -= 1;
        if let Some(last) = block.last() {
            self.lasts[k] = *last;
        } else {
            let empty = self.blocks.remove(k);
            self.lasts.remove(k);
            self.spare.push(empty);
        }
        true
    }

    /// The `k`-th smallest value (0-based).
    fn nth(&self, mut k: usize) -> Option<f64> {
        for b in &self.blocks {
            if k < b.len() {
                return Some(b[k]);
            }
            k -= b.len();
        }
        None
    }

    /// The median (mean of the two middle values for an even count).
    fn median(&self) -> Option<f64> {
        let n = self.len;
        if n == 0 {
            return None;
        }
        let m = n / 2;
        if n.is_multiple_of(2) {
            Some(0.5 * (self.nth(m - 1)? + self.nth(m)?))
        } else {
            self.nth(m)
        }
    }

    fn clear(&mut self) {
        for mut b in self.blocks.drain(..) {
            b.clear();
            self.spare.push(b);
        }
        self.lasts.clear();
        self.len = 0;
    }
}

/// One rigid pair's recent measurements.
#[derive(Debug, Clone, Default)]
struct BoneHistory {
    /// `(measured length, corrected length, along)` in arrival order; `along` is the variance the
    /// noise model gives the measurement along the bone (m²).
    order: VecDeque<(f64, f64, f64)>,
    /// The corrected lengths, sorted (for the median).
    sorted: SortedWindow,
    /// Sums over `order` of the measured length, its square, and `along`.
    sum_l: f64,
    sum_l2: f64,
    sum_along: f64,
}

impl BoneHistory {
    /// How much of the noise model's variance the measured lengths show: their variance over the
    /// model's mean variance along the bone, in [0, 1]; 0 until there are two lengths.
    fn model_share(&self) -> f64 {
        let n = self.order.len() as f64;
        if n < 2.0 || self.sum_along <= 0.0 {
            return 0.0;
        }
        let mean = self.sum_l / n;
        let var = (self.sum_l2 / n - mean * mean).max(0.0);
        (var / (self.sum_along / n)).clamp(0.0, 1.0)
    }

    fn push(&mut self, sample: (f64, f64, f64), window: usize) {
        self.order.push_back(sample);
        self.sorted.insert(sample.1);
        self.sum_l += sample.0;
        self.sum_l2 += sample.0 * sample.0;
        self.sum_along += sample.2;
        if self.order.len() > window {
            if let Some((l, corrected, along)) = self.order.pop_front() {
                self.sorted.remove(corrected);
                self.sum_l -= l;
                self.sum_l2 -= l * l;
                self.sum_along -= along;
            }
        }
    }

    fn clear(&mut self) {
        self.order.clear();
        self.sorted.clear();
        self.sum_l = 0.0;
        self.sum_l2 = 0.0;
        self.sum_along = 0.0;
    }
}

/// For each landmark of [`BONE_LANDMARKS`], the rigid pairs it is an end of, in [`RIGID`]'s order, as
/// `(pair index, the other end)`; `count` of the `MAX_DEGREE` slots are used.
#[derive(Debug, Clone, Copy)]
struct Adjacency {
    count: usize,
    pairs: [(usize, usize); MAX_DEGREE],
}

/// The most rigid pairs one landmark is an end of (a face landmark: 6).
const MAX_DEGREE: usize = 8;

const ADJACENCY: [Adjacency; BONE_LANDMARKS.len()] = {
    let mut out = [Adjacency {
        count: 0,
        pairs: [(0, 0); MAX_DEGREE],
    }; BONE_LANDMARKS.len()];
    let mut k = 0;
    while k < BONE_LANDMARKS.len() {
        let i = BONE_LANDMARKS[k];
        let mut b = 0;
        while b < RIGID.len() {
            let (a, c) = (RIGID[b].0.index(), RIGID[b].1.index());
            let other = if a == i {
                Some(c)
            } else if c == i {
                Some(a)
            } else {
                None
            };
            if let Some(o) = other {
                let n = out[k].count;
                out[k].pairs[n] = (b, o);
                out[k].count = n + 1;
            }
            b += 1;
        }
        k += 1;
    }
    out
};

/// The learned bone lengths of the current operator and the per-frame refinement.
#[derive(Debug, Clone)]
pub struct BonePrior {
    params: BonePriorParams,
    history: Vec<BoneHistory>,
}

impl BonePrior {
    /// A prior with no history.
    pub fn new(params: BonePriorParams) -> Self {
        Self {
            params,
            history: vec![BoneHistory::default(); RIGID.len()],
        }
    }

    /// Forgets the learned lengths (a new operator).
    pub fn reset(&mut self) {
        for h in &mut self.history {
            h.clear();
        }
    }

    /// The learned length of pair `b` (index into the rigid pairs: [`BONES`] then the head), once
    /// enough frames were seen: the median of the corrected lengths [`Self::observe`] kept.
    pub fn length_m(&self, b: usize) -> Option<f64> {
        let sorted = &self.history.get(b)?.sorted;
        if sorted.len() < self.params.min_samples.max(1) {
            return None;
        }
        sorted.median()
    }

    /// Adds this frame's (uncorrected) bone lengths to the history, each freed of the lengthening
    /// that noise across the bone causes.
    ///
    /// A measured length `l` of a bone `d` whose error has covariance `Σ` has `E[l²] = ‖d‖² + tr Σ`;
    /// the part along the bone (`uᵀΣu`, `u` along the bone) averages out of a median, the part across
    /// it does not. So the sample kept is `sqrt(l² − κ·(tr Σ − uᵀΣu))`, with `Σ = Λ_a⁻¹ + Λ_b⁻¹` from
    /// the two landmarks' information matrices (the triangulator's noise model) and `κ` how much of
    /// that model's noise the lengths so far actually show: their variance over the model's mean
    /// `uᵀΣu`, at most 1. Exact data (no spread) stays exact; noisy data gets the model's correction.
    /// Without it, on the digital twin at 3 px the rarely seen right ear sat 4 mm too far back, the
    /// neck read 0.7° low and RULA's grand-score κ was 0.77; with it 0.82.
    ///
    /// A length whose noise across the bone is three quarters of its square or more says nothing
    /// about the bone and is not kept; nor is one whose landmark has a singular or non-finite
    /// information matrix. `information` may be all zeros (unknown): the length is then kept,
    /// uncorrected (and a landmark with zero information contributes no correction to its bones).
    pub fn observe(
        &mut self,
        points: &[Option<Point3<f64>>; LANDMARK_COUNT],
        information: &[Matrix3<f64>; LANDMARK_COUNT],
    ) {
        let covariance: [Option<Matrix3<f64>>; LANDMARK_COUNT] =
            std::array::from_fn(|i| covariance_of(&information[i]));
        self.observe_with_covariance(points, &covariance);
    }

    /// [`Self::observe`] with each landmark's covariance already known: `covariance_of` its
    /// information matrix (the fusion has the triangulator's inverse at hand).
    pub(crate) fn observe_with_covariance(
        &mut self,
        points: &[Option<Point3<f64>>; LANDMARK_COUNT],
        covariance: &[Option<Matrix3<f64>>; LANDMARK_COUNT],
    ) {
        for (b, (a, c)) in RIGID.iter().enumerate() {
            let (Some(pa), Some(pc)) = (points[a.index()], points[c.index()]) else {
                continue;
            };
            let (Some(ca), Some(cc)) = (covariance[a.index()], covariance[c.index()]) else {
                continue;
            };
            let d = pa - pc;
            let l2 = d.norm_squared();
            if !(l2.is_finite() && l2 > 0.0) {
                continue;
            }
            let sigma = ca + cc;
            let u = d * (1.0 / l2.sqrt());
            let along = (u.transpose() * sigma * u)[(0, 0)];
            let across = sigma.trace() - along;
            if !(along.is_finite() && across.is_finite() && across < 0.75 * l2) {
                continue;
            }
            let history = &mut self.history[b];
            let corrected = (l2 - history.model_share() * across.max(0.0)).sqrt();
            history.push((l2.sqrt(), corrected, along.max(0.0)), self.params.window);
        }
    }

    /// Pulls the frame's landmarks towards consistent bone lengths, each by how little its cameras
    /// constrain it (`information[i]` is landmark `i`'s information matrix). Landmarks without an
    /// estimate, and bones without a learned length, are left alone.
    pub fn refine(
        &self,
        points: &mut [Option<Point3<f64>>; LANDMARK_COUNT],
        information: &[Matrix3<f64>; LANDMARK_COUNT],
    ) {
        let lengths: [Option<f64>; RIGID.len()] = std::array::from_fn(|b| self.length_m(b));
        if lengths.iter().all(Option::is_none) {
            return;
        }
        let measured = *points;
        let w = 1.0 / (self.params.sigma_m * self.params.sigma_m);
        for _ in 0..self.params.sweeps {
            for (&i, adjacency) in BONE_LANDMARKS.iter().zip(&ADJACENCY) {
                let (Some(x), Some(x_hat)) = (points[i], measured[i]) else {
                    continue;
                };
                let mut h = Sym3::from_matrix(&information[i]);
                let mut g = information[i] * (x - x_hat);
                let mut constrained = false;
                for &(b, other) in &adjacency.pairs[..adjacency.count] {
                    let (Some(l), Some(y)) = (lengths[b], points[other]) else {
                        continue;
                    };
                    let d: Vector3<f64> = x - y;
                    let n = d.norm();
                    if n < 1e-6 {
                        continue;
                    }
                    let u = d * (1.0 / n);
                    h.add_outer(&u, w);
                    g += u * ((n - l) * w);
                    constrained = true;
                }
                if !constrained {
                    continue;
                }
                if let Some(step) = h.solve(&g) {
                    if step.iter().all(|s| s.is_finite()) {
                        points[i] = Some(x - step);
                    }
                }
            }
        }
    }
}

/// A landmark's covariance from its information matrix, as the prior uses it: all zeros (unknown)
/// gives zeros; a singular or non-finite one gives `None`.
pub(crate) fn covariance_of(information: &Matrix3<f64>) -> Option<Matrix3<f64>> {
    if *information == Matrix3::zeros() {
        Some(Matrix3::zeros())
    } else {
        information
            .try_inverse()
            .filter(|c| c.iter().all(|v| v.is_finite()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_skeleton::Landmark;

    fn arm(elbow_x: f64) -> [Option<Point3<f64>>; LANDMARK_COUNT] {
        let mut p = [None; LANDMARK_COUNT];
        p[Landmark::LeftShoulder.index()] = Some(Point3::new(0.0, 0.0, 1.4));
        p[Landmark::LeftElbow.index()] = Some(Point3::new(elbow_x, 0.0, 1.1));
        p
    }

    #[test]
    fn the_adjacency_lists_every_pair_of_each_landmark_in_order() {
        for (&i, adj) in BONE_LANDMARKS.iter().zip(&ADJACENCY) {
            let expected: Vec<(usize, usize)> = RIGID
                .iter()
                .enumerate()
                .filter_map(|(b, (a, c))| {
                    if a.index() == i {
                        Some((b, c.index()))
                    } else if c.index() == i {
                        Some((b, a.index()))
                    } else {
                        None
                    }
                })
                .collect();
            assert_eq!(adj.pairs[..adj.count].to_vec(), expected, "landmark {i}");
        }
    }

    #[test]
    fn the_blocked_window_keeps_the_same_order_statistics_as_a_sorted_vec() {
        // 5000 insertions of a few distinct values (many ties) and of spread values, each followed,
        // past a window of 300, by the removal of the oldest: the median and every order statistic
        // match a plain sorted Vec at every step.
        let mut seed = 7u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 33) as f64 / (1u64 << 31) as f64
        };
        let mut window = SortedWindow::default();
        let mut reference: Vec<f64> = Vec::new();
        let mut order = VecDeque::new();
        for step in 0..5000 {
            let x = if step % 3 == 0 {
                (next() * 4.0).floor() * 0.1
            } else {
                next()
            };
            window.insert(x);
            let at = reference.partition_point(|v| *v < x);
            reference.insert(at, x);
            order.push_back(x);
            if order.len() > 300 {
                let old = order.pop_front().unwrap();
                assert!(window.remove(old));
                let i = reference.partition_point(|v| *v < old);
                reference.remove(i);
            }
            assert_eq!(window.len(), reference.len());
            let m = reference.len() / 2;
            let median = if reference.len().is_multiple_of(2) {
                0.5 * (reference[m - 1] + reference[m])
            } else {
                reference[m]
            };
            assert_eq!(window.median(), Some(median), "step {step}");
            if step % 97 == 0 {
                for (k, v) in reference.iter().enumerate() {
                    assert_eq!(window.nth(k), Some(*v));
                }
            }
        }
        assert!(!window.remove(2.0), "a value never inserted is not removed");
        window.clear();
        assert_eq!((window.len(), window.median()), (0, None));
    }

    #[test]
    fn bone_landmarks_are_exactly_the_ends_of_the_bones() {
        let mut ends: Vec<usize> = RIGID
            .iter()
            .flat_map(|(a, b)| [a.index(), b.index()])
            .collect();
        ends.sort_unstable();
        ends.dedup();
        assert_eq!(ends, BONE_LANDMARKS.to_vec());
    }

    #[test]
    fn exact_data_is_left_unchanged() {
        let mut prior = BonePrior::new(BonePriorParams {
            min_samples: 3,
            ..BonePriorParams::default()
        });
        for _ in 0..5 {
            prior.observe(&arm(0.0), &[Matrix3::zeros(); LANDMARK_COUNT]);
        }
        assert!((prior.length_m(0).unwrap() - 0.3).abs() < 1e-12);
        let mut p = arm(0.0);
        let info = [Matrix3::identity() * 1e4; LANDMARK_COUNT];
        prior.refine(&mut p, &info);
        assert_eq!(p, arm(0.0));
    }

    #[test]
    fn noise_across_a_bone_does_not_lengthen_the_learned_bone() {
        // The elbow of a true 0.3 m (vertical) bone is seen with 3 cm Gaussian noise in x and z (600
        // samples: a Box–Muller grid, visited in a scrambled order), and its covariance says so. The
        // noise across the bone (x) lengthens the measured lengths, their median by σ²/2L ≈ 1.5 mm;
        // the correction takes most of that off (κ is learned from the lengths as they arrive, so the
        // first few samples are corrected less).
        let sample = |k: usize| {
            let (i, j) = ((k * 397) % 600 / 25, (k * 397) % 25);
            let r = (-2.0 * ((i as f64 + 0.5) / 24.0).ln()).sqrt();
            let theta = std::f64::consts::TAU * (j as f64 + 0.5) / 25.0;
            (0.03 * r * theta.cos(), 0.03 * r * theta.sin())
        };
        let run = |info: &[Matrix3<f64>; LANDMARK_COUNT], scale: f64| {
            let mut prior = BonePrior::new(BonePriorParams::default());
            for k in 0..600 {
                let (x, z) = sample(k);
                let mut p = arm(0.0);
                p[Landmark::LeftElbow.index()] = Some(Point3::new(scale * x, 0.0, 1.1 + scale * z));
                prior.observe(&p, info);
            }
            prior.length_m(0).unwrap()
        };
        let mut info = [Matrix3::identity() * 1e12; LANDMARK_COUNT];
        info[Landmark::LeftElbow.index()] =
            Matrix3::from_diagonal(&Vector3::new(1.0 / 0.0009, 1e12, 1.0 / 0.0009));
        let raw = run(&[Matrix3::zeros(); LANDMARK_COUNT], 1.0);
        let corrected = run(&info, 1.0);
        assert!(raw - 0.3 > 0.001, "raw {raw}");
        assert!((corrected - 0.3).abs() < 0.0004, "corrected {corrected}");
        // Exact measurements show no spread: whatever the model says, nothing is taken off.
        assert!((run(&info, 0.0) - 0.3).abs() < 1e-12);
        // A sample whose noise across the bone is as large as the bone says nothing: not kept.
        info[Landmark::LeftElbow.index()] =
            Matrix3::from_diagonal(&Vector3::new(1.0 / (0.3 * 0.3), 1e12, 1e12));
        let mut prior = BonePrior::new(BonePriorParams::default());
        for _ in 0..20 {
            prior.observe(&arm(0.04), &info);
        }
        assert_eq!(prior.length_m(0), None);
    }

    #[test]
    fn a_weakly_measured_direction_is_pulled_to_the_learned_length() {
        let mut prior = BonePrior::new(BonePriorParams {
            min_samples: 3,
            ..BonePriorParams::default()
        });
        for _ in 0..5 {
            prior.observe(&arm(0.0), &[Matrix3::zeros(); LANDMARK_COUNT]);
        }
        // the elbow came out 10 cm off along x (say the depth of its cameras): bone 0.316 m long
        let mut p = arm(0.1);
        // well measured in y and z, barely in x; the shoulder is well measured in every direction
        let mut info = [Matrix3::identity() * 1e6; LANDMARK_COUNT];
        info[Landmark::LeftElbow.index()] = Matrix3::from_diagonal(&Vector3::new(1.0, 1e6, 1e6));
        prior.refine(&mut p, &info);
        let elbow = p[Landmark::LeftElbow.index()].unwrap();
        let shoulder = p[Landmark::LeftShoulder.index()].unwrap();
        assert!(
            ((elbow - shoulder).norm() - 0.3).abs() < 1e-3,
            "length {}",
            (elbow - shoulder).norm()
        );
        // from 10 cm to under 2 cm along the weak direction; the well-measured ones stay put
        assert!(
            elbow.x.abs() < 0.02,
            "moved along the weak direction: {elbow}"
        );
        assert!(
            (elbow.z - 1.1).abs() < 1e-5 && elbow.y.abs() < 1e-9,
            "{elbow}"
        );
        assert!(
            (shoulder - Point3::new(0.0, 0.0, 1.4)).norm() < 1e-3,
            "well-measured shoulder stays"
        );
    }

    /// A face of the twin's proportions (1.75 m operator), metres.
    fn face() -> [Option<Point3<f64>>; LANDMARK_COUNT] {
        let mut p = [None; LANDMARK_COUNT];
        let h = 1.75;
        let z = 0.118 * h + 1.43;
        for (lm, x, y, dz) in [
            (Landmark::Nose, 0.055, 0.0, -0.018),
            (Landmark::LeftEye, 0.045, 0.018, 0.0),
            (Landmark::RightEye, 0.045, -0.018, 0.0),
            (Landmark::LeftEar, 0.0, 0.043, -0.005),
            (Landmark::RightEar, 0.0, -0.043, -0.005),
            (Landmark::MouthLeft, 0.050, 0.014, -0.040),
            (Landmark::MouthRight, 0.050, -0.014, -0.040),
        ] {
            p[lm.index()] = Some(Point3::new(x * h, y * h, z + dz * h));
        }
        p
    }

    #[test]
    fn both_ears_seen_badly_are_placed_by_the_rest_of_the_face() {
        let mut prior = BonePrior::new(BonePriorParams {
            min_samples: 3,
            ..BonePriorParams::default()
        });
        for _ in 0..5 {
            prior.observe(&face(), &[Matrix3::zeros(); LANDMARK_COUNT]);
        }
        // Both ears 2.7 cm off and barely measured in any direction (hidden from most cameras); the
        // eyes, nose and mouth well seen. With the ears tied only to the nose, one eye and each
        // other, each ear could still swing on a circle; the mouth and the other eye pin it.
        let mut p = face();
        let mut info = [Matrix3::identity() * 1e6; LANDMARK_COUNT];
        for ear in [Landmark::LeftEar, Landmark::RightEar] {
            let e = p[ear.index()].unwrap();
            p[ear.index()] = Some(e + Vector3::new(0.02, 0.01, -0.015));
            info[ear.index()] = Matrix3::identity();
        }
        prior.refine(&mut p, &info);
        for ear in [Landmark::LeftEar, Landmark::RightEar] {
            let err = (p[ear.index()].unwrap() - face()[ear.index()].unwrap()).norm();
            assert!(err < 0.003, "{ear:?} still {:.1} mm off", err * 1e3);
        }
    }

    #[test]
    fn a_badly_seen_finger_landmark_is_held_to_the_hand() {
        // Right hand: wrist, index, pinky and thumb as the twin places them (1.75 m operator).
        let hand = || {
            let mut p = [None; LANDMARK_COUNT];
            p[Landmark::RightWrist.index()] = Some(Point3::new(0.40, -0.10, 1.10));
            p[Landmark::RightIndex.index()] = Some(Point3::new(0.49, -0.085, 1.09));
            p[Landmark::RightPinky.index()] = Some(Point3::new(0.47, -0.125, 1.09));
            p[Landmark::RightThumb.index()] = Some(Point3::new(0.44, -0.06, 1.10));
            p
        };
        let mut prior = BonePrior::new(BonePriorParams {
            min_samples: 3,
            ..BonePriorParams::default()
        });
        for _ in 0..5 {
            prior.observe(&hand(), &[Matrix3::zeros(); LANDMARK_COUNT]);
        }
        // The index 2 cm off sideways, the direction its cameras barely measure: that alone would
        // turn the hand's direction by ~10° (a deviated wrist). The rest of the hand is well seen.
        let mut p = hand();
        let mut info = [Matrix3::identity() * 1e6; LANDMARK_COUNT];
        let ix = Landmark::RightIndex.index();
        p[ix] = p[ix].map(|q| q + Vector3::new(0.0, 0.02, 0.0));
        info[ix] = Matrix3::from_diagonal(&Vector3::new(1e6, 1.0, 1e6));
        prior.refine(&mut p, &info);
        let err = (p[ix].unwrap() - hand()[ix].unwrap()).norm();
        assert!(err < 0.003, "index still {:.1} mm off", err * 1e3);
    }

    #[test]
    fn the_median_follows_a_sliding_window() {
        let mut prior = BonePrior::new(BonePriorParams {
            min_samples: 1,
            window: 3,
            ..BonePriorParams::default()
        });
        for x in [0.0, 0.0, 0.0, 0.4, 0.4] {
            prior.observe(&arm(x), &[Matrix3::zeros(); LANDMARK_COUNT]);
        }
        // window holds lengths for x = 0.0, 0.4, 0.4 → median is the x = 0.4 length
        assert!((prior.length_m(0).unwrap() - 0.5).abs() < 1e-12);
        assert_eq!(prior.length_m(3), None);
    }
}
