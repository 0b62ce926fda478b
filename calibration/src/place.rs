//! Placing calibrated cameras in the cell's frame from points measured in it.
//!
//! `calibrate stereo` gives a pair in its left camera's frame; the cell needs every camera in its
//! own frame (origin on the floor at the operator's station, z up). Each *group* (a stereo pair's
//! file, or any set of cameras calibrated in one frame) is rigid: its pose in the cell,
//! `T_cell_group`, is what is found here, from points whose cell coordinates were measured (a tape, a
//! total station, the corners of a board laid at a known place) and whose pixels each camera saw.
//!
//! 1. Each point seen by two cameras of the group is triangulated in the group's frame (DLT on
//!    undistorted pixels, [`ergocell_perception::triangulation::dlt`]).
//! 2. The rigid transform between those points and their cell coordinates (Kabsch/Umeyama without
//!    scale: Umeyama, TPAMI 13(4), 1991) starts the pose.
//! 3. Levenberg–Marquardt ([`crate::lm`]) refines the pose's six parameters on every sighting's
//!    reprojection error in the group's cameras, points seen by one camera included: the maximum
//!    likelihood pose under pixel noise, as OpenCV's `solvePnP` for one camera.
//!
//! The error per group (RMS and worst pixel, the points used) is reported for the user to judge.

use std::collections::BTreeMap;

use ergocell_perception::triangulation::dlt;
use ergocell_perception::{Camera, CameraRig};
use nalgebra::{
    Isometry3, Matrix3, Point2, Point3, Rotation3, Translation3, UnitQuaternion, Vector2, Vector3,
};
use serde::Deserialize;

use crate::error::{CalibrationError, Result};
use crate::lm::BlockProblem as _;
use crate::model::{pose_from_params, pose_to_params};

/// Points a group must have triangulated to start its pose (three, not on one line).
pub const MIN_TRIANGULATED: usize = 3;

/// The worst fit a placement may have: a reprojection RMS above this is a wrong camera id, a wrong
/// measurement or a wrong click, not noise (clicked markers are about 1 px, board corners 0.2 px).
pub const MAX_RMS_PX: f64 = 5.0;

/// A point measured in the cell's frame and the pixels at which cameras saw it.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredPoint {
    pub name: String,
    pub cell_m: Point3<f64>,
    /// Camera id → pixel (as the camera delivers it: distorted).
    pub seen: BTreeMap<String, Point2<f64>>,
}

/// Where one group ended up, and how well its sightings agree with it.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupPlacement {
    /// The group's cameras, in its file's order.
    pub cameras: Vec<String>,
    /// The group's frame in the cell.
    pub T_cell_group: Isometry3<f64>,
    /// Points triangulated in the group's frame to start the pose, and sightings used to refine it.
    pub triangulated: usize,
    pub sightings: usize,
    /// Reprojection error of the placed group over its sightings, pixels; and of the rigid fit it
    /// started from (the refinement's gain).
    pub rms_px: f64,
    pub start_rms_px: f64,
    pub max_px: f64,
    /// The point whose sighting was worst.
    pub worst_point: String,
}

