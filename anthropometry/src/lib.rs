//! Body proportions for the workspace: the one table of body segment lengths and standing joint
//! heights as fractions of stature `H` (this module), ANSUR II's 6,068 measured people
//! ([`ansur`]: the real spread of proportions between people) and the stature models fitted on
//! them ([`stature`]: stature from the ear's standing height, with a residual measured on people
//! never fitted).
//!
//! # Source
//! Drillis, R. & Contini, R. (1966), *Body Segment Parameters*, Technical Report 1166-03, Office of
//! Vocational Rehabilitation, New York University; as tabulated by D. A. Winter, *Biomechanics and
//! Motor Control of Human Movement* (4th ed., Wiley 2009), Fig. 4.1 "Body segment lengths expressed
//! as a fraction of body height H" (see also `shared/reference/robot.md`). The numbers are 1966
//! population means: priors for a person, not measurements of one.
//!
//! # Who uses it
//! - `ergocell_robot`: the grasp band a handover point must lie in, the operator's arm holding it
//!   (`ArmPosture`) and the body capsules of the separation check;
//! - `ergocell_sim`: the simulated operators' bodies;
//! - `ergocell_ergonomics`: the stature estimators and the synthetic poses of its tests.
//!
//! The robot crate may not depend on the skeleton, perception or ergonomics crates (`.ci/deps`), so
//! the table cannot live in any of them; it is this crate, which depends on nothing, instead of one
//! copy per crate.
//!
//! # Heights and lengths
//! Heights ([`EYE_HEIGHT`] … [`ANKLE_HEIGHT`]) are above the floor, standing upright with the arms
//! hanging. The leg and trunk lengths are the differences of the joint heights: thigh = hip − knee
//! (0.530 − 0.285 = 0.245), shank = knee − ankle (0.285 − 0.039 = 0.246), trunk = shoulder − hip
//! (0.818 − 0.530 = 0.288), so ankle + shank + thigh + trunk = shoulder (0.818). The arm does not
//! compose that way: the tabulated elbow height (0.630) is 0.002 H above shoulder − upper arm
//! (0.632), and the wrist height (0.485) 0.001 H above elbow − forearm (0.484); a model built from
//! the lengths puts the hanging elbow at 0.632 H.
//!
//! In `f64` a difference such as `HIP_HEIGHT - KNEE_HEIGHT` is not bit-equal to the literal `0.245`
//! (it is one or two ulps off). [`THIGH`], [`SHANK`] and [`TRUNK`] are the tabulated literals; the
//! differences themselves are in [`from_heights`], for a body model that stacks its segments on the
//! tabulated heights.

pub mod ansur;
pub mod body;
pub mod stature;

// Heights above the floor, standing upright.

/// Eye height.
pub const EYE_HEIGHT: f64 = 0.936;
/// Chin height.
pub const CHIN_HEIGHT: f64 = 0.870;
/// Shoulder joint (glenohumeral) height.
pub const SHOULDER_HEIGHT: f64 = 0.818;
/// Chest (nipple) height.
pub const CHEST_HEIGHT: f64 = 0.720;
/// Elbow joint height, arm hanging.
pub const ELBOW_HEIGHT: f64 = 0.630;
/// Hip joint (greater trochanter) height.
pub const HIP_HEIGHT: f64 = 0.530;
/// Wrist joint height, arm hanging.
pub const WRIST_HEIGHT: f64 = 0.485;
/// Fingertip height, arm hanging.
pub const FINGERTIP_HEIGHT: f64 = 0.377;
/// Knee joint height.
pub const KNEE_HEIGHT: f64 = 0.285;
/// Ankle joint height.
pub const ANKLE_HEIGHT: f64 = 0.039;

// Lengths and widths.

/// Head, chin to vertex.
pub const HEAD: f64 = 0.130;
/// Shoulder width (joint to joint).
pub const SHOULDER_WIDTH: f64 = 0.259;
/// Hip width (joint to joint).
pub const HIP_WIDTH: f64 = 0.191;
/// Upper arm, shoulder to elbow joint.
pub const UPPER_ARM: f64 = 0.186;
/// Forearm, elbow to wrist joint.
pub const FOREARM: f64 = 0.146;
/// Hand, wrist joint to fingertip.
pub const HAND: f64 = 0.108;
/// Foot length.
pub const FOOT: f64 = 0.152;
/// Thigh, hip to knee joint.
pub const THIGH: f64 = 0.245;
/// Shank (Winter's "leg"), knee to ankle joint.
pub const SHANK: f64 = 0.246;
/// Trunk, hip joint to shoulder joint: the difference of the tabulated shoulder and hip heights,
/// 0.818 − 0.530.
pub const TRUNK: f64 = 0.288;

