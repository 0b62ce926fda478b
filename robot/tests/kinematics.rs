//! Forward kinematics against hand-computed poses, the Jacobian against finite differences and `k`,
//! and IK (limits respected, unreachable targets named).

// Test and bench helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use approx::assert_relative_eq;
use ergocell_robot::ik::{solve_ik, IkSettings};
use ergocell_robot::model::tool_transform;
use ergocell_robot::pose::isometry_from_xyz_rpy;
use ergocell_robot::RobotError;
use nalgebra::{Isometry3, Vector3};
use std::f64::consts::FRAC_PI_2;

const ZERO: [f64; 7] = [0.0; 7];

fn flange(q: &[f64]) -> Vector3<f64> {
    common::shipped()
        .model
        .fk_flange(q)
        .unwrap()
        .translation
        .vector
}

#[test]
fn fk_straight_up_puts_the_flange_at_1_306_m() {
    // Sum of the joint offsets: 0.1575 + 0.2025 + 0.2045 + 0.2155 + 0.1845 + 0.2155 + 0.081 + 0.045.
    assert_relative_eq!(
        flange(&ZERO),
        Vector3::new(0.0, 0.0, 1.306),
        epsilon = 1e-12
    );
    let T = common::shipped().model.fk_flange(&ZERO).unwrap();
    assert_relative_eq!(T.rotation.angle(), 0.0, epsilon = 1e-12);
}

#[test]
fn fk_a2_at_90_deg_lays_the_arm_along_plus_x() {
    // A2 (axis +y) sits 0.360 m up; rotating +90° about y maps the remaining 0.946 m along z onto +x.
    let q = [0.0, FRAC_PI_2, 0.0, 0.0, 0.0, 0.0, 0.0];
    assert_relative_eq!(flange(&q), Vector3::new(0.946, 0.0, 0.360), epsilon = 1e-12);
}

#[test]
fn fk_a4_at_90_deg_folds_the_forearm_toward_minus_x() {
    // A4 (axis −y) sits 0.780 m up; +90° about −y maps the remaining 0.526 m along z onto −x.
    let q = [0.0, 0.0, 0.0, FRAC_PI_2, 0.0, 0.0, 0.0];
    assert_relative_eq!(
        flange(&q),
        Vector3::new(-0.526, 0.0, 0.780),
        epsilon = 1e-12
    );
}

#[test]
fn fk_a1_at_90_deg_turns_the_a2_reach_onto_plus_y() {
    let q = [FRAC_PI_2, FRAC_PI_2, 0.0, 0.0, 0.0, 0.0, 0.0];
    assert_relative_eq!(flange(&q), Vector3::new(0.0, 0.946, 0.360), epsilon = 1e-12);
}

#[test]
fn fk_a6_at_90_deg_bends_the_flange_only() {
    // A6 (axis +y) sits 1.180 m up; the 0.126 m to the flange turn onto +x.
    let q = [0.0, 0.0, 0.0, 0.0, 0.0, FRAC_PI_2, 0.0];
    assert_relative_eq!(flange(&q), Vector3::new(0.126, 0.0, 1.180), epsilon = 1e-12);
}

#[test]
fn fk_matches_k_chain_on_random_poses() {
    let s = common::shipped();
    let robot = urdf_rs::read_from_string(&s.urdf).unwrap();
    let chain = k::Chain::<f64>::from(&robot);
    let serial = k::SerialChain::from_end(chain.find_link("flange").unwrap());
    for i in 0..20 {
        let q: Vec<f64> = (0..7)
            .map(|j| (f64::from(i * 7 + j) * 0.37).sin() * 1.5)
            .collect();
        serial.set_joint_positions_unchecked(&q);
        serial.update_transforms();
        let T_k = serial.end_transform();
        let T_ours = s.model.fk_flange(&q).unwrap();
        assert_relative_eq!(
            T_k.translation.vector,
            T_ours.translation.vector,
            epsilon = 1e-12
        );
        assert!(T_k.rotation.angle_to(&T_ours.rotation) < 1e-9);
        let J_k = k::jacobian(&serial);
        let J_ours = s.model.jacobian(&q, &Isometry3::identity()).unwrap();
        for r in 0..6 {
            for c in 0..7 {
                assert_relative_eq!(J_k[(r, c)], J_ours[(r, c)], epsilon = 1e-9);
            }
        }
    }
}