/// The cameras of every group in the cell's frame, with `up` = +z.
#[derive(Debug, Clone)]
pub struct Placement {
    pub rig: CameraRig,
    pub groups: Vec<GroupPlacement>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PointsFile {
    point: Vec<PointEntry>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PointEntry {
    name: String,
    cell_m: [f64; 3],
    seen: BTreeMap<String, [f64; 2]>,
}

/// Parses a points file (TOML): `[[point]]` tables with `name`, `cell_m = [x, y, z]` (metres, in the
/// cell's frame) and `[point.seen]` (camera id = `[u, v]` pixels). Unknown keys, non-finite values and
/// repeated names are refused, naming the point.
pub fn parse_points(text: &str, source_name: &str) -> Result<Vec<MeasuredPoint>> {
    let bad = |why: String| CalibrationError::BadPoints {
        source_name: source_name.to_owned(),
        why,
    };
    let file: PointsFile = toml::from_str(text).map_err(|e| bad(e.message().to_owned()))?;
    let mut points: Vec<MeasuredPoint> = Vec::with_capacity(file.point.len());
    for p in file.point {
        if points.iter().any(|q| q.name == p.name) {
            return Err(bad(format!("point `{}` is listed twice", p.name)));
        }
        if !p.cell_m.iter().all(|v| v.is_finite()) {
            return Err(bad(format!("point `{}`: cell_m is not finite", p.name)));
        }
        let mut seen = BTreeMap::new();
        for (camera, [u, v]) in p.seen {
            if !(u.is_finite() && v.is_finite()) {
                return Err(bad(format!(
                    "point `{}`: the pixel of `{camera}` is not finite",
                    p.name
                )));
            }
            seen.insert(camera, Point2::new(u, v));
        }
        points.push(MeasuredPoint {
            name: p.name,
            cell_m: Point3::from(p.cell_m),
            seen,
        });
    }
    Ok(points)
}

/// Places each group (a rig in its own frame) in the cell from `points`. Every camera id a point
/// names must be in exactly one group.
pub fn place(groups: &[CameraRig], points: &[MeasuredPoint]) -> Result<Placement> {
    for p in points {
        for camera in p.seen.keys() {
            let owners = groups
                .iter()
                .filter(|g| g.index_of_name(camera).is_some())
                .count();
            if owners != 1 {
                return Err(CalibrationError::PlaceCamera {
                    camera: camera.clone(),
                    groups: owners,
                });
            }
        }
    }
    let mut cameras = Vec::new();
    let mut placed = Vec::new();
    let mut pairs = Vec::new();
    for group in groups {
        let p = place_group(group, points)?;
        for pair in group.pairs() {
            pairs.push((
                format!("S{}", pairs.len() + 1),
                group.cameras()[pair.left].id.as_str().to_owned(),
                group.cameras()[pair.right].id.as_str().to_owned(),
            ));
        }
        for c in group.cameras() {
            let T_camera_cell = c.T_camera_world * p.T_cell_group.inverse();
            cameras.push(Camera::new(
                c.id.clone(),
                c.intrinsics,
                c.distortion,
                T_camera_cell.rotation.to_rotation_matrix(),
                T_camera_cell.translation.vector,
            )?);
        }
        placed.push(p);
    }
    let rig = CameraRig::new(cameras, &pairs, Some(Vector3::z()))?;
    Ok(Placement {
        rig,
        groups: placed,
    })
}

/// One sighting of a measured point by one of the group's cameras.
struct Sighting {
    /// Index into the group's cameras.
    camera: usize,
    cell_m: Point3<f64>,
    pixel: Point2<f64>,
    point: usize,
}

fn place_group(group: &CameraRig, points: &[MeasuredPoint]) -> Result<GroupPlacement> {
    let names: Vec<String> = group
        .cameras()
        .iter()
        .map(|c| c.id.as_str().to_owned())
        .collect();
    if let [only] = names.as_slice() {
        return Err(CalibrationError::GroupOfOne {
            camera: only.clone(),
        });
    }
    let mut sightings = Vec::new();
    let mut pairs = Vec::new(); // (point in the group's frame, in the cell)
    for (i, p) in points.iter().enumerate() {
        let mut views = Vec::new();
        for (camera, pixel) in &p.seen {
            let Some(index) = group.index_of_name(camera) else {
                continue;
            };
            let c = &group.cameras()[index];
            sightings.push(Sighting {
                camera: index,
                cell_m: p.cell_m,
                pixel: *pixel,
                point: i,
            });
            if let Ok(undistorted) = c.undistort_pixel(pixel) {
                views.push((c.projection_matrix(), undistorted, 1.0));
            }
        }
        if views.len() >= 2 {
            if let Ok(p_group) = dlt(&views) {
                pairs.push((p_group, p.cell_m));
            }
        }
    }
    let start = rigid_fit(&pairs).ok_or_else(|| CalibrationError::TooFewPoints {
        cameras: names.join(", "),
        triangulated: pairs.len(),
        needed: MIN_TRIANGULATED,
    })?;
    // Refine T_group_cell: the camera maps a cell point by T_camera_group * T_group_cell.
    let problem = Reprojection {
        group,
        sightings: &sightings,
        params: [0, 1, 2, 3, 4, 5],
    };
    let mut x = pose_to_params(&start.inverse()).to_vec();
    let (start_rms_px, _, _) = fit(&problem, &sightings, &x);
    crate::lm::solve(&problem, &mut x, &[false; 6], 100);
    let T_cell_group = pose_from_params(&x).inverse();
    let (rms_px, max_px, worst) = fit(&problem, &sightings, &x);
    let name = |i: usize| points.get(i).map(|p| p.name.clone()).unwrap_or_default();
    // Every sighting in front of its camera: a point behind one is a wrong id or a wrong sign.
    for s in &sightings {
        let c = &group.cameras()[s.camera];
        if (c.T_camera_world * (T_cell_group.inverse() * s.cell_m)).z <= 0.0 {
            return Err(CalibrationError::BehindCamera {
                camera: c.id.as_str().to_owned(),
                point: name(s.point),
            });
        }
    }
    if rms_px.is_nan() || rms_px > MAX_RMS_PX {
        return Err(CalibrationError::PoorFit {
            cameras: names.join(", "),
            rms_px,
            limit_px: MAX_RMS_PX,
            worst_point: name(worst),
        });
    }
    Ok(GroupPlacement {
        cameras: names,
        T_cell_group,
        triangulated: pairs.len(),
        sightings: sightings.len(),
        rms_px,
        start_rms_px,
        max_px,
        worst_point: name(worst),
    })
}

/// The RMS and worst reprojection error (pixels) at `x`, and the worst sighting's point.
fn fit(problem: &Reprojection<'_>, sightings: &[Sighting], x: &[f64]) -> (f64, f64, usize) {
    let mut residual = Vec::new();
    let (mut sum, mut max, mut worst) = (0.0, 0.0, 0);
    for (b, s) in sightings.iter().enumerate() {
        problem.block_residuals(b, x, &mut residual);
        let e = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
        sum += e * e;
        if e > max {
            max = e;
            worst = s.point;
        }
    }
    let n = sightings.len().max(1);
    ((sum / n as f64).sqrt(), max, worst)
}

/// The residual of a point behind its camera, pixels.
const BEHIND_PX: f64 = 1e4;

/// Reprojection of the group's sightings with the group at `x` = `T_group_cell`'s parameters.
struct Reprojection<'a> {
    group: &'a CameraRig,
    sightings: &'a [Sighting],
    params: [usize; 6],
}

impl crate::lm::BlockProblem for Reprojection<'_> {
    fn blocks(&self) -> usize {
        self.sightings.len()
    }

