//! A camera knocked out of its calibration (bumped, its mount loosened) still sends sharp, confident
//! landmarks, only in the wrong place: nothing about its messages is stale or malformed. What gives
//! it away is geometry: its views no longer agree with the skeleton the other cameras fuse. A 1°
//! rotation of a camera 3 m away moves every pixel by about `f · 0.017` (≈ 17 px at f = 1000 px),
//! against a few pixels of detector noise for a calibrated camera.
//!
//! [`CameraResidualMonitor`] keeps, per camera, the per-frame median reprojection residual of its
//! views against the fused skeleton ([`CameraResidualMonitor::observe_frame`]) over a sliding time window, and its own
//! baseline (the median of its first frames). A camera is flagged when its window median exceeds an
//! absolute floor and has risen well above both its own baseline and the other cameras' window
//! medians (a camera that is simply noisier than the others keeps its own, higher baseline), or lies
//! far above the others' alone; with enough frames in its window, one camera per frame (the worst),
//! the baselines starting again after each flag (the fusion without the flagged camera is another
//! reference),
//! and only while at least three cameras would remain (two cannot outvote each other). A flagged camera stays flagged (it needs
//! recalibration, which is not something a session can do); the caller leaves it out of fusion.
//!
//! Median on median: a single bad frame, an occluded landmark or a detector's left/right swap in
//! one view does not move it; a camera whose every view is off does.

use std::collections::VecDeque;

use ergocell_skeleton::{Landmark, Skeleton3};

use crate::detections::Frame2;
use crate::metrics::median_in_place;
use crate::rig::{CameraIndex, CameraRig};

/// The monitor's tunables. Defaults: 2 s window of at least 10 frames, a 6 px floor, twice the
/// camera's own baseline and twice the other cameras', or 4× the others' alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResidualMonitorConfig {
    /// The sliding window, nanoseconds.
    pub window_nanos: i64,
    /// Frames a camera needs in its window before it can be judged.
    pub min_frames: usize,
    /// A window median below this (pixels) is never flagged, whatever the others do.
    pub min_residual_px: f64,
    /// Flagged above this multiple of its own baseline *and* of the others' median …
    pub ratio: f64,
    /// … or above this multiple of the others' median alone (a camera off from the start, before
    /// it had a baseline).
    pub ratio_without_baseline: f64,
    /// A camera's baseline is the median of its first this many frame residuals.
    pub baseline_frames: usize,
    /// Landmarks a view needs (with a fused landmark to compare) for its frame residual to count.
    pub min_landmarks: usize,
}

impl Default for ResidualMonitorConfig {
    fn default() -> Self {
        Self {
            window_nanos: 2_000_000_000,
            min_frames: 10,
            min_residual_px: 6.0,
            ratio: 2.0,
            ratio_without_baseline: 4.0,
            baseline_frames: 30,
            min_landmarks: 6,
        }
    }
}

/// A camera found out of calibration.
#[derive(Debug, Clone, PartialEq)]
pub struct OutOfCalibration {
    pub camera: CameraIndex,
    /// Its window median residual, pixels.
    pub residual_px: f64,
    /// The median of the other cameras' window medians, pixels.
    pub others_px: f64,
    /// Its own baseline (the median of its first frames), pixels, if it had one.
    pub baseline_px: Option<f64>,
    /// Frames in its window.
    pub frames: usize,
}

/// Finds cameras whose views stopped agreeing with the fused skeleton (see the module docs).
#[derive(Debug, Clone)]
pub struct CameraResidualMonitor {
    config: ResidualMonitorConfig,
    windows: Vec<VecDeque<(i64, f64)>>,
    /// Per camera: its first frame residuals until there are `baseline_frames`, then their median.
    first: Vec<Vec<f64>>,
    baselines: Vec<Option<f64>>,
    flagged: Vec<bool>,
    /// Per-frame buffers, reused (no allocation on the hot path once warm).
    residuals: Vec<Option<f64>>,
    medians: Vec<Option<f64>>,
    scratch: Vec<f64>,
}

impl CameraResidualMonitor {
    pub fn new(cameras: usize, config: ResidualMonitorConfig) -> Self {
        Self {
            config,
            windows: vec![VecDeque::new(); cameras],
            first: vec![Vec::new(); cameras],
            baselines: vec![None; cameras],
            flagged: vec![false; cameras],
            residuals: vec![None; cameras],
            medians: vec![None; cameras],
            scratch: Vec::new(),
        }
    }

    pub fn config(&self) -> &ResidualMonitorConfig {
        &self.config
    }

    /// Whether camera `k` has been found out of calibration.
    pub fn is_flagged(&self, k: CameraIndex) -> bool {
        self.flagged.get(k).copied().unwrap_or(false)
    }

