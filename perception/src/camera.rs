//! The camera model: pinhole intrinsics with Brown–Conrady distortion and world→camera extrinsics.
//!
//! Conventions (the same as OpenCV, Anipose, Pose2Sim and caliscope, so their calibrations load
//! unchanged):
//! - camera frame: x right, y down, z forward (optical axis), metres;
//! - extrinsics map world to camera: `p_camera = R_camera_world · p_world + t_camera_world`;
//! - normalized image coordinates `(x, y) = (X/Z, Y/Z)`, distorted by
//!   `r² = x² + y²`, `radial = 1 + k1 r² + k2 r⁴ + k3 r⁶`,
//!   `x_d = x·radial + 2 p1 x y + p2 (r² + 2x²)`, `y_d = y·radial + p1 (r² + 2y²) + 2 p2 x y`;
//! - pixels `u = fx x_d + skew y_d + cx`, `v = fy y_d + cy`, origin at the top-left pixel's centre.

use nalgebra::{
    Isometry3, Matrix2, Matrix3, Matrix3x4, Point2, Point3, Rotation3, Translation3,
    UnitQuaternion, Vector2, Vector3,
};
use serde::{Deserialize, Serialize};

use crate::error::{PerceptionError, Result};

/// The name of a camera in the rig, e.g. `"s1_left"` or `"cam_0"`.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct CameraId(String);

impl CameraId {
    /// A camera id; ids are non-empty, trimmed names.
    pub fn new(name: impl Into<String>) -> Result<Self> {
        let name: String = name.into();
        let trimmed = name.trim();
        if trimmed.is_empty() {
            return Err(PerceptionError::UnknownCamera(name));
        }
        Ok(Self(trimmed.to_owned()))
    }

    /// The id as text.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl std::fmt::Display for CameraId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Pinhole intrinsics in pixels, and the image size.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Intrinsics {
    pub fx: f64,
    pub fy: f64,
    pub cx: f64,
    pub cy: f64,
    /// `K[0][1]`; zero for every modern sensor, kept so imported matrices round-trip.
    #[serde(default)]
    pub skew: f64,
    pub width_px: u32,
    pub height_px: u32,
}

impl Intrinsics {
    /// The 3×3 camera matrix `K`.
    pub fn matrix(&self) -> Matrix3<f64> {
        Matrix3::new(
            self.fx, self.skew, self.cx, 0.0, self.fy, self.cy, 0.0, 0.0, 1.0,
        )
    }
}

/// Brown–Conrady distortion in OpenCV's order `k1 k2 p1 p2 k3`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Distortion {
    pub k1: f64,
    pub k2: f64,
    pub p1: f64,
    pub p2: f64,
    pub k3: f64,
}

impl Distortion {
    /// From OpenCV's coefficient vector (4 or 5 values; a missing `k3` is 0).
    pub fn from_slice(c: &[f64]) -> Option<Self> {
        match *c {
            [k1, k2, p1, p2] => Some(Self {
                k1,
                k2,
                p1,
                p2,
                k3: 0.0,
            }),
            [k1, k2, p1, p2, k3] => Some(Self { k1, k2, p1, p2, k3 }),
            _ => None,
        }
    }

    /// The coefficients in OpenCV's order.
    pub fn to_array(self) -> [f64; 5] {
        [self.k1, self.k2, self.p1, self.p2, self.k3]
    }

