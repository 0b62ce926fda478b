//! The body model every other ergocell crate speaks: MediaPipe BlazePose-33 landmarks and the fused
//! 3D skeleton.
//!
//! Perception produces a [`Skeleton3`] per frame; ergonomics consumes it. Keeping the type in its own
//! tiny crate lets ergonomics depend on the skeleton without knowing anything about cameras, and keeps
//! both free of ROS and of the robot.
//!
//! Positions are in metres in the **world** frame of the cell calibration (see `ARCHITECTURE.md`).
//! A landmark that no camera saw well enough is `None`, never a made-up point.
//!
//! The topology's tables live here, once, for every crate: the landmarks ([`Landmark`], with each
//! one's [`Side`]), the lines drawn between them ([`DRAWN_BONES`], MediaPipe's connections) and the
//! rigid bones whose length a reconstruction must keep ([`BONES`]).

use nalgebra::Point3;
use serde::{Deserialize, Serialize};

/// Number of landmarks in the BlazePose (MediaPipe Pose) topology.
pub const LANDMARK_COUNT: usize = 33;

/// Which side of the body: the person's own left and right (as in MediaPipe), not the camera's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    Left,
    Right,
}

impl Side {
    /// Both sides, left first.
    pub const BOTH: [Side; 2] = [Side::Left, Side::Right];

    /// "left" / "right".
    pub const fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }

    /// The other side.
    #[must_use]
    pub const fn other(self) -> Side {
        match self {
            Side::Left => Side::Right,
            Side::Right => Side::Left,
        }
    }
}

/// One MediaPipe BlazePose landmark; the discriminant is MediaPipe's index (0..=32).
///
/// Left and right are the **person's** left and right, as in MediaPipe.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[repr(u8)]
pub enum Landmark {
    Nose = 0,
    LeftEyeInner,
    LeftEye,
    LeftEyeOuter,
    RightEyeInner,
    RightEye,
    RightEyeOuter,
    LeftEar,
    RightEar,
    MouthLeft,
    MouthRight,
    LeftShoulder,
    RightShoulder,
    LeftElbow,
    RightElbow,
    LeftWrist,
    RightWrist,
    LeftPinky,
    RightPinky,
    LeftIndex,
    RightIndex,
    LeftThumb,
    RightThumb,
    LeftHip,
    RightHip,
    LeftKnee,
    RightKnee,
    LeftAnkle,
    RightAnkle,
    LeftHeel,
    RightHeel,
    LeftFootIndex,
    RightFootIndex,
}

impl Landmark {
    /// All 33 landmarks in MediaPipe index order.
    pub const ALL: [Landmark; LANDMARK_COUNT] = [
        Landmark::Nose,
        Landmark::LeftEyeInner,
        Landmark::LeftEye,
        Landmark::LeftEyeOuter,
        Landmark::RightEyeInner,
        Landmark::RightEye,
        Landmark::RightEyeOuter,
        Landmark::LeftEar,
        Landmark::RightEar,
        Landmark::MouthLeft,
        Landmark::MouthRight,
        Landmark::LeftShoulder,
        Landmark::RightShoulder,
        Landmark::LeftElbow,
        Landmark::RightElbow,
        Landmark::LeftWrist,
        Landmark::RightWrist,
        Landmark::LeftPinky,
        Landmark::RightPinky,
        Landmark::LeftIndex,
        Landmark::RightIndex,
        Landmark::LeftThumb,
        Landmark::RightThumb,
        Landmark::LeftHip,
        Landmark::RightHip,
        Landmark::LeftKnee,
        Landmark::RightKnee,
        Landmark::LeftAnkle,
        Landmark::RightAnkle,
        Landmark::LeftHeel,
        Landmark::RightHeel,
        Landmark::LeftFootIndex,
        Landmark::RightFootIndex,
    ];

    /// MediaPipe's index of this landmark (0..=32).
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The landmark with MediaPipe index `i`, if `i < 33`.
    pub fn from_index(i: usize) -> Option<Landmark> {
        Self::ALL.get(i).copied()
    }

