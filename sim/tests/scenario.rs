//! The simulator against the perception crate's camera model, its determinism and its script.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::{CameraRig, FusionEngine, FusionMethod};
use ergocell_sim::{DetectorNoise, Operator, Phase, SessionScript, SimConfig, Simulation, Tick};
use ergocell_skeleton::Landmark;
use nalgebra::Point3;

fn reference_rig() -> CameraRig {
    parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

fn c2_handover() -> Point3<f64> {
    Point3::new(0.41, -0.10, 1.055)
}

fn run(seed: u64, noise: &DetectorNoise, stature_m: f64, cycles: usize) -> Vec<Tick> {
    let mut script = SessionScript::new(c2_handover());
    script.cycles = cycles;
    let config = SimConfig {
        noise: *noise,
        ..SimConfig::new(seed)
    };
    Simulation::new(
        reference_rig(),
        Operator::new(stature_m).unwrap(),
        script,
        config,
    )
    .unwrap()
    .collect::<Result<Vec<_>, _>>()
    .unwrap()
}

#[test]
fn noiseless_detections_are_the_perception_camera_projections() {
    let rig = reference_rig();
    let ticks = run(7, &DetectorNoise::none(), 1.72, 1);
    let mut checked = 0;
    for tick in &ticks {
        for view in &tick.frame.views {
            assert_eq!(view.stamp_nanos, tick.truth.stamp_nanos);
            let cam = rig.camera(view.camera).unwrap();
            for lm in Landmark::ALL {
                if let Some(k) = view.get(lm) {
                    let truth = tick.truth.skeleton.position(lm).unwrap();
                    let px = cam.project(&truth).unwrap();
                    assert!((k.pixel() - px).norm() < 1e-9, "{lm} in {}", cam.id);
                    assert!(cam.in_image(&k.pixel()));
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 10_000, "only {checked} keypoints checked");
}

#[test]
fn noiseless_views_triangulate_back_to_the_truth() {
    let ticks = run(3, &DetectorNoise::none(), 1.85, 1);
    let mut engine = FusionEngine::new(reference_rig(), FusionMethod::Default).unwrap();
    let idle = ticks.iter().find(|t| t.truth.phase == Phase::Idle).unwrap();
    let fused = engine.fuse(&idle.frame).unwrap();
    for lm in Landmark::ALL {
        let truth = idle.truth.skeleton.position(lm).unwrap();
        let est = fused.skeleton.position(lm).unwrap();
        assert!((est - truth).norm() < 1e-4, "{lm}: {est:?} vs {truth:?}");
    }
}

#[test]
fn same_seed_same_ticks_other_seed_other_noise() {
    let a = run(11, &DetectorNoise::default(), 1.66, 2);
    let b = run(11, &DetectorNoise::default(), 1.66, 2);
    let c = run(12, &DetectorNoise::default(), 1.66, 2);
    assert_eq!(a, b);
    assert_eq!(a.len(), c.len());
    assert_ne!(a, c);
}

#[test]
fn the_script_walks_in_measures_hands_over_and_walks_out() {
    let ticks = run(5, &DetectorNoise::default(), 1.80, 3);
    let phases: Vec<Phase> = ticks.iter().map(|t| t.truth.phase).collect();
    assert_eq!(phases[0], Phase::WalkIn);
    assert!(phases.contains(&Phase::Idle));
    for cycle in 0..3 {
        assert!(phases.contains(&Phase::Hold { cycle }));
    }
    assert!(phases.contains(&Phase::WalkOut));
    assert!(!phases.contains(&Phase::Hold { cycle: 3 }));
    // ticks are 100 ms apart, starting at 0
    for (k, t) in ticks.iter().enumerate() {
        assert_eq!(t.truth.stamp_nanos, k as i64 * 100_000_000);
        assert_eq!(t.frame.stamp_nanos, t.truth.stamp_nanos);
        for v in &t.frame.views {
            assert!((v.stamp_nanos - t.frame.stamp_nanos).abs() <= 9_000_000);
        }
    }
    // while holding, the grasp point is at the cycle's target
    let op = Operator::new(1.80).unwrap();
    for t in ticks
        .iter()
        .filter(|t| matches!(t.truth.phase, Phase::Hold { .. }))
    {
        let target = t.truth.target_m.unwrap();
        assert!((op.grasp_point(&t.truth.posture) - target).norm() < 0.01);
        assert!((target - c2_handover()).norm() < 0.06);
    }
    // the stature is the operator's
    assert!(ticks.iter().all(|t| t.truth.stature_m == 1.80));
}

#[test]
fn pixel_noise_has_the_configured_spread_and_drops_their_rate() {
    let noise = DetectorNoise {
        pixel_sigma_px: 2.5,
        outlier_probability: 0.0,
        occluded_report_probability: 0.0,
        stamp_jitter_sigma_nanos: 0.0,
        drop_probability: 0.25,
        ..DetectorNoise::default()
    };
    let rig = reference_rig();
    let ticks = run(9, &noise, 1.75, 2);
    let (mut sum_sq, mut n, mut dropped, mut views) = (0.0, 0usize, 0usize, 0usize);
    for tick in &ticks {
        dropped += tick.dropped.len();
        views += tick.frame.views.len();
        for view in &tick.frame.views {
            let cam = rig.camera(view.camera).unwrap();
            for lm in Landmark::ALL {
                if let Some(k) = view.get(lm) {
                    let px = cam
                        .project(&tick.truth.skeleton.position(lm).unwrap())
                        .unwrap();
                    sum_sq += (k.pixel() - px).norm_squared();
                    n += 1;
                }
            }
        }
    }
    let sigma = (sum_sq / (2.0 * n as f64)).sqrt();
    assert!((sigma - 2.5).abs() < 0.1, "measured sigma {sigma}");
    let rate = dropped as f64 / (dropped + views) as f64;
    assert!((rate - 0.25).abs() < 0.03, "drop rate {rate}");
}

#[test]
fn the_camera_behind_the_operator_sees_fewer_landmarks_than_a_front_one() {
    // S3 (cameras 4, 5) stands behind-left of the operator: the torso and head hide landmarks.
    let noise = DetectorNoise {
        occluded_report_probability: 0.0,
        ..DetectorNoise::none()
    };
    let ticks = run(1, &noise, 1.75, 1);
    let idle = ticks.iter().find(|t| t.truth.phase == Phase::Idle).unwrap();
    let count = |cam: usize| {
        idle.frame
            .views
            .iter()
            .find(|v| v.camera == cam)
            .unwrap()
            .observed_count()
    };
    assert!(count(0) > count(4), "{} vs {}", count(0), count(4));
}

fn handovers() -> ergocell_sim::experiments::Handovers {
    ergocell_sim::experiments::Handovers {
        before_m: c2_handover(),
        // trajectories/c1..c3.toml (station frame = world frame in these tests); before: the point
        // set for a 1.75 m operator (`--before-handover`'s default)
        c1_m: Point3::new(0.394, -0.10, 0.963),
        c2_m: Point3::new(0.410, -0.10, 1.080),
        c3_m: Point3::new(0.478, -0.10, 1.169),
        c1_stature_m: [1.50, 1.68],
        c2_stature_m: [1.68, 1.82],
        c3_stature_m: [1.82, 2.00],
        c1_served_m: [1.44, 1.74],
        c2_served_m: [1.62, 1.88],
        c3_served_m: [1.76, 2.06],
    }
}

fn setup(seed: u64) -> ergocell_sim::experiments::Setup {
    ergocell_sim::experiments::Setup {
        rig: reference_rig(),
        noise: DetectorNoise::default(),
        seed,
    }
}

#[test]
fn same_seed_gives_byte_identical_experiment_json() {
    use ergocell_sim::experiments::{height, rula_agreement, table1};
    let json = |seed: u64| {
        let mut none = |_: usize, _: usize| {};
        let t = table1(&setup(seed), &handovers(), &[1.6, 1.9], 1, &mut none).unwrap();
        let people = ergocell_anthropometry::ansur::people().unwrap();
        let options = ergocell_sim::experiments::HeightOptions {
            count: 2,
            idle_secs: 3.0,
            calibration_sessions: 0,
            rula: None,
            decision_sigmas: None,
        };
        let h = height(&setup(seed), &handovers(), &people, &options, &mut none).unwrap();
        let r = rula_agreement(&setup(seed), &handovers(), &[1.7], 1, &mut none).unwrap();
        format!(
            "{}{}{}",
            serde_json::to_string(&t).unwrap(),
            serde_json::to_string(&h).unwrap(),
            serde_json::to_string(&r).unwrap()
        )
    };
    let a = json(4);
    assert_eq!(a, json(4));
    assert_ne!(a, json(5));
}

#[test]
fn default_fusion_beats_every_single_pair_on_the_twin() {
    // The goal for Table 1, as a regression test on a short run.
    let mut none = |_: usize, _: usize| {};
    let t = ergocell_sim::experiments::table1(&setup(2), &handovers(), &[1.6, 1.8], 2, &mut none)
        .unwrap();
    assert_eq!(t.landmarks.len(), 12);
    assert_eq!(t.rmse_m.len(), 5);
    assert_eq!(t.wins("default_fusion", &t.best_pair()), 12);
    assert_eq!(t.wins("default_fusion", &t.rmse_m["paper_fusion"]), 12);
}

#[test]
fn the_solved_hold_posture_reaches_every_class_handover_for_every_stature() {
    // Property over the adaptation grid: every stature reaches its class's handover within 1 cm.
    let thresholds = ergocell_ergonomics::height::ClassThresholds::default();
    for h in ergocell_sim::experiments::adaptation_heights() {
        let class = ergocell_ergonomics::HeightClass::of(h, &thresholds);
        let target = handovers().for_class(class);
        let op = Operator::new(h).unwrap();
        let sol = ergocell_sim::solve_reach(
            &op,
            &ergocell_sim::Posture::default(),
            &target,
            &ergocell_sim::ReachConfig::default(),
        )
        .unwrap();
        assert!(sol.miss_m < 0.01, "{h} m misses by {} m", sol.miss_m);
    }
}

/// After adaptation an operator outside the statures their class's trajectory is served for is not
/// served — the session ends without moving the robot — and the experiment says so instead of a
/// score. The rule is the session's: 1.45 m lies below c1's own statures (1.50–1.68 m) but inside
/// those its trajectory is served for, and is served.
#[test]
fn adaptation_reports_operators_outside_the_served_statures_as_not_served() {
    let mut none = |_: usize, _: usize| {};
    let r = ergocell_sim::experiments::adaptation(
        &setup(1),
        &handovers(),
        &[1.40, 1.45, 1.60, 2.05, 2.10],
        ergocell_sim::experiments::AdaptationBodies::Proportions,
        1,
        &mut none,
    )
    .unwrap();
    let range = |[lo, hi]: [f64; 2]| format!("{lo:.2}–{hi:.2}");
    let h = handovers();
    assert!(r.not_served_after[0]
        .as_ref()
        .unwrap()
        .contains(&range(h.c1_served_m)));
    assert!(r.not_served_after[4]
        .as_ref()
        .unwrap()
        .contains(&range(h.c3_served_m)));
    for i in [0, 4] {
        assert!(r.mean_grand_score_after[i].is_nan());
        assert!(r.true_mean_grand_score_after[i].is_nan());
        assert!(r.mean_grand_score_before[i].is_finite(), "before is scored");
    }
    for i in [1, 2, 3] {
        assert!(r.not_served_after[i].is_none(), "{i}");
        assert!(r.mean_grand_score_after[i].is_finite());
    }
    let json = serde_json::to_value(&r).unwrap();
    assert!(json["mean_grand_score_after"][0].is_null());
    // The posture cost is the grand score plus a mean fraction in [0, 1): its mean over the same
    // frames lies in [mean grand, mean grand + 1).
    for i in 0..r.heights_m.len() {
        let pairs = [
            (
                r.true_mean_posture_cost_before[i],
                r.true_mean_grand_score_before[i],
            ),
            (r.mean_posture_cost_before[i], r.mean_grand_score_before[i]),
        ];
        for (cost, grand) in pairs {
            assert!(
                cost >= grand && cost < grand + 1.0,
                "{i}: {cost} vs {grand}"
            );
        }
    }
    // The goal judges each seed alone: a cost made worse after adaptation fails it.
    let cost_goal = |r: &ergocell_sim::experiments::Adaptation| {
        let s = ergocell_sim::seeds::adaptation(&[1], std::slice::from_ref(r));
        s.goals.last().unwrap().holds_on
    };
    let mut worse = r.clone();
    worse.true_mean_posture_cost_after[2] = worse.true_mean_posture_cost_before[2] + 0.01;
    assert_eq!(cost_goal(&worse), 0);
    let mut better = r.clone();
    for i in [1, 2, 3] {
        better.true_mean_posture_cost_after[i] = better.true_mean_posture_cost_before[i] - 0.01;
    }
    assert_eq!(cost_goal(&better), 1);
    // A served stature with no cost before cannot be judged: it fails.
    better.true_mean_posture_cost_before[2] = f64::NAN;
    assert_eq!(cost_goal(&better), 0);
}

/// The cell may decide a neighbouring class near a boundary: the simulated operator then reaches
/// where the robot brings the part. Cycles not begun move by exactly the shift (each keeping its own
/// drawn variation), a cycle already begun keeps its target, the rest of the session is unchanged.
#[test]
fn retargeting_moves_the_cycles_not_yet_begun_by_the_shift() {
    let make = || {
        let mut script = SessionScript::new(c2_handover());
        script.cycles = 3;
        Simulation::new(
            reference_rig(),
            Operator::new(1.69).unwrap(),
            script,
            SimConfig::new(11),
        )
        .unwrap()
    };
    let base = make();
    let shift = nalgebra::Vector3::new(0.0, 0.02, -0.05);
    let sc = *base.script();
    let cycle_nanos = ((sc.reach_secs + sc.hold_secs + sc.return_secs + sc.rest_secs) * 1e9) as i64;
    let first_nanos = ((sc.walk_in_secs + sc.idle_secs) * 1e9) as i64;
    // During the first cycle's reach: cycles 1 and 2 move, cycle 0 keeps its target.
    let mut moved = make();
    let n = moved
        .retarget_handover(c2_handover() + shift, first_nanos + 1_000_000)
        .unwrap();
    assert_eq!(n, 2);
    let hold = |sim: &Simulation, cycle: i64| {
        let t =
            first_nanos + cycle * cycle_nanos + ((sc.reach_secs + 0.5 * sc.hold_secs) * 1e9) as i64;
        let (phase, _, target) = sim.posture_at(t);
        assert!(matches!(phase, Phase::Hold { .. }), "{phase:?}");
        target.unwrap()
    };
    assert_eq!(hold(&base, 0), hold(&moved, 0));
    for c in 1..3 {
        let d = hold(&moved, c) - hold(&base, c);
        assert!((d - shift).norm() < 1e-12, "cycle {c}: moved by {d:?}");
    }
    // The hand reaches the moved point: its pose differs from the base's at the hold.
    let t = first_nanos + cycle_nanos + ((sc.reach_secs + 0.5 * sc.hold_secs) * 1e9) as i64;
    assert_ne!(base.posture_at(t).1, moved.posture_at(t).1);
    // Before the first reach everything moves; a non-finite point is refused.
    let mut all = make();
    assert_eq!(all.retarget_handover(c2_handover() + shift, 0).unwrap(), 3);
    assert_eq!(all.script().handover_m, c2_handover() + shift);
    assert!(all
        .retarget_handover(Point3::new(f64::NAN, 0.0, 1.0), 0)
        .is_err());
}

/// The controller with a fixed lag scores the tracked frames of the causal path (the smoother
/// changes where landmarks are, not which frames are tracked; at most the last half second before
/// the recording stops is not released), says it was used, and on the default detector agrees with
/// the truth at least as well on this operator (the centred window has no lag).
#[test]
fn the_fixed_lag_smoother_scores_the_same_frames_and_says_so() {
    use ergocell_sim::experiments::{rula_agreement, rula_agreement_with};
    let mut none = |_: usize, _: usize| {};
    let live =
        rula_agreement_with(&setup(3), &handovers(), &[1.7], 1, Some(0.0), &mut none).unwrap();
    let lagged =
        rula_agreement_with(&setup(3), &handovers(), &[1.7], 1, Some(0.5), &mut none).unwrap();
    // the controller's default is the fixed lag
    let default = rula_agreement(&setup(3), &handovers(), &[1.7], 1, &mut none).unwrap();
    assert_eq!(default.fixed_lag_s, Some(0.55));
    assert_eq!(live.fixed_lag_s, None);
    assert_eq!(lagged.fixed_lag_s, Some(0.5));
    assert!(
        lagged.frames <= live.frames && lagged.frames + 6 >= live.frames,
        "{} of {}",
        lagged.frames,
        live.frames
    );
    assert!(lagged.frames > 50, "{}", lagged.frames);
    assert!(
        lagged.grand_score.exact >= live.grand_score.exact,
        "fixed lag {} < causal {}",
        lagged.grand_score.exact,
        live.grand_score.exact
    );
}

/// The controller with a fixed lag of 0.5 s: each tracked frame is scored once a frame more than
/// 0.5 s later has been fused (never sooner, at most a frame or two later), in time order, while the
/// operator and the height come at once: the same decision in the same frame as without the lag.
#[test]
fn with_a_fixed_lag_each_frame_comes_out_half_a_window_late_and_the_height_is_the_same() {
    use ergocell_cell::{Pipeline, PipelineConfig};
    let ticks = run(5, &DetectorNoise::default(), 1.74, 1);
    let up = ergocell_ergonomics::UpVector::z();
    let mut decisions = Vec::new();
    for lag in [None, Some(0.5)] {
        let mut config = PipelineConfig::new(up);
        config.fixed_lag_s = lag;
        let mut p = Pipeline::new(reference_rig(), config).unwrap();
        let (mut released, mut last, mut classes) = (0, i64::MIN, Vec::new());
        for tick in &ticks {
            for output in p.push_views(tick.frame.stamp_nanos, tick.frame.views.clone()) {
                let output = output.unwrap();
                // the operator and the height at once, whatever the lag
                assert_eq!(
                    output.operator.as_ref().map(|o| o.stamp_nanos),
                    output.operator.as_ref().map(|_| output.stamp_nanos)
                );
                classes.extend(
                    output
                        .height
                        .as_ref()
                        .map(|d| (output.stamp_nanos, d.class, d.estimate.height_m)),
                );
                for t in &output.tracked {
                    let late = output.stamp_nanos - t.skeleton.stamp_nanos;
                    match lag {
                        None => assert_eq!(late, 0),
                        Some(_) => assert!(
                            late > 500_000_000 && late < 800_000_000,
                            "released {late} ns late"
                        ),
                    }
                    assert!(t.skeleton.stamp_nanos > last, "out of order");
                    last = t.skeleton.stamp_nanos;
                    assert!(t.assessment.is_ok());
                    released += 1;
                }
            }
        }
        assert!(released > 100, "{released}");
        assert_eq!(classes.len(), 1, "{classes:?}");
        decisions.push(classes[0]);
    }
    assert_eq!(decisions[0], decisions[1]);
}

/// Views that reach the cell 80 ms after their capture (the edge's inference and the network) do
/// not delay the scores: on a clock ticking every 10 ms, a frame is scored within a tick of its
/// lag, in time order, and as many frames are scored as on time. Views 250 ms late are scored at
/// 650 ms: no more than the window's newest 100 ms is left out. (A frame the assembly completed
/// late, waiting for a view, is due 400 ms after it was completed.)
#[test]
fn with_a_fixed_lag_on_the_clock_late_views_do_not_delay_the_scores() {
    use ergocell_cell::{Pipeline, PipelineConfig};
    const MS: i64 = 1_000_000;
    let ticks = run(5, &DetectorNoise::default(), 1.74, 1);
    let mut config = PipelineConfig::new(ergocell_ergonomics::UpVector::z());
    config.fixed_lag_s = Some(0.5);
    let mut counts = Vec::new();
    for (delay, due) in [(0, 500 * MS), (80 * MS, 500 * MS), (250 * MS, 650 * MS)] {
        let mut p = Pipeline::new(reference_rig(), config.clone()).unwrap();
        let (mut scored, mut last) = (Vec::new(), i64::MIN);
        let (mut completed, mut on_time) = (std::collections::BTreeMap::new(), 0);
        let (start, end) = (
            ticks[0].frame.stamp_nanos,
            ticks.last().unwrap().frame.stamp_nanos,
        );
        let mut next = 0;
        for now in (start..end).step_by(10 * MS as usize) {
            let mut tracked = Vec::new();
            // a frame's views, once the last of them has been captured and has come
            let arrives =
                |t: &Tick| t.frame.views.iter().map(|v| v.stamp_nanos).max().unwrap() + delay;
            while next < ticks.len() && arrives(&ticks[next]) <= now {
                for output in p.push_views(now, ticks[next].frame.views.clone()) {
                    let output = output.unwrap();
                    completed.insert(output.stamp_nanos, now);
                    tracked.extend(output.tracked);
                }
                next += 1;
            }
            tracked.extend(p.release_due(now));
            for t in tracked {
                let stamp = t.skeleton.stamp_nanos;
                let after = now - stamp;
                // never before the lag; on the clock within a tick of when it is due (a later
                // frame completing the window may release it sooner)
                let due_here = due.max(completed[&stamp] - stamp + 400 * MS);
                assert!(
                    after > due && after <= due_here + 10 * MS,
                    "{delay}: scored {after} ns after capture"
                );
                // within 30 ms: a tick for the views' arrival and one for the release, and the
                // spread of a frame's view stamps (the last view completes it)
                on_time += usize::from(after <= due + 30 * MS);
                assert!(t.skeleton.stamp_nanos > last, "out of order");
                last = t.skeleton.stamp_nanos;
                assert!(t.assessment.is_ok());
                scored.push(t.skeleton.stamp_nanos);
            }
        }
        // the rest are frames the assembly completed late, waiting out a view that never came
        assert!(
            on_time * 100 >= scored.len() * 85,
            "{delay}: {on_time} of {} within 30 ms of {due}",
            scored.len()
        );
        counts.push(scored.len());
    }
    assert!(counts[0] > 100, "{counts:?}");
    assert_eq!(counts[0], counts[1], "{counts:?}");
    // the frames of the last 150 ms before the end are not yet due at 650 ms
    assert!(
        counts[2] <= counts[0] && counts[2] + 2 >= counts[0],
        "{counts:?}"
    );
}

/// A script placed at a station carries the operator's place, heading, entry and floor pick with
/// the station; at the world's own station (the identity) nothing moves, bit for bit.
#[test]
fn a_script_placed_at_a_station_moves_with_it() {
    use ergocell_sim::FloorPick;
    use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
    let mut script = SessionScript::new(c2_handover());
    script.floor_pick = Some(FloorPick::new(1));
    let mut same = script;
    same.place_at_station(&Isometry3::identity());
    assert_eq!(same, script);
    let yaw = 0.3;
    let t = Isometry3::from_parts(
        Translation3::new(0.12, 0.16, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), yaw),
    );
    let mut moved = script;
    moved.place_at_station(&t);
    let on_floor = |xy: [f64; 2]| {
        let p = t * Point3::new(xy[0], xy[1], 0.0);
        [p.x, p.y]
    };
    let close = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < 1e-12;
    assert!(
        close(moved.station_m, [0.12, 0.16]),
        "{:?}",
        moved.station_m
    );
    assert!(close(moved.entry_m, on_floor(script.entry_m)));
    assert!((moved.station_heading_rad - yaw).abs() < 1e-12);
    let pick = |s: &SessionScript| s.floor_pick.unwrap().target_m;
    assert!((pick(&moved) - t * pick(&script)).norm() < 1e-12);
    // The handover point is the world's already.
    assert_eq!(moved.handover_m, script.handover_m);
}