    /// True when every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.to_array().iter().all(|c| *c == 0.0)
    }

    /// Distorts a normalized image point.
    pub fn distort(&self, p: Vector2<f64>) -> Vector2<f64> {
        let (x, y) = (p.x, p.y);
        let r2 = x * x + y * y;
        let radial = 1.0 + r2 * (self.k1 + r2 * (self.k2 + r2 * self.k3));
        Vector2::new(
            x * radial + 2.0 * self.p1 * x * y + self.p2 * (r2 + 2.0 * x * x),
            y * radial + self.p1 * (r2 + 2.0 * y * y) + 2.0 * self.p2 * x * y,
        )
    }

    /// Jacobian of [`Distortion::distort`] at `p`.
    #[cfg(test)]
    fn distort_jacobian(&self, p: Vector2<f64>) -> Matrix2<f64> {
        self.distort_with_jacobian(p).1
    }

    /// [`Distortion::distort`] and its Jacobian at `p`, sharing the common terms.
    fn distort_with_jacobian(&self, p: Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>) {
        let (x, y) = (p.x, p.y);
        let r2 = x * x + y * y;
        let radial = 1.0 + r2 * (self.k1 + r2 * (self.k2 + r2 * self.k3));
        // d radial / d r2
        let dradial = self.k1 + r2 * (2.0 * self.k2 + 3.0 * r2 * self.k3);
        let value = Vector2::new(
            x * radial + 2.0 * self.p1 * x * y + self.p2 * (r2 + 2.0 * x * x),
            y * radial + self.p1 * (r2 + 2.0 * y * y) + 2.0 * self.p2 * x * y,
        );
        let dxd_dx = radial + x * dradial * 2.0 * x + 2.0 * self.p1 * y + self.p2 * 6.0 * x;
        let dxd_dy = x * dradial * 2.0 * y + 2.0 * self.p1 * x + self.p2 * 2.0 * y;
        let dyd_dx = y * dradial * 2.0 * x + self.p1 * 2.0 * x + 2.0 * self.p2 * y;
        let dyd_dy = radial + y * dradial * 2.0 * y + self.p1 * 6.0 * y + 2.0 * self.p2 * x;
        (value, Matrix2::new(dxd_dx, dxd_dy, dyd_dx, dyd_dy))
    }

    /// Inverts the distortion by Newton's method, starting from OpenCV's fixed-point iterate.
    /// `None` when it does not converge to 1e-12 (a pixel far outside the model's valid range).
    pub fn undistort(&self, d: Vector2<f64>) -> Option<Vector2<f64>> {
        if self.is_zero() {
            return Some(d);
        }
        // Start from OpenCV's first fixed-point iterate (remove tangential part, divide by radial
        // factor at the distorted point); Newton then converges in two or three steps.
        let mut p = {
            let (x, y) = (d.x, d.y);
            let r2 = x * x + y * y;
            let radial = 1.0 + r2 * (self.k1 + r2 * (self.k2 + r2 * self.k3));
            let dx = 2.0 * self.p1 * x * y + self.p2 * (r2 + 2.0 * x * x);
            let dy = self.p1 * (r2 + 2.0 * y * y) + 2.0 * self.p2 * x * y;
            if radial.abs() > 1e-6 {
                let inv = 1.0 / radial;
                Vector2::new((x - dx) * inv, (y - dy) * inv)
            } else {
                d
            }
        };
        for _ in 0..50 {
            let (value, jacobian) = self.distort_with_jacobian(p);
            let residual = value - d;
            // the 2×2 inverse written out: one division, not one per entry
            let det = jacobian[(0, 0)] * jacobian[(1, 1)] - jacobian[(0, 1)] * jacobian[(1, 0)];
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let inv_det = 1.0 / det;
            let step = Vector2::new(
                (jacobian[(1, 1)] * residual.x - jacobian[(0, 1)] * residual.y) * inv_det,
                (jacobian[(0, 0)] * residual.y - jacobian[(1, 0)] * residual.x) * inv_det,
            );
            p -= step;
            if !(p.x.is_finite() && p.y.is_finite()) {
                return None;
            }
            // Newton converges quadratically here: a step below 1e-6 leaves an error of order
            // 1e-12 (≈ 1e-9 px), so no further evaluation is needed.
            if step.norm_squared() < 1e-12 {
                return Some(p);
            }
        }
        ((self.distort(p) - d).norm() < 1e-9).then_some(p)
    }
}

