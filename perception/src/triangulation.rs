//! Triangulation of one landmark from two or more calibrated views.
//!
//! Two methods:
//!
//! 1. [`dlt`]: the seed paper's Direct Linear Transform (Sec. II.A.3). Each view with projection matrix
//!    `P` (rows `k1 k2 k3`) and pixel `(u, v)` adds the rows `u·k3 − k1` and `v·k3 − k2` to `A`, scaled by
//!    the view's weight; the homogeneous point is the right singular vector of `A` for its smallest
//!    singular value. `A` (2n×4) is reduced to a 4×4 triangular factor by Givens rotations as rows arrive
//!    (QR, backward stable, no allocation), which has the same singular values and right singular
//!    vectors as `A`; the vector is found by inverse iteration on that factor, with the Jacobi SVD
//!    when that is not reliable ([`smallest_right_singular_vector_of_triangular`]). With `P = K[R|t]`, raw pixels and unit weights
//!    this is exactly caliscope's triangulation.
//! 2. [`RobustTriangulator`]: ergocell's default. A weighted linear estimate in undistorted normalized
//!    coordinates, refined by Gauss–Newton on the **pixel reprojection error** with Huber weights, then
//!    greedy outlier-view rejection (drop the worst view while its error exceeds a threshold and ≥ 2
//!    views remain, re-refining each time: O(n²) in the number of views, never the 2ⁿ camera subsets
//!    that stall Pose2Sim at 10–16 cameras). Minimising pixel error is the maximum-likelihood estimate
//!    under isotropic pixel noise: each view is automatically weighted by its geometry — a far camera's
//!    pixel constrains depth less, which is where a stereo pair's depth error growing with distance²
//!    comes from — and each view is additionally weighted by the detector's confidence. Points must end
//!    up in front of every camera they use (cheirality); a view that puts the point behind it is dropped.

use nalgebra::{
    Matrix3, Matrix3x4, Matrix4, Point2, Point3, RowVector4, Vector2, Vector3, Vector4,
};

use crate::error::{PerceptionError, Result};

mod lanes;
pub(crate) use lanes::{LaneCamera, LaneObs, LaneResult, LANES};

/// The seed paper's DLT for views given as `(P, pixel, weight)`; `P` maps homogeneous world points to
/// the same image coordinates as `pixel` (pixels with `K[R|t]`, or normalized coordinates with `[R|t]`).
pub fn dlt(views: &[(Matrix3x4<f64>, Point2<f64>, f64)]) -> Result<Point3<f64>> {
    let mut acc = DltAccumulator::default();
    for (p, px, w) in views {
        acc.add_view(p, px, *w);
    }
    acc.solve()
}

/// Incremental QR of the DLT matrix `A`: rows are rotated into a 4×4 upper-triangular factor.
#[derive(Debug, Clone, Copy, Default)]
pub struct DltAccumulator {
    r: Matrix4<f64>,
    views: usize,
}

impl DltAccumulator {
    /// Adds one view's two rows.
    pub fn add_view(&mut self, p: &Matrix3x4<f64>, pixel: &Point2<f64>, weight: f64) {
        if weight <= 0.0 || !weight.is_finite() {
            return;
        }
        let k1 = p.row(0);
        let k2 = p.row(1);
        let k3 = p.row(2);
        self.add_row((k3 * pixel.x - k1) * weight);
        self.add_row((k3 * pixel.y - k2) * weight);
        self.views += 1;
    }

    fn add_row(&mut self, row: RowVector4<f64>) {
        let mut row = row;
        for i in 0..4 {
            let a = self.r[(i, i)];
            let b = row[i];
            if b == 0.0 {
                continue;
            }
            // rows are pixel-scaled projection rows (≲ 1e7): no overflow risk, so no `hypot`
            let h = (a * a + b * b).sqrt();
            let (c, s) = (a / h, b / h);
            for j in i..4 {
                let rij = self.r[(i, j)];
                let xj = row[j];
                self.r[(i, j)] = c * rij + s * xj;
                row[j] = -s * rij + c * xj;
            }
        }
    }

    /// Number of views added.
    pub fn views(&self) -> usize {
        self.views
    }

    /// The least-squares point.
    pub fn solve(&self) -> Result<Point3<f64>> {
        if self.views < 2 {
            return Err(PerceptionError::TooFewViews { views: self.views });
        }
        let mut h = [None];
        smallest_right_singular_vectors_of_triangular(&[self.r], &mut h);
        Self::point_from(h[0].unwrap_or_else(|| smallest_right_singular_vector(&self.r)))
    }

    /// Solves many accumulators at once (the inverse iterations run in lockstep, see
    /// [`smallest_right_singular_vectors_of_triangular`]); `out[i]` is `accs[i].solve()`.
    pub fn solve_many(accs: &[DltAccumulator], out: &mut [Result<Point3<f64>>]) {
        const LANES: usize = 16;
        for (accs, out) in accs.chunks(LANES).zip(out.chunks_mut(LANES)) {
            let mut rs = [Matrix4::zeros(); LANES];
            for (r, a) in rs.iter_mut().zip(accs) {
                *r = a.r;
            }
            let mut hs = [None; LANES];
            smallest_right_singular_vectors_of_triangular(&rs[..accs.len()], &mut hs[..accs.len()]);
            for ((o, a), h) in out.iter_mut().zip(accs).zip(hs) {
                *o = if a.views < 2 {
                    Err(PerceptionError::TooFewViews { views: a.views })
                } else {
                    Self::point_from(h.unwrap_or_else(|| smallest_right_singular_vector(&a.r)))
                };
            }
        }
    }

    fn point_from(h: Vector4<f64>) -> Result<Point3<f64>> {
        let scale = h.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        if h[3].abs() <= 1e-12 * scale || h[3].is_nan() {
            return Err(PerceptionError::Degenerate);
        }
        let p = Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
        if p.coords.iter().all(|x| x.is_finite()) {
            Ok(p)
        } else {
            Err(PerceptionError::Degenerate)
        }
    }
}

