//! OpenCV's own stereo sample (`../shared/data/opencv-stereo-sample`, 13 pairs, 9x6 board, 25 mm
//! squares assumed): our calibration against OpenCV's on the same images.
//!
//! OpenCV 5.0.0 (`opencv-python-headless`; `findChessboardCorners` + `cornerSubPix`,
//! `calibrateCamera` with default flags, `stereoCalibrate` with `CALIB_FIX_INTRINSIC`; script
//! `docs/opencv_calibration_reference.py`) on these images, with `cornerSubPix` `winSize = (5, 5)`
//! (an 11×11 px window, the same as ours):
//!
//! | | fx | fy | cx | cy | RMS px |
//! |---|---|---|---|---|---|
//! | OpenCV left  | 532.825 | 532.944 | 342.492 | 233.861 | 0.1955 |
//! | ours left    | 532.821 | 532.939 | 342.485 | 233.850 | 0.1953 |
//! | OpenCV right | 537.450 | 536.967 | 327.588 | 248.884 | 0.2071 |
//! | ours right   | 537.455 | 536.971 | 327.576 | 248.876 | 0.2069 |
//! | stereo | OpenCV RMS 0.2169, baseline 83.206 mm | ours RMS 0.2167, baseline 83.206 mm |
//!
//! With the `winSize = (11, 11)` of OpenCV's `stereo_calib.cpp` (a 23×23 px window, which reaches
//! the next corner on this board) OpenCV gets fx 536.065 / 542.341, RMS 0.408 / 0.458, baseline
//! 83.622 mm: its corners then carry outliers of up to 4.8 px (left02, right02, right05, right13;
//! see `docs/calibration.md`). The reference here is the equal-window configuration.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::sync::OnceLock;

use ergocell_calibration::{
    calibrate_stereo, detect_checkerboard, BoardSpec, CameraViews, GrayImage, RigCalibration,
    RigOptions,
};
use ergocell_perception::CameraId;

const PAIRS: [&str; 13] = [
    "01", "02", "03", "04", "05", "06", "07", "08", "09", "11", "12", "13", "14",
];

fn sample_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/opencv-stereo-sample")
}

fn views(side: &str, board: &BoardSpec) -> CameraViews {
    let mut frames = Vec::new();
    let mut size = (0, 0);
    for n in PAIRS {
        let name = format!("{side}{n}.jpg");
        let bytes = std::fs::read(sample_dir().join(&name))
            .expect("sample image (../shared beside the repo)");
        let img = GrayImage::decode(&bytes, &name).unwrap();
        size = img.size_px();
        match detect_checkerboard(&img, board) {
            Ok(d) => frames.push(Some(d.corners)),
            Err(why) => {
                println!("{name}: rejected: {why}");
                frames.push(None);
            }
        }
    }
    CameraViews {
        id: CameraId::new(side).unwrap(),
        image_size_px: size,
        frames,
    }
}

struct Sample {
    left: CameraViews,
    calib: RigCalibration,
    right: CameraViews,
}

/// The sample calibrated once per test binary (detection + stereo), shared by the tests below.
fn sample() -> &'static Sample {
    static SAMPLE: OnceLock<Sample> = OnceLock::new();
    SAMPLE.get_or_init(|| {
        let board = BoardSpec::new(9, 6, 0.025).unwrap();
        let left = views("left", &board);
        let right = views("right", &board);
        let calib =
            calibrate_stereo(left.clone(), right.clone(), &board, RigOptions::default()).unwrap();
        Sample { left, calib, right }
    })
}

