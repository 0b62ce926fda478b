//! Quality measures of a 3D reconstruction that need no ground truth.
//!
//! - **Bone-length variation**: bones are rigid, so the length of each bone over a recording should
//!   not change. For each bone of [`ergocell_skeleton::BONES`] the coefficient of variation
//!   (standard deviation / mean, over the frames where both ends are observed) is computed; the
//!   recording's figure is the mean over bones, in percent.
//! - **Reprojection error**: the median over all fused landmarks of their RMS pixel error.
//!
//! Beside them, what a whole run accumulates for its summary ([`RunTally`]: landmarks, reprojection
//! per camera, left/right swaps, rejected views), the frame rate the stamps imply
//! ([`frame_rate_hz`]) and the throughput ([`throughput_fps`]); `report_text` lays them out.

use ergocell_skeleton::{Landmark, Skeleton3, BONES, LANDMARK_COUNT};

use crate::{CameraRig, Frame2, FusedFrame};

/// Per-bone length statistics over a recording.
#[derive(Debug, Clone, PartialEq)]
pub struct BoneStats {
    pub bone: (Landmark, Landmark),
    pub frames: usize,
    pub mean_m: f64,
    /// Coefficient of variation, percent.
    pub cv_percent: f64,
}

/// A bone: its two end landmarks.
pub type Bone = (Landmark, Landmark);

/// Length statistics of every bone (bones seen in fewer than 2 frames are left out).
pub fn bone_stats(frames: &[Skeleton3]) -> Vec<BoneStats> {
    BONES
        .iter()
        .filter_map(|&(a, b)| {
            let lengths: Vec<f64> = frames
                .iter()
                .filter_map(|s| s.bone_length_m(a, b))
                .collect();
            if lengths.len() < 2 {
                return None;
            }
            let n = lengths.len() as f64;
            let mean = lengths.iter().sum::<f64>() / n;
            let var = lengths.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean > 0.0).then(|| BoneStats {
                bone: (a, b),
                frames: lengths.len(),
                mean_m: mean,
                cv_percent: 100.0 * var.sqrt() / mean,
            })
        })
        .collect()
}

/// Mean over bones of the bone-length coefficient of variation, percent (`None` when no bone was
/// seen in two frames).
pub fn bone_length_variation_percent(frames: &[Skeleton3]) -> Option<f64> {
    let stats = bone_stats(frames);
    (!stats.is_empty())
        .then(|| stats.iter().map(|s| s.cv_percent).sum::<f64>() / stats.len() as f64)
}

/// Bone-length variation of several reconstructions of the same recording, compared fairly: the
/// mean is taken over the bones that **every** reconstruction observed (a method that never sees
/// the lower legs must not look better for leaving out the hardest bones). Returns the bones used and
/// one mean per reconstruction (`None` when no bone is common to all).
pub fn common_bone_variation_percent(recordings: &[&[Skeleton3]]) -> Option<(Vec<Bone>, Vec<f64>)> {
    let stats: Vec<Vec<BoneStats>> = recordings.iter().map(|r| bone_stats(r)).collect();
    let common: Vec<Bone> = BONES
        .iter()
        .copied()
        .filter(|bone| stats.iter().all(|st| st.iter().any(|b| b.bone == *bone)))
        .collect();
    if common.is_empty() {
        return None;
    }
    let means = stats
        .iter()
        .map(|st| {
            let used: Vec<f64> = st
                .iter()
                .filter(|b| common.contains(&b.bone))
                .map(|b| b.cv_percent)
                .collect();
            used.iter().sum::<f64>() / used.len() as f64
        })
        .collect();
    Some((common, means))
}

/// The value at quantile `q` (0..=1) of `sorted` (ascending): the element at the rounded rank
/// `(n − 1)·q`; NaN when empty.
pub fn rank_quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let k = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[k.min(sorted.len() - 1)]
}

/// Median of a list (`None` when empty); NaNs are ignored.
pub fn median(values: &[f64]) -> Option<f64> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    median_in_place(&mut v)
}