impl Distortion {
    /// [`Distortion::undistort`] of many points at once, in place: `points[i]` becomes its
    /// undistorted value, or `None`. The same iteration (OpenCV's first iterate, then Newton until a
    /// step is below 1e-6) run in lockstep: two Newton steps for every point in straight loops with
    /// no data-dependent branch, so the processor overlaps the points' long dependency chains
    /// (one point alone is latency-bound: 45 ns on the CI machine); a point whose second step is not
    /// yet below 1e-6, or whose iteration failed, is redone by [`Distortion::undistort`]. A point
    /// that `undistort` would have accepted after one step gets one more (smaller than 1e-12):
    /// the same answer to ≈ 1e-13.
    pub fn undistort_many(&self, points: &mut [Option<Vector2<f64>>]) {
        const LANES: usize = 16;
        if self.is_zero() {
            return;
        }
        for chunk in points.chunks_mut(LANES) {
            let n = chunk.len();
            let mut d = [Vector2::zeros(); LANES];
            let mut p = [Vector2::zeros(); LANES];
            let mut last = [f64::INFINITY; LANES];
            for k in 0..n {
                // absent points run through the lanes as the origin and are left as they are
                d[k] = chunk[k].unwrap_or_else(Vector2::zeros);
                let (x, y) = (d[k].x, d[k].y);
                let r2 = x * x + y * y;
                let radial = 1.0 + r2 * (self.k1 + r2 * (self.k2 + r2 * self.k3));
                let dx = 2.0 * self.p1 * x * y + self.p2 * (r2 + 2.0 * x * x);
                let dy = self.p1 * (r2 + 2.0 * y * y) + 2.0 * self.p2 * x * y;
                let inv = 1.0 / radial;
                p[k] = if radial.abs() > 1e-6 {
                    Vector2::new((x - dx) * inv, (y - dy) * inv)
                } else {
                    d[k]
                };
            }
            for _ in 0..2 {
                for k in 0..n {
                    let (value, j) = self.distort_with_jacobian(p[k]);
                    let r = value - d[k];
                    let det = j[(0, 0)] * j[(1, 1)] - j[(0, 1)] * j[(1, 0)];
                    let inv_det = 1.0 / det;
                    let step = Vector2::new(
                        (j[(1, 1)] * r.x - j[(0, 1)] * r.y) * inv_det,
                        (j[(0, 0)] * r.y - j[(1, 0)] * r.x) * inv_det,
                    );
                    p[k] -= step;
                    // NaN (a zero determinant, an overflow) fails the test below
                    last[k] = step.norm_squared();
                }
            }
            for k in 0..n {
                let Some(original) = chunk[k] else { continue };
                chunk[k] = if last[k] < 1e-12 && p[k].x.is_finite() && p[k].y.is_finite() {
                    Some(p[k])
                } else {
                    self.undistort(original)
                };
            }
        }
    }
}

/// The focal lengths [`Camera::new`] accepts, as multiples of the image's longer side in pixels:
/// `0.05 ×` is a field of view of about 168° (beyond any pinhole lens; fisheyes are not supported),
/// `100 ×` about 0.6° (beyond any lens that watches a person at a work cell). A value outside is a
/// unit or export error (e.g. Qualisys' 1/64-pixel units, a metre focal length, `1e308`), which
/// would otherwise surface only as infinite reprojection errors.
pub const FOCAL_RANGE_PER_PX: (f64, f64) = (0.05, 100.0);

/// How far outside the image [`Camera::new`] lets the principal point lie, as a fraction of the
/// image's width (for `cx`) or height (for `cy`): `−0.5·w ≤ cx ≤ 1.5·w`, `−0.5·h ≤ cy ≤ 1.5·h`.
/// Real lenses put it near the centre; farther out is a wrong image size or a swapped matrix.
pub const PRINCIPAL_POINT_MARGIN: f64 = 0.5;

/// One calibrated camera.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    pub id: CameraId,
    pub intrinsics: Intrinsics,
    pub distortion: Distortion,
    /// Extrinsics: maps world coordinates into this camera's frame.
    pub T_camera_world: Isometry3<f64>,
}

