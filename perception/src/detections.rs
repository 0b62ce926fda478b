//! 2D detections: what a pose estimator reports per camera, in BlazePose-33 order.
//!
//! Every keypoint is validated when it is built ([`Keypoint2::new`]): a NaN or infinite pixel or a
//! confidence outside `0..=1` is an error, and importers turn such keypoints into "not observed"
//! (counted in [`ImportStats`]) instead of passing garbage on.

use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::Point2;

use crate::error::{PerceptionError, Result};
use crate::rig::CameraIndex;

/// One detected 2D keypoint: a (distorted) pixel and the detector's confidence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Keypoint2 {
    pixel: Point2<f64>,
    confidence: f64,
}

impl Keypoint2 {
    /// A keypoint; rejects non-finite pixels and confidences outside `0..=1`.
    pub fn new(u: f64, v: f64, confidence: f64) -> Result<Self> {
        if !(u.is_finite() && v.is_finite()) {
            return Err(PerceptionError::NonFinitePixel { u, v });
        }
        if !(0.0..=1.0).contains(&confidence) {
            return Err(PerceptionError::BadConfidence(confidence));
        }
        Ok(Self {
            pixel: Point2::new(u, v),
            confidence,
        })
    }

    /// The pixel, as the camera saw it (with lens distortion).
    pub fn pixel(&self) -> Point2<f64> {
        self.pixel
    }

    /// The detector's confidence in `0..=1`.
    pub fn confidence(&self) -> f64 {
        self.confidence
    }
}

/// One camera's detection of the operator at one instant, in BlazePose-33 order.
#[derive(Debug, Clone, PartialEq)]
pub struct View2 {
    pub camera: CameraIndex,
    /// Capture time, integer nanoseconds.
    pub stamp_nanos: i64,
    keypoints: [Option<Keypoint2>; LANDMARK_COUNT],
}

impl View2 {
    /// A view with nothing observed.
    pub fn empty(camera: CameraIndex, stamp_nanos: i64) -> Self {
        Self {
            camera,
            stamp_nanos,
            keypoints: [None; LANDMARK_COUNT],
        }
    }

    /// A view from 33 BlazePose-ordered slots.
    pub fn new(
        camera: CameraIndex,
        stamp_nanos: i64,
        keypoints: [Option<Keypoint2>; LANDMARK_COUNT],
    ) -> Self {
        Self {
            camera,
            stamp_nanos,
            keypoints,
        }
    }

    /// The keypoint of one landmark.
    pub fn get(&self, landmark: Landmark) -> Option<&Keypoint2> {
        self.keypoints[landmark.index()].as_ref()
    }

    /// Sets one landmark's keypoint.
    pub fn set(&mut self, landmark: Landmark, keypoint: Option<Keypoint2>) {
        self.keypoints[landmark.index()] = keypoint;
    }

    /// All 33 slots.
    pub fn keypoints(&self) -> &[Option<Keypoint2>; LANDMARK_COUNT] {
        &self.keypoints
    }

    /// Number of observed keypoints.
    pub fn observed_count(&self) -> usize {
        self.keypoints.iter().flatten().count()
    }
}

/// All cameras' views of one instant (after time alignment).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame2 {
    /// The frame's reference time, integer nanoseconds.
    pub stamp_nanos: i64,
    pub views: Vec<View2>,
}

/// What an importer dropped, so the caller can report it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ImportStats {
    /// Keypoints whose pixel or confidence was invalid (NaN, inf, confidence outside 0..1).
    pub invalid_keypoints: usize,
    /// Rows or files that could not be used at all.
    pub skipped_records: usize,
    /// Frames where more than one person was detected in some camera.
    pub multi_person_frames: usize,
    /// (frame, camera) slots with no detection file at all (e.g. a deleted OpenPose JSON): that
    /// camera is missing from that frame only.
    pub missing_views: usize,
    /// Keypoints given more than once for one camera and frame (caliscope rows repeated for a
    /// `sync_index`): left out, since which one is the operator's cannot be told.
    pub duplicate_keypoints: usize,
    /// Rows for a camera the rig does not have (a caliscope `port` N with no camera `cam_N`).
    pub unknown_camera_records: usize,
    /// The first such port, to name it.
    pub first_unknown_port: Option<i64>,
}

