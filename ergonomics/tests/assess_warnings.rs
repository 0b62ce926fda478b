//! Frame-by-frame assessment (both sides, provenance, uncertainty, muscle use from the time series)
//! and the warning stream (hysteresis, dwell, plain words).

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::assess::{
    AngleSmoother, BodyRegion, InputSource, MuscleUseConfig, MuscleUseTracker,
};
use ergocell_ergonomics::pose::{ArmPose, PoseSpec};
use ergocell_ergonomics::summary::SummaryBuilder;
use ergocell_ergonomics::warnings::WarningKind;
use ergocell_ergonomics::{
    AssessmentConfig, ErgonomicsError, FrameAssessment, RulaAssessor, Side, TaskConfig, UpVector,
    WarningConfig, WarningTracker, WristTwist,
};
use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::Vector3;

const SEC: i64 = 1_000_000_000;
const FRAME: i64 = SEC / 10;

fn assessor_for(spec: &PoseSpec) -> RulaAssessor {
    RulaAssessor::new(AssessmentConfig::new(UpVector::new(spec.up()).unwrap())).unwrap()
}

fn at(spec: &PoseSpec, stamp_nanos: i64) -> Skeleton3 {
    PoseSpec {
        stamp_nanos,
        ..spec.clone()
    }
    .skeleton()
}

#[test]
fn both_sides_are_scored_and_the_worse_is_the_headline() {
    let spec = PoseSpec::reaching();
    let f = assessor_for(&spec).assess(&spec.skeleton()).unwrap();
    let (l, r) = (f.left.as_ref().unwrap(), f.right.as_ref().unwrap());
    assert_eq!(r.scores.upper_arm_score, 4, "100° flexion");
    assert_eq!(l.scores.upper_arm_score, 1, "hanging");
    assert_eq!(r.scores.lower_arm_score, 2, "20° elbow");
    assert_eq!(r.scores.wrist_score, 3, "25° wrist");
    assert_eq!(r.scores.neck_score, 3, "25° neck");
    assert_eq!(r.scores.trunk_score, 3, "30° trunk");
    assert_eq!(l.scores.neck_score, r.scores.neck_score);
    assert!(r.scores.score_c_wrist_arm > l.scores.score_c_wrist_arm);
    assert!(r.scores.final_score >= l.scores.final_score);
    assert_eq!(f.headline().unwrap().side, Side::Right);
    assert!(!r.uncertain, "{:?}", r.uncertain_reasons);

    // Upright, the left arm reaching: the left side is worse and is the headline. (The neck looks
    // 5° down: inside RULA's 0–10° band, not on its 0° edge, where a rotated world's rounding
    // decides between flexion and extension.)
    let left_reach = PoseSpec {
        left_arm: spec.right_arm,
        right_arm: PoseSpec::default().right_arm,
        trunk_flexion_rad: 0.0,
        neck_flexion_rad: 5f64.to_radians(),
        ..spec
    };
    let f = assessor_for(&left_reach)
        .assess(&left_reach.skeleton())
        .unwrap();
    let (l, r) = (f.left.as_ref().unwrap(), f.right.as_ref().unwrap());
    assert_eq!((l.scores.final_score, r.scores.final_score), (3, 2));
    assert_eq!(f.headline().unwrap().side, Side::Left);
}

#[test]
fn the_breakdown_says_what_was_observed_and_what_configured() {
    let spec = PoseSpec::default();
    let mut config = AssessmentConfig::new(UpVector::new(spec.up()).unwrap());
    config.task = TaskConfig {
        force_load_score_arm_wrist: 2,
        force_load_score_neck_trunk_legs: 1,
        wrist_twist: WristTwist::EndOfRange,
        arm_supported_or_leaning: false,
        seated_well_supported: false,
        ..TaskConfig::default()
    };
    let f = RulaAssessor::new(config)
        .unwrap()
        .assess(&spec.skeleton())
        .unwrap();
    let r = f.right.unwrap();
    assert_eq!(r.input.force_load_score_arm_wrist, 2);
    assert_eq!(r.input.force_load_score_neck_trunk_legs, 1);
    assert_eq!(r.scores.wrist_twist_score, 2);
    let source = |name: &str| r.sources.iter().find(|(n, _)| *n == name).unwrap().1;
    assert_eq!(source("upper_arm_flexion_deg"), InputSource::Observed);
    assert_eq!(source("neck_flexion_deg"), InputSource::Observed);
    assert_eq!(source("legs_supported_and_balanced"), InputSource::Observed);
    assert_eq!(source("wrist_twist"), InputSource::Configured);
    assert_eq!(
        source("force_load_score_arm_wrist"),
        InputSource::Configured
    );
    assert_eq!(source("muscle_use_arm_wrist"), InputSource::TimeSeries);
    assert!(r.input.legs_supported_and_balanced);
    let names: Vec<&str> = r.sources.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, ergocell_ergonomics::RulaInput::FIELDS);
}

#[test]
fn out_of_range_task_config_is_rejected() {
    let mut config = AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap());
    config.task.force_load_score_arm_wrist = 4;
    assert!(matches!(
        RulaAssessor::new(config),
        Err(ErgonomicsError::OutOfRange {
            field: "task.force_load_score_arm_wrist",
            ..
        })
    ));
}

fn with_confidence(s: &Skeleton3, lm: Landmark, confidence: f64) -> Skeleton3 {
    let mut s = s.clone();
    let mut e = *s.get(lm).unwrap();
    e.confidence = confidence;
    s.set(lm, Some(e)).unwrap();
    s
}

