//! `calibrate place`'s round trip: the reference rig's three pairs, each given in its own left
//! camera's frame (as `calibrate stereo` writes it), placed back in the cell from points measured in
//! it and seen with pixel noise. Every camera must come back within 2 mm and 0.1°.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;

use ergocell_calibration::place::{place, MeasuredPoint};
use ergocell_perception::{Camera, CameraRig};
use nalgebra::{Isometry3, Point2, Point3};
use rand::SeedableRng as _;
use rand_distr::{Distribution as _, Normal};

fn reference_rig() -> CameraRig {
    ergocell_formats::rig_file::parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

/// Each pair of `rig` in its left camera's frame.
fn pairs_in_their_own_frames(rig: &CameraRig) -> Vec<CameraRig> {
    rig.pairs()
        .iter()
        .map(|pair| {
            let left = &rig.cameras()[pair.left];
            let T_left_world = left.T_camera_world;
            let cameras = [pair.left, pair.right]
                .iter()
                .map(|&i| {
                    let c = &rig.cameras()[i];
                    let T_camera_left = c.T_camera_world * T_left_world.inverse();
                    Camera::new(
                        c.id.clone(),
                        c.intrinsics,
                        c.distortion,
                        T_camera_left.rotation.to_rotation_matrix(),
                        T_camera_left.translation.vector,
                    )
                    .unwrap()
                })
                .collect();
            CameraRig::new(cameras, &[], None).unwrap()
        })
        .collect()
}

/// Markers around the station: on the floor and on a table and a post (so not all in one plane),
/// each seen by every camera it is in front of and in the image of, with `sd_px` of pixel noise.
fn measured(rig: &CameraRig, sd_px: f64, seed: u64) -> Vec<MeasuredPoint> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let noise = Normal::new(0.0, sd_px).unwrap();
    let mut points = Vec::new();
    for (i, x) in [-0.6, 0.0, 0.6, 1.0].iter().enumerate() {
        for (j, y) in [-0.7, 0.0, 0.7].iter().enumerate() {
            for (k, z) in [0.0, 0.9, 1.6].iter().enumerate() {
                let cell_m = Point3::new(*x, *y, *z);
                let mut seen = BTreeMap::new();
                for c in rig.cameras() {
                    if (c.T_camera_world * cell_m).z <= 0.1 {
                        continue;
                    }
                    let Ok(px) = c.project(&cell_m) else { continue };
                    if !c.in_image(&px) {
                        continue;
                    }
                    seen.insert(
                        c.id.as_str().to_owned(),
                        Point2::new(px.x + noise.sample(&mut rng), px.y + noise.sample(&mut rng)),
                    );
                }
                points.push(MeasuredPoint {
                    name: format!("m{i}{j}{k}"),
                    cell_m,
                    seen,
                });
            }
        }
    }
    points
}

/// Position (m) and angle (rad) between two poses.
fn error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    let d = a.inverse() * b;
    (d.translation.vector.norm(), d.rotation.angle())
}

/// The pixel noise of the tests: the real checkerboard corners' reprojection RMS after calibration
/// on OpenCV's stereo sample (0.195–0.217 px, docs/calibration.md), as when a board's corners are the
/// measured points.
const CORNER_NOISE_PX: f64 = 0.2;

/// Worst camera position (m) and orientation (rad) error of `place` over `seeds` at `sd_px`.
fn worst_over(seeds: std::ops::RangeInclusive<u64>, sd_px: f64) -> (f64, f64) {
    let truth = reference_rig();
    let groups = pairs_in_their_own_frames(&truth);
    let (mut worst_m, mut worst_rad) = (0.0_f64, 0.0_f64);
    for seed in seeds {
        let points = measured(&truth, sd_px, seed);
        let placed = place(&groups, &points).unwrap();
        assert_eq!(placed.rig.up(), Some(nalgebra::Vector3::z()));
        assert_eq!(placed.rig.pairs().len(), 3);
        for c in truth.cameras() {
            let got = placed.rig.cameras().iter().find(|p| p.id == c.id).unwrap();
            // Camera centres and orientations in the cell.
            let (dm, drad) = error(&c.T_camera_world.inverse(), &got.T_camera_world.inverse());
            worst_m = worst_m.max(dm);
            worst_rad = worst_rad.max(drad);
        }
        for g in &placed.groups {
            assert!(g.rms_px < 3.0 * sd_px.max(0.01), "{g:?}");
        }
    }
    (worst_m, worst_rad)
}

#[test]
fn pairs_given_in_their_own_frames_are_placed_back_in_the_cell_within_2_mm_and_a_tenth_of_a_degree()
{
    // Reporting seeds, never used to tune.
    let (worst_m, worst_rad) = worst_over(301..=340, CORNER_NOISE_PX);
    eprintln!(
        "placed back over seeds 301-340 at {CORNER_NOISE_PX} px: worst camera {:.2} mm, {:.3} deg",
        worst_m * 1e3,
        worst_rad.to_degrees()
    );
    assert!(worst_m < 0.002, "{} mm", worst_m * 1e3);
    assert!(
        worst_rad < 0.1_f64.to_radians(),
        "{} deg",
        worst_rad.to_degrees()
    );
    // Without noise the placement is exact: the method, not the noise, is what is tested above.
    let (exact_m, exact_rad) = worst_over(1..=1, 0.0);
    assert!(
        exact_m < 1e-6 && exact_rad < 1e-8,
        "{exact_m} m, {exact_rad} rad"
    );
}

