//! Import of a Qualisys QTM calibration export (`.qca.txt`, XML), as Pose2Sim converts it.
//!
//! QTM writes each camera's intrinsics in sensor sub-pixel units (1/64 pixel), its distortion scaled
//! the same way, and its pose as the camera's rotation and position in the lab frame, in millimetres.
//! The conversion is Pose2Sim's `calib_qca_fun` (pose2sim 0.10.49, `Pose2Sim/calibration.py`), the
//! reference every Pose2Sim demo is calibrated with:
//!
//! - `fx, fy = focalLengthU/V / 64`, `cx, cy = centerPointU/V / 64 − fov_video left/top`, and the image
//!   size is the video field of view (`right − left + 1` × `bottom − top + 1`); a `video_resolution`
//!   attribute (`"720p"`, …) scales all of these by `resolution / 1080`;
//! - distortion `[k1, k2, p1, p2, k3] = radialDistortion1..3, tangentalDistortion1..2 / 64`;
//! - with `M` the transform's matrix (rows `r11 r12 r13`, …) and `t` its position in metres, the
//!   world→camera pose is `R = diag(1, −1, −1) · M`, `t_cam = −R · t`: QTM's camera looks along its
//!   −z with y up, OpenCV's along +z with y down. So the camera centre is QTM's position, exactly.
//! - Only video cameras are kept (model `Miqus Video`, `Miqus Video UnderWater` or `none`, as
//!   Pose2Sim); marker-only cameras are skipped. Cameras are ordered by natural sort of their serial.
//!
//! The lab frame is QTM's: z up (the rig's `up`), metres. Checked on Pose2Sim's demo
//! (`../shared/data/pose2sim-demo-videos`): MediaPipe's landmarks of its four real videos triangulate
//! through this rig with a sub-pixel-to-few-pixel median reprojection error (`docs/measurements.md`).

use nalgebra::{Matrix3, Rotation3, Vector3};

use crate::error::{parse_err, Result};
use ergocell_perception::camera::{Camera, CameraId, Distortion, Intrinsics};
use ergocell_perception::rig::CameraRig;

/// QTM's sub-pixel unit: intrinsics (and, in its export, the distortion terms) are in 1/64 pixel.
pub const SUBPIXELS_PER_PIXEL: f64 = 64.0;

/// Camera models Pose2Sim treats as video cameras (the others are marker-only).
const VIDEO_MODELS: [&str; 3] = ["Miqus Video", "Miqus Video UnderWater", "none"];

/// True when the text looks like a QTM calibration export (an XML `<calibration>` document).
pub fn looks_like_qca(text: &str) -> bool {
    let t = text.trim_start_matches('\u{feff}').trim_start();
    t.starts_with('<') && t.contains("<calibration") && t.contains("<cameras")
}

