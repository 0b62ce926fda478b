//! A rig of M calibrated cameras in one world frame, grouped into stereo pairs.
//!
//! The seed paper (Sec. II.A) uses 3 stereo pairs; each pair's own DLT gives one estimate per landmark,
//! and fusion combines them. Our default fusion uses every camera directly (N-view), but the pairs are
//! kept because the paper's baseline and the per-pair diagnostics need them.

use nalgebra::{Matrix3, Point3, Vector3};

use crate::camera::{Camera, CameraId};
use crate::error::{PerceptionError, Result};

/// Index of a camera inside its rig (position in [`CameraRig::cameras`]): cheap to copy, used on the
/// per-frame hot path. [`CameraId`] is the name people and files use.
pub type CameraIndex = usize;

/// Two cameras triangulated together, as in the seed paper's `S_j`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StereoPair {
    pub name: String,
    pub left: CameraIndex,
    pub right: CameraIndex,
}

/// Two camera centres closer than this (metres) are the same centre: [`CameraRig::new`] refuses them.
pub const MIN_CAMERA_SEPARATION_M: f64 = 1e-3;

/// Two camera centres farther apart than this (metres) cannot be one cell's cameras:
/// [`CameraRig::new`] refuses them (a calibration in millimetres read as metres).
pub const MAX_CAMERA_SPREAD_M: f64 = 100.0;

/// Where the cameras' optical axes come closest together (least squares), when their directions
/// pin a point down (not all nearly parallel).
fn convergence_point(cameras: &[Camera]) -> Option<Point3<f64>> {
    let mut a = Matrix3::zeros();
    let mut b = Vector3::zeros();
    for c in cameras {
        let forward = c.T_camera_world.rotation.inverse() * Vector3::z();
        let m = Matrix3::identity() - forward * forward.transpose();
        a += m;
        b += m * c.position_world().coords;
    }
    let eig = a.symmetric_eigen().eigenvalues;
    let (lo, hi) = (eig.min(), eig.max());
    // NaN (never for validated cameras) also lands here.
    if lo.partial_cmp(&(0.05 * hi)) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    a.try_inverse().map(|inv| Point3::from(inv * b))
}

/// A validated set of cameras: unique ids, valid parameters, distinct centres (at least
/// [`MIN_CAMERA_SEPARATION_M`] apart), pairs that reference real cameras.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraRig {
    cameras: Vec<Camera>,
    pairs: Vec<StereoPair>,
    /// The world's "up" direction (unit), if the calibration states it. The world frame is whatever the
    /// calibration chose (the paper: the first camera's frame), so "up" cannot be assumed.
    up: Option<Vector3<f64>>,
}

