//! Full stereo calibration of OpenCV's 13-pair sample (`../shared/data/opencv-stereo-sample`):
//! decode 26 JPEGs, detect and refine the corners, calibrate both cameras, stereo refinement.
//!
//! Figures (release, `cargo bench -p ergocell_calibration`), AMD EPYC, 2 cores, shared machine,
//! ergocell 0.1.0, Rust 1.95:
//! - `stereo_13_pairs` (single-threaded): 265–318 ms (three runs; the machine is shared);
//! - `detect_one_image` (left01, decoded): 8.5 ms (ChESS ≈ 4 ms, blur ≈ 2 ms);
//! - OpenCV 5.0.0 (`docs/opencv_calibration_reference.py 5 1`, Python, same steps, median of 5):
//!   146 ms with 1 thread, 155–170 ms with 2.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use criterion::{criterion_group, criterion_main, Criterion};
use ergocell_calibration::{
    calibrate_stereo, detect_checkerboard, BoardSpec, CameraViews, GrayImage, RigOptions,
};
use ergocell_perception::CameraId;

const PAIRS: [&str; 13] = [
    "01", "02", "03", "04", "05", "06", "07", "08", "09", "11", "12", "13", "14",
];

fn load(side: &str) -> Vec<Vec<u8>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data/opencv-stereo-sample");
    PAIRS
        .iter()
        .map(|n| std::fs::read(dir.join(format!("{side}{n}.jpg"))).unwrap())
        .collect()
}

fn views(side: &str, images: &[Vec<u8>], board: &BoardSpec) -> CameraViews {
    let mut size = (0, 0);
    let frames = images
        .iter()
        .map(|bytes| {
            let img = GrayImage::decode(bytes, side).unwrap();
            size = img.size_px();
            detect_checkerboard(&img, board).ok().map(|d| d.corners)
        })
        .collect();
    CameraViews {
        id: CameraId::new(side).unwrap(),
        image_size_px: size,
        frames,
    }
}

fn bench(c: &mut Criterion) {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let (left, right) = (load("left"), load("right"));
    let mut group = c.benchmark_group("calibration");
    group.sample_size(10);
    group.bench_function("stereo_13_pairs", |b| {
        b.iter(|| {
            let l = views("left", &left, &board);
            let r = views("right", &right, &board);
            calibrate_stereo(l, r, &board, RigOptions::default()).unwrap()
        });
    });
    group.bench_function("detect_one_image", |b| {
        let img = GrayImage::decode(&left[0], "left01").unwrap();
        b.iter(|| detect_checkerboard(&img, &board).unwrap());
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
