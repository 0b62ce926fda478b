//! A fixed-lag smoother: each frame's landmarks replaced by their mean over the frames within a
//! half window of time before and after it.
//!
//! The causal One-Euro filter ([`crate::temporal`]) must follow a reach or a glance as it happens,
//! so it lags and keeps much of a detector's slow error; a window centred on the frame has no lag
//! and averages both sides. The price is latency: a frame's smoothed skeleton exists only once its
//! window has closed. Offline (the ergonomist's review of a landmark file, [`centered_mean`]) that
//! costs nothing; live ([`FixedLagSmoother`]) it delays every score by the half window. On the
//! digital twin under the detector fitted to real MediaPipe data (`docs/sim`), ±0.5 s at 10 Hz took
//! per-frame RULA agreement from κ 0.77 (the causal filter) to 0.88.
//!
//! Live, a window closes on the clock ([`FixedLagSmoother::release_due`]), not only when a later
//! frame arrives: a frame is released once the clock is past its stamp by the half window, with
//! the frames that have arrived by then. Camera messages reach the cell some time after their
//! capture (the edge's inference and the network), so the newest of that time's frames are left
//! out of the window rather than waited for, up to [`MAX_CUT_NANOS`] of it (a longer transport, or
//! a cell clock ahead of the cameras', delays the release instead): the score, and the operator's
//! warning, come at the designed lag. The window then leans that much to the past, and live scores
//! are no longer exactly the offline [`centered_mean`]'s; the κ figures above are of whole windows.
//! A frame that arrives after a later one was released is not taken.
//!
//! The window is in time, not in frames: the same half window means the same at 10 Hz and at 60 Hz,
//! and a frame across a gap in the recording (the operator out of sight) is never averaged in. Each
//! landmark is averaged over the frames of the window that observed it (a frame that lacks it adds
//! nothing); a landmark the centre frame lacks stays missing (never smoothed into existence); the
//! legs below the hips are not averaged ([`NOT_AVERAGED`]). At the ends of a sequence the window is
//! cut, not mirrored. Confidence and the other fields of the centre frame are kept.

use std::collections::VecDeque;

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

/// The longest half window accepted, seconds: a minute either side is no longer smoothing.
pub const MAX_HALF_WINDOW_S: f64 = 60.0;

/// A half window that is not a time in `(0, MAX_HALF_WINDOW_S]`.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "the fixed-lag half window must be a time > 0 s and at most {MAX_HALF_WINDOW_S} s, not {0} s"
)]
pub struct BadHalfWindow(pub f64);

/// The half window in nanoseconds, checked.
pub fn half_window_nanos(half_window_s: f64) -> Result<i64, BadHalfWindow> {
    if half_window_s.is_finite() && half_window_s > 0.0 && half_window_s <= MAX_HALF_WINDOW_S {
        Ok((half_window_s * 1e9).round() as i64)
    } else {
        Err(BadHalfWindow(half_window_s))
    }
}

/// The most of a window's newer side that a release on the clock leaves out, nanoseconds: 0.1 s.
///
/// On the clock a frame is due once the clock is past its stamp by the half window, but never
/// sooner than the half window less this after it arrived. With the cameras' clocks in step with
/// the cell's, the frames still in transit at the due time (the edge's inference and the network,
/// up to this long) are left out and the score comes at the designed lag; a slower transport, or a
/// cell clock ahead of the cameras', delays the release instead of cutting more: the window keeps
/// all but its newest 0.1 s whatever the clocks say. A cell clock behind the cameras' delays it
/// until the window is whole, as the release on arrival does.
pub const MAX_CUT_NANOS: i64 = 100_000_000;

/// The live smoother: frames in (time order), smoothed frames out once their window has closed.
#[derive(Debug, Clone)]
pub struct FixedLagSmoother {
    half_window_nanos: i64,
    /// Frames still needed: the unreleased ones and those within the half window before the oldest
    /// unreleased one, each with the time it arrived (the caller's clock).
    frames: VecDeque<(Skeleton3, i64)>,
    /// How many frames at the front of `frames` have been released.
    released: usize,
    /// The stamp of the newest frame released: no frame older than it is taken.
    last_released_nanos: Option<i64>,
}