/// The right singular vector of an upper-triangular 4×4 `R` for its smallest singular value, by
/// inverse iteration on `RᵀR` (two triangular solves a step), or `None` when that would not be
/// reliable — a (near-)zero diagonal entry, or no convergence within 40 steps because the two
/// smallest singular values are close — and the caller falls back to the Jacobi SVD.
///
/// Each step shrinks the error by `(σ₄/σ₃)²`; a DLT of a well-posed point has σ₄ (the noise) far
/// below σ₃ (the parallax), so this converges in a handful of steps (8.7 on the bench's stereo
/// pairs) where the Jacobi SVD takes five or six sweeps of six rotations (it was 73 % of the paper
/// fusion's time). It stops when a step changes the unit vector by less than 1e-15: the same
/// vector as the SVD's to rounding.
pub fn smallest_right_singular_vector_of_triangular(r: &Matrix4<f64>) -> Option<Vector4<f64>> {
    let mut out = [None];
    smallest_right_singular_vectors_of_triangular(&[*r], &mut out);
    out[0]
}

/// [`smallest_right_singular_vector_of_triangular`] of many factors, `out[i]` for `rs[i]`: the
/// iterations run in lockstep, so the processor overlaps the factors' dependency chains (one
/// factor's iteration is a chain of ~20 dependent multiply-adds); each stops at its own test.
pub fn smallest_right_singular_vectors_of_triangular(
    rs: &[Matrix4<f64>],
    out: &mut [Option<Vector4<f64>>],
) {
    // Per factor: its upper triangle, the diagonal's reciprocals, the current unit vector, and
    // whether it is still iterating.
    struct Lane {
        r: [f64; 10],
        inv: [f64; 4],
        x: [f64; 4],
        active: bool,
    }
    fn unit(z: [f64; 4]) -> Option<[f64; 4]> {
        let n2 = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3];
        if !(n2.is_finite() && n2 > 0.0) {
            return None;
        }
        let inv = 1.0 / n2.sqrt();
        Some([z[0] * inv, z[1] * inv, z[2] * inv, z[3] * inv])
    }
    // R z = y, backward; `r` = [r00 r01 r02 r03 r11 r12 r13 r22 r23 r33]
    fn back(r: &[f64; 10], inv: &[f64; 4], y: [f64; 4]) -> [f64; 4] {
        let z3 = y[3] * inv[3];
        let z2 = (y[2] - r[8] * z3) * inv[2];
        let z1 = (y[1] - r[5] * z2 - r[6] * z3) * inv[1];
        let z0 = (y[0] - r[1] * z1 - r[2] * z2 - r[3] * z3) * inv[0];
        [z0, z1, z2, z3]
    }
    // Rᵀ y = x, forward
    fn forward(r: &[f64; 10], inv: &[f64; 4], x: [f64; 4]) -> [f64; 4] {
        let y0 = x[0] * inv[0];
        let y1 = (x[1] - r[1] * y0) * inv[1];
        let y2 = (x[2] - r[2] * y0 - r[5] * y1) * inv[2];
        let y3 = (x[3] - r[3] * y0 - r[6] * y1 - r[8] * y2) * inv[3];
        [y0, y1, y2, y3]
    }
    const LANES: usize = 16;
    for (rs, out) in rs.chunks(LANES).zip(out.chunks_mut(LANES)) {
        let mut lanes: [Lane; LANES] = std::array::from_fn(|_| Lane {
            r: [0.0; 10],
            inv: [0.0; 4],
            x: [0.0; 4],
            active: false,
        });
        for ((lane, r), o) in lanes.iter_mut().zip(rs).zip(out.iter_mut()) {
            *o = None;
            let scale = r.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
            let diag = [r[(0, 0)], r[(1, 1)], r[(2, 2)], r[(3, 3)]];
            if !(scale.is_finite() && scale > 0.0) || diag.iter().any(|d| d.abs() <= 1e-10 * scale)
            {
                continue;
            }
            lane.r = [
                r[(0, 0)],
                r[(0, 1)],
                r[(0, 2)],
                r[(0, 3)],
                r[(1, 1)],
                r[(1, 2)],
                r[(1, 3)],
                r[(2, 2)],
                r[(2, 3)],
                r[(3, 3)],
            ];
            lane.inv = diag.map(|d| 1.0 / d);
            // start from R⁻¹e₄, the direction a small last pivot points to
            if let Some(x) = unit(back(&lane.r, &lane.inv, [0.0, 0.0, 0.0, 1.0])) {
                lane.x = x;
                lane.active = true;
            }
        }
        let lanes = &mut lanes[..rs.len()];
        for _ in 0..40 {
            let mut any = false;
            for (lane, o) in lanes.iter_mut().zip(out.iter_mut()) {
                if !lane.active {
                    continue;
                }
                // x ← R⁻¹R⁻ᵀx, normalised; the iteration keeps the sign (RᵀR is positive
                // definite), so successive vectors compare directly
                let Some(z) = unit(back(
                    &lane.r,
                    &lane.inv,
                    forward(&lane.r, &lane.inv, lane.x),
                )) else {
                    lane.active = false;
                    continue;
                };
                let change = (z[0] - lane.x[0]).powi(2)
                    + (z[1] - lane.x[1]).powi(2)
                    + (z[2] - lane.x[2]).powi(2)
                    + (z[3] - lane.x[3]).powi(2);
                lane.x = z;
                if change < 1e-30 {
                    lane.active = false;
                    *o = Some(Vector4::new(z[0], z[1], z[2], z[3]));
                } else {
                    any = true;
                }
            }
            if !any {
                break;
            }
        }
    }
}