    /// MediaPipe's snake-case name, e.g. `left_shoulder`.
    pub const fn name(self) -> &'static str {
        NAMES[self as usize]
    }

    /// Parses MediaPipe's snake-case name.
    pub fn from_name(name: &str) -> Option<Landmark> {
        NAMES
            .iter()
            .position(|n| *n == name)
            .and_then(Self::from_index)
    }

    /// The side of the body the landmark is on; `None` for the nose, the one landmark on the
    /// midline. Stated per landmark (not derived from MediaPipe's index order, which alternates
    /// left/right only from the shoulders on).
    pub const fn side(self) -> Option<Side> {
        use Landmark as L;
        match self {
            L::Nose => None,
            L::LeftEyeInner
            | L::LeftEye
            | L::LeftEyeOuter
            | L::LeftEar
            | L::MouthLeft
            | L::LeftShoulder
            | L::LeftElbow
            | L::LeftWrist
            | L::LeftPinky
            | L::LeftIndex
            | L::LeftThumb
            | L::LeftHip
            | L::LeftKnee
            | L::LeftAnkle
            | L::LeftHeel
            | L::LeftFootIndex => Some(Side::Left),
            L::RightEyeInner
            | L::RightEye
            | L::RightEyeOuter
            | L::RightEar
            | L::MouthRight
            | L::RightShoulder
            | L::RightElbow
            | L::RightWrist
            | L::RightPinky
            | L::RightIndex
            | L::RightThumb
            | L::RightHip
            | L::RightKnee
            | L::RightAnkle
            | L::RightHeel
            | L::RightFootIndex => Some(Side::Right),
        }
    }

    /// The same landmark on the other side of the body (`Nose` maps to itself).
    #[must_use]
    pub const fn mirrored(self) -> Landmark {
        use Landmark as L;
        match self {
            L::Nose => L::Nose,
            L::LeftEyeInner => L::RightEyeInner,
            L::LeftEye => L::RightEye,
            L::LeftEyeOuter => L::RightEyeOuter,
            L::RightEyeInner => L::LeftEyeInner,
            L::RightEye => L::LeftEye,
            L::RightEyeOuter => L::LeftEyeOuter,
            L::LeftEar => L::RightEar,
            L::RightEar => L::LeftEar,
            L::MouthLeft => L::MouthRight,
            L::MouthRight => L::MouthLeft,
            L::LeftShoulder => L::RightShoulder,
            L::RightShoulder => L::LeftShoulder,
            L::LeftElbow => L::RightElbow,
            L::RightElbow => L::LeftElbow,
            L::LeftWrist => L::RightWrist,
            L::RightWrist => L::LeftWrist,
            L::LeftPinky => L::RightPinky,
            L::RightPinky => L::LeftPinky,
            L::LeftIndex => L::RightIndex,
            L::RightIndex => L::LeftIndex,
            L::LeftThumb => L::RightThumb,
            L::RightThumb => L::LeftThumb,
            L::LeftHip => L::RightHip,
            L::RightHip => L::LeftHip,
            L::LeftKnee => L::RightKnee,
            L::RightKnee => L::LeftKnee,
            L::LeftAnkle => L::RightAnkle,
            L::RightAnkle => L::LeftAnkle,
            L::LeftHeel => L::RightHeel,
            L::RightHeel => L::LeftHeel,
            L::LeftFootIndex => L::RightFootIndex,
            L::RightFootIndex => L::LeftFootIndex,
        }
    }
}

