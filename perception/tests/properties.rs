//! Property tests: triangulate(project(X)) = X for any rig of 2..16 cameras, and no input panics.

#![allow(clippy::unwrap_used, clippy::expect_used)] // test helpers outside #[test] fns

use ergocell_perception::detections::{Keypoint2, View2};
use ergocell_perception::fusion::{FusionEngine, FusionMethod};
use ergocell_perception::{Camera, CameraId, CameraRig, Distortion, Frame2, Intrinsics};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

/// A camera at `eye` looking at `target` (world z up), with a 1280×720 sensor and mild distortion.
fn camera(k: usize, eye: Point3<f64>, target: Point3<f64>, f: f64, k1: f64) -> Camera {
    Camera::look_at(
        CameraId::new(format!("cam_{k}")).unwrap(),
        eye,
        target,
        Vector3::z(),
        Intrinsics {
            fx: f,
            fy: f * 1.002,
            cx: 640.0,
            cy: 360.0,
            skew: 0.0,
            width_px: 1280,
            height_px: 720,
        },
        Distortion {
            k1,
            k2: 0.2 * k1.abs(),
            p1: 0.0004,
            p2: -0.0002,
            k3: 0.0,
        },
    )
    .unwrap()
}

prop_compose! {
    fn rig_strategy()(n in 2usize..=16, seed_angles in prop::collection::vec((0.0f64..std::f64::consts::TAU, 2.5f64..5.0, 0.8f64..2.4, 700.0f64..1400.0, -0.15f64..0.1), 16)) -> CameraRig {
        let target = Point3::new(0.0, 0.0, 1.0);
        let cams = (0..n).map(|k| {
            let (a, d, h, f, k1) = seed_angles[k];
            // spread cameras around the operator; pairs get a 12 cm baseline
            let angle = a + k as f64 * 0.9;
            camera(k, Point3::new(d * angle.cos(), d * angle.sin(), h), target, f, k1)
        }).collect();
        CameraRig::new(cams, &[], None).unwrap()
    }
}

prop_compose! {
    fn skeleton_strategy()(pts in prop::collection::vec((-0.35f64..0.35, -0.35f64..0.35, 0.05f64..1.9), LANDMARK_COUNT)) -> [Point3<f64>; LANDMARK_COUNT] {
        std::array::from_fn(|i| Point3::new(pts[i].0, pts[i].1, pts[i].2))
    }
}

fn project_all(rig: &CameraRig, points: &[Point3<f64>; LANDMARK_COUNT]) -> Frame2 {
    let views = rig
        .cameras()
        .iter()
        .enumerate()
        .map(|(k, cam)| {
            let mut v = View2::empty(k, 0);
            for lm in Landmark::ALL {
                let px = cam.project(&points[lm.index()]).unwrap();
                v.set(lm, Some(Keypoint2::new(px.x, px.y, 1.0).unwrap()));
            }
            v
        })
        .collect();
    Frame2 {
        stamp_nanos: 0,
        views,
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 64,
        rng_seed: proptest::test_runner::RngSeed::Fixed(64),
        .. ProptestConfig::default()
    })]

    #[test]
    fn default_fusion_recovers_any_skeleton_exactly(rig in rig_strategy(), points in skeleton_strategy()) {
        let frame = project_all(&rig, &points);
        let mut engine = FusionEngine::new(rig, FusionMethod::Default).unwrap();
        let fused = engine.fuse(&frame).unwrap();
        for lm in Landmark::ALL {
            let p = fused.skeleton.position(lm).expect("every landmark seen by ≥ 2 cameras");
            prop_assert!((p - points[lm.index()]).norm() < 1e-9, "{lm}: error {}", (p - points[lm.index()]).norm());
        }
    }

    #[test]
    fn paper_fusion_recovers_any_skeleton_when_pairs_exist(rig in rig_strategy(), points in skeleton_strategy()) {
        prop_assume!(!rig.pairs().is_empty());
        let frame = project_all(&rig, &points);
        let mut engine = FusionEngine::new(rig, FusionMethod::Paper).unwrap();
        let fused = engine.fuse(&frame).unwrap();
        for lm in Landmark::ALL {
            let p = fused.skeleton.position(lm).expect("every landmark seen by a pair");
            prop_assert!((p - points[lm.index()]).norm() < 1e-7, "{lm}: error {}", (p - points[lm.index()]).norm());
        }
    }

    #[test]
    fn arbitrary_detections_never_panic_and_never_give_non_finite_points(
        rig in rig_strategy(),
        raw in prop::collection::vec((any::<u8>(), -1e7f64..1e7, -1e7f64..1e7, 0.0f64..=1.0, any::<bool>()), 0..200),
        method in prop_oneof![Just(FusionMethod::Default), Just(FusionMethod::Paper)],
    ) {
        let mut views: Vec<View2> = (0..rig.len()).map(|k| View2::empty(k, 0)).collect();
        for (i, (lm, u, v, c, keep)) in raw.iter().enumerate() {
            if !keep { continue; }
            let cam = i % rig.len();
            let lm = Landmark::ALL[*lm as usize % LANDMARK_COUNT];
            views[cam].set(lm, Some(Keypoint2::new(*u, *v, *c).unwrap()));
        }
        let frame = Frame2 { stamp_nanos: 7, views };
        let mut engine = FusionEngine::new(rig, method).unwrap();
        let fused = engine.fuse(&frame).unwrap();
        for e in fused.skeleton.slots().iter().flatten() {
            prop_assert!(e.position_m.coords.iter().all(|x| x.is_finite()));
            prop_assert!((0.0..=1.0).contains(&e.confidence));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 16,
        rng_seed: proptest::test_runner::RngSeed::Fixed(16),
        .. ProptestConfig::default()
    })]

    /// With the bone-length prior active (after its warm-up), exact data stays exact: a rigid body
    /// moving through the cell has every bone at its learned length, so nothing is pulled.
    #[test]
    fn default_fusion_stays_exact_once_the_bone_prior_is_active(rig in rig_strategy(), points in skeleton_strategy()) {
        let mut engine = FusionEngine::new(rig.clone(), FusionMethod::Default).unwrap();
        for k in 0..15 {
            let shift = Vector3::new(0.01 * f64::from(k), -0.005 * f64::from(k), 0.0);
            let moved: [Point3<f64>; LANDMARK_COUNT] = std::array::from_fn(|i| points[i] + shift);
            let fused = engine.fuse(&project_all(&rig, &moved)).unwrap();
            for lm in Landmark::ALL {
                let p = fused.skeleton.position(lm).unwrap();
                prop_assert!((p - moved[lm.index()]).norm() < 1e-8, "frame {k} {lm}: error {}", (p - moved[lm.index()]).norm());
            }
        }
    }
}