#[test]
fn low_confidence_makes_the_score_uncertain_never_lower() {
    let spec = PoseSpec::reaching();
    let sure = assessor_for(&spec).assess(&spec.skeleton()).unwrap();
    let shaky = with_confidence(&spec.skeleton(), Landmark::RightWrist, 0.2);
    let unsure = assessor_for(&spec).assess(&shaky).unwrap();
    let (a, b) = (sure.right.unwrap(), unsure.right.unwrap());
    assert!(!a.uncertain);
    assert!(b.uncertain);
    assert!(
        b.uncertain_reasons
            .iter()
            .any(|r| r.contains("right_wrist")),
        "{:?}",
        b.uncertain_reasons
    );
    assert_eq!(a.scores, b.scores, "the score is unchanged");
    assert!(
        !unsure.left.unwrap().uncertain,
        "the left side did not use the right wrist"
    );
}

#[test]
fn missing_landmarks_are_held_or_leave_the_side_unscored() {
    let spec = PoseSpec::reaching();
    let mut assessor = assessor_for(&spec);
    let mut first = at(&spec, 0);
    first.set(Landmark::RightElbow, None).unwrap();
    let f = assessor.assess(&first).unwrap();
    assert!(
        f.right.is_none(),
        "never observed: no score, not a safe score"
    );
    assert!(f.left.is_some());
    assert!(f.unscored_reasons.iter().any(|r| r.contains("right arm")));

    assessor.assess(&at(&spec, FRAME)).unwrap();
    let mut gap = at(&spec, 2 * FRAME);
    gap.set(Landmark::RightElbow, None).unwrap();
    let f = assessor.assess(&gap).unwrap();
    let r = f.right.unwrap();
    assert!(r.uncertain);
    assert_eq!(r.scores.upper_arm_score, 4, "held from the previous frame");
    let source = r
        .sources
        .iter()
        .find(|(n, _)| *n == "upper_arm_flexion_deg")
        .unwrap()
        .1;
    assert_eq!(source, InputSource::Held);
}

#[test]
fn time_going_backwards_is_an_error() {
    let spec = PoseSpec::default();
    let mut assessor = assessor_for(&spec);
    assessor.assess(&at(&spec, 5 * SEC)).unwrap();
    assert_eq!(
        assessor.assess(&at(&spec, 4 * SEC)).unwrap_err(),
        ErgonomicsError::TimeWentBackwards {
            previous: 5 * SEC,
            got: 4 * SEC
        }
    );
}

#[test]
fn muscle_use_from_a_posture_held_over_a_minute() {
    let spec = PoseSpec {
        right_arm: ArmPose {
            flexion_rad: 60f64.to_radians(),
            elbow_flexion_rad: 80f64.to_radians(),
            ..ArmPose::default()
        },
        ..PoseSpec::default()
    };
    let mut assessor = assessor_for(&spec);
    let mut last = None;
    for k in 0..=610 {
        let f = assessor.assess(&at(&spec, k * FRAME)).unwrap();
        let r = f.right.unwrap();
        if k * FRAME <= 60 * SEC {
            assert!(!r.input.muscle_use_arm_wrist, "not yet static at frame {k}");
        }
        assert!(
            !f.left.unwrap().input.muscle_use_arm_wrist,
            "relaxed arm is not static load"
        );
        last = Some(r);
    }
    let r = last.unwrap();
    assert!(r.muscle_use_arm_wrist.static_hold);
    assert!(r.input.muscle_use_arm_wrist);
}

fn repetitions(per_minute: i64) -> bool {
    let mut t = MuscleUseTracker::new(MuscleUseConfig::default());
    let period = 60 * SEC / per_minute;
    let mut repeated = false;
    let mut stamp = 0;
    while stamp < 120 * SEC {
        // Two seconds reaching out (non-relaxed), the rest relaxed.
        let reaching = stamp % period < 2 * SEC;
        repeated = t.update(stamp, !reaching).unwrap().repeated;
        stamp += FRAME;
    }
    repeated
}

#[test]
fn muscle_use_from_repetitions_four_a_minute() {
    assert!(repetitions(4));
    assert!(repetitions(10));
    assert!(!repetitions(3));
}

/// A posture held out of the relaxed one while the angle wanders back across the relaxed limit for
/// a moment (shorter than the return time) is one excursion: static after a minute, never counted
/// twice. A return that lasts ends it.
#[test]
fn a_moment_back_across_the_relaxed_limit_neither_ends_nor_repeats_an_excursion() {
    let config = MuscleUseConfig::default();
    let mut t = MuscleUseTracker::new(config);
    let blip = config.min_return_nanos / 2;
    let mut most = 0;
    let mut last = None;
    let mut stamp = 0;
    while stamp <= 62 * SEC {
        // Out, and every 5 s back for half the return time.
        let relaxed = stamp % (5 * SEC) >= 4 * SEC && stamp % (5 * SEC) < 4 * SEC + blip;
        let m = t.update(stamp, relaxed).unwrap();
        most = most.max(m.repetitions_in_window);
        last = Some(m);
        stamp += FRAME;
    }
    let held = last.unwrap();
    assert!(held.static_hold, "{held:?}");
    assert_eq!(most, 1);

    // Relaxed for the return time: the excursion is over, and with it the hold.
    let end = stamp + config.min_return_nanos;
    while stamp <= end {
        last = Some(t.update(stamp, true).unwrap());
        stamp += FRAME;
    }
    assert!(!last.unwrap().static_hold);
}