    fn block_params(&self, _: usize) -> &[usize] {
        &self.params
    }

    fn block_residuals(&self, b: usize, x: &[f64], out: &mut Vec<f64>) {
        out.clear();
        let s = &self.sightings[b];
        let c = &self.group.cameras()[s.camera];
        let p_camera = c.T_camera_world * (pose_from_params(x) * s.cell_m);
        if p_camera.z <= 1e-9 {
            // Behind the camera: as far off as a pixel can be, so the solve turns away from it.
            out.extend([BEHIND_PX, BEHIND_PX]);
            return;
        }
        // The camera's own model (skew included), as triangulation uses it.
        let px = c.normalized_to_pixel(Vector2::new(
            p_camera.x / p_camera.z,
            p_camera.y / p_camera.z,
        ));
        out.push(px.x - s.pixel.x);
        out.push(px.y - s.pixel.y);
    }
}

/// The rigid transform `T` with `T * from ≈ to` in least squares (Kabsch), or `None` for fewer than
/// [`MIN_TRIANGULATED`] pairs or points on one line.
pub fn rigid_fit(pairs: &[(Point3<f64>, Point3<f64>)]) -> Option<Isometry3<f64>> {
    if pairs.len() < MIN_TRIANGULATED {
        return None;
    }
    let n = pairs.len() as f64;
    let ca = pairs.iter().map(|p| p.0.coords).sum::<Vector3<f64>>() / n;
    let cb = pairs.iter().map(|p| p.1.coords).sum::<Vector3<f64>>() / n;
    let mut h = Matrix3::zeros();
    for (a, b) in pairs {
        h += (a.coords - ca) * (b.coords - cb).transpose();
    }
    let svd = h.svd(true, true);
    let (u, v_t) = (svd.u?, svd.v_t?);
    // Points on a line (or one point repeated) leave two singular values at zero: no rotation.
    let s = svd.singular_values;
    let largest = s.max();
    let mut sorted = [s[0], s[1], s[2]];
    sorted.sort_by(f64::total_cmp);
    if largest.is_nan() || largest <= 0.0 || sorted[1] <= 1e-9 * largest {
        return None;
    }
    let mut d = Matrix3::identity();
    if (v_t.transpose() * u.transpose()).determinant() < 0.0 {
        d[(2, 2)] = -1.0;
    }
    let r = v_t.transpose() * d * u.transpose();
    let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r));
    let t = cb - rotation * ca;
    Some(Isometry3::from_parts(Translation3::from(t), rotation))
}
