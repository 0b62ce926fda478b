//! Time: aligning frames from different cameras, and a causal filter for the real-time path.
//!
//! - [`FrameAssembler`] groups per-camera views whose stamps lie within a stated tolerance of each
//!   other into one [`Frame2`]. A frame is released as soon as every camera has contributed, or when
//!   its deadline (`max_wait_nanos` after its first view, on the caller's clock) passes — then with the
//!   cameras it has: a late or missing camera degrades the estimate, it never blocks it. A view that
//!   arrives after its frame was released is dropped and counted.
//! - [`OneEuroFilter`] (Casiez, Roussel & Vogel, CHI 2012): a speed-adaptive low-pass filter per
//!   coordinate — little lag when the operator moves fast, strong smoothing when still. Causal: each
//!   output depends only on the past. A landmark unseen for longer than `max_gap_nanos` restarts.

use std::collections::VecDeque;

use ergocell_skeleton::{LandmarkEstimate, Skeleton3, LANDMARK_COUNT};
use nalgebra::Vector3;

use crate::detections::{Frame2, View2};

/// Groups per-camera views into time-aligned frames (see the module docs).
#[derive(Debug, Clone)]
pub struct FrameAssembler {
    camera_count: usize,
    tolerance_nanos: i64,
    max_wait_nanos: i64,
    pending: VecDeque<Pending>,
    last_released_nanos: Option<i64>,
    late_views: usize,
}

#[derive(Debug, Clone)]
struct Pending {
    reference_nanos: i64,
    opened_at_nanos: i64,
    views: Vec<View2>,
}

impl FrameAssembler {
    /// `tolerance_nanos`: how far apart two cameras' stamps may be and still be one instant (e.g. half
    /// a frame period); `max_wait_nanos`: how long a frame waits for missing cameras.
    pub fn new(camera_count: usize, tolerance_nanos: i64, max_wait_nanos: i64) -> Self {
        Self {
            camera_count,
            tolerance_nanos: tolerance_nanos.max(0),
            max_wait_nanos: max_wait_nanos.max(0),
            pending: VecDeque::new(),
            last_released_nanos: None,
            late_views: 0,
        }
    }

    /// Views dropped because their frame had already been released.
    pub fn late_views(&self) -> usize {
        self.late_views
    }

    /// Adds a view received at `now_nanos`; returns the frames that are complete.
    pub fn push(&mut self, view: View2, now_nanos: i64) -> Vec<Frame2> {
        if let Some(last) = self.last_released_nanos {
            if view.stamp_nanos <= last + self.tolerance_nanos {
                self.late_views += 1;
                return self.poll(now_nanos);
            }
        }
        let slot = self.pending.iter_mut().find(|p| {
            (p.reference_nanos - view.stamp_nanos).abs() <= self.tolerance_nanos
                && p.views.iter().all(|v| v.camera != view.camera)
        });
        if let Some(p) = slot {
            p.views.push(view);
        } else {
            let at = self
                .pending
                .iter()
                .position(|p| p.reference_nanos > view.stamp_nanos)
                .unwrap_or(self.pending.len());
            self.pending.insert(
                at,
                Pending {
                    reference_nanos: view.stamp_nanos,
                    opened_at_nanos: now_nanos,
                    views: vec![view],
                },
            );
        }
        self.poll(now_nanos)
    }

    /// Releases, in time order, every frame that is complete or past its deadline at `now_nanos`.
    pub fn poll(&mut self, now_nanos: i64) -> Vec<Frame2> {
        let mut out = Vec::new();
        // Release from the front only, so frames leave in time order.
        while let Some(front) = self.pending.front() {
            let complete = front.views.len() >= self.camera_count;
            let expired = now_nanos - front.opened_at_nanos >= self.max_wait_nanos;
            // a complete later frame also releases earlier ones that can no longer complete in time
            let overtaken = self
                .pending
                .iter()
                .skip(1)
                .any(|p| p.views.len() >= self.camera_count);
            if !(complete || expired || overtaken) {
                break;
            }
            let Some(p) = self.pending.pop_front() else {
                break;
            };
            self.last_released_nanos = Some(p.reference_nanos);
            let mut views = p.views;
            views.sort_by_key(|v| v.camera);
            out.push(Frame2 {
                stamp_nanos: p.reference_nanos,
                views,
            });
        }
        out
    }

    /// Releases everything still pending (end of stream).
    pub fn flush(&mut self) -> Vec<Frame2> {
        self.poll(i64::MAX)
    }
}

/// Parameters of the One-Euro filter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneEuroParams {
    /// Cut-off frequency at rest, Hz (lower: smoother, more lag when still).
    pub min_cutoff_hz: f64,
    /// Speed coefficient, 1/m (higher: less lag when moving fast).
    pub beta: f64,
    /// Cut-off of the speed estimate, Hz.
    pub derivative_cutoff_hz: f64,
    /// A landmark unseen for longer restarts its filter.
    pub max_gap_nanos: i64,
}

impl Default for OneEuroParams {
    /// Tuned for body landmarks at 10–30 Hz: ~1 Hz smoothing at rest, lag shrinking above ~0.5 m/s.
    fn default() -> Self {
        Self {
            min_cutoff_hz: 1.0,
            beta: 2.0,
            derivative_cutoff_hz: 1.0,
            max_gap_nanos: 500_000_000,
        }
    }
}

#[derive(Debug, Clone, Copy)]
struct State {
    x: Vector3<f64>,
    dx: Vector3<f64>,
    stamp_nanos: i64,
}

/// A causal One-Euro filter over whole skeletons (each landmark and axis independently).
#[derive(Debug, Clone)]
pub struct OneEuroFilter {
    params: OneEuroParams,
    states: [Option<State>; LANDMARK_COUNT],
}