/// Four excursions of 2 s a minute, each interrupted by a moment back: still four.
#[test]
fn repetitions_are_counted_through_a_moment_back() {
    let config = MuscleUseConfig::default();
    let mut t = MuscleUseTracker::new(config);
    let period = 15 * SEC;
    let mut last = None;
    let mut stamp = 0;
    while stamp < 59 * SEC {
        let phase = stamp % period;
        // Out 0–3 s, except a moment back at 1.5 s; relaxed the rest of the period.
        let blip = phase >= 3 * SEC / 2 && phase < 3 * SEC / 2 + config.min_return_nanos / 2;
        let relaxed = phase >= 3 * SEC || blip;
        last = Some(t.update(stamp, relaxed).unwrap());
        stamp += FRAME;
    }
    let m = last.unwrap();
    assert_eq!(m.repetitions_in_window, 4, "{m:?}");
    assert!(m.repeated);
}

#[test]
fn band_edge_noise_is_not_counted_as_repetitions() {
    let mut t = MuscleUseTracker::new(MuscleUseConfig::default());
    let mut last = None;
    for k in 0..600 {
        // Alternates every frame: never back in the relaxed posture for the return time, so one
        // posture held at the limit (one excursion), not sixty repetitions.
        last = Some(t.update(k * FRAME, k % 2 == 0).unwrap());
    }
    let m = last.unwrap();
    assert_eq!(m.repetitions_in_window, 1);
    assert!(!m.repeated);
}

/// "Neck within 20° of upright" is relaxed either way: a head upright within a few degrees, now a
/// little forward, now a little back (as a measured one is), is no muscle use; held 25° back it is.
#[test]
fn a_head_a_few_degrees_back_is_relaxed_for_muscle_use() {
    let mut a =
        RulaAssessor::new(AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap())).unwrap();
    let mut last = None;
    for k in 0..600 {
        // 0.5 s at +4°, 0.5 s at −4°: sixty half-second stays in extension in a minute.
        let deg = if (k / 5) % 2 == 0 { 4.0 } else { -4.0 };
        last = Some(a.assess(&neck_pose(deg, k * FRAME)).unwrap());
    }
    let r = last.unwrap().right.unwrap();
    assert_eq!(
        r.scores.neck_score, 4,
        "the posture score still sees extension"
    );
    assert!(!r.input.muscle_use_neck_trunk_legs);
    assert_eq!(r.muscle_use_neck_trunk_legs.repetitions_in_window, 0);

    let mut a =
        RulaAssessor::new(AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap())).unwrap();
    let mut last = None;
    for k in 0..700 {
        last = Some(a.assess(&neck_pose(-25.0, k * FRAME)).unwrap());
    }
    let r = last.unwrap().right.unwrap();
    assert!(
        r.muscle_use_neck_trunk_legs.static_hold,
        "held back over a minute"
    );
}

fn neck_pose(deg: f64, stamp_nanos: i64) -> Skeleton3 {
    PoseSpec {
        neck_flexion_rad: deg.to_radians(),
        stamp_nanos,
        ..PoseSpec::default()
    }
    .skeleton()
}

fn run_warnings(angles_deg: &[(i64, f64)]) -> Vec<ergocell_ergonomics::WarningEvent> {
    let mut assessor = assessor_for(&PoseSpec::default());
    let mut warnings = WarningTracker::new(WarningConfig::default());
    let mut events = Vec::new();
    for &(stamp, deg) in angles_deg {
        let f: FrameAssessment = assessor.assess(&neck_pose(deg, stamp)).unwrap();
        events.extend(warnings.update(&f));
    }
    events
}

#[test]
fn a_sustained_bent_neck_warns_in_plain_words_after_the_dwell_time() {
    let frames: Vec<(i64, f64)> = (0..50).map(|k| (k * FRAME, 35.0)).collect();
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(neck.len(), 1, "{events:?}");
    let e = neck[0];
    assert_eq!(e.kind, WarningKind::Raised);
    assert_eq!(e.stamp_nanos, 2 * SEC, "after exactly the 2 s dwell");
    assert_eq!(e.region_score, 3);
    assert!(
        e.message
            .starts_with("Neck bent forward 35° — raise the work piece"),
        "{}",
        e.message
    );
    assert!(e.message.contains("action level"), "{}", e.message);
}

#[test]
fn no_flicker_at_a_band_edge() {
    // Raised, then the neck dithers around the 20° edge: the warning stays up.
    let mut frames: Vec<(i64, f64)> = (0..30).map(|k| (k * FRAME, 30.0)).collect();
    frames.extend((30..200).map(|k| (k * FRAME, if k % 2 == 0 { 19.0 } else { 21.0 })));
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(neck.len(), 1, "only the first raise: {neck:?}");

    // Dithering from the start never raises a warning.
    let frames: Vec<(i64, f64)> = (0..200)
        .map(|k| (k * FRAME, if k % 3 == 0 { 19.5 } else { 20.5 }))
        .collect();
    let events = run_warnings(&frames);
    assert!(
        events.iter().all(|e| e.region != BodyRegion::Neck),
        "{events:?}"
    );
}

#[test]
fn a_warning_clears_only_inside_the_margin_and_after_the_dwell() {
    let mut frames: Vec<(i64, f64)> = (0..30).map(|k| (k * FRAME, 30.0)).collect();
    // 17°: below the 20° edge but within the 5° margin → stays.
    frames.extend((30..80).map(|k| (k * FRAME, 17.0)));
    // 12°: 8° inside → clears after 2 s.
    frames.extend((80..130).map(|k| (k * FRAME, 12.0)));
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(neck.len(), 2, "{neck:?}");
    assert_eq!(neck[1].kind, WarningKind::Cleared);
    assert_eq!(neck[1].stamp_nanos, 100 * FRAME);
}