/// Median of a list without NaNs, reordering it in place (`None` when empty): no allocation, for
/// per-frame use.
pub fn median_in_place(v: &mut [f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    // the middle value(s) a sort would give, found by selection: this runs per camera per frame
    // over the health monitor's window, where a full sort was ≈ 5 % of `ergocell triangulate`
    let (m, even) = (v.len() / 2, v.len().is_multiple_of(2));
    let (below, &mut upper, _) = v.select_nth_unstable_by(m, f64::total_cmp);
    Some(if even {
        // the largest of the values before the middle one: the sorted order's `v[m − 1]`
        let lower = below
            .iter()
            .copied()
            .max_by(f64::total_cmp)
            .unwrap_or(upper);
        0.5 * (lower + upper)
    } else {
        upper
    })
}

/// Median reprojection error (pixels) over every fused landmark of a recording.
pub fn median_reprojection_px(frames: &[Skeleton3]) -> Option<f64> {
    let errors: Vec<f64> = frames
        .iter()
        .flat_map(|s| {
            s.slots()
                .iter()
                .flatten()
                .filter_map(|e| e.reprojection_error_px)
        })
        .collect();
    median(&errors)
}

/// The same measures accumulated one frame at a time, for a recording too long to hold (`ergocell
/// triangulate` of hours): bone lengths by Welford's running mean and variance (the figures of
/// [`bone_stats`] to rounding), the reprojection error's median from a histogram of 0.001 px bins up
/// to [`StreamingStats::MAX_REPROJECTION_PX`] (the median to ±0.0005 px). Memory: 4 MB, whatever the
/// length.
#[derive(Debug, Clone)]
pub struct StreamingStats {
    bones: [(usize, f64, f64); BONES.len()],
    histogram: Vec<u32>,
    reprojections: u64,
    frames: usize,
    landmarks: usize,
}

impl Default for StreamingStats {
    fn default() -> Self {
        Self {
            bones: [(0, 0.0, 0.0); BONES.len()],
            histogram: vec![0; Self::BINS + 1],
            reprojections: 0,
            frames: 0,
            landmarks: 0,
        }
    }
}

impl StreamingStats {
    /// Reprojection errors above this (pixels) share one overflow bin.
    pub const MAX_REPROJECTION_PX: f64 = 1000.0;
    const BIN_PX: f64 = 0.001;
    const BINS: usize = 1_000_000;

    /// Adds one frame.
    pub fn push(&mut self, s: &Skeleton3) {
        self.frames += 1;
        self.landmarks += s.observed_count();
        for (acc, &(a, b)) in self.bones.iter_mut().zip(BONES.iter()) {
            if let Some(l) = s.bone_length_m(a, b) {
                // Welford: count, mean, sum of squared deviations
                acc.0 += 1;
                let d = l - acc.1;
                acc.1 += d / acc.0 as f64;
                acc.2 += d * (l - acc.1);
            }
        }
        for e in s.slots().iter().flatten() {
            if let Some(r) = e.reprojection_error_px.filter(|r| !r.is_nan()) {
                let bin = if r >= 0.0 {
                    ((r / Self::BIN_PX) as usize).min(Self::BINS)
                } else {
                    0
                };
                self.histogram[bin] += 1;
                self.reprojections += 1;
            }
        }
    }

    /// Frames added.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Landmarks observed over all frames.
    pub fn landmarks(&self) -> usize {
        self.landmarks
    }

    /// Landmark slots over all frames: frames × [`LANDMARK_COUNT`].
    pub fn landmark_slots(&self) -> usize {
        self.frames * LANDMARK_COUNT
    }

    /// Landmarks observed, per cent of [`StreamingStats::landmark_slots`] (NaN before the first
    /// frame).
    pub fn landmark_percent(&self) -> f64 {
        100.0 * self.landmarks as f64 / self.landmark_slots() as f64
    }

    /// As [`bone_stats`].
    pub fn bone_stats(&self) -> Vec<BoneStats> {
        self.bones
            .iter()
            .zip(BONES.iter())
            .filter(|(&(n, mean, _), _)| n >= 2 && mean > 0.0)
            .map(|(&(n, mean, m2), &bone)| BoneStats {
                bone,
                frames: n,
                mean_m: mean,
                cv_percent: 100.0 * (m2 / (n as f64 - 1.0)).max(0.0).sqrt() / mean,
            })
            .collect()
    }

    /// As [`bone_length_variation_percent`].
    pub fn bone_length_variation_percent(&self) -> Option<f64> {
        let stats = self.bone_stats();
        (!stats.is_empty())
            .then(|| stats.iter().map(|s| s.cv_percent).sum::<f64>() / stats.len() as f64)
    }

    /// As [`median_reprojection_px`], to ±0.0005 px (the centre of the median's bin; the mean of
    /// the two middle bins' centres for an even count).
    pub fn median_reprojection_px(&self) -> Option<f64> {
        let n = self.reprojections;
        if n == 0 {
            return None;
        }
        let centre = |bin: usize| (bin as f64 + 0.5) * Self::BIN_PX;
        let kth = |k: u64| {
            let mut seen = 0u64;
            for (bin, &c) in self.histogram.iter().enumerate() {
                seen += u64::from(c);
                if seen > k {
                    return centre(bin);
                }
            }
            centre(Self::BINS)
        };
        Some(if n.is_multiple_of(2) {
            0.5 * (kth(n / 2 - 1) + kth(n / 2))
        } else {
            kth(n / 2)
        })
    }
}

/// Each camera's reprojection error against the fused skeleton, accumulated one frame at a time:
/// for every landmark a camera observed and the fusion placed, the distance in pixels between the
/// camera's keypoint and the fused point projected through its calibration (lens distortion
/// included). Views the fusion rejected count too, so a camera that is off (a swapped left and
/// right, a bad calibration, an undeclared video geometry) shows. Medians from histograms of 0.01 px
/// bins up to [`StreamingStats::MAX_REPROJECTION_PX`] (400 kB per camera).
#[derive(Debug, Clone, Default)]
pub struct PerCameraReprojection {
    histograms: Vec<Vec<u32>>,
    counts: Vec<u64>,
    /// Per camera: views with anything observed, and of those, views used mirrored.
    views: Vec<(usize, usize)>,
}

impl PerCameraReprojection {
    const BIN_PX: f64 = 0.01;
    const BINS: usize = 100_000;

    /// Adds one frame's views against its fused skeleton; the views of the cameras in `swapped`
    /// (a bit per camera, [`crate::FusedFrame::swapped_views`]) are compared mirrored, as the
    /// fusion used them.
    pub fn push(
        &mut self,
        rig: &crate::CameraRig,
        frame: &crate::Frame2,
        fused: &Skeleton3,
        swapped: u64,
    ) {
        for view in &frame.views {
            let Some(camera) = rig.camera(view.camera) else {
                continue;
            };
            let mirrored = swapped & (1 << view.camera) != 0;
            if view.observed_count() > 0 {
                if self.views.len() <= view.camera {
                    self.views.resize(view.camera + 1, (0, 0));
                }
                let v = &mut self.views[view.camera];
                v.0 += 1;
                v.1 += usize::from(mirrored);
            }
            for lm in ergocell_skeleton::Landmark::ALL {
                let as_used = if mirrored { lm.mirrored() } else { lm };
                let (Some(k), Some(p)) = (view.get(lm), fused.position(as_used)) else {
                    continue;
                };
                let Ok(q) = camera.project(&p) else { continue };
                let e = (q - k.pixel()).norm();
                if e.is_finite() {
                    self.add(view.camera, e);
                }
            }
        }
    }

    fn add(&mut self, camera: usize, error_px: f64) {
        if self.histograms.len() <= camera {
            self.histograms.resize_with(camera + 1, Vec::new);
            self.counts.resize(camera + 1, 0);
        }
        let h = &mut self.histograms[camera];
        if h.is_empty() {
            h.resize(Self::BINS + 1, 0);
        }
        h[((error_px / Self::BIN_PX) as usize).min(Self::BINS)] += 1;
        self.counts[camera] += 1;
    }

    /// One camera's views with anything observed, and how many of them were used mirrored.
    pub fn views(&self, camera: usize) -> (usize, usize) {
        self.views.get(camera).copied().unwrap_or((0, 0))
    }

    /// The views of cameras `0..cameras` summed: views with anything observed, and of those, views
    /// used mirrored.
    pub fn swap_totals(&self, cameras: usize) -> SwapTotals {
        (0..cameras)
            .map(|k| self.views(k))
            .fold(SwapTotals::default(), |t, (views, swapped)| SwapTotals {
                views: t.views + views,
                swapped: t.swapped + swapped,
            })
    }

    /// The median error of one camera (to ±0.005 px) and its sample count; `None` for a camera
    /// with no sample.
    pub fn median_px(&self, camera: usize) -> Option<(f64, u64)> {
        let n = *self.counts.get(camera).filter(|&&n| n > 0)?;
        let h = &self.histograms[camera];
        let kth = |k: u64| {
            let mut seen = 0u64;
            for (bin, &c) in h.iter().enumerate() {
                seen += u64::from(c);
                if seen > k {
                    return (bin as f64 + 0.5) * Self::BIN_PX;
                }
            }
            (Self::BINS as f64 + 0.5) * Self::BIN_PX
        };
        let m = if n.is_multiple_of(2) {
            0.5 * (kth(n / 2 - 1) + kth(n / 2))
        } else {
            kth(n / 2)
        };
        Some((m, n))
    }
}

/// Views with anything observed over a set of cameras ([`PerCameraReprojection::swap_totals`]), and
/// how many of them had the person's left and right swapped and were used mirrored.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SwapTotals {
    pub views: usize,
    pub swapped: usize,
}

