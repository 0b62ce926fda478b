//! The texts `ergocell calibrate` prints: the table of images (or image pairs) used or rejected and
//! why, each camera's calibration, the stereo pair's pose, and where `calibrate place` put each
//! group and how well it fits.
//!
//! A layout of the calibrations' facts; the only arithmetic is [`StereoPose`]'s conversion of the
//! pair's pose into display units (millimetres, degrees). No I/O: the caller prints the text.

use std::fmt::Write as _;

use ergocell_perception::CameraId;
use nalgebra::Vector3;

use crate::detect::ImageDetection;
use crate::intrinsics::CameraCalibration;
use crate::place::GroupPlacement;
use crate::rig::RigCalibration;

/// `calibrate intrinsics`' table: one row per image, used with its view's reprojection error
/// (`view_rms_px[k]` for the `k`-th image of `used`; `-` without one) or rejected and why.
pub fn intrinsics_table(images: &[ImageDetection], used: &[usize], view_rms_px: &[f64]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<28} {:<9} {:>9}  why",
        "image", "status", "error px"
    );
    for (i, image) in images.iter().enumerate() {
        let name = image.file_name();
        match &image.corners {
            Ok(_) => {
                let err = used
                    .iter()
                    .position(|&u| u == i)
                    .and_then(|k| view_rms_px.get(k))
                    .map_or_else(|| "-".to_owned(), |e| format!("{e:.4}"));
                let _ = writeln!(out, "{name:<28} {:<9} {err:>9}", "used");
            }
            Err(why) => {
                let _ = writeln!(out, "{name:<28} {:<9} {:>9}  {why}", "rejected", "-");
            }
        }
    }
    out
}

/// A camera calibrated alone, after a blank line: its intrinsics and distortion, and the RMS
/// reprojection error over its views.
pub fn intrinsics_text(id: &CameraId, calib: &CameraCalibration) -> String {
    let k = calib.intrinsics;
    format!(
        "\n{id}: fx {:.3} fy {:.3} cx {:.3} cy {:.3} px; distortion k1 k2 p1 p2 k3 = {:?}\n\
         RMS reprojection error {:.4} px over {} views\n",
        k.fx,
        k.fy,
        k.cx,
        k.cy,
        calib.distortion.to_array(),
        calib.rms_px,
        calib.view_rms_px.len()
    )
}

/// `calibrate stereo`'s table: one row per pair of images (paired in order), used with each
/// camera's reprojection error in the rig solve (`view_rms_px[camera][pair]`, `-` without one) or
/// rejected and why.
pub fn stereo_table(
    left: &[ImageDetection],
    right: &[ImageDetection],
    view_rms_px: Option<&[Vec<Option<f64>>]>,
) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<22} {:<22} {:<9} {:>8} {:>8}  why",
        "left", "right", "status", "left px", "right px"
    );
    for (f, (l, r)) in left.iter().zip(right).enumerate() {
        let err = |cam: usize| {
            view_rms_px
                .and_then(|e| e.get(cam)?.get(f).copied().flatten())
                .map_or_else(|| "-".to_owned(), |e| format!("{e:.4}"))
        };
        let why: Vec<String> = [("left", &l.corners), ("right", &r.corners)]
            .iter()
            .filter_map(|(side, c)| c.as_ref().err().map(|w| format!("{side}: {w}")))
            .collect();
        let status = if why.is_empty() { "used" } else { "rejected" };
        let _ = writeln!(
            out,
            "{:<22} {:<22} {status:<9} {:>8} {:>8}  {}",
            l.file_name(),
            r.file_name(),
            err(0),
            err(1),
            why.join("; ")
        );
    }
    out
}

/// Each camera of a calibrated rig: its intrinsics and distortion in the rig, and its RMS
/// reprojection error when calibrated alone.
pub fn rig_cameras_text(calib: &RigCalibration) -> String {
    let mut out = String::new();
    for (cam, single) in calib.rig.cameras().iter().zip(&calib.single) {
        let k = cam.intrinsics;
        let _ = writeln!(
            out,
            "{}: fx {:.3} fy {:.3} cx {:.3} cy {:.3} px; distortion {:?}; alone: RMS {:.4} px",
            cam.id,
            k.fx,
            k.fy,
            k.cx,
            k.cy,
            cam.distortion.to_array(),
            single.rms_px
        );
    }
    out
}

