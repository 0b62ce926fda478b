//! `ergocell triangulate` of a long recording: an hour of 6 cameras at 30 Hz (108 000 frames,
//! 21 million keypoints) from a generated caliscope CSV, timed end to end with its peak memory;
//! then one minute of the same data as OpenPose JSON folders, triangulated by ergocell and — when a
//! Pose2Sim install is found — by Pose2Sim (`tools/pose2sim/triangulate_timing.py`), as a ratio.
//!
//! `cargo bench --bench triangulate_hour` (release build of the binary). Environment:
//! `ERGOCELL_HOUR_SECONDS` (default 3600), `ERGOCELL_P2S_SECONDS` (default 60),
//! `ERGOCELL_P2S_PYTHON` (a Python with pose2sim; default `/tmp/p2s_min/bin/python` if present; see
//! `tools/pose2sim/README.md`), `ERGOCELL_BEFORE_BIN` (another build's `ergocell`: the CSV rows are
//! run by it too, before this build, for a before → after comparison in one run). The data is
//! generated once into `target/tmp/triangulate_hour/` (the hour is ≈ 1 GB) and reused; the
//! synthetic cell is `perception/benches/rig.rs`'s 6-camera ring (moving body, 2 px noise, 5 %
//! missing, 2 % gross errors, seed 1). Not run by CI (minutes and a gigabyte); figures are in
//! `docs/measurements.md`.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::print_stdout,
    clippy::disallowed_methods
)]

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use ergocell_formats::rig_file::{to_anipose_toml, to_ergocell_toml};
use ergocell_skeleton::Landmark;

#[path = "../perception/benches/rig.rs"]
mod rig;