/// The right singular vector of a 4×4 matrix for its smallest singular value, by one-sided Jacobi
/// (Hestenes) SVD: columns are rotated pairwise until orthogonal; the rotations accumulate into `V`
/// and the column norms are the singular values. Accurate to high relative precision.
///
/// Written out rather than calling nalgebra's `svd`: nalgebra 0.30 (the version `k` pins for the
/// whole workspace) returns wrong singular values for some well-conditioned DLT matrices of real
/// data (found on caliscope's recording: σ_max reported below the norm of a single row).
pub fn smallest_right_singular_vector(m: &Matrix4<f64>) -> Vector4<f64> {
    let mut u = *m;
    let mut v = Matrix4::<f64>::identity();
    let mut norms = [0.0; 4];
    for _sweep in 0..60 {
        // exact column norms at the start of each sweep; within it they are updated by the
        // rotation's closed form (α' = α − tγ, β' = β + tγ), which saves two dot products per pair
        for (j, n) in norms.iter_mut().enumerate() {
            *n = u.column(j).norm_squared();
        }
        let mut rotated = false;
        for p in 0..3 {
            for q in (p + 1)..4 {
                let (alpha, beta) = (norms[p], norms[q]);
                let gamma = u.column(p).dot(&u.column(q));
                if alpha == 0.0 || beta == 0.0 || gamma.abs() <= 1e-15 * (alpha * beta).sqrt() {
                    continue;
                }
                rotated = true;
                let zeta = (beta - alpha) / (2.0 * gamma);
                let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
                let c = 1.0 / (1.0 + t * t).sqrt();
                let s = c * t;
                for i in 0..4 {
                    let (up, uq) = (u[(i, p)], u[(i, q)]);
                    u[(i, p)] = c * up - s * uq;
                    u[(i, q)] = s * up + c * uq;
                    let (vp, vq) = (v[(i, p)], v[(i, q)]);
                    v[(i, p)] = c * vp - s * vq;
                    v[(i, q)] = s * vp + c * vq;
                }
                norms[p] = alpha - t * gamma;
                norms[q] = beta + t * gamma;
            }
        }
        if !rotated {
            break;
        }
    }
    let imin = (0..4)
        .min_by(|&a, &b| {
            u.column(a)
                .norm_squared()
                .total_cmp(&u.column(b).norm_squared())
        })
        .unwrap_or(3);
    v.column(imin).into_owned()
}

/// One view of a landmark prepared for [`RobustTriangulator`].
#[derive(Debug, Clone, Copy)]
pub struct NormalizedView {
    /// World→camera rotation and translation.
    pub R_camera_world: Matrix3<f64>,
    pub t_camera_world: Vector3<f64>,
    /// Undistorted normalized image coordinates of the observation.
    pub normalized: Vector2<f64>,
    /// Focal lengths (pixels per normalized unit), to express residuals in pixels.
    pub focal_px: Vector2<f64>,
    /// Detector confidence in `0..=1` (the view's weight).
    pub confidence: f64,
}

/// The result of triangulating one landmark.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Triangulated {
    pub point: Point3<f64>,
    /// RMS pixel reprojection error over the views kept (undistorted pinhole model).
    pub rms_px: f64,
    /// Bit `i` set: view `i` of the input was kept.
    pub used_mask: u64,
    /// Mean detector confidence of the kept views.
    pub mean_confidence: f64,
    /// Information matrix of `point` (inverse covariance, m⁻²) under the noise model: `JᵀWJ` of the
    /// last Gauss–Newton step. Depth along narrow-baseline rays is weakly constrained; this says how
    /// weakly, per direction.
    pub information: Matrix3<f64>,
    /// `information⁻¹` (m²): the covariance of `point` under the noise model.
    pub covariance: Matrix3<f64>,
}

impl Triangulated {
    /// Number of views kept.
    pub fn views_used(&self) -> u32 {
        self.used_mask.count_ones()
    }
}

/// ergocell's default triangulator (see the module docs).
///
/// Noise model: a detector's error on a body landmark has two parts, a pixel floor (quantisation,
/// blur) and a part proportional to the body's apparent size in the image — the detector is wrong by
/// a roughly constant fraction of the body, i.e. by roughly constant **metres at the body**. So the
/// standard deviation of a view's error perpendicular to its ray, at depth `Z` with focal length `f`,
/// is `σ = sqrt((σ_px·Z/f)² + σ_body²)` metres. Each view is weighted by `confidence / σ²`: a far
/// camera (large `Z/f`) counts less because its pixel floor is worth more metres — the stereo
/// depth-error-grows-with-distance² effect — while the body part of the error is the same for every
/// view. With `σ_body = 0` this is pixel-space maximum likelihood; with `σ_px = 0` it is the
/// object-space (linear DLT-like) estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobustTriangulator {
    /// Pixel noise floor of the detector (pixels).
    pub pixel_noise_px: f64,
    /// Detector noise that scales with the body's size in the image, expressed at the body (metres).
    pub body_noise_m: f64,
    /// Huber threshold of the robust refinement, in standard deviations of the noise model.
    pub huber_sigmas: f64,
    /// A view whose error exceeds this many standard deviations is dropped while ≥ 2 views remain.
    pub outlier_sigmas: f64,
    /// Gauss–Newton iterations per refinement.
    pub iterations: usize,
    /// Observations below this detector confidence are not used.
    pub min_confidence: f64,
    /// A point whose position uncertainty under the noise model (`sqrt(trace(information⁻¹))`,
    /// metres) exceeds this is not reported. One stereo pair of the reference cell at the station
    /// gives ≈ 0.6 m along its rays (the bone prior then fixes that direction); a wrong detection on
    /// nearly parallel rays gives tens of metres to kilometres (seen in `ergocell demo` while the
    /// operator walked out: an eye 3 km away).
    pub max_position_sigma_m: f64,
}