#[test]
fn jacobian_matches_finite_differences() {
    let s = common::shipped();
    let T_flange_tcp = tool_transform([0.0, 0.0, 0.15]);
    let h = 1e-6;
    for i in 0..10 {
        let q: Vec<f64> = (0..7)
            .map(|j| (f64::from(i * 11 + j * 3) * 0.61).cos() * 1.2)
            .collect();
        let J = s.model.jacobian(&q, &T_flange_tcp).unwrap();
        let T0 = s.model.fk_tcp(&q, &T_flange_tcp).unwrap();
        for c in 0..7 {
            let mut qp = q.clone();
            qp[c] += h;
            let mut qm = q.clone();
            qm[c] -= h;
            let Tp = s.model.fk_tcp(&qp, &T_flange_tcp).unwrap();
            let Tm = s.model.fk_tcp(&qm, &T_flange_tcp).unwrap();
            let dp = (Tp.translation.vector - Tm.translation.vector) / (2.0 * h);
            // Angular column: the rotation vector of R(q+h) R(q)ᵀ per unit step.
            let dw = (Tp.rotation * T0.rotation.inverse()).scaled_axis() / h;
            let dw_m = (T0.rotation * Tm.rotation.inverse()).scaled_axis() / h;
            for r in 0..3 {
                assert_relative_eq!(J[(r, c)], dp[r], epsilon = 1e-6);
                assert_relative_eq!(J[(r + 3, c)], 0.5 * (dw[r] + dw_m[r]), epsilon = 1e-6);
            }
        }
    }
}

#[test]
fn velocity_and_effort_limits_are_read_from_the_urdf() {
    let s = common::shipped();
    let deg = |x: f64| x.to_degrees();
    let speeds: Vec<f64> = s
        .model
        .joints()
        .iter()
        .map(|j| deg(j.velocity_rad_s))
        .collect();
    let torques: Vec<f64> = s.model.joints().iter().map(|j| j.effort_nm).collect();
    let uppers: Vec<f64> = s.model.joints().iter().map(|j| deg(j.upper_rad)).collect();
    for (got, want) in speeds
        .iter()
        .zip([85.0, 85.0, 100.0, 75.0, 130.0, 135.0, 135.0])
    {
        assert_relative_eq!(*got, want, epsilon = 1e-4);
    }
    assert_eq!(torques, vec![320.0, 320.0, 176.0, 176.0, 110.0, 40.0, 40.0]);
    for (got, want) in uppers
        .iter()
        .zip([170.0, 120.0, 170.0, 120.0, 170.0, 120.0, 175.0])
    {
        assert_relative_eq!(*got, want, epsilon = 1e-4);
    }
    let names: Vec<&str> = s.model.joints().iter().map(|j| j.name.as_str()).collect();
    assert_eq!(
        names,
        ["joint_1", "joint_2", "joint_3", "joint_4", "joint_5", "joint_6", "joint_7"]
    );
}

#[test]
fn ik_from_the_straight_up_pose_converges_within_limits() {
    // k's default JacobianIkSolver (10 tries) fails from here.
    let s = common::shipped();
    let T_flange_tcp = tool_transform([0.0, 0.0, 0.15]);
    let target = isometry_from_xyz_rpy([0.8, 0.1, 0.4], [0.0, FRAC_PI_2, 0.0]);
    let sol = solve_ik(
        &s.model,
        &target,
        &T_flange_tcp,
        &[ZERO.to_vec()],
        &IkSettings::default(),
    )
    .unwrap();
    s.model.check_positions(&sol.positions_rad).unwrap();
    let reached = s.model.fk_tcp(&sol.positions_rad, &T_flange_tcp).unwrap();
    assert!((reached.translation.vector - target.translation.vector).norm() < 1e-4);
    assert!(reached.rotation.angle_to(&target.rotation) < 1e-3);
}

#[test]
fn ik_out_of_reach_names_the_target_and_the_closest_pose() {
    let s = common::shipped();
    let T_flange_tcp = tool_transform([0.0, 0.0, 0.15]);
    let target = isometry_from_xyz_rpy([2.0, 0.0, 0.4], [0.0, FRAC_PI_2, 0.0]);
    let err = solve_ik(
        &s.model,
        &target,
        &T_flange_tcp,
        &[ZERO.to_vec()],
        &IkSettings::default(),
    )
    .unwrap_err();
    match &err {
        RobotError::Unreachable {
            target,
            closest,
            position_error_m,
            ..
        } => {
            assert_relative_eq!(target.xyz_m[0], 2.0, epsilon = 1e-12);
            assert_eq!(target.frame, "link_0");
            // The arm reaches at most 0.946 + 0.15 m from A2: the closest pose is about 0.9 m short.
            assert!(*position_error_m > 0.8, "{err}");
            assert!(closest.xyz_m[0] > 0.9 && closest.xyz_m[0] < 1.2, "{err}");
        }
        other => panic!("expected Unreachable, got {other:?}"),
    }
    assert!(err.to_string().contains("target unreachable"));
}