impl CameraRig {
    /// Builds a rig. `pairs` are `(name, left id, right id)`; with no pairs given, consecutive cameras
    /// are paired (0–1, 2–3, …) when the count is even.
    pub fn new(
        cameras: Vec<Camera>,
        pairs: &[(String, String, String)],
        up: Option<Vector3<f64>>,
    ) -> Result<Self> {
        if cameras.is_empty() {
            return Err(PerceptionError::EmptyRig);
        }
        for (i, c) in cameras.iter().enumerate() {
            if cameras[..i].iter().any(|other| other.id == c.id) {
                return Err(PerceptionError::DuplicateCamera(c.id.clone()));
            }
        }
        // Two cameras at one centre (a duplicated entry, a failed extrinsic calibration) see every
        // point along the same ray: nothing can be triangulated from them.
        let centres: Vec<_> = cameras.iter().map(Camera::position_world).collect();
        for (i, c) in centres.iter().enumerate() {
            for (j, other) in centres[..i].iter().enumerate() {
                let distance_m = (c - other).norm();
                if distance_m < MIN_CAMERA_SEPARATION_M {
                    return Err(PerceptionError::CoincidentCameras {
                        first: cameras[j].id.clone(),
                        second: cameras[i].id.clone(),
                        distance_m,
                        limit_m: MIN_CAMERA_SEPARATION_M,
                    });
                }
            }
        }
        // A rig in millimetres read as metres: its cameras are kilometres apart.
        for (i, c) in centres.iter().enumerate() {
            for (j, other) in centres[..i].iter().enumerate() {
                let distance_m = (c - other).norm();
                if distance_m > MAX_CAMERA_SPREAD_M || distance_m.is_nan() {
                    return Err(PerceptionError::RigTooLarge {
                        first: cameras[j].id.clone(),
                        second: cameras[i].id.clone(),
                        distance_m,
                        limit_m: MAX_CAMERA_SPREAD_M,
                    });
                }
            }
        }
        // Cameras that all look away from where their axes meet see no one (inverted extrinsics).
        if let Some(p) = convergence_point(&cameras) {
            if cameras.iter().all(|c| (c.T_camera_world * p).z <= 0.0) {
                return Err(PerceptionError::CamerasFaceAway {
                    x: p.x,
                    y: p.y,
                    z: p.z,
                });
            }
        }
        let mut rig = Self {
            cameras,
            pairs: Vec::new(),
            up: None,
        };
        if let Some(u) = up {
            let n = u.norm();
            if !n.is_finite() || n < 1e-9 {
                return Err(PerceptionError::Parse {
                    source_name: "rig".into(),
                    field: "up".into(),
                    message: format!("up vector {u:?} is not a direction"),
                });
            }
            rig.up = Some(u / n);
        }
        if pairs.is_empty() {
            if rig.cameras.len().is_multiple_of(2) {
                rig.pairs = (0..rig.cameras.len() / 2)
                    .map(|j| StereoPair {
                        name: format!("S{}", j + 1),
                        left: 2 * j,
                        right: 2 * j + 1,
                    })
                    .collect();
            }
        } else {
            for (name, left, right) in pairs {
                let l = rig
                    .index_of_name(left)
                    .ok_or_else(|| PerceptionError::UnknownCamera(left.clone()))?;
                let r = rig
                    .index_of_name(right)
                    .ok_or_else(|| PerceptionError::UnknownCamera(right.clone()))?;
                if l == r {
                    return Err(PerceptionError::DegeneratePair(name.clone()));
                }
                rig.pairs.push(StereoPair {
                    name: name.clone(),
                    left: l,
                    right: r,
                });
            }
        }
        Ok(rig)
    }

    /// The cameras, in rig order.
    pub fn cameras(&self) -> &[Camera] {
        &self.cameras
    }

    /// The stereo pairs.
    pub fn pairs(&self) -> &[StereoPair] {
        &self.pairs
    }

    /// The world's up direction, if the calibration states it.
    pub fn up(&self) -> Option<Vector3<f64>> {
        self.up
    }

    /// Number of cameras.
    pub fn len(&self) -> usize {
        self.cameras.len()
    }

    /// Always false: a rig has at least one camera.
    pub fn is_empty(&self) -> bool {
        self.cameras.is_empty()
    }

    /// The camera at `index`.
    pub fn camera(&self, index: CameraIndex) -> Option<&Camera> {
        self.cameras.get(index)
    }

    /// The index of the camera with this id.
    pub fn index_of(&self, id: &CameraId) -> Option<CameraIndex> {
        self.cameras.iter().position(|c| &c.id == id)
    }

    /// The index of the camera with this name.
    pub fn index_of_name(&self, name: &str) -> Option<CameraIndex> {
        self.cameras
            .iter()
            .position(|c| c.id.as_str() == name.trim())
    }

