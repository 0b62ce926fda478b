//! The height experiment on measured people (ANSUR II): everyone served, the calibration round trip.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_formats::rig_file::parse_rig;
use ergocell_sim::experiments::{height, Handovers, HeightOptions, Setup};
use ergocell_sim::DetectorNoise;
use nalgebra::Point3;

fn handovers() -> Handovers {
    Handovers {
        before_m: Point3::new(0.41, -0.10, 1.055),
        c1_m: Point3::new(0.394, -0.10, 0.963),
        c2_m: Point3::new(0.425, -0.10, 1.08),
        c3_m: Point3::new(0.478, -0.10, 1.169),
        c1_stature_m: [1.50, 1.68],
        c2_stature_m: [1.68, 1.82],
        c3_stature_m: [1.82, 2.00],
        c1_served_m: [1.44, 1.74],
        c2_served_m: [1.62, 1.88],
        c3_served_m: [1.76, 2.06],
    }
}

fn setup(seed: u64, ear_offset_m: f64) -> Setup {
    Setup {
        rig: parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
            .unwrap()
            .0,
        noise: DetectorNoise {
            ear_offset_m,
            ..DetectorNoise::default()
        },
        seed,
    }
}

/// A detector that puts the ear landmark 15 mm above the tragion: 5 calibration sessions learn the
/// offset, and the operators are then measured as well as with no offset at all (the same people
/// and noise: only the offset differs).
#[test]
fn an_injected_ear_offset_is_learned_and_removed() {
    let people = ergocell_anthropometry::ansur::people().unwrap();
    let options = HeightOptions {
        count: 6,
        idle_secs: 6.0,
        calibration_sessions: 5,
        rula: None,
        decision_sigmas: None,
    };
    let mut none = |_: usize, _: usize| {};
    let clean = height(&setup(7, 0.0), &handovers(), &people, &options, &mut none).unwrap();
    let biased = height(&setup(7, 0.015), &handovers(), &people, &options, &mut none).unwrap();
    let learned = biased.calibration.offset_m - clean.calibration.offset_m;
    assert!((learned - 0.015).abs() < 0.002, "{learned}");
    assert!(
        (biased.mae_m - clean.mae_m).abs() < 0.002,
        "MAE {} with the offset, {} without",
        biased.mae_m,
        clean.mae_m
    );
    // Every operator is served, each within their class's served statures.
    for r in [&clean, &biased] {
        assert_eq!(r.undecided, 0, "{r:?}");
        for o in &r.operators {
            let class = o.decided_class.unwrap();
            let [lo, hi] = handovers().served().unwrap().of(class);
            assert!((lo..=hi).contains(&o.true_m), "{o:?}");
        }
    }
    // Uncalibrated, the same offset reads every operator tall.
    let uncalibrated = height(
        &setup(7, 0.015),
        &handovers(),
        &people,
        &HeightOptions {
            calibration_sessions: 0,
            ..options
        },
        &mut none,
    )
    .unwrap();
    let bias: f64 = uncalibrated
        .operators
        .iter()
        .map(|o| o.estimated_m.unwrap() - o.true_m)
        .sum::<f64>()
        / uncalibrated.operators.len() as f64;
    assert!(bias > 0.008, "uncalibrated bias {bias}");
}
