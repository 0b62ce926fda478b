//! Stature estimation and the height class decision on synthetic operators.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::height::{ClassThresholds, DecisionBasis};
use ergocell_ergonomics::pose::PoseSpec;
use ergocell_ergonomics::{
    ErgonomicsError, HeightClass, HeightConfig, HeightEstimator, HeightStatus, UpVector,
};
use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Point3, Rotation3, Vector3};

fn spec(stature_m: f64) -> PoseSpec {
    PoseSpec {
        stature_m,
        world_rotation: Rotation3::from_euler_angles(-1.4, 0.2, 0.9),
        world_translation: Vector3::new(1.0, -2.0, 0.7),
        ..PoseSpec::default()
    }
}

fn estimator(spec: &PoseSpec) -> HeightEstimator {
    HeightEstimator::new(HeightConfig::new(UpVector::new(spec.up()).unwrap()))
}

fn frame(spec: &PoseSpec, k: i64) -> Skeleton3 {
    PoseSpec {
        stamp_nanos: k * 33_000_000,
        ..spec.clone()
    }
    .skeleton()
}

#[test]
fn class_edges_c2_is_inclusive_at_both_ends() {
    let t = ClassThresholds::default();
    assert_eq!(HeightClass::of(1.679_999, &t), HeightClass::C1);
    assert_eq!(HeightClass::of(1.68, &t), HeightClass::C2);
    assert_eq!(HeightClass::of(1.82, &t), HeightClass::C2);
    assert_eq!(HeightClass::of(1.820_001, &t), HeightClass::C3);
    assert!(matches!(
        ClassThresholds::new(1.9, 1.8),
        Err(ErgonomicsError::BadClassThresholds { .. })
    ));
    assert!(ClassThresholds::new(f64::NAN, 1.8).is_err());
}

#[test]
fn both_estimators_recover_the_stature_and_decide_the_class() {
    for (stature, class) in [
        (1.55, HeightClass::C1),
        (1.75, HeightClass::C2),
        (1.95, HeightClass::C3),
    ] {
        let s = spec(stature);
        let mut est = estimator(&s);
        let mut decision = None;
        for k in 0..40 {
            if let Some(d) = est.push(&frame(&s, k)) {
                assert!(decision.is_none(), "the decision is emitted once");
                decision = Some((k, d));
            }
        }
        let (k, d) = decision.expect("decided");
        assert_eq!(k, 14, "after the 15 frames the config asks for");
        assert_eq!(d.class, class);
        assert_eq!(d.estimate.frames_used, 15);
        assert!((d.estimate.height_m - stature).abs() < 0.005, "{d:?}");
        assert!(d.estimate.uncertainty_m > 0.0 && d.estimate.uncertainty_m < 0.05);
        assert_eq!(d.estimate.estimators.len(), 2);
        for e in &d.estimate.estimators {
            assert!((e.height_m - stature).abs() < 0.005, "{e:?}");
        }
        assert!(matches!(d.basis, DecisionBasis::Interval { .. }));
        assert!(matches!(est.status(), HeightStatus::Decided(_)));
    }
}

/// An operator whose stated interval straddles a class boundary stays undecided, however many
/// noiseless frames agree: the decision follows from the estimate's uncertainty only.
#[test]
fn an_interval_that_straddles_a_boundary_is_undecided_however_many_frames_agree() {
    let s = spec(1.69);
    let mut est = estimator(&s);
    for k in 0..600 {
        assert!(est.push(&frame(&s, k)).is_none(), "decided at frame {k}");
    }
    match est.status() {
        HeightStatus::Measuring {
            why,
            upright_frames,
            estimate,
            ..
        } => {
            assert_eq!(upright_frames, 600);
            assert!(
                why.contains("straddles") && why.contains("undecided"),
                "{why}"
            );
            let e = estimate.unwrap();
            assert!((e.height_m - 1.69).abs() < 0.005);
            // The interval really straddles 1.68 m (this is what keeps it undecided).
            assert!(e.height_m - 2.0 * e.uncertainty_m < 1.68);
            assert!(why.contains("100% of frames say c2"), "{why}");
        }
        HeightStatus::Decided(d) => panic!("decided although the interval straddles: {d:?}"),
    }
}

/// Every decision's stated interval lies inside the decided class.
#[test]
fn every_decision_lies_inside_its_class_with_its_whole_interval() {
    let mut decided = 0;
    for stature in [
        1.50, 1.55, 1.60, 1.62, 1.63, 1.72, 1.75, 1.77, 1.87, 1.9, 2.0,
    ] {
        let s = spec(stature);
        let mut est = estimator(&s);
        let d = (0..600).find_map(|k| est.push(&frame(&s, k)));
        let Some(d) = d else {
            continue;
        };
        decided += 1;
        let DecisionBasis::Interval { sigmas } = d.basis;
        let (lo, hi) = (
            d.estimate.height_m - sigmas * d.estimate.uncertainty_m,
            d.estimate.height_m + sigmas * d.estimate.uncertainty_m,
        );
        let t = ergocell_ergonomics::height::ClassThresholds::default();
        assert_eq!(HeightClass::of(lo, &t), d.class, "{stature}: {d:?}");
        assert_eq!(HeightClass::of(hi, &t), d.class, "{stature}: {d:?}");
    }
    assert!(decided >= 8, "only {decided} of 11 statures decided");
}

