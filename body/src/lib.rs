//! The one human body model of the workspace: a body's dimensions ([`Body`]: stature-scaled from
//! Drillis & Contini, or a measured ANSUR II person's) posed by joint angles ([`Posture`]), forward
//! kinematics to the 33 BlazePose landmarks ([`kinematics`]). The digital twin's operators
//! (`ergocell_sim`) and the ergonomics crate's synthetic test poses (`ergocell_ergonomics::pose`)
//! are both this model, in this one axis convention.
//! It must not know cameras, assessment, the robot or ROS: it depends on anthropometry and the
//! skeleton alone, and does no I/O.
//!
//! # Anthropometry
//! Every segment is the body's ([`ergocell_anthropometry::body::Body`]); for the average body a
//! fraction of stature `H` from Drillis & Contini (1966), *Body segment parameters*, as tabulated by
//! Winter, *Biomechanics and Motor Control of Human Movement*, Fig. 4.1 (heights above the floor —
//! ankle 0.039, knee 0.285, hip 0.530, shoulder 0.818, eye 0.936; lengths — shoulder width 0.259,
//! hip width 0.191, upper arm 0.186, forearm 0.146, hand 0.108, foot 0.152). Shank, thigh and trunk
//! are stacked on the ankle height, so standing upright the eyes are at 0.936 H and the shoulder
//! joints at 0.818 H (to rounding), which is what the ergonomics height estimator inverts. The ears
//! stand where ANSUR II's stature model ([`ergocell_anthropometry::stature::FLOOR_TO_EAR`]) puts the
//! tragion of a person of that stature (a measured person: their own).
//!
//! # Frames
//! The body frame has its origin on the floor below the hip midpoint, **x forward** (where the
//! person faces), **y to the person's left**, **z up**. [`Posture::position_m`] and
//! [`Posture::heading_rad`] place it in a z-up world (floor at z = 0, as in `config/rig.toml`):
//! heading 0 faces world +x.
//!
//! # Joint angles ([`Posture`], radians)
//! - trunk: flexion (forward bend about the hip midpoint), side bend (towards the right +), twist
//!   (shoulders to the left +);
//! - neck: flexion relative to the trunk (positive = looking down), yaw (turning the head left);
//! - per arm: shoulder flexion (upper arm raised forward from hanging), abduction (raised sideways,
//!   out of the trunk's sagittal plane; negative = across the chest), humeral rotation, elbow flexion
//!   (0 = straight), wrist flexion (towards the palm), wrist deviation (towards the thumb), shoulder
//!   raise (shrug, metres);
//! - per leg: hip flexion (thigh forward of vertical) and knee flexion. The pelvis sinks so that the
//!   longer leg's ankle stays at its standing height: feet on the floor.
//!
//! The upper-arm direction is `R_y(−flexion)·R_x(±abduction)·down` in the trunk frame, so
//! ergonomics' definitions (elevation from the trunk's downward axis; abduction `asin(â·o)`) recover
//! exactly these values when humeral rotation is zero.

pub use ergocell_anthropometry::body::Body;
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Rotation3, Vector3};
use serde::Serialize;

