//! Simulated operators: a body (stature-scaled or a measured person's) and its working hand, posed
//! through the workspace's one body model, [`ergocell_body`] (its frames and joint angles are
//! documented there: x forward, y left, z up). The posture types are that crate's, re-exported.

use ergocell_anthropometry::body::Body;
pub use ergocell_body::{rx, ry, rz, ArmPosture, Kinematics, LegPosture, Posture, Torso};
use ergocell_skeleton::LANDMARK_COUNT;
use nalgebra::Point3;
use serde::Serialize;

use crate::SimError;

/// A simulated operator: a body (stature-scaled or a measured person's) and the working hand.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Operator {
    body: Body,
    /// True for a right-handed operator (reaches with the right hand).
    pub right_handed: bool,
}

impl Serialize for Operator {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = serializer.serialize_struct("Operator", 3)?;
        s.serialize_field("stature_m", &self.body.stature_m)?;
        s.serialize_field("right_handed", &self.right_handed)?;
        s.serialize_field("subject_id", &self.body.subject_id)?;
        s.end()
    }
}

impl Operator {
    /// An operator of this stature (0.5–2.5 m) with Drillis & Contini's proportions
    /// ([`Body::average`]), right-handed.
    pub fn new(stature_m: f64) -> Result<Self, SimError> {
        Self::check_stature(stature_m)?;
        Ok(Self {
            body: Body::average(stature_m),
            right_handed: true,
        })
    }

    /// A measured person's body ([`Body::measured`]), right-handed.
    pub fn measured(person: &ergocell_anthropometry::ansur::Person) -> Result<Self, SimError> {
        Self::check_stature(person.stature_m)?;
        Ok(Self {
            body: Body::measured(person),
            right_handed: true,
        })
    }

    fn check_stature(stature_m: f64) -> Result<(), SimError> {
        if !(0.5..=2.5).contains(&stature_m) {
            return Err(SimError::BadParameter {
                name: "stature_m",
                value: stature_m,
                why: "must be within 0.5..=2.5 m",
            });
        }
        Ok(())
    }

    /// The same operator, left-handed.
    #[must_use]
    pub fn left_handed(mut self) -> Self {
        self.right_handed = false;
        self
    }

    /// True stature, metres.
    pub fn stature_m(&self) -> f64 {
        self.body.stature_m
    }

    /// The body's dimensions.
    pub fn body(&self) -> &Body {
        &self.body
    }

    /// A segment length or height: `ratio · H`.
    pub fn len(&self, ratio: f64) -> f64 {
        ratio * self.body.stature_m
    }

    /// The 33 landmarks of this operator in `posture`, world frame.
    pub fn landmarks(&self, posture: &Posture) -> [Point3<f64>; LANDMARK_COUNT] {
        self.kinematics(posture).points
    }

    /// The grasp point of the working hand (palm centre, halfway from the wrist to the knuckles).
    pub fn grasp_point(&self, posture: &Posture) -> Point3<f64> {
        let k = self.kinematics(posture);
        if self.right_handed {
            k.grasp_right
        } else {
            k.grasp_left
        }
    }

    /// Landmarks, grasp points and the torso/head geometry used for occlusion.
    pub(crate) fn kinematics(&self, q: &Posture) -> Kinematics {
        ergocell_body::kinematics(&self.body, q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_of_range_stature_is_rejected() {
        assert!(Operator::new(0.2).is_err());
        assert!(Operator::new(f64::NAN).is_err());
    }

    #[test]
    fn the_operator_is_the_body_model() {
        let op = Operator::new(1.8).unwrap();
        let q = Posture::default();
        assert_eq!(
            op.landmarks(&q),
            ergocell_body::kinematics(&Body::average(1.8), &q).points
        );
    }
}
