//! A camera's video geometry relative to its calibration: where a pixel of the video the detector saw
//! lies in the calibrated image.
//!
//! Real recordings are not always the image the camera was calibrated in: Pose2Sim's demo ships two of
//! its four videos as the calibrated 1088×1920 frame scaled to 1080 px wide and letterboxed to
//! 1080×1920 (`../shared/data/pose2sim-demo-videos/SOURCE.md`). Triangulating those pixels as if they
//! were calibrated ones puts every ray of that camera off by up to 8 px. The geometry is declared per
//! camera and applied to the 2D keypoints before anything else sees them:
//!
//! - `fit`: the calibrated image scaled uniformly to fit inside the video frame and centred (letterbox
//!   or pillarbox bars), the common result of a resize for a fixed output size;
//! - `affine:SX,SY,OX,OY`: `x_cal = SX·(x − OX)`, `y_cal = SY·(y − OY)` in pixels, for anything else
//!   (a crop is `affine:1,1,−left,−top`).
//!
//! Pixel coordinates are continuous with the origin at the top-left pixel's centre (the convention of
//! `ergocell_msgs/CameraLandmarks`); `fit` maps the frames' edges onto each other.

use std::fmt;

use nalgebra::Point2;

use crate::detections::{Keypoint2, View2};
use crate::error::{PerceptionError, Result};

/// How one camera's video relates to its calibrated image.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VideoGeometry {
    /// The calibrated image scaled uniformly to fit the video frame, centred.
    Fit,
    /// `x_cal = scale[0]·(x − offset_px[0])`, `y_cal = scale[1]·(y − offset_px[1])`.
    Affine {
        scale: [f64; 2],
        offset_px: [f64; 2],
    },
}

impl VideoGeometry {
    /// Parses one `--video-geometry` entry, `CAMERA=fit` or `CAMERA=affine:SX,SY,OX,OY`, into the
    /// camera id and its geometry.
    pub fn parse_entry(entry: &str) -> Result<(String, Self)> {
        let bad = |why: &str| {
            PerceptionError::Unsupported(format!(
                "video geometry `{entry}`: {why} (expected CAMERA=fit or CAMERA=affine:SX,SY,OX,OY)"
            ))
        };
        let (camera, spec) = entry.split_once('=').ok_or_else(|| bad("no `=`"))?;
        let camera = camera.trim();
        if camera.is_empty() {
            return Err(bad("no camera id"));
        }
        let spec = spec.trim();
        let geometry = if spec.eq_ignore_ascii_case("fit") {
            Self::Fit
        } else if let Some(numbers) = spec.strip_prefix("affine:") {
            let v: Vec<f64> = numbers
                .split(',')
                .map(|s| s.trim().parse::<f64>())
                .collect::<std::result::Result<_, _>>()
                .map_err(|_| bad("not four numbers"))?;
            let [sx, sy, ox, oy] = v[..] else {
                return Err(bad("not four numbers"));
            };
            if !(sx.is_finite() && sy.is_finite() && sx > 0.0 && sy > 0.0) {
                return Err(bad("scales must be positive"));
            }
            if !(ox.is_finite() && oy.is_finite()) {
                return Err(bad("offsets must be finite"));
            }
            Self::Affine {
                scale: [sx, sy],
                offset_px: [ox, oy],
            }
        } else {
            return Err(bad("unknown kind"));
        };
        Ok((camera.to_owned(), geometry))
    }

    /// The map from a video of `video` = (width, height) pixels into the `calibrated` image.
    pub fn map(self, video: (u32, u32), calibrated: (u32, u32)) -> Result<VideoMap> {
        match self {
            Self::Affine { scale, offset_px } => Ok(VideoMap { scale, offset_px }),
            Self::Fit => {
                if video.0 == 0 || video.1 == 0 {
                    return Err(PerceptionError::Unsupported(format!(
                        "video geometry `fit` needs the video's size, got {}x{}",
                        video.0, video.1
                    )));
                }
                let (vw, vh) = (f64::from(video.0), f64::from(video.1));
                let (cw, ch) = (f64::from(calibrated.0), f64::from(calibrated.1));
                let s = (vw / cw).min(vh / ch);
                // edges: X_cal = (X_vid − bar)/s with X = x + ½ (origin at the pixel's corner)
                let bar = [(vw - s * cw) / 2.0, (vh - s * ch) / 2.0];
                Ok(VideoMap {
                    scale: [1.0 / s, 1.0 / s],
                    offset_px: [bar[0] + 0.5 * (s - 1.0), bar[1] + 0.5 * (s - 1.0)],
                })
            }
        }
    }
}

/// Parses `--video-geometry` entries against a rig: one slot per rig camera, `None` where nothing
/// is declared. An unknown camera or a camera given twice is an error.
pub fn parse_declarations(
    rig: &crate::CameraRig,
    entries: &[String],
) -> Result<Vec<Option<VideoGeometry>>> {
    let mut declared = vec![None; rig.len()];
    for entry in entries {
        let (id, geometry) = VideoGeometry::parse_entry(entry)?;
        let index = rig.index_of_name(&id).ok_or_else(|| {
            let known: Vec<_> = rig.cameras().iter().map(|c| c.id.as_str()).collect();
            PerceptionError::Unsupported(format!(
                "video geometry `{entry}`: no camera `{id}` in the calibration (it has {})",
                known.join(", ")
            ))
        })?;
        if declared[index].replace(geometry).is_some() {
            return Err(PerceptionError::Unsupported(format!(
                "video geometry: camera {id} given twice"
            )));
        }
    }
    Ok(declared)
}