/// The body `b` in posture `q`: its landmarks, grasp points and the torso and head geometry (for
/// self-occlusion), in the world the posture places it in.
pub fn kinematics(b: &Body, q: &Posture) -> Kinematics {
    use Landmark as L;
    let h = b.stature_m;
    let mut p = [Point3::origin(); LANDMARK_COUNT];
    let mut set = |l: L, v: Vector3<f64>| p[l.index()] = Point3::from(v);

    // Legs: thigh and shank angles from vertical (positive = forward), pelvis at the height that
    // puts the longer leg's ankle at its standing height.
    let leg = |hip_flex: f64, knee_flex: f64| {
        let thigh = Vector3::new(hip_flex.sin(), 0.0, -hip_flex.cos()) * b.thigh_m;
        let shank_angle = hip_flex - knee_flex;
        let shank = Vector3::new(shank_angle.sin(), 0.0, -shank_angle.cos()) * b.shank_m;
        (thigh, shank)
    };
    let (tl, sl) = leg(q.left_leg.hip_flexion_rad, q.left_leg.knee_flexion_rad);
    let (tr, sr) = leg(q.right_leg.hip_flexion_rad, q.right_leg.knee_flexion_rad);
    let drop = (-(tl + sl).z).max(-(tr + sr).z);
    let hip_mid = Vector3::new(0.0, 0.0, b.ankle_height_m + drop);
    let hip_y = 0.5 * b.hip_width_m;
    for (sy, (thigh, shank), ids) in [
        (
            1.0,
            (tl, sl),
            [
                L::LeftHip,
                L::LeftKnee,
                L::LeftAnkle,
                L::LeftHeel,
                L::LeftFootIndex,
            ],
        ),
        (
            -1.0,
            (tr, sr),
            [
                L::RightHip,
                L::RightKnee,
                L::RightAnkle,
                L::RightHeel,
                L::RightFootIndex,
            ],
        ),
    ] {
        let hip = hip_mid + Vector3::new(0.0, sy * hip_y, 0.0);
        let knee = hip + thigh;
        let ankle = knee + shank;
        let foot_drop = b.ankle_height_m;
        set(ids[0], hip);
        set(ids[1], knee);
        set(ids[2], ankle);
        set(ids[3], ankle + Vector3::new(-0.025 * h, 0.0, -foot_drop));
        set(
            ids[4],
            ankle + Vector3::new(b.foot_m - 0.025 * h, 0.0, -foot_drop),
        );
    }

    // Trunk about the hip midpoint.
    let r_trunk = ry(q.trunk_flexion_rad) * rx(q.trunk_side_bend_rad) * rz(q.trunk_twist_rad);
    let trunk = |v: Vector3<f64>| hip_mid + r_trunk * v;
    let trunk_len = b.trunk_m;
    let neck = Vector3::new(0.0, 0.0, trunk_len);
    let r_head = ry(q.neck_flexion_rad) * rz(q.neck_yaw_rad);
    let eye_z = b.eye_above_shoulder_m;
    let head = |v: Vector3<f64>| trunk(neck + r_head * v);
    let ear_z = b.ear_above_shoulder_m;
    set(
        L::Nose,
        head(Vector3::new(0.055 * h, 0.0, eye_z - 0.018 * h)),
    );
    for (sy, inner, eye, outer, ear, mouth) in [
        (
            1.0,
            L::LeftEyeInner,
            L::LeftEye,
            L::LeftEyeOuter,
            L::LeftEar,
            L::MouthLeft,
        ),
        (
            -1.0,
            L::RightEyeInner,
            L::RightEye,
            L::RightEyeOuter,
            L::RightEar,
            L::MouthRight,
        ),
    ] {
        set(inner, head(Vector3::new(0.045 * h, sy * 0.010 * h, eye_z)));
        set(eye, head(Vector3::new(0.045 * h, sy * 0.018 * h, eye_z)));
        set(outer, head(Vector3::new(0.042 * h, sy * 0.026 * h, eye_z)));
        set(ear, head(Vector3::new(0.0, sy * 0.043 * h, ear_z)));
        set(
            mouth,
            head(Vector3::new(0.050 * h, sy * 0.014 * h, eye_z - 0.040 * h)),
        );
    }
    let head_centre = head(Vector3::new(0.012 * h, 0.0, eye_z - 0.01 * h));

    // Arms in the trunk frame.
    let shoulder_y = 0.5 * b.shoulder_width_m;
    let mut grasp = [Vector3::zeros(); 2];
    for (k, (sy, arm, ids)) in [
        (
            1.0,
            &q.left_arm,
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
            -1.0,
            &q.right_arm,
            [
                L::RightShoulder,
                L::RightElbow,
                L::RightWrist,
                L::RightIndex,
                L::RightPinky,
                L::RightThumb,
            ],
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let down = -Vector3::z();
        let shoulder = Vector3::new(0.0, sy * shoulder_y, trunk_len + arm.shoulder_raise_m);
        let r_upper = ry(-arm.flexion_rad) * rx(sy * arm.abduction_rad);
        let elbow = shoulder + r_upper * down * b.upper_arm_m;
        let r_fore = r_upper * rz(sy * arm.humeral_rotation_rad) * ry(-arm.elbow_flexion_rad);
        let wrist = elbow + r_fore * down * b.forearm_m;
        // Palm faces the body's midline when the arm hangs (thumb forward); flexion bends the
        // hand towards the palm.
        let mut r_hand = r_fore * rx(-sy * arm.wrist_flexion_rad);
        if arm.wrist_deviation_rad != 0.0 {
            // towards the thumb (forward when the arm hangs)
            r_hand *= ry(-arm.wrist_deviation_rad);
        }
        let knuckles = 0.45 * b.hand_m;
        let half_width = 0.012 * h;
        set(ids[0], trunk(shoulder));
        set(ids[1], trunk(elbow));
        set(ids[2], trunk(wrist));
        set(
            ids[3],
            trunk(wrist + r_hand * Vector3::new(half_width, 0.0, -knuckles)),
        );
        set(
            ids[4],
            trunk(wrist + r_hand * Vector3::new(-half_width, 0.0, -knuckles)),
        );
        set(
            ids[5],
            trunk(wrist + r_hand * Vector3::new(1.5 * half_width, 0.0, -0.5 * knuckles)),
        );
        grasp[k] = trunk(wrist + r_hand * Vector3::new(0.0, 0.0, -0.5 * knuckles));
    }

    // Body → world.
    let r_world = rz(q.heading_rad);
    let t_world = Vector3::new(q.position_m[0], q.position_m[1], 0.0);
    let to_world = |v: Vector3<f64>| Point3::from(r_world * v + t_world);
    Kinematics {
        points: p.map(|x| to_world(x.coords)),
        grasp_left: to_world(grasp[0]),
        grasp_right: to_world(grasp[1]),
        torso: Torso {
            base: to_world(hip_mid),
            R_world_trunk: r_world * r_trunk,
            length_m: trunk_len,
            half_depth_m: 0.063 * h,
            half_width_m: 0.085 * h,
        },
        head_centre: to_world(head_centre),
    }
}

/// The torso as an elliptic cylinder (for self-occlusion): base at the hip midpoint, axis along the
/// trunk, half-width across, half-depth front to back.
#[derive(Debug, Clone, Copy)]
pub struct Torso {
    pub base: Point3<f64>,
    pub R_world_trunk: Rotation3<f64>,
    pub length_m: f64,
    pub half_depth_m: f64,
    pub half_width_m: f64,
}

/// Everything the forward kinematics produces.
#[derive(Debug, Clone, Copy)]
pub struct Kinematics {
    pub points: [Point3<f64>; LANDMARK_COUNT],
    pub grasp_left: Point3<f64>,
    pub grasp_right: Point3<f64>,
    pub torso: Torso,
    pub head_centre: Point3<f64>,
}

pub fn rx(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::x_axis(), a)
}
pub fn ry(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::y_axis(), a)
}
pub fn rz(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), a)
}