impl Default for RobustTriangulator {
    /// Defaults for MediaPipe-class detectors: a 2 px floor and 2 cm at the body; robust beyond
    /// 2 σ, outlier beyond 6 σ (chosen on caliscope's real 4-camera recording, see the crate tests).
    fn default() -> Self {
        Self {
            pixel_noise_px: 2.0,
            body_noise_m: 0.02,
            huber_sigmas: 2.0,
            outlier_sigmas: 6.0,
            iterations: 5,
            min_confidence: 0.05,
            max_position_sigma_m: 1.0,
        }
    }
}

/// Maximum number of views one landmark can use (the mask is a `u64`).
pub const MAX_VIEWS: usize = 64;

impl RobustTriangulator {
    /// Triangulates one landmark from its views (at most [`MAX_VIEWS`]).
    pub fn triangulate(&self, views: &[NormalizedView]) -> Result<Triangulated> {
        let mut mask: u64 = 0;
        for (i, v) in views.iter().enumerate().take(MAX_VIEWS) {
            if v.confidence >= self.min_confidence
                && v.confidence > 0.0
                && v.normalized.iter().all(|x| x.is_finite())
            {
                mask |= 1 << i;
            }
        }
        if mask.count_ones() < 2 {
            return Err(PerceptionError::TooFewViews {
                views: mask.count_ones() as usize,
            });
        }
        let pixel_terms = self.pixel_terms(views, mask);
        let mut point = self.linear_estimate(views, mask)?;
        let mut information;
        (point, information) = self.refine(views, &pixel_terms, mask, point)?;
        // Cheirality: a view that puts the point behind its camera is dropped.
        loop {
            let behind = iter_mask(mask).find(|&i| depth(&views[i], &point) <= 0.0);
            let Some(i) = behind else { break };
            mask &= !(1 << i);
            if mask.count_ones() < 2 {
                return Err(PerceptionError::TooFewViews {
                    views: mask.count_ones() as usize,
                });
            }
            point = self.linear_estimate(views, mask)?;
            (point, information) = self.refine(views, &pixel_terms, mask, point)?;
        }
        // Greedy outlier-view rejection, and the pixel error of the views kept: one projection of
        // the point per view and round.
        let (sq, conf) = loop {
            let judge = mask.count_ones() > 2;
            let (mut worst, mut worst_err) = (usize::MAX, -1.0);
            let (mut sq, mut conf, mut behind) = (0.0, 0.0, false);
            for i in iter_mask(mask) {
                let v = &views[i];
                let pc = camera_coordinates(&v.R_camera_world, &v.t_camera_world, &point);
                let err = if pc.z > 1e-9 {
                    let ex = pc.x / pc.z - v.normalized.x;
                    let ey = pc.y / pc.z - v.normalized.y;
                    let (px, py) = (ex * v.focal_px.x, ey * v.focal_px.y);
                    sq += px * px + py * py;
                    conf += v.confidence;
                    if judge {
                        let s2 = self.variance_normalized(&pixel_terms[i], 1.0 / pc.z);
                        (ex * ex / s2.x + ey * ey / s2.y).sqrt()
                    } else {
                        0.0
                    }
                } else {
                    behind = true;
                    f64::INFINITY
                };
                if err > worst_err {
                    (worst, worst_err) = (i, err);
                }
            }
            if judge && worst_err > self.outlier_sigmas {
                mask &= !(1 << worst);
                (point, information) = self.refine(views, &pixel_terms, mask, point)?;
                continue;
            }
            if behind {
                return Err(PerceptionError::Degenerate);
            }
            break (sq, conf);
        };
        self.finish(point, information, mask, sq, conf)
    }

    /// The result from the refined point: its covariance (refused when the noise model leaves it
    /// unconstrained), the RMS pixel error `sqrt(sq / n)` and mean confidence `conf / n` of the `n`
    /// views of `mask`.
    pub(crate) fn finish(
        &self,
        point: Point3<f64>,
        information: Matrix3<f64>,
        mask: u64,
        sq: f64,
        conf: f64,
    ) -> Result<Triangulated> {
        let covariance = information.try_inverse();
        let sigma_m = covariance.map_or(f64::INFINITY, |cov| cov.trace().max(0.0).sqrt());
        let Some(covariance) = covariance.filter(|_| sigma_m <= self.max_position_sigma_m) else {
            return Err(PerceptionError::Unconstrained {
                sigma_m,
                limit_m: self.max_position_sigma_m,
            });
        };
        let n = f64::from(mask.count_ones());
        Ok(Triangulated {
            point,
            rms_px: (sq / n).sqrt(),
            used_mask: mask,
            mean_confidence: conf / n,
            information,
            covariance,
        })
    }

    /// Per view, the pixel floor of the noise model in normalized units, squared, per axis:
    /// `(σ_px / f)²` (the part of σ that does not depend on depth).
    fn pixel_terms(&self, views: &[NormalizedView], mask: u64) -> [Vector2<f64>; MAX_VIEWS] {
        let mut out = [Vector2::zeros(); MAX_VIEWS];
        for i in iter_mask(mask) {
            let f = &views[i].focal_px;
            let (a, b) = (self.pixel_noise_px / f.x, self.pixel_noise_px / f.y);
            out[i] = Vector2::new(a * a, b * b);
        }
        out
    }

    /// Per-axis variance of a view's error in normalized image units at inverse depth `inv_z`,
    /// from its [`Self::pixel_terms`] entry.
    #[inline]
    fn variance_normalized(&self, pixel_term: &Vector2<f64>, inv_z: f64) -> Vector2<f64> {
        let body = self.body_noise_m * inv_z;
        let body2 = body * body;
        Vector2::new(pixel_term.x + body2, pixel_term.y + body2)
    }

