//! Calibration files: ergocell's own rig TOML, and import of the Anipose / Pose2Sim and caliscope TOMLs
//! and of Qualisys QTM's XML export.
//!
//! The crate does no I/O: callers pass the file's text and its name (used in every error, together
//! with the offending field, e.g. `calib.toml: field cam_1.matrix[0][0]: not a finite number`).
//!
//! | format | rotation | translation | notes |
//! |---|---|---|---|
//! | ergocell (`[[camera]]` array) | Rodrigues vector, world→camera | metres | optional `up`, `[[stereo_pair]]` |
//! | Anipose / Pose2Sim (`[cam_x]` tables) | Rodrigues vector, world→camera | metres (Pose2Sim); Anipose writes the board's unit, scale it | `fisheye = true` is refused |
//! | caliscope `config.toml` (`[cam_N]` tables) | 3×3 matrix, world→camera | metres | `ignore = true` cameras are skipped |
//! | Qualisys QTM `.qca.txt` (XML) | 3×3 matrix, camera pose in the lab | millimetres | intrinsics in 1/64 px; [`crate::qualisys`] |

use nalgebra::{Matrix3, Rotation3, Vector3};
use serde::{Deserialize, Serialize};
use toml::Value;

use crate::error::{parse_err, PerceptionError, Result};
use ergocell_perception::camera::{Camera, CameraId, Distortion, Intrinsics};
use ergocell_perception::rig::CameraRig;

/// Which calibration format a file is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RigFormat {
    /// ergocell's own rig file.
    Ergocell,
    /// Anipose / Pose2Sim calibration TOML (Rodrigues rotation).
    Anipose,
    /// caliscope `config.toml` (3×3 rotation matrix).
    Caliscope,
    /// Qualisys QTM calibration export (`.qca.txt`, XML), converted as Pose2Sim does
    /// ([`crate::qualisys`]).
    Qualisys,
}

/// Parses a calibration file of any supported format, detecting the format from its content.
pub fn parse_rig(text: &str, source_name: &str) -> Result<(CameraRig, RigFormat)> {
    if crate::qualisys::looks_like_qca(text) {
        return Ok((
            crate::qualisys::parse_qualisys(text, source_name)?,
            RigFormat::Qualisys,
        ));
    }
    let value: Value =
        toml::from_str(text).map_err(|e| parse_err(source_name, "(file)", e.message()))?;
    let table = value
        .as_table()
        .ok_or_else(|| parse_err(source_name, "(file)", "not a TOML table"))?;
    if table.contains_key("camera") {
        return Ok((parse_ergocell(text, source_name)?, RigFormat::Ergocell));
    }
    let is_caliscope = table.values().filter_map(Value::as_table).any(|t| {
        t.get("rotation")
            .and_then(Value::as_array)
            .and_then(|a| a.first())
            .is_some_and(Value::is_array)
    });
    if is_caliscope {
        Ok((parse_caliscope(&value, source_name)?, RigFormat::Caliscope))
    } else {
        Ok((parse_anipose(&value, source_name, 1.0)?, RigFormat::Anipose))
    }
}

/// One camera in ergocell's rig file.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraEntry {
    id: String,
    /// Image size in pixels, `[width, height]`.
    size_px: [u32; 2],
    fx: f64,
    fy: f64,
    cx: f64,
    cy: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    skew: f64,
    /// Brown–Conrady coefficients, OpenCV order `[k1, k2, p1, p2, k3]`.
    distortion: [f64; 5],
    /// World→camera rotation as a Rodrigues vector (axis × angle, radians).
    rotation_rodrigues_rad: [f64; 3],
    /// World→camera translation, metres (`p_camera = R p_world + t`).
    translation_m: [f64; 3],
}