/// One arm's joint angles, radians (metres for the shrug).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ArmPosture {
    /// Upper arm raised forward from hanging (negative = extension).
    pub flexion_rad: f64,
    /// Upper arm raised sideways, out of the trunk's sagittal plane (negative = across the chest).
    pub abduction_rad: f64,
    /// Rotation of the upper arm about its own axis (positive swings the forearm outwards).
    pub humeral_rotation_rad: f64,
    /// Elbow flexion, 0 = straight.
    pub elbow_flexion_rad: f64,
    /// Wrist flexion towards the palm (negative = extension).
    pub wrist_flexion_rad: f64,
    /// Shoulder raised along the trunk axis (shrug), metres.
    pub shoulder_raise_m: f64,
    /// Wrist deviation towards the thumb side (applied after flexion; negative = towards the little
    /// finger).
    pub wrist_deviation_rad: f64,
}

/// One leg's joint angles, radians.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct LegPosture {
    /// Thigh forward of vertical.
    pub hip_flexion_rad: f64,
    /// Knee flexion, 0 = straight.
    pub knee_flexion_rad: f64,
}

/// A whole-body posture and where the body stands: the simulator's ground-truth joint angles.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Posture {
    /// Floor point below the hip midpoint, world x and y, metres.
    pub position_m: [f64; 2],
    /// Facing direction about world z; 0 faces +x.
    pub heading_rad: f64,
    pub trunk_flexion_rad: f64,
    /// Positive bends towards the operator's right.
    pub trunk_side_bend_rad: f64,
    /// Positive turns the shoulders to the left.
    pub trunk_twist_rad: f64,
    /// Relative to the trunk; positive = looking down.
    pub neck_flexion_rad: f64,
    /// Relative to the trunk; positive = turned to the left.
    pub neck_yaw_rad: f64,
    pub left_arm: ArmPosture,
    pub right_arm: ArmPosture,
    pub left_leg: LegPosture,
    pub right_leg: LegPosture,
}