#[test]
fn opencv_sample_matches_opencv() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let Sample { left, calib, right } = sample();
    // every view of this sample is a good one: all 26 images are used
    assert_eq!(left.frames.iter().flatten().count(), 13);
    assert_eq!(right.frames.iter().flatten().count(), 13);
    for (c, s) in calib.single.iter().enumerate() {
        let k = s.intrinsics;
        println!(
            "camera {c}: fx {:.3} fy {:.3} cx {:.3} cy {:.3} rms {:.4} dist {:?}",
            k.fx,
            k.fy,
            k.cx,
            k.cy,
            s.rms_px,
            s.distortion.to_array()
        );
    }
    let baseline = calib.baseline_m(0, 1).unwrap();
    println!(
        "stereo rms {:.4} baseline {:.3} mm",
        calib.rms_px,
        baseline * 1e3
    );
    // OpenCV's numbers (module doc)
    let opencv = [
        (532.825, 532.944, 342.492, 233.861),
        (537.450, 536.967, 327.588, 248.884),
    ];
    for (s, (fx, fy, cx, cy)) in calib.single.iter().zip(opencv) {
        let k = s.intrinsics;
        assert!(
            (k.fx / fx - 1.0).abs() < 0.005,
            "fx {} vs OpenCV {fx}",
            k.fx
        );
        assert!(
            (k.fy / fy - 1.0).abs() < 0.005,
            "fy {} vs OpenCV {fy}",
            k.fy
        );
        assert!((k.cx - cx).abs() < 3.0, "cx {} vs OpenCV {cx}", k.cx);
        assert!((k.cy - cy).abs() < 3.0, "cy {} vs OpenCV {cy}", k.cy);
        assert!(s.rms_px < 0.5, "rms {}", s.rms_px);
    }
    assert!(calib.rms_px < 0.5, "stereo rms {}", calib.rms_px);
    assert!(
        (baseline / 0.083_206 - 1.0).abs() < 0.01,
        "baseline {baseline}"
    );
    // and within 1 % of the 83.622 mm OpenCV gets with the sample program's larger window
    assert!(
        (baseline / 0.083_622 - 1.0).abs() < 0.01,
        "baseline {baseline}"
    );
}

/// OpenCV's corners (`tests/data/opencv_corners.csv`) per image, in OpenCV's order.
fn opencv_corners() -> Vec<(String, Vec<nalgebra::Point2<f64>>)> {
    let text = include_str!("data/opencv_corners.csv");
    let mut out: Vec<(String, Vec<nalgebra::Point2<f64>>)> = Vec::new();
    for line in text.lines().skip(2) {
        let f: Vec<&str> = line.split(',').collect();
        let p = nalgebra::Point2::new(f[2].parse().unwrap(), f[3].parse().unwrap());
        match out.last_mut() {
            Some((name, v)) if name == f[0] => v.push(p),
            _ => out.push((f[0].to_owned(), vec![p])),
        }
    }
    out
}

/// Our solver on OpenCV's own corners reproduces OpenCV's `calibrateCamera` (the solver is then
/// not the source of any difference: the detector is).
#[test]
fn solver_on_opencv_corners_matches_opencv() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let all = opencv_corners();
    let opencv = [
        ("left", 532.825, 532.944, 342.492, 233.861, 0.1955),
        ("right", 537.450, 536.967, 327.588, 248.884, 0.2071),
    ];
    for (side, fx, fy, cx, cy, rms) in opencv {
        let views: Vec<_> = all
            .iter()
            .filter(|(n, _)| n.starts_with(side))
            .map(|(_, v)| v.clone())
            .collect();
        let c = ergocell_calibration::calibrate_camera(
            &views,
            &board,
            (640, 480),
            ergocell_calibration::SolveOptions::default(),
        )
        .unwrap();
        let k = c.intrinsics;
        println!(
            "{side} on OpenCV corners: fx {:.3} fy {:.3} cx {:.3} cy {:.3} rms {:.4}",
            k.fx, k.fy, k.cx, k.cy, c.rms_px
        );
        assert!((k.fx / fx - 1.0).abs() < 1e-3, "fx {}", k.fx);
        assert!((k.fy / fy - 1.0).abs() < 1e-3, "fy {}", k.fy);
        assert!((k.cx - cx).abs() < 0.5 && (k.cy - cy).abs() < 0.5);
        assert!((c.rms_px - rms).abs() < 0.01, "rms {}", c.rms_px);
    }
}