fn alpha(cutoff_hz: f64, dt_s: f64) -> f64 {
    let tau = 1.0 / (2.0 * std::f64::consts::PI * cutoff_hz);
    1.0 / (1.0 + tau / dt_s)
}

impl OneEuroFilter {
    /// A filter with these parameters.
    pub fn new(params: OneEuroParams) -> Self {
        Self {
            params,
            states: [None; LANDMARK_COUNT],
        }
    }

    /// Filters one skeleton; unobserved landmarks stay unobserved (never extrapolated).
    pub fn filter(&mut self, skeleton: &Skeleton3) -> Skeleton3 {
        let mut out = skeleton.clone();
        for (i, slot) in skeleton.slots().iter().enumerate() {
            let Some(e) = slot else { continue };
            let x = e.position_m.coords;
            let t = skeleton.stamp_nanos;
            let state = match self.states[i] {
                Some(s) if t > s.stamp_nanos && t - s.stamp_nanos <= self.params.max_gap_nanos => {
                    let dt = (t - s.stamp_nanos) as f64 * 1e-9;
                    let dx = (x - s.x) / dt;
                    let a_d = alpha(self.params.derivative_cutoff_hz, dt);
                    let dx_hat = s.dx + (dx - s.dx) * a_d;
                    let cutoff = self.params.min_cutoff_hz + self.params.beta * dx_hat.norm();
                    let a = alpha(cutoff, dt);
                    State {
                        x: s.x + (x - s.x) * a,
                        dx: dx_hat,
                        stamp_nanos: t,
                    }
                }
                Some(s) if t <= s.stamp_nanos => s, // out-of-order or repeated stamp: keep state
                _ => State {
                    x,
                    dx: Vector3::zeros(),
                    stamp_nanos: t,
                },
            };
            self.states[i] = Some(state);
            let filtered = LandmarkEstimate {
                position_m: state.x.into(),
                ..*e
            };
            // positions stay finite: a convex combination of finite inputs
            let _ = out.set(ergocell_skeleton::Landmark::ALL[i], Some(filtered));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detections::Keypoint2;
    use ergocell_skeleton::Landmark;
    use nalgebra::Point3;

    fn view(camera: usize, stamp: i64) -> View2 {
        let mut v = View2::empty(camera, stamp);
        v.set(Landmark::Nose, Some(Keypoint2::new(1.0, 2.0, 0.9).unwrap()));
        v
    }

    #[test]
    fn complete_frames_are_released_at_once_and_in_order() {
        let mut a = FrameAssembler::new(3, 5_000_000, 50_000_000);
        assert!(a.push(view(0, 100_000_000), 0).is_empty());
        assert!(a.push(view(1, 102_000_000), 1).is_empty());
        let out = a.push(view(2, 98_000_000), 2);
        assert_eq!(out.len(), 1);
        assert_eq!(
            out[0].views.iter().map(|v| v.camera).collect::<Vec<_>>(),
            vec![0, 1, 2]
        );
        assert_eq!(out[0].stamp_nanos, 100_000_000);
    }

    #[test]
    fn a_missing_camera_degrades_after_the_deadline_and_late_views_are_dropped() {
        let mut a = FrameAssembler::new(3, 5_000_000, 50_000_000);
        a.push(view(0, 0), 0);
        a.push(view(1, 1_000_000), 0);
        assert!(a.poll(49_000_000).is_empty(), "still waiting for camera 2");
        let out = a.poll(50_000_000);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].views.len(), 2);
        // camera 2 finally arrives for that instant: too late, dropped
        assert!(a.push(view(2, 2_000_000), 60_000_000).is_empty());
        assert_eq!(a.late_views(), 1);
    }

    #[test]
    fn a_complete_later_frame_releases_an_incomplete_earlier_one() {
        let mut a = FrameAssembler::new(2, 5_000_000, 1_000_000_000);
        a.push(view(0, 0), 0);
        a.push(view(0, 100_000_000), 1);
        let out = a.push(view(1, 100_000_000), 2);
        assert_eq!(
            out.iter().map(|f| f.stamp_nanos).collect::<Vec<_>>(),
            vec![0, 100_000_000]
        );
        assert_eq!(out[0].views.len(), 1);
    }

    fn skel(t: i64, x: f64) -> Skeleton3 {
        let mut s = Skeleton3::empty(t);
        s.set(
            Landmark::Nose,
            Some(LandmarkEstimate {
                position_m: Point3::new(x, 0.0, 0.0),
                confidence: 1.0,
                reprojection_error_px: None,
                views: 2,
                position_sd_m: None,
            }),
        )
        .unwrap();
        s
    }

    #[test]
    fn one_euro_smooths_noise_and_follows_a_step() {
        let mut f = OneEuroFilter::new(OneEuroParams::default());
        // alternating ±1 cm noise around 0: output variation shrinks well below the input's
        let mut outs = Vec::new();
        for k in 0..100 {
            let x = if k % 2 == 0 { 0.01 } else { -0.01 };
            outs.push(
                f.filter(&skel(k * 33_000_000, x))
                    .position(Landmark::Nose)
                    .unwrap()
                    .x,
            );
        }
        let spread = outs[50..].iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        assert!(spread < 0.005, "spread {spread}");
        // a 30 cm step is followed to within 1 cm in 1 s
        let mut last = 0.0;
        for k in 100..130 {
            last = f
                .filter(&skel(k * 33_000_000, 0.3))
                .position(Landmark::Nose)
                .unwrap()
                .x;
        }
        assert!((last - 0.3).abs() < 0.01, "{last}");
        // unobserved stays unobserved
        assert!(f
            .filter(&Skeleton3::empty(5_000_000_000))
            .position(Landmark::Nose)
            .is_none());
    }
}
