//! A fixed-lag smoother: each frame's landmarks replaced by their mean over the frames up to
//! `half_window` before and after it.
//!
//! The causal One-Euro filter ([`crate::temporal`]) must follow a reach or a glance as it happens,
//! so it lags and keeps much of a detector's slow error; a window centred on the frame has no lag
//! and averages both sides. The price is latency: a frame's smoothed skeleton exists only once
//! `half_window` later frames have arrived. Offline (the ergonomist's review of a recording) that
//! costs nothing; live it delays every score by the half window. On the digital twin under the
//! detector fitted to real MediaPipe data (`docs/sim`), ±5 frames at 10 Hz took per-frame RULA
//! agreement from κ 0.77 (the causal filter) to 0.89.
//!
//! Each landmark is averaged over the frames of the window that observed it (a frame that lacks it
//! adds nothing); a landmark the centre frame lacks stays missing (never smoothed into existence);
//! the legs below the hips are not averaged ([`NOT_AVERAGED`]).
//! At the ends of a sequence the window is cut, not mirrored. Confidence and the other fields of the
//! centre frame are kept.
//!
//! A recording's window is given in time ([`FixedLag::over`]: ±0.5 s is ±5 frames at 10 Hz, ±30 at
//! 60 Hz, from the median frame interval), and a frame more than the window's span away in time —
//! across a gap in the recording — is not averaged in ([`centered_mean_within`]).

use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Point3, Vector3};

/// The legs below the hips are left as fused. RULA scores them as a stance ("supported, weight
/// evenly balanced": both feet on the floor, the hips over them), and a mean across a stride is no
/// stance anyone stood in: on the twin, averaging the feet of an operator walking in raised
/// "weight on one leg" warnings several times as often as the truth's.
pub const NOT_AVERAGED: [Landmark; 8] = [
    Landmark::LeftKnee,
    Landmark::RightKnee,
    Landmark::LeftAnkle,
    Landmark::RightAnkle,
    Landmark::LeftHeel,
    Landmark::RightHeel,
    Landmark::LeftFootIndex,
    Landmark::RightFootIndex,
];

/// A fixed-lag window for a sequence of frames: how many frames either side of each, and how far in
/// time a frame may be from the centre to be averaged in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedLag {
    /// Frames either side of the centre.
    pub half_window: usize,
    /// A frame farther than this from the centre frame's stamp is left out (a gap in the recording).
    pub max_offset_nanos: i64,
}

/// Why no window could be set for a sequence.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FixedLagError {
    #[error("the fixed-lag half window must be a finite time > 0 s, not {0} s")]
    BadHalfWindow(f64),
    #[error("{0} frame(s) with increasing stamps: too few to know the frame rate (at least 2)")]
    TooFewFrames(usize),
    #[error("a half window of {half_window_s} s is {frames} frames at the median interval of {interval_s} s: more than {max} frames")]
    TooLong {
        half_window_s: f64,
        interval_s: f64,
        frames: f64,
        max: usize,
    },
}

/// The most frames either side a window may span ([`FixedLag::over`]).
pub const MAX_HALF_WINDOW_FRAMES: usize = 1000;