    /// The cameras found so far.
    pub fn flagged(&self) -> impl Iterator<Item = CameraIndex> + '_ {
        self.flagged
            .iter()
            .enumerate()
            .filter(|(_, f)| **f)
            .map(|(k, _)| k)
    }

    /// Camera `k`'s window median, if it has enough frames.
    pub fn window_median(&mut self, k: CameraIndex) -> Option<f64> {
        let window = self.windows.get(k)?;
        if window.len() < self.config.min_frames {
            return None;
        }
        self.scratch.clear();
        self.scratch.extend(window.iter().map(|(_, r)| *r));
        median_in_place(&mut self.scratch)
    }

    /// One fused frame: each camera's median pixel distance between its observed keypoints and the
    /// fused skeleton's landmarks projected into it (counted when at least `min_landmarks` compare),
    /// then [`Self::observe`]. Returns the camera newly found out of calibration, if one is.
    pub fn observe_frame(
        &mut self,
        rig: &CameraRig,
        frame: &Frame2,
        skeleton: &Skeleton3,
    ) -> Option<OutOfCalibration> {
        let mut residuals = std::mem::take(&mut self.residuals);
        residuals.clear();
        residuals.resize(rig.len(), None);
        for view in &frame.views {
            let Some(camera) = rig.cameras().get(view.camera) else {
                continue;
            };
            self.scratch.clear();
            for landmark in Landmark::ALL {
                let (Some(k), Some(p)) = (view.get(landmark), skeleton.position(landmark)) else {
                    continue;
                };
                if let Ok(projected) = camera.project(&p) {
                    let d = (projected - k.pixel()).norm();
                    if d.is_finite() {
                        self.scratch.push(d);
                    }
                }
            }
            if self.scratch.len() >= self.config.min_landmarks.max(1) {
                residuals[view.camera] = median_in_place(&mut self.scratch);
            }
        }
        let found = self.observe(frame.stamp_nanos, &residuals);
        self.residuals = residuals;
        found
    }

    /// One frame's per-camera residuals (pixels; `None`: not seen) at `stamp_nanos`; returns the
    /// camera newly found out of calibration, if one is.
    pub fn observe(
        &mut self,
        stamp_nanos: i64,
        residuals: &[Option<f64>],
    ) -> Option<OutOfCalibration> {
        let oldest = stamp_nanos.saturating_sub(self.config.window_nanos);
        for (k, window) in self.windows.iter_mut().enumerate() {
            if let Some(Some(r)) = residuals.get(k) {
                window.push_back((stamp_nanos, *r));
                if self.baselines[k].is_none() {
                    let first = &mut self.first[k];
                    first.push(*r);
                    if first.len() >= self.config.baseline_frames.max(1) {
                        self.baselines[k] = median_in_place(first);
                        *first = Vec::new();
                    }
                }
            }
            while window.front().is_some_and(|(t, _)| *t < oldest) {
                window.pop_front();
            }
        }
        // Three must remain after flagging one: with two there is no majority to tell which is off.
        let unflagged = self.flagged.iter().filter(|f| !**f).count();
        if unflagged < 4 {
            return None;
        }
        let mut medians = std::mem::take(&mut self.medians);
        medians.clear();
        for k in 0..self.windows.len() {
            let m = if self.flagged[k] {
                None
            } else {
                self.window_median(k)
            };
            medians.push(m);
        }
        let found = self.judge(&medians);
        self.medians = medians;
        found
    }

    /// The worst camera of these window medians, if it is out of calibration (then flagged).
    fn judge(&mut self, medians: &[Option<f64>]) -> Option<OutOfCalibration> {
        let (worst, worst_px) = medians
            .iter()
            .enumerate()
            .filter_map(|(k, m)| m.map(|m| (k, m)))
            .max_by(|a, b| a.1.total_cmp(&b.1))?;
        self.scratch.clear();
        self.scratch.extend(
            medians
                .iter()
                .enumerate()
                .filter(|(k, _)| *k != worst)
                .filter_map(|(_, m)| *m),
        );
        if self.scratch.len() < 2 {
            return None;
        }
        let others_px = median_in_place(&mut self.scratch)?;
        let c = &self.config;
        let baseline_px = self.baselines[worst];
        let risen = baseline_px.is_some_and(|b| worst_px > c.ratio * b.max(others_px));
        let off = worst_px > c.min_residual_px
            && (risen || worst_px > c.ratio_without_baseline * others_px);
        if off {
            self.flagged[worst] = true;
            // The caller now fuses without it: every other camera's residual is measured against
            // another skeleton (its stereo partner, now alone on its side, sits further from it),
            // so the baselines start again; until they are set, only the others' route flags.
            for (baseline, first) in self.baselines.iter_mut().zip(self.first.iter_mut()) {
                *baseline = None;
                first.clear();
            }
            return Some(OutOfCalibration {
                camera: worst,
                residual_px: worst_px,
                others_px,
                baseline_px,
                frames: self.windows[worst].len(),
            });
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn feed(
        m: &mut CameraResidualMonitor,
        frames: i64,
        per_camera: &[f64],
    ) -> Vec<OutOfCalibration> {
        let mut found = Vec::new();
        for i in 0..frames {
            let r: Vec<Option<f64>> = per_camera
                .iter()
                .enumerate()
                // a little variation, deterministic
                .map(|(k, px)| Some(px * (1.0 + 0.1 * (((i + k as i64) % 3) as f64 - 1.0))))
                .collect();
            found.extend(m.observe(i * 100_000_000, &r));
        }
        found
    }

    #[test]
    fn calibrated_cameras_are_never_flagged() {
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        // One camera three times as noisy as the others, all within a few pixels: not a bump.
        assert!(feed(&mut m, 300, &[2.0, 2.5, 1.8, 6.0, 2.2, 2.1]).is_empty());
        // A camera at 7 px from the start (its baseline), three times the others: not a bump.
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        assert!(feed(&mut m, 300, &[2.5, 2.5, 7.0, 2.5, 2.5, 2.5]).is_empty());
    }

    #[test]
    fn a_bumped_camera_is_flagged_once_after_enough_frames() {
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        assert!(feed(&mut m, 50, &[2.0; 6]).is_empty());
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        let found = feed(&mut m, 50, &[2.0, 2.0, 25.0, 2.0, 2.0, 2.0]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].camera, 2);
        assert_eq!(
            found[0].frames, 10,
            "judged as soon as the window holds min_frames"
        );
        assert!(found[0].residual_px > 20.0 && found[0].others_px < 2.5);
        assert!(m.is_flagged(2));
        assert_eq!(m.flagged().collect::<Vec<_>>(), vec![2]);
    }

    #[test]
    fn a_camera_that_drifts_from_its_own_baseline_is_flagged() {
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        assert!(feed(&mut m, 100, &[3.5; 6]).is_empty());
        // Bumped by about a degree: 3.5 → 9 px, the others dragged a little, to 4 px.
        let found = feed(&mut m, 100, &[4.0, 9.0, 4.0, 4.0, 4.0, 4.0]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].camera, 1);
        assert!((found[0].baseline_px.unwrap() - 3.5).abs() < 0.5);
    }

    #[test]
    fn three_cameras_always_remain() {
        let mut m = CameraResidualMonitor::new(3, ResidualMonitorConfig::default());
        // Three cameras, one far off: flagging it would leave two, which cannot outvote each other.
        assert!(feed(&mut m, 100, &[2.0, 2.0, 30.0]).is_empty());
        let mut m = CameraResidualMonitor::new(4, ResidualMonitorConfig::default());
        let found = feed(&mut m, 100, &[2.0, 30.0, 2.0, 40.0]);
        assert_eq!(
            found.len(),
            1,
            "the worst only, then two are left: {found:?}"
        );
        assert_eq!(found[0].camera, 3);
    }

    #[test]
    fn old_frames_leave_the_window() {
        let config = ResidualMonitorConfig {
            min_frames: 5,
            ..ResidualMonitorConfig::default()
        };
        let mut m = CameraResidualMonitor::new(4, config);
        for i in 0..5 {
            m.observe(i * 100_000_000, &[Some(1.0); 4]);
        }
        assert_eq!(m.window_median(0), Some(1.0));
        // 10 s later: the old frames are gone, one new frame is not enough.
        m.observe(10_000_000_000, &[Some(1.0); 4]);
        assert_eq!(m.window_median(0), None);
    }

    #[test]
    fn after_a_flag_the_partner_left_alone_on_its_side_is_not_flagged_for_its_new_residual() {
        let mut m = CameraResidualMonitor::new(6, ResidualMonitorConfig::default());
        let mut t = 0;
        let mut run = |m: &mut CameraResidualMonitor, frames: i64, px: [f64; 6]| {
            let mut found = Vec::new();
            for _ in 0..frames {
                t += 100_000_000;
                if let Some(o) = m.observe(t, &px.map(Some)) {
                    // the caller fuses without it from the next frame on
                    found.push(o);
                    break;
                }
            }
            found.into_iter().map(|o| o.camera).collect::<Vec<_>>()
        };
        assert!(run(&mut m, 40, [3.0; 6]).is_empty());
        assert_eq!(run(&mut m, 30, [20.0, 3.0, 3.0, 3.0, 3.0, 3.0]), vec![0]);
        // Fused without camera 0, camera 1 (its stereo partner) sits 2.3x its old baseline: the
        // fusion changed, not camera 1.
        let partner = [20.0, 7.0, 3.0, 3.0, 3.0, 3.0];
        assert!(run(&mut m, 60, partner).is_empty(), "camera 1 flagged");
        // A camera really knocked afterwards is still found.
        assert_eq!(run(&mut m, 30, [20.0, 7.0, 30.0, 3.0, 3.0, 3.0]), vec![2]);
    }
}