/// Parses a QTM `.qca.txt` calibration export into a rig (no stereo pairs unless the count is even,
/// then consecutive cameras as [`CameraRig::new`] pairs them; `up` = +z).
pub fn parse_qualisys(text: &str, source_name: &str) -> Result<CameraRig> {
    // roxmltree builds its tree recursively: bound the nesting before it reads.
    ergocell_nesting::check(text, ergocell_nesting::MAX_XML_DEPTH)
        .map_err(|e| parse_err(source_name, "(file)", e.to_string()))?;
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| parse_err(source_name, "(file)", format!("not valid XML: {e}")))?;
    let root = doc.root_element();
    if !root.has_tag_name("calibration") {
        return Err(parse_err(
            source_name,
            "(file)",
            format!(
                "root element is <{}>, a QTM export has <calibration>",
                root.tag_name().name()
            ),
        ));
    }
    let cameras_node = root
        .children()
        .find(|n| n.has_tag_name("cameras"))
        .ok_or_else(|| parse_err(source_name, "cameras", "no <cameras> element"))?;
    let mut cameras = Vec::new();
    for (index, node) in cameras_node
        .children()
        .filter(|n| n.has_tag_name("camera"))
        .enumerate()
    {
        let serial = node
            .attribute("serial")
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .ok_or_else(|| {
                parse_err(
                    source_name,
                    format!("camera[{index}].serial"),
                    "missing or empty",
                )
            })?;
        let field = |f: &str| format!("camera {serial}.{f}");
        if node
            .attribute("model")
            .is_some_and(|m| !VIDEO_MODELS.contains(&m))
        {
            continue; // a marker-only camera: no video to detect people in
        }
        let scale = match node.attribute("video_resolution") {
            None => 1.0,
            Some(r) => {
                let lines: f64 = r
                    .trim()
                    .trim_end_matches(['p', 'P'])
                    .parse()
                    .ok()
                    .filter(|v: &f64| v.is_finite() && *v > 0.0)
                    .ok_or_else(|| {
                        parse_err(
                            source_name,
                            field("video_resolution"),
                            format!("`{r}` is not like \"1080p\""),
                        )
                    })?;
                lines / 1080.0
            }
        };
        let child = |tag: &str| {
            node.children()
                .find(|n| n.has_tag_name(tag))
                .ok_or_else(|| parse_err(source_name, field(tag), "missing"))
        };
        let number = |n: roxmltree::Node<'_, '_>, tag: &str, attr: &str| -> Result<f64> {
            let raw = n.attribute(attr).ok_or_else(|| {
                parse_err(source_name, field(&format!("{tag}.{attr}")), "missing")
            })?;
            raw.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    parse_err(
                        source_name,
                        field(&format!("{tag}.{attr}")),
                        format!("`{raw}` is not a finite number"),
                    )
                })
        };
        let fov = child("fov_video")?;
        let (left, right) = (
            number(fov, "fov_video", "left")?,
            number(fov, "fov_video", "right")?,
        );
        let (top, bottom) = (
            number(fov, "fov_video", "top")?,
            number(fov, "fov_video", "bottom")?,
        );
        let size = |lo: f64, hi: f64, what: &str| -> Result<u32> {
            let s = ((hi - lo + 1.0) * scale).round();
            if (1.0..=100_000.0).contains(&s) {
                Ok(s as u32)
            } else {
                Err(parse_err(
                    source_name,
                    field("fov_video"),
                    format!("{what} of {s} px (from {lo}..{hi})"),
                ))
            }
        };
        let (width_px, height_px) = (size(left, right, "width")?, size(top, bottom, "height")?);
        let i = child("intrinsic")?;
        let sub = |attr: &str| number(i, "intrinsic", attr).map(|v| v / SUBPIXELS_PER_PIXEL);
        let intrinsics = Intrinsics {
            fx: sub("focalLengthU")? * scale,
            fy: sub("focalLengthV")? * scale,
            cx: (sub("centerPointU")? - left) * scale,
            cy: (sub("centerPointV")? - top) * scale,
            skew: 0.0,
            width_px,
            height_px,
        };
        let optional = |attr: &str| -> Result<f64> {
            if i.attribute(attr).is_some() {
                sub(attr)
            } else {
                Ok(0.0)
            }
        };
        let distortion = Distortion {
            k1: sub("radialDistortion1")?,
            k2: sub("radialDistortion2")?,
            p1: sub("tangentalDistortion1")?,
            p2: sub("tangentalDistortion2")?,
            k3: optional("radialDistortion3")?,
        };
        let tr = child("transform")?;
        let mut m = Matrix3::zeros();
        for r in 0..3 {
            for c in 0..3 {
                m[(r, c)] = number(tr, "transform", &format!("r{}{}", r + 1, c + 1))?;
            }
        }
        let position_m = Vector3::new(
            number(tr, "transform", "x")?,
            number(tr, "transform", "y")?,
            number(tr, "transform", "z")?,
        ) / 1000.0;
        let orthonormal_error = (m.transpose() * m - Matrix3::identity()).amax();
        if orthonormal_error > 1e-6 || m.determinant() < 0.0 {
            return Err(parse_err(
                source_name,
                field("transform"),
                format!(
                    "not a rotation (|MᵀM − I| = {orthonormal_error:.1e}, det {:.3})",
                    m.determinant()
                ),
            ));
        }
        let r_camera_world = Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)) * m;
        let r_camera_world = Rotation3::from_matrix(&r_camera_world);
        let t_camera_world = -(r_camera_world * position_m);
        let id = CameraId::new(serial).map_err(|e| parse_err(source_name, field("serial"), e))?;
        cameras.push(
            Camera::new(id, intrinsics, distortion, r_camera_world, t_camera_world)
                .map_err(|e| parse_err(source_name, field("(camera)"), e))?,
        );
    }
    if cameras.is_empty() {
        return Err(parse_err(
            source_name,
            "cameras",
            "no video camera in the file",
        ));
    }
    cameras.sort_by(|a, b| natural_cmp(a.id.as_str(), b.id.as_str()));
    CameraRig::new(cameras, &[], Some(Vector3::z())).map_err(|e| parse_err(source_name, "(rig)", e))
}