#[test]
fn a_posture_passing_through_a_band_warns_one_dwell_after_the_warning_edge() {
    // 1 s at 15° (score 2), then 30° (score 3): the warning comes 2 s after the 20° edge was
    // crossed, not 2 s for band 2 and 2 s more for band 3.
    let mut frames: Vec<(i64, f64)> = (0..10).map(|k| (k * FRAME, 15.0)).collect();
    frames.extend((10..60).map(|k| (k * FRAME, 30.0)));
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(neck.len(), 1, "{neck:?}");
    assert_eq!(neck[0].kind, WarningKind::Raised);
    assert_eq!(neck[0].region_score, 3);
    assert_eq!(neck[0].stamp_nanos, 10 * FRAME + 2 * SEC);

    // And back: 30° → 2° passes band 2 on its way: cleared one dwell after reaching 2°.
    let mut frames: Vec<(i64, f64)> = (0..40).map(|k| (k * FRAME, 30.0)).collect();
    frames.extend((40..45).map(|k| (k * FRAME, 14.0)));
    frames.extend((45..100).map(|k| (k * FRAME, 2.0)));
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(
        neck.iter().map(|e| e.kind).collect::<Vec<_>>(),
        [WarningKind::Raised, WarningKind::Cleared]
    );
    // 14° is 6° inside the 20° edge (past the 5° margin): the clock for "at most 2" starts at 40.
    assert_eq!(neck[1].stamp_nanos, 40 * FRAME + 2 * SEC);
    assert_eq!(
        neck[1].region_score, 2,
        "below the warning, on its way down"
    );
}

#[test]
fn a_warning_rises_only_past_the_edge_by_the_rise_margin() {
    let neck_events = |deg: f64| {
        let frames: Vec<(i64, f64)> = (0..60).map(|k| (k * FRAME, deg)).collect();
        run_warnings(&frames)
            .into_iter()
            .filter(|e| e.region == BodyRegion::Neck)
            .map(|e| (e.kind, e.region_score))
            .collect::<Vec<_>>()
    };
    let margin = WarningConfig::default().rise_margin_rad.to_degrees();
    assert!((margin - 3.0).abs() < 1e-12);
    // 21°: scored 3, but 1° past the 20° edge: no warning, however long it is held.
    assert_eq!(neck_events(21.0), []);
    assert_eq!(neck_events(24.0), [(WarningKind::Raised, 3)]);
    // The extension band (scored 4 below 0°) alike: 1° back is not warned, 5° back is.
    assert_eq!(neck_events(-1.0), []);
    assert_eq!(neck_events(-5.0), [(WarningKind::Raised, 4)]);
}

/// A yes/no adjustment is a band edge too: a wrist deviated 1° past the 10° threshold scores the
/// +1, but the warning rises on it only once it is the rise margin past.
#[test]
fn a_warning_rises_on_an_adjustment_only_past_its_threshold_by_the_rise_margin() {
    let wrist_events = |deviation_deg: f64| {
        let mut assessor = assessor_for(&PoseSpec::default());
        let mut warnings = WarningTracker::new(WarningConfig::default());
        let mut events = Vec::new();
        let mut scored = Vec::new();
        for k in 0..60 {
            let s = PoseSpec {
                right_arm: ArmPose {
                    flexion_rad: 40f64.to_radians(),
                    elbow_flexion_rad: 90f64.to_radians(),
                    wrist_flexion_rad: 8f64.to_radians(),
                    wrist_deviation_rad: deviation_deg.to_radians(),
                    ..ArmPose::default()
                },
                stamp_nanos: k * FRAME,
                ..PoseSpec::default()
            }
            .skeleton();
            let f = assessor.assess(&s).unwrap();
            scored.push(f.right.as_ref().unwrap().scores.wrist_score);
            events.extend(
                warnings
                    .update(&f)
                    .into_iter()
                    .filter(|e| e.region == BodyRegion::Wrist && e.side == Some(Side::Right))
                    .map(|e| (e.kind, e.region_score)),
            );
        }
        (scored.last().copied(), events)
    };
    // 8° of flexion scores 2; a deviation past 10° adds 1.
    assert_eq!(wrist_events(0.0), (Some(2), vec![]));
    // 11°: scored 3 every frame, never warned however long it is held.
    assert_eq!(wrist_events(11.0), (Some(3), vec![]));
    // 15°: past by more than the 3° margin, warned at 3.
    assert_eq!(
        wrist_events(15.0),
        (Some(3), vec![(WarningKind::Raised, 3)])
    );
}

#[test]
fn session_summary_shares_add_up() {
    let spec = PoseSpec::reaching();
    let mut assessor = assessor_for(&spec);
    let mut summary = SummaryBuilder::new(SEC);
    for k in 0..20 {
        // Relaxed: the neck 5° down, inside RULA's 0–10° band rather than on its 0° edge.
        let relaxed = PoseSpec {
            neck_flexion_rad: 5f64.to_radians(),
            world_rotation: spec.world_rotation,
            world_translation: spec.world_translation,
            ..PoseSpec::default()
        };
        let s = at(if k < 10 { &relaxed } else { &spec }, k * FRAME);
        summary.add(&assessor.assess(&s).unwrap(), None);
    }
    let s = summary.finish();
    assert_eq!(s.frames, 20);
    assert!((s.action_level_share.iter().sum::<f64>() - 1.0).abs() < 1e-9);
    assert!((s.duration_secs - 2.0).abs() < 1e-9);
    for r in &s.regions {
        let total: f64 = r.share_by_score.iter().map(|(_, x)| x).sum();
        assert!((total - 1.0).abs() < 1e-9, "{r:?}");
    }
    // Half the time standing relaxed (grand score 2, level 1), half reaching (grand score 4, level 2).
    assert!(
        (s.action_level_share[0] - 0.5).abs() < 1e-9,
        "{:?}",
        s.action_level_share
    );
    assert!(
        (s.action_level_share[1] - 0.5).abs() < 1e-9,
        "{:?}",
        s.action_level_share
    );
    assert_eq!(s.unscored_share, 0.0);
}

