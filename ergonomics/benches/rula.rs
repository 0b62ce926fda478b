//! RULA for both sides of one frame: angle extraction from a 33-landmark skeleton, the worksheet for
//! left and right, Tables A/B/C, the muscle-use trackers.
//!
//! Figures (record machine and version here when they change):
//! - 2026-11-23, ergocell 0.1.0, rustc 1.95.0, `cargo bench -p ergocell_ergonomics --bench rula` on the
//!   shared 2-core AMD EPYC development VM (two other builds running): 0.96 µs per frame, both sides
//!   (criterion interval 0.92–1.01 µs).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ergocell_ergonomics::pose::{ArmPose, PoseSpec};
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor, UpVector};
use nalgebra::{Rotation3, Vector3};

fn bench_rula(c: &mut Criterion) {
    let spec = PoseSpec {
        trunk_flexion_rad: 25f64.to_radians(),
        neck_flexion_rad: 15f64.to_radians(),
        right_arm: ArmPose {
            flexion_rad: 60f64.to_radians(),
            elbow_flexion_rad: 70f64.to_radians(),
            wrist_flexion_rad: 20f64.to_radians(),
            ..ArmPose::default()
        },
        world_rotation: Rotation3::from_euler_angles(0.3, -0.2, 1.1),
        world_translation: Vector3::new(1.0, 2.0, 0.5),
        ..PoseSpec::default()
    };
    let skeleton = spec.skeleton();
    let Ok(up) = UpVector::new(spec.up()) else {
        panic!("the pose's up vector is a unit vector")
    };
    let Ok(mut assessor) = RulaAssessor::new(AssessmentConfig::new(up)) else {
        panic!("default config is valid")
    };
    c.bench_function("rula_both_sides_one_frame", |b| {
        b.iter(|| {
            let Ok(frame) = assessor.assess(black_box(&skeleton)) else {
                panic!("frame scores")
            };
            black_box(frame.headline().map(|h| h.scores.final_score))
        });
    });
}

criterion_group!(benches, bench_rula);
criterion_main!(benches);