impl fmt::Display for VideoGeometry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Fit => write!(f, "fit"),
            Self::Affine { scale, offset_px } => write!(
                f,
                "affine:{},{},{},{}",
                scale[0], scale[1], offset_px[0], offset_px[1]
            ),
        }
    }
}

/// A resolved video → calibrated-image map: `x_cal = scale[0]·(x − offset_px[0])`, likewise y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VideoMap {
    pub scale: [f64; 2],
    pub offset_px: [f64; 2],
}

impl VideoMap {
    /// The identity (the video is the calibrated image).
    pub const IDENTITY: Self = Self {
        scale: [1.0, 1.0],
        offset_px: [0.0, 0.0],
    };

    /// Whether this map moves nothing.
    pub fn is_identity(&self) -> bool {
        *self == Self::IDENTITY
    }

    /// One video pixel in the calibrated image.
    pub fn apply(&self, p: Point2<f64>) -> Point2<f64> {
        Point2::new(
            self.scale[0] * (p.x - self.offset_px[0]),
            self.scale[1] * (p.y - self.offset_px[1]),
        )
    }

    /// Every keypoint of a view, in place.
    pub fn apply_view(&self, view: &mut View2) {
        if self.is_identity() {
            return;
        }
        for lm in ergocell_skeleton::Landmark::ALL {
            if let Some(k) = view.get(lm).copied() {
                let p = self.apply(k.pixel());
                // finite in, finite out (positive finite scales): the keypoint stays valid
                view.set(lm, Keypoint2::new(p.x, p.y, k.confidence()).ok());
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn fit_of_the_pose2sim_letterbox_matches_its_source_note() {
        // SOURCE.md: a pixel (x, y) of the 1080×1920 video is (x·1088/1080, (y−7)·1088/1080)
        let m = VideoGeometry::Fit.map((1080, 1920), (1088, 1920)).unwrap();
        for (x, y) in [(0.0, 7.0), (540.0, 960.0), (1079.0, 1912.0), (300.0, 100.0)] {
            let p = m.apply(Point2::new(x, y));
            let s = 1088.0 / 1080.0;
            assert!((p.x - x * s).abs() < 0.01, "{x}: {}", p.x);
            // the bar is 7.06 rows, not 7: within 0.1 px
            assert!((p.y - (y - 7.0) * s).abs() < 0.1, "{y}: {}", p.y);
        }
        // the frames' edges map onto each other, and the centres too
        let c = m.apply(Point2::new(539.5, 959.5));
        assert_relative_eq!(c, Point2::new(543.5, 959.5), epsilon = 1e-9);
        let left_edge = m.apply(Point2::new(-0.5, 959.5));
        assert_relative_eq!(left_edge.x, -0.5, epsilon = 1e-9);
    }

    #[test]
    fn fit_of_the_same_size_is_the_identity_and_pillarbox_works() {
        let m = VideoGeometry::Fit.map((1088, 1920), (1088, 1920)).unwrap();
        assert_relative_eq!(
            m.apply(Point2::new(10.0, 20.0)),
            Point2::new(10.0, 20.0),
            epsilon = 1e-12
        );
        // a 1280×720 calibration shown in a 1920×1080 frame: exactly 1.5×, no bars
        let m = VideoGeometry::Fit.map((1920, 1080), (1280, 720)).unwrap();
        assert_relative_eq!(
            m.apply(Point2::new(-0.5, -0.5)),
            Point2::new(-0.5, -0.5),
            epsilon = 1e-12
        );
        assert_relative_eq!(
            m.apply(Point2::new(1919.5, 1079.5)),
            Point2::new(1279.5, 719.5),
            epsilon = 1e-9
        );
        // 4:3 calibration in a 16:9 video: bars left and right
        let m = VideoGeometry::Fit.map((1920, 1080), (640, 480)).unwrap();
        assert_relative_eq!(m.apply(Point2::new(239.5, -0.5)).x, -0.5, epsilon = 1e-9);
        assert!(VideoGeometry::Fit.map((0, 1080), (640, 480)).is_err());
    }

    #[test]
    fn entries_parse_and_bad_ones_say_what_is_expected() {
        assert_eq!(
            VideoGeometry::parse_entry("cam01=fit").unwrap(),
            ("cam01".to_owned(), VideoGeometry::Fit)
        );
        let (id, g) = VideoGeometry::parse_entry("c=affine:2,2,-10,5").unwrap();
        assert_eq!(id, "c");
        let p = g.map((0, 0), (0, 0)).unwrap().apply(Point2::new(0.0, 5.0));
        assert_relative_eq!(p, Point2::new(20.0, 0.0));
        assert_eq!(g.to_string(), "affine:2,2,-10,5");
        for bad in [
            "cam01",
            "=fit",
            "c=zoom",
            "c=affine:1,2,3",
            "c=affine:0,1,0,0",
            "c=affine:1,1,x,0",
            "c=affine:1,1,NaN,0",
        ] {
            let e = VideoGeometry::parse_entry(bad).unwrap_err().to_string();
            assert!(e.contains("CAMERA=fit"), "{bad}: {e}");
        }
    }

    #[test]
    fn a_view_is_mapped_in_place_keeping_confidences() {
        let mut v = View2::empty(0, 0);
        v.set(
            ergocell_skeleton::Landmark::Nose,
            Some(Keypoint2::new(100.0, 50.0, 0.7).unwrap()),
        );
        let m = VideoMap {
            scale: [2.0, 3.0],
            offset_px: [10.0, 0.0],
        };
        m.apply_view(&mut v);
        let k = v.get(ergocell_skeleton::Landmark::Nose).unwrap();
        assert_relative_eq!(k.pixel(), Point2::new(180.0, 150.0));
        assert_relative_eq!(k.confidence(), 0.7);
        assert_eq!(v.observed_count(), 1);
    }
}