impl SwapTotals {
    /// Swapped views, per cent of the views (0 when there is no view).
    pub fn percent(self) -> f64 {
        100.0 * self.swapped as f64 / self.views.max(1) as f64
    }
}

/// What a reconstruction run accumulates frame by frame for its summary (`ergocell triangulate`):
/// landmarks, bone lengths and reprojection errors ([`StreamingStats`]), each camera's reprojection
/// and swaps ([`PerCameraReprojection`]), and the views the fusion left out. Memory flat in the
/// run's length.
#[derive(Debug, Clone, Default)]
pub struct RunTally {
    pub stats: StreamingStats,
    pub per_camera: PerCameraReprojection,
    /// Views the fusion rejected (outliers, behind the camera), over all frames.
    pub rejected_views: usize,
    /// Keypoints the fusion could not undistort (outside the lens model), over all frames.
    pub undistortion_failures: usize,
}

impl RunTally {
    /// Adds one frame: `fused` is what the fusion made of `frame` (its counts and swapped views),
    /// `skeleton` the frame's result as delivered (filtered, or the fused skeleton itself).
    pub fn push(
        &mut self,
        rig: &CameraRig,
        frame: &Frame2,
        fused: &FusedFrame,
        skeleton: &Skeleton3,
    ) {
        self.rejected_views += fused.rejected_views;
        self.undistortion_failures += fused.undistortion_failures;
        self.stats.push(skeleton);
        self.per_camera
            .push(rig, frame, skeleton, fused.swapped_views);
    }
}

