//! The `rula score`, `rula track` and `height` commands end to end: output format, exit codes.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

use ergocell_ergonomics::pose::{ArmPose, PoseSpec};
use ergocell_ergonomics::RulaInput;

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

fn ergocell(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn rula_score_prints_one_breakdown_per_worksheet_in_order() {
    let reaching = RulaInput {
        upper_arm_flexion_deg: 95.0,
        neck_flexion_deg: -3.0,
        ..RulaInput::neutral()
    };
    let path = tmp("cases.json");
    std::fs::write(
        &path,
        serde_json::to_string(&[RulaInput::neutral(), reaching]).unwrap(),
    )
    .unwrap();
    let (code, stdout, stderr) = ergocell(&["rula", "score", "--input", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), 2);
    assert_eq!(arr[0]["final_score"], 1);
    assert_eq!(arr[1]["upper_arm_score"], 4);
    assert_eq!(arr[1]["neck_score"], 4);
    assert_eq!(arr[1].as_object().unwrap().len(), 13);
}

#[test]
fn rula_score_rejects_malformed_input_with_exit_code_2() {
    let mut bad = serde_json::to_value(RulaInput::neutral()).unwrap();
    bad["lower_arm_flexion_deg"] = serde_json::json!(true);
    let path = tmp("bad_cases.json");
    let good = serde_json::to_value(RulaInput::neutral()).unwrap();
    std::fs::write(&path, serde_json::to_string(&[good, bad]).unwrap()).unwrap();
    let (code, stdout, stderr) = ergocell(&["rula", "score", "--input", path.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert!(
        stderr.contains("entry 1") && stderr.contains("lower_arm_flexion_deg"),
        "{stderr}"
    );
}

/// 30 frames of `spec`, then 30 with the head up, at 10 Hz.
fn write_recording(name: &str, spec: &PoseSpec) -> PathBuf {
    let skeletons: Vec<_> = (0..60)
        .map(|k| {
            PoseSpec {
                stamp_nanos: k * 100_000_000,
                neck_flexion_rad: if k < 30 { spec.neck_flexion_rad } else { 0.0 },
                ..spec.clone()
            }
            .skeleton()
        })
        .collect();
    let path = tmp(name);
    std::fs::write(&path, serde_json::to_string(&skeletons).unwrap()).unwrap();
    path
}

#[test]
fn rula_track_and_height_on_a_synthetic_recording() {
    // A y-up world: the commands must be told.
    let spec = PoseSpec {
        stature_m: 1.95,
        neck_flexion_rad: 30f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 50f64.to_radians(),
            elbow_flexion_rad: 80f64.to_radians(),
            ..ArmPose::default()
        },
        world_rotation: nalgebra::Rotation3::from_axis_angle(
            &nalgebra::Vector3::x_axis(),
            -std::f64::consts::FRAC_PI_2,
        ),
        ..PoseSpec::default()
    };
    let path = write_recording("recording.json", &spec);
    let p = path.to_str().unwrap();
    let (code, stdout, stderr) = ergocell(&["rula", "track", "--landmarks", p, "--up", "0,1,0"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("Neck bent forward 30° — raise the work piece"),
        "{stdout}"
    );
    assert!(stdout.contains("time share per action level"), "{stdout}");

    // The JSON breakdown says which inputs were observed and which configured.
    let (code, stdout, stderr) =
        ergocell(&["rula", "track", "--landmarks", p, "--up", "0,1,0", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let right = &doc["frames"][0]["right"];
    assert_eq!(right["sources"]["upper_arm_flexion_deg"], "observed");
    assert_eq!(right["sources"]["force_load_score_arm_wrist"], "configured");
    assert_eq!(right["sources"]["wrist_twist"], "configured");
    assert_eq!(right["sources"]["muscle_use_arm_wrist"], "time_series");
    assert!(right["input"]["upper_arm_flexion_deg"].as_f64().unwrap() > 45.0);
    assert_eq!(right["scores"]["upper_arm_score"], 3);

    let (code, stdout, stderr) = ergocell(&["height", "--landmarks", p, "--up", "0,1,0"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("stature: 1.950"), "{stdout}");
    assert!(stdout.contains("class: c3"), "{stdout}");

    let (code, _, stderr) = ergocell(&["height", "--landmarks", p, "--up", "0,0,0"]);
    assert_eq!(code, 2, "{stderr}");
}
