//! Each camera's persistent image offset, learnt from the fused skeleton and taken out of its views.
//!
//! On real video the detector's error is mostly **persistent and shared by a view's landmarks**: on
//! Pose2Sim's four real cameras each view's landmarks sit, together, 3.2 % of the person's image
//! height (about 24 px) off the point the other views give, nearly constant over the recording,
//! against 1.6 % for each landmark's own part (`docs/detector-error.md`). A small calibration or
//! synchronisation error of that camera does the same. A whole view displaced moves the fused
//! skeleton more than its angles, but not nothing: the head is fused from the cameras that see the
//! face, the shoulders from all of them, so one camera's displacement bends the neck.
//!
//! [`ViewOffsets`] keeps, per camera, a 2-D offset (pixels, in the image as delivered) and subtracts
//! it from every keypoint of the camera's views before fusion ([`ViewOffsets::correct`]). After each
//! fused frame it moves each camera's offset towards the median of that view's residuals against
//! the fused skeleton ([`ViewOffsets::observe`]): an exponential average over
//! [`ViewOffsetConfig::time_constant_nanos`], so one frame, a swap or a gross error hardly moves it,
//! and only views with enough landmarks count. Like bundle adjustment, residuals alone cannot tell
//! where the whole skeleton is (every camera's offset could be the projection of one common 3-D
//! translation): the part of the offsets that is a translation of the skeleton (least squares over
//! the cameras, linearised at the skeleton's centre) is removed after every update, so the correction
//! makes the views agree without moving the operator. An offset is bounded by
//! [`ViewOffsetConfig::max_offset_fraction`] of the person's image height, and a view whose
//! landmarks sit further than that off the skeleton (someone else, a camera knocked askew) teaches
//! nothing; a camera displaced further is out of calibration, which [`crate::camera_health`] finds
//! (it watches the views as delivered, not as corrected).

use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Matrix3, Point3, Vector2, Vector3};

use crate::detections::{Frame2, Keypoint2, View2};
use crate::metrics::median_in_place;
use crate::rig::CameraRig;

/// The estimator's tunables. Defaults: 1 s time constant, views of at least 8 compared landmarks,
/// offsets at most 8 % of the person's image height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewOffsetConfig {
    /// Time constant of the exponential average, nanoseconds.
    pub time_constant_nanos: i64,
    /// Landmarks a view needs, compared with a fused landmark, to update its camera's offset.
    pub min_landmarks: usize,
    /// An offset is clamped to this fraction of the person's image height in the view.
    pub max_offset_fraction: f64,
}

impl Default for ViewOffsetConfig {
    fn default() -> Self {
        Self {
            time_constant_nanos: 1_000_000_000,
            min_landmarks: 8,
            max_offset_fraction: 0.08,
        }
    }
}

/// Per camera, the image offset taken out of its views (see the module docs).
#[derive(Debug, Clone)]
pub struct ViewOffsets {
    config: ViewOffsetConfig,
    offsets: Vec<Vector2<f64>>,
    last_nanos: Option<i64>,
    scratch_u: Vec<f64>,
    scratch_v: Vec<f64>,
}

impl ViewOffsets {
    /// No offset yet for any of `cameras` cameras.
    pub fn new(cameras: usize, config: ViewOffsetConfig) -> Self {
        Self {
            config,
            offsets: vec![Vector2::zeros(); cameras],
            last_nanos: None,
            scratch_u: Vec::new(),
            scratch_v: Vec::new(),
        }
    }

    /// The offset (pixels) currently taken out of camera `k`'s views.
    pub fn offset(&self, k: usize) -> Option<Vector2<f64>> {
        self.offsets.get(k).copied()
    }

