//! A bystander some cameras follow instead of the operator (issue 17): with the cell's operator gate
//! (`[pipeline] operator_gate_radius_m`), the operator is still the one fused and the bystander does
//! not flip the height class. The twin's operator, 1.60 m (c1, 8 cm inside its band), stands at the
//! station from the start; the bystander, 1.95 m (c3), stands still 1.2 m beside it, and the
//! single-person detector of one camera, or of one stereo pair's two, follows them throughout.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_cell::{CellSettings, Pipeline};
use ergocell_ergonomics::UpVector;
use ergocell_ergonomics::{HeightClass, HeightStatus};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::CameraRig;
use ergocell_sim::{Bystander, Operator, SessionScript, SimConfig, Simulation};
use ergocell_skeleton::Landmark;
use nalgebra::Point3;

fn reference_rig() -> CameraRig {
    parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

/// One session's outcome: the decided class (if any), and over the tracked frames the share whose
/// fused mid-hip is within 0.10 m of the operator's true one, and the largest distance.
struct Outcome {
    class: Option<HeightClass>,
    near_share: f64,
    worst_m: f64,
    tracked: usize,
}

/// The cell's pipeline as `config/cell.toml` sets it (the operator gate on), or with the gate off.
fn pipeline(rig: CameraRig, gate: bool) -> Pipeline {
    let settings =
        CellSettings::from_toml_str(include_str!("../../config/cell.toml"), "config/cell.toml")
            .unwrap();
    let mut config = settings.pipeline(UpVector::z()).unwrap();
    assert!(config.reconstruction.operator_zone.is_some());
    if !gate {
        config.reconstruction.operator_zone = None;
    }
    Pipeline::new(rig, config).unwrap()
}

fn session(seed: u64, cameras: u64, gate: bool) -> Outcome {
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = 1;
    // the operator is at the station from the start, the bystander too
    script.walk_in_secs = 0.0;
    let config = SimConfig {
        bystander: (cameras != 0).then(|| Bystander {
            person: Operator::new(1.95).unwrap(),
            position_m: [0.0, 1.2],
            heading_rad: 0.0,
            cameras,
            from_nanos: 0,
        }),
        ..SimConfig::new(seed)
    };
    let rig = reference_rig();
    let ticks: Vec<_> = Simulation::new(rig.clone(), Operator::new(1.60).unwrap(), script, config)
        .unwrap()
        .collect::<Result<_, _>>()
        .unwrap();
    let mid_hip = |s: &ergocell_skeleton::Skeleton3| {
        Some(nalgebra::center(
            &s.position(Landmark::LeftHip)?,
            &s.position(Landmark::RightHip)?,
        ))
    };
    let (mut near, mut tracked, mut worst) = (0usize, 0usize, 0.0f64);
    let mut p = pipeline(rig, gate);
    for (i, tick) in ticks.iter().enumerate() {
        for output in p.push_views(tick.frame.stamp_nanos, tick.frame.views.clone()) {
            let output = output.unwrap();
            // the operator as fused in this frame (RULA's smoothed frames come later)
            if let Some(operator) = &output.operator {
                // frames are released at most a few ticks late: compare with the nearest truth
                let j = (0..=i)
                    .rev()
                    .take(5)
                    .min_by_key(|&j| (ticks[j].frame.stamp_nanos - operator.stamp_nanos).abs())
                    .unwrap_or(i);
                let (Some(fused), Some(truth)) =
                    (mid_hip(operator), mid_hip(&ticks[j].truth.skeleton))
                else {
                    continue;
                };
                let d = (fused - truth).norm();
                tracked += 1;
                near += usize::from(d < 0.10);
                worst = worst.max(d);
            }
        }
    }
    let pipeline = p;
    Outcome {
        class: match pipeline.height_status() {
            HeightStatus::Decided(d) => Some(d.class),
            HeightStatus::Measuring { .. } => None,
        },
        near_share: near as f64 / tracked.max(1) as f64,
        worst_m: worst,
        tracked,
    }
}

#[test]
fn a_bystander_seen_by_one_stereo_pair_is_not_fused_and_does_not_flip_the_class() {
    let rig = reference_rig();
    let pair = |name: &str| {
        let p = rig.pairs().iter().find(|p| p.name == name).unwrap();
        (1u64 << p.left) | (1u64 << p.right)
    };
    // ERGOCELL_BYSTANDER_ALL=1 also prints the gate off and two pairs of three on the bystander
    // (what `docs/measurements.md` reports; two pairs is not asserted: see there)
    let all = std::env::var_os("ERGOCELL_BYSTANDER_ALL").is_some();
    let mut cases = vec![
        ("one camera", 1u64 << rig.pairs()[0].left, true),
        ("one pair", pair("S1"), true),
    ];
    if all {
        cases.extend([
            ("nobody", 0, false),
            ("one pair", pair("S1"), false),
            ("two pairs", pair("S1") | pair("S2"), false),
            ("two pairs", pair("S1") | pair("S2"), true),
        ]);
    }
    for (what, cameras, gate) in cases {
        for seed in 1..=6 {
            let o = session(seed, cameras, gate);
            eprintln!(
                "{what}, gate {gate}, seed {seed}: class {:?}, {} tracked frames, mid-hip within 0.10 m of the operator in {:.1} %, worst {:.3} m",
                o.class,
                o.tracked,
                100.0 * o.near_share,
                o.worst_m
            );
            if gate && what == "two pairs" {
                // Most cameras on the bystander: the fused person may be the bystander or a ghost;
                // the height is then not measured off the station, so the class is the operator's
                // or undecided (the robot does not move) — never the bystander's.
                assert!(
                    matches!(o.class, None | Some(HeightClass::C1)),
                    "{what}, seed {seed}: {:?}",
                    o.class
                );
            }
            if gate && what != "two pairs" {
                assert_eq!(o.class, Some(HeightClass::C1), "{what}, seed {seed}");
                assert!(
                    o.tracked > 100,
                    "{what}, seed {seed}: {} tracked",
                    o.tracked
                );
                // All but a few frames (4 of 112 at worst, seed 6, as the gate first locks on).
                assert!(o.near_share > 0.95, "{what}, seed {seed}: {}", o.near_share);
                assert!(o.worst_m < 0.4, "{what}, seed {seed}: {}", o.worst_m);
            }
        }
    }
}
