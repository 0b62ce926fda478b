//! A cell whose station and robot base are moved together: turned 0.3 rad about the vertical and
//! shifted 0.2 m, so every trajectory is the same relative to the station. Locking gives the same
//! samples; the session, the simulator, the robot markers and the demo's operator all put each
//! class's handover point at the same place in the world; the demo's operator stands at the moved
//! station and takes every part.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use ergocell_cell::CellSettings;
use ergocell_robot::{CellConfig, LockFile, TrajectoryClass};
use nalgebra::{Point3, Rotation3, Vector3};

const YAW_RAD: f64 = 0.3;
/// The shift: 0.2 m, not along an axis (an x/y mix-up would show).
const SHIFT_M: [f64; 2] = [0.12, 0.16];

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Where a point given relative to the reference cell's world lands in the moved cell's.
fn moved(p: Point3<f64>) -> Point3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), YAW_RAD) * p
        + Vector3::new(SHIFT_M[0], SHIFT_M[1], 0.0)
}

/// A fresh cell with `[station]` and the robot's base moved together, its three classes locked.
fn moved_cell(name: &str) -> PathBuf {
    let dir = common::fresh_cell(name);
    std::fs::copy(
        root().join("trajectories/handover_rula.toml"),
        dir.join("trajectories/handover_rula.toml"),
    )
    .unwrap();
    let path = dir.join("config/cell.toml");
    let shipped = std::fs::read_to_string(&path).unwrap();
    let base = moved(Point3::new(1.35, 0.0, 0.65));
    let text = [
        (
            "base_xyz_m = [1.35, 0.0, 0.65]",
            format!("base_xyz_m = [{:?}, {:?}, {:?}]", base.x, base.y, base.z),
        ),
        (
            "base_rpy_rad = [0.0, 0.0, 3.141592653589793]",
            format!(
                "base_rpy_rad = [0.0, 0.0, {:?}]",
                std::f64::consts::PI + YAW_RAD
            ),
        ),
        (
            "xyz_m = [0.0, 0.0, 0.0]",
            format!("xyz_m = [{:?}, {:?}, 0.0]", SHIFT_M[0], SHIFT_M[1]),
        ),
        ("yaw_rad = 0.0", format!("yaw_rad = {YAW_RAD:?}")),
    ]
    .iter()
    .fold(shipped.clone(), |text, (from, to)| {
        assert!(
            text.contains(from),
            "the shipped cell.toml changed: update this test ({from})"
        );
        text.replacen(from, to, 1)
    });
    std::fs::write(&path, text).unwrap();
    for class in ["c1", "c2", "c3"] {
        let (code, out, err) = common::outcome(
            Command::new(env!("CARGO_BIN_EXE_ergocell"))
                .args(["trajectories", "lock", "--class", class, "--cell"])
                .arg(&path)
                .arg("--trajectories-dir")
                .arg(dir.join("trajectories")),
        );
        assert_eq!(code, 0, "{out}{err}");
    }
    dir
}

#[test]
fn a_station_and_robot_moved_together_lock_the_same_samples_and_agree_on_the_handover_point() {
    let dir = moved_cell("moved-cell");
    let cell_text = std::fs::read_to_string(dir.join("config/cell.toml")).unwrap();
    let cell = CellConfig::from_toml_str(&cell_text).unwrap();
    let settings = CellSettings::from_toml_str(&cell_text, "moved cell.toml").unwrap();
    let urdf = std::fs::read_to_string(dir.join("config").join(&cell.robot.urdf)).unwrap();
    for class in TrajectoryClass::ALL {
        let read = |d: &Path| {
            let text =
                std::fs::read_to_string(d.join(format!("trajectories/locks/{class}.lock.toml")))
                    .unwrap();
            LockFile::from_toml_str(class, &text).unwrap()
        };
        let (reference, relocked) = (read(root()), read(&dir));
        // The same trajectory: every sample's joints, and the handover point in the station's frame.
        assert_eq!(
            reference.trajectory.point.len(),
            relocked.trajectory.point.len()
        );
        for (a, b) in reference
            .trajectory
            .point
            .iter()
            .zip(&relocked.trajectory.point)
        {
            assert!(
                (a.time_s - b.time_s).abs() < 1e-9,
                "{class}: {} vs {} s",
                a.time_s,
                b.time_s
            );
            for (x, y) in a.positions_rad.iter().zip(&b.positions_rad) {
                assert!((x - y).abs() < 1e-9, "{class}: {x} vs {y}");
            }
        }
        let h = relocked.summary.handover_station_m;
        for (x, y) in reference.summary.handover_station_m.iter().zip(h) {
            assert!((x - y).abs() < 1e-9, "{class}: handover {x} vs {y}");
        }
        // In the world: where the session puts it, where the simulator's experiments put it, where
        // the robot markers draw it, and where it is (the reference cell's point, moved).
        let session = ergocell_robot::handover_world(&settings.session.T_world_station, h);
        let sim = cell.handover_world(h);
        let spec = std::fs::read_to_string(dir.join(format!("trajectories/{class}.toml"))).unwrap();
        let markers = ergocell::robot_markers::RobotGeometry::from_texts(&cell_text, &urdf, &spec)
            .unwrap()
            .handover_world();
        let expected = moved(Point3::from(reference.summary.handover_station_m));
        for (who, p) in [("session", session), ("sim", sim), ("markers", markers)] {
            assert!(
                (p - expected).norm() < 1e-9,
                "{class}: {who} puts the handover at {p:?}, expected {expected:?}"
            );
        }
    }
}