/// The frame rate the stamps imply: one over the median interval between consecutive frames,
/// repeated stamps left out (`None` without a positive interval).
pub fn frame_rate_hz(frames: &[Skeleton3]) -> Option<f64> {
    let dts: Vec<f64> = frames
        .windows(2)
        .map(|w| (w[1].stamp_nanos - w[0].stamp_nanos) as f64 * 1e-9)
        .filter(|dt| *dt > 0.0)
        .collect();
    median(&dts).map(|dt| 1.0 / dt)
}

/// Frames per second of wall time, `elapsed_s` floored at a nanosecond (a run too short to time is
/// not infinitely fast).
pub fn throughput_fps(frames: usize, elapsed_s: f64) -> f64 {
    frames as f64 / elapsed_s.max(1e-9)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    #[test]
    fn rigid_bones_have_zero_variation_and_stretching_shows() {
        let mut frames = Vec::new();
        for k in 0..10 {
            let pts = std::array::from_fn(|i| Point3::new(i as f64 * 0.1 + k as f64, 0.0, 0.0));
            frames.push(Skeleton3::from_points(k, &pts).unwrap());
        }
        assert!(bone_length_variation_percent(&frames).unwrap() < 1e-9);
        let mut stretched = Vec::new();
        for k in 0..10 {
            let s = 1.0 + 0.1 * (k % 2) as f64;
            let pts = std::array::from_fn(|i| Point3::new(i as f64 * 0.1 * s, 0.0, 0.0));
            stretched.push(Skeleton3::from_points(k, &pts).unwrap());
        }
        let cv = bone_length_variation_percent(&stretched).unwrap();
        // lengths alternate L and 1.1 L: CV = 0.05 / 1.05 · sqrt(10/9) ≈ 5.02 %
        assert!(
            (cv - 100.0 * 0.05 / 1.05 * (10.0_f64 / 9.0).sqrt()).abs() < 1e-9,
            "{cv}"
        );
        assert_eq!(bone_length_variation_percent(&[]), None);
    }

    #[test]
    fn streaming_stats_agree_with_the_whole_recording_measures() {
        // a skeleton whose bones stretch differently every frame, with reprojection errors spread
        // over 0–40 px
        let frames: Vec<Skeleton3> = (0..301)
            .map(|k| {
                let s = 1.0 + 0.07 * ((k * 13) % 11) as f64 / 11.0;
                let pts: [Option<Point3<f64>>; ergocell_skeleton::LANDMARK_COUNT] =
                    std::array::from_fn(|i| {
                        ((k + i) % 9 != 0)
                            .then(|| Point3::new(i as f64 * 0.1 * s, 0.01 * i as f64, 1.0))
                    });
                let mut sk = Skeleton3::from_optional_points(k as i64, &pts).unwrap();
                for lm in Landmark::ALL {
                    if let Some(mut e) = sk.get(lm).copied() {
                        let i = lm.index();
                        e.reprojection_error_px =
                            Some(((k * 31 + i * 7) % 400) as f64 * 0.1 + 0.0123);
                        sk.set(lm, Some(e)).unwrap();
                    }
                }
                sk
            })
            .collect();
        let mut st = StreamingStats::default();
        for f in &frames {
            st.push(f);
        }
        assert_eq!(st.frames(), 301);
        let (whole, streamed) = (bone_stats(&frames), st.bone_stats());
        assert_eq!(whole.len(), streamed.len());
        for (a, b) in whole.iter().zip(&streamed) {
            assert_eq!((a.bone, a.frames), (b.bone, b.frames));
            assert!(
                (a.mean_m - b.mean_m).abs() < 1e-12 && (a.cv_percent - b.cv_percent).abs() < 1e-9
            );
        }
        let exact = median_reprojection_px(&frames).unwrap();
        assert!(
            (st.median_reprojection_px().unwrap() - exact).abs() <= 0.0005 + 1e-12,
            "{exact}"
        );
        assert_eq!(StreamingStats::default().median_reprojection_px(), None);
    }

    #[test]
    fn rank_quantiles_round_the_rank_and_are_nan_when_empty() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(rank_quantile(&v, 0.0), 1.0);
        assert_eq!(rank_quantile(&v, 0.5), 3.0);
        assert_eq!(rank_quantile(&v, 0.99), 5.0);
        assert_eq!(rank_quantile(&[10.0, 20.0, 30.0, 40.0], 0.5), 30.0);
        assert!(rank_quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn median_of_even_and_odd_lists() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
        assert_eq!(median(&[f64::NAN]), None);
    }

    #[test]
    fn the_median_by_selection_is_the_median_of_the_sorted_list() {
        // lists of 1..=70 values with many ties (and signed zeros), against the sorted list's
        // middle value(s)
        let mut seed = 11u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            seed >> 33
        };
        for n in 1..=70 {
            for _ in 0..20 {
                let v: Vec<f64> = (0..n)
                    .map(|_| match next() % 5 {
                        0 => -0.0,
                        1 => 0.0,
                        _ => (next() % 7) as f64 * 0.25 - 0.5,
                    })
                    .collect();
                let mut sorted = v.clone();
                sorted.sort_by(f64::total_cmp);
                let m = n / 2;
                let expected = if n % 2 == 0 {
                    0.5 * (sorted[m - 1] + sorted[m])
                } else {
                    sorted[m]
                };
                let mut w = v.clone();
                let got = median_in_place(&mut w).unwrap();
                assert_eq!(got.to_bits(), expected.to_bits(), "{v:?}");
            }
        }
        assert_eq!(median_in_place(&mut []), None);
    }

    #[test]
    fn per_camera_reprojection_medians() {
        let mut r = PerCameraReprojection::default();
        for e in [0.5, 1.5, 2.5] {
            r.add(1, e);
        }
        r.add(3, 7.0);
        r.add(3, 9.0);
        assert_eq!(r.median_px(0), None);
        let (m, n) = r.median_px(1).unwrap();
        assert!((m - 1.5).abs() < 0.01 && n == 3, "{m}");
        let (m, n) = r.median_px(3).unwrap();
        assert!((m - 8.0).abs() < 0.01 && n == 2, "{m}");
        assert_eq!(r.median_px(9), None);
    }

    fn line_of_landmarks(stamp_nanos: i64) -> Skeleton3 {
        let pts = std::array::from_fn(|i| Point3::new(0.1 * i as f64, 0.0, 1.0));
        Skeleton3::from_points(stamp_nanos, &pts).unwrap()
    }

    #[test]
    fn the_landmark_share_counts_observed_slots() {
        let mut st = StreamingStats::default();
        assert_eq!(st.landmark_slots(), 0);
        assert!(st.landmark_percent().is_nan());
        // a full frame and one with the even landmarks only (17 of 33)
        let even: [Option<Point3<f64>>; LANDMARK_COUNT] = std::array::from_fn(|i| {
            i.is_multiple_of(2)
                .then(|| Point3::new(0.1 * i as f64, 0.0, 1.0))
        });
        st.push(&line_of_landmarks(0));
        st.push(&Skeleton3::from_optional_points(1, &even).unwrap());
        assert_eq!(st.landmark_slots(), 2 * LANDMARK_COUNT);
        assert_eq!(st.landmarks(), LANDMARK_COUNT + 17);
        let percent = st.landmark_percent();
        assert!((percent - 100.0 * 50.0 / 66.0).abs() < 1e-12, "{percent}");
    }

    #[test]
    fn swap_totals_sum_the_cameras_asked_for() {
        let r = PerCameraReprojection {
            views: vec![(10, 2), (0, 0), (5, 1)],
            ..PerCameraReprojection::default()
        };
        let all = r.swap_totals(3);
        assert_eq!(
            all,
            SwapTotals {
                views: 15,
                swapped: 3
            }
        );
        assert_eq!(
            r.swap_totals(1),
            SwapTotals {
                views: 10,
                swapped: 2
            }
        );
        // cameras never seen add nothing
        assert_eq!(r.swap_totals(9), all);
        assert!((all.percent() - 20.0).abs() < 1e-12);
        // no view: no swap, not NaN
        assert_eq!(SwapTotals::default().percent(), 0.0);
    }

    #[test]
    fn the_frame_rate_is_one_over_the_median_interval() {
        let at = |ms: &[i64]| -> Vec<Skeleton3> {
            ms.iter()
                .map(|&t| Skeleton3::empty(t * 1_000_000))
                .collect()
        };
        // 25 Hz with a repeated stamp and a dropped frame: the median interval is still 40 ms
        let rate = frame_rate_hz(&at(&[0, 40, 40, 80, 120, 200, 240])).unwrap();
        assert!((rate - 25.0).abs() < 1e-9, "{rate}");
        assert_eq!(frame_rate_hz(&at(&[0])), None);
        assert_eq!(frame_rate_hz(&at(&[5, 5, 5])), None);
    }

    #[test]
    fn throughput_is_frames_per_wall_second() {
        assert!((throughput_fps(300, 2.0) - 150.0).abs() < 1e-12);
        // a run too short to time: a nanosecond, not a division by zero
        let instant = throughput_fps(3, 0.0);
        assert!(
            instant.is_finite() && (instant - 3e9).abs() < 1.0,
            "{instant}"
        );
    }

    #[test]
    fn a_run_tally_adds_the_fusions_counts_and_the_delivered_skeleton() {
        let rig = crate::fusion::tests::ring_rig(2);
        let frame = Frame2 {
            stamp_nanos: 0,
            views: Vec::new(),
        };
        let fused = FusedFrame {
            skeleton: Skeleton3::empty(0),
            rejected_views: 3,
            undistortion_failures: 1,
            cameras_present: 0,
            swapped_views: 0,
        };
        let delivered = line_of_landmarks(0);
        let mut t = RunTally::default();
        t.push(&rig, &frame, &fused, &delivered);
        t.push(&rig, &frame, &fused, &delivered);
        assert_eq!((t.rejected_views, t.undistortion_failures), (6, 2));
        // the delivered skeleton is counted, not the fused one (empty here)
        assert_eq!(
            (t.stats.frames(), t.stats.landmarks()),
            (2, 2 * LANDMARK_COUNT)
        );
        assert_eq!(t.per_camera.swap_totals(2), SwapTotals::default());
    }
}