/// A stereo pair's result in display units: camera `b`'s pose in camera `a`'s frame
/// ([`RigCalibration::T_between`]) and the rig solve's error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StereoPose {
    /// RMS reprojection error of the rig solve, pixels.
    pub rms_px: f64,
    /// Distance between the two cameras' centres, millimetres.
    pub baseline_mm: f64,
    /// `T_b_a`'s translation, metres.
    pub t_m: Vector3<f64>,
    /// `T_b_a`'s rotation vector (axis × angle), degrees.
    pub rotation_deg: Vector3<f64>,
}

impl StereoPose {
    /// Camera `b`'s pose relative to camera `a` (`None` when the rig lacks either).
    pub fn of(calib: &RigCalibration, a: usize, b: usize) -> Option<Self> {
        let T = calib.T_between(a, b)?;
        Some(Self {
            rms_px: calib.rms_px,
            baseline_mm: calib.baseline_m(a, b)? * 1e3,
            t_m: T.translation.vector,
            rotation_deg: T.rotation.scaled_axis() * (180.0 / std::f64::consts::PI),
        })
    }

    /// The line `calibrate stereo` prints, the pose of the right camera (`b`) in the left one's
    /// frame (`a`).
    pub fn text(&self) -> String {
        let (t, r) = (self.t_m, self.rotation_deg);
        format!(
            "stereo: RMS {:.4} px; baseline {:.2} mm; T_right_left: t = [{:.5}, {:.5}, {:.5}] m, rotation vector = [{:.3}, {:.3}, {:.3}] deg\n",
            self.rms_px, self.baseline_mm, t.x, t.y, t.z, r.x, r.y, r.z
        )
    }
}