impl std::fmt::Display for Landmark {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

const NAMES: [&str; LANDMARK_COUNT] = [
    "nose",
    "left_eye_inner",
    "left_eye",
    "left_eye_outer",
    "right_eye_inner",
    "right_eye",
    "right_eye_outer",
    "left_ear",
    "right_ear",
    "mouth_left",
    "mouth_right",
    "left_shoulder",
    "right_shoulder",
    "left_elbow",
    "right_elbow",
    "left_wrist",
    "right_wrist",
    "left_pinky",
    "right_pinky",
    "left_index",
    "right_index",
    "left_thumb",
    "right_thumb",
    "left_hip",
    "right_hip",
    "left_knee",
    "right_knee",
    "left_ankle",
    "right_ankle",
    "left_heel",
    "right_heel",
    "left_foot_index",
    "right_foot_index",
];

/// The lines drawn between landmarks to show the skeleton: MediaPipe's `POSE_CONNECTIONS` (35),
/// in its order — the face (eyes to ears, the mouth), the shoulders, each arm down to the hand's
/// pinky, index and thumb, the trunk, and each leg down to the heel and the foot's tip. Drawing, not
/// anatomy: for the bones whose length must stay constant see [`BONES`] (all of them are drawn).
pub const DRAWN_BONES: [(Landmark, Landmark); 35] = {
    use Landmark as L;
    [
        (L::Nose, L::LeftEyeInner),
        (L::LeftEyeInner, L::LeftEye),
        (L::LeftEye, L::LeftEyeOuter),
        (L::LeftEyeOuter, L::LeftEar),
        (L::Nose, L::RightEyeInner),
        (L::RightEyeInner, L::RightEye),
        (L::RightEye, L::RightEyeOuter),
        (L::RightEyeOuter, L::RightEar),
        (L::MouthLeft, L::MouthRight),
        (L::LeftShoulder, L::RightShoulder),
        (L::LeftShoulder, L::LeftElbow),
        (L::LeftElbow, L::LeftWrist),
        (L::LeftWrist, L::LeftPinky),
        (L::LeftWrist, L::LeftIndex),
        (L::LeftWrist, L::LeftThumb),
        (L::LeftPinky, L::LeftIndex),
        (L::RightShoulder, L::RightElbow),
        (L::RightElbow, L::RightWrist),
        (L::RightWrist, L::RightPinky),
        (L::RightWrist, L::RightIndex),
        (L::RightWrist, L::RightThumb),
        (L::RightPinky, L::RightIndex),
        (L::LeftShoulder, L::LeftHip),
        (L::RightShoulder, L::RightHip),
        (L::LeftHip, L::RightHip),
        (L::LeftHip, L::LeftKnee),
        (L::RightHip, L::RightKnee),
        (L::LeftKnee, L::LeftAnkle),
        (L::RightKnee, L::RightAnkle),
        (L::LeftAnkle, L::LeftHeel),
        (L::RightAnkle, L::RightHeel),
        (L::LeftHeel, L::LeftFootIndex),
        (L::RightHeel, L::RightFootIndex),
        (L::LeftAnkle, L::LeftFootIndex),
        (L::RightAnkle, L::RightFootIndex),
    ]
};

/// The rigid bones whose length should not change over a recording: used to measure how consistent a
/// 3D reconstruction is (per-bone length variation, coefficient of variation over frames).
pub const BONES: [(Landmark, Landmark); 12] = [
    (Landmark::LeftShoulder, Landmark::LeftElbow),
    (Landmark::RightShoulder, Landmark::RightElbow),
    (Landmark::LeftElbow, Landmark::LeftWrist),
    (Landmark::RightElbow, Landmark::RightWrist),
    (Landmark::LeftHip, Landmark::LeftKnee),
    (Landmark::RightHip, Landmark::RightKnee),
    (Landmark::LeftKnee, Landmark::LeftAnkle),
    (Landmark::RightKnee, Landmark::RightAnkle),
    (Landmark::LeftShoulder, Landmark::RightShoulder),
    (Landmark::LeftHip, Landmark::RightHip),
    (Landmark::LeftShoulder, Landmark::LeftHip),
    (Landmark::RightShoulder, Landmark::RightHip),
];

/// One fused 3D landmark.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LandmarkEstimate {
    /// Position in the world frame, metres.
    pub position_m: Point3<f64>,
    /// Tracking confidence in `0..=1`: for a fused landmark, the mean of its views' detector
    /// confidences, each weighted by itself (the robust triangulator also weights views by confidence).
    pub confidence: f64,
    /// Root-mean-square reprojection error over the views used, pixels (`None` when not applicable,
    /// e.g. a ground-truth skeleton).
    pub reprojection_error_px: Option<f64>,
    /// Number of camera views that contributed.
    pub views: u32,
    /// Standard deviation of the position per axis, metres: `sqrt(trace(Σ)/3)` of the fusion's
    /// covariance for this landmark (the triangulation's noise model over the views it kept). What
    /// the joint angles' uncertainty is propagated from. `None` when not known (a ground-truth
    /// skeleton, a file without it, the paper's fusion).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position_sd_m: Option<f64>,
}

