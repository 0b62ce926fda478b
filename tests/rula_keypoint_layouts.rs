//! RULA from the keypoint layouts in use, not only BlazePose-33.
//!
//! Most 2D detectors have no hand points: OpenPose BODY_25 and BODY_25B, COCO-17 and HALPE-26 fill
//! the BlazePose landmarks listed by `ergocell_perception::detections::KeypointFormat::mapping` and no
//! index or pinky, so the wrist's flexion and deviation (which need them, see
//! `ergocell_ergonomics::angles`) are never observed. Issue row: `rula track` scored 0 of 100 frames of
//! such a recording, with null sides and no reason. Now every side is scored from what the layout
//! sees; the unobserved wrist is scored conservatively (RULA wrist score 3, McAtamney & Corlett 1993
//! step 3, see `assess::UNOBSERVED_WRIST_FLEXION_DEG`), the side is uncertain and says why, and a
//! full BlazePose skeleton scores exactly as before.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::assess::{BodyRegion, InputSource, UNOBSERVED_WRIST_FLEXION_DEG};
use ergocell_ergonomics::pose::PoseSpec;
use ergocell_ergonomics::{
    AssessmentConfig, FrameAssessment, RulaAssessor, Side, SideAssessment, UpVector, WarningConfig,
    WarningTracker,
};
use ergocell_perception::detections::KeypointFormat;
use ergocell_skeleton::{Landmark, Skeleton3};

const FRAME: i64 = 100_000_000;

/// The layouts without hand points.
const LAYOUTS: [(KeypointFormat, &str); 4] = [
    (KeypointFormat::Body25, "BODY_25"),
    (KeypointFormat::Body25B, "BODY_25B"),
    (KeypointFormat::Coco17, "COCO-17"),
    (KeypointFormat::Halpe26, "HALPE-26"),
];

/// The skeleton with only the landmarks `layout` fills (what triangulating its detections gives).
fn as_seen_by(layout: KeypointFormat, full: &Skeleton3) -> Skeleton3 {
    let kept: Vec<Landmark> = layout.mapping().iter().flatten().copied().collect();
    let mut s = full.clone();
    for lm in Landmark::ALL {
        if !kept.contains(&lm) {
            s.set(lm, None).unwrap();
        }
    }
    s
}

fn assessor(spec: &PoseSpec) -> RulaAssessor {
    RulaAssessor::new(AssessmentConfig::new(UpVector::new(spec.up()).unwrap())).unwrap()
}

/// `n` frames of `spec` at 10 Hz, as `layout` sees them (`None`: every landmark), assessed in order.
fn assess_frames(spec: &PoseSpec, layout: Option<KeypointFormat>, n: i64) -> Vec<FrameAssessment> {
    let mut a = assessor(spec);
    (0..n)
        .map(|k| {
            let full = PoseSpec {
                stamp_nanos: k * FRAME,
                ..spec.clone()
            }
            .skeleton();
            let s = layout.map_or_else(|| full.clone(), |l| as_seen_by(l, &full));
            a.assess(&s).unwrap()
        })
        .collect()
}

fn both(f: &FrameAssessment) -> [&SideAssessment; 2] {
    [f.left.as_ref().unwrap(), f.right.as_ref().unwrap()]
}

#[test]
fn the_layouts_have_no_hand_points_but_everything_else_the_worksheet_needs() {
    for (layout, name) in LAYOUTS {
        let m = layout.mapping();
        for hand in [
            Landmark::LeftIndex,
            Landmark::LeftPinky,
            Landmark::RightIndex,
            Landmark::RightPinky,
        ] {
            assert!(!m.contains(&Some(hand)), "{name} has {hand}");
        }
        for needed in [
            Landmark::LeftShoulder,
            Landmark::RightShoulder,
            Landmark::LeftElbow,
            Landmark::RightElbow,
            Landmark::LeftWrist,
            Landmark::RightWrist,
            Landmark::LeftHip,
            Landmark::RightHip,
            Landmark::LeftEar,
            Landmark::RightEar,
            Landmark::LeftAnkle,
            Landmark::RightAnkle,
        ] {
            assert!(m.contains(&Some(needed)), "{name} lacks {needed}");
        }
    }
}

