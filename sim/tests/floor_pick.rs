//! The optional floor pick: a bad-posture episode solved by the reach optimisation, and a script
//! without it unchanged.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_ergonomics::angles::body_angles;
use ergocell_ergonomics::UpVector;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::CameraRig;
use ergocell_sim::{
    DetectorNoise, FloorPick, Operator, Phase, PickStage, SessionScript, SimConfig, Simulation,
    Tick,
};
use nalgebra::{Point3, Vector3};

fn reference_rig() -> CameraRig {
    parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

fn sim(floor_pick: Option<FloorPick>, cycles: usize) -> Simulation {
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = cycles;
    script.floor_pick = floor_pick;
    let config = SimConfig {
        noise: DetectorNoise::default(),
        ..SimConfig::new(42)
    };
    Simulation::new(
        reference_rig(),
        Operator::new(1.75).unwrap(),
        script,
        config,
    )
    .unwrap()
}

fn ticks(s: Simulation) -> Vec<Tick> {
    s.collect::<Result<Vec<_>, _>>().unwrap()
}

fn hold(t: &Tick) -> bool {
    t.truth.phase
        == Phase::FloorPick {
            stage: PickStage::Hold,
        }
}

#[test]
fn the_floor_pick_bends_the_trunk_past_60_degrees_while_holding() {
    let pick = FloorPick::new(1);
    let s = sim(Some(pick), 3);
    let all = ticks(s.clone());
    let held: Vec<&Tick> = all.iter().filter(|t| hold(t)).collect();
    // 4 s at 10 Hz
    assert!(held.len() >= 39, "{} hold ticks", held.len());
    let up = UpVector::new(Vector3::z()).unwrap();
    let op = Operator::new(1.75).unwrap();
    for t in &held {
        let posture_deg = t.truth.posture.trunk_flexion_rad.to_degrees();
        let measured_deg = body_angles(&t.truth.skeleton, &up, Some(0.0))
            .trunk_flexion_rad
            .unwrap()
            .to_degrees();
        assert!(posture_deg > 60.0, "trunk flexion {posture_deg:.1}°");
        assert!(
            measured_deg > 60.0,
            "trunk flexion from the landmarks {measured_deg:.1}°"
        );
        assert_eq!(t.truth.target_m, Some(pick.target_m));
        // solved, not scripted: the hand is at the part
        let miss = (op.grasp_point(&t.truth.posture) - pick.target_m).norm();
        assert!(miss < 0.01, "missed the part by {miss} m");
    }
    // after the first cycle, before the second; the robot's cycles all still happen
    let first = all
        .iter()
        .position(|t| matches!(t.truth.phase, Phase::FloorPick { .. }));
    let first = first.unwrap();
    assert!(matches!(
        all[first - 1].truth.phase,
        Phase::Rest { cycle: 0 }
    ));
    let last = all
        .iter()
        .rposition(|t| matches!(t.truth.phase, Phase::FloorPick { .. }))
        .unwrap();
    assert!(matches!(
        all[last + 1].truth.phase,
        Phase::Reach { cycle: 1 }
    ));
    for cycle in 0..3 {
        assert!(all.iter().any(|t| t.truth.phase == Phase::Hold { cycle }));
    }
    // back to the resting posture: the first rest after the pick is the rest before it
    let rest_before = all[first - 1].truth.posture;
    let rest_after = all
        .iter()
        .find(|t| t.truth.phase == Phase::Rest { cycle: 1 })
        .unwrap()
        .truth
        .posture;
    assert_eq!(rest_before, rest_after);
    // same seed, same session
    assert_eq!(all, ticks(sim(Some(pick), 3)));
}

#[test]
fn without_a_floor_pick_the_session_is_unchanged_and_with_one_only_shifted() {
    let plain = sim(None, 2);
    let pick = FloorPick::new(1);
    let picking = sim(Some(pick), 2);
    let (a, b) = (ticks(plain.clone()), ticks(picking.clone()));
    // the default script has no pick and no pick phase
    assert_eq!(SessionScript::new(Point3::origin()).floor_pick, None);
    assert!(a
        .iter()
        .all(|t| !matches!(t.truth.phase, Phase::FloorPick { .. })));
    // 4 s walk in + 4 s idle + 2 × 5 s cycles + 4 s walk out, 10 Hz, both ends
    assert_eq!(a.len(), 221);
    assert_eq!(b.len(), a.len() + 70);
    // before the pick (walk in, idle, cycle 0) the sessions are identical tick for tick, noise too
    let from = b
        .iter()
        .position(|t| matches!(t.truth.phase, Phase::FloorPick { .. }))
        .unwrap();
    assert_eq!(from, 130);
    assert_eq!(a[..from], b[..from]);
    // after it the motion is the same, 7 s later
    let shift = 7_000_000_000;
    let op = plain.operator();
    for t in &a[from..] {
        let s = t.truth.stamp_nanos;
        let (phase_a, posture_a, target_a) = plain.posture_at(s);
        let (phase_b, posture_b, target_b) = picking.posture_at(s + shift);
        assert_eq!(phase_a, phase_b, "at {s} ns");
        assert_eq!(target_a, target_b, "at {s} ns");
        // the same up to rounding (the clock's seconds are 7 s larger)
        let (pa, pb) = (op.landmarks(&posture_a), op.landmarks(&posture_b));
        for (x, y) in pa.iter().zip(pb.iter()) {
            assert!((x - y).norm() < 1e-9, "at {s} ns: {x:?} vs {y:?}");
        }
    }
    // the pick is validated
    let bad = [
        FloorPick::new(3),
        FloorPick {
            hold_secs: f64::NAN,
            ..FloorPick::new(2)
        },
    ];
    for pick in bad {
        let mut script = *picking.script();
        script.floor_pick = Some(pick);
        assert!(Simulation::new(
            reference_rig(),
            Operator::new(1.75).unwrap(),
            script,
            SimConfig::new(1)
        )
        .is_err());
    }
}