impl FixedLag {
    /// The window of ±`half_window_s` seconds on `frames` (in time order): the number of frames it
    /// spans at their median interval (at least 1), and a time bound of that many intervals plus a
    /// half, so that a frame across a gap is not averaged in while the stamp jitter of a steady rate
    /// keeps every frame of the window.
    pub fn over(frames: &[Skeleton3], half_window_s: f64) -> Result<Self, FixedLagError> {
        if !(half_window_s.is_finite() && half_window_s > 0.0) {
            return Err(FixedLagError::BadHalfWindow(half_window_s));
        }
        let mut intervals: Vec<i64> = frames
            .windows(2)
            .map(|w| w[1].stamp_nanos.saturating_sub(w[0].stamp_nanos))
            .filter(|d| *d > 0)
            .collect();
        if intervals.is_empty() {
            return Err(FixedLagError::TooFewFrames(frames.len()));
        }
        intervals.sort_unstable();
        let interval = intervals[intervals.len() / 2] as f64 * 1e-9;
        let span = half_window_s / interval;
        if span > MAX_HALF_WINDOW_FRAMES as f64 {
            return Err(FixedLagError::TooLong {
                half_window_s,
                interval_s: interval,
                frames: span,
                max: MAX_HALF_WINDOW_FRAMES,
            });
        }
        let half_window = (span.round() as usize).max(1);
        Ok(Self {
            half_window,
            max_offset_nanos: ((half_window as f64 + 0.5) * interval * 1e9).round() as i64,
        })
    }
}

/// The frames (in time order) with each landmark's position replaced by its mean over the frames
/// within `half_window` of it (0: unchanged), but for [`NOT_AVERAGED`].
pub fn centered_mean(frames: &[Skeleton3], half_window: usize) -> Vec<Skeleton3> {
    centered_mean_within(
        frames,
        FixedLag {
            half_window,
            max_offset_nanos: i64::MAX,
        },
    )
}

