//! #18 row "the upper-arm flexion sign flips between about +26° and −26° when the arm hangs near the
//! trunk's side plane": a hanging arm on the back/side diagonal, seen with a few degrees of noise,
//! keeps one sign in the frame-by-frame assessment (hysteresis,
//! `assess::UPPER_ARM_SIGN_BAND`), while a clear move backwards or sideways still switches it.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::angles::body_angles;
use ergocell_ergonomics::pose::{ArmPose, PoseSpec};
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor, UpVector};

const FRAME: i64 = 33_333_333;

fn arm(flexion_deg: f64, abduction_deg: f64, stamp_nanos: i64) -> PoseSpec {
    PoseSpec {
        right_arm: ArmPose {
            flexion_rad: flexion_deg.to_radians(),
            abduction_rad: abduction_deg.to_radians(),
            ..ArmPose::default()
        },
        stamp_nanos,
        ..PoseSpec::default()
    }
}

/// The right upper arm's flexion as one frame alone gives it (no history).
fn stateless(spec: &PoseSpec) -> f64 {
    let up = UpVector::new(spec.up()).unwrap();
    body_angles(&spec.skeleton(), &up, None)
        .right
        .upper_arm_flexion_rad
        .unwrap()
}

#[test]
fn a_hanging_arm_on_the_back_side_diagonal_keeps_its_sign() {
    // Extended 20° backwards, then abducted: find where one frame's sign flips.
    let flip = (0..400)
        .map(|k| f64::from(k) * 0.1)
        .find(|&a| stateless(&arm(-20.0, a, 0)) > 0.0)
        .expect("the sign flips somewhere between pure extension and sideways");
    let (below, above) = (flip - 1.5, flip + 1.5);
    let (s_below, s_above) = (
        stateless(&arm(-20.0, below, 0)),
        stateless(&arm(-20.0, above, 0)),
    );
    assert!(
        s_below < 0.0 && s_above > 0.0,
        "one frame alone flips: {:.1}° and {:.1}°",
        s_below.to_degrees(),
        s_above.to_degrees()
    );
    assert!(
        s_below.abs().to_degrees() > 20.0,
        "a flip across the 20° band edges"
    );

    let spec = arm(-20.0, 0.0, 0);
    let mut assessor =
        RulaAssessor::new(AssessmentConfig::new(UpVector::new(spec.up()).unwrap())).unwrap();
    let mut stamp = 0;
    let mut assess = |flexion: f64, abduction: f64| {
        stamp += FRAME;
        let a = assessor
            .assess(&arm(flexion, abduction, stamp).skeleton())
            .unwrap();
        a.angles.right.upper_arm_flexion_rad.unwrap()
    };
    // Start clearly sideways (flexion), then jitter across the diagonal: one sign throughout.
    for _ in 0..10 {
        assert!(assess(0.0, 30.0) > 0.0);
    }
    for k in 0..60 {
        let a = if k % 2 == 0 { below } else { above };
        let got = assess(-20.0, a);
        assert!(
            got > 0.0,
            "frame {k}: {:.1}° (abduction {a:.1}°)",
            got.to_degrees()
        );
    }
    // A clear move backwards switches to extension, and the jitter then keeps that.
    let mut last = 0.0;
    for _ in 0..10 {
        last = assess(-30.0, 0.0);
    }
    assert!(last < 0.0, "clearly backwards: {:.1}°", last.to_degrees());
    for k in 0..60 {
        let a = if k % 2 == 0 { below } else { above };
        let got = assess(-20.0, a);
        assert!(
            got < 0.0,
            "frame {k}: {:.1}° (abduction {a:.1}°)",
            got.to_degrees()
        );
    }
    // A clear move sideways switches back.
    for _ in 0..10 {
        last = assess(-10.0, 50.0);
    }
    assert!(last > 0.0, "clearly sideways: {:.1}°", last.to_degrees());
}