/// The regression test of the issue row: every frame, both sides scored; the wrist at the
/// conservative value, uncertain, with the reason; every other region as the full skeleton scores it.
#[test]
fn rula_track_scored_0_of_100_frames_of_a_detector_without_hand_points() {
    let spec = PoseSpec::reaching();
    let full = assess_frames(&spec, None, 100);
    for (layout, name) in LAYOUTS {
        let frames = assess_frames(&spec, Some(layout), 100);
        for (k, (f, g)) in frames.iter().zip(&full).enumerate() {
            assert!(
                f.left.is_some() && f.right.is_some(),
                "{name} frame {k}: unscored: {:?}",
                f.unscored_reasons
            );
            assert!(
                f.unscored_reasons.is_empty(),
                "{name} {:?}",
                f.unscored_reasons
            );
            for (side, (a, b)) in [Side::Left, Side::Right]
                .into_iter()
                .zip(both(f).into_iter().zip(both(g)))
            {
                let what = format!("{name} frame {k} {side:?}");
                assert_eq!(
                    a.scores.wrist_score, 3,
                    "{what}: the conservative wrist score"
                );
                assert_eq!(
                    a.input.wrist_flexion_deg, UNOBSERVED_WRIST_FLEXION_DEG,
                    "{what}"
                );
                assert!(!a.input.wrist_bent_from_midline, "{what}");
                assert_eq!(
                    a.source("wrist_flexion_deg"),
                    Some(InputSource::Conservative),
                    "{what}"
                );
                assert_eq!(
                    a.source("wrist_bent_from_midline"),
                    Some(InputSource::NotObserved),
                    "{what}"
                );
                assert!(a.uncertain, "{what}");
                let prefix = if side == Side::Left { "left" } else { "right" };
                let reason = a
                    .uncertain_reasons
                    .iter()
                    .find(|r| r.contains("wrist scored conservatively as 3"))
                    .unwrap_or_else(|| panic!("{what}: {:?}", a.uncertain_reasons));
                assert!(
                    reason.contains(&format!("no {prefix}_index, {prefix}_pinky")),
                    "{what}: {reason}"
                );
                assert!(reason.contains("BODY_25B"), "{what}: {reason}");
                // Everything the layout sees scores as on the full skeleton.
                let (sa, sb) = (&a.scores, &b.scores);
                assert_eq!(
                    (sa.upper_arm_score, sa.lower_arm_score, sa.wrist_twist_score),
                    (sb.upper_arm_score, sb.lower_arm_score, sb.wrist_twist_score),
                    "{what}"
                );
                assert_eq!(
                    (
                        sa.neck_score,
                        sa.trunk_score,
                        sa.legs_score,
                        sa.score_d_neck_trunk_legs
                    ),
                    (
                        sb.neck_score,
                        sb.trunk_score,
                        sb.legs_score,
                        sb.score_d_neck_trunk_legs
                    ),
                    "{what}"
                );
                assert!(sa.final_score >= 1 && sa.final_score <= 7, "{what}");
            }
            // The right wrist really is flexed 25° (score 3): the conservative score agrees.
            assert_eq!(
                f.right.as_ref().unwrap().scores,
                g.right.as_ref().unwrap().scores
            );
            // The left wrist is straight: the conservative score is higher, never lower.
            let (l, gl) = (f.left.as_ref().unwrap(), g.left.as_ref().unwrap());
            assert!(gl.scores.wrist_score < 3, "{:?}", gl.scores);
            assert!(l.scores.final_score >= gl.scores.final_score);
        }
    }
}

