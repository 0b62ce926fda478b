//! `ergocell triangulate` end to end: OpenPose folders (BODY_25, two people in view) through the
//! reference cell's rig, and caliscope's real recording; malformed input exits with code 2.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

use ergocell_formats::landmarks_file::{read_landmarks, LandmarksFormat};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::{CameraRig, KeypointFormat};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Vector3};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&p);
    p
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

fn reference_rig() -> CameraRig {
    let text = std::fs::read_to_string(repo().join("config/rig.toml")).unwrap();
    parse_rig(&text, "config/rig.toml").unwrap().0
}

/// A standing body at the station (x forward, z up), shifted by `offset`.
fn body(offset: Vector3<f64>) -> [Point3<f64>; LANDMARK_COUNT] {
    std::array::from_fn(|i| {
        let lm = Landmark::ALL[i];
        let side = if lm.name().starts_with("left") {
            1.0
        } else if lm.name().starts_with("right") {
            -1.0
        } else {
            0.0
        };
        let z = match lm {
            Landmark::LeftShoulder | Landmark::RightShoulder => 1.42,
            Landmark::LeftElbow | Landmark::RightElbow => 1.10,
            Landmark::LeftWrist | Landmark::RightWrist => 0.85,
            Landmark::LeftHip | Landmark::RightHip => 0.92,
            Landmark::LeftKnee | Landmark::RightKnee => 0.50,
            Landmark::LeftAnkle | Landmark::RightAnkle => 0.07,
            Landmark::LeftHeel | Landmark::RightHeel => 0.03,
            Landmark::LeftFootIndex | Landmark::RightFootIndex => 0.02,
            _ => 1.60 + 0.002 * i as f64,
        };
        let y = side * if z < 1.0 && z > 0.3 { 0.1 } else { 0.18 };
        let x = if matches!(lm, Landmark::LeftFootIndex | Landmark::RightFootIndex) {
            0.15
        } else {
            0.01 * (i % 3) as f64
        };
        Point3::new(x, y, z) + offset
    })
}

fn write_openpose(
    dir: &Path,
    rig: &CameraRig,
    frames: usize,
) -> Vec<[Point3<f64>; LANDMARK_COUNT]> {
    let mapping = KeypointFormat::Body25.mapping();
    let mut truth = Vec::new();
    for k in 0..frames {
        let operator = body(Vector3::new(0.0, 0.02 * k as f64, 0.0));
        let bystander = body(Vector3::new(-0.6, 1.2, 0.0));
        for (c, cam) in rig.cameras().iter().enumerate() {
            let folder = dir.join(format!("{}_json", cam.id));
            std::fs::create_dir_all(&folder).unwrap();
            let person = |pts: &[Point3<f64>; LANDMARK_COUNT], conf: f64| {
                let values: Vec<String> = mapping
                    .iter()
                    .flat_map(
                        |lm| match lm.and_then(|lm| cam.project(&pts[lm.index()]).ok()) {
                            Some(px) => vec![
                                format!("{:.4}", px.x),
                                format!("{:.4}", px.y),
                                format!("{conf}"),
                            ],
                            None => vec!["0".into(), "0".into(), "0".into()],
                        },
                    )
                    .collect();
                format!(
                    "{{\"person_id\":[-1],\"pose_keypoints_2d\":[{}]}}",
                    values.join(",")
                )
            };
            // the bystander is listed first in some cameras and is less confident
            let people = if c % 2 == 0 {
                format!("[{},{}]", person(&bystander, 0.5), person(&operator, 0.9))
            } else {
                format!("[{},{}]", person(&operator, 0.9), person(&bystander, 0.5))
            };
            std::fs::write(
                folder.join(format!("frame_{k:06}_keypoints.json")),
                format!("{{\"version\":1.3,\"people\":{people}}}"),
            )
            .unwrap();
        }
        truth.push(operator);
    }
    truth
}