impl Camera {
    /// A camera, validated: finite parameters, a positive image size, focal lengths within
    /// [`FOCAL_RANGE_PER_PX`] × the image's longer side, the principal point within
    /// [`PRINCIPAL_POINT_MARGIN`] of the image, and a proper rotation. Errors name the field and
    /// the value.
    pub fn new(
        id: CameraId,
        intrinsics: Intrinsics,
        distortion: Distortion,
        R_camera_world: Rotation3<f64>,
        t_camera_world: Vector3<f64>,
    ) -> Result<Self> {
        let bad = |field: &'static str, value: f64, why: &'static str| {
            Err(PerceptionError::BadCameraParameter {
                camera: id.clone(),
                field,
                value,
                why,
            })
        };
        let k = intrinsics;
        for (field, value) in [
            ("fx", k.fx),
            ("fy", k.fy),
            ("cx", k.cx),
            ("cy", k.cy),
            ("skew", k.skew),
        ] {
            if !value.is_finite() {
                return bad(field, value, "not finite");
            }
        }
        if k.fx <= 0.0 {
            return bad("fx", k.fx, "focal length must be positive");
        }
        if k.fy <= 0.0 {
            return bad("fy", k.fy, "focal length must be positive");
        }
        if k.width_px == 0 || k.height_px == 0 {
            return bad(
                "size",
                f64::from(k.width_px.min(k.height_px)),
                "image size must be positive",
            );
        }
        // Sanity beyond finiteness (every format carries the image size, so it is always known).
        let longest = f64::from(k.width_px.max(k.height_px));
        for (field, value) in [("fx", k.fx), ("fy", k.fy)] {
            if value < FOCAL_RANGE_PER_PX.0 * longest {
                return bad(
                    field,
                    value,
                    "focal length below 0.05 × the image's longer side (a field of view over 168°)",
                );
            }
            if value > FOCAL_RANGE_PER_PX.1 * longest {
                return bad(
                    field,
                    value,
                    "focal length above 100 × the image's longer side (a field of view under 0.6°)",
                );
            }
        }
        let (w, h) = (f64::from(k.width_px), f64::from(k.height_px));
        let m = PRINCIPAL_POINT_MARGIN;
        if !(-m * w..=(1.0 + m) * w).contains(&k.cx) {
            return bad(
                "cx",
                k.cx,
                "principal point more than half the image width outside the image",
            );
        }
        if !(-m * h..=(1.0 + m) * h).contains(&k.cy) {
            return bad(
                "cy",
                k.cy,
                "principal point more than half the image height outside the image",
            );
        }
        for (field, value) in ["k1", "k2", "p1", "p2", "k3"]
            .into_iter()
            .zip(distortion.to_array())
        {
            if !value.is_finite() {
                return bad(field, value, "not finite");
            }
        }
        for value in R_camera_world.matrix().iter() {
            if !value.is_finite() {
                return bad("rotation", *value, "not finite");
            }
        }
        let r = R_camera_world.matrix();
        let orthonormality = (r.transpose() * r - Matrix3::identity()).norm();
        if orthonormality > 1e-6 || r.determinant() < 0.0 {
            return bad("rotation", orthonormality, "not a proper rotation matrix");
        }
        for value in t_camera_world.iter() {
            if !value.is_finite() {
                return bad("translation", *value, "not finite");
            }
        }
        // Re-orthonormalise the (validated) rotation so downstream maths sees an exact rotation.
        let rotation = UnitQuaternion::from_matrix(r);
        Ok(Self {
            id,
            intrinsics,
            distortion,
            T_camera_world: Isometry3::from_parts(Translation3::from(t_camera_world), rotation),
        })
    }

