//! A camera knocked out of its calibration mid-session is found by its reprojection residuals,
//! left out of fusion and reported (issue #18's "camera bumped"): on the twin, over many seeds and
//! bump sizes, and never on calibrated cameras — the twin's nor caliscope's real 4-camera recording.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_cell::pipeline::{Reconstruction, ReconstructionConfig};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::CameraRig;
use ergocell_sim::{CameraBump, Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

fn reference_rig() -> CameraRig {
    parse_rig(include_str!("../config/rig.toml"), "config/rig.toml")
        .unwrap()
        .0
}

/// The seeds reported: 6..=11 by default (a debug build runs a twin session in about 2 s), or
/// `ERGOCELL_BUMP_SEEDS=A..B`; `docs/measurements.md`'s figures are `ERGOCELL_BUMP_SEEDS=6..25 cargo test --release
/// --test bumped_camera`. Seeds 1..=5 were used for tuning and are never reported.
fn reported_seeds() -> std::ops::RangeInclusive<u64> {
    let Ok(text) = std::env::var("ERGOCELL_BUMP_SEEDS") else {
        return 6..=11;
    };
    let (a, b) = text.split_once("..").expect("ERGOCELL_BUMP_SEEDS=A..B");
    let (a, b): (u64, u64) = (a.parse().unwrap(), b.parse().unwrap());
    assert!(a >= 6, "seeds 1..=5 were used for tuning");
    a..=b
}

/// Runs a twin session (two handover cycles) through the reconstruction stage — with a bump, until
/// 8 s after it — and returns when each camera was found out of calibration (seconds after the
/// start) and its residuals.
fn session(seed: u64, bump: Option<CameraBump>) -> Vec<(usize, f64, f64, f64)> {
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = 2;
    let config = SimConfig {
        bump,
        ..SimConfig::new(seed)
    };
    let rig = reference_rig();
    let sim = Simulation::new(rig.clone(), Operator::new(1.75).unwrap(), script, config).unwrap();
    let mut r = Reconstruction::new(rig, ReconstructionConfig::default()).unwrap();
    let mut found = Vec::new();
    for tick in sim {
        let tick = tick.unwrap();
        if bump.is_some_and(|b| tick.frame.stamp_nanos > b.from_nanos + 8_000_000_000) {
            break;
        }
        let out = r.process_frame(&tick.frame).unwrap();
        if let Some(o) = out.out_of_calibration {
            found.push((
                o.camera,
                tick.frame.stamp_nanos as f64 * 1e-9,
                o.residual_px,
                o.others_px,
            ));
        }
    }
    found
}

const BUMP_AT_NANOS: i64 = 12_000_000_000;

fn bump(seed: u64, deg: f64, tilt: bool) -> CameraBump {
    let angle = deg.to_radians();
    CameraBump {
        camera: (seed as usize * 7 + usize::from(tilt)) % 6,
        from_nanos: BUMP_AT_NANOS,
        rotation_rad: if tilt {
            [angle, 0.0, 0.0]
        } else {
            [0.0, angle, 0.0]
        },
    }
}

/// Tuned (the monitor's defaults) on seeds 1..=5 with pans; reported on [`reported_seeds`], pans and
/// tilts of 1°, 1.5° and 2°: every bump is found, on the bumped camera, within 5 s, and nothing else
/// is flagged (measured on seeds 6..=25: 120 of 120, median 1.0 s, the slowest 3.6 s).
#[test]
fn a_bumped_camera_is_found_within_seconds_on_every_seed() {
    let mut delays = Vec::new();
    for seed in reported_seeds() {
        for deg in [1.0, 1.5, 2.0] {
            for tilt in [false, true] {
                let b = bump(seed, deg, tilt);
                let found = session(seed, Some(b));
                assert_eq!(
                    found.len(),
                    1,
                    "seed {seed}, {deg}°, tilt {tilt}: {found:?}"
                );
                let (camera, t, residual, others) = found[0];
                assert_eq!(camera, b.camera, "seed {seed}, {deg}°: the wrong camera");
                let delay = t - BUMP_AT_NANOS as f64 * 1e-9;
                assert!(
                    (0.0..=5.0).contains(&delay),
                    "seed {seed}, {deg}°, tilt {tilt}: found {delay:.1} s after the bump"
                );
                assert!(residual > 2.0 * others);
                delays.push(delay);
            }
        }
    }
    delays.sort_by(f64::total_cmp);
    eprintln!(
        "{} bumps found; delay after the bump: median {:.1} s, slowest {:.1} s",
        delays.len(),
        delays[delays.len() / 2],
        delays[delays.len() - 1]
    );
}

/// Calibrated cameras are never flagged: whole twin sessions without a bump (20 of 20 on seeds 6..=25).
#[test]
fn calibrated_twin_cameras_are_never_flagged() {
    for seed in reported_seeds() {
        assert_eq!(session(seed, None), vec![], "seed {seed}");
    }
}

/// caliscope's real recording (4 cameras, calibrated by caliscope, MediaPipe detections): no camera
/// is flagged, through the same reconstruction stage.
#[test]
fn no_camera_of_a_real_calibrated_recording_is_flagged() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let dir =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/caliscope-4cam");
    let text = std::fs::read_to_string(dir.join("config.toml")).unwrap();
    let (rig, _) = parse_rig(&text, "config.toml").unwrap();
    let xy = std::fs::read_to_string(dir.join("xy_pose33.csv")).unwrap();
    let mut stats = ergocell_perception::detections::ImportStats::default();
    let frames =
        ergocell_formats::import::parse_caliscope_xy(&xy, "xy_pose33.csv", &rig, &mut stats)
            .unwrap();
    assert!(frames.len() > 100);
    let mut r = Reconstruction::new(rig, ReconstructionConfig::default()).unwrap();
    let mut judged = 0;
    for frame in &frames {
        let out = r.process_frame(frame).unwrap();
        assert_eq!(out.out_of_calibration, None);
        judged += 1;
    }
    eprintln!("caliscope: {judged} frames, no camera flagged");
}
