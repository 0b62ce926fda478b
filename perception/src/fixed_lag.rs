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

/// The frames (in time order) with each landmark's position replaced by its mean over the frames
/// within `half_window` of it (0: unchanged), but for [`NOT_AVERAGED`].
pub fn centered_mean(frames: &[Skeleton3], half_window: usize) -> Vec<Skeleton3> {
    let mut out = frames.to_vec();
    if half_window == 0 {
        return out;
    }
    for (n, smoothed) in out.iter_mut().enumerate() {
        let lo = n.saturating_sub(half_window);
        let hi = (n + half_window).min(frames.len().saturating_sub(1));
        for landmark in Landmark::ALL {
            if NOT_AVERAGED.contains(&landmark) {
                continue;
            }
            let Some(mut estimate) = smoothed.get(landmark).copied() else {
                continue;
            };
            let (sum, count) = frames[lo..=hi]
                .iter()
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
