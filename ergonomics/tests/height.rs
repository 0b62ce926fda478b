//! Stature estimation and the height class decision on synthetic operators.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::height::{
    ClassThresholds, DecisionBasis, HandoverRula, ServedStatures, DEFAULT_EAR_OFFSET_SIGMA_M,
};
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
        assert_eq!(k, 29, "after the 30 frames the config asks for");
        assert_eq!(d.class, class);
        assert_eq!(d.estimate.frames_used, 30);
        assert!((d.estimate.height_m - stature).abs() < 0.005, "{d:?}");
        assert!(d.estimate.uncertainty_m > 0.0 && d.estimate.uncertainty_m < 0.05);
        assert_eq!(d.estimate.estimators.len(), 2);
        // The ears stand where the floor-to-ear model puts them; the ankle-to-ear chain reads a
        // few millimetres tall on this body (Drillis & Contini's ankle at 0.039 H, below the
        // lateral malleolus ANSUR II measures), well inside its 9 mm residual.
        for e in &d.estimate.estimators {
            let tolerance = if e.name == "floor_to_ear" {
                0.001
            } else {
                0.009
            };
            assert!((e.height_m - stature).abs() < tolerance, "{e:?}");
        }
        assert_eq!(d.basis, DecisionBasis::Interval);
        assert!(d.probability > 0.95, "{d:?}");
        assert_eq!(d.options.len(), 1);
        // Uncalibrated: the ear offset's default uncertainty is in the stated σ.
        assert!(d.estimate.uncertainty_m >= DEFAULT_EAR_OFFSET_SIGMA_M);
        assert!(d.estimate.ear_offset.calibrated_sessions.is_none());
        assert!(matches!(est.status(), HeightStatus::Decided(_)));
    }
}

/// An operator whose interval straddles a boundary is served as soon as enough upright frames were
/// seen: the more probable class without RULA curves, the cheaper one with them; a class whose
/// trajectory does not serve the whole interval is never chosen.
#[test]
fn an_interval_that_straddles_a_boundary_is_decided_at_once_and_stays_served() {
    let s = spec(1.69);
    let decide = |config: HeightConfig| {
        let mut est = HeightEstimator::new(config);
        let found = (0..600).find_map(|k| est.push(&frame(&s, k)).map(|d| (k, d)));
        (found, est.status())
    };
    let config = HeightConfig::new(UpVector::new(s.up()).unwrap());

    // No curves: the most probable class, c2 (1.69 m is above 1.68 m).
    let (found, _) = decide(config.clone());
    let (k, d) = found.expect("decided");
    assert_eq!(k, 29, "after the 30 frames the config asks for");
    assert_eq!(d.basis, DecisionBasis::MostProbable);
    assert_eq!(d.class, HeightClass::C2);
    assert!(d.interval_m[0] < 1.68 && 1.68 < d.interval_m[1], "{d:?}");
    assert!(d.probability > 0.5 && d.probability < 0.95, "{d:?}");
    let p: f64 = d.options.iter().map(|o| o.probability).sum();
    assert!(
        (p - 1.0).abs() < 1e-3,
        "the options hold the whole distribution: {p}"
    );
    assert!(d.expected_rula_cost.is_none());

    // Curves that make c1's handover cheaper around 1.69 m: c1 is chosen, at a stated cost.
    let curves = HandoverRula {
        statures_m: vec![1.5, 1.68, 1.82, 2.0],
        c1: vec![2.0, 2.0, 3.0, 4.0],
        c2: vec![4.0, 3.0, 2.5, 3.0],
        c3: vec![5.0, 4.0, 3.0, 2.5],
    };
    curves.check().unwrap();
    let mut with_curves = config.clone();
    with_curves.handover_rula = Some(curves.clone());
    let (found, _) = decide(with_curves.clone());
    let d = found.expect("decided").1;
    assert_eq!(d.basis, DecisionBasis::ExpectedRula);
    assert_eq!(d.class, HeightClass::C1);
    let cost = d.expected_rula_cost.unwrap();
    assert!(
        cost < 0.0,
        "c1 is cheaper than the true class c2 here: {cost}"
    );
    let c1 = d
        .options
        .iter()
        .find(|o| o.class == HeightClass::C1)
        .unwrap();
    let c2 = d
        .options
        .iter()
        .find(|o| o.class == HeightClass::C2)
        .unwrap();
    assert!(c1.expected_rula.unwrap() < c2.expected_rula.unwrap());

    // c1's trajectory serves up to 1.68 m only: c2 is chosen although c1 would be cheaper.
    let mut narrow = with_curves.clone();
    narrow.served_m = Some(ServedStatures::new([[1.5, 1.68], [1.62, 1.88], [1.76, 2.0]]).unwrap());
    let d = decide(narrow).0.expect("decided").1;
    assert_eq!(d.class, HeightClass::C2);
    assert!(
        !d.options
            .iter()
            .find(|o| o.class == HeightClass::C1)
            .unwrap()
            .served
    );

    // No trajectory serves the interval: undecided, and the status says why.
    let mut none = with_curves;
    none.served_m = Some(ServedStatures::new([[1.5, 1.68], [1.70, 1.88], [1.76, 2.0]]).unwrap());
    let (found, status) = decide(none);
    assert!(found.is_none());
    match status {
        HeightStatus::Measuring { why, .. } => {
            assert!(why.contains("no class serves"), "{why}");
        }
        HeightStatus::Decided(d) => panic!("{d:?}"),
    }
}