impl ImportStats {
    /// One line for the user when anything was left out, `None` when the import was clean.
    pub fn warning(&self) -> Option<String> {
        if self.invalid_keypoints == 0
            && self.skipped_records == 0
            && self.missing_views == 0
            && self.duplicate_keypoints == 0
            && self.unknown_camera_records == 0
        {
            return None;
        }
        let unknown = match self.first_unknown_port {
            Some(port) if self.unknown_camera_records > 0 => format!(
                "{} rows for cameras the calibration does not have (the first: caliscope port \
                 {port}, which would be camera cam_{port}) and ",
                self.unknown_camera_records
            ),
            _ if self.unknown_camera_records > 0 => format!(
                "{} rows for cameras the calibration does not have and ",
                self.unknown_camera_records
            ),
            _ => String::new(),
        };
        Some(format!(
            "{unknown}{} invalid keypoints (NaN/inf pixel or confidence outside 0..1), {} unusable records \
             (malformed or non-UTF-8 files, unparsable rows), {} missing views (no file for that \
             camera and frame) and {} keypoints given more than once for one camera and frame (which \
             one is the operator's cannot be told) were left out",
            self.invalid_keypoints, self.skipped_records, self.missing_views, self.duplicate_keypoints
        ))
    }
}

/// The 2D keypoint layouts ergocell reads, and how each maps onto BlazePose-33.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum KeypointFormat {
    /// MediaPipe BlazePose, 33 points: the native skeleton.
    BlazePose33,
    /// OpenPose BODY_25.
    Body25,
    /// OpenPose BODY_25B (the experimental, more accurate model).
    Body25B,
    /// COCO-17 (e.g. RTMPose/MMPose body models).
    Coco17,
    /// HALPE-26 (Pose2Sim's default with RTMPose).
    Halpe26,
}