#[test]
fn a_urdf_without_the_flange_link_is_named_in_the_error() {
    let s = common::shipped();
    let err = ergocell_robot::RobotModel::from_urdf_str(&s.urdf, "link_0", "tool0").unwrap_err();
    assert!(
        matches!(err, RobotError::UnknownLink { ref link, .. } if link == "tool0"),
        "{err}"
    );
}

#[test]
fn a_joint_without_velocity_limit_is_rejected() {
    let s = common::shipped();
    let urdf = s
        .urdf
        .replacen("velocity=\"1.4835299\"", "velocity=\"0\"", 1);
    let err = ergocell_robot::RobotModel::from_urdf_str(&urdf, "link_0", "flange").unwrap_err();
    assert!(
        matches!(err, RobotError::InvalidLimit { ref joint, .. } if joint == "joint_1"),
        "{err}"
    );
}

#[test]
fn another_serial_urdf_loads_the_same_way() {
    // A 6-axis test fixture (not a real robot's data): the model works for any revolute serial arm.
    let urdf = r#"<robot name="six_axis_fixture">
      <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="l4"/><link name="l5"/><link name="tool0"/>
      <joint name="a1" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 0.4"/><axis xyz="0 0 -1"/><limit lower="-3" upper="3" velocity="6" effort="100"/></joint>
      <joint name="a2" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="0.025 0 0"/><axis xyz="0 1 0"/><limit lower="-3" upper="1" velocity="6" effort="100"/></joint>
      <joint name="a3" type="revolute"><parent link="l2"/><child link="l3"/><origin xyz="0.455 0 0"/><axis xyz="0 1 0"/><limit lower="-2" upper="2.5" velocity="6" effort="100"/></joint>
      <joint name="a4" type="revolute"><parent link="l3"/><child link="l4"/><origin xyz="0.42 0 0.035"/><axis xyz="-1 0 0"/><limit lower="-3" upper="3" velocity="6" effort="100"/></joint>
      <joint name="a5" type="revolute"><parent link="l4"/><child link="l5"/><origin xyz="0 0 0"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" velocity="6" effort="100"/></joint>
      <joint name="a6" type="revolute"><parent link="l5"/><child link="tool0"/><origin xyz="0.08 0 0"/><axis xyz="-1 0 0"/><limit lower="-6" upper="6" velocity="6" effort="100"/></joint>
    </robot>"#;
    let model = ergocell_robot::RobotModel::from_urdf_str(urdf, "base", "tool0").unwrap();
    assert_eq!(model.dof(), 6);
    let T = model.fk_flange(&[0.0; 6]).unwrap();
    assert_relative_eq!(
        T.translation.vector,
        Vector3::new(0.98, 0.0, 0.435),
        epsilon = 1e-12
    );
    let names = ergocell_robot::config::ControllerJointNames::default()
        .names(6)
        .unwrap();
    assert_eq!(names[5], "joint_6");
}

#[test]
fn lever_arms_are_the_reach_beyond_each_joint_and_bound_the_arms_displacement() {
    let s = common::shipped();
    // Straight up: A2 sits 0.360 m up and A4 0.780 m up (above), the flange at 1.306 m, a tool 0.15 m
    // further along z.
    let tool = tool_transform([0.0, 0.0, 0.15]);
    let arms = s.model.joint_lever_arms_m(&ZERO, &tool).unwrap();
    assert_eq!(arms.len(), 7);
    assert_relative_eq!(arms[1], 1.456 - 0.360, epsilon = 1e-12);
    assert_relative_eq!(arms[3], 1.456 - 0.780, epsilon = 1e-12);
    assert!(arms.windows(2).all(|w| w[0] >= w[1] - 1e-12), "{arms:?}");
    // The bound: a small error δ at joint j moves no point of the arm farther than arms[j]·|δ|.
    let q = [0.3, -0.7, 0.5, -1.2, 0.4, 0.9, -0.2];
    let arms = s.model.joint_lever_arms_m(&q, &tool).unwrap();
    let before = s.model.link_points(&q, &tool).unwrap();
    for j in 0..7 {
        let mut moved = q;
        moved[j] += 0.01;
        let after = s.model.link_points(&moved, &tool).unwrap();
        let worst = before
            .iter()
            .zip(&after)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0_f64, f64::max);
        assert!(
            worst <= arms[j] * 0.01 + 1e-12,
            "joint {j}: {worst} > {}",
            arms[j] * 0.01
        );
        if j == 1 {
            // A2's axis is across the arm: its bound is nearly reached.
            assert!(
                worst >= 0.8 * arms[j] * 0.01,
                "the bound is far from tight: {worst}"
            );
        }
    }
    assert!(s.model.joint_lever_arms_m(&[0.0; 3], &tool).is_err());
}

