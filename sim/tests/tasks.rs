//! The station's tasks in the twin: each task of the shipped mix takes the body region it is for
//! past that region's warning band in the truth's own RULA, the session's timeline holds every task
//! once in order, and the warnings measured on such sessions are reproducible.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_cell::PipelineConfig;
use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor, UpVector, WarningConfig};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::CameraRig;
use ergocell_sim::experiments::{Handovers, Setup};
use ergocell_sim::tasks::{TaskKind, TaskMix};
use ergocell_sim::warning_trust::warning_trust;
use ergocell_sim::{
    DetectorNoise, Operator, Phase, SessionScript, SimConfig, Simulation, TaskStage, Tick,
};
use nalgebra::{Point3, Vector3};

fn reference_rig() -> CameraRig {
    parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

fn session(mix: &TaskMix, seed: u64, stature_m: f64) -> Vec<Tick> {
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = mix.handovers;
    Simulation::with_tasks(
        reference_rig(),
        Operator::new(stature_m).unwrap(),
        script,
        SimConfig::new(seed),
        mix.draw(seed),
    )
    .unwrap()
    .collect::<Result<Vec<_>, _>>()
    .unwrap()
}

/// The region each task is for.
fn region_of(kind: TaskKind) -> BodyRegion {
    match kind {
        TaskKind::LowBin | TaskKind::SideTable => BodyRegion::Trunk,
        TaskKind::HighShelf | TaskKind::LongReach => BodyRegion::UpperArm,
        TaskKind::ReadLabel => BodyRegion::Neck,
        TaskKind::Fastening => BodyRegion::Wrist,
        TaskKind::Kneel => BodyRegion::Legs,
    }
}

#[test]
fn every_task_takes_its_region_into_the_warning_band_in_the_truth() {
    let mix = TaskMix::default_mix().unwrap();
    let warn_at = WarningConfig::default().warn_at;
    let up = UpVector::new(Vector3::z()).unwrap();
    for (seed, stature) in [(1, 1.55), (2, 1.75), (3, 1.95)] {
        let ticks = session(&mix, seed, stature);
        let mut truth = RulaAssessor::new(AssessmentConfig {
            smoothing_window_nanos: 0,
            ..AssessmentConfig::new(up)
        })
        .unwrap();
        let mut seen = std::collections::BTreeSet::new();
        for t in &ticks {
            let a = truth.assess(&t.truth.skeleton).unwrap();
            let Phase::Task {
                kind,
                stage: TaskStage::Hold,
                ..
            } = t.truth.phase
            else {
                continue;
            };
            let region = region_of(kind);
            let ri = BodyRegion::ALL.iter().position(|r| *r == region).unwrap();
            let score = [a.left.as_ref(), a.right.as_ref()]
                .into_iter()
                .flatten()
                .map(|s| region.score(&s.scores))
                .max()
                .unwrap();
            assert!(
                score >= warn_at[ri],
                "{kind:?} at {stature} m, seed {seed}: {region:?} scores {score}, warns at {}",
                warn_at[ri]
            );
            seen.insert(kind);
        }
        assert_eq!(seen.len(), TaskKind::ALL.len(), "every task held");
    }
}

#[test]
fn the_timeline_holds_each_task_once_between_the_handovers() {
    let mix = TaskMix::default_mix().unwrap();
    let ticks = session(&mix, 7, 1.75);
    let drawn = mix.draw(7);
    // Each task occurrence appears as one contiguous stretch, in the drawn order.
    let mut order: Vec<usize> = Vec::new();
    for t in &ticks {
        if let Phase::Task { index, .. } = t.truth.phase {
            if order.last() != Some(&index) {
                order.push(index);
            }
        }
    }
    assert_eq!(order, (0..drawn.len()).collect::<Vec<_>>());
    // Every handover cycle is still there, and the session ends walking out.
    let cycles: std::collections::BTreeSet<usize> = ticks
        .iter()
        .filter_map(|t| match t.truth.phase {
            Phase::Hold { cycle } => Some(cycle),
            _ => None,
        })
        .collect();
    assert_eq!(cycles.len(), mix.handovers);
    let expected_s = 4.0
        + 4.0
        + 4.0
        + mix.handovers as f64 * 5.0
        + drawn
            .iter()
            .map(ergocell_sim::tasks::TaskOccurrence::duration_secs)
            .sum::<f64>();
    let last = ticks.last().unwrap();
    assert!((last.truth.stamp_nanos as f64 * 1e-9 - expected_s).abs() <= 0.1);
    assert_eq!(last.truth.phase, Phase::WalkOut);
    // The same seed, the same session.
    assert_eq!(session(&mix, 7, 1.75)[200].frame, ticks[200].frame);
}

#[test]
fn the_warnings_of_a_task_session_are_measured_and_reproducible() {
    let mix = TaskMix::from_toml_str(
        "handovers = 1\n[task.read_label]\ncount = 2\n[task.fastening]\ncount = 1\n",
    )
    .unwrap();
    let setup = Setup {
        rig: reference_rig(),
        noise: DetectorNoise::default(),
        seed: 5,
    };
    let p = Point3::new(0.41, -0.10, 1.055);
    let handovers = Handovers {
        before_m: p,
        c1_m: p,
        c2_m: p,
        c3_m: p,
        c1_stature_m: [1.4, 1.7],
        c2_stature_m: [1.68, 1.82],
        c3_stature_m: [1.8, 2.1],
        c1_served_m: [1.4, 1.7],
        c2_served_m: [1.68, 1.82],
        c3_served_m: [1.8, 2.1],
    };
    let config = PipelineConfig::new(UpVector::new(Vector3::z()).unwrap());
    let run = || {
        warning_trust(
            &setup,
            &handovers,
            &[1.70],
            &mix,
            &config,
            0,
            &mut |_, _| {},
        )
        .unwrap()
    };
    let w = run();
    // (NaN ≠ NaN: compared as the JSON they are written as.)
    let json = |w: &ergocell_sim::warning_trust::WarningTrust| serde_json::to_string(w).unwrap();
    assert_eq!(json(&w), json(&run()));
    let neck = &w.regions[BodyRegion::ALL
        .iter()
        .position(|r| *r == BodyRegion::Neck)
        .unwrap()];
    // Two labels read at 24–40° for 4–7 s each: two clear neck stretches, both warned.
    assert_eq!(neck.clear, 2, "{neck:?}");
    assert_eq!(neck.clear_caught, 2);
    assert_eq!(neck.latencies_s.len(), 2);
    // Warned after the dwell and the fixed lag have passed, never before.
    let dwell_and_lag = 2.0 + config.fixed_lag_s.unwrap_or(0.0);
    for l in &neck.latencies_s {
        assert!(*l >= dwell_and_lag - 0.25, "{l}");
    }
    assert_eq!(w.tasks.get("read_label"), Some(&2));
    assert!(w.frames > 0);
}
