//! One person's body: the standing heights and segment lengths a body model stacks, metres.
//!
//! Two sources: [`Body::average`] scales the Drillis & Contini table by stature (one set of
//! proportions for everyone, the robot's planning model), with the ears where ANSUR II's stature
//! model puts them for that stature; [`Body::measured`] takes a measured person's own heights and
//! lengths ([`crate::ansur::Person`]: the real spread of proportions between people).
//!
//! Widths (shoulders and hips joint to joint) and the face's layout are stature-scaled in both:
//! ANSUR II's biacromial and hip breadths are skin-to-skin, not the joint centres a pose estimator
//! reports.

use crate::ansur::Person;
use crate::stature::FLOOR_TO_EAR;
use crate::{from_heights, ANKLE_HEIGHT, FOOT, FOREARM, HAND, HIP_WIDTH, SHOULDER_HEIGHT};
use crate::{SHOULDER_WIDTH, UPPER_ARM};

/// A body's dimensions, metres. Heights stack: ankle + shank + thigh + trunk = shoulder height;
/// the eye and ear are measured above the shoulder joint, standing upright.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    pub stature_m: f64,
    /// Ankle joint above the floor.
    pub ankle_height_m: f64,
    /// Knee − ankle.
    pub shank_m: f64,
    /// Hip − knee.
    pub thigh_m: f64,
    /// Shoulder − hip.
    pub trunk_m: f64,
    /// Eye height − shoulder height.
    pub eye_above_shoulder_m: f64,
    /// Ear (tragion) height − shoulder height.
    pub ear_above_shoulder_m: f64,
    pub upper_arm_m: f64,
    pub forearm_m: f64,
    pub hand_m: f64,
    pub foot_m: f64,
    /// Shoulder joint to shoulder joint.
    pub shoulder_width_m: f64,
    /// Hip joint to hip joint.
    pub hip_width_m: f64,
    /// The measured person's subject id, `None` for [`Body::average`].
    pub subject_id: Option<u32>,
}

impl Body {
    /// Drillis & Contini's proportions at `stature_m`, the ears where ANSUR II's floor-to-ear model
    /// puts a person of that stature.
    pub fn average(stature_m: f64) -> Self {
        let h = stature_m;
        Self {
            stature_m: h,
            ankle_height_m: ANKLE_HEIGHT * h,
            shank_m: from_heights::SHANK * h,
            thigh_m: from_heights::THIGH * h,
            trunk_m: from_heights::TRUNK * h,
            eye_above_shoulder_m: from_heights::EYE_ABOVE_SHOULDER * h,
            ear_above_shoulder_m: FLOOR_TO_EAR.span_m(h) - SHOULDER_HEIGHT * h,
            upper_arm_m: UPPER_ARM * h,
            forearm_m: FOREARM * h,
            hand_m: HAND * h,
            foot_m: FOOT * h,
            shoulder_width_m: SHOULDER_WIDTH * h,
            hip_width_m: HIP_WIDTH * h,
            subject_id: None,
        }
    }

    /// A measured person's own heights and lengths (acromion for the shoulder, greater trochanter
    /// for the hip, lateral femoral epicondyle for the knee, lateral malleolus for the ankle);
    /// widths stature-scaled.
    pub fn measured(p: &Person) -> Self {
        let h = p.stature_m;
        Self {
            stature_m: h,
            ankle_height_m: p.ankle_height_m,
            shank_m: p.knee_height_m - p.ankle_height_m,
            thigh_m: p.hip_height_m - p.knee_height_m,
            trunk_m: p.shoulder_height_m - p.hip_height_m,
            eye_above_shoulder_m: p.eye_height_m - p.shoulder_height_m,
            ear_above_shoulder_m: p.ear_height_m - p.shoulder_height_m,
            upper_arm_m: p.upper_arm_m,
            forearm_m: p.forearm_m,
            hand_m: p.hand_m,
            foot_m: p.foot_m,
            shoulder_width_m: SHOULDER_WIDTH * h,
            hip_width_m: HIP_WIDTH * h,
            subject_id: Some(p.subject_id),
        }
    }

    /// Shoulder joint height standing upright.
    pub fn shoulder_height_m(&self) -> f64 {
        self.ankle_height_m + self.shank_m + self.thigh_m + self.trunk_m
    }

    /// Ear (tragion) height standing upright.
    pub fn ear_height_m(&self) -> f64 {
        self.shoulder_height_m() + self.ear_above_shoulder_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ansur::people;

    #[test]
    fn an_average_body_stands_on_the_tabulated_heights() {
        let b = Body::average(1.75);
        assert!((b.shoulder_height_m() - SHOULDER_HEIGHT * 1.75).abs() < 1e-12);
        assert!((b.ear_height_m() - FLOOR_TO_EAR.span_m(1.75)).abs() < 1e-12);
        assert!((FLOOR_TO_EAR.stature_m(b.ear_height_m()) - 1.75).abs() < 1e-12);
    }

    #[test]
    fn a_measured_body_stands_on_its_own_heights() {
        let people = people().unwrap();
        for p in people.iter().take(50) {
            let b = Body::measured(p);
            assert!((b.shoulder_height_m() - p.shoulder_height_m).abs() < 1e-12);
            assert!((b.ear_height_m() - p.ear_height_m).abs() < 1e-12);
            assert!(b.shank_m > 0.0 && b.thigh_m > 0.0 && b.trunk_m > 0.0);
            assert!(b.ear_above_shoulder_m > 0.0);
            assert_eq!(b.subject_id, Some(p.subject_id));
        }
    }
}
