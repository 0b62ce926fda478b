//! Small dense linear algebra written out for robustness: a cyclic Jacobi eigen-solver for
//! symmetric matrices (null vectors of homogeneous systems `A x = 0` as the eigenvector of `AᵀA`
//! with the smallest eigenvalue), the nearest rotation to a 3×3 matrix, and normalized DLT
//! homographies (Hartley & Zisserman, Alg. 4.2).
//!
//! Written out rather than calling nalgebra 0.30's `svd` (the workspace's pinned version), which
//! returns wrong singular values on some small matrices (see `perception::triangulation`).

use nalgebra::{DMatrix, DVector, Matrix3, Point2, Rotation3, Vector3};

/// Eigen-decomposition of a symmetric matrix by cyclic Jacobi rotations: `(eigenvalues, V)` with
/// eigenvectors as the columns of `V`, unsorted.
pub fn symmetric_eigen(m: &DMatrix<f64>) -> (DVector<f64>, DMatrix<f64>) {
    let n = m.nrows();
    let mut a = m.clone();
    let mut v = DMatrix::<f64>::identity(n, n);
    for _sweep in 0..100 {
        let mut off = 0.0;
        for p in 0..n {
            for q in (p + 1)..n {
                off += a[(p, q)] * a[(p, q)];
            }
        }
        let scale: f64 = (0..n).map(|i| a[(i, i)] * a[(i, i)]).sum::<f64>() + off;
        if off <= 1e-30 * scale || off == 0.0 {
            break;
        }
        for p in 0..n {
            for q in (p + 1)..n {
                let apq = a[(p, q)];
                if apq == 0.0 {
                    continue;
                }
                let theta = (a[(q, q)] - a[(p, p)]) / (2.0 * apq);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[(k, p)], a[(k, q)]);
                    a[(k, p)] = c * akp - s * akq;
                    a[(k, q)] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[(p, k)], a[(q, k)]);
                    a[(p, k)] = c * apk - s * aqk;
                    a[(q, k)] = s * apk + c * aqk;
                }
                for k in 0..n {
                    let (vkp, vkq) = (v[(k, p)], v[(k, q)]);
                    v[(k, p)] = c * vkp - s * vkq;
                    v[(k, q)] = s * vkp + c * vkq;
                }
            }
        }
    }
    (a.diagonal(), v)
}

/// The unit null vector of `A` in the least-squares sense (eigenvector of `AᵀA` with the smallest
/// eigenvalue).
pub fn null_vector(a: &DMatrix<f64>) -> DVector<f64> {
    let ata = a.transpose() * a;
    let (values, vectors) = symmetric_eigen(&ata);
    let imin = values.argmin().0;
    let v = vectors.column(imin).into_owned();
    let n = v.norm();
    v / n
}

/// The rotation nearest to `m` in the Frobenius norm (polar decomposition `m (mᵀm)^-½`).
pub fn nearest_rotation(m: &Matrix3<f64>) -> Option<Rotation3<f64>> {
    let mtm = DMatrix::from_column_slice(3, 3, (m.transpose() * m).as_slice());
    let (values, vectors) = symmetric_eigen(&mtm);
    if values.iter().any(|&l| !(l.is_finite() && l > 1e-300)) {
        return None;
    }
    let mut inv_sqrt = Matrix3::zeros();
    for k in 0..3 {
        let e = Vector3::new(vectors[(0, k)], vectors[(1, k)], vectors[(2, k)]);
        inv_sqrt += e * e.transpose() / values[k].sqrt();
    }
    let mut r = m * inv_sqrt;
    if r.determinant() < 0.0 {
        r = -r;
    }
    r.iter()
        .all(|x| x.is_finite())
        .then(|| Rotation3::from_matrix_unchecked(r))
}