/// Our detector's corners against OpenCV's on the same images (nearest corner).
#[test]
fn detector_corners_close_to_opencv() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let mut worst = 0.0f64;
    let mut sum2 = 0.0;
    let mut n = 0;
    for (name, theirs) in opencv_corners() {
        let bytes = std::fs::read(sample_dir().join(format!("{name}.jpg"))).unwrap();
        let img = GrayImage::decode(&bytes, &name).unwrap();
        let ours = detect_checkerboard(&img, &board).unwrap();
        let mut img_worst = 0.0f64;
        for p in &theirs {
            let q = ours
                .corners
                .iter()
                .min_by(|a, b| (*a - p).norm().total_cmp(&(*b - p).norm()))
                .unwrap();
            let d = (q - p).norm();
            img_worst = img_worst.max(d);
            sum2 += d * d;
            n += 1;
        }
        worst = worst.max(img_worst);
    }
    let rms = (sum2 / f64::from(n)).sqrt();
    println!("ours vs OpenCV corners: rms {rms:.3} px, worst {worst:.3} px");
    assert!(rms < 0.05 && worst < 0.3, "rms {rms} worst {worst}");
}

/// Triangulating the board's corners with the stereo result measures its 25 mm squares within 1 %
/// (DLT of undistorted pixels, `perception::triangulation::dlt`, the runtime's own triangulation).
#[test]
fn triangulated_squares_measure_25_mm() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let Sample { left, calib, right } = sample();
    let cams = calib.rig.cameras();
    let (pl, pr) = (cams[0].projection_matrix(), cams[1].projection_matrix());
    let mut sides = Vec::new();
    for (l, r) in left.frames.iter().zip(&right.frames) {
        let (Some(l), Some(r)) = (l, r) else { continue };
        let points: Vec<nalgebra::Point3<f64>> = l
            .iter()
            .zip(r)
            .map(|(a, b)| {
                let a = cams[0].undistort_pixel(a).unwrap();
                let b = cams[1].undistort_pixel(b).unwrap();
                ergocell_perception::triangulation::dlt(&[(pl, a, 1.0), (pr, b, 1.0)]).unwrap()
            })
            .collect();
        for row in 0..6 {
            for col in 0..9 {
                let k = row * 9 + col;
                if col + 1 < 9 {
                    sides.push((points[k + 1] - points[k]).norm());
                }
                if row + 1 < 6 {
                    sides.push((points[k + 9] - points[k]).norm());
                }
            }
        }
    }
    let n = sides.len() as f64;
    let mean = sides.iter().sum::<f64>() / n;
    let sd = (sides.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / n).sqrt();
    println!(
        "triangulated square side: mean {:.3} mm, sd {:.3} mm over {} sides",
        mean * 1e3,
        sd * 1e3,
        sides.len()
    );
    assert!((mean / 0.025 - 1.0).abs() < 0.01, "mean side {mean} m");
    assert!(sd < 0.0005, "side sd {sd} m");
}

/// The rig writes as ergocell's rig file and as Anipose TOML, and ergocell's parser reads both back
/// to the same cameras.
#[test]
fn calibrated_rig_round_trips_through_both_file_formats() {
    use ergocell_formats::rig_file::{parse_rig, to_anipose_toml, to_ergocell_toml};
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let rig = &sample().calib.rig;
    for text in [to_ergocell_toml(rig), to_anipose_toml(rig)] {
        let (back, _) = parse_rig(&text, "calibrated").unwrap();
        assert_eq!(back.len(), 2);
        for (a, b) in rig.cameras().iter().zip(back.cameras()) {
            assert!((a.intrinsics.fx - b.intrinsics.fx).abs() < 1e-9);
            assert!((a.position_world() - b.position_world()).norm() < 1e-9);
        }
    }
}

/// Refining the intrinsics in the stereo solve (OpenCV's `stereoCalibrate` without
/// `CALIB_FIX_INTRINSIC`) can only lower the joint error, and keeps the baseline.
#[test]
fn refining_intrinsics_in_the_stereo_solve_keeps_the_baseline() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let Sample { left, calib, right } = sample();
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let options = RigOptions {
        refine_intrinsics: true,
        ..RigOptions::default()
    };
    let refined = calibrate_stereo(left.clone(), right.clone(), &board, options).unwrap();
    println!(
        "refined intrinsics: rms {:.4} (fixed {:.4}), baseline {:.3} mm",
        refined.rms_px,
        calib.rms_px,
        refined.baseline_m(0, 1).unwrap() * 1e3
    );
    assert!(refined.rms_px <= calib.rms_px + 1e-9);
    let (a, b) = (
        refined.baseline_m(0, 1).unwrap(),
        calib.baseline_m(0, 1).unwrap(),
    );
    assert!((a / b - 1.0).abs() < 0.005, "{a} vs {b}");
}