    /// `view` with its camera's offset taken out of every keypoint.
    pub fn correct(&self, view: &View2) -> View2 {
        let Some(o) = self
            .offsets
            .get(view.camera)
            .filter(|o| **o != Vector2::zeros())
        else {
            return view.clone();
        };
        let mut out = view.clone();
        for landmark in Landmark::ALL {
            if let Some(k) = view.get(landmark) {
                let p = k.pixel();
                // Finite in, finite out: an offset is bounded and finite.
                if let Ok(moved) = Keypoint2::new(p.x - o.x, p.y - o.y, k.confidence()) {
                    out.set(landmark, Some(moved));
                }
            }
        }
        out
    }

    /// Updates every camera's offset from `frame` (the views as corrected and fused) and the
    /// skeleton fused from them; `swapped` has bit `k` set when camera `k`'s view was used with
    /// left and right exchanged; `skip` bit `k` when camera `k`'s view must not teach (out of
    /// calibration, someone else).
    pub fn observe(
        &mut self,
        rig: &CameraRig,
        frame: &Frame2,
        skeleton: &Skeleton3,
        swapped: u64,
        skip: u64,
    ) {
        let dt = self
            .last_nanos
            .map_or(0, |last| (frame.stamp_nanos - last).max(0));
        self.last_nanos = Some(frame.stamp_nanos);
        if dt == 0 || self.config.time_constant_nanos <= 0 {
            return;
        }
        let alpha = 1.0 - (-(dt as f64) / self.config.time_constant_nanos as f64).exp();
        let mut changed = false;
        for view in &frame.views {
            let k = view.camera;
            let (Some(camera), true) = (rig.cameras().get(k), k < self.offsets.len()) else {
                continue;
            };
            if k < 64 && skip & (1 << k) != 0 {
                continue;
            }
            let mirrored = k < 64 && swapped & (1 << k) != 0;
            self.scratch_u.clear();
            self.scratch_v.clear();
            let (mut top, mut bottom) = (f64::INFINITY, f64::NEG_INFINITY);
            for landmark in Landmark::ALL {
                let Some(keypoint) = view.get(landmark) else {
                    continue;
                };
                let pixel = keypoint.pixel();
                top = top.min(pixel.y);
                bottom = bottom.max(pixel.y);
                let fused = if mirrored {
                    landmark.mirrored()
                } else {
                    landmark
                };
                let Some(p) = skeleton.position(fused) else {
                    continue;
                };
                if let Ok(projected) = camera.project(&p) {
                    let r = pixel - projected;
                    if r.x.is_finite() && r.y.is_finite() {
                        self.scratch_u.push(r.x);
                        self.scratch_v.push(r.y);
                    }
                }
            }
            if self.scratch_u.len() < self.config.min_landmarks.max(1)
                || bottom.partial_cmp(&top) != Some(std::cmp::Ordering::Greater)
            {
                continue;
            }
            let (Some(du), Some(dv)) = (
                median_in_place(&mut self.scratch_u),
                median_in_place(&mut self.scratch_v),
            ) else {
                continue;
            };
            let limit = self.config.max_offset_fraction * (bottom - top);
            let step = Vector2::new(du, dv);
            if step.norm() > limit {
                // The view is further off the skeleton than any offset it may have: someone else,
                // a bumped camera, a swap not undone. It teaches nothing.
                continue;
            }
            let o = self.offsets[k] + step * alpha;
            self.offsets[k] = if o.norm() > limit {
                o * (limit / o.norm())
            } else {
                o
            };
            changed = true;
        }
        if changed {
            self.remove_translation(rig, skeleton);
        }
    }

