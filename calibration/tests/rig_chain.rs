//! A rig of three cameras (two stereo pairs sharing the middle camera) chained into the first
//! camera's frame, with and without the joint refinement; corner observations are exact
//! projections plus 0.1 px of noise (detection is tested elsewhere).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_calibration::{calibrate_rig, BoardSpec, CalibrationError, CameraViews, RigOptions};
use ergocell_perception::{Camera, CameraId, Distortion, Intrinsics};
use nalgebra::{Isometry3, Point2, Translation3, UnitQuaternion, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};

fn camera(id: &str, fx: f64, T_camera_world: Isometry3<f64>) -> Camera {
    Camera::new(
        CameraId::new(id).unwrap(),
        Intrinsics {
            fx,
            fy: fx * 1.002,
            cx: 322.0,
            cy: 238.0,
            skew: 0.0,
            width_px: 640,
            height_px: 480,
        },
        Distortion {
            k1: -0.1,
            k2: 0.02,
            p1: 0.0,
            p2: 0.0,
            k3: 0.0,
        },
        T_camera_world.rotation.to_rotation_matrix(),
        T_camera_world.translation.vector,
    )
    .unwrap()
}

fn truth() -> Vec<Camera> {
    vec![
        camera("c0", 600.0, Isometry3::identity()),
        camera(
            "c1",
            590.0,
            Isometry3::from_parts(
                Translation3::new(-0.1, 0.0, 0.01),
                UnitQuaternion::from_euler_angles(0.0, -0.15, 0.0),
            ),
        ),
        camera(
            "c2",
            610.0,
            Isometry3::from_parts(
                Translation3::new(-0.2, 0.01, 0.05),
                UnitQuaternion::from_euler_angles(0.02, -0.35, 0.01),
            ),
        ),
    ]
}

/// Board poses in the world (camera 0) frame; camera 0 sees only the first 8, camera 2 only the
/// last 8, so camera 2 joins the rig through camera 1.
fn observations(cams: &[Camera], board: &BoardSpec, noise_px: f64) -> Vec<CameraViews> {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let noise = Normal::new(0.0, noise_px).unwrap();
    let centre = Vector3::new(0.1, 0.0625, 0.0);
    let poses: Vec<Isometry3<f64>> = (0..14)
        .map(|i| {
            let a = f64::from(i);
            let r = UnitQuaternion::from_euler_angles(
                0.5 * (a * 1.7).sin(),
                -0.2 + 0.45 * (a * 1.1).cos(),
                0.3 * (a * 0.5).sin(),
            );
            let t = Vector3::new(
                0.04 + 0.07 * (a * 0.8).sin(),
                0.05 * a.cos(),
                0.42 + 0.1 * (a * 0.9).sin(),
            ) - r * centre;
            Isometry3::from_parts(Translation3::from(t), r)
        })
        .collect();
    let object = board.object_points();
    cams.iter()
        .enumerate()
        .map(|(c, cam)| CameraViews {
            id: cam.id.clone(),
            image_size_px: (640, 480),
            frames: poses
                .iter()
                .enumerate()
                .map(|(f, T_world_board)| {
                    let seen = match c {
                        0 => f < 8,
                        2 => f >= 6,
                        _ => true,
                    };
                    seen.then(|| {
                        object
                            .iter()
                            .map(|p| {
                                let q = cam.project(&(T_world_board * p)).unwrap();
                                Point2::new(
                                    q.x + noise.sample(&mut rng),
                                    q.y + noise.sample(&mut rng),
                                )
                            })
                            .collect::<Vec<_>>()
                    })
                })
                .collect(),
        })
        .collect()
}

#[test]
fn three_cameras_chain_into_the_first_cameras_frame() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let cams = truth();
    // exact observations: exact rig; 0.1 px noise: within 3 mm and 0.3° (the principal points,
    // correlated with tangential distortion, move by ~1 px at this noise and so do the angles)
    for (noise_px, tol_m, tol_rad) in [(1e-6, 1e-6, 1e-6), (0.1, 0.003, 0.3_f64.to_radians())] {
        let views = observations(&cams, &board, noise_px);
        for joint in [true, false] {
            let options = RigOptions {
                joint_refinement: joint,
                refine_intrinsics: joint,
                ..RigOptions::default()
            };
            let calib = calibrate_rig(&views, &board, &[], options).unwrap();
            assert_eq!(calib.rig.len(), 3);
            assert_eq!(calib.rig.cameras()[0].T_camera_world, Isometry3::identity());
            for (ours, truth) in calib.rig.cameras().iter().zip(&cams) {
                let dp = (ours.position_world() - truth.position_world()).norm();
                assert!(
                    dp < tol_m,
                    "noise {noise_px} joint {joint}: {} is {dp} m off",
                    ours.id
                );
                let dr = (ours.T_camera_world.rotation.inverse() * truth.T_camera_world.rotation)
                    .angle();
                assert!(
                    dr < tol_rad,
                    "noise {noise_px} joint {joint}: {} {dr} rad off",
                    ours.id
                );
            }
            assert!(calib.rms_px < 2.0 * noise_px + 1e-5, "rms {}", calib.rms_px);
            // views a camera did not see have no error
            assert!(calib.view_rms_px[0][10].is_none());
            assert!(calib.view_rms_px[2][10].is_some());
        }
    }
}

#[test]
fn a_camera_sharing_too_few_frames_is_an_error() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let cams = truth();
    let mut views = observations(&cams, &board, 0.1);
    // camera 2 now shares only frames 6 and 7 with the others
    for f in 8..14 {
        views[1].frames[f] = None;
        views[0].frames[f] = None;
    }
    let err = calibrate_rig(&views, &board, &[], RigOptions::default()).unwrap_err();
    assert!(
        matches!(
            err,
            CalibrationError::TooFewViews {
                usable: 2,
                needed: 3,
                ..
            }
        ),
        "{err}"
    );
}
