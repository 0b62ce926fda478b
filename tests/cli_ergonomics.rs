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
    // The ears stand where the floor-to-ear model puts them on this synthetic body.
    assert!(stdout.contains("floor_to_ear   1.950 m"), "{stdout}");
    assert!(stdout.contains("class: c3"), "{stdout}");

    let (code, _, stderr) = ergocell(&["height", "--landmarks", p, "--up", "0,0,0"]);
    assert_eq!(code, 2, "{stderr}");
}

/// Issue row: `rula track` scored 0 of 100 frames of a recording from a detector without hand points
/// (OpenPose BODY_25B; COCO-17, HALPE-26 and BODY_25 alike), with null sides and no reason. Ten
/// frames of a BODY_25B skeleton (only the BlazePose landmarks its layout fills): every frame and side
/// is scored, the wrist conservatively (RULA wrist score 3), uncertain, and the output says why.
#[test]
fn rula_track_scores_every_frame_of_a_detector_without_hand_points() {
    use ergocell_formats::landmarks_file::{write_landmarks, LandmarksFormat};
    use ergocell_perception::detections::KeypointFormat;
    use ergocell_skeleton::Landmark;

    let kept: Vec<Landmark> = KeypointFormat::Body25B
        .mapping()
        .iter()
        .flatten()
        .copied()
        .collect();
    let spec = PoseSpec {
        neck_flexion_rad: 15f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 50f64.to_radians(),
            elbow_flexion_rad: 80f64.to_radians(),
            ..ArmPose::default()
        },
        ..PoseSpec::default()
    };
    let frames: Vec<_> = (0..10)
        .map(|k| {
            let mut s = PoseSpec {
                stamp_nanos: k * 100_000_000,
                ..spec.clone()
            }
            .skeleton();
            for lm in Landmark::ALL {
                if !kept.contains(&lm) {
                    s.set(lm, None).unwrap();
                }
            }
            s
        })
        .collect();
    let path = tmp("body25b-landmarks.json");
    std::fs::write(
        &path,
        write_landmarks(&frames, LandmarksFormat::Json, "body25b", 10.0),
    )
    .unwrap();
    let p = path.to_str().unwrap();

    let (code, stdout, stderr) =
        ergocell(&["rula", "track", "--json", "--landmarks", p, "--up", "0,0,1"]);
    assert_eq!(code, 0, "{stderr}");
    let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let docs = doc["frames"].as_array().unwrap();
    assert_eq!(docs.len(), 10);
    for (k, f) in docs.iter().enumerate() {
        assert_eq!(f["unscored_reasons"], serde_json::json!([]), "frame {k}");
        for side in ["left", "right"] {
            let s = &f[side];
            assert!(s.is_object(), "frame {k} {side} not scored: {f}");
            assert_eq!(s["uncertain"], true, "frame {k} {side}");
            assert_eq!(s["scores"]["wrist_score"], 3, "frame {k} {side}");
            assert_eq!(s["sources"]["wrist_flexion_deg"], "conservative");
            assert_eq!(s["sources"]["upper_arm_flexion_deg"], "observed");
            let reasons = s["uncertain_reasons"].as_array().unwrap();
            assert!(
                reasons.iter().any(|r| {
                    let r = r.as_str().unwrap();
                    r.contains("wrist scored conservatively as 3")
                        && r.contains(&format!("no {side}_index, {side}_pinky"))
                }),
                "frame {k} {side}: {reasons:?}"
            );
        }
        assert_eq!(f["right"]["scores"]["upper_arm_score"], 3, "frame {k}: 50°");
    }
    assert_eq!(doc["summary"]["scored_frames"], 10);
    assert_eq!(doc["summary"]["unscored_share"], 0.0);
    // Nobody saw the wrists: no wrist warning.
    assert!(
        doc["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .all(|w| w["region"] != "wrist"),
        "{}",
        doc["warnings"]
    );

    // The text output says why too, once while the reasons stay the same.
    let (code, stdout, stderr) = ergocell(&["rula", "track", "--landmarks", p, "--up", "0,0,1"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(!stdout.contains("not scored"), "{stdout}");
    for side in ["left", "right"] {
        let why: Vec<&str> = stdout
            .lines()
            .filter(|l| l.contains(&format!("why {side} uncertain:")))
            .collect();
        assert_eq!(why.len(), 1, "{stdout}");
        assert!(
            why[0].contains("wrist scored conservatively as 3"),
            "{}",
            why[0]
        );
    }
    assert!(stdout.contains("10 frames over"), "{stdout}");
    assert!(stdout.contains("10 scored, 10 uncertain"), "{stdout}");
}

/// `reba score` mirrors `rula score`: one breakdown per worksheet, in order; bad input exits 2 naming
/// the entry and the field.
#[test]
fn reba_score_prints_one_breakdown_per_worksheet_and_refuses_bad_input() {
    use ergocell_ergonomics::reba::{Coupling, RebaInput};
    // Bending to pick a 6 kg part from low down, one knee bent 45°, a fair grip.
    let pick = RebaInput {
        trunk_flexion_deg: 50.0,
        neck_flexion_deg: 25.0,
        knee_flexion_deg: 45.0,
        load_kg: 6.0,
        upper_arm_flexion_deg: 60.0,
        lower_arm_flexion_deg: 40.0,
        wrist_flexion_deg: 20.0,
        coupling: Coupling::Fair,
        activity_repeated: true,
        ..RebaInput::neutral()
    };
    let path = tmp("reba_cases.json");
    std::fs::write(
        &path,
        serde_json::to_string(&[RebaInput::neutral(), pick]).unwrap(),
    )
    .unwrap();
    let (code, stdout, stderr) = ergocell(&["reba", "score", "--input", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), 2);
    assert_eq!(arr[0]["reba_score"], 1);
    assert_eq!(arr[0]["risk"], "negligible");
    // Trunk 3, neck 2, legs 2 → Table A 5, +1 load = 6; upper arm 3, lower arm 2, wrist 2 → Table B
    // 5, +1 coupling = 6; Table C[6][6] = 8, +1 repeated = 9: high, action level 3.
    let p = &arr[1];
    for (key, want) in [
        ("trunk_score", 3),
        ("neck_score", 2),
        ("legs_score", 2),
        ("table_a", 5),
        ("score_a", 6),
        ("upper_arm_score", 3),
        ("lower_arm_score", 2),
        ("wrist_score", 2),
        ("table_b", 5),
        ("score_b", 6),
        ("table_c", 8),
        ("reba_score", 9),
        ("action_level", 3),
    ] {
        assert_eq!(p[key], want, "{key} in {p}");
    }
    assert_eq!(p["risk"], "high");

    let mut bad = serde_json::to_value(RebaInput::neutral()).unwrap();
    bad["coupling"] = serde_json::json!("excellent");
    std::fs::write(&path, serde_json::to_string(&[bad]).unwrap()).unwrap();
    let (code, stdout, stderr) = ergocell(&["reba", "score", "--input", path.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert!(
        stderr.contains("entry 0") && stderr.contains("coupling"),
        "{stderr}"
    );
}

/// `rula track --csv/--summary-csv` (#20): a CSV round trip — every frame's row holds the scores and
/// angles the `--json` breakdown has for that frame; the summary's action-level shares add up to
/// 100 %; an existing file is refused without `--force`, an input always.
#[test]
fn rula_track_csv_round_trips_the_json_breakdown() {
    let spec = PoseSpec {
        neck_flexion_rad: 25f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 95f64.to_radians(),
            elbow_flexion_rad: 40f64.to_radians(),
            ..ArmPose::default()
        },
        ..PoseSpec::default()
    };
    let path = write_recording("csv_recording.json", &spec);
    let p = path.to_str().unwrap();
    let csv_path = tmp("frames.csv");
    let summary_path = tmp("summary.csv");
    let (c, s) = (csv_path.to_str().unwrap(), summary_path.to_str().unwrap());
    let args = [
        "rula",
        "track",
        "--landmarks",
        p,
        "--up",
        "0,0,1",
        "--csv",
        c,
        "--summary-csv",
        s,
        "--force",
    ];
    let (code, _, stderr) = ergocell(&args);
    assert_eq!(code, 0, "{stderr}");
    let (code, stdout, stderr) =
        ergocell(&["rula", "track", "--landmarks", p, "--up", "0,0,1", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let frames = doc["frames"].as_array().unwrap();

    let mut reader = csv::Reader::from_path(&csv_path).unwrap();
    let header: Vec<String> = reader
        .headers()
        .unwrap()
        .iter()
        .map(str::to_owned)
        .collect();
    assert_eq!(header, ergocell_ergonomics::export::frame_header());
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), frames.len());
    for (row, frame) in rows.iter().zip(frames) {
        assert_eq!(row[col("stamp_ns")], frame["stamp_nanos"].to_string());
        for side in ["left", "right"] {
            let f = &frame[side];
            assert_eq!(&row[col(&format!("{side}_scored"))], "1");
            for score in [
                "final_score",
                "action_level",
                "upper_arm_score",
                "neck_score",
                "trunk_score",
            ] {
                assert_eq!(
                    row[col(&format!("{side}_{score}"))],
                    f["scores"][score].to_string(),
                    "{side} {score}"
                );
            }
            for score in [
                "reba_score",
                "action_level",
                "score_a",
                "score_b",
                "legs_score",
            ] {
                assert_eq!(
                    row[col(&format!(
                        "{side}_reba_{}",
                        score.trim_start_matches("reba_")
                    ))],
                    f["reba"]["scores"][score].to_string(),
                    "{side} REBA {score}"
                );
            }
            for angle in [
                "upper_arm_flexion_deg",
                "lower_arm_flexion_deg",
                "neck_flexion_deg",
            ] {
                let csv_value: f64 = row[col(&format!("{side}_{angle}"))].parse().unwrap();
                let json_value = f["input"][angle].as_f64().unwrap();
                assert!(
                    (csv_value - json_value).abs() <= 5e-4,
                    "{side} {angle}: {csv_value} vs {json_value}"
                );
            }
        }
    }
    // The posed right arm (95°) and the neck (25°) are what the rows say.
    let ua: f64 = rows[5][col("right_upper_arm_flexion_deg")].parse().unwrap();
    assert!((ua - 95.0).abs() < 3.0, "{ua}");
    assert_eq!(&rows[5][col("right_upper_arm_score")], "4");
    assert!(rows.iter().any(|r| r[col("warnings")].contains("raised")));

    let mut summary = csv::Reader::from_path(&summary_path).unwrap();
    let rows: Vec<csv::StringRecord> = summary.records().map(Result::unwrap).collect();
    let level_total: f64 = rows
        .iter()
        .filter(|r| &r[0] == "action_level_share" && r[6].is_empty())
        .map(|r| r[4].parse::<f64>().unwrap())
        .sum();
    assert!((level_total - 100.0).abs() < 0.01, "{level_total}");
    assert!(rows
        .iter()
        .any(|r| &r[0] == "warnings_raised" && &r[2] == "neck" && &r[4] != "0"));

    // No overwrite without --force; never onto an input, --force or not.
    let (code, _, stderr) = ergocell(&args[..args.len() - 1]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("already exists"), "{stderr}");
    let (code, _, stderr) = ergocell(&[
        "rula",
        "track",
        "--landmarks",
        p,
        "--up",
        "0,0,1",
        "--csv",
        p,
        "--force",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("is also an input"), "{stderr}");
}

/// `height calibrate`: five people of known stature whose ear landmarks sit 15 mm above the
/// tragion; the offset is measured and written into a copy of the cell file (its comments kept),
/// which then reads back with it; bad sessions are refused with the reason and leave the file as
/// it was.
#[test]
fn height_calibrate_measures_the_ear_offset_and_writes_it_into_the_cell_file() {
    use ergocell_skeleton::Landmark;
    let mut sessions = Vec::new();
    for stature in [1.58, 1.66, 1.73, 1.80, 1.91] {
        let spec = PoseSpec {
            stature_m: stature,
            ..PoseSpec::default()
        };
        let skeletons: Vec<_> = (0..40)
            .map(|k| {
                let mut s = PoseSpec {
                    stamp_nanos: k * 100_000_000,
                    ..spec.clone()
                }
                .skeleton();
                for lm in [Landmark::LeftEar, Landmark::RightEar] {
                    let mut e = *s.get(lm).unwrap();
                    e.position_m += spec.up() * 0.015;
                    s.set(lm, Some(e)).unwrap();
                }
                s
            })
            .collect();
        let path = tmp(&format!("calibration-{stature}.json"));
        std::fs::write(&path, serde_json::to_string(&skeletons).unwrap()).unwrap();
        sessions.push(format!("{}={stature}", path.display()));
    }
    let shipped = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("config/cell.toml");
    let cell = tmp("calibrated-cell.toml");
    std::fs::copy(&shipped, &cell).unwrap();
    let up = format!(
        "{},{},{}",
        PoseSpec::default().up().x,
        PoseSpec::default().up().y,
        PoseSpec::default().up().z
    );
    let mut args = vec![
        "height",
        "calibrate",
        "--config",
        cell.to_str().unwrap(),
        "--up",
        &up,
    ];
    for s in &sessions {
        args.extend(["--session", s.as_str()]);
    }
    let (code, stdout, stderr) = ergocell(&args);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("from 5 sessions"), "{stdout}");
    let text = std::fs::read_to_string(&cell).unwrap();
    let table: toml::Table = toml::from_str(&text).unwrap();
    let offset = table["height"]["ear_offset_m"].as_float().unwrap();
    assert!((offset - 0.015).abs() < 0.002, "{offset}");
    assert_eq!(table["height"]["ear_offset_sessions"].as_integer(), Some(5));
    // The shipped file's comments are kept; the result reads back as a cell configuration.
    let shipped_text = std::fs::read_to_string(&shipped).unwrap();
    assert!(text.starts_with(&shipped_text[..200]));
    ergocell_cell::CellSettings::from_toml_str(&text, "calibrated").unwrap();

    // Four sessions, a stature in centimetres, a file with nobody upright: refused, file untouched.
    let before = std::fs::read_to_string(&cell).unwrap();
    let mut four = vec![
        "height",
        "calibrate",
        "--config",
        cell.to_str().unwrap(),
        "--up",
        &up,
    ];
    for s in &sessions[..4] {
        four.extend(["--session", s.as_str()]);
    }
    let (code, _, stderr) = ergocell(&four);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("at least 5"), "{stderr}");
    let cm = sessions[0].replace("=1.58", "=158");
    let (code, _, stderr) = ergocell(&[
        "height",
        "calibrate",
        "--config",
        cell.to_str().unwrap(),
        "--session",
        &cm,
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("centimetres"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&cell).unwrap(), before);
}

/// `rula track --fixed-lag-s`: a neck read alternately 5° and 25° (a jittering detector around a
/// steady 15°) scores 1 and 3 frame by frame; on the mean over ±0.5 s it scores what the operator
/// held, 2. The window is said in the output.
#[test]
fn rula_track_fixed_lag_scores_the_held_posture_not_the_jitter() {
    let skeletons: Vec<_> = (0..40)
        .map(|k| {
            PoseSpec {
                stamp_nanos: k * 100_000_000,
                neck_flexion_rad: if k % 2 == 0 { 5f64 } else { 25f64 }.to_radians(),
                ..PoseSpec::default()
            }
            .skeleton()
        })
        .collect();
    let path = tmp("neck-jitter.json");
    std::fs::write(&path, serde_json::to_string(&skeletons).unwrap()).unwrap();
    let p = path.to_str().unwrap();
    let neck_scores = |extra: &[&str]| {
        let mut args = vec!["rula", "track", "--json", "--landmarks", p, "--up", "0,0,1"];
        args.extend_from_slice(extra);
        let (code, stdout, stderr) = ergocell(&args);
        assert_eq!(code, 0, "{stderr}");
        let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        let scores: Vec<u64> = doc["frames"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["right"]["scores"]["neck_score"].as_u64().unwrap())
            .collect();
        (scores, doc["fixed_lag"].clone())
    };
    let (raw, lag) = neck_scores(&[]);
    assert_eq!(lag, serde_json::Value::Null);
    assert!(raw.iter().all(|s| *s == 1 || *s == 3), "{raw:?}");
    let (smoothed, lag) = neck_scores(&["--fixed-lag-s", "0.5"]);
    assert_eq!(lag["half_window_s"], 0.5, "{lag}");
    assert_eq!(smoothed.len(), 40, "every frame scored");
    assert!(smoothed.iter().all(|s| *s == 2), "{smoothed:?}");

    let with_lag = |seconds: &str| {
        ergocell(&[
            "rula",
            "track",
            "--landmarks",
            p,
            "--up",
            "0,0,1",
            "--fixed-lag-s",
            seconds,
        ])
    };
    let (code, stdout, stderr) = with_lag("0.5");
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("over ±0.5 s of each frame"), "{stdout}");
    for bad in ["0", "nan", "61"] {
        let (code, _, stderr) = with_lag(bad);
        assert_eq!(code, 2, "--fixed-lag-s {bad}: {stderr}");
        assert!(stderr.contains("--fixed-lag-s"), "{stderr}");
    }
}