#[test]
fn the_demo_on_a_moved_cell_serves_the_operator_at_the_moved_station() {
    let dir = moved_cell("moved-cell-demo");
    let out = dir.join("demo.mcap");
    let cycles = 2;
    let (code, stdout, stderr) = common::outcome(
        Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(&dir)
            .args(["--log", "error", "demo", "--no-faults", "--cycles"])
            .arg(cycles.to_string())
            .args([
                "--cell",
                "config/cell.toml",
                "--trajectories",
                "trajectories",
                "--out",
            ])
            .arg(&out),
    );
    assert_eq!(code, 0, "{stdout}{stderr}");
    let bytes = std::fs::read(&out).unwrap();
    let messages = || {
        mcap::MessageStream::new(&bytes)
            .unwrap()
            .map(Result::unwrap)
    };
    let states: Vec<ergocell_bridge::msg::SessionState> = messages()
        .filter(|m| m.channel.topic == ergocell_bridge::topics::SESSION_STATE)
        .map(|m| ergocell_bridge::cdr::decode(&m.data).unwrap())
        .collect();
    let last = states.last().unwrap();
    assert_eq!(
        (
            last.state.as_str(),
            last.parts_taken,
            last.height_class.as_str()
        ),
        ("session_ended", cycles, "c1"),
        "{stdout}"
    );
    // The operator was measured standing at the moved station: the fused skeleton (the landmarks'
    // sphere list) when the class was decided has its per-axis median over the station, not over
    // the world's origin 0.2 m away.
    let decided = states
        .iter()
        .find(|s| s.state == "class_decided")
        .unwrap()
        .header
        .stamp
        .to_nanos();
    let skeleton = messages()
        .filter(|m| m.channel.topic == ergocell_bridge::topics::SKELETON)
        .map(|m| {
            ergocell_bridge::cdr::decode::<ergocell_bridge::msg::MarkerArray>(&m.data).unwrap()
        })
        .filter_map(|a| a.markers.into_iter().find(|m| m.id == 0))
        .take_while(|m| m.header.stamp.to_nanos() <= decided)
        .last()
        .expect("a skeleton before the class was decided");
    let median = |f: fn(&ergocell_bridge::msg::Point) -> f64| {
        let mut v: Vec<f64> = skeleton.points.iter().map(f).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (x, y) = (median(|p| p.x), median(|p| p.y));
    // In the station's frame: ahead of the station's origin by the face and hands in front of the
    // feet, and not to either side (at the world's origin it would be 0.14 m to the right).
    let (dx, dy) = (x - SHIFT_M[0], y - SHIFT_M[1]);
    let ahead = dx * YAW_RAD.cos() + dy * YAW_RAD.sin();
    let aside = -dx * YAW_RAD.sin() + dy * YAW_RAD.cos();
    assert!(
        (0.0..0.15).contains(&ahead) && aside.abs() < 0.05,
        "the operator's landmarks centre on ({x:.3}, {y:.3}): {ahead:.3} m ahead of the station, \
         {aside:.3} m to its left"
    );
    // The robot markers draw c2's handover point where the moved cell puts it.
    let reference = LockFile::from_toml_str(
        TrajectoryClass::C2,
        &std::fs::read_to_string(root().join("trajectories/locks/c2.lock.toml")).unwrap(),
    )
    .unwrap();
    let expected = moved(Point3::from(reference.summary.handover_station_m));
    let marker = messages()
        .filter(|m| m.channel.topic == ergocell_bridge::topics::ROBOT_MARKERS)
        .map(|m| {
            ergocell_bridge::cdr::decode::<ergocell_bridge::msg::MarkerArray>(&m.data).unwrap()
        })
        .find_map(|a| a.markers.into_iter().find(|m| m.id == 1))
        .expect("a handover marker recorded");
    let p = &marker.pose.position;
    assert!(
        (Point3::new(p.x, p.y, p.z) - expected).norm() < 1e-9,
        "marker at {p:?}, expected {expected:?}"
    );
}