    /// Removes from the offsets the projection of the one 3-D translation of the skeleton that best
    /// explains them (the gauge residuals cannot fix).
    fn remove_translation(&mut self, rig: &CameraRig, skeleton: &Skeleton3) {
        const STEP: f64 = 1e-3;
        let points: Vec<Point3<f64>> = Landmark::ALL
            .iter()
            .filter_map(|l| skeleton.position(*l))
            .collect();
        if points.is_empty() {
            return;
        }
        let centre = Point3::from(
            points.iter().map(|p| p.coords).sum::<Vector3<f64>>() / points.len() as f64,
        );
        // Jacobians of each camera's projection at the centre, by central differences (1 mm).
        let mut jacobians = Vec::with_capacity(self.offsets.len());
        let mut normal = Matrix3::zeros();
        let mut rhs = Vector3::zeros();
        for (k, offset) in self.offsets.iter().enumerate() {
            let Some(camera) = rig.cameras().get(k) else {
                jacobians.push(None);
                continue;
            };
            let mut j = nalgebra::Matrix2x3::zeros();
            let mut ok = true;
            for axis in 0..3 {
                let mut d = Vector3::zeros();
                d[axis] = STEP;
                match (camera.project(&(centre + d)), camera.project(&(centre - d))) {
                    (Ok(a), Ok(b)) => j.set_column(axis, &((a - b) / (2.0 * STEP))),
                    _ => ok = false,
                }
            }
            if !ok || !j.iter().all(|x| x.is_finite()) {
                jacobians.push(None);
                continue;
            }
            normal += j.transpose() * j;
            rhs += j.transpose() * offset;
            jacobians.push(Some(j));
        }
        // Two cameras or more constrain a translation; with fewer there is nothing to remove.
        if jacobians.iter().flatten().count() < 2 {
            return;
        }
        let Some(translation) = normal.try_inverse().map(|inv| inv * rhs) else {
            return;
        };
        if !translation.iter().all(|x| x.is_finite()) {
            return;
        }
        for (offset, j) in self.offsets.iter_mut().zip(&jacobians) {
            if let Some(j) = j {
                *offset -= j * translation;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{Camera, CameraId, Distortion, Intrinsics};
    use crate::rig::CameraRig;
    use nalgebra::Point2;

    fn rig() -> CameraRig {
        // Four cameras around a person at the origin, 3 m away, 1.2 m up, looking at (0, 0, 1).
        let target = Point3::new(0.0, 0.0, 1.0);
        let cameras = (0..4)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::FRAC_PI_2 + 0.3;
                Camera::look_at(
                    CameraId::new(format!("c{i}")).unwrap(),
                    Point3::new(3.0 * a.cos(), 3.0 * a.sin(), 1.2),
                    target,
                    Vector3::z(),
                    Intrinsics {
                        fx: 1000.0,
                        fy: 1000.0,
                        cx: 640.0,
                        cy: 360.0,
                        skew: 0.0,
                        width_px: 1280,
                        height_px: 720,
                    },
                    Distortion::default(),
                )
                .unwrap()
            })
            .collect();
        CameraRig::new(cameras, &[], Some(Vector3::z())).unwrap()
    }

    fn skeleton() -> Skeleton3 {
        // A column of landmarks: a body 1.6 m tall, 33 points spread in x, y and z.
        let points: [Point3<f64>; 33] = std::array::from_fn(|i| {
            let f = i as f64 / 32.0;
            Point3::new(
                0.15 * (7.0 * f).sin(),
                0.12 * (5.0 * f).cos(),
                0.1 + 1.5 * f,
            )
        });
        Skeleton3::from_points(0, &points).unwrap()
    }

    fn frame(rig: &CameraRig, s: &Skeleton3, shifts: &[Vector2<f64>], t: i64) -> Frame2 {
        Frame2 {
            stamp_nanos: t,
            views: rig
                .cameras()
                .iter()
                .enumerate()
                .map(|(k, c)| {
                    let mut v = View2::empty(k, t);
                    for l in Landmark::ALL {
                        let p: Point2<f64> = c.project(&s.position(l).unwrap()).unwrap();
                        let q = p + shifts[k];
                        v.set(l, Some(Keypoint2::new(q.x, q.y, 0.9).unwrap()));
                    }
                    v
                })
                .collect(),
        }
    }

    #[test]
    fn a_displaced_camera_is_learnt_and_taken_out_without_moving_the_skeleton() {
        let rig = rig();
        let s = skeleton();
        let shifts = [
            Vector2::new(12.0, -5.0),
            Vector2::zeros(),
            Vector2::zeros(),
            Vector2::zeros(),
        ];
        let mut offsets = ViewOffsets::new(4, ViewOffsetConfig::default());
        // The fused skeleton is the truth here (the other three cameras outvote the first).
        for i in 0..600 {
            let mut f = frame(&rig, &s, &shifts, i * 33_000_000);
            f.views = f.views.iter().map(|v| offsets.correct(v)).collect();
            offsets.observe(&rig, &f, &s, 0, 0);
        }
        // The views as corrected agree with one another: each landmark triangulates from all four
        // to a point every view sees within a fifth of the disagreement before. What is left is
        // the translation of the whole skeleton (the gauge) seen at landmarks away from the centre,
        // where its pixels differ from the centre's.
        let f = frame(&rig, &s, &shifts, 600 * 33_000_000);
        let disagreement = |views: &[View2]| {
            let mut worst: f64 = 0.0;
            for l in Landmark::ALL {
                let obs: Vec<_> = views
                    .iter()
                    .map(|v| {
                        let c = &rig.cameras()[v.camera];
                        let px = v.get(l).unwrap().pixel();
                        (c.projection_matrix(), px, 1.0)
                    })
                    .collect();
                let p = crate::triangulation::dlt(&obs).unwrap();
                for v in views {
                    let c = &rig.cameras()[v.camera];
                    let r = (c.project(&p).unwrap() - v.get(l).unwrap().pixel()).norm();
                    worst = worst.max(r);
                }
            }
            worst
        };
        let before = disagreement(&f.views);
        let corrected: Vec<View2> = f.views.iter().map(|v| offsets.correct(v)).collect();
        let after = disagreement(&corrected);
        assert!(before > 5.0, "{before}");
        assert!(
            after < 0.2 * before,
            "views still disagree by {after:.2} px (were {before:.2})"
        );
        // Camera 0 carries most of the correction.
        let o = |k: usize| offsets.offset(k).unwrap().norm();
        assert!(
            o(0) > o(1) && o(0) > o(3),
            "{:?}",
            (0..4).map(o).collect::<Vec<_>>()
        );
    }

    #[test]
    fn a_translation_of_the_whole_skeleton_is_not_learnt() {
        let rig = rig();
        let s = skeleton();
        // Every camera displaced as a 10 cm translation of the person displaces it: the views agree
        // with a skeleton 10 cm away; the offsets must not pull it back (that is the gauge).
        let moved: [Point3<f64>; 33] =
            std::array::from_fn(|i| s.position(Landmark::ALL[i]).unwrap() + Vector3::x() * 0.1);
        let m = Skeleton3::from_points(0, &moved).unwrap();
        let mut offsets = ViewOffsets::new(4, ViewOffsetConfig::default());
        let zero = [Vector2::zeros(); 4];
        for i in 0..300 {
            // views of the moved person, fused skeleton the original: residuals are a translation
            let mut f = frame(&rig, &m, &zero, i * 33_000_000);
            f.views = f.views.iter().map(|v| offsets.correct(v)).collect();
            offsets.observe(&rig, &f, &s, 0, 0);
        }
        for k in 0..4 {
            let o = offsets.offset(k).unwrap();
            assert!(o.norm() < 1.0, "camera {k} learnt {o:?} from a translation");
        }
    }

    #[test]
    fn a_view_with_too_few_landmarks_or_skipped_teaches_nothing() {
        let rig = rig();
        let s = skeleton();
        let shifts = [Vector2::new(20.0, 0.0); 4];
        let mut offsets = ViewOffsets::new(4, ViewOffsetConfig::default());
        for i in 0..100 {
            let f = frame(&rig, &s, &shifts, i * 33_000_000);
            offsets.observe(&rig, &f, &s, 0, 0b1111);
        }
        assert!((0..4).all(|k| offsets.offset(k) == Some(Vector2::zeros())));
    }
}