    /// A camera at `eye` looking at `target`, its image "up" towards `world_up` (camera x right,
    /// y down, z forward). Errors when the eye and target coincide or the view is along `world_up`.
    pub fn look_at(
        id: CameraId,
        eye: Point3<f64>,
        target: Point3<f64>,
        world_up: Vector3<f64>,
        intrinsics: Intrinsics,
        distortion: Distortion,
    ) -> Result<Self> {
        let bad = |why: &'static str, value: f64| PerceptionError::BadCameraParameter {
            camera: id.clone(),
            field: "look_at",
            value,
            why,
        };
        let z = (target - eye)
            .try_normalize(1e-9)
            .ok_or_else(|| bad("eye and target coincide", 0.0))?;
        let x = z
            .cross(&world_up)
            .try_normalize(1e-9)
            .ok_or_else(|| bad("view direction is along world up", z.dot(&world_up)))?;
        let y = z.cross(&x);
        let R_camera_world = Rotation3::from_matrix_unchecked(Matrix3::from_rows(&[
            x.transpose(),
            y.transpose(),
            z.transpose(),
        ]));
        let t_camera_world = -(R_camera_world * eye.coords);
        Self::new(id, intrinsics, distortion, R_camera_world, t_camera_world)
    }

    /// The camera centre in world coordinates (`-Rᵀ t`).
    pub fn position_world(&self) -> Point3<f64> {
        self.T_camera_world
            .inverse_transform_point(&Point3::origin())
    }

    /// The 3×4 projection matrix `P = K [R | t]` of the undistorted pinhole model.
    pub fn projection_matrix(&self) -> Matrix3x4<f64> {
        self.intrinsics.matrix() * self.pose_matrix()
    }

    /// `[R | t]`, the world→camera pose as a 3×4 matrix (projection matrix in normalized coordinates).
    pub fn pose_matrix(&self) -> Matrix3x4<f64> {
        let mut m = Matrix3x4::zeros();
        m.fixed_slice_mut::<3, 3>(0, 0)
            .copy_from(self.T_camera_world.rotation.to_rotation_matrix().matrix());
        m.fixed_slice_mut::<3, 1>(0, 3)
            .copy_from(&self.T_camera_world.translation.vector);
        m
    }

    /// Projects a world point to a (distorted) pixel. Errors when the point is not in front of the camera.
    pub fn project(&self, p_world: &Point3<f64>) -> Result<Point2<f64>> {
        let p_camera = self.T_camera_world * p_world;
        if p_camera.z <= 1e-9 || !p_camera.z.is_finite() {
            return Err(PerceptionError::BehindCamera {
                camera: self.id.clone(),
                depth_m: p_camera.z,
            });
        }
        Ok(self.normalized_to_pixel(Vector2::new(
            p_camera.x / p_camera.z,
            p_camera.y / p_camera.z,
        )))
    }

    /// Distorts a normalized point and maps it to pixels.
    pub fn normalized_to_pixel(&self, normalized: Vector2<f64>) -> Point2<f64> {
        let d = self.distortion.distort(normalized);
        let k = &self.intrinsics;
        Point2::new(k.fx * d.x + k.skew * d.y + k.cx, k.fy * d.y + k.cy)
    }

    /// Maps a (distorted) pixel to undistorted normalized coordinates, by iterative undistortion.
    pub fn pixel_to_normalized(&self, pixel: &Point2<f64>) -> Result<Vector2<f64>> {
        if !(pixel.x.is_finite() && pixel.y.is_finite()) {
            return Err(PerceptionError::NonFinitePixel {
                u: pixel.x,
                v: pixel.y,
            });
        }
        let k = &self.intrinsics;
        let yd = (pixel.y - k.cy) / k.fy;
        let xd = (pixel.x - k.cx - k.skew * yd) / k.fx;
        self.distortion
            .undistort(Vector2::new(xd, yd))
            .ok_or_else(|| PerceptionError::UndistortionDiverged {
                camera: self.id.clone(),
                u: pixel.x,
                v: pixel.y,
            })
    }

    /// Maps a (distorted) pixel to the pixel an ideal (distortion-free) camera with the same `K` sees.
    pub fn undistort_pixel(&self, pixel: &Point2<f64>) -> Result<Point2<f64>> {
        let n = self.pixel_to_normalized(pixel)?;
        let k = &self.intrinsics;
        Ok(Point2::new(
            k.fx * n.x + k.skew * n.y + k.cx,
            k.fy * n.y + k.cy,
        ))
    }

    /// True when the pixel lies inside the image.
    pub fn in_image(&self, pixel: &Point2<f64>) -> bool {
        let k = &self.intrinsics;
        pixel.x >= -0.5
            && pixel.y >= -0.5
            && pixel.x < f64::from(k.width_px) - 0.5
            && pixel.y < f64::from(k.height_px) - 0.5
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn test_camera(distortion: Distortion) -> Camera {
        Camera::new(
            CameraId::new("c").unwrap(),
            Intrinsics {
                fx: 900.0,
                fy: 905.0,
                cx: 640.0,
                cy: 360.0,
                skew: 0.0,
                width_px: 1280,
                height_px: 720,
            },
            distortion,
            Rotation3::from_euler_angles(0.1, -0.2, 0.3),
            Vector3::new(0.1, -0.2, 2.5),
        )
        .unwrap()
    }

    #[test]
    fn projection_matches_the_projection_matrix_without_distortion() {
        let cam = test_camera(Distortion::default());
        let p = Point3::new(0.3, -0.2, 0.4);
        let px = cam.project(&p).unwrap();
        let h = cam.projection_matrix() * p.to_homogeneous();
        assert_relative_eq!(px.x, h.x / h.z, epsilon = 1e-9);
        assert_relative_eq!(px.y, h.y / h.z, epsilon = 1e-9);
    }

    #[test]
    fn undistortion_inverts_distortion() {
        let d = Distortion {
            k1: -0.338,
            k2: 0.0967,
            p1: -0.00135,
            p2: 0.00316,
            k3: -0.00375,
        };
        let cam = test_camera(d);
        for &(x, y) in &[(0.0, 0.0), (0.3, -0.2), (-0.5, 0.35), (0.6, 0.3)] {
            let n = Vector2::new(x, y);
            let px = cam.normalized_to_pixel(n);
            let back = cam.pixel_to_normalized(&px).unwrap();
            assert_relative_eq!(back, n, epsilon = 1e-10);
        }
    }

    #[test]
    fn undistorting_many_points_agrees_with_one_at_a_time() {
        let d = Distortion {
            k1: -0.338,
            k2: 0.0967,
            p1: -0.00135,
            p2: 0.00316,
            k3: -0.00375,
        };
        // a grid over a 16:9 image's normalized extent, beyond its corners, and points outside the
        // model's valid range (where both must fail alike)
        let mut pts: Vec<Option<Vector2<f64>>> = Vec::new();
        for i in 0..41 {
            for j in 0..23 {
                let x = -1.2 + 2.4 * f64::from(i) / 40.0;
                let y = -0.7 + 1.4 * f64::from(j) / 22.0;
                pts.push(Some(Vector2::new(x, y)));
            }
        }
        pts.extend([
            None,
            Some(Vector2::new(40.0, -30.0)),
            Some(Vector2::new(1e200, 0.0)),
            None,
        ]);
        let mut many = pts.clone();
        d.undistort_many(&mut many);
        let mut failed = 0;
        for (p, m) in pts.iter().zip(&many) {
            match (p.and_then(|p| d.undistort(p)), m) {
                (Some(a), Some(b)) => assert_relative_eq!(a, *b, epsilon = 1e-12),
                (None, None) => failed += 1,
                (a, b) => panic!("{p:?}: one at a time {a:?}, many {b:?}"),
            }
        }
        assert!(
            failed >= 3,
            "the absent and the out-of-range points: {failed}"
        );
        // with no distortion nothing changes
        let mut same = pts.clone();
        Distortion::default().undistort_many(&mut same);
        assert_eq!(same, pts);
    }

    #[test]
    fn distortion_jacobian_matches_finite_differences() {
        let d = Distortion {
            k1: 0.19,
            k2: -0.25,
            p1: 0.0028,
            p2: -0.0052,
            k3: 0.115,
        };
        let p = Vector2::new(0.31, -0.22);
        let j = d.distort_jacobian(p);
        let h = 1e-7;
        for c in 0..2 {
            let mut e = Vector2::zeros();
            e[c] = h;
            let fd = (d.distort(p + e) - d.distort(p - e)) / (2.0 * h);
            assert_relative_eq!(j.column(c).into_owned(), fd, epsilon = 1e-7);
        }
    }

    #[test]
    fn look_at_puts_the_target_on_the_optical_axis_with_up_up() {
        let k = Intrinsics {
            fx: 700.0,
            fy: 700.0,
            cx: 640.0,
            cy: 360.0,
            skew: 0.0,
            width_px: 1280,
            height_px: 720,
        };
        let id = CameraId::new("c").unwrap();
        let eye = Point3::new(3.0, 1.0, 2.0);
        let target = Point3::new(0.0, 0.0, 1.0);
        let cam = Camera::look_at(
            id.clone(),
            eye,
            target,
            Vector3::z(),
            k,
            Distortion::default(),
        )
        .unwrap();
        assert_relative_eq!(cam.position_world(), eye, epsilon = 1e-12);
        assert_relative_eq!(
            cam.project(&target).unwrap(),
            Point2::new(640.0, 360.0),
            epsilon = 1e-9
        );
        // a point above the target appears higher in the image (smaller v)
        assert!(cam.project(&Point3::new(0.0, 0.0, 1.5)).unwrap().y < 360.0);
        assert!(
            Camera::look_at(id.clone(), eye, eye, Vector3::z(), k, Distortion::default()).is_err()
        );
        assert!(Camera::look_at(
            id,
            eye,
            eye - Vector3::z(),
            Vector3::z(),
            k,
            Distortion::default()
        )
        .is_err());
    }

    #[test]
    fn points_behind_the_camera_have_no_image() {
        let cam = test_camera(Distortion::default());
        let behind = cam
            .T_camera_world
            .inverse_transform_point(&Point3::new(0.0, 0.0, -1.0));
        assert!(matches!(
            cam.project(&behind),
            Err(PerceptionError::BehindCamera { .. })
        ));
    }

    #[test]
    fn camera_centre_projects_nowhere_and_is_minus_rt() {
        let cam = test_camera(Distortion::default());
        let c = cam.position_world();
        let r = cam.T_camera_world.rotation.to_rotation_matrix();
        let expected = -(r.transpose() * cam.T_camera_world.translation.vector);
        assert_relative_eq!(c.coords, expected, epsilon = 1e-12);
        assert!(cam.project(&c).is_err());
    }

    #[test]
    fn invalid_parameters_are_rejected_by_name() {
        let k = Intrinsics {
            fx: f64::NAN,
            fy: 1.0,
            cx: 0.0,
            cy: 0.0,
            skew: 0.0,
            width_px: 10,
            height_px: 10,
        };
        let err = Camera::new(
            CameraId::new("x").unwrap(),
            k,
            Distortion::default(),
            Rotation3::identity(),
            Vector3::zeros(),
        )
        .unwrap_err();
        assert!(matches!(
            err,
            PerceptionError::BadCameraParameter { field: "fx", .. }
        ));
        let k = Intrinsics { fx: 1.0, ..k };
        let mirror =
            Rotation3::from_matrix_unchecked(Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0)));
        let err = Camera::new(
            CameraId::new("x").unwrap(),
            k,
            Distortion::default(),
            mirror,
            Vector3::zeros(),
        )
        .unwrap_err();
        assert!(matches!(
            err,
            PerceptionError::BadCameraParameter {
                field: "rotation",
                ..
            }
        ));
        assert!(CameraId::new("  ").is_err());
    }

    #[test]
    fn non_finite_pixels_are_an_error() {
        let cam = test_camera(Distortion::default());
        assert!(matches!(
            cam.pixel_to_normalized(&Point2::new(f64::NAN, 1.0)),
            Err(PerceptionError::NonFinitePixel { .. })
        ));
    }
}
