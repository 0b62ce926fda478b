//! Synthetic skeletons posed to known angles, for tests and benchmarks (ergonomics cannot depend on
//! the simulator crate).
//!
//! A [`PoseSpec`] builds the 33 BlazePose landmarks of a person of a given stature from the Drillis &
//! Contini (1966) segment ratios (tabulated by Winter; the workspace's one table,
//! [`ergocell_anthropometry`]), in a body frame with x to the person's right, y forwards and z up,
//! feet on the floor at z = 0 — except the ears, which stand where ANSUR II's stature model
//! ([`ergocell_anthropometry::stature::FLOOR_TO_EAR`]) puts the tragion of a person of that
//! stature, so the height estimator's ear models see the person they were fitted on; then maps it to the world with an arbitrary rotation and
//! translation. The world "up" of the pose is [`PoseSpec::up`]. Every joint angle is applied as a
//! rotation, so the angles the extractor should recover are exactly the ones set here (see
//! [`crate::angles`] for the definitions).

use ergocell_skeleton::{Landmark, Skeleton3, LANDMARK_COUNT};
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
    /// Body frame (x right, y forward, z up) → world.
    pub world_rotation: Rotation3<f64>,
    /// Position of the body origin (floor between the feet) in the world, metres.
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

fn rx(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::x_axis(), a)
}
fn ry(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::y_axis(), a)
}
fn rz(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), a)
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

    /// The 33 landmark positions in the world frame.
    pub fn points(&self) -> [Point3<f64>; LANDMARK_COUNT] {
        use ergocell_anthropometry::stature::FLOOR_TO_EAR;
        use ergocell_anthropometry::{
            from_heights, ANKLE_HEIGHT, FOREARM, HAND, HIP_WIDTH, SHANK, SHOULDER_HEIGHT,
            SHOULDER_WIDTH, THIGH, TRUNK, UPPER_ARM,
        };
        use Landmark as L;
        let h = self.stature_m;
        let mut p = [Point3::origin(); LANDMARK_COUNT];
        let mut set = |l: L, v: Vector3<f64>| p[l.index()] = Point3::from(v);

        // Legs, built from the floor up so that bent knees keep the feet on the floor.
        let half_k = self.knee_flexion_rad * 0.5;
        let hip_x = HIP_WIDTH * h * 0.5;
        let ankle_z = ANKLE_HEIGHT * h;
        let shank = Vector3::new(0.0, half_k.sin(), half_k.cos()) * (SHANK * h);
        let thigh = Vector3::new(0.0, -half_k.sin(), half_k.cos()) * (THIGH * h);
        for (sx, ankle, heel, toe, knee, hip) in [
            (
                -1.0,
                L::LeftAnkle,
                L::LeftHeel,
                L::LeftFootIndex,
                L::LeftKnee,
                L::LeftHip,
            ),
            (
                1.0,
                L::RightAnkle,
                L::RightHeel,
                L::RightFootIndex,
                L::RightKnee,
                L::RightHip,
            ),
        ] {
            let a = Vector3::new(sx * hip_x, 0.0, ankle_z);
            set(ankle, a);
            set(heel, Vector3::new(sx * hip_x, -0.025 * h, 0.0));
            set(toe, Vector3::new(sx * hip_x, 0.10 * h, 0.0));
            set(knee, a + shank);
            set(hip, a + shank + thigh);
        }
        let hip_mid = Vector3::new(0.0, 0.0, ankle_z) + shank + thigh;

        // Upper body, in the trunk's own frame, rotated about the hip midpoint.
        let r_trunk =
            rx(-self.trunk_flexion_rad) * ry(self.trunk_side_bend_rad) * rz(self.trunk_twist_rad);
        let trunk = |v: Vector3<f64>| hip_mid + r_trunk * v;
        let trunk_len = TRUNK * h;
        let shoulder_x = SHOULDER_WIDTH * h * 0.5;

        // Head about the neck base (shoulder midpoint).
        let neck = Vector3::new(0.0, 0.0, trunk_len);
        let r_head = rx(-self.neck_flexion_rad) * rz(self.neck_twist_rad);
        let eye_z = from_heights::EYE_ABOVE_SHOULDER * h;
        let head = |v: Vector3<f64>| trunk(neck + r_head * v);
        set(
            L::Nose,
            head(Vector3::new(0.0, 0.055 * h, eye_z - 0.018 * h)),
        );
        set(
            L::LeftEyeInner,
            head(Vector3::new(-0.010 * h, 0.045 * h, eye_z)),
        );
        set(L::LeftEye, head(Vector3::new(-0.018 * h, 0.045 * h, eye_z)));
        set(
            L::LeftEyeOuter,
            head(Vector3::new(-0.026 * h, 0.042 * h, eye_z)),
        );
        set(
            L::RightEyeInner,
            head(Vector3::new(0.010 * h, 0.045 * h, eye_z)),
        );
        set(L::RightEye, head(Vector3::new(0.018 * h, 0.045 * h, eye_z)));
        set(
            L::RightEyeOuter,
            head(Vector3::new(0.026 * h, 0.042 * h, eye_z)),
        );
        // The ears where ANSUR II's stature model puts a person of this stature's tragion.
        let ear_z = FLOOR_TO_EAR.span_m(h) - SHOULDER_HEIGHT * h;
        set(L::LeftEar, head(Vector3::new(-0.043 * h, 0.0, ear_z)));
        set(L::RightEar, head(Vector3::new(0.043 * h, 0.0, ear_z)));
        set(
            L::MouthLeft,
            head(Vector3::new(-0.014 * h, 0.050 * h, eye_z - 0.040 * h)),
        );
        set(
            L::MouthRight,
            head(Vector3::new(0.014 * h, 0.050 * h, eye_z - 0.040 * h)),
        );

        // Arms, in the trunk frame.
        for (sx, arm, ids) in [
            (
                -1.0,
                &self.left_arm,
                [
                    L::LeftShoulder,
                    L::LeftElbow,
                    L::LeftWrist,
                    L::LeftIndex,
                    L::LeftPinky,
                    L::LeftThumb,
                ],
            ),
            (
                1.0,
                &self.right_arm,
                [
                    L::RightShoulder,
                    L::RightElbow,
                    L::RightWrist,
                    L::RightIndex,
                    L::RightPinky,
                    L::RightThumb,
                ],
            ),
        ] {
            let shoulder = Vector3::new(sx * shoulder_x, 0.0, trunk_len + arm.shoulder_raise_m);
            let r_upper = ry(-sx * arm.abduction_rad) * rx(arm.flexion_rad);
            let down = -Vector3::z();
            let elbow = shoulder + r_upper * down * (UPPER_ARM * h);
            let r_fore = r_upper * rx(arm.elbow_flexion_rad);
            let wrist = elbow + r_fore * down * (FOREARM * h);
            let r_hand = r_fore * ry(sx * arm.wrist_flexion_rad) * rx(arm.wrist_deviation_rad);
            let knuckles = 0.45 * HAND * h;
            let half_width = 0.012 * h;
            set(ids[0], trunk(shoulder));
            set(ids[1], trunk(elbow));
            set(ids[2], trunk(wrist));
            set(
                ids[3],
                trunk(wrist + r_hand * Vector3::new(0.0, half_width, -knuckles)),
            );
            set(
                ids[4],
                trunk(wrist + r_hand * Vector3::new(0.0, -half_width, -knuckles)),
            );
            set(
                ids[5],
                trunk(wrist + r_hand * Vector3::new(0.0, 1.5 * half_width, -0.5 * knuckles)),
            );
        }

        p.map(|q| Point3::from(self.world_rotation * q.coords + self.world_translation))
    }

    /// The pose as a skeleton with confidence 1 everywhere. A pose with non-finite parameters gives
    /// an empty skeleton (nothing observed).
    pub fn skeleton(&self) -> Skeleton3 {
        Skeleton3::from_points(self.stamp_nanos, &self.points())
            .unwrap_or_else(|_| Skeleton3::empty(self.stamp_nanos))
    }
}
