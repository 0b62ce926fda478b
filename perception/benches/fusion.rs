//! One frame of 33 landmarks → fused skeleton: undistortion + triangulation + fusion.
//!
//! Rigs: 6 cameras (3 stereo pairs, the seed paper's cell) and 16 cameras (8 pairs), cameras in a ring
//! 3 m around the operator, 1280×720, mild distortion; detections with ~2 px deterministic noise.
//! Run: `cargo bench -p ergocell_perception --bench fusion`. Figures are reported in the closing notes
//! of the work that changed them (machine: the project's 2-core CI machine).

#![allow(clippy::unwrap_used)]

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use ergocell_perception::detections::{Keypoint2, View2};
use ergocell_perception::{
    Camera, CameraId, CameraRig, Distortion, Frame2, FusionEngine, FusionMethod, Intrinsics,
};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Vector3};

fn rig(n: usize) -> CameraRig {
    let cams = (0..n)
        .map(|k| {
            let pair = k / 2;
            let angle = pair as f64 * std::f64::consts::TAU / (n / 2) as f64;
            let centre = Point3::new(3.0 * angle.cos(), 3.0 * angle.sin(), 2.0);
            let target = Point3::new(0.0, 0.0, 1.0);
            let x = (target - centre).cross(&Vector3::z()).normalize();
            let offset = x * if k % 2 == 0 { -0.06 } else { 0.06 };
            // both cameras of a pair look the same way (parallel axes, 12 cm baseline)
            Camera::look_at(
                CameraId::new(format!("cam_{k}")).unwrap(),
                centre + offset,
                target + offset,
                Vector3::z(),
                Intrinsics {
                    fx: 700.0,
                    fy: 700.0,
                    cx: 640.0,
                    cy: 360.0,
                    skew: 0.0,
                    width_px: 1280,
                    height_px: 720,
                },
                Distortion {
                    k1: -0.04,
                    k2: 0.01,
                    p1: 0.0002,
                    p2: -0.0003,
                    k3: 0.0,
                },
            )
            .unwrap()
        })
        .collect();
    CameraRig::new(cams, &[], None).unwrap()
}

fn frame(rig: &CameraRig) -> Frame2 {
    let body: [Point3<f64>; LANDMARK_COUNT] = std::array::from_fn(|i| {
        Point3::new(
            0.1 * ((i * 7) % 5) as f64 - 0.2,
            0.05 * ((i * 3) % 4) as f64 - 0.1,
            0.1 + 1.6 * i as f64 / 33.0,
        )
    });
    let views = rig
        .cameras()
        .iter()
        .enumerate()
        .map(|(k, cam)| {
            let mut v = View2::empty(k, 0);
            for lm in Landmark::ALL {
                let px = cam.project(&body[lm.index()]).unwrap();
                let noise = ((k * 31 + lm.index() * 17) % 9) as f64 * 0.5 - 2.0;
                v.set(
                    lm,
                    Some(Keypoint2::new(px.x + noise, px.y - 0.7 * noise, 0.9).unwrap()),
                );
            }
            v
        })
        .collect();
    Frame2 {
        stamp_nanos: 0,
        views,
    }
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("fuse_one_frame");
    for n in [6usize, 16] {
        let rig = rig(n);
        let frame = frame(&rig);
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