    /// Iteratively reweighted Gauss–Newton on the whitened, confidence-weighted, Huber-robust error.
    fn refine(
        &self,
        views: &[NormalizedView],
        pixel_terms: &[Vector2<f64>; MAX_VIEWS],
        mask: u64,
        start: Point3<f64>,
    ) -> Result<(Point3<f64>, Matrix3<f64>)> {
        // 1/σ of each view at the starting depth (depths change by millimetres during refinement,
        // σ by far less than its own uncertainty): computed once, not per iteration.
        let mut inv_sigma = [Vector2::zeros(); MAX_VIEWS];
        for i in iter_mask(mask) {
            let z = depth(&views[i], &start);
            let s2 =
                self.variance_normalized(&pixel_terms[i], if z > 1e-9 { 1.0 / z } else { 1.0 });
            inv_sigma[i] = Vector2::new(1.0 / s2.x.sqrt(), 1.0 / s2.y.sqrt());
        }
        let huber2 = self.huber_sigmas * self.huber_sigmas;
        let mut x = start;
        let mut information = Matrix3::zeros();
        for _ in 0..self.iterations {
            let mut h = Sym3::default();
            let mut g = Vector3::zeros();
            for i in iter_mask(mask) {
                let v = &views[i];
                let r = &v.R_camera_world;
                let pc = camera_coordinates(r, &v.t_camera_world, &x);
                if pc.z <= 1e-9 {
                    continue;
                }
                let inv_z = 1.0 / pc.z;
                let (u, w) = (pc.x * inv_z, pc.y * inv_z);
                let (sx, sy) = (inv_sigma[i].x, inv_sigma[i].y);
                let (r0, r1) = ((u - v.normalized.x) * sx, (w - v.normalized.y) * sy);
                let norm2 = r0 * r0 + r1 * r1;
                let huber = if norm2 > huber2 {
                    self.huber_sigmas / norm2.sqrt()
                } else {
                    1.0
                };
                let weight = v.confidence * huber;
                // rows of d(whitened residual)/d(p_world): (R₀ − u·R₂)/z·sx and (R₁ − w·R₂)/z·sy
                let (ax, ay) = (inv_z * sx, inv_z * sy);
                let j0 = Vector3::new(
                    (r[(0, 0)] - u * r[(2, 0)]) * ax,
                    (r[(0, 1)] - u * r[(2, 1)]) * ax,
                    (r[(0, 2)] - u * r[(2, 2)]) * ax,
                );
                let j1 = Vector3::new(
                    (r[(1, 0)] - w * r[(2, 0)]) * ay,
                    (r[(1, 1)] - w * r[(2, 1)]) * ay,
                    (r[(1, 2)] - w * r[(2, 2)]) * ay,
                );
                h.add_outer(&j0, weight);
                h.add_outer(&j1, weight);
                let (wr0, wr1) = (weight * r0, weight * r1);
                g = Vector3::new(
                    g.x + (j0.x * wr0 + j1.x * wr1),
                    g.y + (j0.y * wr0 + j1.y * wr1),
                    g.z + (j0.z * wr0 + j1.z * wr1),
                );
            }
            let step = solve_normal3(&h, &g)?;
            information = h.to_matrix();
            x = Point3::new(x.x - step.x, x.y - step.y, x.z - step.z);
            if !(x.x.is_finite() && x.y.is_finite() && x.z.is_finite()) {
                return Err(PerceptionError::Degenerate);
            }
            // 1 µm: three orders of magnitude below any body landmark's accuracy
            if step.x * step.x + step.y * step.y + step.z * step.z < 1e-12 {
                break;
            }
        }
        Ok((x, information))
    }

    /// Weighted linear least squares in normalized coordinates (inhomogeneous DLT): each view's rows
    /// are its error in metres at the point's depth, divided by the noise model's σ there. The first
    /// round knows no depth and uses the body term only; the second uses the first round's depths.
    fn linear_estimate(&self, views: &[NormalizedView], mask: u64) -> Result<Point3<f64>> {
        let mut point: Option<Point3<f64>> = None;
        let body2 = self.body_noise_m * self.body_noise_m;
        for _round in 0..2 {
            let mut ata = Sym3::default();
            let mut atb = Vector3::zeros();
            for i in iter_mask(mask) {
                let v = &views[i];
                let r = &v.R_camera_world;
                let t = &v.t_camera_world;
                let r2 = Vector3::new(r[(2, 0)], r[(2, 1)], r[(2, 2)]);
                let z = point
                    .map(|p| r2.x * p.x + r2.y * p.y + r2.z * p.z + t.z)
                    .filter(|z| *z > 1e-6);
                let f = 0.5 * (v.focal_px.x + v.focal_px.y);
                let sigma_m = match z {
                    Some(z) => {
                        let a = self.pixel_noise_px * z / f;
                        (a * a + body2).sqrt()
                    }
                    None => self.body_noise_m.max(1e-3),
                };
                let w = v.confidence.sqrt() / sigma_m;
                for (c, axis) in [(v.normalized.x, 0usize), (v.normalized.y, 1usize)] {
                    // (c·r3 − r_axis)·X = −(c·t3 − t_axis): the error c·Z − X_axis, metres at the point
                    let row = Vector3::new(
                        (r2.x * c - r[(axis, 0)]) * w,
                        (r2.y * c - r[(axis, 1)]) * w,
                        (r2.z * c - r[(axis, 2)]) * w,
                    );
                    let rhs = -(c * t.z - t[axis]) * w;
                    ata.add_outer(&row, 1.0);
                    atb = Vector3::new(
                        atb.x + row.x * rhs,
                        atb.y + row.y * rhs,
                        atb.z + row.z * rhs,
                    );
                }
            }
            let p = Point3::from(solve_normal3(&ata, &atb)?);
            if !(p.x.is_finite() && p.y.is_finite() && p.z.is_finite()) {
                return Err(PerceptionError::Degenerate);
            }
            point = Some(p);
        }
        point.ok_or(PerceptionError::Degenerate)
    }
}

