//! `ergocell calibrate` end to end on OpenCV's stereo sample (`../shared/data/opencv-stereo-sample`):
//! the per-image table, the written rig file in both formats, and exit code 2 when too few views
//! remain or the board is wrong.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

use ergocell_perception::rig_file::{parse_rig, RigFormat};

fn sample(pattern: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/opencv-stereo-sample")
        .join(pattern)
        .display()
        .to_string()
}

fn tmp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_calibrate");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
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
fn stereo_writes_a_rig_with_the_sample_baseline() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    for format in ["ergocell", "anipose"] {
        let out = tmp(&format!("rig_{format}.toml"));
        let (code, stdout, stderr) = ergocell(&[
            "calibrate",
            "stereo",
            "--left",
            &sample("left0*.jpg"),
            "--right",
            &sample("right0*.jpg"),
            "--board",
            "9x6",
            "--square-m",
            "0.025",
            // The same file on every test run: overwritten on purpose.
            "--force",
            "--out",
            out.to_str().unwrap(),
            "--format",
            format,
        ]);
        assert_eq!(code, 0, "{stderr}");
        // one table row per pair, all used
        assert_eq!(
            stdout.lines().filter(|l| l.contains(" used ")).count(),
            9,
            "{stdout}"
        );
        assert!(stdout.contains("baseline"), "{stdout}");
        let text = std::fs::read_to_string(&out).unwrap();
        let (rig, parsed_format) = parse_rig(&text, "calibrated").unwrap();
        let expected = if format == "anipose" {
            RigFormat::Anipose
        } else {
            RigFormat::Ergocell
        };
        assert_eq!(parsed_format, expected);
        let cams = rig.cameras();
        assert_eq!(cams.len(), 2);
        let baseline = (cams[0].position_world() - cams[1].position_world()).norm();
        assert!(
            (baseline / 0.083_206 - 1.0).abs() < 0.01,
            "baseline {baseline} m"
        );
        assert!(
            cams[0].position_world().coords.norm() < 1e-12,
            "left camera is the world origin"
        );
    }
}

#[test]
fn intrinsics_table_and_rig_file() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let out = tmp("left.toml");
    let (code, stdout, stderr) = ergocell(&[
        "calibrate",
        "intrinsics",
        "--images",
        &sample("left1*.jpg"),
        "--force",
        "--out",
        out.to_str().unwrap(),
        "--id",
        "cam_left",
    ]);
    assert_eq!(code, 0, "{stderr}");
    for name in ["left11.jpg", "left12.jpg", "left13.jpg", "left14.jpg"] {
        assert!(
            stdout
                .lines()
                .any(|l| l.starts_with(name) && l.contains(" used ")),
            "{stdout}"
        );
    }
    let (rig, _) = parse_rig(&std::fs::read_to_string(&out).unwrap(), "left.toml").unwrap();
    assert_eq!(rig.cameras()[0].id.as_str(), "cam_left");
    assert!((rig.cameras()[0].intrinsics.fx / 532.8 - 1.0).abs() < 0.02);
}

#[test]
fn too_few_views_is_a_usage_error() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let out = tmp("never.toml");
    let (code, stdout, stderr) = ergocell(&[
        "calibrate",
        "intrinsics",
        "--images",
        &sample("left0?.jpg"),
        "--board",
        "8x6",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("usable views"), "{stderr}");
    // every image is listed as rejected, with the reason
    assert_eq!(
        stdout.lines().filter(|l| l.contains("rejected")).count(),
        9,
        "{stdout}"
    );
    assert!(stdout.contains("expected 8x6"), "{stdout}");
    assert!(!out.exists());
}

#[test]
fn mismatched_stereo_lists_and_bad_boards_are_usage_errors() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let out = tmp("never2.toml");
    let out = out.to_str().unwrap();
    let (code, _, stderr) = ergocell(&[
        "calibrate",
        "stereo",
        "--left",
        &sample("left0*.jpg"),
        "--right",
        &sample("right1*.jpg"),
        "--out",
        out,
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("must pair up"), "{stderr}");
    let (code, _, stderr) = ergocell(&[
        "calibrate",
        "intrinsics",
        "--images",
        &sample("left0*.jpg"),
        "--board",
        "9by6",
        "--out",
        out,
    ]);
    assert_eq!(code, 2, "{stderr}");
    let (code, _, stderr) = ergocell(&[
        "calibrate",
        "intrinsics",
        "--images",
        &sample("nothing*.jpg"),
        "--out",
        out,
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("no images"), "{stderr}");
}