/// [`centered_mean`] over the window `lag`: frames within `lag.half_window` places of the centre
/// and `lag.max_offset_nanos` of its stamp.
pub fn centered_mean_within(frames: &[Skeleton3], lag: FixedLag) -> Vec<Skeleton3> {
    let mut out = frames.to_vec();
    let half_window = lag.half_window;
    if half_window == 0 {
        return out;
    }
    for (n, smoothed) in out.iter_mut().enumerate() {
        let lo = n.saturating_sub(half_window);
        let hi = (n + half_window).min(frames.len().saturating_sub(1));
        let centre = smoothed.stamp_nanos;
        let near =
            |f: &&Skeleton3| f.stamp_nanos.abs_diff(centre) <= lag.max_offset_nanos.unsigned_abs();
        for landmark in Landmark::ALL {
            if NOT_AVERAGED.contains(&landmark) {
                continue;
            }
            let Some(mut estimate) = smoothed.get(landmark).copied() else {
                continue;
            };
            let (sum, count) = frames[lo..=hi]
                .iter()
                .filter(near)
                .filter_map(|f| f.position(landmark))
                .fold((Vector3::zeros(), 0u32), |(s, c), p| (s + p.coords, c + 1));
            // count ≥ 1: the centre frame observed it
            estimate.position_m = Point3::from(sum / f64::from(count.max(1)));
            // A mean of finite positions is finite, so the estimate stays valid.
            let _ = smoothed.set(landmark, Some(estimate));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_skeleton::LandmarkEstimate;

    fn frame(stamp: i64, x: f64, with_nose: bool) -> Skeleton3 {
        let slots = Landmark::ALL
            .iter()
            .map(|l| {
                (with_nose || *l != Landmark::Nose).then(|| LandmarkEstimate {
                    position_m: Point3::new(x, l.index() as f64 * 0.01, 1.0),
                    confidence: 0.9,
                    reprojection_error_px: None,
                    views: 2,
                })
            })
            .collect();
        Skeleton3::try_from_slots(stamp, slots).unwrap()
    }

    #[test]
    fn a_steady_motion_is_unchanged_inside_and_noise_is_averaged() {
        // x moves 1 cm per frame: a centred mean of a straight line is the line itself (no lag)
        let line: Vec<_> = (0..20).map(|i| frame(i, 0.01 * i as f64, true)).collect();
        let s = centered_mean(&line, 3);
        for n in 3..17 {
            let x = s[n].position(Landmark::LeftWrist).unwrap().x;
            assert!((x - 0.01 * n as f64).abs() < 1e-12, "frame {n}: {x}");
        }
        // alternating ±1 cm noise around 0: averaged down to at most 1/7 of it
        let noisy: Vec<_> = (0..20)
            .map(|i| frame(i, if i % 2 == 0 { 0.01 } else { -0.01 }, true))
            .collect();
        let s = centered_mean(&noisy, 3);
        for f in &s[3..17] {
            assert!(f.position(Landmark::LeftWrist).unwrap().x.abs() <= 0.01 / 7.0 + 1e-12);
        }
        assert_eq!(centered_mean(&noisy, 0), noisy);
        // the legs stay as fused
        for (f, g) in s.iter().zip(&noisy) {
            for lm in NOT_AVERAGED {
                assert_eq!(f.position(lm), g.position(lm));
            }
        }
    }

    #[test]
    fn a_window_in_seconds_follows_the_frame_rate_and_stops_at_gaps() {
        // 10 Hz with a few ms of jitter: ±0.5 s is ±5 frames
        let at_10hz: Vec<_> = (0..30)
            .map(|i| frame(i * 100_000_000 + (i % 3) * 3_000_000, 0.0, true))
            .collect();
        let lag = FixedLag::over(&at_10hz, 0.5).unwrap();
        assert_eq!(lag.half_window, 5);
        // 5.5 median intervals (103 ms here): the ±5th frames are in, the ±6th are not
        assert_eq!(lag.max_offset_nanos, 566_500_000);
        // 60 Hz: ±30 frames; a short window is still one frame either side
        let at_60hz: Vec<_> = (0..100).map(|i| frame(i * 16_666_667, 0.0, true)).collect();
        assert_eq!(FixedLag::over(&at_60hz, 0.5).unwrap().half_window, 30);
        assert_eq!(FixedLag::over(&at_60hz, 0.001).unwrap().half_window, 1);
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                FixedLag::over(&at_10hz, bad),
                Err(FixedLagError::BadHalfWindow(_))
            ));
        }
        assert!(matches!(
            FixedLag::over(&at_10hz[..1], 0.5),
            Err(FixedLagError::TooFewFrames(1))
        ));
        assert!(matches!(
            FixedLag::over(&at_60hz, 1e6),
            Err(FixedLagError::TooLong { .. })
        ));
        // x = 0 for 10 frames, then 8 s later x = 1: the gap's far side is not averaged in
        let mut gap: Vec<_> = (0..10).map(|i| frame(i * 100_000_000, 0.0, true)).collect();
        gap.extend((0..10).map(|i| frame(9_000_000_000 + i * 100_000_000, 1.0, true)));
        let lag = FixedLag::over(&gap, 0.5).unwrap();
        let s = centered_mean_within(&gap, lag);
        for (i, f) in s.iter().enumerate() {
            let x = f.position(Landmark::LeftWrist).unwrap().x;
            assert_eq!(x, if i < 10 { 0.0 } else { 1.0 }, "frame {i}");
        }
        // by index alone the gap is crossed
        let crossed = centered_mean(&gap, 5);
        assert!(crossed[9].position(Landmark::LeftWrist).unwrap().x > 0.0);
    }

    #[test]
    fn a_missing_landmark_is_neither_invented_nor_counted() {
        let frames = vec![
            frame(0, 0.0, true),
            frame(1, 1.0, false),
            frame(2, 2.0, true),
        ];
        let s = centered_mean(&frames, 1);
        assert!(
            s[1].get(Landmark::Nose).is_none(),
            "smoothed into existence"
        );
        // the nose of frame 0 averages frames 0 and 1, but frame 1 has none: only frame 0 counts
        assert_eq!(s[0].position(Landmark::Nose).unwrap().x, 0.0);
        assert_eq!(s[2].position(Landmark::Nose).unwrap().x, 2.0);
        // the ends are cut windows: frame 0 averages frames 0..=1
        assert_eq!(s[0].position(Landmark::LeftWrist).unwrap().x, 0.5);
        assert_eq!(s.len(), 3);
    }
}
