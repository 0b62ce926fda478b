//! Single-camera calibration: Zhang's closed form from plane homographies, then a
//! Levenberg–Marquardt refinement of `fx fy cx cy k1 k2 p1 p2 k3` and every view's board pose.
//!
//! Z. Zhang, "A flexible new technique for camera calibration", IEEE TPAMI 22(11), 2000: each view's
//! homography `H = λ K [r1 r2 t]` gives two linear constraints on `B = K⁻ᵀK⁻¹`
//! (`h1ᵀBh2 = 0`, `h1ᵀBh1 = h2ᵀBh2`); `K` follows from `B` in closed form (zero skew enforced by an
//! extra row, as OpenCV's zero-skew model). Should the views be too few or too alike for that, the
//! principal point is put at the image centre and only the focal lengths are solved, as OpenCV's
//! `initIntrinsicParams2D` does. Distortion starts at zero and everything is refined together by
//! minimising the reprojection error, as OpenCV's `calibrateCamera`; the RMS is OpenCV's
//! `sqrt(Σ‖e‖² / points)`.

use ergocell_perception::{Distortion, Intrinsics};
use nalgebra::{
    DMatrix, Isometry3, Matrix3, Point2, Point3, Translation3, UnitQuaternion, Vector3,
};

use crate::board::BoardSpec;
use crate::error::{CalibrationError, Result};
use crate::linalg::{homography, nearest_rotation, null_vector};
use crate::lm::{solve, BlockProblem, LmReport};
use crate::model::{
    camera_of, pose_from_params, pose_to_params, rms_per_point, view_residuals, N_INTRINSICS,
    N_POSE,
};

/// Fewest views a single-camera calibration accepts.
pub const MIN_VIEWS: usize = 3;

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Levenberg–Marquardt iteration limit.
    pub max_iterations: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self {
            max_iterations: 100,
        }
    }
}

/// The result of a single-camera calibration.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraCalibration {
    pub intrinsics: Intrinsics,
    pub distortion: Distortion,
    /// Board pose in the camera frame for each input view, in input order.
    pub T_camera_board: Vec<Isometry3<f64>>,
    /// RMS reprojection error over all corners, pixels.
    pub rms_px: f64,
    /// RMS reprojection error of each view, pixels.
    pub view_rms_px: Vec<f64>,
    /// How the refinement ended.
    pub report: LmReport,
}