/// Errors building a skeleton from outside data.
#[derive(Debug, thiserror::Error, PartialEq)]
#[non_exhaustive]
pub enum SkeletonError {
    #[error("a skeleton has exactly {LANDMARK_COUNT} landmark slots, got {got}")]
    WrongLength { got: usize },
    #[error("landmark {landmark} has a non-finite position ({x}, {y}, {z})")]
    NonFinite {
        landmark: Landmark,
        x: f64,
        y: f64,
        z: f64,
    },
    #[error("landmark {landmark} has confidence {confidence} outside 0..=1")]
    BadConfidence { landmark: Landmark, confidence: f64 },
    #[error("landmark {landmark} has a position standard deviation of {sd_m} m (must be finite and >= 0)")]
    BadSpread { landmark: Landmark, sd_m: f64 },
}

/// The fused 3D skeleton of one frame: one optional estimate per BlazePose landmark.
///
/// Built only through [`Skeleton3::new`] / [`Skeleton3::try_from_slots`], so every present landmark has
/// a finite position and a confidence in `0..=1`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Skeleton3 {
    /// Capture time of the frame, integer nanoseconds on the session clock.
    pub stamp_nanos: i64,
    landmarks: Vec<Option<LandmarkEstimate>>,
}

impl Skeleton3 {
    /// An empty skeleton (nothing observed) at `stamp_nanos`.
    pub fn empty(stamp_nanos: i64) -> Self {
        Self {
            stamp_nanos,
            landmarks: vec![None; LANDMARK_COUNT],
        }
    }

    /// A skeleton from 33 slots, validated.
    pub fn new(
        stamp_nanos: i64,
        slots: [Option<LandmarkEstimate>; LANDMARK_COUNT],
    ) -> Result<Self, SkeletonError> {
        Self::try_from_slots(stamp_nanos, slots.to_vec())
    }

    /// A skeleton from a vector of 33 slots, validated.
    pub fn try_from_slots(
        stamp_nanos: i64,
        slots: Vec<Option<LandmarkEstimate>>,
    ) -> Result<Self, SkeletonError> {
        if slots.len() != LANDMARK_COUNT {
            return Err(SkeletonError::WrongLength { got: slots.len() });
        }
        for (lm, slot) in Landmark::ALL.iter().zip(&slots) {
            if let Some(e) = slot {
                validate(*lm, e)?;
            }
        }
        Ok(Self {
            stamp_nanos,
            landmarks: slots,
        })
    }

    /// A skeleton of exact points (e.g. simulator ground truth): confidence 1, no reprojection error.
    pub fn from_points(
        stamp_nanos: i64,
        points: &[Point3<f64>; LANDMARK_COUNT],
    ) -> Result<Self, SkeletonError> {
        Self::from_optional_points(stamp_nanos, &points.map(Some))
    }

    /// A skeleton of bare positions, `None` where a landmark was not found (e.g. the output of a
    /// plain triangulation): confidence 1, no reprojection error, no view count.
    pub fn from_optional_points(
        stamp_nanos: i64,
        points: &[Option<Point3<f64>>; LANDMARK_COUNT],
    ) -> Result<Self, SkeletonError> {
        let slots = points
            .iter()
            .map(|p| {
                p.map(|position_m| LandmarkEstimate {
                    position_m,
                    confidence: 1.0,
                    reprojection_error_px: None,
                    views: 0,
                    position_sd_m: None,
                })
            })
            .collect();
        Self::try_from_slots(stamp_nanos, slots)
    }