impl Default for Posture {
    /// Standing relaxed at the origin facing +x: arms hanging with elbows bent 15°.
    fn default() -> Self {
        let arm = ArmPosture {
            elbow_flexion_rad: 15f64.to_radians(),
            ..ArmPosture::default()
        };
        Self {
            position_m: [0.0, 0.0],
            heading_rad: 0.0,
            trunk_flexion_rad: 0.0,
            trunk_side_bend_rad: 0.0,
            trunk_twist_rad: 0.0,
            neck_flexion_rad: 0.0,
            neck_yaw_rad: 0.0,
            left_arm: arm,
            right_arm: arm,
            left_leg: LegPosture::default(),
            right_leg: LegPosture::default(),
        }
    }
}

impl ArmPosture {
    fn lerp(&self, o: &Self, s: f64) -> Self {
        let l = |a: f64, b: f64| a + (b - a) * s;
        Self {
            flexion_rad: l(self.flexion_rad, o.flexion_rad),
            abduction_rad: l(self.abduction_rad, o.abduction_rad),
            humeral_rotation_rad: l(self.humeral_rotation_rad, o.humeral_rotation_rad),
            elbow_flexion_rad: l(self.elbow_flexion_rad, o.elbow_flexion_rad),
            wrist_flexion_rad: l(self.wrist_flexion_rad, o.wrist_flexion_rad),
            shoulder_raise_m: l(self.shoulder_raise_m, o.shoulder_raise_m),
            wrist_deviation_rad: l(self.wrist_deviation_rad, o.wrist_deviation_rad),
        }
    }
}

impl Posture {
    /// Joint-space interpolation: `s = 0` gives `self`, `s = 1` gives `other` (heading by the
    /// shorter way round).
    #[must_use]
    pub fn lerp(&self, other: &Self, s: f64) -> Self {
        let l = |a: f64, b: f64| a + (b - a) * s;
        let dh = (other.heading_rad - self.heading_rad + std::f64::consts::PI)
            .rem_euclid(std::f64::consts::TAU)
            - std::f64::consts::PI;
        let leg = |a: &LegPosture, b: &LegPosture| LegPosture {
            hip_flexion_rad: l(a.hip_flexion_rad, b.hip_flexion_rad),
            knee_flexion_rad: l(a.knee_flexion_rad, b.knee_flexion_rad),
        };
        Self {
            position_m: [
                l(self.position_m[0], other.position_m[0]),
                l(self.position_m[1], other.position_m[1]),
            ],
            heading_rad: self.heading_rad + dh * s,
            trunk_flexion_rad: l(self.trunk_flexion_rad, other.trunk_flexion_rad),
            trunk_side_bend_rad: l(self.trunk_side_bend_rad, other.trunk_side_bend_rad),
            trunk_twist_rad: l(self.trunk_twist_rad, other.trunk_twist_rad),
            neck_flexion_rad: l(self.neck_flexion_rad, other.neck_flexion_rad),
            neck_yaw_rad: l(self.neck_yaw_rad, other.neck_yaw_rad),
            left_arm: self.left_arm.lerp(&other.left_arm, s),
            right_arm: self.right_arm.lerp(&other.right_arm, s),
            left_leg: leg(&self.left_leg, &other.left_leg),
            right_leg: leg(&self.right_leg, &other.right_leg),
        }
    }

