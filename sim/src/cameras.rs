//! Simulated camera rigs.
//!
//! The reference cell's rig comes from `config/rig.toml`, parsed by the caller with
//! `ergocell_formats::rig_file::parse_rig` (this crate does no file I/O). For "any number of
//! cameras", [`ring_rig`] builds one: stereo pairs of 1280×720 cameras (intrinsics and lens distortion
//! like the reference rig's, 12 cm baseline) spread on an arc around the operator's station, each
//! looking at a point at chest height above the station. Projection is always the perception crate's
//! own [`Camera::project`], so the simulator and the reconstruction share one camera model.

use ergocell_perception::{Camera, CameraId, CameraRig, Distortion, Intrinsics};
use nalgebra::{Point3, Vector3};

use crate::SimError;

/// Where and how [`ring_rig`] places its cameras.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingRigConfig {
    /// Horizontal distance from the station, metres (default 3.3, as the reference rig).
    pub radius_m: f64,
    /// Camera height above the floor, metres (default 2.1).
    pub height_m: f64,
    /// Azimuth of the first pair, radians from world +x (default −35°).
    pub first_azimuth_rad: f64,
    /// Azimuth step between pairs (default 115°: pairs at −35°, 80°, 195°, ...).
    pub azimuth_step_rad: f64,
    /// Stereo baseline, metres (default 0.12).
    pub baseline_m: f64,
    /// The point every camera looks at (default (0, 0, 1.0): the station at chest height).
    pub look_at: Point3<f64>,
}

impl Default for RingRigConfig {
    fn default() -> Self {
        Self {
            radius_m: 3.3,
            height_m: 2.1,
            first_azimuth_rad: (-35f64).to_radians(),
            azimuth_step_rad: 115f64.to_radians(),
            baseline_m: 0.12,
            look_at: Point3::new(0.0, 0.0, 1.0),
        }
    }
}

/// Intrinsics of the simulated 1280×720 stereo camera (as `config/rig.toml`, ~90° horizontal field).
pub fn default_intrinsics() -> Intrinsics {
    Intrinsics {
        fx: 700.0,
        fy: 700.0,
        cx: 640.0,
        cy: 360.0,
        skew: 0.0,
        width_px: 1280,
        height_px: 720,
    }
}

/// Lens distortion of the simulated camera (as `config/rig.toml`).
pub fn default_distortion() -> Distortion {
    Distortion {
        k1: -0.042,
        k2: 0.011,
        p1: 0.0002,
        p2: -0.0003,
        k3: 0.0,
    }
}

/// A camera at `centre` looking at `target`, world z up (camera x right, y down, z forward).
pub fn look_at_camera(
    id: &str,
    centre: Point3<f64>,
    target: Point3<f64>,
    intrinsics: Intrinsics,
    distortion: Distortion,
) -> Result<Camera, SimError> {
    Ok(Camera::look_at(
        CameraId::new(id)?,
        centre,
        target,
        Vector3::z(),
        intrinsics,
        distortion,
    )?)
}

/// A rig of `count` cameras (1..=64): stereo pairs `S1, S2, …` on an arc around the station (an odd
/// last camera stands alone), world up = +z.
pub fn ring_rig(count: usize, cfg: &RingRigConfig) -> Result<CameraRig, SimError> {
    if count == 0 || count > 64 {
        return Err(SimError::BadParameter {
            name: "cameras",
            value: count as f64,
            why: "a rig has 1 to 64 cameras",
        });
    }
    let mut cameras = Vec::with_capacity(count);
    let mut pairs = Vec::new();
    for j in 0..count.div_ceil(2) {
        let az = cfg.first_azimuth_rad + cfg.azimuth_step_rad * j as f64;
        let mid = Point3::new(
            cfg.look_at.x + cfg.radius_m * az.cos(),
            cfg.look_at.y + cfg.radius_m * az.sin(),
            cfg.height_m,
        );
        // Baseline along the pair's horizontal right direction.
        let toward = (cfg.look_at - mid).normalize();
        let right = toward
            .cross(&Vector3::z())
            .try_normalize(1e-9)
            .unwrap_or_else(Vector3::y);
        let both = 2 * j + 1 < count;
        let (names, offsets): (Vec<String>, Vec<f64>) = if both {
            (
                vec![format!("s{}_left", j + 1), format!("s{}_right", j + 1)],
                vec![-0.5 * cfg.baseline_m, 0.5 * cfg.baseline_m],
            )
        } else {
            (vec![format!("s{}", j + 1)], vec![0.0])
        };
        for (name, off) in names.iter().zip(offsets) {
            let c = mid + right * off;
            let target = cfg.look_at + right * off;
            cameras.push(look_at_camera(
                name,
                c,
                target,
                default_intrinsics(),
                default_distortion(),
            )?);
        }
        if both {
            pairs.push((format!("S{}", j + 1), names[0].clone(), names[1].clone()));
        }
    }
    Ok(CameraRig::new(cameras, &pairs, Some(Vector3::z()))?)
}

/// A rig whose world is not the simulator's: its calibration states an up other than +z.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the simulator's world is z-up with the floor at z = 0; this rig's up is {up:?}")]
pub struct NotZUp {
    /// The up direction the rig's calibration states.
    pub up: Vector3<f64>,
}

/// Checks that `rig`'s world is the simulator's (z up, the floor at z = 0): its stated up within
/// 1e-6 of +z, or no up stated.
pub fn check_z_up(rig: &CameraRig) -> Result<(), NotZUp> {
    match rig.up() {
        Some(up) if (up - Vector3::z()).norm() > 1e-6 => Err(NotZUp { up }),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ring_rig_sees_the_station_at_the_image_centre() {
        for n in [1, 2, 5, 6, 8] {
            let rig = ring_rig(n, &RingRigConfig::default()).unwrap();
            assert_eq!(rig.len(), n);
            assert_eq!(rig.pairs().len(), n / 2);
            for cam in rig.cameras() {
                let px = cam.project(&Point3::new(0.0, 0.0, 1.0)).unwrap();
                assert!((px.x - 640.0).abs() < 30.0 && (px.y - 360.0).abs() < 5.0);
                // the floor at the station is in view, below the centre
                let feet = cam.project(&Point3::new(0.0, 0.0, 0.0)).unwrap();
                assert!(cam.in_image(&feet) && feet.y > px.y);
            }
        }
        assert!(ring_rig(0, &RingRigConfig::default()).is_err());
    }

    #[test]
    fn only_a_rig_with_another_up_is_refused() {
        let ring = ring_rig(2, &RingRigConfig::default()).unwrap();
        assert_eq!(check_z_up(&ring), Ok(()));
        let rig = |up| CameraRig::new(ring.cameras().to_vec(), &[], up).unwrap();
        assert_eq!(check_z_up(&rig(None)), Ok(()));
        let y_up = check_z_up(&rig(Some(Vector3::y()))).unwrap_err();
        assert_eq!(y_up.up, Vector3::y());
        assert!(y_up.to_string().contains("z-up"), "{y_up}");
        assert!(check_z_up(&rig(Some(-Vector3::z()))).is_err());
    }
}
