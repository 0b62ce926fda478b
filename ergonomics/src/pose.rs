//! Synthetic skeletons posed to known angles, for tests and benchmarks.
//!
//! A [`PoseSpec`] is a posture of the workspace's one body model ([`ergocell_body`], the digital
//! twin's too: the same forward kinematics and axis convention — x forward, y to the person's left,
//! z up): an average body of the given stature (Drillis & Contini 1966, tabulated by Winter; the ears
//! where ANSUR II's stature model puts a person of that stature's tragion, so the height
//! estimator's ear models see the person they were fitted on), mapped to the world with an
//! arbitrary rotation and translation. The world "up" of the pose is [`PoseSpec::up`]. Every joint
//! angle is applied as a rotation, so the angles the extractor should recover are exactly the ones
//! set here (see [`crate::angles`] for the definitions).

use ergocell_body::{ArmPosture, Body, LegPosture, Posture};
use ergocell_skeleton::{Skeleton3, LANDMARK_COUNT};
use nalgebra::{Point3, Rotation3, Vector3};

/// One arm's pose, radians (metres for the shoulder raise).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ArmPose {
    /// Upper arm raised forwards from hanging (negative = extension backwards).
    pub flexion_rad: f64,
    /// Upper arm raised sideways (applied after flexion).
    pub abduction_rad: f64,
    /// Elbow flexion, 0 = straight.
    pub elbow_flexion_rad: f64,
    /// Wrist flexion towards the palm (negative = extension).
    pub wrist_flexion_rad: f64,
    /// Wrist deviation towards the thumb side.
    pub wrist_deviation_rad: f64,
    /// Shoulder raised (shrug), metres along the trunk axis.
    pub shoulder_raise_m: f64,
}

/// A whole-body synthetic pose.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseSpec {
    pub stature_m: f64,
    pub trunk_flexion_rad: f64,
    pub trunk_side_bend_rad: f64,
    pub trunk_twist_rad: f64,
    pub neck_flexion_rad: f64,
    pub neck_twist_rad: f64,
    /// Flexion of both knees (feet stay on the floor, hips sink straight down).
    pub knee_flexion_rad: f64,
    pub left_arm: ArmPose,
    pub right_arm: ArmPose,
    /// Body frame (the body model's: x forward, y to the person's left, z up; origin on the floor
    /// below the hip midpoint) → world.
    pub world_rotation: Rotation3<f64>,
    /// Position of the body origin (the floor below the hip midpoint) in the world, metres.
    pub world_translation: Vector3<f64>,
    pub stamp_nanos: i64,
}

impl Default for PoseSpec {
    /// Standing upright, arms hanging with elbows at 80°, 1.75 m, world = body frame.
    fn default() -> Self {
        let arm = ArmPose {
            elbow_flexion_rad: 80f64.to_radians(),
            ..ArmPose::default()
        };
        Self {
            stature_m: 1.75,
            trunk_flexion_rad: 0.0,
            trunk_side_bend_rad: 0.0,
            trunk_twist_rad: 0.0,
            neck_flexion_rad: 0.0,
            neck_twist_rad: 0.0,
            knee_flexion_rad: 0.0,
            left_arm: arm,
            right_arm: arm,
            world_rotation: Rotation3::identity(),
            world_translation: Vector3::zeros(),
            stamp_nanos: 0,
        }
    }
}

impl PoseSpec {
    /// The golden reaching pose the assessment tests score: right arm 100° up, elbow 20°, wrist
    /// flexed 25°; trunk 30° and neck 25° forward; the left arm hanging with a straight wrist; in a
    /// rotated and shifted world (so no test relies on z being up).
    pub fn reaching() -> Self {
        Self {
            trunk_flexion_rad: 30f64.to_radians(),
            neck_flexion_rad: 25f64.to_radians(),
            right_arm: ArmPose {
                flexion_rad: 100f64.to_radians(),
                elbow_flexion_rad: 20f64.to_radians(),
                wrist_flexion_rad: 25f64.to_radians(),
                ..ArmPose::default()
            },
            world_rotation: Rotation3::from_euler_angles(1.2, 0.3, -0.7),
            world_translation: Vector3::new(0.5, 0.5, 2.0),
            ..Self::default()
        }
    }

    /// The world's up vector for this pose.
    pub fn up(&self) -> Vector3<f64> {
        self.world_rotation * Vector3::z()
    }

    /// The pose as the body model's posture (standing at the body frame's origin, heading 0).
    pub fn posture(&self) -> Posture {
        let arm = |a: &ArmPose| ArmPosture {
            flexion_rad: a.flexion_rad,
            abduction_rad: a.abduction_rad,
            humeral_rotation_rad: 0.0,
            elbow_flexion_rad: a.elbow_flexion_rad,
            wrist_flexion_rad: a.wrist_flexion_rad,
            shoulder_raise_m: a.shoulder_raise_m,
            wrist_deviation_rad: a.wrist_deviation_rad,
        };
        // Both knees bent alike with the feet on the floor: each thigh forward by half the knee
        // angle, each shank back by the other half.
        let leg = LegPosture {
            hip_flexion_rad: 0.5 * self.knee_flexion_rad,
            knee_flexion_rad: self.knee_flexion_rad,
        };
        Posture {
            position_m: [0.0, 0.0],
            heading_rad: 0.0,
            trunk_flexion_rad: self.trunk_flexion_rad,
            trunk_side_bend_rad: self.trunk_side_bend_rad,
            trunk_twist_rad: self.trunk_twist_rad,
            neck_flexion_rad: self.neck_flexion_rad,
            neck_yaw_rad: self.neck_twist_rad,
            left_arm: arm(&self.left_arm),
            right_arm: arm(&self.right_arm),
            left_leg: leg,
            right_leg: leg,
        }
    }

    /// The 33 landmark positions in the world frame: the body model's
    /// ([`ergocell_body::kinematics`], an average body of this stature) mapped by the world pose.
    pub fn points(&self) -> [Point3<f64>; LANDMARK_COUNT] {
        let body = Body::average(self.stature_m);
        ergocell_body::kinematics(&body, &self.posture())
            .points
            .map(|q| Point3::from(self.world_rotation * q.coords + self.world_translation))
    }

    /// The pose as a skeleton with confidence 1 everywhere. A pose with non-finite parameters gives
    /// an empty skeleton (nothing observed).
    pub fn skeleton(&self) -> Skeleton3 {
        Skeleton3::from_points(self.stamp_nanos, &self.points())
            .unwrap_or_else(|_| Skeleton3::empty(self.stamp_nanos))
    }
}