/// Segments as differences of the tabulated heights, evaluated in `f64`: equal to [`crate::THIGH`],
/// [`crate::SHANK`] and [`crate::TRUNK`] to within two ulps, not bit for bit. A body model that
/// stacks these on [`crate::ANKLE_HEIGHT`] puts its joints at the tabulated heights to rounding.
pub mod from_heights {
    use super::{ANKLE_HEIGHT, EYE_HEIGHT, HIP_HEIGHT, KNEE_HEIGHT, SHOULDER_HEIGHT};

    /// Thigh: hip height − knee height.
    pub const THIGH: f64 = HIP_HEIGHT - KNEE_HEIGHT;
    /// Shank: knee height − ankle height.
    pub const SHANK: f64 = KNEE_HEIGHT - ANKLE_HEIGHT;
    /// Trunk: shoulder height − hip height.
    pub const TRUNK: f64 = SHOULDER_HEIGHT - HIP_HEIGHT;
    /// Eye above the shoulder joint: eye height − shoulder height (0.118).
    pub const EYE_ABOVE_SHOULDER: f64 = EYE_HEIGHT - SHOULDER_HEIGHT;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Decimal relations are checked to this; `f64` differences are off by a few ulps.
    const TOL: f64 = 1e-12;

    #[test]
    fn the_published_values() {
        let heights = [
            (EYE_HEIGHT, 0.936),
            (CHIN_HEIGHT, 0.870),
            (SHOULDER_HEIGHT, 0.818),
            (CHEST_HEIGHT, 0.720),
            (ELBOW_HEIGHT, 0.630),
            (HIP_HEIGHT, 0.530),
            (WRIST_HEIGHT, 0.485),
            (FINGERTIP_HEIGHT, 0.377),
            (KNEE_HEIGHT, 0.285),
            (ANKLE_HEIGHT, 0.039),
        ];
        let lengths = [
            (HEAD, 0.130),
            (SHOULDER_WIDTH, 0.259),
            (HIP_WIDTH, 0.191),
            (UPPER_ARM, 0.186),
            (FOREARM, 0.146),
            (HAND, 0.108),
            (FOOT, 0.152),
            (THIGH, 0.245),
            (SHANK, 0.246),
            (TRUNK, 0.288),
        ];
        for (value, published) in heights.iter().chain(&lengths) {
            assert_eq!(value, published);
        }
        // Standing heights fall strictly from the eyes to the ankles.
        assert!(heights.windows(2).all(|w| w[0].0 > w[1].0));
    }

    #[test]
    fn leg_and_trunk_segments_are_differences_of_the_joint_heights() {
        assert!((HIP_HEIGHT - KNEE_HEIGHT - THIGH).abs() < TOL);
        assert!((KNEE_HEIGHT - ANKLE_HEIGHT - SHANK).abs() < TOL);
        assert!((SHOULDER_HEIGHT - HIP_HEIGHT - TRUNK).abs() < TOL);
        // Stacked from the ankle: shoulder = ankle + shank + thigh + trunk.
        assert!((ANKLE_HEIGHT + SHANK + THIGH + TRUNK - SHOULDER_HEIGHT).abs() < TOL);
        // Head = stature − chin height; fingertip = wrist − hand.
        assert!((1.0 - CHIN_HEIGHT - HEAD).abs() < TOL);
        assert!((WRIST_HEIGHT - HAND - FINGERTIP_HEIGHT).abs() < TOL);
        assert!((from_heights::EYE_ABOVE_SHOULDER - 0.118).abs() < TOL);
    }

    #[test]
    fn from_heights_is_the_tabulated_segments_to_rounding() {
        for (derived, tabulated) in [
            (from_heights::THIGH, THIGH),
            (from_heights::SHANK, SHANK),
            (from_heights::TRUNK, TRUNK),
        ] {
            assert!((derived - tabulated).abs() <= 2.0 * f64::EPSILON * tabulated);
        }
    }

    #[test]
    fn the_arm_lengths_do_not_compose_to_the_hanging_heights() {
        // Documented above: the tabulated elbow and wrist heights are measured, not derived.
        assert!((SHOULDER_HEIGHT - UPPER_ARM - ELBOW_HEIGHT - 0.002).abs() < TOL);
        assert!((ELBOW_HEIGHT - FOREARM - WRIST_HEIGHT + 0.001).abs() < TOL);
    }
}
