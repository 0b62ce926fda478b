//! Synthetic checkerboards rendered through known cameras (Brown–Conrady distortion, sensor blur
//! and noise): detection finds the true corners in the true order, calibration recovers the known
//! intrinsics and the known stereo pose.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_calibration::{
    calibrate_camera, calibrate_stereo, detect_checkerboard, BoardSpec, CameraViews, GrayImage,
    OrientationSource, RigOptions, SolveOptions,
};
use ergocell_perception::{CameraId, Distortion, Intrinsics};
use nalgebra::{Isometry3, Point2, Point3, Translation3, UnitQuaternion, Vector2, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};

const W: usize = 640;
const H: usize = 480;

struct TrueCamera {
    k: Intrinsics,
    d: Distortion,
    /// undistorted normalized coordinates at pixel corners, (W+1)·(H+1)
    map: Vec<Vector2<f64>>,
}

impl TrueCamera {
    fn new(fx: f64, fy: f64, cx: f64, cy: f64, d: Distortion) -> Self {
        let k = Intrinsics {
            fx,
            fy,
            cx,
            cy,
            skew: 0.0,
            width_px: W as u32,
            height_px: H as u32,
        };
        let mut map = Vec::with_capacity((W + 1) * (H + 1));
        for y in 0..=H {
            for x in 0..=W {
                let xd = (x as f64 - 0.5 - cx) / fx;
                let yd = (y as f64 - 0.5 - cy) / fy;
                map.push(d.undistort(Vector2::new(xd, yd)).unwrap());
            }
        }
        Self { k, d, map }
    }

    fn project(&self, p_camera: &Point3<f64>) -> Point2<f64> {
        let n = self.d.distort(Vector2::new(
            p_camera.x / p_camera.z,
            p_camera.y / p_camera.z,
        ));
        Point2::new(self.k.fx * n.x + self.k.cx, self.k.fy * n.y + self.k.cy)
    }

    /// Renders the board at `T_camera_board`: 8 samples per pixel, σ = 0.7 px blur, σ = 2 grey
    /// levels of noise.
    fn render(&self, board: &BoardSpec, T: &Isometry3<f64>, rng: &mut ChaCha8Rng) -> GrayImage {
        let s = board.square_m();
        let (cols, rows) = (board.cols() as i64, board.rows() as i64);
        let rt = T.rotation.inverse();
        let t_board = rt * T.translation.vector; // R^T t
        let colour = |n: Vector2<f64>| -> f64 {
            let d = rt * Vector3::new(n.x, n.y, 1.0);
            if d.z.abs() < 1e-12 {
                return 90.0;
            }
            let lambda = t_board.z / d.z;
            if lambda <= 0.0 {
                return 90.0;
            }
            let p = d * lambda - t_board;
            let (i, j) = ((p.x / s).floor() as i64, (p.y / s).floor() as i64);
            if i >= -1 && i < cols && j >= -1 && j < rows {
                if (i + j).rem_euclid(2) == 0 {
                    30.0
                } else {
                    220.0
                }
            } else if i >= -2 && i <= cols && j >= -2 && j <= rows {
                225.0 // white margin
            } else {
                90.0
            }
        };
        let mut data = vec![0.0f32; W * H];
        for y in 0..H {
            for x in 0..W {
                let m00 = self.map[y * (W + 1) + x];
                let m10 = self.map[y * (W + 1) + x + 1];
                let m01 = self.map[(y + 1) * (W + 1) + x];
                let m11 = self.map[(y + 1) * (W + 1) + x + 1];
                let mut acc = 0.0;
                // 8 "rooks" samples: 8 distinct x and y offsets, so a straight edge's coverage is
                // quantised to 1/8 px rather than 1/2 (which would bias sub-pixel corners)
                for k in 0..8u32 {
                    let a = (f64::from(k) + 0.5) / 8.0;
                    let b = (f64::from((3 * k) % 8) + 0.5) / 8.0;
                    let n = m00 * ((1.0 - a) * (1.0 - b))
                        + m10 * (a * (1.0 - b))
                        + m01 * ((1.0 - a) * b)
                        + m11 * (a * b);
                    acc += colour(n);
                }
                data[y * W + x] = (acc / 8.0) as f32;
            }
        }
        let img = GrayImage::from_vec(W, H, data).unwrap().gaussian_blur(0.7);
        let noise = Normal::new(0.0, 2.0).unwrap();
        let mut noisy = Vec::with_capacity(W * H);
        for y in 0..H {
            for x in 0..W {
                noisy.push(img.at(x as isize, y as isize) + noise.sample(rng) as f32);
            }
        }
        GrayImage::from_vec(W, H, noisy).unwrap()
    }
}