/// Similarity that moves the points' centroid to the origin and their mean distance to √2.
fn normalizing_transform(points: &[Point2<f64>]) -> Matrix3<f64> {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p.x / n, y + p.y / n));
    let mean_dist = points
        .iter()
        .map(|p| ((p.x - mx).powi(2) + (p.y - my).powi(2)).sqrt())
        .sum::<f64>()
        / n;
    let s = if mean_dist > 0.0 {
        std::f64::consts::SQRT_2 / mean_dist
    } else {
        1.0
    };
    Matrix3::new(s, 0.0, -s * mx, 0.0, s, -s * my, 0.0, 0.0, 1.0)
}

/// The homography `H` with `dst ~ H src`, by the normalized DLT. `None` for fewer than 4 points or
/// a degenerate configuration.
pub fn homography(src: &[Point2<f64>], dst: &[Point2<f64>]) -> Option<Matrix3<f64>> {
    if src.len() < 4 || src.len() != dst.len() {
        return None;
    }
    let ts = normalizing_transform(src);
    let td = normalizing_transform(dst);
    let mut a = DMatrix::<f64>::zeros(2 * src.len(), 9);
    for (k, (s, d)) in src.iter().zip(dst).enumerate() {
        let s = ts * Vector3::new(s.x, s.y, 1.0);
        let d = td * Vector3::new(d.x, d.y, 1.0);
        let (x, y) = (s.x / s.z, s.y / s.z);
        let (u, v) = (d.x / d.z, d.y / d.z);
        let r0 = [-x, -y, -1.0, 0.0, 0.0, 0.0, u * x, u * y, u];
        let r1 = [0.0, 0.0, 0.0, -x, -y, -1.0, v * x, v * y, v];
        for c in 0..9 {
            a[(2 * k, c)] = r0[c];
            a[(2 * k + 1, c)] = r1[c];
        }
    }
    let h = null_vector(&a);
    let hn = Matrix3::new(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], h[8]);
    let full = td.try_inverse()? * hn * ts;
    let scale = full[(2, 2)];
    if !scale.is_finite() || scale.abs() < 1e-12 {
        return None;
    }
    let full = full / scale;
    full.iter().all(|x| x.is_finite()).then_some(full)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jacobi_eigen_reconstructs_the_matrix() {
        let a = DMatrix::from_row_slice(
            4,
            4,
            &[
                4.0, 1.0, -2.0, 0.5, 1.0, 3.0, 0.0, 1.0, -2.0, 0.0, 5.0, -1.0, 0.5, 1.0, -1.0, 2.0,
            ],
        );
        let (values, v) = symmetric_eigen(&a);
        let back = &v * DMatrix::from_diagonal(&values) * v.transpose();
        assert!((back - &a).norm() < 1e-10);
        assert!((v.transpose() * &v - DMatrix::identity(4, 4)).norm() < 1e-10);
        // trace is preserved
        assert!((values.sum() - 14.0).abs() < 1e-10);
    }

    #[test]
    fn homography_is_recovered_exactly_from_exact_points() {
        let h = Matrix3::new(1.2, 0.1, 30.0, -0.05, 0.9, 12.0, 1e-4, -2e-4, 1.0);
        let src: Vec<Point2<f64>> = (0..12)
            .map(|i| Point2::new(f64::from(i % 4) * 10.0, f64::from(i / 4) * 7.0))
            .collect();
        let dst: Vec<Point2<f64>> = src
            .iter()
            .map(|p| {
                let q = h * Vector3::new(p.x, p.y, 1.0);
                Point2::new(q.x / q.z, q.y / q.z)
            })
            .collect();
        let est = homography(&src, &dst).unwrap();
        assert!((est - h).norm() < 1e-8, "{est}");
        assert!(homography(&src[..3], &dst[..3]).is_none());
    }

    #[test]
    fn nearest_rotation_of_a_rotation_is_itself_and_of_a_scaled_one_too() {
        let r = Rotation3::from_euler_angles(0.3, -0.2, 1.1);
        let back = nearest_rotation(&(r.matrix() * 1.7)).unwrap();
        assert!((back.matrix() - r.matrix()).norm() < 1e-10);
        assert!(nearest_rotation(&Matrix3::zeros()).is_none());
    }
}