impl FixedLagSmoother {
    /// A smoother of ±`half_window_s` seconds.
    pub fn new(half_window_s: f64) -> Result<Self, BadHalfWindow> {
        Ok(Self {
            half_window_nanos: half_window_nanos(half_window_s)?,
            frames: VecDeque::new(),
            released: 0,
            last_released_nanos: None,
        })
    }

    /// A new frame that arrived at its own stamp (a recording, the twin); as
    /// [`Self::push_arrived`].
    pub fn push(&mut self, frame: Skeleton3) -> Vec<Skeleton3> {
        let stamp = frame.stamp_nanos;
        self.push_arrived(frame, stamp)
    }

    /// A new frame that arrived at `arrived_nanos` (the clock of [`Self::release_due`]); returns
    /// the frames (smoothed, in time order) whose window it closed: those more than the half window
    /// older than it. A frame older than the last one, or than the last one released, is not taken
    /// (time went backwards, or it came after its time was scored; the next frames close the window
    /// as usual).
    pub fn push_arrived(&mut self, frame: Skeleton3, arrived_nanos: i64) -> Vec<Skeleton3> {
        let stamp = frame.stamp_nanos;
        if self
            .frames
            .back()
            .is_some_and(|(f, _)| f.stamp_nanos > stamp)
            || self.last_released_nanos.is_some_and(|t| t > stamp)
        {
            return Vec::new();
        }
        self.frames.push_back((frame, arrived_nanos));
        self.advance(stamp)
    }

    /// Time has reached `stamp_nanos` in the frames' own time (a frame without the operator): the
    /// windows of the frames more than the half window older have closed, whole; they are
    /// released.
    pub fn advance(&mut self, stamp_nanos: i64) -> Vec<Skeleton3> {
        let w = self.half_window_nanos;
        self.release_while(|centre, _| stamp_nanos.saturating_sub(centre.stamp_nanos) > w)
    }

    /// The clock has reached `now_nanos`: every frame due by then ([`Self::next_release_nanos`],
    /// [`MAX_CUT_NANOS`]) is released, on the frames that have arrived.
    pub fn release_due(&mut self, now_nanos: i64) -> Vec<Skeleton3> {
        let (w, cut) = (self.half_window_nanos, MAX_CUT_NANOS);
        self.release_while(|centre, arrived| now_nanos > due(centre.stamp_nanos, arrived, w, cut))
    }

    /// Releases frames from the oldest unreleased one while `closed(frame, arrived)` holds.
    fn release_while(&mut self, closed: impl Fn(&Skeleton3, i64) -> bool) -> Vec<Skeleton3> {
        let mut out = Vec::new();
        while let Some((centre, arrived)) = self.frames.get(self.released) {
            if !closed(centre, *arrived) {
                break;
            }
            self.last_released_nanos = Some(centre.stamp_nanos);
            out.push(self.smoothed(self.released));
            self.released += 1;
        }
        self.forget();
        out
    }

    /// Every frame not yet released, on the window cut at the end (the sequence is over).
    pub fn flush(&mut self) -> Vec<Skeleton3> {
        let out = (self.released..self.frames.len())
            .map(|n| self.smoothed(n))
            .collect();
        self.last_released_nanos = self
            .frames
            .back()
            .map(|(f, _)| f.stamp_nanos)
            .or(self.last_released_nanos);
        self.frames.clear();
        self.released = 0;
        out
    }

    /// When the oldest unreleased frame is due on the clock, if there is one:
    /// [`Self::release_due`] at any time past this releases it.
    pub fn next_release_nanos(&self) -> Option<i64> {
        self.frames.get(self.released).map(|(f, arrived)| {
            due(
                f.stamp_nanos,
                *arrived,
                self.half_window_nanos,
                MAX_CUT_NANOS,
            )
        })
    }

