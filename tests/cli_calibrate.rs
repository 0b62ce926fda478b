//! `ergocell calibrate` end to end on OpenCV's stereo sample (`../shared/data/opencv-stereo-sample`):
//! the per-image table, the written rig file in both formats, and exit code 2 when too few views
//! remain or the board is wrong.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

use ergocell_formats::rig_file::{parse_rig, RigFormat};

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

/// `calibrate place` end to end: the reference rig's pairs, each written in its own left camera's
/// frame (as `calibrate stereo` writes it), and markers measured in the cell with the pixels each
/// camera saw: the rig written is the reference rig, `up` included. A points file naming a camera in
/// no pair, or with an unknown key, is a usage error naming it.
#[test]
fn place_puts_pairs_given_in_their_own_frames_back_in_the_cell() {
    use ergocell_perception::{Camera, CameraRig};
    use std::fmt::Write as _;
    let truth = parse_rig(
        &std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("config/rig.toml"))
            .unwrap(),
        "config/rig.toml",
    )
    .unwrap()
    .0;
    let mut args: Vec<String> = vec!["calibrate".into(), "place".into()];
    for (k, pair) in truth.pairs().iter().enumerate() {
        let T_left_world = truth.cameras()[pair.left].T_camera_world;
        let cameras = [pair.left, pair.right]
            .iter()
            .map(|&i| {
                let c = &truth.cameras()[i];
                let t = c.T_camera_world * T_left_world.inverse();
                Camera::new(
                    c.id.clone(),
                    c.intrinsics,
                    c.distortion,
                    t.rotation.to_rotation_matrix(),
                    t.translation.vector,
                )
                .unwrap()
            })
            .collect();
        let rig = CameraRig::new(cameras, &[], None).unwrap();
        let path = tmp(&format!("place-pair{k}.toml"));
        std::fs::write(&path, ergocell_formats::rig_file::to_ergocell_toml(&rig)).unwrap();
        args.extend(["--pair".into(), path.display().to_string()]);
    }
    let mut points = String::new();
    for (i, (x, y, z)) in [
        (-0.6, -0.7, 0.0),
        (0.6, -0.7, 0.0),
        (-0.6, 0.7, 0.0),
        (0.6, 0.7, 0.0),
        (0.0, 0.0, 0.9),
        (1.0, 0.0, 0.9),
        (0.0, -0.7, 1.6),
        (0.0, 0.7, 1.6),
        (1.0, 0.7, 1.6),
    ]
    .iter()
    .enumerate()
    {
        let p = nalgebra::Point3::new(*x, *y, *z);
        writeln!(
            points,
            "[[point]]\nname = \"m{i}\"\ncell_m = [{x:?}, {y:?}, {z:?}]\n[point.seen]"
        )
        .unwrap();
        for c in truth.cameras() {
            let Ok(px) = c.project(&p) else { continue };
            if (c.T_camera_world * p).z > 0.1 && c.in_image(&px) {
                writeln!(points, "{} = [{:?}, {:?}]", c.id.as_str(), px.x, px.y).unwrap();
            }
        }
    }
    let points_path = tmp("place-points.toml");
    std::fs::write(&points_path, &points).unwrap();
    let out = tmp("place-rig.toml");
    let _ = std::fs::remove_file(&out);
    args.extend([
        "--points".into(),
        points_path.display().to_string(),
        "--out".into(),
        out.display().to_string(),
    ]);
    let argv: Vec<&str> = args.iter().map(String::as_str).collect();
    let (code, stdout, stderr) = ergocell(&argv);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let placed = parse_rig(&std::fs::read_to_string(&out).unwrap(), "placed")
        .unwrap()
        .0;
    assert_eq!(placed.up(), Some(nalgebra::Vector3::z()));
    for c in truth.cameras() {
        let got = placed.cameras().iter().find(|p| p.id == c.id).unwrap();
        let d = c.T_camera_world.inverse() * got.T_camera_world;
        assert!(
            d.translation.vector.norm() < 1e-6,
            "{}: {d:?}",
            c.id.as_str()
        );
        assert!(d.rotation.angle() < 1e-6, "{}: {d:?}", c.id.as_str());
    }
    // Refused as bad input: a camera in no pair, an unknown key; nothing written.
    for (bad, named) in [
        (format!("{points}[[point]]\nname = \"x\"\ncell_m = [0.0, 0.0, 0.0]\n[point.seen]\nnobody = [1.0, 2.0]\n"), "nobody"),
        (format!("{points}[[point]]\nname = \"y\"\ncell_mm = [0.0, 0.0, 0.0]\nseen = {{}}\n"), "cell_mm"),
    ] {
        std::fs::write(&points_path, bad).unwrap();
        let refused = tmp("place-refused.toml");
        let _ = std::fs::remove_file(&refused);
        let mut argv = argv.clone();
        let n = argv.len();
        let refused_s = refused.display().to_string();
        argv[n - 1] = &refused_s;
        let (code, stdout, stderr) = ergocell(&argv);
        assert_eq!(code, 2, "{stdout}{stderr}");
        assert!(stderr.contains(named), "{stderr}");
        assert!(!refused.exists());
    }
}