/// Board poses in the left camera: tilted up to ~35°, 0.3–0.45 m away, all corners in view.
fn poses(board: &BoardSpec) -> Vec<Isometry3<f64>> {
    let s = board.square_m();
    let centre = Vector3::new(
        (board.cols() - 1) as f64 * s / 2.0,
        (board.rows() - 1) as f64 * s / 2.0,
        0.0,
    );
    let tilts = [
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.36),
        (0.5, 0.0, 0.1, 0.0, 0.01, 0.38),
        (-0.5, 0.1, -0.1, 0.01, -0.01, 0.40),
        (0.0, 0.55, 0.2, -0.02, 0.0, 0.40),
        (0.1, -0.55, -0.2, 0.03, 0.01, 0.42),
        (0.35, 0.35, 0.3, -0.03, -0.02, 0.38),
        (-0.35, -0.35, -0.3, 0.02, 0.03, 0.42),
        (0.3, -0.3, 0.5, 0.04, -0.03, 0.45),
        (-0.3, 0.3, -0.4, -0.05, 0.02, 0.43),
        (0.2, 0.1, 1.2, 0.0, 0.0, 0.37),
    ];
    tilts
        .iter()
        .map(|&(ax, ay, az, dx, dy, z)| {
            let r = UnitQuaternion::from_euler_angles(ax, ay, az);
            // centred between the two cameras of the stereo test (the right one is 9 cm to the right)
            let t = Vector3::new(dx + 0.045, dy, z) - r * centre;
            Isometry3::from_parts(Translation3::from(t), r)
        })
        .collect()
}

fn left_camera() -> TrueCamera {
    TrueCamera::new(
        610.0,
        606.0,
        324.5,
        236.0,
        Distortion {
            k1: -0.22,
            k2: 0.06,
            p1: 0.0008,
            p2: -0.0005,
            k3: 0.0,
        },
    )
}

fn right_camera() -> TrueCamera {
    TrueCamera::new(
        598.0,
        597.0,
        315.0,
        245.0,
        Distortion {
            k1: -0.18,
            k2: 0.03,
            p1: -0.0004,
            p2: 0.0006,
            k3: 0.0,
        },
    )
}

/// Largest pixel difference between the true lens and ours over the central 60 % of the image,
/// where the boards were (a fitted polynomial is not meant to extrapolate to the corners).
fn max_model_difference_px(a: &TrueCamera, k: &Intrinsics, d: &Distortion) -> f64 {
    let mut worst = 0.0f64;
    for y in (H / 5..4 * H / 5).step_by(10) {
        for x in (W / 5..4 * W / 5).step_by(10) {
            let n = a.map[y * (W + 1) + x];
            let p = Point3::new(n.x, n.y, 1.0);
            let truth = a.project(&p);
            let dn = d.distort(Vector2::new(n.x, n.y));
            let ours = Point2::new(k.fx * dn.x + k.cx, k.fy * dn.y + k.cy);
            worst = worst.max((truth - ours).norm());
        }
    }
    worst
}

#[test]
fn detection_finds_the_true_corners_in_the_true_order() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let cam = left_camera();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let object = board.object_points();
    let mut sum2 = 0.0;
    let mut n = 0;
    for (v, T) in poses(&board).iter().enumerate() {
        let img = cam.render(&board, T, &mut rng);
        let det = detect_checkerboard(&img, &board).unwrap_or_else(|r| panic!("view {v}: {r}"));
        assert_eq!(det.orientation, OrientationSource::Colour);
        for (p, q) in object.iter().zip(&det.corners) {
            let truth = cam.project(&(T * p));
            let e = (truth - q).norm();
            assert!(e < 0.3, "view {v}: corner off by {e} px");
            sum2 += e * e;
            n += 1;
        }
    }
    let rms = (sum2 / f64::from(n)).sqrt();
    assert!(rms < 0.08, "corner rms {rms} px");
}

