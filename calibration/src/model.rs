//! Parameter vectors of the camera model shared by the solvers, and the projection they minimise.
//!
//! Intrinsics are `[fx, fy, cx, cy, k1, k2, p1, p2, k3]` (pixels; OpenCV's distortion order, zero
//! skew as OpenCV's `calibrateCamera`), poses `[rx, ry, rz, tx, ty, tz]` (a rotation vector in
//! radians, a translation in metres). Projection is `ergocell_perception`'s model exactly: the
//! distortion is [`Distortion::distort`], so a calibration means the same thing in perception.

use ergocell_perception::{Distortion, Intrinsics};
use nalgebra::{Isometry3, Point2, Point3, Translation3, UnitQuaternion, Vector3};

/// Number of intrinsic parameters per camera.
pub const N_INTRINSICS: usize = 9;
/// Number of pose parameters.
pub const N_POSE: usize = 6;

/// A pose from `[rx, ry, rz, tx, ty, tz]`.
pub fn pose_from_params(p: &[f64]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[3], p[4], p[5]),
        UnitQuaternion::from_scaled_axis(Vector3::new(p[0], p[1], p[2])),
    )
}

/// `[rx, ry, rz, tx, ty, tz]` of a pose.
pub fn pose_to_params(t: &Isometry3<f64>) -> [f64; 6] {
    let r = t.rotation.scaled_axis();
    let v = t.translation.vector;
    [r.x, r.y, r.z, v.x, v.y, v.z]
}

/// The distortion part of an intrinsics vector.
pub fn distortion_of(k: &[f64]) -> Distortion {
    Distortion {
        k1: k[4],
        k2: k[5],
        p1: k[6],
        p2: k[7],
        k3: k[8],
    }
}

/// Intrinsics and distortion from a parameter vector and the image size.
pub fn camera_of(k: &[f64], size_px: (u32, u32)) -> (Intrinsics, Distortion) {
    (
        Intrinsics {
            fx: k[0],
            fy: k[1],
            cx: k[2],
            cy: k[3],
            skew: 0.0,
            width_px: size_px.0,
            height_px: size_px.1,
        },
        distortion_of(k),
    )
}

/// The parameter vector of intrinsics and distortion.
pub fn params_of(k: &Intrinsics, d: &Distortion) -> [f64; N_INTRINSICS] {
    [k.fx, k.fy, k.cx, k.cy, d.k1, d.k2, d.p1, d.p2, d.k3]
}

/// Projects a point in the camera frame to a (distorted) pixel. A point on or behind the camera's
/// centre plane projects far away (a large residual), never to NaN.
pub fn project(k: &[f64], d: &Distortion, p_camera: &Point3<f64>) -> Point2<f64> {
    let z = if p_camera.z.abs() < 1e-9 {
        1e-9
    } else {
        p_camera.z
    };
    let n = d.distort(nalgebra::Vector2::new(p_camera.x / z, p_camera.y / z));
    Point2::new(k[0] * n.x + k[2], k[1] * n.y + k[3])
}

/// Appends the residuals `projected − observed` (u then v per corner) of one view.
pub fn view_residuals(
    k: &[f64],
    T_camera_board: &Isometry3<f64>,
    object: &[Point3<f64>],
    observed: &[Point2<f64>],
    out: &mut Vec<f64>,
) {
    let d = distortion_of(k);
    for (p, o) in object.iter().zip(observed) {
        let q = project(k, &d, &(T_camera_board * p));
        out.push(q.x - o.x);
        out.push(q.y - o.y);
    }
}

/// RMS of a residual vector taken per point (`sqrt(Σ(du² + dv²) / points)`), OpenCV's definition.
pub fn rms_per_point(residuals: &[f64]) -> f64 {
    let points = (residuals.len() / 2).max(1) as f64;
    (residuals.iter().map(|r| r * r).sum::<f64>() / points).sqrt()
}