    /// Sets one landmark, validated.
    pub fn set(
        &mut self,
        landmark: Landmark,
        estimate: Option<LandmarkEstimate>,
    ) -> Result<(), SkeletonError> {
        if let Some(e) = &estimate {
            validate(landmark, e)?;
        }
        self.landmarks[landmark.index()] = estimate;
        Ok(())
    }

    /// The estimate of one landmark, if it was observed.
    pub fn get(&self, landmark: Landmark) -> Option<&LandmarkEstimate> {
        self.landmarks[landmark.index()].as_ref()
    }

    /// The position of one landmark, if it was observed.
    pub fn position(&self, landmark: Landmark) -> Option<Point3<f64>> {
        self.get(landmark).map(|e| e.position_m)
    }

    /// All 33 slots in MediaPipe order.
    pub fn slots(&self) -> &[Option<LandmarkEstimate>] {
        &self.landmarks
    }

    /// Number of observed landmarks.
    pub fn observed_count(&self) -> usize {
        self.landmarks.iter().filter(|s| s.is_some()).count()
    }

    /// Length of a bone in metres, if both ends were observed.
    pub fn bone_length_m(&self, a: Landmark, b: Landmark) -> Option<f64> {
        Some((self.position(a)? - self.position(b)?).norm())
    }
}

impl<'de> Deserialize<'de> for Skeleton3 {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        struct Raw {
            stamp_nanos: i64,
            landmarks: Vec<Option<LandmarkEstimate>>,
        }
        let raw = Raw::deserialize(d)?;
        Skeleton3::try_from_slots(raw.stamp_nanos, raw.landmarks).map_err(serde::de::Error::custom)
    }
}