#[test]
fn path_tolerances_from_the_lock_keep_the_whole_arm_within_its_separation_margin() {
    use ergocell_robot::monitor::path_tolerances;
    use ergocell_robot::{LockFile, TrajectoryClass};
    let s = common::shipped();
    let lock = LockFile::from_toml_str(
        TrajectoryClass::C2,
        &common::read("trajectories/locks/c2.lock.toml"),
    )
    .unwrap();
    let margin = lock.summary.min_separation_m - lock.summary.required_separation_m;
    assert!(margin > 0.1, "{margin}");
    let tool = tool_transform(common::spec(TrajectoryClass::C2).tool.tcp_from_flange_m);
    let points = &lock.trajectory.point;
    let tol = path_tolerances(&s.model, &tool, points, margin, 0.05).unwrap();
    assert_eq!(tol.len(), 7);
    assert!(tol.iter().all(|&t| t > 0.0 && t <= 0.05), "{tol:?}");
    // The base joints carry the whole arm: tighter than the cap.
    assert!(tol[0] < 0.05 && tol[1] < 0.05, "{tol:?}");
    // Every joint at its tolerance at once, on every locked sample, in both signs of each joint's
    // error: no point of the arm moves by more than the margin.
    let mut worst = 0.0_f64;
    for p in points {
        let q = &p.positions_rad;
        let before = s.model.link_points(q, &tool).unwrap();
        for signs in 0..(1u32 << 7) {
            let moved: Vec<f64> = q
                .iter()
                .zip(&tol)
                .enumerate()
                .map(|(j, (x, t))| if signs >> j & 1 == 1 { x + t } else { x - t })
                .collect();
            let after = s.model.link_points(&moved, &tool).unwrap();
            for (a, b) in before.iter().zip(&after) {
                worst = worst.max((a - b).norm());
            }
        }
    }
    assert!(worst <= margin, "{worst} m > margin {margin} m");
    assert!(
        worst >= 0.3 * margin,
        "the tolerances are needlessly tight: {worst} m of {margin} m"
    );
    // No margin, no tolerance: an error.
    assert!(path_tolerances(&s.model, &tool, points, 0.0, 0.05).is_err());
    // The lock carries what the validation derived (signed with it): the same tolerances, capped
    // only at half a turn; the cell's cap (here 0.05 rad) only tightens them.
    let locked = &lock.summary.path_tolerance_rad;
    let derived = path_tolerances(
        &s.model,
        &tool,
        points,
        margin,
        ergocell_robot::validate::PATH_TOLERANCE_MAX_RAD,
    )
    .unwrap();
    assert_eq!(locked, &derived);
    for (l, t) in locked.iter().zip(&tol) {
        assert_eq!(l.min(0.05), *t);
    }
}

/// A lock of the earlier format (no path tolerances) is refused with what to do, not with the field
/// it lacks; a lock whose tolerances were edited fails its own hash.
#[test]
fn a_lock_without_its_path_tolerances_is_refused_saying_relock() {
    use ergocell_robot::{LockFile, TrajectoryClass};
    let text = common::read("trajectories/locks/c2.lock.toml");
    let old: String = text
        .lines()
        .filter(|l| !l.starts_with("path_tolerance_rad"))
        .map(|l| l.replace("ergocell-trajectory-lock/4", "ergocell-trajectory-lock/3") + "\n")
        .collect();
    let e = LockFile::from_toml_str(TrajectoryClass::C2, &old)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("format `ergocell-trajectory-lock/3`") && e.contains("lock it again"),
        "{e}"
    );
    let loosened = text.replacen("path_tolerance_rad = [0.0", "path_tolerance_rad = [0.9", 1);
    assert_ne!(loosened, text);
    let e = LockFile::from_toml_str(TrajectoryClass::C2, &loosened)
        .unwrap_err()
        .to_string();
    assert!(e.contains("content was edited"), "{e}");
}
