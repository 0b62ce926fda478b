//! One recording, one set of numbers: `ergocell report` (the offline review's per-region rows) and
//! `ergocell rula track` (its summary) report the same time shares per body-region score and per
//! grand score, the worse side's action level (with its exposure over time) and each side's REBA
//! score, because both are `ergocell_ergonomics::summary`.
//!
//! The recording is a synthetic operator (`ergonomics::pose`) whose frame rate changes (10 Hz, then
//! 30 Hz while reaching, so frame counts and time disagree), with a 3 s gap (no frames: not counted)
//! and unscored frames at the start (nothing seen yet). The same skeletons go to `rula track` as a
//! landmark file and, assessed as a session assesses them, into an MCAP recording (operator pose +
//! RULA and REBA states, the session's messages) for `report`.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

use ergocell::messages::{ergonomic_message, operator_pose_message, reba_message};
use ergocell::recording::{topics, McapRecorder};
use ergocell_ergonomics::pose::{ArmPose, PoseSpec};
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor, UpVector};
use ergocell_skeleton::Skeleton3;
use nalgebra::Vector3;

const MS: i64 = 1_000_000;

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

fn ergocell(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap()
}

/// The skeletons: 3 empty frames, 2 s relaxed at 10 Hz, 1 s reaching at 30 Hz (right arm up 60°,
/// neck bent 25°), a 3 s gap, 1 s with the left arm up 100° and the neck bent 35° at 10 Hz.
fn skeletons() -> Vec<Skeleton3> {
    let relaxed = PoseSpec::default();
    let reaching = PoseSpec {
        neck_flexion_rad: 25f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 60f64.to_radians(),
            elbow_flexion_rad: 50f64.to_radians(),
            ..ArmPose::default()
        },
        ..PoseSpec::default()
    };
    let overhead = PoseSpec {
        neck_flexion_rad: 35f64.to_radians(),
        left_arm: ArmPose {
            flexion_rad: 100f64.to_radians(),
            elbow_flexion_rad: 30f64.to_radians(),
            ..ArmPose::default()
        },
        ..PoseSpec::default()
    };
    let mut t = 1_000 * MS;
    let mut out = Vec::new();
    let mut push = |spec: Option<&PoseSpec>, n: usize, dt: i64, t: &mut i64| {
        for _ in 0..n {
            out.push(spec.map_or_else(
                || Skeleton3::empty(*t),
                |s| {
                    PoseSpec {
                        stamp_nanos: *t,
                        ..s.clone()
                    }
                    .skeleton()
                },
            ));
            *t += dt;
        }
    };
    push(None, 3, 100 * MS, &mut t);
    push(Some(&relaxed), 20, 100 * MS, &mut t);
    push(Some(&reaching), 30, 33 * MS, &mut t);
    t += 3_000 * MS;
    push(Some(&overhead), 10, 100 * MS, &mut t);
    out
}

/// The session's recording of `frames`: each assessed with `rula track`'s defaults, its operator pose
/// and its RULA and REBA states written as the session writes them.
fn record_session(frames: &[Skeleton3], path: &std::path::Path) {
    let mut assessor =
        RulaAssessor::new(AssessmentConfig::new(UpVector::new(Vector3::z()).unwrap())).unwrap();
    let mut rec = McapRecorder::create(path).unwrap();
    for s in frames {
        let a = assessor.assess(s).unwrap();
        let t = s.stamp_nanos;
        rec.write(
            topics::OPERATOR_POSE,
            t,
            &operator_pose_message(s, Some(&a)),
        )
        .unwrap();
        rec.write(topics::ERGONOMICS, t, &ergonomic_message(&a))
            .unwrap();
        rec.write(topics::REBA, t, &reba_message(&a)).unwrap();
    }
    rec.finish().unwrap();
}

/// The report's data (what the page reads).
fn report_data(html: &str) -> serde_json::Value {
    let start = html.find("window.ERGOCELL_REVIEW_DATA = ").unwrap() + 30;
    let end = start + html[start..].find(";</script>").unwrap();
    serde_json::from_str(&html[start..end]).unwrap()
}