#[allow(clippy::trivially_copy_pass_by_ref)] // serde's skip_serializing_if passes a reference
fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PairEntry {
    name: String,
    left: String,
    right: String,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RigEntry {
    /// The world's up direction, if known (the world frame is the calibration's choice).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    up: Option<[f64; 3]>,
    camera: Vec<CameraEntry>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    stereo_pair: Vec<PairEntry>,
}

/// Parses ergocell's own rig file.
pub fn parse_ergocell(text: &str, source_name: &str) -> Result<CameraRig> {
    let rig: RigEntry = toml::from_str(text).map_err(|e| {
        let span = e
            .span()
            .map(|s| format!(" (byte {})", s.start))
            .unwrap_or_default();
        parse_err(source_name, "(file)", format!("{}{span}", e.message()))
    })?;
    let mut cameras = Vec::with_capacity(rig.camera.len());
    for (i, c) in rig.camera.iter().enumerate() {
        let at = |field: &str| format!("camera[{i}].{field}");
        let id = CameraId::new(c.id.clone())
            .map_err(|_| parse_err(source_name, at("id"), "empty camera id"))?;
        let intrinsics = Intrinsics {
            fx: c.fx,
            fy: c.fy,
            cx: c.cx,
            cy: c.cy,
            skew: c.skew,
            width_px: c.size_px[0],
            height_px: c.size_px[1],
        };
        let [k1, k2, p1, p2, k3] = c.distortion;
        let rotation = rodrigues(
            c.rotation_rodrigues_rad,
            source_name,
            &at("rotation_rodrigues_rad"),
        )?;
        let camera = Camera::new(
            id,
            intrinsics,
            Distortion { k1, k2, p1, p2, k3 },
            rotation,
            Vector3::from(c.translation_m),
        )
        .map_err(|e| parse_err(source_name, format!("camera[{i}]"), e))?;
        cameras.push(camera);
    }
    let pairs: Vec<_> = rig
        .stereo_pair
        .iter()
        .map(|p| (p.name.clone(), p.left.clone(), p.right.clone()))
        .collect();
    CameraRig::new(cameras, &pairs, rig.up.map(Vector3::from))
        .map_err(|e| parse_err(source_name, "(rig)", e))
}

/// Writes a rig in ergocell's own format.
pub fn to_ergocell_toml(rig: &CameraRig) -> String {
    let entry = RigEntry {
        up: rig.up().map(Into::into),
        camera: rig
            .cameras()
            .iter()
            .map(|c| {
                let k = c.intrinsics;
                let r = c.T_camera_world.rotation.scaled_axis();
                CameraEntry {
                    id: c.id.to_string(),
                    size_px: [k.width_px, k.height_px],
                    fx: k.fx,
                    fy: k.fy,
                    cx: k.cx,
                    cy: k.cy,
                    skew: k.skew,
                    distortion: c.distortion.to_array(),
                    rotation_rodrigues_rad: [r.x, r.y, r.z],
                    translation_m: c.T_camera_world.translation.vector.into(),
                }
            })
            .collect(),
        stereo_pair: rig
            .pairs()
            .iter()
            .map(|p| PairEntry {
                name: p.name.clone(),
                left: rig.cameras()[p.left].id.to_string(),
                right: rig.cameras()[p.right].id.to_string(),
            })
            .collect(),
    };
    let body = toml::to_string(&entry).unwrap_or_default();
    format!(
        "# ergocell camera rig. Extrinsics map world to camera: p_camera = R(rotation_rodrigues_rad) p_world + translation_m.\n\
         # Camera frame: x right, y down, z forward. Distortion: OpenCV order k1 k2 p1 p2 k3.\n{body}"
    )
}

/// Writes a rig as an Anipose / Pose2Sim calibration TOML (translation in metres).
pub fn to_anipose_toml(rig: &CameraRig) -> String {
    use std::fmt::Write as _;
    let mut out = String::new();
    for (i, c) in rig.cameras().iter().enumerate() {
        let k = c.intrinsics;
        let r = c.T_camera_world.rotation.scaled_axis();
        let t = c.T_camera_world.translation.vector;
        let d = c.distortion.to_array();
        let _ = writeln!(out, "[cam_{i}]");
        let _ = writeln!(out, "name = \"{}\"", c.id);
        let _ = writeln!(out, "size = [ {}, {},]", k.width_px, k.height_px);
        let _ = writeln!(
            out,
            "matrix = [ [ {:?}, {:?}, {:?},], [ 0.0, {:?}, {:?},], [ 0.0, 0.0, 1.0,],]",
            k.fx, k.skew, k.cx, k.fy, k.cy
        );
        let _ = writeln!(
            out,
            "distortions = [ {:?}, {:?}, {:?}, {:?}, {:?},]",
            d[0], d[1], d[2], d[3], d[4]
        );
        let _ = writeln!(out, "rotation = [ {:?}, {:?}, {:?},]", r.x, r.y, r.z);
        let _ = writeln!(out, "translation = [ {:?}, {:?}, {:?},]", t.x, t.y, t.z);
        let _ = writeln!(out, "fisheye = false\n");
    }
    out.push_str("[metadata]\nadjusted = false\nerror = 0.0\n");
    out
}

/// Parses an Anipose / Pose2Sim calibration; translations are multiplied by `translation_scale`
/// (1 for Pose2Sim's metres, 0.001 for an Anipose file in millimetres).
pub fn parse_anipose(
    value: &Value,
    source_name: &str,
    translation_scale: f64,
) -> Result<CameraRig> {
    let table = value
        .as_table()
        .ok_or_else(|| parse_err(source_name, "(file)", "not a TOML table"))?;
    let mut cameras = Vec::new();
    for (key, entry) in table {
        if key == "metadata" {
            continue;
        }
        let Some(t) = entry.as_table() else { continue };
        let id = match t.get("name") {
            Some(v) => v
                .as_str()
                .map(str::to_owned)
                .ok_or_else(|| parse_err(source_name, format!("{key}.name"), "not a string"))?,
            None => key.clone(),
        };
        if t.get("fisheye").and_then(Value::as_bool) == Some(true) {
            return Err(parse_err(
                source_name,
                format!("{key}.fisheye"),
                "fisheye (Kannala–Brandt) cameras are not supported",
            ));
        }
        let (intrinsics, distortion) = intrinsics_of(t, key, source_name)?;
        let rvec = numbers::<3>(t, "rotation", key, source_name)?;
        let rotation = rodrigues(rvec, source_name, &format!("{key}.rotation"))?;
        let translation =
            Vector3::from(numbers::<3>(t, "translation", key, source_name)?) * translation_scale;
        let camera_id = CameraId::new(id)
            .map_err(|_| parse_err(source_name, format!("{key}.name"), "empty camera name"))?;
        cameras.push(
            Camera::new(camera_id, intrinsics, distortion, rotation, translation)
                .map_err(|e| parse_err(source_name, key.clone(), e))?,
        );
    }
    CameraRig::new(cameras, &[], None).map_err(|e| parse_err(source_name, "(rig)", e))
}

/// Parses caliscope's `config.toml` (rotation as a 3×3 matrix). Cameras marked `ignore = true` are
/// skipped. Camera ids are the table names (`cam_0`, …), which match `port` N in caliscope's CSVs.
pub fn parse_caliscope(value: &Value, source_name: &str) -> Result<CameraRig> {
    let table = value
        .as_table()
        .ok_or_else(|| parse_err(source_name, "(file)", "not a TOML table"))?;
    let mut cameras = Vec::new();
    for (key, entry) in table {
        let Some(t) = entry.as_table() else { continue };
        if !key.starts_with("cam_") {
            continue;
        }
        if t.get("ignore").and_then(Value::as_bool) == Some(true) {
            continue;
        }
        let (intrinsics, distortion) = intrinsics_of(t, key, source_name)?;
        let r = matrix3(t, "rotation", key, source_name)?;
        let rotation = Rotation3::from_matrix_unchecked(r);
        let translation = Vector3::from(numbers::<3>(t, "translation", key, source_name)?);
        let camera_id =
            CameraId::new(key.clone()).map_err(|e| parse_err(source_name, key.clone(), e))?;
        cameras.push(
            Camera::new(camera_id, intrinsics, distortion, rotation, translation)
                .map_err(|e| parse_err(source_name, key.clone(), e))?,
        );
    }
    // TOML tables are unordered in `toml::Table` (sorted by key); sort by port number so cam_10 follows cam_9.
    cameras.sort_by_key(|c| {
        c.id.as_str()
            .trim_start_matches("cam_")
            .parse::<u64>()
            .unwrap_or(u64::MAX)
    });
    CameraRig::new(cameras, &[], None).map_err(|e| parse_err(source_name, "(rig)", e))
}

fn intrinsics_of(
    t: &toml::Table,
    key: &str,
    source_name: &str,
) -> Result<(Intrinsics, Distortion)> {
    let size = numbers::<2>(t, "size", key, source_name)?;
    if size
        .iter()
        .any(|s| *s < 1.0 || s.fract() != 0.0 || *s > f64::from(u32::MAX))
    {
        return Err(parse_err(
            source_name,
            format!("{key}.size"),
            format!("{size:?} is not a positive pixel size"),
        ));
    }
    let k = matrix3(t, "matrix", key, source_name)?;
    if k[(1, 0)] != 0.0 || k[(2, 0)] != 0.0 || k[(2, 1)] != 0.0 || k[(2, 2)] != 1.0 {
        return Err(parse_err(
            source_name,
            format!("{key}.matrix"),
            "not an upper-triangular camera matrix with K[2][2] = 1",
        ));
    }
    let d = t
        .get("distortions")
        .ok_or_else(|| parse_err(source_name, format!("{key}.distortions"), "missing"))?;
    let d = float_list(d, source_name, &format!("{key}.distortions"))?;
    let distortion = Distortion::from_slice(&d).ok_or_else(|| {
        parse_err(
            source_name,
            format!("{key}.distortions"),
            format!("expected 4 or 5 coefficients, got {}", d.len()),
        )
    })?;
    Ok((
        Intrinsics {
            fx: k[(0, 0)],
            fy: k[(1, 1)],
            cx: k[(0, 2)],
            cy: k[(1, 2)],
            skew: k[(0, 1)],
            width_px: size[0] as u32,
            height_px: size[1] as u32,
        },
        distortion,
    ))
}

fn float_list(v: &Value, source_name: &str, field: &str) -> Result<Vec<f64>> {
    let a = v
        .as_array()
        .ok_or_else(|| parse_err(source_name, field, "not an array"))?;
    a.iter()
        .enumerate()
        .map(|(i, x)| {
            let f = x.as_float().or_else(|| x.as_integer().map(|n| n as f64));
            match f {
                Some(f) if f.is_finite() => Ok(f),
                _ => Err(parse_err(
                    source_name,
                    format!("{field}[{i}]"),
                    format!("`{x}` is not a finite number"),
                )),
            }
        })
        .collect()
}

fn numbers<const N: usize>(
    t: &toml::Table,
    name: &str,
    key: &str,
    source_name: &str,
) -> Result<[f64; N]> {
    let field = format!("{key}.{name}");
    let v = t
        .get(name)
        .ok_or_else(|| parse_err(source_name, &field, "missing"))?;
    let list = float_list(v, source_name, &field)?;
    list.try_into().map_err(|l: Vec<f64>| {
        parse_err(
            source_name,
            &field,
            format!("expected {N} numbers, got {}", l.len()),
        )
    })
}

fn matrix3(t: &toml::Table, name: &str, key: &str, source_name: &str) -> Result<Matrix3<f64>> {
    let field = format!("{key}.{name}");
    let v = t
        .get(name)
        .ok_or_else(|| parse_err(source_name, &field, "missing"))?;
    let rows = v
        .as_array()
        .ok_or_else(|| parse_err(source_name, &field, "not an array of rows"))?;
    if rows.len() != 3 {
        return Err(parse_err(
            source_name,
            &field,
            format!("expected 3 rows, got {}", rows.len()),
        ));
    }
    let mut m = Matrix3::zeros();
    for (i, row) in rows.iter().enumerate() {
        let row_field = format!("{field}[{i}]");
        let r = float_list(row, source_name, &row_field)?;
        if r.len() != 3 {
            return Err(parse_err(
                source_name,
                &row_field,
                format!("expected 3 numbers, got {}", r.len()),
            ));
        }
        for (j, x) in r.into_iter().enumerate() {
            m[(i, j)] = x;
        }
    }
    Ok(m)
}

fn rodrigues(r: [f64; 3], source_name: &str, field: &str) -> Result<Rotation3<f64>> {
    if r.iter().any(|x| !x.is_finite()) {
        return Err(parse_err(source_name, field, "not finite"));
    }
    Ok(Rotation3::from_scaled_axis(Vector3::from(r)))
}

/// Returns an error that names the unsupported format, for callers that match on extension.
pub fn unsupported(what: &str) -> PerceptionError {
    PerceptionError::Unsupported(what.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::Point3;

    const ANIPOSE: &str = r#"
[cam_0]
name = "int_cam1_img"
size = [ 1088.0, 1920.0,]
matrix = [ [ 1681.1, 0.0, 533.7,], [ 0.0, 1681.8, 958.7,], [ 0.0, 0.0, 1.0,],]
distortions = [ -0.0146, 0.0299, 0.0001, -0.0008,]
rotation = [ 1.6827, 1.0567, -0.5683,]
translation = [ 0.6118, 0.9706, 4.0118,]
fisheye = false

[cam_1]
name = "int_cam2_img"
size = [ 1088.0, 1920.0,]
matrix = [ [ 1694.0, 0.0, 532.0,], [ 0.0, 1694.6, 958.2,], [ 0.0, 0.0, 1.0,],]
distortions = [ -0.03, 0.05, 0.0, 0.0, 0.001]
rotation = [ 1.4, -1.2, 0.8,]
translation = [ -0.33, 0.9, 3.1,]
fisheye = false

[metadata]
adjusted = false
error = 0.0
"#;

    #[test]
    fn anipose_file_parses_with_four_or_five_coefficients() {
        let (rig, format) = parse_rig(ANIPOSE, "Calib.toml").unwrap();
        assert_eq!(format, RigFormat::Anipose);
        assert_eq!(rig.len(), 2);
        let c = &rig.cameras()[0];
        assert_eq!(c.id.as_str(), "int_cam1_img");
        assert_eq!(c.intrinsics.width_px, 1088);
        assert_eq!(c.distortion.k3, 0.0);
        assert_relative_eq!(
            c.T_camera_world.rotation.scaled_axis(),
            Vector3::new(1.6827, 1.0567, -0.5683),
            epsilon = 1e-12
        );
        assert_eq!(rig.cameras()[1].distortion.k3, 0.001);
    }

    #[test]
    fn errors_name_the_file_and_field() {
        let broken = ANIPOSE.replace("1681.1", "nan");
        let err = parse_rig(&broken, "Calib.toml").unwrap_err().to_string();
        assert!(
            err.contains("Calib.toml") && err.contains("cam_0.matrix[0][0]"),
            "{err}"
        );
        let broken = ANIPOSE.replace(
            "translation = [ 0.6118, 0.9706, 4.0118,]",
            "translation = [ 0.6118, 0.9706,]",
        );
        let err = parse_rig(&broken, "Calib.toml").unwrap_err().to_string();
        assert!(
            err.contains("cam_0.translation") && err.contains("expected 3"),
            "{err}"
        );
        let broken = ANIPOSE.replace("fisheye = false\n\n[cam_1]", "fisheye = true\n\n[cam_1]");
        let err = parse_rig(&broken, "Calib.toml").unwrap_err().to_string();
        assert!(err.contains("fisheye"), "{err}");
        let err = parse_rig("this is = not toml [", "x.toml")
            .unwrap_err()
            .to_string();
        assert!(err.contains("x.toml"), "{err}");
    }

    #[test]
    fn ergocell_format_round_trips_and_projects_identically() {
        let (rig, _) = parse_rig(ANIPOSE, "Calib.toml").unwrap();
        let text = to_ergocell_toml(&rig);
        let (back, format) = parse_rig(&text, "rig.toml").unwrap();
        assert_eq!(format, RigFormat::Ergocell);
        let anipose_again = to_anipose_toml(&back);
        let (back2, _) = parse_rig(&anipose_again, "again.toml").unwrap();
        let p = Point3::new(0.1, 0.2, 0.3);
        for (a, b) in rig.cameras().iter().zip(back2.cameras()) {
            assert_eq!(a.id, b.id);
            assert_relative_eq!(
                a.project(&p).unwrap(),
                b.project(&p).unwrap(),
                epsilon = 1e-9
            );
        }
    }

    #[test]
    fn ergocell_format_rejects_unknown_fields() {
        let (rig, _) = parse_rig(ANIPOSE, "Calib.toml").unwrap();
        let text = to_ergocell_toml(&rig).replace("fx =", "focal = 3\nfx =");
        let err = parse_rig(&text, "rig.toml").unwrap_err().to_string();
        assert!(err.contains("rig.toml") && err.contains("focal"), "{err}");
    }
}