#[test]
fn frames_that_are_not_upright_are_not_used() {
    for bent in [
        PoseSpec {
            trunk_flexion_rad: 45f64.to_radians(),
            ..spec(1.75)
        },
        PoseSpec {
            knee_flexion_rad: 40f64.to_radians(),
            ..spec(1.75)
        },
        PoseSpec {
            neck_flexion_rad: 30f64.to_radians(),
            ..spec(1.75)
        },
    ] {
        let mut est = estimator(&bent);
        assert_eq!(est.is_upright(&bent.skeleton()), Some(false));
        for k in 0..30 {
            assert!(est.push(&frame(&bent, k)).is_none());
        }
        match est.status() {
            HeightStatus::Measuring {
                upright_frames,
                frames_seen,
                why,
                ..
            } => {
                assert_eq!((upright_frames, frames_seen), (0, 30));
                assert!(why.contains("upright"), "{why}");
            }
            HeightStatus::Decided(d) => panic!("{d:?}"),
        }
    }
}

#[test]
fn outlier_frames_do_not_move_the_median() {
    let s = spec(1.80);
    let mut est = estimator(&s);
    let up = s.up();
    for k in 0..50 {
        let mut sk = frame(&s, k);
        if k % 5 == 0 {
            // A bad triangulation: both eyes 30 cm too high.
            for lm in [Landmark::LeftEye, Landmark::RightEye] {
                let mut e = *sk.get(lm).unwrap();
                e.position_m = Point3::from(e.position_m.coords + up * 0.3);
                sk.set(lm, Some(e)).unwrap();
            }
        }
        est.push(&sk);
    }
    let e = est.estimate().unwrap();
    assert!((e.height_m - 1.80).abs() < 0.01, "{e:?}");
}

#[test]
fn a_configured_floor_is_used_when_known() {
    let s = PoseSpec {
        world_rotation: Rotation3::identity(),
        world_translation: Vector3::new(0.0, 0.0, 0.25),
        ..spec(1.70)
    };
    let mut config = HeightConfig::new(UpVector::new(Vector3::z()).unwrap());
    config.floor_height_m = Some(0.25);
    let mut est = HeightEstimator::new(config);
    // Feet hidden: only the configured floor gives the eye estimator its reference.
    for k in 0..20 {
        let mut sk = frame(&s, k);
        for lm in [
            Landmark::LeftHeel,
            Landmark::RightHeel,
            Landmark::LeftFootIndex,
            Landmark::RightFootIndex,
        ] {
            sk.set(lm, None).unwrap();
        }
        est.push(&sk);
    }
    let e = est.estimate().unwrap();
    let eye = e
        .estimators
        .iter()
        .find(|x| x.name == "floor_to_eye")
        .unwrap();
    assert!((eye.height_m - 1.70).abs() < 0.005, "{eye:?}");
}

#[test]
fn a_seated_operator_gets_a_segment_length_estimate_but_no_class() {
    let seated = PoseSpec {
        knee_flexion_rad: 90f64.to_radians(),
        ..spec(1.72)
    };
    let mut est = estimator(&seated);
    for k in 0..60 {
        assert!(est.push(&frame(&seated, k)).is_none());
    }
    assert!(matches!(
        est.status(),
        HeightStatus::Measuring {
            upright_frames: 0,
            ..
        }
    ));
    assert!(est.estimate().is_none());
    let seg = est.segment_estimate().unwrap();
    assert_eq!(seg.name, "segment_lengths");
    assert_eq!(seg.frames, 60);
    assert!((seg.height_m - 1.72).abs() < 0.02, "{seg:?}");
    assert!(
        seg.sigma_m >= 0.04 * seg.height_m,
        "includes the model spread: {seg:?}"
    );
}

/// #18: `height` confidently classed a 1753 m or a 2 mm "operator" (a landmark file in millimetres,
/// or scaled). A per-frame stature outside 0.5–2.5 m is never used: no class, and the status says why.
#[test]
fn height_of_a_physically_impossible_operator_is_never_classed() {
    for scale in [1000.0, 0.001] {
        let s = spec(1.753);
        let mut est = estimator(&s);
        for k in 0..200 {
            let f = frame(&s, k);
            let slots: Vec<_> = f
                .slots()
                .iter()
                .map(|l| {
                    l.map(|mut e| {
                        e.position_m = Point3::from(e.position_m.coords * scale);
                        e
                    })
                })
                .collect();
            let scaled = Skeleton3::try_from_slots(f.stamp_nanos, slots).unwrap();
            assert!(
                est.push(&scaled).is_none(),
                "×{scale}: decided at frame {k}"
            );
        }
        match est.status() {
            HeightStatus::Measuring { why, estimate, .. } => {
                assert!(why.contains("physically impossible"), "×{scale}: {why}");
                assert!(estimate.is_none(), "×{scale}: {estimate:?}");
            }
            HeightStatus::Decided(d) => panic!("×{scale}: classed {d:?}"),
        }
    }
}