#[test]
fn legs_need_both_feet_down_and_standing_needs_the_hips_over_the_feet() {
    let spec = PoseSpec::default();
    let up = UpVector::new(spec.up()).unwrap();
    let legs = |s: &Skeleton3, seated: bool| {
        let mut config = AssessmentConfig::new(up);
        config.task.seated_well_supported = seated;
        let f = RulaAssessor::new(config).unwrap().assess(s).unwrap();
        f.right.unwrap().scores.legs_score
    };
    let standing = spec.skeleton();
    assert_eq!(legs(&standing, false), 1);

    // Hips 0.4 m behind the ankles (sitting back on a stool).
    let mut back = standing.clone();
    for lm in [Landmark::LeftHip, Landmark::RightHip] {
        let mut e = *back.get(lm).unwrap();
        e.position_m.y -= 0.4;
        back.set(lm, Some(e)).unwrap();
    }
    assert_eq!(
        legs(&back, false),
        2,
        "standing with the weight off the feet"
    );
    assert_eq!(legs(&back, true), 1, "seated: the seat carries the weight");

    // One foot lifted 10 cm.
    let mut lifted = standing.clone();
    for lm in [
        Landmark::LeftAnkle,
        Landmark::LeftHeel,
        Landmark::LeftFootIndex,
    ] {
        let mut e = *lifted.get(lm).unwrap();
        e.position_m.z += 0.10;
        lifted.set(lm, Some(e)).unwrap();
    }
    assert_eq!(legs(&lifted, false), 2);
    assert_eq!(legs(&lifted, true), 2);
}

#[test]
fn an_empty_skeleton_is_unscored_not_safe() {
    let mut assessor = assessor_for(&PoseSpec::default());
    let f = assessor.assess(&Skeleton3::empty(0)).unwrap();
    assert!(f.left.is_none() && f.right.is_none() && f.headline().is_none());
    assert!(!f.unscored_reasons.is_empty());
    let mut warnings = WarningTracker::new(WarningConfig::default());
    assert!(warnings.update(&f).is_empty());
    let mut summary = SummaryBuilder::new(SEC);
    summary.add(&f, None);
    assert_eq!(summary.finish().unscored_share, 1.0);
}

mod arbitrary_skeletons {
    use super::*;
    use ergocell_ergonomics::{HeightConfig, HeightEstimator};
    use ergocell_skeleton::{LandmarkEstimate, LANDMARK_COUNT};
    use nalgebra::Point3;
    use proptest::prelude::*;

    fn arb_skeleton() -> impl Strategy<Value = Skeleton3> {
        proptest::collection::vec(
            proptest::option::of(((-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64), 0.0..=1.0f64)),
            LANDMARK_COUNT,
        )
        .prop_map(|slots| {
            let slots = slots
                .into_iter()
                .map(|s| {
                    s.map(|((x, y, z), c)| LandmarkEstimate {
                        position_m: Point3::new(x, y, z),
                        confidence: c,
                        reprojection_error_px: None,
                        views: 2,
                        position_sd_m: None,
                    })
                })
                .collect();
            Skeleton3::try_from_slots(0, slots).unwrap()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            rng_seed: proptest::test_runner::RngSeed::Fixed(500),
            ..ProptestConfig::default()
        })]

        /// Any skeleton, however implausible or incomplete: no panic, scores in range, and a scored
        /// side always carries the full 1..=7 grand score.
        #[test]
        fn any_skeleton_scores_in_range_or_not_at_all(skeletons in proptest::collection::vec(arb_skeleton(), 1..4)) {
            let up = UpVector::new(Vector3::z()).unwrap();
            let mut assessor = RulaAssessor::new(AssessmentConfig::new(up)).unwrap();
            let mut height = HeightEstimator::new(HeightConfig::new(up));
            let mut warnings = WarningTracker::new(WarningConfig::default());
            for (k, s) in skeletons.iter().enumerate() {
                let mut s = s.clone();
                s.stamp_nanos = k as i64 * FRAME;
                let f = assessor.assess(&s).unwrap();
                for side in [f.left.as_ref(), f.right.as_ref()].into_iter().flatten() {
                    prop_assert!((1..=7).contains(&side.scores.final_score));
                    prop_assert!((1..=4).contains(&side.scores.action_level));
                }
                warnings.update(&f);
                height.push(&s);
            }
            if let Some(e) = height.estimate() {
                prop_assert!(e.height_m.is_finite() && e.uncertainty_m.is_finite());
            }
        }
    }
}