    /// Drops the frames no unreleased frame's window reaches.
    fn forget(&mut self) {
        let oldest_needed = self
            .frames
            .get(self.released)
            .map(|(f, _)| f.stamp_nanos.saturating_sub(self.half_window_nanos));
        while self.released > 0
            && self
                .frames
                .front()
                .is_some_and(|(f, _)| oldest_needed.is_none_or(|t| f.stamp_nanos < t))
        {
            self.frames.pop_front();
            self.released -= 1;
        }
    }

    /// Frame `n` of `frames` on its window: the frames (in time order) within the half window of
    /// its stamp, a contiguous run.
    fn smoothed(&self, n: usize) -> Skeleton3 {
        let mut out = self.frames[n].0.clone();
        let centre = out.stamp_nanos;
        let w = self.half_window_nanos;
        let lo = self
            .frames
            .partition_point(|(f, _)| f.stamp_nanos < centre.saturating_sub(w));
        let hi = self
            .frames
            .partition_point(|(f, _)| f.stamp_nanos <= centre.saturating_add(w));
        for landmark in Landmark::ALL {
            if NOT_AVERAGED.contains(&landmark) {
                continue;
            }
            let Some(mut estimate) = out.get(landmark).copied() else {
                continue;
            };
            let (sum, count) = self
                .frames
                .range(lo..hi)
                .filter_map(|(f, _)| f.position(landmark))
                .fold((Vector3::zeros(), 0u32), |(s, c), p| (s + p.coords, c + 1));
            // count ≥ 1: the centre frame observed it
            estimate.position_m = Point3::from(sum / f64::from(count.max(1)));
            // A mean of finite positions is finite, so the estimate stays valid.
            let _ = out.set(landmark, Some(estimate));
        }
        out
    }
}

/// When a frame stamped `stamp` that arrived at `arrived` is due on the clock: its stamp plus the
/// half window `w`, but not before `arrived + w − cut`.
fn due(stamp: i64, arrived: i64, w: i64, cut: i64) -> i64 {
    stamp
        .saturating_add(w)
        .max(arrived.saturating_add(w).saturating_sub(cut))
}

/// Why a sequence could not be smoothed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum FixedLagError {
    #[error(transparent)]
    BadHalfWindow(#[from] BadHalfWindow),
    /// The live smoother skips a frame from the past; a whole sequence must not have one.
    #[error("frame {index}: its stamp is earlier than the frame before it (time went backwards)")]
    OutOfOrder { index: usize },
}