#[test]
fn review_region_shares_are_rula_tracks_summary() {
    let frames = skeletons();
    let landmarks = tmp("agreement-landmarks.json");
    std::fs::write(&landmarks, serde_json::to_string(&frames).unwrap()).unwrap();

    // The session's recording of the same frames: assessed with `rula track`'s defaults.
    let recording = tmp("agreement.mcap");
    record_session(&frames, &recording);

    let o = ergocell(&[
        "rula",
        "track",
        "--landmarks",
        landmarks.to_str().unwrap(),
        "--up",
        "0,0,1",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let track: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let summary = &track["summary"];

    let html = tmp("agreement.html");
    let o = ergocell(&[
        "report",
        recording.to_str().unwrap(),
        "--out",
        html.to_str().unwrap(),
        "--force",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let data = report_data(&std::fs::read_to_string(&html).unwrap());
    let rows = data["sessions"][0]["regions"].as_array().unwrap();

    // Every scored row of the review is a row of the summary, with the same shares and frames.
    let mut compared = 0;
    for row in rows {
        let samples = row["samples"].as_u64().unwrap();
        let side = row["side"].as_str().unwrap();
        let name = row["name"].as_str().unwrap();
        let level_row;
        let expected = if name == "grand score" || name == "REBA score" {
            let key = if name == "grand score" {
                "grand_score"
            } else {
                "reba_score"
            };
            summary[key]
                .as_array()
                .unwrap()
                .iter()
                .find(|g| g["side"] == side)
        } else if name == "action level" {
            assert_eq!(row["exposure"], summary["action_level_exposure"]);
            let pairs: Vec<serde_json::Value> = summary["action_level_share"]
                .as_array()
                .unwrap()
                .iter()
                .enumerate()
                .map(|(k, x)| serde_json::json!([k + 1, x]))
                .collect();
            level_row = serde_json::json!({
                "frames": summary["scored_frames"],
                "share_by_score": pairs,
            });
            Some(&level_row)
        } else {
            summary["regions"].as_array().unwrap().iter().find(|r| {
                r["region"] == name.replace(' ', "_")
                    && (r["side"] == side || (side.is_empty() && r["side"].is_null()))
            })
        };
        let Some(expected) = expected else {
            assert_eq!(samples, 0, "{row} is not in the summary {summary}");
            continue;
        };
        assert_eq!(samples, expected["frames"].as_u64().unwrap(), "{row}");
        let share = row["time_share"].as_array().unwrap();
        let mut from_summary = vec![0.0; share.len()];
        for pair in expected["share_by_score"].as_array().unwrap() {
            let score = pair[0].as_u64().unwrap() as usize;
            from_summary[score - 1] = pair[1].as_f64().unwrap();
        }
        for (k, (a, b)) in share.iter().zip(&from_summary).enumerate() {
            let a = a.as_f64().unwrap();
            assert!(
                (a - b).abs() < 1e-12,
                "{name} {side} score {}: review {a}, rula track {b}",
                k + 1
            );
        }
        compared += 1;
    }
    let in_summary = summary["regions"].as_array().unwrap().len()
        + summary["grand_score"].as_array().unwrap().len()
        + 1
        + summary["reba_score"].as_array().unwrap().len();
    assert_eq!(compared, in_summary, "every summary row is on the page");
    assert_eq!(
        compared, 14,
        "six regions (three per side), two grand scores, the action level and two REBA scores"
    );

    // The recording is one where frame counting would disagree: the right upper arm's share at its
    // reaching score by frames is not its share by time.
    let by_frames = {
        let scored: Vec<u64> = track["frames"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|f| f["right"]["scores"]["upper_arm_score"].as_u64())
            .collect();
        scored.iter().filter(|&&s| s == 3).count() as f64 / scored.len() as f64
    };
    let ua_right = rows
        .iter()
        .find(|r| r["name"] == "upper arm" && r["side"] == "right")
        .unwrap();
    let by_time = ua_right["time_share"][2].as_f64().unwrap();
    assert!(by_time > 0.0, "{ua_right}");
    assert!(
        (by_time - by_frames).abs() > 0.05,
        "by time {by_time}, by frames {by_frames}"
    );
}

/// `report --csv/--summary-csv` of a recording and `rula track --csv/--summary-csv` of the same
/// frames: the summary rows are the same row for row (time shares, exposure, REBA, ISO 11226 static
/// postures, task segments), and every frame row has the same RULA and REBA scores. The operator
/// walks in, holds the trunk at 45° with the neck at 35° for 6 s (a static hold: the trunk within
/// ISO 11226's limit, the neck not acceptable), picks a part off the floor and stands relaxed.
#[test]
fn report_csv_exports_round_trip_rula_tracks() {
    let up = PoseSpec::default();
    let bent = PoseSpec {
        trunk_flexion_rad: 45f64.to_radians(),
        neck_flexion_rad: 35f64.to_radians(),
        ..up.clone()
    };
    let pick = PoseSpec {
        trunk_flexion_rad: 90f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 90f64.to_radians(),
            ..ArmPose::default()
        },
        ..up.clone()
    };
    let mut frames = Vec::new();
    let mut t = 1_000 * MS;
    for (spec, n, walk) in [
        (&up, 15, true),
        (&bent, 60, false),
        (&pick, 10, false),
        (&up, 20, false),
    ] {
        for k in 0..n {
            let x = if walk { -1.5 + f64::from(k) * 0.1 } else { 0.0 };
            frames.push(
                PoseSpec {
                    stamp_nanos: t,
                    world_translation: Vector3::new(x, 0.0, 0.0),
                    ..spec.clone()
                }
                .skeleton(),
            );
            t += 100 * MS;
        }
    }
    let landmarks = tmp("exports-landmarks.json");
    std::fs::write(&landmarks, serde_json::to_string(&frames).unwrap()).unwrap();
    let recording = tmp("exports.mcap");
    record_session(&frames, &recording);

    let out = |name: &str| tmp(name).to_str().unwrap().to_owned();
    let (track_frames, track_summary) = (out("track-frames.csv"), out("track-summary.csv"));
    let (report_frames, report_summary) = (out("report-frames.csv"), out("report-summary.csv"));
    let o = ergocell(&[
        "rula",
        "track",
        "--landmarks",
        landmarks.to_str().unwrap(),
        "--up",
        "0,0,1",
        "--csv",
        &track_frames,
        "--summary-csv",
        &track_summary,
        "--force",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("task segments"), "{text}");
    let o = ergocell(&[
        "report",
        recording.to_str().unwrap(),
        "--out",
        &out("exports.html"),
        "--csv",
        &report_frames,
        "--summary-csv",
        &report_summary,
        "--force",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let read = |path: &str| -> (Vec<String>, Vec<csv::StringRecord>) {
        let mut r = csv::Reader::from_path(path).unwrap();
        let header = r.headers().unwrap().iter().map(str::to_owned).collect();
        (header, r.records().map(Result::unwrap).collect())
    };
    // The summaries: the same rows, but for the warnings (the recording holds none).
    let (h1, s1) = read(&track_summary);
    let (h2, s2) = read(&report_summary);
    assert_eq!(h1, h2);
    assert_eq!(
        h1,
        ["quantity", "side", "region", "score", "value", "unit", "phase"]
    );
    let keep = |rows: Vec<csv::StringRecord>| -> Vec<csv::StringRecord> {
        rows.into_iter()
            .filter(|r| &r[0] != "warnings_raised")
            .collect()
    };
    let (s1, s2) = (keep(s1), keep(s2));
    assert_eq!(s1.len(), s2.len());
    for (a, b) in s1.iter().zip(&s2) {
        assert_eq!(a, b);
    }
    let value = |q: &str, region: &str, phase: &str| -> f64 {
        s1.iter()
            .find(|r| &r[0] == q && &r[2] == region && &r[6] == phase)
            .unwrap_or_else(|| panic!("{q} {region} {phase}"))[4]
            .parse()
            .unwrap()
    };
    // The 6 s bend is one static hold of each part; ISO 11226 accepts the trunk's (45°: 2'12"), not
    // the neck's (beyond 25°).
    assert_eq!(value("static_holds", "trunk", ""), 1.0);
    assert_eq!(value("static_holds_exceeding_iso11226", "trunk", ""), 0.0);
    assert_eq!(value("static_holds_exceeding_iso11226", "neck", ""), 1.0);
    assert!((value("longest_static_hold", "neck", "") - 6.0).abs() < 0.25);
    // The arms hang from the shoulders, so in the bend they are 45° from vertical: one static hold
    // each, in the 20°–60° zone whose holding time no readable source gives — counted, no verdict.
    let arm = |q: &str| -> f64 {
        s1.iter()
            .find(|r| &r[0] == q && &r[1] == "left" && &r[2] == "upper_arm")
            .unwrap_or_else(|| panic!("{q}"))[4]
            .parse()
            .unwrap()
    };
    assert_eq!(arm("static_holds"), 1.0);
    assert_eq!(arm("static_holds_limit_unknown"), 1.0);
    assert_eq!(arm("static_holds_exceeding_iso11226"), 0.0);
    // The task segments: walking at the start (once its speed is measured), the pick, in place.
    for phase in ["walking", "floor pick", "in place"] {
        assert!(value("phase_duration", "", phase) > 0.0, "{phase}");
    }
    assert!((value("phase_duration", "", "floor pick") - 1.0).abs() < 0.25);
    assert!(value("phase_duration", "", "walking") >= 1.0);

    // The frames: one row each, the same scores.
    let (h1, f1) = read(&track_frames);
    let (h2, f2) = read(&report_frames);
    assert_eq!(f1.len(), frames.len());
    assert_eq!(f2.len(), frames.len());
    let col = |h: &[String], name: &str| h.iter().position(|c| c == name).unwrap();
    for side in ["left", "right"] {
        for c in [
            "final_score",
            "action_level",
            "neck_score",
            "reba_score",
            "reba_action_level",
        ] {
            let name = format!("{side}_{c}");
            let (i, j) = (col(&h1, &name), col(&h2, &name));
            for (a, b) in f1.iter().zip(&f2) {
                assert_eq!(a[i], b[j], "{name}");
            }
        }
    }
    let (i, j) = (
        col(&h1, "right_trunk_flexion_deg"),
        col(&h2, "trunk_flexion_deg"),
    );
    for (a, b) in f1.iter().zip(&f2) {
        assert_eq!(a[i], b[j]);
    }
    // Two outputs naming one file (spelled differently) are refused before anything is written.
    let dir = tmp("collide");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let html = dir.join("r.html");
    let o = ergocell(&[
        "report",
        recording.to_str().unwrap(),
        "--out",
        html.to_str().unwrap(),
        "--csv",
        dir.join(".").join("r.html").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("is also --out"), "{err}");
    assert!(!html.exists(), "nothing written");

    let phase = col(&h2, "phase");
    assert_eq!(&f2[0][phase], "in place", "walking needs 0.2 s of history");
    assert_eq!(&f2[10][phase], "walking");
    assert_eq!(&f2[80][phase], "floor pick");
}

/// A recorded frame that neither side could be scored on carries level 0 in its message; the frame
/// CSV must show it as not scored (an empty cell), never as a level (REBA's 0 reads "negligible").
/// The demo's session has such a frame.
#[test]
fn report_csv_leaves_the_levels_of_an_unscored_frame_empty() {
    let recording = tmp("unscored-demo.mcap");
    let o = ergocell(&["demo", "--out", recording.to_str().unwrap(), "--force"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let frames = tmp("unscored-frames.csv");
    let o = ergocell(&[
        "report",
        recording.to_str().unwrap(),
        "--out",
        tmp("unscored.html").to_str().unwrap(),
        "--csv",
        frames.to_str().unwrap(),
        "--force",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut r = csv::Reader::from_path(&frames).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_owned).collect();
    let col = |name: &str| header.iter().position(|c| c == name).unwrap();
    let (ls, rs) = (col("left_scored"), col("right_scored"));
    let (al, rl) = (col("action_level"), col("reba_action_level"));
    let (mut scored, mut unscored) = (0, 0);
    for row in r.records().map(Result::unwrap) {
        if &row[ls] == "1" || &row[rs] == "1" {
            scored += 1;
            assert!(matches!(&row[al], "1" | "2" | "3" | "4"), "{row:?}");
            assert!(matches!(&row[rl], "0" | "1" | "2" | "3" | "4"), "{row:?}");
        } else {
            unscored += 1;
            assert_eq!((&row[al], &row[rl]), ("", ""), "{row:?}");
        }
    }
    assert!(
        scored > 0 && unscored > 0,
        "{scored} scored, {unscored} unscored"
    );
}
