//! A wrist that is never observed (no hand points: index, pinky, thumb) is scored conservatively, not
//! left unscored.
//!
//! The wrist's flexion and deviation need the index and pinky (`ergocell_ergonomics::angles`), which
//! most 2D keypoint layouts in use have none of (OpenPose BODY_25/BODY_25B, COCO-17, HALPE-26; each
//! layout is tested through its own mapping in the workspace's `tests/rula_keypoint_layouts.rs`,
//! since this crate does not depend on perception). Such a side is scored with the wrist at RULA's
//! top flexion band (wrist score 3; McAtamney & Corlett 1993, step 3; see
//! `assess::UNOBSERVED_WRIST_FLEXION_DEG`), marked uncertain with the reason; a skeleton with its
//! hands scores exactly as before.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::assess::{InputSource, UNOBSERVED_WRIST_FLEXION_DEG};
use ergocell_ergonomics::pose::PoseSpec;
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor, Side, UpVector};
use ergocell_skeleton::{Landmark, Skeleton3};

const FRAME: i64 = 100_000_000;

const HAND_POINTS: [Landmark; 6] = [
    Landmark::LeftIndex,
    Landmark::LeftPinky,
    Landmark::LeftThumb,
    Landmark::RightIndex,
    Landmark::RightPinky,
    Landmark::RightThumb,
];

/// The golden reaching pose (`PoseSpec::reaching`) at a time.
fn reaching(stamp_nanos: i64) -> PoseSpec {
    PoseSpec {
        stamp_nanos,
        ..PoseSpec::reaching()
    }
}

fn without_hands(s: &Skeleton3) -> Skeleton3 {
    let mut s = s.clone();
    for lm in HAND_POINTS {
        s.set(lm, None).unwrap();
    }
    s
}

fn assessor() -> RulaAssessor {
    RulaAssessor::new(AssessmentConfig::new(
        UpVector::new(reaching(0).up()).unwrap(),
    ))
    .unwrap()
}

#[test]
fn a_side_without_hand_points_is_scored_with_a_conservative_uncertain_wrist() {
    let (mut hands, mut no_hands) = (assessor(), assessor());
    for k in 0..20 {
        let full = reaching(k * FRAME).skeleton();
        let f = hands.assess(&full).unwrap();
        let g = no_hands.assess(&without_hands(&full)).unwrap();
        assert!(g.unscored_reasons.is_empty(), "{:?}", g.unscored_reasons);
        for side in [Side::Left, Side::Right] {
            let (a, b) = (f.side(side).unwrap(), g.side(side).unwrap());
            assert!(!a.uncertain, "{:?}", a.uncertain_reasons);
            assert_eq!(a.source("wrist_flexion_deg"), Some(InputSource::Observed));
            assert_eq!(b.scores.wrist_score, 3, "{side:?}");
            assert_eq!(b.input.wrist_flexion_deg, UNOBSERVED_WRIST_FLEXION_DEG);
            assert_eq!(
                b.source("wrist_flexion_deg"),
                Some(InputSource::Conservative)
            );
            assert_eq!(
                b.source("wrist_bent_from_midline"),
                Some(InputSource::NotObserved)
            );
            assert!(b.uncertain);
            let name = side.name();
            assert!(
                b.uncertain_reasons
                    .iter()
                    .any(|r| r.contains(&format!("no {name}_index, {name}_pinky"))
                        && r.contains("wrist scored conservatively as 3")),
                "{:?}",
                b.uncertain_reasons
            );
            // Only the wrist differs: every other region as observed with the hands.
            let (sa, sb) = (a.scores, b.scores);
            assert_eq!(sa.upper_arm_score, sb.upper_arm_score);
            assert_eq!(sa.lower_arm_score, sb.lower_arm_score);
            assert_eq!(sa.score_d_neck_trunk_legs, sb.score_d_neck_trunk_legs);
        }
        // The right wrist is flexed 25° (3 either way); the straight left wrist scores lower seen.
        assert_eq!(
            f.right.as_ref().unwrap().scores,
            g.right.as_ref().unwrap().scores
        );
        assert!(f.left.as_ref().unwrap().scores.wrist_score < 3);
    }
}

#[test]
fn a_skeleton_with_its_hands_scores_as_before() {
    let f = assessor().assess(&reaching(0).skeleton()).unwrap();
    let (l, r) = (f.left.unwrap(), f.right.unwrap());
    assert_eq!(
        (
            r.scores.upper_arm_score,
            r.scores.lower_arm_score,
            r.scores.wrist_score,
            r.scores.neck_score,
            r.scores.trunk_score
        ),
        (4, 2, 3, 3, 3),
        "the golden values of assess_warnings.rs"
    );
    assert_eq!(l.scores.upper_arm_score, 1);
    assert!(!l.uncertain && !r.uncertain);
}
