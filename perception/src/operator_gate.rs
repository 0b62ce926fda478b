//! Which views show the operator and which show someone else, before fusion.
//!
//! A camera node runs a single-person detector (MediaPipe's legacy BlazePose): with two people in
//! view, each camera reports whichever one it locked onto. On Pose2Sim's two-person video one camera
//! of four followed the other person; the robust fusion rejects such a minority as outliers. But when
//! most cameras see a bystander (the twin: two stereo pairs of three), the fusion follows the majority
//! and the bystander's height decides the class.
//!
//! The gate keeps the views whose torso — the mean of the shoulders and hips the view has — lies on a
//! ray that passes within a radius of where the operator is expected: the operator's last tracked
//! torso, or, with none recent, the station's. A view with no torso keypoint cannot be judged and is
//! kept. While the reference is only the station and no judged view is near it, every view is kept:
//! the gate never blinds the cell to a lone person walking in (they are then tracked, and the gate
//! follows them). Once the operator is tracked, far views are dropped even when none is near: a frame
//! that lost the operator fuses nothing rather than the bystander. One near view is enough to drop
//! the far ones.

use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Point2, Point3, Vector3};

use crate::detections::{Frame2, View2};
use crate::rig::CameraRig;

/// The torso landmarks: a view's torso point is the mean of those it has.
pub const TORSO: [Landmark; 4] = [
    Landmark::LeftShoulder,
    Landmark::RightShoulder,
    Landmark::LeftHip,
    Landmark::RightHip,
];

/// The torso point of a fused skeleton (the mean of the torso landmarks it has), world frame.
pub fn torso_of(skeleton: &Skeleton3) -> Option<Point3<f64>> {
    mean_of(
        TORSO
            .iter()
            .filter_map(|&l| skeleton.position(l).map(|p| p.coords)),
    )
    .map(Point3::from)
}

/// The mean of some vectors, without collecting them (this runs for every view of every frame);
/// `None` for none.
fn mean_of<const D: usize>(
    items: impl Iterator<Item = nalgebra::SVector<f64, D>>,
) -> Option<nalgebra::SVector<f64, D>> {
    let (sum, n) = items.fold(
        (nalgebra::SVector::<f64, D>::zeros(), 0usize),
        |(s, n), v| (s + v, n + 1),
    );
    (n > 0).then(|| sum / n as f64)
}

/// The distance from `reference` (world) to the ray through a view's torso, metres; `None` when the
/// view has no torso keypoint or its torso pixel cannot be undistorted, or the camera is unknown.
pub fn torso_ray_distance_m(rig: &CameraRig, view: &View2, reference: &Point3<f64>) -> Option<f64> {
    let camera = rig.camera(view.camera)?;
    let mean = mean_of(
        TORSO
            .iter()
            .filter_map(|&l| view.get(l).map(|k| k.pixel().coords)),
    )?;
    let n = camera.pixel_to_normalized(&Point2::from(mean)).ok()?;
    let rotation = camera.T_camera_world.rotation.inverse();
    let direction = (rotation * Vector3::new(n.x, n.y, 1.0)).normalize();
    let to_reference = reference - camera.position_world();
    // behind the camera, the nearest point of the ray is its origin
    let along = to_reference.dot(&direction).max(0.0);
    Some((to_reference - direction * along).norm())
}