/// A whole sequence (in time order) smoothed at once: every frame on its window of ±`half_window_s`,
/// as [`FixedLagSmoother`] releases them live.
pub fn centered_mean(
    frames: &[Skeleton3],
    half_window_s: f64,
) -> Result<Vec<Skeleton3>, FixedLagError> {
    if let Some(index) = frames
        .windows(2)
        .position(|w| w[1].stamp_nanos < w[0].stamp_nanos)
    {
        return Err(FixedLagError::OutOfOrder { index: index + 1 });
    }
    let mut smoother = FixedLagSmoother::new(half_window_s)?;
    let mut out = Vec::with_capacity(frames.len());
    for f in frames {
        out.extend(smoother.push(f.clone()));
    }
    out.extend(smoother.flush());
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_skeleton::LandmarkEstimate;

    const MS: i64 = 1_000_000;

    fn frame(stamp: i64, x: f64, with_nose: bool) -> Skeleton3 {
        let slots = Landmark::ALL
            .iter()
            .map(|l| {
                (with_nose || *l != Landmark::Nose).then(|| LandmarkEstimate {
                    position_m: Point3::new(x, l.index() as f64 * 0.01, 1.0),
                    confidence: 0.9,
                    reprojection_error_px: None,
                    views: 2,
                    position_sd_m: None,
                })
            })
            .collect();
        Skeleton3::try_from_slots(stamp, slots).unwrap()
    }

    fn x(f: &Skeleton3) -> f64 {
        f.position(Landmark::LeftWrist).unwrap().x
    }

    #[test]
    fn a_steady_motion_is_unchanged_inside_and_noise_is_averaged() {
        // 10 Hz, x moves 1 cm per frame: a centred mean of a straight line is the line itself
        let line: Vec<_> = (0..20)
            .map(|i| frame(i * 100 * MS, 0.01 * i as f64, true))
            .collect();
        let s = centered_mean(&line, 0.3).unwrap();
        assert_eq!(s.len(), 20);
        for n in 3..17 {
            assert!(
                (x(&s[n]) - 0.01 * n as f64).abs() < 1e-12,
                "frame {n}: {}",
                x(&s[n])
            );
        }
        // alternating ±1 cm noise around 0: averaged down to at most 1/7 of it
        let noisy: Vec<_> = (0..20)
            .map(|i| frame(i * 100 * MS, if i % 2 == 0 { 0.01 } else { -0.01 }, true))
            .collect();
        let s = centered_mean(&noisy, 0.3).unwrap();
        for f in &s[3..17] {
            assert!(x(f).abs() <= 0.01 / 7.0 + 1e-12);
        }
        // the legs stay as fused
        for (f, g) in s.iter().zip(&noisy) {
            for lm in NOT_AVERAGED {
                assert_eq!(f.position(lm), g.position(lm));
            }
        }
    }

    #[test]
    fn the_window_is_in_time_the_same_at_any_rate_and_stops_at_gaps() {
        // ±0.1 s: 3 frames at 10 Hz, 13 at 60 Hz; a step from 0 to 1 at t = 1 s
        for interval in [100 * MS, 16_666_667] {
            let frames: Vec<_> = (0..120)
                .map(|i| {
                    let t = i * interval;
                    frame(t, if t >= 1_000_000_000 { 1.0 } else { 0.0 }, true)
                })
                .collect();
            let s = centered_mean(&frames, 0.1).unwrap();
            for (f, g) in s.iter().zip(&frames) {
                let away = (g.stamp_nanos - 1_000_000_000).abs();
                if away > 100 * MS + interval {
                    assert_eq!(x(f), x(g), "{interval}: {}", g.stamp_nanos);
                }
            }
        }
        // x = 0 for 10 frames, then 8 s later x = 1: the gap's far side is not averaged in
        let mut gap: Vec<_> = (0..10).map(|i| frame(i * 100 * MS, 0.0, true)).collect();
        gap.extend((0..10).map(|i| frame(9_000 * MS + i * 100 * MS, 1.0, true)));
        let s = centered_mean(&gap, 0.5).unwrap();
        for (i, f) in s.iter().enumerate() {
            assert_eq!(x(f), if i < 10 { 0.0 } else { 1.0 }, "frame {i}");
        }
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 61.0] {
            let Err(FixedLagError::BadHalfWindow(e)) = centered_mean(&gap, bad) else {
                panic!("{bad} accepted");
            };
            assert!(e.0 == bad || (e.0.is_nan() && bad.is_nan()), "{e}");
        }
    }

    #[test]
    fn live_frames_come_out_half_a_window_late_and_as_offline() {
        let frames: Vec<_> = (0..50)
            .map(|i| {
                frame(
                    i * 100 * MS + (i % 3) * 3 * MS,
                    (i as f64 * 0.7).sin(),
                    true,
                )
            })
            .collect();
        let offline = centered_mean(&frames, 0.5).unwrap();
        let mut live = FixedLagSmoother::new(0.5).unwrap();
        let mut out = Vec::new();
        for f in &frames {
            for released in live.push(f.clone()) {
                // released only once a frame more than 0.5 s later has arrived
                assert!(f.stamp_nanos - released.stamp_nanos > 500 * MS);
                assert!(f.stamp_nanos - released.stamp_nanos <= 600 * MS + 6 * MS);
                out.push(released);
            }
        }
        assert!(out.len() >= 44, "{}", out.len());
        // the operator gone: time moves on without frames and the rest comes out
        out.extend(live.advance(frames[49].stamp_nanos + 501 * MS));
        assert_eq!(out, offline);
        assert!(live.flush().is_empty());
        // a frame from the past is not taken
        let mut live = FixedLagSmoother::new(0.5).unwrap();
        assert!(live.push(frames[10].clone()).is_empty());
        assert!(live.push(frames[5].clone()).is_empty());
        assert_eq!(live.flush().len(), 1);
        // offline, a frame from the past is an error, not a frame left out
        let backwards = [frames[10].clone(), frames[5].clone()];
        assert_eq!(
            centered_mean(&backwards, 0.5),
            Err(FixedLagError::OutOfOrder { index: 1 })
        );
    }

    #[test]
    fn on_the_clock_a_frame_is_released_at_its_lag_on_the_frames_that_arrived() {
        // 10 Hz, x = frame index
        let frames: Vec<_> = (0..30)
            .map(|i| frame(i * 100 * MS, i as f64, true))
            .collect();
        // Frames that arrive 80 ms after their stamps are due at the lag (500 ms); 250 ms after,
        // at 650 ms: no more than the newest 100 ms of a window is left out, whatever the delay
        // (or a cell clock ahead of the cameras').
        for (delay, due) in [(80 * MS, 500 * MS), (250 * MS, 650 * MS)] {
            let mut live = FixedLagSmoother::new(0.5).unwrap();
            let mut out = Vec::new();
            let mut next = 0;
            // the clock ticks every 10 ms; each frame is pushed once it has arrived
            for now in (0..3_000 * MS).step_by(10 * MS as usize) {
                while next < frames.len() && frames[next].stamp_nanos + delay <= now {
                    let f = frames[next].clone();
                    out.extend(live.push_arrived(f, now).into_iter().map(|f| (now, f)));
                    next += 1;
                }
                let expected = live.next_release_nanos();
                let released = live.release_due(now);
                assert_eq!(
                    !released.is_empty(),
                    expected.is_some_and(|d| now > d),
                    "at {now}: due {expected:?}"
                );
                out.extend(released.into_iter().map(|f| (now, f)));
            }
            let last = (3_000 * MS - 10 * MS - due - 1) / (100 * MS);
            assert_eq!(out.len() as i64, last + 1, "{delay}: frames 0..={last}");
            for (now, f) in &out {
                // released on the clock, within a tick of its due time, not when frame +6 arrived
                let after = now - f.stamp_nanos;
                assert!(after > due && after <= due + 10 * MS, "{delay}: {after}");
            }
            // frame 10 (1 s): frames 5..=14 had arrived, 15 (the window's newest) not yet
            let (_, ten) = &out[10];
            assert_eq!(ten.stamp_nanos, 1_000 * MS);
            assert!((x(ten) - 9.5).abs() < 1e-12, "{delay}: {}", x(ten));
        }
        // a frame older than one released is not taken, even with nothing unreleased before it
        let mut live = FixedLagSmoother::new(0.5).unwrap();
        assert!(live.push(frames[10].clone()).is_empty());
        assert_eq!(live.release_due(2_000 * MS).len(), 1);
        assert_eq!(live.next_release_nanos(), None);
        assert!(live.push(frames[8].clone()).is_empty());
        assert!(live.flush().is_empty());
        assert!(live.push(frames[12].clone()).is_empty());
        assert_eq!(live.next_release_nanos(), Some(1_700 * MS));
    }

    #[test]
    fn a_missing_landmark_is_neither_invented_nor_counted() {
        let frames = vec![
            frame(0, 0.0, true),
            frame(100 * MS, 1.0, false),
            frame(200 * MS, 2.0, true),
        ];
        let s = centered_mean(&frames, 0.1).unwrap();
        assert!(
            s[1].get(Landmark::Nose).is_none(),
            "smoothed into existence"
        );
        // the nose of frame 0 averages frames 0 and 1, but frame 1 has none: only frame 0 counts
        assert_eq!(s[0].position(Landmark::Nose).unwrap().x, 0.0);
        assert_eq!(s[2].position(Landmark::Nose).unwrap().x, 2.0);
        // the ends are cut windows: frame 0 averages frames 0..=1
        assert_eq!(x(&s[0]), 0.5);
        assert_eq!(s.len(), 3);
    }
}
