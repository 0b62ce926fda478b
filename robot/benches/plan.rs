//! Planning + validation of one class: IK for the via points and the handover, the clarabel QP
//! (7 joints × 100 knots × (q, v, a) = 2100 variables), and the dense re-checks (joint limits at 8
//! samples per interval; TCP speed, separation and singularity margin at 4 samples per interval).
//!
//! Run: `cargo bench -p ergocell_robot --bench plan`.
//! Figures (AMD EPYC, 2 vCPUs shared with two other builds (load ~2.3), rustc 1.95, release,
//! one thread; criterion median of 20 samples):
//!   c1 17.4 ms, c2 15.3 ms, c3 16.9 ms per plan + validate; of which the clarabel solve ~12.5 ms
//!   (8 interior-point iterations, 2100 variables, 1435 equality + 4200 inequality rows).
//! Target: ≤ 20 ms per class on one core. With the variables ordered joint-major instead of
//! knot-major the same QP took ~17 ms and plan + validate ~23 ms.

// Test and bench helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use criterion::{criterion_group, criterion_main, Criterion};
use ergocell_robot::{
    plan_and_validate, CellConfig, InputHashes, PlanInputs, RobotModel, TrajectoryClass,
    TrajectorySpec,
};

fn read(rel: &str) -> String {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    std::fs::read_to_string(root.join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn bench(c: &mut Criterion) {
    let cell = CellConfig::from_toml_str(&read("config/cell.toml")).unwrap();
    let urdf = read(&format!("config/{}", cell.robot.urdf));
    let model =
        RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link).unwrap();
    let mut group = c.benchmark_group("plan_and_validate");
    group.sample_size(20);
    for class in TrajectoryClass::ALL {
        let text = read(&format!("trajectories/{class}.toml"));
        let spec = TrajectorySpec::from_toml_str(&text).unwrap();
        let hashes = InputHashes::new(
            text.as_bytes(),
            urdf.as_bytes(),
            &cell,
            ergocell_robot::TrustFiles {
                allowed_signers: b"",
                revoked_keys: b"",
            },
            "bench",
        );
        let inputs = PlanInputs {
            model: &model,
            cell: &cell,
            spec: &spec,
            hashes: &hashes,
        };
        let v = plan_and_validate(&inputs).unwrap();
        assert!(v.report.accepted, "{}", v.report);
        println!(
            "{class}: QP {} in {} iterations, clarabel solve time {:.2} ms",
            v.report.qp.status, v.report.qp.iterations, v.report.qp.solve_time_ms
        );
        group.bench_function(class.as_str(), |b| {
            b.iter(|| plan_and_validate(std::hint::black_box(&inputs)).unwrap());
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