/// Splits a frame's views into the operator's and the others': returns the bit mask of the cameras
/// whose view was judged to show someone else (farther than `radius_m` from `reference`); `0` when
/// nothing is dropped. With `keep_all_when_none_near`, a frame with no judged view near `reference`
/// keeps them all (the reference is only the station: a lone person walking in); without, they are
/// all dropped (the reference is the operator tracked a moment ago: the views that lost them show
/// someone else, and a bystander must not take their place).
pub fn other_person_views(
    rig: &CameraRig,
    frame: &Frame2,
    reference: &Point3<f64>,
    radius_m: f64,
    keep_all_when_none_near: bool,
) -> u64 {
    let mut far = 0u64;
    let mut kept_judged = 0usize;
    for v in &frame.views {
        match torso_ray_distance_m(rig, v, reference) {
            Some(d) if d > radius_m => far |= 1 << v.camera,
            Some(_) => kept_judged += 1,
            None => {}
        }
    }
    if kept_judged == 0 && keep_all_when_none_near {
        0
    } else {
        far
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detections::Keypoint2;
    use crate::fusion::tests::ring_rig;

    fn view_of(rig: &CameraRig, camera: usize, torso: Point3<f64>) -> View2 {
        let mut v = View2::empty(camera, 0);
        for (i, l) in TORSO.iter().enumerate() {
            let offset = Vector3::new(
                0.0,
                if i % 2 == 0 { 0.2 } else { -0.2 },
                if i < 2 { 0.25 } else { -0.25 },
            );
            let p = rig.cameras()[camera].project(&(torso + offset)).unwrap();
            v.set(*l, Some(Keypoint2::new(p.x, p.y, 0.9).unwrap()));
        }
        v
    }

    #[test]
    fn views_of_someone_else_are_found_and_a_lone_person_is_never_dropped() {
        let rig = ring_rig(6);
        let operator = Point3::new(0.0, 0.0, 1.0);
        let bystander = Point3::new(0.3, 1.3, 1.0);
        let frame = |others: &[usize]| Frame2 {
            stamp_nanos: 0,
            views: (0..6)
                .map(|k| {
                    view_of(
                        &rig,
                        k,
                        if others.contains(&k) {
                            bystander
                        } else {
                            operator
                        },
                    )
                })
                .collect(),
        };
        // the torso ray of the operator passes through the reference (to the few millimetres by which
        // the mean of four projected points misses the projection of their mean); the bystander's
        // 1.3 m away
        let d = torso_ray_distance_m(&rig, &frame(&[]).views[0], &operator).unwrap();
        assert!(d < 0.01, "{d}");
        let d = torso_ray_distance_m(&rig, &frame(&[0]).views[0], &operator).unwrap();
        assert!(d > 0.5, "{d}");
        // a majority of views on the bystander: the operator's are still the ones kept
        assert_eq!(
            other_person_views(&rig, &frame(&[0, 1, 2, 3]), &operator, 0.5, true),
            0b1111
        );
        assert_eq!(
            other_person_views(&rig, &frame(&[3]), &operator, 0.5, true),
            0b1000
        );
        assert_eq!(
            other_person_views(&rig, &frame(&[]), &operator, 0.5, true),
            0
        );
        // one view near the reference is enough to drop the others
        let mut f = frame(&[0, 1, 2, 3]);
        f.views[5] = View2::empty(5, 0);
        assert_eq!(other_person_views(&rig, &f, &operator, 0.5, true), 0b1111);
        // no view near it: nothing is dropped (a lone person elsewhere is still seen) while the
        // reference is the station; everything is once it is the operator tracked a moment ago.
        // (Cameras 4 and 5 see the bystander nearly behind the operator: their rays pass 0.26 m
        // from the operator, inside the gate; such views are for the fusion's outlier test.)
        let mut lone = frame(&[0, 1, 2, 3]);
        lone.views.truncate(4);
        assert_eq!(other_person_views(&rig, &lone, &operator, 0.5, true), 0);
        assert_eq!(
            other_person_views(&rig, &lone, &operator, 0.5, false),
            0b1111
        );
        // a view without a torso cannot be judged and is kept
        let mut f = frame(&[0, 1]);
        f.views[0] = View2::empty(0, 0);
        assert_eq!(other_person_views(&rig, &f, &operator, 0.5, true), 0b10);
    }

    #[test]
    fn the_torso_of_a_skeleton_is_the_mean_of_what_it_has() {
        let mut s = Skeleton3::empty(0);
        assert!(torso_of(&s).is_none());
        let points: [Option<Point3<f64>>; ergocell_skeleton::LANDMARK_COUNT] =
            std::array::from_fn(|i| match Landmark::from_index(i) {
                Some(Landmark::LeftShoulder) => Some(Point3::new(0.0, 0.2, 1.4)),
                Some(Landmark::RightShoulder) => Some(Point3::new(0.0, -0.2, 1.4)),
                Some(Landmark::LeftHip) => Some(Point3::new(0.0, 0.1, 0.9)),
                _ => None,
            });
        s = Skeleton3::from_optional_points(0, &points).unwrap();
        let t = torso_of(&s).unwrap();
        assert!(
            (t - Point3::new(0.0, 0.1 / 3.0, 3.7 / 3.0)).norm() < 1e-12,
            "{t}"
        );
    }
}