fn validate(landmark: Landmark, e: &LandmarkEstimate) -> Result<(), SkeletonError> {
    let p = e.position_m;
    if !(p.x.is_finite() && p.y.is_finite() && p.z.is_finite()) {
        return Err(SkeletonError::NonFinite {
            landmark,
            x: p.x,
            y: p.y,
            z: p.z,
        });
    }
    if !(0.0..=1.0).contains(&e.confidence) {
        return Err(SkeletonError::BadConfidence {
            landmark,
            confidence: e.confidence,
        });
    }
    if let Some(sd_m) = e.position_sd_m.filter(|v| !(v.is_finite() && *v >= 0.0)) {
        return Err(SkeletonError::BadSpread { landmark, sd_m });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_and_names_round_trip() {
        for (i, lm) in Landmark::ALL.iter().enumerate() {
            assert_eq!(lm.index(), i);
            assert_eq!(Landmark::from_index(i), Some(*lm));
            assert_eq!(Landmark::from_name(lm.name()), Some(*lm));
        }
        assert_eq!(Landmark::from_index(33), None);
        assert_eq!(Landmark::LeftShoulder.index(), 11);
        assert_eq!(Landmark::RightFootIndex.index(), 32);
    }

    #[test]
    fn mirroring_is_an_involution_that_swaps_sides() {
        for lm in Landmark::ALL {
            assert_eq!(lm.mirrored().mirrored(), lm);
            if lm != Landmark::Nose {
                assert_ne!(lm.mirrored(), lm);
                let (a, b) = (lm.name(), lm.mirrored().name());
                let side_free = |n: &str| n.replace("left", "X").replace("right", "X");
                assert_eq!(side_free(a), side_free(b));
                assert_ne!(a, b);
            }
        }
    }

    #[test]
    fn each_landmark_is_on_the_side_its_name_says() {
        for lm in Landmark::ALL {
            let name = lm.name();
            let expected = if name.contains("left") {
                Some(Side::Left)
            } else if name.contains("right") {
                Some(Side::Right)
            } else {
                None
            };
            assert_eq!(lm.side(), expected, "{lm}");
            assert_eq!(lm.mirrored().side(), expected.map(Side::other), "{lm}");
        }
        assert_eq!(Landmark::Nose.side(), None);
        // The face breaks MediaPipe's odd = left rule: 9 (mouth_left) is left, 10 is right, and
        // 4..=6 are right although 5 is odd.
        assert_eq!(Landmark::MouthLeft.side(), Some(Side::Left));
        assert_eq!(Landmark::RightEye.side(), Some(Side::Right));
    }

    /// MediaPipe's `POSE_CONNECTIONS` as index pairs, from its source.
    const POSE_CONNECTIONS: [[usize; 2]; 35] = [
        [0, 1],
        [1, 2],
        [2, 3],
        [3, 7],
        [0, 4],
        [4, 5],
        [5, 6],
        [6, 8],
        [9, 10],
        [11, 12],
        [11, 13],
        [13, 15],
        [15, 17],
        [15, 19],
        [15, 21],
        [17, 19],
        [12, 14],
        [14, 16],
        [16, 18],
        [16, 20],
        [16, 22],
        [18, 20],
        [11, 23],
        [12, 24],
        [23, 24],
        [23, 25],
        [24, 26],
        [25, 27],
        [26, 28],
        [27, 29],
        [28, 30],
        [29, 31],
        [30, 32],
        [27, 31],
        [28, 32],
    ];

    #[test]
    fn drawn_bones_are_mediapipes_connections_mirror_symmetric_and_hold_every_rigid_bone() {
        let as_index = |(a, b): (Landmark, Landmark)| [a.index(), b.index()];
        assert_eq!(DRAWN_BONES.map(as_index), POSE_CONNECTIONS);
        let drawn = |a: Landmark, b: Landmark| {
            DRAWN_BONES
                .iter()
                .any(|&(x, y)| (x, y) == (a, b) || (y, x) == (a, b))
        };
        for (a, b) in DRAWN_BONES {
            assert_ne!(a, b);
            assert!(drawn(a.mirrored(), b.mirrored()), "{a}-{b} has no mirror");
        }
        for (a, b) in BONES {
            assert!(drawn(a, b), "rigid bone {a}-{b} is not drawn");
        }
        // Every landmark is on the drawn skeleton.
        for lm in Landmark::ALL {
            assert!(DRAWN_BONES.iter().any(|&(a, b)| a == lm || b == lm), "{lm}");
        }
    }

    #[test]
    fn non_finite_and_bad_confidence_are_rejected() {
        let mut s = Skeleton3::empty(0);
        let bad = LandmarkEstimate {
            position_m: Point3::new(f64::NAN, 0.0, 0.0),
            confidence: 0.5,
            reprojection_error_px: Some(0.0),
            views: 2,
            position_sd_m: None,
        };
        assert!(matches!(
            s.set(Landmark::Nose, Some(bad)),
            Err(SkeletonError::NonFinite { .. })
        ));
        let bad = LandmarkEstimate {
            position_m: Point3::origin(),
            confidence: 1.5,
            ..bad
        };
        assert!(matches!(
            s.set(Landmark::Nose, Some(bad)),
            Err(SkeletonError::BadConfidence { .. })
        ));
        assert_eq!(s.observed_count(), 0);
        assert!(matches!(
            Skeleton3::try_from_slots(0, vec![None; 3]),
            Err(SkeletonError::WrongLength { got: 3 })
        ));
    }

    #[test]
    fn json_round_trip_and_validation_on_deserialize() {
        let pts = std::array::from_fn(|i| Point3::new(i as f64, 0.5, -1.0));
        let s = Skeleton3::from_points(42, &pts).unwrap();
        let json = serde_json::to_string(&s).unwrap();
        let back: Skeleton3 = serde_json::from_str(&json).unwrap();
        assert_eq!(back, s);
        let truncated = r#"{"stamp_nanos":1,"landmarks":[null,null]}"#;
        assert!(serde_json::from_str::<Skeleton3>(truncated).is_err());
        assert!(
            (s.bone_length_m(Landmark::Nose, Landmark::LeftEyeInner)
                .unwrap()
                - 1.0)
                .abs()
                < 1e-12
        );
    }
}