/// A symmetric 3×3 matrix accumulated from outer products, its six distinct entries only.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Sym3 {
    xx: f64,
    xy: f64,
    xz: f64,
    yy: f64,
    yz: f64,
    zz: f64,
}

impl Sym3 {
    /// Adds `w·v·vᵀ`.
    #[inline]
    pub(crate) fn add_outer(&mut self, v: &Vector3<f64>, w: f64) {
        let (a, b, c) = (v.x * w, v.y * w, v.z * w);
        self.xx += a * v.x;
        self.xy += a * v.y;
        self.xz += a * v.z;
        self.yy += b * v.y;
        self.yz += b * v.z;
        self.zz += c * v.z;
    }

    /// The symmetric part of a matrix (its upper triangle).
    pub(crate) fn from_matrix(m: &Matrix3<f64>) -> Self {
        Self {
            xx: m[(0, 0)],
            xy: m[(0, 1)],
            xz: m[(0, 2)],
            yy: m[(1, 1)],
            yz: m[(1, 2)],
            zz: m[(2, 2)],
        }
    }

    fn to_matrix(self) -> Matrix3<f64> {
        Matrix3::new(
            self.xx, self.xy, self.xz, self.xy, self.yy, self.yz, self.xz, self.yz, self.zz,
        )
    }

    /// The distinct cofactors `[c00, c01, c02, c11, c12, c22]` (the adjugate of a symmetric
    /// matrix is symmetric) and the determinant.
    #[inline]
    fn adjugate(&self) -> ([f64; 6], f64) {
        let (a, bb, c, d, e, f) = (self.xx, self.xy, self.xz, self.yy, self.yz, self.zz);
        let c00 = d * f - e * e;
        let c01 = c * e - bb * f;
        let c02 = bb * e - c * d;
        let c11 = a * f - c * c;
        let c12 = bb * c - a * e;
        let c22 = a * d - bb * bb;
        let det = a * c00 + bb * c01 + c * c02;
        ([c00, c01, c02, c11, c12, c22], det)
    }

    /// `self⁻¹·b` by the adjugate, or `None` when the matrix is singular or not finite.
    #[inline]
    pub(crate) fn solve(&self, b: &Vector3<f64>) -> Option<Vector3<f64>> {
        let ([c00, c01, c02, c11, c12, c22], det) = self.adjugate();
        if !det.is_finite() || det == 0.0 {
            return None;
        }
        let inv_det = 1.0 / det;
        Some(Vector3::new(
            (c00 * b.x + c01 * b.y + c02 * b.z) * inv_det,
            (c01 * b.x + c11 * b.y + c12 * b.z) * inv_det,
            (c02 * b.x + c12 * b.y + c22 * b.z) * inv_det,
        ))
    }
}

/// Solves `m x = b` for a symmetric positive semi-definite 3×3 normal matrix by its adjugate,
/// refusing a (numerically) rank-deficient one: parallel rays or a single camera position give no
/// depth, and a solve would return garbage instead of an error.
///
/// Written out operation by operation (no library product whose summation order could change):
/// [`lanes`] repeats these steps for several landmarks at once and must round alike.
fn solve_normal3(sym: &Sym3, b: &Vector3<f64>) -> Result<Vector3<f64>> {
    let ([c00, c01, c02, c11, c12, c22], det) = sym.adjugate();
    let (a, d, f) = (sym.xx, sym.yy, sym.zz);
    // det / (product of the diagonal) ≤ 1 for a PSD matrix; tiny means (near) singular
    let scale = a * d * f;
    if !(det.is_finite() && scale.is_finite()) || scale <= 0.0 || det <= 1e-12 * scale {
        return Err(PerceptionError::Degenerate);
    }
    let (i00, i01, i02) = (c00 / det, c01 / det, c02 / det);
    let (i11, i12, i22) = (c11 / det, c12 / det, c22 / det);
    Ok(Vector3::new(
        i00 * b.x + i01 * b.y + i02 * b.z,
        i01 * b.x + i11 * b.y + i12 * b.z,
        i02 * b.x + i12 * b.y + i22 * b.z,
    ))
}

/// `R·p + t`, written out (see [`solve_normal3`]).
#[inline]
fn camera_coordinates(r: &Matrix3<f64>, t: &Vector3<f64>, p: &Point3<f64>) -> Vector3<f64> {
    Vector3::new(
        r[(0, 0)] * p.x + r[(0, 1)] * p.y + r[(0, 2)] * p.z + t.x,
        r[(1, 0)] * p.x + r[(1, 1)] * p.y + r[(1, 2)] * p.z + t.y,
        r[(2, 0)] * p.x + r[(2, 1)] * p.y + r[(2, 2)] * p.z + t.z,
    )
}

fn depth(v: &NormalizedView, p: &Point3<f64>) -> f64 {
    let r = &v.R_camera_world;
    r[(2, 0)] * p.x + r[(2, 1)] * p.y + r[(2, 2)] * p.z + v.t_camera_world.z
}