/// Natural order: runs of digits compare as numbers (`cam2` < `cam10`), the rest case-insensitively.
fn natural_cmp(a: &str, b: &str) -> std::cmp::Ordering {
    fn chunks(s: &str) -> Vec<(bool, String)> {
        let mut out: Vec<(bool, String)> = Vec::new();
        for ch in s.chars() {
            let digit = ch.is_ascii_digit();
            match out.last_mut() {
                Some((d, text)) if *d == digit => text.push(ch),
                _ => out.push((digit, ch.to_string())),
            }
        }
        out
    }
    let (ca, cb) = (chunks(a), chunks(b));
    for ((da, ta), (db, tb)) in ca.iter().zip(&cb) {
        let ord = match (da, db) {
            (true, true) => {
                let (na, nb) = (ta.trim_start_matches('0'), tb.trim_start_matches('0'));
                na.len().cmp(&nb.len()).then_with(|| na.cmp(nb))
            }
            _ => ta.to_lowercase().cmp(&tb.to_lowercase()),
        };
        if ord.is_ne() {
            return ord;
        }
    }
    ca.len().cmp(&cb.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::Point3;

    /// Pose2Sim demo's cam01 as QTM wrote it (../shared/data/pose2sim-demo-videos/calibration).
    const CAM01: &str = r#"<camera active="1" avg-residual="0.402000" model="none" point-count="999999999" serial="cam01" viewrotation="0">
      <fov_video bottom="1919" left="0" right="1087" top="0"/>
      <transform r11="0.5536380477336265" r12="0.8046719867383512" r13="0.2144479094331626" r21="-0.4345300743838753" r22="0.05946489349975602" r23="0.8986921279821063" r31="0.7104002579937896" r32="-0.5907342212870501" r33="0.3825762057979294" x="1460.2323709212087" y="-1909.1590482454608" z="1896.5058524092062"/>
      <intrinsic centerPointU="34110.316406" centerPointV="60680.792969" focalLengthU="107599.671875" focalLengthV="107588.828125" focallength="9.314096596679686" radialDistortion1="-0.046183" radialDistortion2="0.139983" radialDistortion3="0.000000" sensorMaxU="69568" sensorMaxV="122816" sensorMinU="0.000000" sensorMinV="0.000000" skew="0.000000" tangentalDistortion1="0.000608" tangentalDistortion2="0.00069"/>
    </camera>"#;

    fn file(cameras: &[&str]) -> String {
        format!(
            "<?xml version='1.0' encoding='ASCII'?>\n<calibration type=\"regular\">\n  <cameras>\n{}\n  </cameras>\n</calibration>\n",
            cameras.join("\n")
        )
    }

    #[test]
    fn pose2sims_conversion_of_the_demo_camera() {
        let text = file(&[CAM01]);
        assert!(looks_like_qca(&text));
        let rig = parse_qualisys(&text, "Calib.qca.txt").unwrap();
        let c = &rig.cameras()[0];
        assert_eq!(c.id.as_str(), "cam01");
        assert_eq!(
            (c.intrinsics.width_px, c.intrinsics.height_px),
            (1088, 1920)
        );
        // calib_qca_fun's arithmetic by hand: 107599.671875/64, 34110.316406/64 − 0, 60680.792969/64 − 0
        assert_relative_eq!(c.intrinsics.fx, 107_599.671_875 / 64.0, epsilon = 1e-9);
        assert_relative_eq!(c.intrinsics.cx, 532.973_693_843_75, epsilon = 1e-9);
        assert_relative_eq!(c.intrinsics.cy, 948.137_390_140_625, epsilon = 1e-9);
        assert_relative_eq!(c.distortion.k1, -0.046_183 / 64.0, epsilon = 1e-15);
        // the camera centre is QTM's position, in metres
        let centre = c.position_world();
        assert_relative_eq!(
            centre,
            Point3::new(
                1.460_232_370_921_208_7,
                -1.909_159_048_245_460_8,
                1.896_505_852_409_206_2
            ),
            epsilon = 1e-12
        );
        // it looks along QTM's −z camera axis (the matrix's third row is that axis in the lab):
        // down and towards the lab's origin from where it stands
        let forward_world = c.T_camera_world.rotation.inverse() * Vector3::z();
        assert_relative_eq!(
            forward_world,
            -Vector3::new(
                0.710_400_257_993_789_6,
                -0.590_734_221_287_050_1,
                0.382_576_205_797_929_4
            ),
            epsilon = 1e-12
        );
        assert!(forward_world.dot(&-centre.coords) > 0.0);
        assert_eq!(rig.up(), Some(Vector3::z()));
    }

    #[test]
    fn the_demo_file_parses_four_cameras_that_look_at_the_capture_volume() {
        let relative = "data/pose2sim-demo-videos/calibration/Calib.qca.txt";
        if ergocell_testdata::skip_without(relative) {
            return;
        }
        let text = std::fs::read_to_string(ergocell_testdata::shared(relative)).unwrap();
        let rig = parse_qualisys(&text, "Calib.qca.txt").unwrap();
        let ids: Vec<_> = rig.cameras().iter().map(|c| c.id.as_str()).collect();
        assert_eq!(ids, ["cam01", "cam02", "cam03", "cam04"]);
        // every camera sees a point 1 m above the lab origin near its image centre
        for c in rig.cameras() {
            let p = c.project(&Point3::new(0.0, 0.0, 1.0)).unwrap();
            assert!(c.in_image(&p), "{}: {p}", c.id);
        }
    }

    #[test]
    fn video_resolution_scales_the_intrinsics() {
        let text =
            file(&[&CAM01.replace("viewrotation", "video_resolution=\"540p\" viewrotation")]);
        let c = parse_qualisys(&text, "x").unwrap().cameras()[0].clone();
        assert_eq!((c.intrinsics.width_px, c.intrinsics.height_px), (544, 960));
        assert_relative_eq!(
            c.intrinsics.fx,
            107_599.671_875 / 64.0 / 2.0,
            epsilon = 1e-9
        );
    }

    #[test]
    fn marker_cameras_are_skipped_and_serials_sort_naturally() {
        let cam = |serial: &str, model: &str, dx: f64| {
            CAM01
                .replace("serial=\"cam01\"", &format!("serial=\"{serial}\""))
                .replace("model=\"none\"", &format!("model=\"{model}\""))
                .replace(
                    "x=\"1460.2323709212087\"",
                    &format!("x=\"{}\"", 1460.0 + dx),
                )
        };
        let text = file(&[
            &cam("cam10", "none", 0.0),
            &cam("cam2", "Miqus Video", 300.0),
            &cam("cam3", "Miqus M3", 600.0),
        ]);
        let rig = parse_qualisys(&text, "x").unwrap();
        let ids: Vec<_> = rig.cameras().iter().map(|c| c.id.as_str()).collect();
        assert_eq!(ids, ["cam2", "cam10"]);
    }

    #[test]
    fn errors_name_the_file_camera_and_field() {
        let e = parse_qualisys("<calibration><cameras>", "a.qca.txt").unwrap_err();
        assert!(
            e.to_string().contains("a.qca.txt") && e.to_string().contains("XML"),
            "{e}"
        );
        let bad = file(&[&CAM01.replace("focalLengthU=\"107599.671875\"", "focalLengthU=\"NaN\"")]);
        let e = parse_qualisys(&bad, "a.qca.txt").unwrap_err().to_string();
        assert!(e.contains("camera cam01.intrinsic.focalLengthU"), "{e}");
        let bad = file(&[&CAM01.replace("r11=\"0.5536380477336265\"", "r11=\"2\"")]);
        let e = parse_qualisys(&bad, "a.qca.txt").unwrap_err().to_string();
        assert!(e.contains("not a rotation"), "{e}");
        let e = parse_qualisys(&file(&[]), "a.qca.txt")
            .unwrap_err()
            .to_string();
        assert!(e.contains("no video camera"), "{e}");
        let missing = file(&[&CAM01.replace(
            "<fov_video bottom=\"1919\" left=\"0\" right=\"1087\" top=\"0\"/>",
            "",
        )]);
        let e = parse_qualisys(&missing, "a.qca.txt")
            .unwrap_err()
            .to_string();
        assert!(e.contains("fov_video") && e.contains("missing"), "{e}");
    }

    #[test]
    fn natural_order() {
        let mut v = vec!["cam10", "Cam2", "cam1", "cam02b"];
        v.sort_by(|a, b| natural_cmp(a, b));
        assert_eq!(v, ["cam1", "Cam2", "cam02b", "cam10"]);
    }
}