fn env_secs(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Writes the frames of `seconds` at 30 Hz as caliscope's long CSV (one row per keypoint seen).
fn write_caliscope(path: &Path, rig: &ergocell_perception::CameraRig, frames: usize) {
    let tmp = path.with_extension("partial");
    let mut w = BufWriter::with_capacity(1 << 20, std::fs::File::create(&tmp).unwrap());
    writeln!(
        w,
        "sync_index,port,frame_index,frame_time,point_id,img_loc_x,img_loc_y,obj_loc_x,obj_loc_y"
    )
    .unwrap();
    for (f, frame) in rig::sequence(rig, frames, 1).enumerate() {
        for v in &frame.views {
            let t = v.stamp_nanos as f64 * 1e-9;
            for lm in Landmark::ALL {
                if let Some(k) = v.get(lm) {
                    let p = k.pixel();
                    writeln!(
                        w,
                        "{f},{},{f},{t:.6},{},{:.3},{:.3},,",
                        v.camera,
                        lm.index(),
                        p.x,
                        p.y
                    )
                    .unwrap();
                }
            }
        }
    }
    w.flush().unwrap();
    drop(w);
    std::fs::rename(tmp, path).unwrap();
}

/// Writes the frames as OpenPose JSON folders `cam_k/frame_<12 digits>_keypoints.json`.
fn write_openpose(dir: &Path, rig: &ergocell_perception::CameraRig, frames: usize) {
    let tmp = dir.with_extension("partial");
    let _ = std::fs::remove_dir_all(&tmp);
    for k in 0..rig.len() {
        std::fs::create_dir_all(tmp.join(format!("cam_{k}"))).unwrap();
    }
    for (f, frame) in rig::sequence(rig, frames, 1).enumerate() {
        for v in &frame.views {
            let mut values = Vec::with_capacity(99);
            for lm in Landmark::ALL {
                match v.get(lm) {
                    Some(k) => {
                        let p = k.pixel();
                        values.push(format!("{:.3},{:.3},{:.3}", p.x, p.y, k.confidence()));
                    }
                    None => values.push("0,0,0".into()),
                }
            }
            let path = tmp.join(format!("cam_{}/frame_{f:012}_keypoints.json", v.camera));
            std::fs::write(
                path,
                format!(
                    "{{\"version\":1.3,\"people\":[{{\"pose_keypoints_2d\":[{}]}}]}}",
                    values.join(",")
                ),
            )
            .unwrap();
        }
    }
    std::fs::rename(tmp, dir).unwrap();
}

/// Runs a command under GNU time (`/usr/bin/time -f %M`: the peak resident memory, exact), returns
/// (wall seconds, peak resident memory in MB, stdout).
fn timed(cmd: &Command) -> (f64, f64, String) {
    let rss_file = std::env::temp_dir().join(format!("ergocell-bench-rss-{}", std::process::id()));
    let mut wrapped = Command::new("/usr/bin/time");
    wrapped
        .arg("-f")
        .arg("%M")
        .arg("-o")
        .arg(&rss_file)
        .arg(cmd.get_program())
        .args(cmd.get_args())
        .stderr(Stdio::null());
    let start = Instant::now();
    let out = wrapped
        .output()
        .expect("/usr/bin/time (GNU time) runs the command");
    let elapsed = start.elapsed().as_secs_f64();
    let kb: f64 = std::fs::read_to_string(&rss_file)
        .ok()
        .and_then(|t| t.lines().last().and_then(|l| l.trim().parse().ok()))
        .unwrap_or(f64::NAN);
    let _ = std::fs::remove_file(&rss_file);
    (
        elapsed,
        kb / 1024.0,
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// `ergocell triangulate` of this build, or of `ERGOCELL_BEFORE_BIN` when `before` (another build,
/// for a before → after comparison in one run).
fn triangulate_by(
    before: bool,
    calibration: &Path,
    detections: &Path,
    out: &Path,
) -> (f64, f64, String) {
    let bin = if before {
        std::env::var("ERGOCELL_BEFORE_BIN").unwrap()
    } else {
        env!("CARGO_BIN_EXE_ergocell").to_owned()
    };
    timed(
        Command::new(bin)
            .arg("triangulate")
            .arg("--calibration")
            .arg(calibration)
            .arg("--detections")
            .arg(detections)
            .arg("--force")
            .arg("--out")
            .arg(out),
    )
}

fn triangulate(calibration: &Path, detections: &Path, out: &Path) -> (f64, f64, String) {
    triangulate_by(false, calibration, detections, out)
}

fn line<'a>(stdout: &'a str, key: &str) -> &'a str {
    stdout
        .lines()
        .find(|l| l.starts_with(key))
        .map_or("", |l| l[key.len()..].trim())
}

fn main() {
    // `cargo bench` passes `--bench`; anything else (e.g. `cargo test --benches`) only checks that
    // this builds
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let hour_s = env_secs("ERGOCELL_HOUR_SECONDS", 3600.0);
    let p2s_s = env_secs("ERGOCELL_P2S_SECONDS", 60.0);
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("triangulate_hour");
    std::fs::create_dir_all(&dir).unwrap();
    let rig = rig::rig(6);
    let calibration = dir.join("rig.toml");
    std::fs::write(&calibration, to_ergocell_toml(&rig)).unwrap();
    let anipose = dir.join("calibration.toml");
    std::fs::write(&anipose, to_anipose_toml(&rig)).unwrap();

    let hour_frames = (hour_s * 30.0).round() as usize;
    let csv = dir.join(format!("ring6_{hour_frames}.csv"));
    if !csv.exists() {
        println!("generating {} ({hour_frames} frames) …", csv.display());
        write_caliscope(&csv, &rig, hour_frames);
    }
    // a tenth of it, to show the memory does not grow with the length
    let tenth_frames = hour_frames / 10;
    let tenth = dir.join(format!("ring6_{tenth_frames}.csv"));
    if !tenth.exists() {
        write_caliscope(&tenth, &rig, tenth_frames);
    }
    println!("| input | frames | wall s | frames/s | peak RSS MB |");
    println!("|---|---|---|---|---|");
    // with ERGOCELL_BEFORE_BIN, each input by that build first, then by this one
    let builds: &[bool] = if std::env::var_os("ERGOCELL_BEFORE_BIN").is_some() {
        &[true, false]
    } else {
        &[false]
    };
    for (name, path, frames) in [
        ("caliscope CSV, 1/10", &tenth, tenth_frames),
        ("caliscope CSV", &csv, hour_frames),
    ] {
        for &before in builds {
            let (s, rss, stdout) = triangulate_by(before, &calibration, path, &dir.join("out.trc"));
            assert!(line(&stdout, "frames:") == frames.to_string(), "{stdout}");
            println!(
                "| {name} ({:.0} MB){} | {frames} | {s:.1} | {:.0} | {rss:.0} |",
                std::fs::metadata(path).unwrap().len() as f64 / 1e6,
                if before { ", before" } else { "" },
                frames as f64 / s
            );
        }
    }

    let p2s_frames = (p2s_s * 30.0).round() as usize;
    let pose = dir.join(format!("openpose_{p2s_frames}"));
    if !pose.exists() {
        write_openpose(&pose, &rig, p2s_frames);
    }
    // once untimed first: the hour's gigabyte has just pushed the 10 800 small JSON files out of
    // the page cache (cold, the run took 0.89 s instead of 0.15 s), and Pose2Sim, run after, reads
    // them warm
    triangulate(&calibration, &pose, &dir.join("openpose.trc"));
    let (s, rss, _) = triangulate(&calibration, &pose, &dir.join("openpose.trc"));
    let ours = p2s_frames as f64 / s;
    println!("| OpenPose JSON folders | {p2s_frames} | {s:.2} | {ours:.0} | {rss:.0} |");
    let python = std::env::var("ERGOCELL_P2S_PYTHON").ok().or_else(|| {
        Path::new("/tmp/p2s_min/bin/python")
            .exists()
            .then(|| "/tmp/p2s_min/bin/python".into())
    });
    let Some(python) = python else {
        println!("Pose2Sim: no install found (ERGOCELL_P2S_PYTHON); see tools/pose2sim/README.md");
        return;
    };
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tools/pose2sim/triangulate_timing.py");
    for undistort in [false, true] {
        let mut cmd = Command::new(&python);
        cmd.arg(&script)
            .arg("--calibration")
            .arg(&anipose)
            .arg("--pose")
            .arg(&pose)
            .arg("--quiet");
        if undistort {
            cmd.arg("--undistort");
        }
        let (_, rss, stdout) = timed(&cmd);
        let Some(json) = stdout.lines().rev().find(|l| l.starts_with('{')) else {
            println!("Pose2Sim gave no result");
            continue;
        };
        let v: serde_json::Value = serde_json::from_str(json).unwrap();
        let whole = v["frames_per_s"].as_f64().unwrap_or(f64::NAN);
        let core = v["core_frames_per_s"].as_f64().unwrap_or(f64::NAN);
        println!(
            "| Pose2Sim {} {} | {} | {:.2} | {whole:.0} (core {core:.0}) | {rss:.0} |",
            v["version"].as_str().unwrap_or("?"),
            if undistort {
                "with undistortion"
            } else {
                "without undistortion"
            },
            v["frames"],
            v["seconds"].as_f64().unwrap_or(f64::NAN),
        );
        println!(
            "ergocell / Pose2Sim ({}): {:.0}× the whole step, {:.0}× its triangulation alone",
            if undistort {
                "both undistorting"
            } else {
                "Pose2Sim not undistorting"
            },
            ours / whole,
            ours / core
        );
    }
}