#[test]
fn messages_are_plain_words_with_the_angle_and_the_advice() {
    use ergocell_ergonomics::warnings::describe;
    use ergocell_ergonomics::RulaInput;
    let i = RulaInput {
        upper_arm_flexion_deg: 95.4,
        lower_arm_flexion_deg: 130.0,
        wrist_flexion_deg: -22.0,
        wrist_bent_from_midline: true,
        neck_flexion_deg: -12.0,
        neck_twisted: true,
        trunk_flexion_deg: 45.0,
        ..RulaInput::neutral()
    };
    let cases = [
        (
            BodyRegion::UpperArm,
            Some(Side::Right),
            "Right upper arm raised 95° — lower the work piece or bring it closer",
        ),
        (
            BodyRegion::LowerArm,
            Some(Side::Left),
            "Left elbow at 130° — keep the elbow between 60° and 100°: bring the work closer",
        ),
        (
            BodyRegion::Wrist,
            Some(Side::Right),
            "Right wrist bent 22° and to the side — straighten the wrist: change the grip or the tool angle (wrist scores are the least reliable part of RULA)",
        ),
        (
            BodyRegion::Neck,
            None,
            "Neck bent back 12°, twisted — lower the work piece or bring it in front of you",
        ),
        (
            BodyRegion::Trunk,
            None,
            "Trunk bent forward 45° — raise the work or bring it closer",
        ),
    ];
    for (region, side, want) in cases {
        assert_eq!(describe(region, side, &i), want);
    }
}

mod no_flicker {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 24,
            rng_seed: proptest::test_runner::RngSeed::Fixed(24),
            ..ProptestConfig::default()
        })]
        /// Noise smaller than the hysteresis margin around any steady neck angle: at most one event
        /// (the first raise), never a clear.
        #[test]
        fn noise_within_the_margin_never_flickers(
            base in -30.0..60.0f64,
            noise in proptest::collection::vec(-2.0..2.0f64, 150),
        ) {
            let frames: Vec<(i64, f64)> = noise
                .iter()
                .enumerate()
                .map(|(k, n)| (k as i64 * FRAME, base + n))
                .collect();
            let events = run_warnings(&frames);
            let neck: Vec<_> = events.iter().filter(|e| e.region == BodyRegion::Neck).collect();
            prop_assert!(neck.len() <= 1, "{:?}", neck);
            prop_assert!(neck.iter().all(|e| e.kind == WarningKind::Raised));
        }
    }
}

#[test]
fn an_extension_warning_clears_only_the_margin_past_upright() {
    let mut frames: Vec<(i64, f64)> = (0..30).map(|k| (k * FRAME, -6.0)).collect();
    // +3°: flexed, but within 5° of extension → stays.
    frames.extend((30..80).map(|k| (k * FRAME, 3.0)));
    // +8°: clears after the dwell.
    frames.extend((80..130).map(|k| (k * FRAME, 8.0)));
    let events = run_warnings(&frames);
    let neck: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Neck)
        .collect();
    assert_eq!(neck.len(), 2, "{neck:?}");
    assert_eq!(neck[0].kind, WarningKind::Raised);
    assert_eq!(neck[0].region_score, 4);
    assert!(
        neck[0].message.starts_with("Neck bent back 6°"),
        "{}",
        neck[0].message
    );
    assert_eq!(neck[1].kind, WarningKind::Cleared);
    assert_eq!(neck[1].stamp_nanos, 100 * FRAME);
}

/// A non-relaxed posture held for over a minute is static load even when measurement noise flips
/// one of its angles across a band edge every frame (here the wrist around 15°, and the neck around
/// 20° with the trunk bent): the noise must not restart the hold clock.
#[test]
fn band_edge_noise_does_not_hide_a_posture_held_over_a_minute() {
    let pose = |k: i64| {
        let wobble: f64 = if k % 2 == 0 { -1.0 } else { 1.0 };
        PoseSpec {
            trunk_flexion_rad: 30f64.to_radians(),
            neck_flexion_rad: (20.0 + wobble).to_radians(),
            right_arm: ArmPose {
                flexion_rad: 60f64.to_radians(),
                elbow_flexion_rad: 80f64.to_radians(),
                wrist_flexion_rad: (15.0 + wobble).to_radians(),
                ..ArmPose::default()
            },
            stamp_nanos: k * FRAME,
            ..PoseSpec::default()
        }
    };
    let mut assessor = assessor_for(&pose(0));
    let mut last = None;
    for k in 0..=700 {
        let f = assessor.assess(&pose(k).skeleton()).unwrap();
        let r = f.right.unwrap();
        if k * FRAME < 60 * SEC {
            assert!(!r.input.muscle_use_arm_wrist, "not yet static at frame {k}");
        }
        last = Some(r);
    }
    let r = last.unwrap();
    assert!(
        r.muscle_use_arm_wrist.static_hold,
        "{:?}",
        r.muscle_use_arm_wrist
    );
    assert!(r.input.muscle_use_arm_wrist);
    assert!(
        r.muscle_use_neck_trunk_legs.static_hold,
        "{:?}",
        r.muscle_use_neck_trunk_legs
    );
    assert!(r.input.muscle_use_neck_trunk_legs);
}

fn deviated(wrist_deviation_deg: f64, stamp_nanos: i64) -> Skeleton3 {
    PoseSpec {
        right_arm: ArmPose {
            flexion_rad: 40f64.to_radians(),
            elbow_flexion_rad: 90f64.to_radians(),
            wrist_deviation_rad: wrist_deviation_deg.to_radians(),
            ..ArmPose::default()
        },
        stamp_nanos,
        ..PoseSpec::default()
    }
    .skeleton()
}

