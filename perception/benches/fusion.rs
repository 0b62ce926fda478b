//! One frame of 33 landmarks → fused skeleton: undistortion + triangulation + fusion.
//!
//! Rigs (`rig.rs`): 6, 8 and 16 cameras (3, 4 and 8 stereo pairs), cameras in a ring 3 m around the
//! operator, 1280×720, mild distortion; detections with ~2 px deterministic noise.
//! Run: `cargo bench -p ergocell_perception --bench fusion`. Figures are in `docs/measurements.md`
//! (machine: the project's 2-core CI machine).

#![allow(clippy::unwrap_used)]

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use ergocell_perception::{FusionEngine, FusionMethod};

#[path = "rig.rs"]
mod rig;

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("fuse_one_frame");
    for n in [6usize, 8, 16] {
        let rig = rig::rig(n);
        let frame = rig::frame(&rig);
        for (name, method) in [
            ("paper", FusionMethod::Paper),
            ("default", FusionMethod::Default),
        ] {
            let mut engine = FusionEngine::new(rig.clone(), method).unwrap();
            group.bench_with_input(BenchmarkId::new(name, n), &frame, |b, f| {
                b.iter(|| engine.fuse(std::hint::black_box(f)).unwrap());
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