/// Calibrates one camera from views of `board` (each a full, ordered corner list, as
/// [`crate::detect::Detection::corners`]) in images of `image_size_px`.
pub fn calibrate_camera(
    views: &[Vec<Point2<f64>>],
    board: &BoardSpec,
    image_size_px: (u32, u32),
    options: SolveOptions,
) -> Result<CameraCalibration> {
    if views.len() < MIN_VIEWS {
        return Err(CalibrationError::TooFewViews {
            what: "single-camera calibration".into(),
            usable: views.len(),
            needed: MIN_VIEWS,
        });
    }
    for (v, corners) in views.iter().enumerate() {
        if corners.len() != board.corner_count() {
            return Err(CalibrationError::CornerCount {
                view: v,
                got: corners.len(),
                expected: board.corner_count(),
            });
        }
    }
    let object = board.object_points();
    let plane: Vec<Point2<f64>> = object.iter().map(|p| Point2::new(p.x, p.y)).collect();
    let homographies = views
        .iter()
        .enumerate()
        .map(|(v, c)| {
            homography(&plane, c).ok_or_else(|| {
                CalibrationError::Initialisation(format!("view {v}: degenerate homography"))
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let k0 = zhang_intrinsics(&homographies, image_size_px)
        .or_else(|| centred_intrinsics(&homographies, image_size_px))
        .ok_or_else(|| {
            CalibrationError::Initialisation(
                "no focal length fits the views (are the boards all parallel to the image?)".into(),
            )
        })?;
    let poses: Vec<Isometry3<f64>> = homographies
        .iter()
        .enumerate()
        .map(|(v, h)| {
            pose_from_homography(&k0, h).ok_or_else(|| {
                CalibrationError::Initialisation(format!("view {v}: no pose from the homography"))
            })
        })
        .collect::<Result<_>>()?;

    let mut x = Vec::with_capacity(N_INTRINSICS + N_POSE * views.len());
    x.extend_from_slice(&[k0[(0, 0)], k0[(1, 1)], k0[(0, 2)], k0[(1, 2)]]);
    x.extend_from_slice(&[0.0; 5]);
    for p in &poses {
        x.extend_from_slice(&pose_to_params(p));
    }
    let problem = IntrinsicsProblem::new(&object, views);
    let fixed = vec![false; x.len()];
    // Distortion-free first (robust start), then everything.
    let mut fixed_first = fixed.clone();
    for f in fixed_first.iter_mut().take(N_INTRINSICS).skip(4) {
        *f = true;
    }
    solve(&problem, &mut x, &fixed_first, options.max_iterations);
    let report = solve(&problem, &mut x, &fixed, options.max_iterations);

    let (intrinsics, distortion) = camera_of(&x[..N_INTRINSICS], image_size_px);
    let mut all = Vec::new();
    let mut view_rms_px = Vec::with_capacity(views.len());
    let mut T_camera_board = Vec::with_capacity(views.len());
    for (v, observed) in views.iter().enumerate() {
        let pose = pose_from_params(&x[N_INTRINSICS + N_POSE * v..N_INTRINSICS + N_POSE * (v + 1)]);
        let mut r = Vec::new();
        view_residuals(&x[..N_INTRINSICS], &pose, &object, observed, &mut r);
        view_rms_px.push(rms_per_point(&r));
        all.extend_from_slice(&r);
        T_camera_board.push(pose);
    }
    check_camera(&intrinsics, &distortion)?;
    check_determined(&intrinsics)?;
    Ok(CameraCalibration {
        intrinsics,
        distortion,
        T_camera_board,
        rms_px: rms_per_point(&all),
        view_rms_px,
        report,
    })
}

/// Rejects an estimate the views did not pin down: focal lengths beyond 100 image widths (or below
/// 1/20), an aspect ratio beyond 3, a principal point outside the image.
pub(crate) fn check_determined(k: &Intrinsics) -> Result<()> {
    let size = f64::from(k.width_px.max(k.height_px));
    let bad = |field, value| {
        Err(CalibrationError::Degenerate {
            field,
            value,
            width_px: k.width_px,
            height_px: k.height_px,
        })
    };
    for (field, f) in [("fx", k.fx), ("fy", k.fy)] {
        if !(f > 0.05 * size && f < 100.0 * size) {
            return bad(field, f);
        }
    }
    if k.fx / k.fy > 3.0 || k.fy / k.fx > 3.0 {
        return bad("fx/fy", k.fx / k.fy);
    }
    if !(0.0..=f64::from(k.width_px)).contains(&k.cx) {
        return bad("cx", k.cx);
    }
    if !(0.0..=f64::from(k.height_px)).contains(&k.cy) {
        return bad("cy", k.cy);
    }
    Ok(())
}

/// Validates the estimate through the camera model's own checks.
pub(crate) fn check_camera(k: &Intrinsics, d: &Distortion) -> Result<()> {
    let id = ergocell_perception::CameraId::new("calibrated")?;
    ergocell_perception::Camera::new(
        id,
        *k,
        *d,
        nalgebra::Rotation3::identity(),
        Vector3::zeros(),
    )?;
    Ok(())
}

struct IntrinsicsProblem<'a> {
    object: &'a [Point3<f64>],
    views: &'a [Vec<Point2<f64>>],
    params: Vec<Vec<usize>>,
}

impl<'a> IntrinsicsProblem<'a> {
    fn new(object: &'a [Point3<f64>], views: &'a [Vec<Point2<f64>>]) -> Self {
        let params = (0..views.len())
            .map(|v| {
                (0..N_INTRINSICS)
                    .chain(N_INTRINSICS + N_POSE * v..N_INTRINSICS + N_POSE * (v + 1))
                    .collect()
            })
            .collect();
        Self {
            object,
            views,
            params,
        }
    }
}

impl BlockProblem for IntrinsicsProblem<'_> {
    fn blocks(&self) -> usize {
        self.views.len()
    }
    fn block_params(&self, b: usize) -> &[usize] {
        &self.params[b]
    }
    fn block_residuals(&self, b: usize, x: &[f64], out: &mut Vec<f64>) {
        out.clear();
        let pose = pose_from_params(&x[N_INTRINSICS + N_POSE * b..N_INTRINSICS + N_POSE * (b + 1)]);
        view_residuals(&x[..N_INTRINSICS], &pose, self.object, &self.views[b], out);
    }
}

/// Zhang's `v_ij` row: `h_iᵀ B h_j` as a dot product with `b = [B11 B12 B22 B13 B23 B33]`.
fn v_row(h: &Matrix3<f64>, i: usize, j: usize) -> [f64; 6] {
    let (hi, hj) = (h.column(i), h.column(j));
    [
        hi[0] * hj[0],
        hi[0] * hj[1] + hi[1] * hj[0],
        hi[1] * hj[1],
        hi[2] * hj[0] + hi[0] * hj[2],
        hi[2] * hj[1] + hi[1] * hj[2],
        hi[2] * hj[2],
    ]
}

/// Pre-scales homographies by the image size so `B`'s entries are of similar magnitude.
fn scaled(hs: &[Matrix3<f64>], size_px: (u32, u32)) -> (Vec<Matrix3<f64>>, Matrix3<f64>) {
    let s = f64::from(size_px.0.max(size_px.1)).max(1.0);
    let n = Matrix3::new(1.0 / s, 0.0, 0.0, 0.0, 1.0 / s, 0.0, 0.0, 0.0, 1.0);
    (hs.iter().map(|h| n * h).collect(), n)
}

/// Zhang's closed form with zero skew; `None` when `B` is not a valid camera.
fn zhang_intrinsics(hs: &[Matrix3<f64>], size_px: (u32, u32)) -> Option<Matrix3<f64>> {
    let (hs, n) = scaled(hs, size_px);
    let mut v = DMatrix::<f64>::zeros(2 * hs.len() + 1, 6);
    for (k, h) in hs.iter().enumerate() {
        let v12 = v_row(h, 0, 1);
        let v11 = v_row(h, 0, 0);
        let v22 = v_row(h, 1, 1);
        for c in 0..6 {
            v[(2 * k, c)] = v12[c];
            v[(2 * k + 1, c)] = v11[c] - v22[c];
        }
    }
    // zero skew: B12 = 0
    v[(2 * hs.len(), 1)] = 1.0;
    let mut b = null_vector(&v);
    if b[0] < 0.0 {
        b = -b;
    }
    let (b11, b12, b22, b13, b23, b33) = (b[0], b[1], b[2], b[3], b[4], b[5]);
    let den = b11 * b22 - b12 * b12;
    if den <= 0.0 || b11 <= 0.0 {
        return None;
    }
    let v0 = (b12 * b13 - b11 * b23) / den;
    let lambda = b33 - (b13 * b13 + v0 * (b12 * b13 - b11 * b23)) / b11;
    if lambda / b11 <= 0.0 {
        return None;
    }
    let alpha = (lambda / b11).sqrt();
    let beta = (lambda * b11 / den).sqrt();
    let u0 = -b13 * alpha * alpha / lambda;
    let k_scaled = Matrix3::new(alpha, 0.0, u0, 0.0, beta, v0, 0.0, 0.0, 1.0);
    let k = n.try_inverse()? * k_scaled;
    plausible(&k, size_px).then_some(k)
}

/// OpenCV's fallback: principal point at the image centre, focal lengths by least squares.
fn centred_intrinsics(hs: &[Matrix3<f64>], size_px: (u32, u32)) -> Option<Matrix3<f64>> {
    let cx = (f64::from(size_px.0) - 1.0) / 2.0;
    let cy = (f64::from(size_px.1) - 1.0) / 2.0;
    let t = Matrix3::new(1.0, 0.0, -cx, 0.0, 1.0, -cy, 0.0, 0.0, 1.0);
    // unknowns a = 1/fx², b = 1/fy²
    let mut ata = nalgebra::Matrix2::<f64>::zeros();
    let mut atb = nalgebra::Vector2::<f64>::zeros();
    for h in hs {
        let h = t * h;
        let h = h / h.column(0).norm().max(1e-300);
        let rows = [
            (
                [h[(0, 0)] * h[(0, 1)], h[(1, 0)] * h[(1, 1)]],
                -h[(2, 0)] * h[(2, 1)],
            ),
            (
                [
                    h[(0, 0)] * h[(0, 0)] - h[(0, 1)] * h[(0, 1)],
                    h[(1, 0)] * h[(1, 0)] - h[(1, 1)] * h[(1, 1)],
                ],
                -(h[(2, 0)] * h[(2, 0)] - h[(2, 1)] * h[(2, 1)]),
            ),
        ];
        for (a, rhs) in rows {
            let a = nalgebra::Vector2::new(a[0], a[1]);
            ata += a * a.transpose();
            atb += a * rhs;
        }
    }
    let sol = ata.try_inverse()? * atb;
    if sol[0] <= 0.0 || sol[1] <= 0.0 {
        return None;
    }
    let k = Matrix3::new(
        1.0 / sol[0].sqrt(),
        0.0,
        cx,
        0.0,
        1.0 / sol[1].sqrt(),
        cy,
        0.0,
        0.0,
        1.0,
    );
    plausible(&k, size_px).then_some(k)
}

/// A camera matrix worth starting from: finite, positive focal lengths, principal point near the
/// image.
fn plausible(k: &Matrix3<f64>, size_px: (u32, u32)) -> bool {
    let (w, h) = (f64::from(size_px.0), f64::from(size_px.1));
    k.iter().all(|v| v.is_finite())
        && k[(0, 0)] > 0.0
        && k[(1, 1)] > 0.0
        && k[(0, 0)] / k[(1, 1)] < 3.0
        && k[(1, 1)] / k[(0, 0)] < 3.0
        && (-0.5 * w..1.5 * w).contains(&k[(0, 2)])
        && (-0.5 * h..1.5 * h).contains(&k[(1, 2)])
}

/// The board pose from `H = λ K [r1 r2 t]` (Zhang 2000, Sec. 3.1), board in front of the camera.
pub(crate) fn pose_from_homography(k: &Matrix3<f64>, h: &Matrix3<f64>) -> Option<Isometry3<f64>> {
    let kinv = k.try_inverse()?;
    let m = kinv * h;
    let (m1, m2, m3) = (m.column(0), m.column(1), m.column(2));
    let mut lambda = 1.0 / m1.norm();
    if !lambda.is_finite() {
        return None;
    }
    if m3[2] * lambda < 0.0 {
        lambda = -lambda;
    }
    let r1 = m1 * lambda;
    let r2 = m2 * lambda;
    let r3 = r1.cross(&r2);
    let t = m3 * lambda;
    let r = Matrix3::from_columns(&[r1, r2, r3]);
    let rot = nearest_rotation(&r)?;
    Some(Isometry3::from_parts(
        Translation3::from(t),
        UnitQuaternion::from_rotation_matrix(&rot),
    ))
}