/// One frame in five with the wrist 25° off (noise on the hand landmarks) is not a deviated wrist;
/// a deviation held 0.3 s is, and the unsmoothed assessor flags every spike.
#[test]
fn wrist_deviation_is_scored_on_its_median_over_half_a_second() {
    let config = AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap());
    assert_eq!(config.smoothing_window_nanos, 500_000_000);
    let mut smoothed = RulaAssessor::new(config).unwrap();
    let mut raw = RulaAssessor::new(AssessmentConfig {
        smoothing_window_nanos: 0,
        ..config
    })
    .unwrap();
    let (mut flagged_smoothed, mut flagged_raw) = (0, 0);
    for k in 0..50 {
        let deg = if k % 5 == 3 { 25.0 } else { 0.0 };
        let s = deviated(deg, k * FRAME);
        let bent = |f: FrameAssessment| f.right.unwrap().input.wrist_bent_from_midline;
        flagged_smoothed += usize::from(bent(smoothed.assess(&s).unwrap()));
        flagged_raw += usize::from(bent(raw.assess(&s).unwrap()));
    }
    assert_eq!(flagged_raw, 10);
    assert_eq!(flagged_smoothed, 0);
    // A real deviation: scored from the third frame on (the median of five is then the new value).
    let mut first = None;
    for k in 50..70 {
        let deg = if k < 55 { 0.0 } else { 25.0 };
        let f = smoothed.assess(&deviated(deg, k * FRAME)).unwrap();
        if first.is_none() && f.right.unwrap().input.wrist_bent_from_midline {
            first = Some(k - 55);
        }
    }
    assert_eq!(first, Some(2));
}

#[test]
fn the_smoother_passes_through_when_off_and_never_invents_a_value() {
    let a = ergocell_ergonomics::BodyAngles {
        neck_twist_rad: Some(0.3),
        neck_flexion_rad: Some(0.2),
        ..Default::default()
    };
    let mut off = AngleSmoother::new(0);
    assert_eq!(off.push(0, &a), a);
    let mut on = AngleSmoother::new(500_000_000);
    let _ = on.push(0, &a);
    let _ = on.push(FRAME, &a);
    let missing = ergocell_ergonomics::BodyAngles {
        neck_flexion_rad: Some(0.25),
        ..Default::default()
    };
    let out = on.push(2 * FRAME, &missing);
    assert_eq!(
        out.neck_twist_rad, None,
        "not observed this frame stays None"
    );
    assert_eq!(
        out.neck_flexion_rad,
        Some(0.25),
        "neck flexion is not smoothed"
    );
    // Frames older than the window drop out: only the last one is left.
    let twisted = ergocell_ergonomics::BodyAngles {
        neck_twist_rad: Some(-0.1),
        ..Default::default()
    };
    let out = on.push(2 * FRAME + 500_000_000, &twisted);
    assert_eq!(out.neck_twist_rad, Some(-0.1));
    assert!(RulaAssessor::new(AssessmentConfig {
        smoothing_window_nanos: -1,
        ..AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap())
    })
    .is_err());
}

#[test]
fn an_easing_warning_says_it_is_easing_not_the_old_advice() {
    // Trunk bent 70° (score 4) long enough to warn, then straightening through 40° (score 3, 1 s)
    // to 3° (score 2): the warning steps down one level at a time (4 → 3 → cleared), each after the
    // dwell, so the 4 → 3 step comes when the trunk is already at 3°. The step is a "changed" event that must not
    // repeat the advice with the new angle (the demo printed "Trunk bent forward 1° — raise the work").
    let trunk = |deg: f64, stamp_nanos: i64| {
        PoseSpec {
            trunk_flexion_rad: deg.to_radians(),
            stamp_nanos,
            ..PoseSpec::default()
        }
        .skeleton()
    };
    let mut assessor = assessor_for(&PoseSpec::default());
    let mut warnings = WarningTracker::new(WarningConfig::default());
    let mut events = Vec::new();
    for k in 0..200 {
        // Straightening up passes through the 20–60° band (score 3) on the way.
        let deg = match k {
            0..40 => 70.0,
            40..50 => 40.0,
            _ => 3.0,
        };
        let f: FrameAssessment = assessor.assess(&trunk(deg, k * FRAME)).unwrap();
        events.extend(warnings.update(&f));
    }
    let t: Vec<_> = events
        .iter()
        .filter(|e| e.region == BodyRegion::Trunk)
        .collect();
    let kinds: Vec<_> = t.iter().map(|e| e.kind).collect();
    assert_eq!(
        kinds,
        vec![
            WarningKind::Raised,
            WarningKind::Changed,
            WarningKind::Cleared
        ],
        "{t:#?}"
    );
    let changed = &t[1].message;
    assert!(
        changed.starts_with("Trunk easing: now bent forward 3°"),
        "{changed}"
    );
    assert!(!changed.contains("raise the work"), "{changed}");
    assert!(t[0].message.contains("raise the work"), "{}", t[0].message);
}