    /// The pair a camera belongs to, if any.
    pub fn pair_of(&self, camera: CameraIndex) -> Option<usize> {
        self.pairs
            .iter()
            .position(|p| p.left == camera || p.right == camera)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{Distortion, Intrinsics};
    use nalgebra::Rotation3;

    /// A camera whose centre depends on its name, so every test camera has its own centre.
    fn cam(name: &str) -> Camera {
        let offset = name.bytes().map(f64::from).sum::<f64>() * 0.01;
        Camera::new(
            CameraId::new(name).unwrap(),
            Intrinsics {
                fx: 800.0,
                fy: 800.0,
                cx: 320.0,
                cy: 240.0,
                skew: 0.0,
                width_px: 640,
                height_px: 480,
            },
            Distortion::default(),
            Rotation3::identity(),
            Vector3::new(offset, 0.0, 0.0),
        )
        .unwrap()
    }

    #[test]
    fn duplicate_ids_are_rejected() {
        let err = CameraRig::new(vec![cam("a"), cam("b"), cam("a")], &[], None).unwrap_err();
        assert_eq!(
            err,
            PerceptionError::DuplicateCamera(CameraId::new("a").unwrap())
        );
    }

    #[test]
    fn default_pairs_are_consecutive_and_named_pairs_resolve() {
        let rig = CameraRig::new(vec![cam("a"), cam("b"), cam("c"), cam("d")], &[], None).unwrap();
        assert_eq!(rig.pairs().len(), 2);
        assert_eq!((rig.pairs()[1].left, rig.pairs()[1].right), (2, 3));
        let pairs = [("front".to_owned(), "d".to_owned(), "a".to_owned())];
        let rig =
            CameraRig::new(vec![cam("a"), cam("b"), cam("c"), cam("d")], &pairs, None).unwrap();
        assert_eq!((rig.pairs()[0].left, rig.pairs()[0].right), (3, 0));
        assert_eq!(rig.pair_of(1), None);
        let bad = [("x".to_owned(), "a".to_owned(), "zz".to_owned())];
        assert!(matches!(
            CameraRig::new(vec![cam("a")], &bad, None),
            Err(PerceptionError::UnknownCamera(_))
        ));
        let same = [("x".to_owned(), "a".to_owned(), "a".to_owned())];
        assert!(matches!(
            CameraRig::new(vec![cam("a")], &same, None),
            Err(PerceptionError::DegeneratePair(_))
        ));
        assert!(matches!(
            CameraRig::new(vec![], &[], None),
            Err(PerceptionError::EmptyRig)
        ));
    }

    /// Four cameras on a 3 m ring, 1.5 m up, looking at the operator's chest (the cell's layout), or
    /// each turned round to look straight away from it.
    fn ring(turned_away: bool) -> Vec<Camera> {
        (0..4)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::FRAC_PI_2;
                let eye = Point3::new(3.0 * a.cos(), 3.0 * a.sin(), 1.5);
                let chest = Point3::new(0.0, 0.0, 1.2);
                let target = if turned_away {
                    eye + (eye - chest)
                } else {
                    chest
                };
                Camera::look_at(
                    CameraId::new(format!("cam{i}")).unwrap(),
                    eye,
                    target,
                    Vector3::z(),
                    cam("x").intrinsics,
                    Distortion::default(),
                )
                .unwrap()
            })
            .collect()
    }

    #[test]
    fn a_rig_in_millimetres_or_facing_away_is_refused_naming_why() {
        assert!(CameraRig::new(ring(false), &[], None).is_ok());
        // The same ring in millimetres: 4.2 km between neighbours.
        let mm: Vec<Camera> = ring(false)
            .into_iter()
            .map(|c| {
                let t = c.T_camera_world.translation.vector * 1000.0;
                Camera::new(
                    c.id.clone(),
                    c.intrinsics,
                    Distortion::default(),
                    c.T_camera_world.rotation.to_rotation_matrix(),
                    t,
                )
                .unwrap()
            })
            .collect();
        let e = CameraRig::new(mm, &[], None).unwrap_err();
        assert!(matches!(e, PerceptionError::RigTooLarge { .. }), "{e}");
        assert!(e.to_string().contains("millimetres"), "{e}");
        // Every camera turned away.
        let e = CameraRig::new(ring(true), &[], None).unwrap_err();
        assert!(matches!(e, PerceptionError::CamerasFaceAway { .. }), "{e}");
        // Two cameras side by side looking the same way (a stereo bar) pin no point down: accepted.
        assert!(CameraRig::new(vec![cam("a"), cam("b")], &[], None).is_ok());
    }

    #[test]
    fn up_is_normalised_and_zero_up_rejected() {
        let rig = CameraRig::new(vec![cam("a")], &[], Some(Vector3::new(0.0, 0.0, 2.0))).unwrap();
        assert_eq!(rig.up(), Some(Vector3::z()));
        assert!(CameraRig::new(vec![cam("a")], &[], Some(Vector3::zeros())).is_err());
    }
}