/// `ergocell triangulate` of a BODY_25 OpenPose folder (10 Hz) on the reference rig into
/// `<dir>/out.trc`: stdout, stderr and the frames read back; the command must succeed.
fn triangulate_body25(dir: &Path) -> (String, String, Vec<ergocell_skeleton::Skeleton3>) {
    let out = dir.join("out.trc");
    let (code, stdout, stderr) = ergocell(&[
        "triangulate",
        "--calibration",
        repo().join("config/rig.toml").to_str().unwrap(),
        "--detections",
        dir.to_str().unwrap(),
        "--keypoints",
        "body_25",
        "--rate-hz",
        "10",
        "--force",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    let frames = read_landmarks(
        &std::fs::read_to_string(&out).unwrap(),
        LandmarksFormat::Trc,
        "out.trc",
    )
    .unwrap();
    (stdout, stderr, frames)
}

#[test]
fn openpose_body25_folders_triangulate_to_the_true_body_and_ignore_the_bystander() {
    let rig = reference_rig();
    let dir = tmp("openpose_body25");
    let truth = write_openpose(&dir, &rig, 6);
    let (stdout, _, frames) = triangulate_body25(&dir);
    assert!(stdout.contains("frames:                   6"), "{stdout}");
    assert_eq!(frames.len(), 6);
    let mut compared = 0;
    for (skeleton, truth) in frames.iter().zip(&truth) {
        for lm in KeypointFormat::Body25.mapping().iter().flatten() {
            let p = skeleton
                .position(*lm)
                .unwrap_or_else(|| panic!("{lm} missing"));
            // pixels were written with 4 decimals and the TRC with 6: sub-millimetre agreement
            assert!(
                (p - truth[lm.index()]).norm() < 1e-3,
                "{lm}: {p} vs {}",
                truth[lm.index()]
            );
            compared += 1;
        }
        assert!(
            skeleton.position(Landmark::LeftPinky).is_none(),
            "BODY_25 has no pinky: nothing is made up"
        );
    }
    assert_eq!(compared, 6 * 21);
}

#[test]
fn caliscope_recording_gives_a_summary_and_json() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let out = tmp("caliscope_out").with_extension("json");
    let (code, stdout, stderr) = triangulate_caliscope(&out, &[]);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    assert!(stdout.contains("frames:                   267"), "{stdout}");
    assert!(stdout.contains("median reprojection err:"), "{stdout}");
    assert!(stdout.contains("bone-length variation:"), "{stdout}");
    let frames = read_landmarks(
        &std::fs::read_to_string(&out).unwrap(),
        LandmarksFormat::Json,
        "out.json",
    )
    .unwrap();
    assert_eq!(frames.len(), 267);
}

/// `triangulate` on caliscope's real recording into `out` (`--force`), with `extra` arguments.
fn triangulate_caliscope(out: &Path, extra: &[&str]) -> (i32, String, String) {
    let data = repo().join("../shared/data/caliscope-4cam");
    let calibration = data.join("config.toml");
    let detections = data.join("xy_pose33.csv");
    let mut args = vec![
        "triangulate",
        "--calibration",
        calibration.to_str().unwrap(),
        "--detections",
        detections.to_str().unwrap(),
        "--force",
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    ergocell(&args)
}

/// `--detector-error` on caliscope's real recording: each view judged by the others, tables on
/// stdout and the same figures as JSON.
#[test]
fn the_detector_error_of_a_real_recording_is_measured_view_against_view() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let data = repo().join("../shared/data/caliscope-4cam");
    let out = tmp("caliscope_err_out").with_extension("json");
    let err = tmp("caliscope_err").with_extension("json");
    let (code, stdout, stderr) =
        triangulate_caliscope(&out, &["--detector-error", err.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    assert!(
        stdout.contains("detector error, each view against the other views (267 frames"),
        "{stdout}"
    );
    assert!(
        stdout.contains("(the detections carry no confidence)"),
        "{stdout}"
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&err).unwrap()).unwrap();
    assert_eq!(report["frames"], 267);
    let cameras = report["cameras"].as_array().unwrap();
    assert_eq!(cameras.len(), 4);
    for c in cameras {
        let (seen, missing) = (
            c["frames_seen"].as_u64().unwrap(),
            c["frames_missing"].as_u64().unwrap(),
        );
        assert_eq!(seen + missing, 267, "{c}");
    }
    // An upper-body recording: face and arms measured, legs not at all.
    let groups = report["groups"].as_array().unwrap();
    let count = |i: usize| groups[i][1]["total"]["count"].as_u64().unwrap();
    assert!(
        count(0) > 1000 && count(1) > 1000 && count(3) == 0,
        "{groups:?}"
    );
    // A MediaPipe detector, not garbage: the median error is 1–10 % of the person's image height,
    // and persistent + jitter bound it (|a + b| ≤ |a| + |b| holds per residual, so at the median
    // the parts cannot both be far below it).
    let all = &report["all"];
    let p50 = all["total"]["p50"].as_f64().unwrap();
    assert!((0.01..0.10).contains(&p50), "{all}");
    let parts = all["persistent"]["p50"].as_f64().unwrap() + all["jitter"]["p50"].as_f64().unwrap();
    assert!(parts >= 0.5 * p50, "{all}");
    assert_eq!(report["confidence_error_spearman"], serde_json::Value::Null);
    // The report is an output like --out: never onto an input.
    let input = data.join("xy_pose33.csv");
    let (code, _, stderr) =
        triangulate_caliscope(&out, &["--detector-error", input.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
}

#[test]
fn malformed_calibration_and_unknown_output_format_exit_with_code_2() {
    let dir = tmp("bad_calibration");
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("calib.toml");
    let text = std::fs::read_to_string(repo().join("config/rig.toml"))
        .unwrap()
        .replacen("fx = ", "fx = nan # ", 1);
    std::fs::write(&bad, text).unwrap();
    let (code, _, stderr) = ergocell(&[
        "triangulate",
        "--calibration",
        bad.to_str().unwrap(),
        "--detections",
        dir.to_str().unwrap(),
        "--out",
        "x.trc",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("calib.toml"), "{stderr}");
    let (code, _, stderr) = ergocell(&[
        "triangulate",
        "--calibration",
        repo().join("config/rig.toml").to_str().unwrap(),
        "--detections",
        dir.to_str().unwrap(),
        "--out",
        "x.xlsx",
    ]);
    assert_eq!(code, 2, "{stderr}");
}

/// #18: OpenPose frames were paired by file order, so deleting one `*_keypoints.json` in one camera
/// folder shifted every later frame of that camera. Now a missing file is one missing view: every
/// frame still triangulates to its own true body.
#[test]
fn openpose_frames_paired_by_file_order_a_missing_file_no_longer_shifts_later_frames() {
    let rig = reference_rig();
    let dir = tmp("openpose_missing_file");
    let truth = write_openpose(&dir, &rig, 6);
    let cam0 = rig.cameras()[0].id.as_str().to_owned();
    std::fs::remove_file(dir.join(format!("{cam0}_json/frame_000002_keypoints.json"))).unwrap();
    let (_, stderr, frames) = triangulate_body25(&dir);
    assert!(
        stderr.contains("missing"),
        "the missing view is reported: {stderr}"
    );
    assert_eq!(frames.len(), 6);
    for (k, (skeleton, truth)) in frames.iter().zip(&truth).enumerate() {
        let p = skeleton.position(Landmark::LeftShoulder).unwrap();
        assert!(
            (p - truth[Landmark::LeftShoulder.index()]).norm() < 1e-3,
            "frame {k}: {p}"
        );
    }
}

#[test]
fn triangulate_streams_into_a_temporary_file_and_reads_an_unsorted_csv_whole() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    // The output appears only when complete (written beside it as `.<name>.partial-<pid>`, then
    // moved): no temporary file is left, an existing output is refused before any work, and a CSV
    // whose rows are out of sync_index order is read whole with a note and the same result.
    let data = repo().join("../shared/data/caliscope-4cam");
    let dir = tmp("streaming");
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(data.join("xy_pose33.csv")).unwrap();
    let mut lines: Vec<&str> = text.lines().collect();
    let moved = lines.remove(1);
    lines.push(moved);
    let unsorted = dir.join("unsorted.csv");
    std::fs::write(&unsorted, lines.join("\n")).unwrap();
    let run = |detections: &Path, out: &Path| {
        ergocell(&[
            "triangulate",
            "--calibration",
            data.join("config.toml").to_str().unwrap(),
            "--detections",
            detections.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let (sorted_out, unsorted_out) = (dir.join("sorted.trc"), dir.join("unsorted.trc"));
    let (code, stdout, stderr) = run(&data.join("xy_pose33.csv"), &sorted_out);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("throughput:"), "{stdout}");
    assert!(!stderr.contains("read first"), "{stderr}");
    let (code, _, stderr) = run(&unsorted, &unsorted_out);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.contains("not in sync_index order"), "{stderr}");
    let strip_name = |p: &Path| {
        let t = std::fs::read_to_string(p).unwrap();
        t.split_once('\n').unwrap().1.to_owned()
    };
    assert_eq!(strip_name(&sorted_out), strip_name(&unsorted_out));
    let (code, _, stderr) = run(&unsorted, &unsorted_out);
    assert_eq!(code, 2, "{stderr}");
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names.iter().all(|n| !n.contains("partial")),
        "a temporary file was left: {names:?}"
    );
}