/// Every decision's interval lies inside the statures its class serves; an interval inside one
/// class decides that class.
#[test]
fn every_decision_is_served_with_its_whole_interval() {
    let served = ServedStatures::new([[1.44, 1.74], [1.62, 1.88], [1.76, 2.06]]).unwrap();
    let t = ClassThresholds::default();
    for stature in [
        1.50, 1.55, 1.60, 1.62, 1.67, 1.68, 1.69, 1.72, 1.75, 1.81, 1.82, 1.83, 1.87, 1.9, 2.0,
    ] {
        let s = spec(stature);
        let mut config = HeightConfig::new(UpVector::new(s.up()).unwrap());
        config.served_m = Some(served);
        let mut est = HeightEstimator::new(config);
        let d = (0..600)
            .find_map(|k| est.push(&frame(&s, k)))
            .unwrap_or_else(|| panic!("{stature} m: undecided: {:?}", est.status()));
        let [lo, hi] = served.of(d.class);
        assert!(
            lo <= d.interval_m[0] && d.interval_m[1] <= hi,
            "{stature}: {d:?}"
        );
        if HeightClass::of(d.interval_m[0], &t) == HeightClass::of(d.interval_m[1], &t) {
            assert_eq!(d.basis, DecisionBasis::Interval);
            assert_eq!(d.class, HeightClass::of(stature, &t), "{stature}: {d:?}");
        }
    }
}

#[test]
fn handover_rula_curves_are_checked_and_interpolated() {
    let curves = HandoverRula {
        statures_m: vec![1.5, 1.7, 2.0],
        c1: vec![2.0, 3.0, 4.0],
        c2: vec![3.0, 3.0, 3.0],
        c3: vec![4.0, 3.0, 2.0],
    };
    curves.check().unwrap();
    assert!((curves.at(HeightClass::C1, 1.6) - 2.5).abs() < 1e-12);
    assert_eq!(
        curves.at(HeightClass::C1, 1.4),
        2.0,
        "constant below the first stature"
    );
    assert_eq!(
        curves.at(HeightClass::C3, 2.2),
        2.0,
        "constant beyond the last"
    );
    let mut bad = curves.clone();
    bad.c2.pop();
    assert!(bad.check().is_err());
    let mut bad = curves.clone();
    bad.statures_m = vec![1.5, 1.5, 2.0];
    assert!(bad.check().is_err());
    let mut bad = curves;
    bad.c3[0] = f64::NAN;
    assert!(bad.check().is_err());
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
            // A bad triangulation: both ears 30 cm too high.
            for lm in [Landmark::LeftEar, Landmark::RightEar] {
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
    // Feet hidden: only the configured floor gives the ear estimator its reference.
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
    let ear = e
        .estimators
        .iter()
        .find(|x| x.name == "floor_to_ear")
        .unwrap();
    assert!((ear.height_m - 1.70).abs() < 0.002, "{ear:?}");
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

#[test]
fn an_ear_offset_is_calibrated_from_five_sessions_and_removed() {
    use ergocell_ergonomics::height::{calibrate_ear_offset, CalibrationSample};
    // Five people whose ear landmark sits 15 mm above the tragion: the uncalibrated estimate reads
    // tall by the model's slope times 15 mm (noiseless synthetic bodies: exactly).
    let mut samples = Vec::new();
    for stature in [1.58, 1.66, 1.73, 1.80, 1.91] {
        let s = spec(stature);
        let mut sk_est = estimator(&s);
        for k in 0..30 {
            let mut sk = frame(&s, k);
            for lm in [Landmark::LeftEar, Landmark::RightEar] {
                let mut e = *sk.get(lm).unwrap();
                e.position_m = Point3::from(e.position_m.coords + s.up() * 0.015);
                sk.set(lm, Some(e)).unwrap();
            }
            sk_est.push(&sk);
        }
        samples.push(CalibrationSample::from_estimate(
            &sk_est.estimate().unwrap(),
            stature,
        ));
    }
    let offset = calibrate_ear_offset(&samples).unwrap();
    // The chain reads a few millimetres tall on these bodies (see above), which the calibration
    // takes in with the offset: within 2 mm.
    assert!((offset.offset_m - 0.015).abs() < 0.002, "{offset:?}");
    assert_eq!(offset.calibrated_sessions, Some(5));
    // The model's 6.5 mm residual over √5, widened by Student's t(4): about 4 mm.
    assert!(
        offset.sigma_m > 0.0035 && offset.sigma_m < 0.0045,
        "{offset:?}"
    );
    // With the offset configured, the same person is measured as without it.
    let s = spec(1.75);
    let mut config = HeightConfig::new(UpVector::new(s.up()).unwrap());
    config.ear_offset = offset;
    let mut est = HeightEstimator::new(config);
    for k in 0..30 {
        let mut sk = frame(&s, k);
        for lm in [Landmark::LeftEar, Landmark::RightEar] {
            let mut e = *sk.get(lm).unwrap();
            e.position_m = Point3::from(e.position_m.coords + s.up() * 0.015);
            sk.set(lm, Some(e)).unwrap();
        }
        est.push(&sk);
    }
    let e = est.estimate().unwrap();
    assert!((e.height_m - 1.75).abs() < 0.003, "{e:?}");
    assert!(e.uncertainty_m < 0.010, "calibrated: {e:?}");
    // Too few sessions, or statures that are not a person's, are refused with the reason.
    let e = calibrate_ear_offset(&samples[..4]).unwrap_err();
    assert!(e.to_string().contains("at least 5"), "{e}");
    let mut bad = samples.clone();
    bad[2].measured_m = 175.0;
    let e = calibrate_ear_offset(&bad).unwrap_err();
    assert!(e.to_string().contains("session 3"), "{e}");
}