/// REBA from the tracked skeleton: the same observations as RULA plus the knees, scored through the
/// worksheet (Hignett & McAtamney 2000) by hand for the reaching pose.
#[test]
fn reba_is_scored_beside_rula_from_the_same_frame() {
    // Reaching: trunk 30°, neck 25°, right arm 100° flexed, elbow 20°, wrist 25°; knees 45°.
    let spec = PoseSpec {
        knee_flexion_rad: 45f64.to_radians(),
        ..PoseSpec::reaching()
    };
    let f = assessor_for(&spec).assess(&spec.skeleton()).unwrap();
    let r = f.right.as_ref().unwrap();
    let reba = &r.reba;
    assert!((reba.input.knee_flexion_deg - 45.0).abs() < 1e-6);
    assert_eq!(reba.input.trunk_flexion_deg, r.input.trunk_flexion_deg);
    assert_eq!(
        reba.input.upper_arm_flexion_deg,
        r.input.upper_arm_flexion_deg
    );
    // Group A: trunk 20°–60° → 3; neck > 20° → 2; legs bilateral 1 + knees 30°–60° → 2.
    assert_eq!(reba.scores.trunk_score, 3);
    assert_eq!(reba.scores.neck_score, 2);
    assert_eq!(reba.scores.legs_score, 2);
    // Table A[neck 2][trunk 3][legs 2] = 5, no load.
    assert_eq!(reba.scores.table_a, 5);
    assert_eq!(reba.scores.score_a, 5);
    // Group B: upper arm > 90° → 4; elbow 20° (outside 60°–100°) → 2; wrist 25° → 2.
    assert_eq!(
        (
            reba.scores.upper_arm_score,
            reba.scores.lower_arm_score,
            reba.scores.wrist_score
        ),
        (4, 2, 2)
    );
    // Table B[4][2][2] = 6; Table C[5][6] = 7; no activity in one frame: medium risk.
    assert_eq!(reba.scores.table_b, 6);
    assert_eq!(reba.scores.table_c, 7);
    assert_eq!(reba.scores.reba_score, 7);
    assert_eq!(reba.scores.action_level, 2);
    assert!(!reba.uncertain, "{:?}", reba.uncertain_reasons);

    // Straight knees score legs 1; beyond 60° they add 2.
    for (knee_deg, legs) in [(0.0, 1), (70.0, 3)] {
        let spec = PoseSpec {
            knee_flexion_rad: f64::to_radians(knee_deg),
            ..PoseSpec::reaching()
        };
        let f = assessor_for(&spec).assess(&spec.skeleton()).unwrap();
        assert_eq!(f.right.unwrap().reba.scores.legs_score, legs, "{knee_deg}°");
    }
}

/// A knee the cameras never saw is scored beyond 60° (never as straight) and marks REBA (not RULA)
/// uncertain; a knee seen before is held.
#[test]
fn reba_says_when_the_knees_were_not_seen() {
    let spec = PoseSpec {
        knee_flexion_rad: 45f64.to_radians(),
        ..PoseSpec::default()
    };
    let without_knees = |stamp| {
        let mut s = at(&spec, stamp);
        for lm in [Landmark::LeftKnee, Landmark::RightKnee] {
            s.set(lm, None).unwrap();
        }
        s
    };
    let mut a = assessor_for(&spec);
    let f = a.assess(&without_knees(0)).unwrap();
    let r = f.right.unwrap();
    assert!(
        !r.uncertain,
        "RULA does not use the knees: {:?}",
        r.uncertain_reasons
    );
    assert!(r.reba.uncertain);
    assert!(
        r.reba
            .uncertain_reasons
            .iter()
            .any(|x| x.contains("right_knee_flexion: never observed")),
        "{:?}",
        r.reba.uncertain_reasons
    );
    // Never scored as straight (that would lower the score): beyond 60°, legs 1 + 2.
    assert_eq!(r.reba.input.knee_flexion_deg, 90.0);
    assert_eq!(r.reba.scores.legs_score, 3);

    let mut a = assessor_for(&spec);
    a.assess(&at(&spec, 0)).unwrap();
    let r = a.assess(&without_knees(FRAME)).unwrap().right.unwrap();
    assert!((r.reba.input.knee_flexion_deg - 45.0).abs() < 1e-6, "held");
    assert!(r
        .reba
        .uncertain_reasons
        .iter()
        .any(|x| x.contains("last value held")));
}

#[test]
fn reba_load_from_the_task_config_is_range_checked() {
    let spec = PoseSpec::default();
    let mut config = AssessmentConfig::new(UpVector::new(spec.up()).unwrap());
    config.task.reba_load_kg = 7.0;
    config.task.reba_coupling = ergocell_ergonomics::reba::Coupling::Poor;
    let f = RulaAssessor::new(config)
        .unwrap()
        .assess(&spec.skeleton())
        .unwrap();
    let r = f.right.unwrap();
    assert_eq!(r.reba.scores.load_force_score, 1, "5–10 kg");
    assert_eq!(r.reba.scores.coupling_score, 2);
    for bad in [-1.0, f64::NAN, 2000.0] {
        config.task.reba_load_kg = bad;
        assert!(matches!(
            RulaAssessor::new(config),
            Err(ErgonomicsError::OutOfRange {
                field: "task.reba_load_kg",
                ..
            })
        ));
    }
}

/// REBA scores walking as bilateral (legs 1), though one foot is off the floor; the same raised foot
/// standing still is unilateral (legs 2).
#[test]
fn reba_counts_walking_as_bilateral_weight_bearing() {
    let spec = PoseSpec::default();
    let raise = |mut s: Skeleton3| {
        for lm in [
            Landmark::LeftAnkle,
            Landmark::LeftHeel,
            Landmark::LeftFootIndex,
        ] {
            let mut e = *s.get(lm).unwrap();
            e.position_m += spec.up() * 0.15;
            s.set(lm, Some(e)).unwrap();
        }
        s
    };
    let frame = |k: i64, speed: f64| {
        raise(
            PoseSpec {
                stamp_nanos: k * FRAME,
                world_translation: spec.world_translation
                    + spec.world_rotation * Vector3::x() * speed * (k as f64 * 0.1),
                ..spec.clone()
            }
            .skeleton(),
        )
    };
    for (speed, legs) in [(1.2, 1), (0.0, 2)] {
        let mut a = assessor_for(&spec);
        let mut last = None;
        for k in 0..10 {
            last = Some(a.assess(&frame(k, speed)).unwrap());
        }
        let r = last.unwrap().right.unwrap();
        assert!(
            !r.input.legs_supported_and_balanced,
            "a foot is off the floor"
        );
        assert_eq!(r.reba.scores.legs_score, legs, "{speed} m/s");
    }
}