    /// The working arm of an operator.
    pub fn working_arm_mut(&mut self, right_handed: bool) -> &mut ArmPosture {
        if right_handed {
            &mut self.right_arm
        } else {
            &mut self.left_arm
        }
    }

    /// The working arm of an operator.
    pub fn working_arm(&self, right_handed: bool) -> &ArmPosture {
        if right_handed {
            &self.right_arm
        } else {
            &self.left_arm
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn at(p: &[Point3<f64>; LANDMARK_COUNT], l: Landmark) -> Point3<f64> {
        p[l.index()]
    }

    fn points(h: f64, q: &Posture) -> [Point3<f64>; LANDMARK_COUNT] {
        kinematics(&Body::average(h), q).points
    }

    #[test]
    fn standing_heights_match_drillis_and_contini() {
        for h in [1.5, 1.75, 2.0] {
            let q = Posture {
                left_arm: ArmPosture::default(),
                right_arm: ArmPosture::default(),
                ..Posture::default()
            };
            let p = points(h, &q);
            let eye = 0.5 * (at(&p, Landmark::LeftEye).z + at(&p, Landmark::RightEye).z);
            assert!((eye - 0.936 * h).abs() < 1e-9);
            assert!((at(&p, Landmark::LeftShoulder).z - 0.818 * h).abs() < 1e-9);
            assert!((at(&p, Landmark::RightHip).z - 0.530 * h).abs() < 1e-9);
            assert!((at(&p, Landmark::LeftKnee).z - 0.285 * h).abs() < 1e-9);
            assert!((at(&p, Landmark::LeftAnkle).z - 0.039 * h).abs() < 1e-9);
            assert!((at(&p, Landmark::RightElbow).z - (0.818 - 0.186) * h).abs() < 1e-9);
            assert!(at(&p, Landmark::LeftHeel).z.abs() < 1e-12);
            // x forward, y to the left
            assert!(at(&p, Landmark::LeftShoulder).y > 0.0);
            assert!(at(&p, Landmark::Nose).x > 0.0);
        }
    }

    #[test]
    fn heading_turns_the_body_rigidly() {
        let q0 = Posture::default();
        let q1 = Posture {
            heading_rad: 1.0,
            position_m: [0.5, -0.2],
            ..q0
        };
        let (a, b) = (points(1.8, &q0), points(1.8, &q1));
        for (i, j) in [(0, 11), (11, 24), (15, 32)] {
            let da = (a[i] - a[j]).norm();
            let db = (b[i] - b[j]).norm();
            assert!((da - db).abs() < 1e-9);
        }
    }

    /// Wrist deviation turns the hand towards the thumb (forward for a hanging arm) and leaves the
    /// wrist where it was; zero deviation is no rotation at all.
    #[test]
    fn wrist_deviation_turns_the_hand_towards_the_thumb() {
        let hanging = ArmPosture::default();
        let deviated = ArmPosture {
            wrist_deviation_rad: 20f64.to_radians(),
            ..hanging
        };
        let q = |arm: ArmPosture| Posture {
            right_arm: arm,
            ..Posture::default()
        };
        let (a, b) = (points(1.75, &q(hanging)), points(1.75, &q(deviated)));
        assert_eq!(at(&a, Landmark::RightWrist), at(&b, Landmark::RightWrist));
        let index = |p: &[Point3<f64>; LANDMARK_COUNT]| at(p, Landmark::RightIndex).x;
        assert!(index(&b) > index(&a) + 0.01, "{} {}", index(&a), index(&b));
    }
}