impl KeypointFormat {
    /// Parses the CLI name (`blazepose33`, `body_25`, `body_25b`, `coco17`, `halpe26`).
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name.to_ascii_lowercase().replace('-', "_").as_str() {
            "blazepose33" | "blazepose" | "mediapipe" => Self::BlazePose33,
            "body_25" | "body25" => Self::Body25,
            "body_25b" | "body25b" => Self::Body25B,
            "coco17" | "coco_17" | "coco" => Self::Coco17,
            "halpe26" | "halpe_26" | "halpe" => Self::Halpe26,
            _ => return None,
        })
    }

    /// Number of keypoints in this layout.
    pub fn len(self) -> usize {
        self.mapping().len()
    }

    /// Always false.
    pub fn is_empty(self) -> bool {
        false
    }

    /// For each keypoint index of this layout, the BlazePose landmark it is (None: no BlazePose
    /// equivalent, e.g. OpenPose's neck or mid-hip, which are derived points).
    pub fn mapping(self) -> &'static [Option<Landmark>] {
        use Landmark as L;
        const COCO: [Option<Landmark>; 17] = [
            Some(L::Nose),
            Some(L::LeftEye),
            Some(L::RightEye),
            Some(L::LeftEar),
            Some(L::RightEar),
            Some(L::LeftShoulder),
            Some(L::RightShoulder),
            Some(L::LeftElbow),
            Some(L::RightElbow),
            Some(L::LeftWrist),
            Some(L::RightWrist),
            Some(L::LeftHip),
            Some(L::RightHip),
            Some(L::LeftKnee),
            Some(L::RightKnee),
            Some(L::LeftAnkle),
            Some(L::RightAnkle),
        ];
        const HALPE: [Option<Landmark>; 26] = [
            COCO[0],
            COCO[1],
            COCO[2],
            COCO[3],
            COCO[4],
            COCO[5],
            COCO[6],
            COCO[7],
            COCO[8],
            COCO[9],
            COCO[10],
            COCO[11],
            COCO[12],
            COCO[13],
            COCO[14],
            COCO[15],
            COCO[16],
            None, // head
            None, // neck
            None, // mid hip
            Some(L::LeftFootIndex),
            Some(L::RightFootIndex),
            None, // left small toe
            None, // right small toe
            Some(L::LeftHeel),
            Some(L::RightHeel),
        ];
        const BODY_25: [Option<Landmark>; 25] = [
            Some(L::Nose),
            None, // neck
            Some(L::RightShoulder),
            Some(L::RightElbow),
            Some(L::RightWrist),
            Some(L::LeftShoulder),
            Some(L::LeftElbow),
            Some(L::LeftWrist),
            None, // mid hip
            Some(L::RightHip),
            Some(L::RightKnee),
            Some(L::RightAnkle),
            Some(L::LeftHip),
            Some(L::LeftKnee),
            Some(L::LeftAnkle),
            Some(L::RightEye),
            Some(L::LeftEye),
            Some(L::RightEar),
            Some(L::LeftEar),
            Some(L::LeftFootIndex),
            None, // left small toe
            Some(L::LeftHeel),
            Some(L::RightFootIndex),
            None, // right small toe
            Some(L::RightHeel),
        ];
        const BODY_25B: [Option<Landmark>; 25] = [
            COCO[0],
            COCO[1],
            COCO[2],
            COCO[3],
            COCO[4],
            COCO[5],
            COCO[6],
            COCO[7],
            COCO[8],
            COCO[9],
            COCO[10],
            COCO[11],
            COCO[12],
            COCO[13],
            COCO[14],
            COCO[15],
            COCO[16],
            None, // upper neck
            None, // head top
            Some(L::LeftFootIndex),
            None, // left small toe
            Some(L::LeftHeel),
            Some(L::RightFootIndex),
            None, // right small toe
            Some(L::RightHeel),
        ];
        const BLAZE: [Option<Landmark>; LANDMARK_COUNT] = {
            let mut m = [None; LANDMARK_COUNT];
            let mut i = 0;
            while i < LANDMARK_COUNT {
                m[i] = Some(Landmark::ALL[i]);
                i += 1;
            }
            m
        };
        match self {
            Self::BlazePose33 => &BLAZE,
            Self::Body25 => &BODY_25,
            Self::Body25B => &BODY_25B,
            Self::Coco17 => &COCO,
            Self::Halpe26 => &HALPE,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keypoints_reject_garbage() {
        assert!(Keypoint2::new(f64::NAN, 1.0, 0.5).is_err());
        assert!(Keypoint2::new(1.0, f64::INFINITY, 0.5).is_err());
        assert!(Keypoint2::new(1.0, 1.0, 1.01).is_err());
        assert!(Keypoint2::new(1.0, 1.0, -0.01).is_err());
        assert!(Keypoint2::new(1.0, 1.0, f64::NAN).is_err());
        assert!(Keypoint2::new(1.0, 1.0, 1.0).is_ok());
    }

    #[test]
    fn mappings_have_the_published_lengths_and_never_repeat_a_landmark() {
        for (format, len) in [
            (KeypointFormat::BlazePose33, 33),
            (KeypointFormat::Body25, 25),
            (KeypointFormat::Body25B, 25),
            (KeypointFormat::Coco17, 17),
            (KeypointFormat::Halpe26, 26),
        ] {
            assert_eq!(format.len(), len);
            let m: Vec<_> = format.mapping().iter().flatten().collect();
            for (i, a) in m.iter().enumerate() {
                assert!(!m[..i].contains(a), "{format:?} maps {a} twice");
            }
            // Every layout gives what RULA and height need at minimum: shoulders, elbows, wrists, hips,
            // knees, ankles and the nose.
            for need in [
                Landmark::Nose,
                Landmark::LeftShoulder,
                Landmark::RightElbow,
                Landmark::LeftWrist,
                Landmark::RightHip,
                Landmark::LeftKnee,
                Landmark::RightAnkle,
            ] {
                assert!(m.contains(&&need), "{format:?} lacks {need}");
            }
        }
        // Spot checks against the published layouts.
        assert_eq!(
            KeypointFormat::Body25.mapping()[4],
            Some(Landmark::RightWrist)
        );
        assert_eq!(KeypointFormat::Body25.mapping()[1], None);
        assert_eq!(
            KeypointFormat::Body25B.mapping()[5],
            Some(Landmark::LeftShoulder)
        );
        assert_eq!(
            KeypointFormat::Halpe26.mapping()[25],
            Some(Landmark::RightHeel)
        );
        assert_eq!(
            KeypointFormat::from_name("BODY_25B"),
            Some(KeypointFormat::Body25B)
        );
    }
}