/// The full skeleton scores exactly as before (the golden values of `ergonomics/tests/assess_warnings.rs`): nothing
/// is conservative, nothing uncertain.
#[test]
fn a_full_blazepose_skeleton_scores_exactly_as_before() {
    let f = &assess_frames(&PoseSpec::reaching(), None, 1)[0];
    let [l, r] = both(f);
    assert_eq!(r.scores.upper_arm_score, 4, "100° flexion");
    assert_eq!(l.scores.upper_arm_score, 1, "hanging");
    assert_eq!(r.scores.lower_arm_score, 2, "20° elbow");
    assert_eq!(r.scores.wrist_score, 3, "25° wrist");
    assert_eq!(r.scores.neck_score, 3, "25° neck");
    assert_eq!(r.scores.trunk_score, 3, "30° trunk");
    for s in [l, r] {
        assert!(!s.uncertain, "{:?}", s.uncertain_reasons);
        assert_eq!(s.source("wrist_flexion_deg"), Some(InputSource::Observed));
        assert_eq!(
            s.source("wrist_bent_from_midline"),
            Some(InputSource::Observed)
        );
    }
    assert_eq!(f.headline().unwrap().side, Side::Right);

    // Upright with the left arm reaching: (3, 2), as in `ergonomics/tests/assess_warnings.rs` (the
    // neck 5° down, inside RULA's 0–10° band rather than on its 0° edge).
    let spec = PoseSpec::reaching();
    let left_reach = PoseSpec {
        left_arm: spec.right_arm,
        right_arm: PoseSpec::default().right_arm,
        trunk_flexion_rad: 0.0,
        neck_flexion_rad: 5f64.to_radians(),
        ..spec
    };
    let f = &assess_frames(&left_reach, None, 1)[0];
    let [l, r] = both(f);
    assert_eq!((l.scores.final_score, r.scores.final_score), (3, 2));
}

/// A hand seen once and then lost is held (the last observed wrist), as any other input: the
/// conservative value is only for a wrist never observed.
#[test]
fn a_hand_seen_before_is_held_not_scored_conservatively() {
    let spec = PoseSpec::reaching();
    let mut a = assessor(&spec);
    let at = |k: i64| {
        PoseSpec {
            stamp_nanos: k * FRAME,
            ..spec.clone()
        }
        .skeleton()
    };
    let seen = a.assess(&at(0)).unwrap();
    let lost = a
        .assess(&as_seen_by(KeypointFormat::Body25B, &at(1)))
        .unwrap();
    for side in [Side::Left, Side::Right] {
        let (s, l) = (seen.side(side).unwrap(), lost.side(side).unwrap());
        assert_eq!(l.source("wrist_flexion_deg"), Some(InputSource::Held));
        assert_eq!(l.scores, s.scores, "{side:?}");
        assert!(l.uncertain);
        assert!(
            l.uncertain_reasons
                .iter()
                .all(|r| !r.contains("conservatively")),
            "{:?}",
            l.uncertain_reasons
        );
    }
}

/// A wrist nobody saw raises no posture warning (a warning states an angle and what to change);
/// the regions the layout sees warn as on the full skeleton.
#[test]
fn an_unobserved_wrist_raises_no_warning() {
    let spec = PoseSpec::reaching();
    for (layout, name) in LAYOUTS {
        let mut tracker = WarningTracker::new(WarningConfig::default());
        let mut full_tracker = WarningTracker::new(WarningConfig::default());
        let frames = assess_frames(&spec, Some(layout), 50);
        let full = assess_frames(&spec, None, 50);
        let mut events = Vec::new();
        let mut full_events = Vec::new();
        for (f, g) in frames.iter().zip(&full) {
            events.extend(tracker.update(f));
            full_events.extend(full_tracker.update(g));
        }
        assert!(
            events.iter().all(|e| e.region != BodyRegion::Wrist),
            "{name}: {events:?}"
        );
        let not_wrist =
            |es: &[ergocell_ergonomics::WarningEvent]| -> Vec<(BodyRegion, Option<Side>, u8)> {
                es.iter()
                    .filter(|e| e.region != BodyRegion::Wrist)
                    .map(|e| (e.region, e.side, e.region_score))
                    .collect()
            };
        assert_eq!(not_wrist(&events), not_wrist(&full_events), "{name}");
        assert!(
            !not_wrist(&events).is_empty(),
            "the neck and trunk at 25° and 30° warn"
        );
    }
}