/// Indices of the set bits of `mask`.
pub fn iter_mask(mask: u64) -> impl Iterator<Item = usize> {
    let mut m = mask;
    std::iter::from_fn(move || {
        if m == 0 {
            None
        } else {
            let i = m.trailing_zeros() as usize;
            m &= m - 1;
            Some(i)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Rotation3, UnitQuaternion};

    fn look_at(eye: Point3<f64>, target: Point3<f64>) -> (Matrix3<f64>, Vector3<f64>) {
        // camera z towards the target, y roughly down (world z up)
        let z = (target - eye).normalize();
        let x = z.cross(&Vector3::z()).normalize();
        let y = z.cross(&x);
        let r_world_camera = Matrix3::from_columns(&[x, y, z]);
        let r = r_world_camera.transpose();
        (r, -(r * eye.coords))
    }

    fn views_of(p: &Point3<f64>, eyes: &[Point3<f64>]) -> Vec<NormalizedView> {
        eyes.iter()
            .map(|eye| {
                let (r, t) = look_at(*eye, Point3::new(0.0, 0.0, 1.0));
                let pc = r * p.coords + t;
                NormalizedView {
                    R_camera_world: r,
                    t_camera_world: t,
                    normalized: Vector2::new(pc.x / pc.z, pc.y / pc.z),
                    focal_px: Vector2::new(900.0, 900.0),
                    confidence: 1.0,
                }
            })
            .collect()
    }

    fn eyes() -> Vec<Point3<f64>> {
        vec![
            Point3::new(3.0, 0.0, 1.5),
            Point3::new(3.0, 0.12, 1.5),
            Point3::new(-1.5, 2.6, 1.4),
            Point3::new(-1.6, 2.5, 1.4),
            Point3::new(-1.5, -2.6, 1.6),
        ]
    }

    #[test]
    fn dlt_recovers_an_exact_point() {
        let p = Point3::new(0.2, -0.1, 1.3);
        let views: Vec<_> = views_of(&p, &eyes())
            .iter()
            .map(|v| {
                let mut m = Matrix3x4::zeros();
                m.fixed_slice_mut::<3, 3>(0, 0).copy_from(&v.R_camera_world);
                m.fixed_slice_mut::<3, 1>(0, 3).copy_from(&v.t_camera_world);
                (m, Point2::from(v.normalized), 1.0)
            })
            .collect();
        assert_relative_eq!(dlt(&views).unwrap(), p, epsilon = 1e-10);
        assert_relative_eq!(dlt(&views[..2]).unwrap(), p, epsilon = 1e-8);
        assert!(matches!(
            dlt(&views[..1]),
            Err(PerceptionError::TooFewViews { views: 1 })
        ));
    }

    #[test]
    fn dlt_minimises_the_algebraic_error_on_real_data() {
        // Three views of caliscope's recording (sync 52, point 21): P = K[R|t] and raw pixels.
        let p = [
            Matrix3x4::new(
                104.295_676_998_402_2,
                -1_085.674_814_668_402_4,
                2.286_841_858_559_228,
                331.026_417_096_382_5,
                -843.677_107_238_725_7,
                -289.487_803_646_834_4,
                -373.256_171_633_313_95,
                760.175_084_665_286_2,
                0.126_347_520_311_210_7,
                -0.564_349_390_479_059,
                -0.815_810_069_548_741_8,
                1.451_538_316_839_271_5,
            ),
            Matrix3x4::new(
                704.472_882_788_796_9,
                0.479_745_623_001_395_2,
                625.425_925_546_476_7,
                1.924_529_037_893_884_2,
                -1.870_052_704_903_588,
                705.296_442_170_214,
                350.752_232_893_075_3,
                -0.504_434_557_401_312_8,
                0.000_827_956_039_493_433_9,
                -0.002_673_685_678_261_217_5,
                0.999_996_082_939_173_9,
                0.002_586_533_725_961_536_3,
            ),
            Matrix3x4::new(
                -607.373_246_193_982_3,
                -564.960_995_262_921_9,
                -387.550_275_474_289_44,
                1_022.518_994_091_361_7,
                -27.323_493_806_754_854,
                91.216_701_934_049_75,
                -731.686_952_459_668_4,
                1_000.321_934_842_665_8,
                0.042_276_993_302_244_21,
                -0.786_252_676_038_872,
                -0.616_457_123_617_721_2,
                1.518_360_243_991_087_3,
            ),
        ];
        let px = [
            Point2::new(432.0, 546.0),
            Point2::new(680.0, 423.0),
            Point2::new(682.0, 347.0),
        ];
        let views: Vec<_> = p.iter().zip(px).map(|(p, px)| (*p, px, 1.0)).collect();
        let got = dlt(&views).unwrap();
        // numpy.linalg.svd (LAPACK) on the same 6×4 matrix gives this point:
        assert_relative_eq!(
            got,
            Point3::new(0.049_468_45, 0.084_522_49, 0.986_845_73),
            epsilon = 1e-8
        );
        // and it is the minimiser of |A h| over unit h: no random direction does better.
        let mut a = nalgebra::DMatrix::zeros(6, 4);
        for (i, (m, px, _)) in views.iter().enumerate() {
            a.set_row(2 * i, &(m.row(2) * px.x - m.row(0)));
            a.set_row(2 * i + 1, &(m.row(2) * px.y - m.row(1)));
        }
        let h = got.to_homogeneous().normalize();
        let best = (&a * nalgebra::DVector::from_column_slice(h.as_slice())).norm();
        let mut seed = 12345u64;
        for _ in 0..2000 {
            let mut r = [0.0; 4];
            for x in &mut r {
                seed = seed
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                *x = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            }
            let u = nalgebra::DVector::from_column_slice(&r).normalize();
            assert!((&a * u).norm() >= best - 1e-9);
        }
    }

    #[test]
    fn inverse_iteration_agrees_with_the_jacobi_svd_or_declines() {
        // Triangular factors of DLT matrices of two and three noisy views of random points (the
        // paper's stereo pairs and more), and ill-posed ones (nearly parallel rays): wherever the
        // inverse iteration answers, it is the SVD's vector (up to sign) to 1e-12.
        let mut seed = 99u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut answered, mut declined) = (0, 0);
        for case in 0..2000 {
            let p = Point3::new(next(), next(), 1.0 + next());
            let spread = if case % 10 == 0 { 1e-7 } else { 3.0 };
            let eyes: Vec<Point3<f64>> = (0..2 + case % 2)
                .map(|_| Point3::new(3.0 + next() * spread, next() * spread, 1.5 + next()))
                .collect();
            let mut acc = DltAccumulator::default();
            for v in views_of(&p, &eyes) {
                let mut m = Matrix3x4::zeros();
                m.fixed_slice_mut::<3, 3>(0, 0).copy_from(&v.R_camera_world);
                m.fixed_slice_mut::<3, 1>(0, 3).copy_from(&v.t_camera_world);
                let noisy = v.normalized + Vector2::new(next(), next()) * 0.01;
                acc.add_view(&m, &Point2::from(noisy), 1.0);
            }
            let jacobi = smallest_right_singular_vector(&acc.r);
            match smallest_right_singular_vector_of_triangular(&acc.r) {
                Some(v) => {
                    answered += 1;
                    let aligned = if v.dot(&jacobi) < 0.0 { -v } else { v };
                    assert!(
                        (aligned - jacobi).norm() < 1e-12,
                        "case {case}: {v} vs {jacobi}"
                    );
                }
                None => declined += 1,
            }
        }
        assert!(answered > 1500, "answered {answered}, declined {declined}");
        // a singular factor is left to the SVD
        let mut r = Matrix4::identity();
        r[(3, 3)] = 0.0;
        assert_eq!(smallest_right_singular_vector_of_triangular(&r), None);
    }

    #[test]
    fn jacobi_svd_finds_the_null_vector_of_a_rank_deficient_matrix() {
        let m = Matrix4::new(
            1.0, 2.0, 3.0, 6.0, 0.5, -1.0, 2.0, 1.5, 3.0, 0.0, 1.0, 4.0, 2.0, 2.0, 2.0, 6.0,
        );
        // column 4 = col1 + col2 + col3 → null vector (1, 1, 1, −1)/2
        let v = smallest_right_singular_vector(&m);
        assert!((m * v).norm() < 1e-12);
        assert_relative_eq!(v.norm(), 1.0, epsilon = 1e-12);
    }

    #[test]
    fn robust_triangulation_is_exact_without_noise_and_rejects_an_outlier() {
        let p = Point3::new(-0.3, 0.25, 1.1);
        let mut views = views_of(&p, &eyes());
        let t = RobustTriangulator::default().triangulate(&views).unwrap();
        assert_relative_eq!(t.point, p, epsilon = 1e-9);
        assert_eq!(t.views_used(), 5);
        // One gross outlier (≈ 90 px) is dropped, the rest still give the exact point.
        views[2].normalized.x += 0.1;
        let t = RobustTriangulator::default().triangulate(&views).unwrap();
        assert_eq!(t.used_mask & (1 << 2), 0);
        assert_relative_eq!(t.point, p, epsilon = 1e-6);
    }

    #[test]
    fn a_view_behind_the_point_is_dropped_and_two_views_are_required() {
        let p = Point3::new(0.0, 0.0, 1.0);
        let mut views = views_of(&p, &eyes()[..3]);
        // Turn camera 2 around: the point is now behind it.
        let flip = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::PI);
        let r = Rotation3::from(flip).matrix() * views[2].R_camera_world;
        views[2].R_camera_world = r;
        views[2].t_camera_world = Rotation3::from(flip).matrix() * views[2].t_camera_world;
        let t = RobustTriangulator::default().triangulate(&views).unwrap();
        assert_eq!(t.views_used(), 2);
        assert_relative_eq!(t.point, p, epsilon = 1e-8);
        assert!(matches!(
            RobustTriangulator::default().triangulate(&views[..1]),
            Err(PerceptionError::TooFewViews { .. })
        ));
    }

    #[test]
    fn parallel_rays_are_degenerate_not_garbage() {
        let p = Point3::new(0.0, 0.0, 1.0);
        let eye = Point3::new(3.0, 0.0, 1.5);
        let views = views_of(&p, &[eye, eye]);
        assert!(RobustTriangulator::default().triangulate(&views).is_err());
    }

    #[test]
    fn a_wrong_detection_on_a_narrow_pair_is_too_uncertain_to_report() {
        // One 12 cm stereo pair 3 m from a point: its own views triangulate it (σ ≈ 0.6 m along the
        // rays with the default noise model, within the limit).
        let p = Point3::new(0.0, 0.0, 1.2);
        let pair = [Point3::new(3.0, 0.0, 1.5), Point3::new(3.0, 0.12, 1.5)];
        let mut views = views_of(&p, &pair);
        let tri = RobustTriangulator::default();
        let t = tri.triangulate(&views).unwrap();
        assert_relative_eq!(t.point, p, epsilon = 1e-6);
        // A gross detection error (≈ 36 px, the pair's whole disparity) in the second view makes its
        // ray parallel to the first's, but for 0.5 px: the rays meet hundreds of metres away. That
        // point is refused, not reported.
        let d0 = views[0].R_camera_world.transpose()
            * Vector3::new(views[0].normalized.x, views[0].normalized.y, 1.0);
        let d1 = views[1].R_camera_world * d0;
        let parallel = Vector2::new(d1.x / d1.z, d1.y / d1.z);
        let toward = views[1].normalized - parallel;
        views[1].normalized = parallel + toward.normalize() * (0.5 / 900.0);
        let dlt_far = tri.linear_estimate(&views, 0b11).unwrap();
        assert!((dlt_far - p).norm() > 20.0, "{dlt_far:?}");
        match tri.triangulate(&views) {
            Err(PerceptionError::Unconstrained { sigma_m, limit_m }) => {
                assert!(sigma_m > limit_m, "{sigma_m} vs {limit_m}");
            }
            Ok(t) => panic!("reported {:?} (linear estimate {dlt_far:?})", t.point),
            Err(e) => assert!(matches!(e, PerceptionError::Degenerate), "{e}"),
        }
    }

    #[test]
    fn mask_iteration_lists_set_bits() {
        assert_eq!(iter_mask(0b1011_0001).collect::<Vec<_>>(), vec![0, 4, 5, 7]);
        assert_eq!(iter_mask(0).count(), 0);
    }
}
