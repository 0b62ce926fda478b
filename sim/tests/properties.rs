//! Property-style checks over seeded random inputs (cheap enough to run on every `cargo test`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_sim::{ArmPosture, LegPosture, Operator, Posture, ReachConfig};
use ergocell_skeleton::Landmark as L;
use nalgebra::{Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.random::<f64>()
}

fn random_arm(rng: &mut ChaCha8Rng) -> ArmPosture {
    ArmPosture {
        flexion_rad: uniform(rng, -0.8, 3.0),
        abduction_rad: uniform(rng, -0.6, 2.0),
        humeral_rotation_rad: uniform(rng, -1.0, 1.5),
        elbow_flexion_rad: uniform(rng, 0.0, 2.5),
        wrist_flexion_rad: uniform(rng, -1.0, 1.0),
        shoulder_raise_m: uniform(rng, 0.0, 0.04),
        wrist_deviation_rad: 0.0,
    }
}

fn random_leg(rng: &mut ChaCha8Rng) -> LegPosture {
    LegPosture {
        hip_flexion_rad: uniform(rng, -0.4, 1.2),
        knee_flexion_rad: uniform(rng, 0.0, 1.8),
    }
}

#[test]
fn every_posture_keeps_every_segment_length_and_the_feet_off_the_floor_never_below_it() {
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    for _ in 0..500 {
        let h = uniform(&mut rng, 1.4, 2.1);
        let op = Operator::new(h).unwrap();
        let q = Posture {
            position_m: [uniform(&mut rng, -3.0, 3.0), uniform(&mut rng, -3.0, 3.0)],
            heading_rad: uniform(&mut rng, -4.0, 4.0),
            trunk_flexion_rad: uniform(&mut rng, -0.2, 1.4),
            trunk_side_bend_rad: uniform(&mut rng, -0.4, 0.4),
            trunk_twist_rad: uniform(&mut rng, -0.6, 0.6),
            neck_flexion_rad: uniform(&mut rng, -0.6, 0.9),
            neck_yaw_rad: uniform(&mut rng, -1.2, 1.2),
            left_arm: random_arm(&mut rng),
            right_arm: random_arm(&mut rng),
            left_leg: random_leg(&mut rng),
            right_leg: random_leg(&mut rng),
        };
        let p = op.landmarks(&q);
        let len = |a: L, b: L| (p[a.index()] - p[b.index()]).norm();
        for (a, b, ratio) in [
            (L::LeftElbow, L::LeftWrist, 0.146),
            (L::RightElbow, L::RightWrist, 0.146),
            (L::LeftHip, L::LeftKnee, 0.245),
            (L::RightKnee, L::RightAnkle, 0.246),
            (L::LeftHip, L::RightHip, 0.191),
        ] {
            assert!((len(a, b) - ratio * h).abs() < 1e-9, "{a}-{b}");
        }
        // shrugging moves the shoulder, so the upper arm is measured from the raised shoulder
        assert!((len(L::LeftShoulder, L::LeftElbow) - 0.186 * h).abs() < 1e-9);
        // both ankles at or above their standing height, one of them exactly there
        let (al, ar) = (p[L::LeftAnkle.index()].z, p[L::RightAnkle.index()].z);
        assert!(al >= 0.039 * h - 1e-9 && ar >= 0.039 * h - 1e-9);
        assert!((al.min(ar) - 0.039 * h).abs() < 1e-9);
        assert!(p.iter().all(|x| x.coords.iter().all(|c| c.is_finite())));
    }
}

#[test]
fn random_targets_within_reach_in_front_are_reached_within_a_centimetre() {
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    let cfg = ReachConfig::default();
    for _ in 0..40 {
        let h = uniform(&mut rng, 1.5, 2.0);
        let op = Operator::new(h).unwrap();
        let base = Posture::default();
        let shoulder = op.landmarks(&base)[L::RightShoulder.index()];
        let azimuth = uniform(&mut rng, -0.9, 0.5);
        let elevation = uniform(&mut rng, -0.9, 0.9);
        let r = uniform(&mut rng, 0.45, 0.85) * ergocell_sim::reach::arm_reach_m(&op);
        let dir = Vector3::new(
            elevation.cos() * azimuth.cos(),
            elevation.cos() * azimuth.sin(),
            elevation.sin(),
        );
        let target: Point3<f64> = shoulder + dir * r;
        let sol = ergocell_sim::solve_reach(&op, &base, &target, &cfg).unwrap();
        assert!(
            sol.miss_m < 0.01,
            "{h:.2} m to {target:?} (az {azimuth:.2}, el {elevation:.2}): miss {:.3} m",
            sol.miss_m
        );
        let q = sol.posture.right_arm;
        for (i, v) in [
            q.flexion_rad,
            q.abduction_rad,
            q.humeral_rotation_rad,
            q.elbow_flexion_rad,
            q.wrist_flexion_rad,
            sol.posture.trunk_flexion_rad,
        ]
        .into_iter()
        .enumerate()
        {
            assert!(v >= cfg.lower_rad[i] - 1e-12 && v <= cfg.upper_rad[i] + 1e-12);
        }
    }
}