#[test]
fn stereo_calibration_recovers_the_known_cameras_and_pose() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let (left, right) = (left_camera(), right_camera());
    let T_right_left = Isometry3::from_parts(
        Translation3::new(-0.09, 0.002, 0.003),
        UnitQuaternion::from_euler_angles(0.01, -0.06, 0.005),
    );
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut lf = Vec::new();
    let mut rf = Vec::new();
    for T in poses(&board) {
        let l = left.render(&board, &T, &mut rng);
        let r = right.render(&board, &(T_right_left * T), &mut rng);
        let (dl, dr) = (
            detect_checkerboard(&l, &board),
            detect_checkerboard(&r, &board),
        );
        lf.push(dl.ok().map(|d| d.corners));
        rf.push(dr.ok().map(|d| d.corners));
    }
    assert!(lf.iter().flatten().count() >= 9 && rf.iter().flatten().count() >= 8);
    let views = |id: &str, frames| CameraViews {
        id: CameraId::new(id).unwrap(),
        image_size_px: (W as u32, H as u32),
        frames,
    };
    let calib = calibrate_stereo(
        views("left", lf.clone()),
        views("right", rf),
        &board,
        RigOptions::default(),
    )
    .unwrap();
    for (cam, truth) in calib.rig.cameras().iter().zip([&left, &right]) {
        let (k, t) = (cam.intrinsics, truth.k);
        assert!((k.fx / t.fx - 1.0).abs() < 0.005, "fx {} vs {}", k.fx, t.fx);
        assert!((k.fy / t.fy - 1.0).abs() < 0.005, "fy {} vs {}", k.fy, t.fy);
        assert!((k.cx - t.cx).abs() < 2.0, "cx {} vs {}", k.cx, t.cx);
        assert!((k.cy - t.cy).abs() < 2.0, "cy {} vs {}", k.cy, t.cy);
        assert!((cam.distortion.k1 - truth.d.k1).abs() < 0.03);
        let model = max_model_difference_px(truth, &k, &cam.distortion);
        eprintln!("{}: lens model differs by at most {model} px", cam.id);
        assert!(model < 1.0, "lens model differs by {model} px");
    }
    assert!(calib.rms_px < 0.15, "stereo rms {}", calib.rms_px);
    let T = calib.T_between(0, 1).unwrap();
    let dt = (T.translation.vector - T_right_left.translation.vector).norm();
    assert!(dt < 0.0009, "translation off by {dt} m");
    let dr = (T.rotation.inverse() * T_right_left.rotation).angle();
    assert!(dr < 0.2_f64.to_radians(), "rotation off by {dr} rad");
    let baseline = calib.baseline_m(0, 1).unwrap();
    assert!((baseline / T_right_left.translation.vector.norm() - 1.0).abs() < 0.005);

    // the left camera alone, too
    let alone: Vec<_> = lf.into_iter().flatten().collect();
    let c = calibrate_camera(
        &alone,
        &board,
        (W as u32, H as u32),
        SolveOptions::default(),
    )
    .unwrap();
    assert!((c.intrinsics.fx / left.k.fx - 1.0).abs() < 0.005);
    assert!(c.rms_px < 0.15);
    assert_eq!(c.view_rms_px.len(), alone.len());
}

#[test]
fn a_corrupted_view_is_rejected_and_a_clean_one_is_not() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let cam = left_camera();
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let T = poses(&board)[1];
    let img = cam.render(&board, &T, &mut rng);
    assert!(detect_checkerboard(&img, &board).is_ok());
    // paint over one inner square's corner region: the grid loses a corner
    let object = board.object_points();
    let hole = cam.project(&(T * object[13]));
    let mut data = Vec::with_capacity(W * H);
    for y in 0..H {
        for x in 0..W {
            let d = ((x as f64 - hole.x).powi(2) + (y as f64 - hole.y).powi(2)).sqrt();
            data.push(if d < 9.0 {
                220.0
            } else {
                img.at(x as isize, y as isize)
            });
        }
    }
    let damaged = GrayImage::from_vec(W, H, data).unwrap();
    let got = detect_checkerboard(&damaged, &board);
    assert!(got.is_err(), "a board with a blotted corner was accepted");
}

/// An 8x6 board (rows + cols even) is found, but its order is only by image position: a rig must
/// not use it; a 9x6 board's order comes from its colours.
#[test]
fn a_half_turn_symmetric_board_is_not_used_for_a_rig() {
    let board = BoardSpec::new(8, 6, 0.025).unwrap();
    let cam = left_camera();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let T = poses(&board)[2];
    let det = detect_checkerboard(&cam.render(&board, &T, &mut rng), &board).unwrap();
    assert_eq!(det.orientation, OrientationSource::ImagePosition);
    assert!(matches!(
        det.into_rig_corners(&board),
        Err(ergocell_calibration::Rejection::AmbiguousOrder { cols: 8, rows: 6 })
    ));
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let det = detect_checkerboard(&cam.render(&board, &T, &mut rng), &board).unwrap();
    assert_eq!(det.into_rig_corners(&board).unwrap().len(), 54);
}
