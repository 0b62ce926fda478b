//! Small pose helpers: a printable pose summary and the transforms built from config values.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use serde::Serialize;

/// A pose as a person reads it: position in metres and roll/pitch/yaw in radians, with its frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PoseSummary {
    /// The frame the pose is expressed in, e.g. `robot_base`.
    pub frame: String,
    pub xyz_m: [f64; 3],
    pub rpy_rad: [f64; 3],
}

impl PoseSummary {
    /// Summarise `T_frame_x` expressed in `frame`.
    pub fn new(frame: &str, T_frame_x: &Isometry3<f64>) -> Self {
        let t = T_frame_x.translation.vector;
        let (r, p, y) = T_frame_x.rotation.euler_angles();
        Self {
            frame: frame.to_owned(),
            xyz_m: [t.x, t.y, t.z],
            rpy_rad: [r, p, y],
        }
    }
}

impl std::fmt::Display for PoseSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y, z] = self.xyz_m;
        let [r, p, yw] = self.rpy_rad;
        write!(
            f,
            "[{}] xyz = ({x:.4}, {y:.4}, {z:.4}) m, rpy = ({:.1}, {:.1}, {:.1})°",
            self.frame,
            r.to_degrees(),
            p.to_degrees(),
            yw.to_degrees()
        )
    }
}

/// Build a transform from a translation (m) and roll/pitch/yaw (rad, URDF convention: R = Rz(y) Ry(p) Rx(r)).
pub fn isometry_from_xyz_rpy(xyz_m: [f64; 3], rpy_rad: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(xyz_m[0], xyz_m[1], xyz_m[2]),
        UnitQuaternion::from_euler_angles(rpy_rad[0], rpy_rad[1], rpy_rad[2]),
    )
}

/// Position error (m) and orientation error (rad) between two poses in the same frame.
pub fn pose_error(T_a: &Isometry3<f64>, T_b: &Isometry3<f64>) -> (f64, f64) {
    let dp = (T_a.translation.vector - T_b.translation.vector).norm();
    let dr = T_a.rotation.angle_to(&T_b.rotation);
    (dp, dr)
}

/// The 6-vector error [Δp; Δθ] that moves `T_current` toward `T_target` (both in the same frame).
pub(crate) fn twist_error(
    T_current: &Isometry3<f64>,
    T_target: &Isometry3<f64>,
) -> nalgebra::Vector6<f64> {
    let dp: Vector3<f64> = T_target.translation.vector - T_current.translation.vector;
    let dr = (T_target.rotation * T_current.rotation.inverse()).scaled_axis();
    nalgebra::Vector6::new(dp.x, dp.y, dp.z, dr.x, dr.y, dr.z)
}