/// Where `calibrate place` put each group, one line per group (`sources[k]` names group `k`'s
/// file): its position in the cell, the points and sightings used, and how well they fit.
pub fn placement_text(groups: &[GroupPlacement], sources: &[String]) -> String {
    let mut out = String::new();
    for (g, source) in groups.iter().zip(sources) {
        let at = g.T_cell_group.translation.vector;
        let _ = writeln!(
            out,
            "{source} ({}): at [{:.3}, {:.3}, {:.3}] m in the cell; {} points triangulated, {} sightings, \
             reprojection RMS {:.2} px, worst {:.2} px (point `{}`)",
            g.cameras.join(", "),
            at.x,
            at.y,
            at.z,
            g.triangulated,
            g.sightings,
            g.rms_px,
            g.max_px,
            g.worst_point
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lm::{LmReport, LmStatus};
    use ergocell_perception::{Camera, CameraRig, Distortion, Intrinsics};
    use nalgebra::{Isometry3, Point2, Rotation3};

    fn image(name: &str, found: bool) -> ImageDetection {
        ImageDetection {
            name: format!("data/{name}"),
            size_px: Some((640, 480)),
            corners: if found {
                Ok(vec![Point2::new(1.0, 2.0)])
            } else {
                Err("no board".to_owned())
            },
        }
    }

    fn intrinsics(fy: f64) -> Intrinsics {
        Intrinsics {
            fx: 800.0,
            fy,
            cx: 320.0,
            cy: 240.0,
            skew: 0.0,
            width_px: 640,
            height_px: 480,
        }
    }

    fn calibration(rms_px: f64) -> CameraCalibration {
        CameraCalibration {
            intrinsics: Intrinsics {
                cx: 320.25,
                cy: 240.75,
                ..intrinsics(801.5)
            },
            distortion: Distortion {
                k1: -0.1,
                k2: 0.02,
                ..Distortion::default()
            },
            T_camera_board: Vec::new(),
            rms_px,
            view_rms_px: vec![0.2, 0.3, 0.2],
            report: LmReport {
                status: LmStatus::Converged,
                iterations: 10,
                initial_cost: 1.0,
                final_cost: 0.1,
            },
        }
    }

    /// Two cameras 120 mm apart, the right one turned 10° about the left one's y axis.
    fn stereo() -> RigCalibration {
        let left = Camera::new(
            CameraId::new("left").unwrap(),
            intrinsics(800.0),
            Distortion::default(),
            Rotation3::identity(),
            Vector3::zeros(),
        )
        .unwrap();
        let right = Camera::new(
            CameraId::new("right").unwrap(),
            intrinsics(800.0),
            Distortion::default(),
            Rotation3::from_axis_angle(&Vector3::y_axis(), 10f64.to_radians()),
            Vector3::new(-0.12, 0.0, 0.0),
        )
        .unwrap();
        RigCalibration {
            rig: CameraRig::new(vec![left, right], &[], None).unwrap(),
            single: vec![calibration(0.2345), calibration(0.3456)],
            rms_px: 0.25,
            view_rms_px: Vec::new(),
            report: None,
        }
    }

    #[test]
    fn the_stereo_pose_is_in_millimetres_and_degrees() {
        let calib = stereo();
        let pose = StereoPose::of(&calib, 0, 1).unwrap();
        assert!((pose.baseline_mm - 120.0).abs() < 1e-9, "{pose:?}");
        assert!(
            (pose.t_m - Vector3::new(-0.12, 0.0, 0.0)).norm() < 1e-12,
            "{pose:?}"
        );
        assert!(
            (pose.rotation_deg - Vector3::new(0.0, 10.0, 0.0)).norm() < 1e-9,
            "{pose:?}"
        );
        assert_eq!(pose.rms_px, 0.25);
        assert_eq!(StereoPose::of(&calib, 0, 2), None);
    }

    #[test]
    fn the_stereo_line_states_the_pose() {
        let pose = StereoPose {
            rms_px: 0.1234,
            baseline_mm: 120.0,
            t_m: Vector3::new(-0.12, 0.0, 0.001),
            rotation_deg: Vector3::new(0.0, 10.0, -0.5),
        };
        assert_eq!(
            pose.text(),
            "stereo: RMS 0.1234 px; baseline 120.00 mm; T_right_left: t = [-0.12000, 0.00000, 0.00100] m, rotation vector = [0.000, 10.000, -0.500] deg\n"
        );
    }

    #[test]
    fn each_camera_of_a_rig_with_its_error_alone() {
        assert_eq!(
            rig_cameras_text(&stereo()),
            "left: fx 800.000 fy 800.000 cx 320.000 cy 240.000 px; distortion [0.0, 0.0, 0.0, 0.0, 0.0]; alone: RMS 0.2345 px\n\
             right: fx 800.000 fy 800.000 cx 320.000 cy 240.000 px; distortion [0.0, 0.0, 0.0, 0.0, 0.0]; alone: RMS 0.3456 px\n"
        );
    }

    #[test]
    fn a_single_camera_states_its_parameters_and_views() {
        assert_eq!(
            intrinsics_text(&CameraId::new("left").unwrap(), &calibration(0.2345)),
            "\nleft: fx 800.000 fy 801.500 cx 320.250 cy 240.750 px; distortion k1 k2 p1 p2 k3 = [-0.1, 0.02, 0.0, 0.0, 0.0]\n\
             RMS reprojection error 0.2345 px over 3 views\n"
        );
    }

    #[test]
    fn the_image_table_gives_each_used_image_its_error_and_each_rejected_one_why() {
        let images = [
            image("a.png", true),
            image("b.png", false),
            image("c.png", true),
        ];
        // `c.png` was found but is not among the views solved (a failed calibration): no error
        let text = intrinsics_table(&images, &[0], &[0.12346]);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines,
            [
                "image                        status     error px  why",
                "a.png                        used         0.1235",
                "b.png                        rejected          -  no board",
                "c.png                        used              -",
            ]
        );
    }

    #[test]
    fn the_pair_table_names_the_side_that_was_rejected() {
        let left = [
            image("l1.png", true),
            image("l2.png", false),
            image("l3.png", false),
        ];
        let right = [
            image("r1.png", true),
            image("r2.png", true),
            image("r3.png", false),
        ];
        let errors = vec![vec![Some(0.2), None, None], vec![Some(0.3), None, None]];
        let text = stereo_table(&left, &right, Some(errors.as_slice()));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines,
            [
                "left                   right                  status     left px right px  why",
                "l1.png                 r1.png                 used        0.2000   0.3000  ",
                "l2.png                 r2.png                 rejected         -        -  left: no board",
                "l3.png                 r3.png                 rejected         -        -  left: no board; right: no board",
            ]
        );
        // before a solve: no errors at all
        assert_eq!(
            stereo_table(&left, &right, None).lines().nth(1),
            Some("l1.png                 r1.png                 used             -        -  ")
        );
    }

    #[test]
    fn a_placed_group_states_where_it_is_and_how_well_it_fits() {
        let group = GroupPlacement {
            cameras: vec!["s1_left".to_owned(), "s1_right".to_owned()],
            T_cell_group: Isometry3::translation(1.0, -2.5, 3.0),
            triangulated: 6,
            sightings: 14,
            rms_px: 0.456,
            start_rms_px: 2.0,
            max_px: 1.234,
            worst_point: "corner_3".to_owned(),
        };
        assert_eq!(
            placement_text(&[group], &["s1.toml".to_owned()]),
            "s1.toml (s1_left, s1_right): at [1.000, -2.500, 3.000] m in the cell; 6 points triangulated, 14 sightings, reprojection RMS 0.46 px, worst 1.23 px (point `corner_3`)\n"
        );
    }
}