#[test]
fn a_group_with_too_few_points_or_a_camera_in_no_group_is_refused() {
    let truth = reference_rig();
    let groups = pairs_in_their_own_frames(&truth);
    let mut points = measured(&truth, 0.0, 1);
    points.truncate(2);
    assert!(matches!(
        place(&groups, &points),
        Err(ergocell_calibration::CalibrationError::TooFewPoints { needed: 3, .. })
    ));
    let mut points = measured(&truth, 0.0, 1);
    points[0]
        .seen
        .insert("s9_left".to_owned(), Point2::new(1.0, 1.0));
    assert!(matches!(
        place(&groups, &points),
        Err(ergocell_calibration::CalibrationError::PlaceCamera { groups: 0, .. })
    ));
}

#[test]
fn markers_all_on_the_floor_place_the_pairs_too_and_the_refinement_improves_on_the_rigid_fit() {
    // One plane (a board laid on the floor, floor markers): the rigid fit's reflection case.
    let truth = reference_rig();
    let groups = pairs_in_their_own_frames(&truth);
    let floor: Vec<MeasuredPoint> = measured(&truth, CORNER_NOISE_PX, 301)
        .into_iter()
        .filter(|p| p.cell_m.z == 0.0)
        .collect();
    let placed = place(&groups, &floor).unwrap();
    for c in truth.cameras() {
        let got = placed.rig.cameras().iter().find(|p| p.id == c.id).unwrap();
        let (dm, drad) = error(&c.T_camera_world.inverse(), &got.T_camera_world.inverse());
        assert!(
            dm < 0.005 && drad < 0.2_f64.to_radians(),
            "{}: {dm} m, {drad} rad",
            c.id.as_str()
        );
    }
    // Under noise the reprojection refinement lowers the error the rigid fit started from.
    for g in &placed.groups {
        assert!(g.rms_px < g.start_rms_px, "{g:?}");
    }
}

#[test]
fn a_swapped_camera_id_or_a_group_of_one_camera_is_refused() {
    let truth = reference_rig();
    let groups = pairs_in_their_own_frames(&truth);
    // s1's left and right pixels swapped: no pose fits them.
    let mut points = measured(&truth, 0.0, 1);
    for p in &mut points {
        if let (Some(l), Some(r)) = (
            p.seen.get("s1_left").copied(),
            p.seen.get("s1_right").copied(),
        ) {
            p.seen.insert("s1_left".to_owned(), r);
            p.seen.insert("s1_right".to_owned(), l);
        }
    }
    // Triangulated swapped, every point lands behind the pair: refused, naming the camera.
    assert!(matches!(
        place(&groups, &points),
        Err(ergocell_calibration::CalibrationError::BehindCamera { camera, .. }) if camera.starts_with("s1_")
    ));
    // A wrong click on every sighting of one pair (20 px off): a pose fits, but far too badly.
    let mut points = measured(&truth, 0.0, 1);
    for (i, p) in points.iter_mut().enumerate() {
        for (id, px) in &mut p.seen {
            if id.starts_with("s2_") {
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                px.x += 20.0 * sign;
            }
        }
    }
    assert!(matches!(
        place(&groups, &points),
        Err(ergocell_calibration::CalibrationError::PoorFit { rms_px, .. }) if rms_px > 5.0
    ));
    let one = CameraRig::new(vec![truth.cameras()[0].clone()], &[], None).unwrap();
    assert!(matches!(
        place(&[one], &measured(&truth, 0.0, 1)[..0]),
        Err(ergocell_calibration::CalibrationError::GroupOfOne { .. })
    ));
}

#[test]
fn points_on_one_line_do_not_fix_a_rotation() {
    let line: Vec<_> = (0..5)
        .map(|i| {
            let p = Point3::new(f64::from(i), 0.0, 0.0);
            (p, p)
        })
        .collect();
    assert!(ergocell_calibration::place::rigid_fit(&line).is_none());
}

/// The accuracy against pixel noise (docs/calibration.md's table, printed with
/// `cargo test -p ergocell_calibration --test place accuracy_against_pixel_noise -- --nocapture`):
/// the placement's error grows with the noise, roughly in proportion (the same seeds, the noise
/// scaled), so a placement that ignored the sightings, or fitted them worse than noise, would show.
#[test]
fn accuracy_against_pixel_noise() {
    let rows: Vec<(f64, f64, f64)> = [0.1, 0.2, 0.3, 0.5, 1.0]
        .iter()
        .map(|&sd| {
            let (m, rad) = worst_over(301..=340, sd);
            eprintln!(
                "| {sd} px | {:.2} mm | {:.3} deg |",
                m * 1e3,
                rad.to_degrees()
            );
            (sd, m, rad)
        })
        .collect();
    for w in rows.windows(2) {
        let ((sd0, m0, r0), (sd1, m1, r1)) = (w[0], w[1]);
        assert!(m1 > m0 && r1 > r0, "{sd1} px is not worse than {sd0} px");
        // Proportional to the noise within a factor of 1.5 either way.
        let ratio = (m1 / m0) / (sd1 / sd0);
        assert!(
            (1.0 / 1.5..1.5).contains(&ratio),
            "{sd0} → {sd1} px: {ratio}"
        );
    }
}
