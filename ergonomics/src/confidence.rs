//! How sure each region's score is: the joint angle's uncertainty, propagated from the fused
//! skeleton, and the probability that the angle lies in the band the score was given for.
//!
//! RULA scores a region from one angle cut into bands (an upper arm at 44° and at 46° score 2 and 3).
//! A measured angle is off by a few degrees, so a score 1° from an edge is a coin toss, and one 20°
//! inside its band is not. This module says which:
//!
//! 1. **Each landmark's spread.** The fusion states each landmark's position standard deviation
//!    ([`ergocell_skeleton::LandmarkEstimate::position_sd_m`], from the triangulation's covariance
//!    over the views it kept: fewer or noisier views, larger spread).
//! 2. **Each angle's spread.** A segment from `a` to `b` of length `L` points in a direction known to
//!    `sqrt(σ_a² + σ_b²) / L` radians (first order, per axis); the angle between two segments adds
//!    their variances. The upper arm is shoulder→elbow against the trunk (mid-hips→mid-shoulders);
//!    the lower arm is shoulder→elbow against elbow→wrist; the wrist is elbow→wrist against
//!    wrist→mid(index, pinky); the neck is mid-shoulders→mid-ears against the trunk; the trunk is its
//!    axis against the vertical. This is the *propagated* spread `σₚ`.
//! 3. **Calibrated.** The propagated spread knows the detector's noise as the fusion models it, not
//!    the smoothing after it nor the detector's bias (a landmark is not a joint centre). The stated
//!    spread is `σ = sqrt((k·σₚ)² + f²)` with a scale `k` and a floor `f` per region
//!    ([`ConfidenceModel`]), fitted on the twin's tuning seeds to the pipeline's error against the
//!    true skeleton; whether the stated probabilities are right is checked on seeds never fitted
//!    (a reliability table, `ergocell sim warnings`).
//! 4. **The band's probability.** With the measured angle `x` and a normal error of spread `σ`, the
//!    probability that the true angle scores the same band: the normal mass over the stretches of
//!    angle where the region's score (the worksheet's adjustments held as they are) equals the one
//!    given. The adjustments (abducted, raised, twisted) are yes/no findings of their own and are not
//!    in this probability.
//! 5. **Recalibrated.** The normal mass treats every true angle as equally likely before the
//!    measurement, and people do not hold their joints that way: a measured angle on a band's edge
//!    is more often right than the mass's ½ says. Per region, the mass is mapped to the share of
//!    tuning samples that were right at that mass (histogram binning made monotone, Zadrozny & Elkan
//!    2002): [`RECALIBRATION_EDGES`] cut the mass into bins, each bin's mean mass maps to its share
//!    right, and a mass in between is interpolated linearly.
//!
//! Regions without an angle (the legs) and angles that were held, never observed or scored
//! conservatively carry no probability (`None`): nothing measured this frame to be sure of.

use ergocell_skeleton::{Landmark, Skeleton3};
use serde::{Deserialize, Serialize};

use crate::assess::{BodyRegion, InputSource, SideAssessment};
use crate::rula::{
    RulaInput, LOWER_ARM_EDGES_DEG, NECK_EDGES_DEG, TRUNK_EDGES_DEG, UPPER_ARM_EDGES_DEG,
    WRIST_EDGES_DEG,
};
use crate::warnings::{region_angle, region_score_at, with_region_angle};
use crate::Side;

/// The regions that have an angle, in [`BodyRegion::ALL`] order (the legs have none).
pub const ANGLED_REGIONS: [BodyRegion; 5] = [
    BodyRegion::UpperArm,
    BodyRegion::LowerArm,
    BodyRegion::Wrist,
    BodyRegion::Neck,
    BodyRegion::Trunk,
];

/// A probability at or above which a band is called sure; below it, a warning in that band is
/// "near the limit" on the operator display.
pub const SURE_PROBABILITY: f64 = 0.9;

/// The calibration of the stated spread: `σ = sqrt((scale·σₚ)² + floor²)` per region, in
/// [`ANGLED_REGIONS`] order.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ConfidenceModel {
    /// Multiplies the propagated spread (the smoothing after the fusion narrows it, unmodelled
    /// correlations widen it).
    pub scale: [f64; 5],
    /// The spread that remains however well the landmarks are placed (the detector's bias: a
    /// landmark is not a joint centre), radians.
    pub floor_rad: [f64; 5],
    /// The recalibration: per region, `(mass, stated)` points with both rising, one per bin of
    /// [`RECALIBRATION_EDGES`]; the identity where the tuning samples left a bin empty.
    pub recalibration: [[[f64; 2]; RECALIBRATION_BINS]; 5],
}

/// Where the recalibration's bins of the normal mass are cut: fine near 1, where most frames are.
pub const RECALIBRATION_EDGES: [f64; RECALIBRATION_BINS + 1] =
    [0.0, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 0.999, 1.0];
/// Bins of the recalibration.
pub const RECALIBRATION_BINS: usize = 9;

/// The identity recalibration: each bin's middle maps to itself.
pub fn identity_recalibration() -> [[f64; 2]; RECALIBRATION_BINS] {
    std::array::from_fn(|i| {
        let mid = f64::midpoint(RECALIBRATION_EDGES[i], RECALIBRATION_EDGES[i + 1]);
        [mid, mid]
    })
}

/// `points` (rising in both) read at `x`: linear between points, flat beyond the ends.
pub fn interpolate(points: &[[f64; 2]], x: f64) -> f64 {
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return x;
    };
    if x <= first[0] {
        return first[1];
    }
    if x >= last[0] {
        return last[1];
    }
    for w in points.windows(2) {
        let ([x0, y0], [x1, y1]) = (w[0], w[1]);
        if x <= x1 {
            return if x1 > x0 {
                y0 + (y1 - y0) * (x - x0) / (x1 - x0)
            } else {
                y1
            };
        }
    }
    last[1]
}

impl Default for ConfidenceModel {
    /// Fitted on the twin's tuning seeds 1–20 (six cameras `config/rig.toml`, the detector fitted
    /// to MediaPipe's error on Pose2Sim's video, the default task mix) by `ergocell sim warnings
    /// --detector sim/detectors/mediapipe-pose2sim.toml --seeds 1..20 --fit-confidence`: per
    /// region, the scale and floor whose band probabilities have the least log loss against the
    /// true skeleton's bands, then the recalibration's points. The propagated spread
    /// earns a weight for the upper arm, lower arm, wrist and trunk; the neck's error is the
    /// detector's bias, which the fusion's covariance cannot see (scale 0).
    // fitted numbers, one of which happens to be close to π/4
    #[allow(clippy::approx_constant)]
    fn default() -> Self {
        Self {
            // upper arm, lower arm, wrist, neck, trunk
            scale: [0.5, 0.3, 0.2, 0.0, 0.4],
            floor_rad: [
                1.25f64.to_radians(),
                2.0f64.to_radians(),
                4.0f64.to_radians(),
                1.5f64.to_radians(),
                0.5f64.to_radians(),
            ],
            recalibration: [
                // upper arm
                [
                    [0.2500, 0.2500],
                    [0.5506, 0.5856],
                    [0.6514, 0.7097],
                    [0.7513, 0.8385],
                    [0.8541, 0.9182],
                    [0.9274, 0.9516],
                    [0.9742, 0.9754],
                    [0.9960, 0.9876],
                    [1.0000, 0.9995],
                ],
                // lower arm
                [
                    [0.2500, 0.2500],
                    [0.5485, 0.5685],
                    [0.6516, 0.6704],
                    [0.7521, 0.7945],
                    [0.8541, 0.8570],
                    [0.9274, 0.9112],
                    [0.9750, 0.9725],
                    [0.9959, 0.9947],
                    [1.0000, 1.0000],
                ],
                // wrist
                [
                    [0.2500, 0.2500],
                    [0.5510, 0.6369],
                    [0.6538, 0.8649],
                    [0.7560, 0.9579],
                    [0.8576, 0.9836],
                    [0.9282, 0.9836],
                    [0.9748, 0.9836],
                    [0.9960, 0.9836],
                    [0.9996, 0.9836],
                ],
                // neck
                [
                    [0.2500, 0.2500],
                    [0.5501, 0.5597],
                    [0.6514, 0.6761],
                    [0.7521, 0.7854],
                    [0.8535, 0.8731],
                    [0.9272, 0.9435],
                    [0.9742, 0.9763],
                    [0.9962, 0.9937],
                    [0.9998, 0.9990],
                ],
                // trunk
                [
                    [0.2500, 0.2500],
                    [0.5508, 0.5625],
                    [0.6512, 0.6718],
                    [0.7521, 0.7765],
                    [0.8547, 0.8798],
                    [0.9275, 0.9452],
                    [0.9745, 0.9786],
                    [0.9959, 0.9936],
                    [0.9999, 0.9988],
                ],
            ],
        }
    }
}

impl ConfidenceModel {
    /// Index of `region` in [`ANGLED_REGIONS`] (`None` for the legs).
    pub fn slot(region: BodyRegion) -> Option<usize> {
        ANGLED_REGIONS.iter().position(|r| *r == region)
    }

    /// The stated spread from the propagated one, radians.
    pub fn stated_sd_rad(&self, region: BodyRegion, propagated_rad: f64) -> Option<f64> {
        let i = Self::slot(region)?;
        let s = self.scale[i] * propagated_rad;
        Some((s * s + self.floor_rad[i] * self.floor_rad[i]).sqrt())
    }

    /// The probability stated for a normal mass `p` in `region`'s band: the recalibration applied
    /// (`p` itself for the legs).
    pub fn stated_probability(&self, region: BodyRegion, p: f64) -> f64 {
        let Some(i) = Self::slot(region) else {
            return p;
        };
        interpolate(&self.recalibration[i], p).clamp(0.0, 1.0)
    }

    /// Refuses a scale or floor that is negative or not finite, and a recalibration whose points
    /// leave `0..=1` or fall, naming the region.
    pub fn validate(&self) -> Result<(), crate::ErgonomicsError> {
        for (i, region) in ANGLED_REGIONS.iter().enumerate() {
            let points = &self.recalibration[i];
            let rising = points
                .windows(2)
                .all(|w| w[0][0] <= w[1][0] && w[0][1] <= w[1][1]);
            let inside = points.iter().flatten().all(|v| (0.0..=1.0).contains(v));
            if !(rising && inside) {
                return Err(crate::ErgonomicsError::BadConfidenceModel {
                    region: region.name(),
                    parameter: "recalibration",
                    value: f64::NAN,
                });
            }
            for (what, v) in [("scale", self.scale[i]), ("floor_rad", self.floor_rad[i])] {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(crate::ErgonomicsError::BadConfidenceModel {
                        region: region.name(),
                        parameter: what,
                        value: v,
                    });
                }
            }
        }
        Ok(())
    }
}

/// How sure one region's score is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BandConfidence {
    /// The stated standard deviation of the region's angle, degrees.
    pub sd_deg: f64,
    /// The spread propagated from the landmarks' before calibration, `σₚ`, degrees.
    pub propagated_sd_deg: f64,
    /// The probability that the true angle lies in the band the score was given for, `0..=1`.
    pub probability: f64,
}

/// How sure each region's score of one side is (`None`: nothing measured to be sure of).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct RegionConfidences {
    pub upper_arm: Option<BandConfidence>,
    pub lower_arm: Option<BandConfidence>,
    pub wrist: Option<BandConfidence>,
    pub neck: Option<BandConfidence>,
    pub trunk: Option<BandConfidence>,
}

impl RegionConfidences {
    /// The region's confidence (always `None` for the legs).
    pub fn get(&self, region: BodyRegion) -> Option<BandConfidence> {
        match region {
            BodyRegion::UpperArm => self.upper_arm,
            BodyRegion::LowerArm => self.lower_arm,
            BodyRegion::Wrist => self.wrist,
            BodyRegion::Neck => self.neck,
            BodyRegion::Trunk => self.trunk,
            BodyRegion::Legs => None,
        }
    }

    fn slot_mut(&mut self, region: BodyRegion) -> Option<&mut Option<BandConfidence>> {
        match region {
            BodyRegion::UpperArm => Some(&mut self.upper_arm),
            BodyRegion::LowerArm => Some(&mut self.lower_arm),
            BodyRegion::Wrist => Some(&mut self.wrist),
            BodyRegion::Neck => Some(&mut self.neck),
            BodyRegion::Trunk => Some(&mut self.trunk),
            BodyRegion::Legs => None,
        }
    }
}

/// The worksheet field each angled region's angle is recorded under (its source says whether it
/// was measured this frame).
const fn angle_field(region: BodyRegion) -> &'static str {
    match region {
        BodyRegion::UpperArm => "upper_arm_flexion_deg",
        BodyRegion::LowerArm => "lower_arm_flexion_deg",
        BodyRegion::Wrist => "wrist_flexion_deg",
        BodyRegion::Neck => "neck_flexion_deg",
        BodyRegion::Trunk => "trunk_flexion_deg",
        BodyRegion::Legs => "legs_supported_and_balanced",
    }
}

fn sd(s: &Skeleton3, l: Landmark) -> Option<f64> {
    s.get(l)?.position_sd_m
}

/// The direction spread (radians) of the segment from a point of spread `sa` to one of spread `sb`,
/// `length` metres apart.
fn segment_sd(sa: f64, sb: f64, length: f64) -> Option<f64> {
    (length > 1e-6).then(|| (sa * sa + sb * sb).sqrt() / length)
}

/// The midpoint of two landmarks with its spread.
fn midpoint(s: &Skeleton3, a: Landmark, b: Landmark) -> Option<(nalgebra::Point3<f64>, f64)> {
    let (pa, pb) = (s.position(a)?, s.position(b)?);
    let (sa, sb) = (sd(s, a)?, sd(s, b)?);
    Some((nalgebra::center(&pa, &pb), (sa * sa + sb * sb).sqrt() / 2.0))
}

/// The spread of a segment between two landmarks.
fn landmark_segment_sd(s: &Skeleton3, a: Landmark, b: Landmark) -> Option<f64> {
    let (pa, pb) = (s.position(a)?, s.position(b)?);
    segment_sd(sd(s, a)?, sd(s, b)?, (pb - pa).norm())
}

fn trunk_sd(s: &Skeleton3) -> Option<f64> {
    let (hip, sh) = (
        midpoint(s, Landmark::LeftHip, Landmark::RightHip)?,
        midpoint(s, Landmark::LeftShoulder, Landmark::RightShoulder)?,
    );
    segment_sd(hip.1, sh.1, (sh.0 - hip.0).norm())
}

/// The propagated spread `σₚ` (radians) of `region`'s angle on `side` (ignored for the neck and
/// trunk) in skeleton `s`; `None` when a landmark it needs, or its spread, is missing.
pub fn propagated_sd_rad(s: &Skeleton3, region: BodyRegion, side: Side) -> Option<f64> {
    let (shoulder, elbow, wrist, index, pinky) = match side {
        Side::Left => (
            Landmark::LeftShoulder,
            Landmark::LeftElbow,
            Landmark::LeftWrist,
            Landmark::LeftIndex,
            Landmark::LeftPinky,
        ),
        Side::Right => (
            Landmark::RightShoulder,
            Landmark::RightElbow,
            Landmark::RightWrist,
            Landmark::RightIndex,
            Landmark::RightPinky,
        ),
    };
    let hyp = |a: f64, b: f64| (a * a + b * b).sqrt();
    match region {
        BodyRegion::Trunk => trunk_sd(s),
        BodyRegion::Neck => {
            let sh = midpoint(s, Landmark::LeftShoulder, Landmark::RightShoulder)?;
            let ears = midpoint(s, Landmark::LeftEar, Landmark::RightEar)?;
            Some(hyp(
                segment_sd(sh.1, ears.1, (ears.0 - sh.0).norm())?,
                trunk_sd(s)?,
            ))
        }
        BodyRegion::UpperArm => Some(hyp(landmark_segment_sd(s, shoulder, elbow)?, trunk_sd(s)?)),
        BodyRegion::LowerArm => Some(hyp(
            landmark_segment_sd(s, shoulder, elbow)?,
            landmark_segment_sd(s, elbow, wrist)?,
        )),
        BodyRegion::Wrist => {
            let hand = midpoint(s, index, pinky)?;
            let pw = s.position(wrist)?;
            Some(hyp(
                landmark_segment_sd(s, elbow, wrist)?,
                segment_sd(sd(s, wrist)?, hand.1, (hand.0 - pw).norm())?,
            ))
        }
        BodyRegion::Legs => None,
    }
}

/// The standard normal distribution's cumulative distribution function.
fn normal_cdf(z: f64) -> f64 {
    0.5 * libm::erfc(-z / std::f64::consts::SQRT_2)
}

fn edges_deg(region: BodyRegion) -> &'static [f64] {
    match region {
        BodyRegion::UpperArm => &UPPER_ARM_EDGES_DEG,
        BodyRegion::LowerArm => &LOWER_ARM_EDGES_DEG,
        BodyRegion::Wrist => &WRIST_EDGES_DEG,
        BodyRegion::Neck => &NECK_EDGES_DEG,
        BodyRegion::Trunk => &TRUNK_EDGES_DEG,
        BodyRegion::Legs => &[],
    }
}

/// The probability that a true angle, normal around `angle_deg` with spread `sd_deg`, gives
/// `region` the same score as `angle_deg` does, the worksheet's adjustments (`input`) held. The
/// score is constant between the region's band edges (RULA's single-angle bands: the wrist's exact
/// 0° has no width and no mass). A spread of 0 gives 1.
pub fn band_probability(region: BodyRegion, input: &RulaInput, angle_deg: f64, sd_deg: f64) -> f64 {
    let stated = region_score_at(region, input, Some(angle_deg));
    if edges_deg(region).is_empty() || sd_deg <= 0.0 || !sd_deg.is_finite() {
        return 1.0;
    }
    let same = stretch_mass::<std::convert::Infallible>(region, angle_deg, sd_deg, |probe| {
        Ok(region_score_at(region, input, Some(probe)) == stated)
    });
    match same {
        Ok(p) => p.clamp(0.0, 1.0),
        Err(never) => match never {},
    }
}

/// The normal mass (around `angle_deg`, spread `sd_deg` > 0) of the stretches between `region`'s
/// band edges whose inner point `keep` accepts. Each stretch is judged at one point inside it: a
/// third of the way in (never the wrist's 0°), or 1° from the one finite end of an outer stretch;
/// which side holds an edge does not matter to a mass.
fn stretch_mass<E>(
    region: BodyRegion,
    angle_deg: f64,
    sd_deg: f64,
    mut keep: impl FnMut(f64) -> Result<bool, E>,
) -> Result<f64, E> {
    let mut p = 0.0;
    let mut lo = f64::NEG_INFINITY;
    for hi in edges_deg(region).iter().copied().chain([f64::INFINITY]) {
        let probe = match (lo.is_finite(), hi.is_finite()) {
            (true, true) => lo + (hi - lo) / 3.0,
            (false, true) => hi - 1.0,
            (true, false) => lo + 1.0,
            (false, false) => angle_deg,
        };
        if keep(probe)? {
            p += normal_cdf((hi - angle_deg) / sd_deg) - normal_cdf((lo - angle_deg) / sd_deg);
        }
        lo = hi;
    }
    Ok(p)
}

/// The probability that a reading of `input` whose angles err with spread `sd_deg` (per region, in
/// [`ANGLED_REGIONS`] order, degrees) gives another RULA grand score than `input` itself: how hard
/// the posture is to measure, not how bad it is. A posture whose angles sit on band edges that
/// move the grand score is misread half the time; one deep inside its bands, or whose neighbouring
/// bands give the same grand score (RULA's tables saturate), is read right.
///
/// First order: each region's angle errs on its own, the others held. Its misread mass is the
/// normal mass of the stretches between its band edges where the worksheet, with the angle moved
/// there and then `readjust`ed (what else follows from the angle, such as muscle use decided from
/// the relaxed posture; the identity when nothing does), scores another grand score. The posture
/// is read right when no region is misread. A spread of 0 reads right.
///
/// # Errors
/// A worksheet [`crate::rula::score_worksheet`] refuses.
pub fn grand_misread_probability(
    input: &RulaInput,
    sd_deg: &[f64; 5],
    readjust: impl Fn(RulaInput) -> RulaInput,
) -> Result<f64, crate::ErgonomicsError> {
    let grand = crate::rula::score_worksheet(input)?.scores.final_score;
    let mut read_right = 1.0;
    for (region, &sd) in ANGLED_REGIONS.iter().zip(sd_deg) {
        let Some(angle) = region_angle(*region, input) else {
            continue;
        };
        if !(sd > 0.0 && sd.is_finite()) {
            continue;
        }
        let moved = stretch_mass(*region, angle, sd, |probe| {
            let there = readjust(with_region_angle(*region, input, probe));
            Ok::<_, crate::ErgonomicsError>(
                crate::rula::score_worksheet(&there)?.scores.final_score != grand,
            )
        })?;
        read_right *= (1.0 - moved).clamp(0.0, 1.0);
    }
    Ok((1.0 - read_right).clamp(0.0, 1.0))
}

/// Each angled region's confidence for one side's worksheet: the stated spread from the skeleton's
/// propagated one through `model`, and the band's probability at the worksheet's angle. `None` for
/// a region whose angle was not measured this frame ([`InputSource::Observed`] only) or whose
/// landmarks carry no spread.
pub fn region_confidences(
    skeleton: &Skeleton3,
    side: &SideAssessment,
    model: &ConfidenceModel,
) -> RegionConfidences {
    let mut out = RegionConfidences::default();
    for region in ANGLED_REGIONS {
        if side.source(angle_field(region)) != Some(InputSource::Observed) {
            continue;
        }
        let (Some(angle), Some(propagated)) = (
            region_angle(region, &side.input),
            propagated_sd_rad(skeleton, region, side.side),
        ) else {
            continue;
        };
        let Some(sd_deg) = model.stated_sd_rad(region, propagated).map(f64::to_degrees) else {
            continue;
        };
        if let Some(slot) = out.slot_mut(region) {
            let mass = band_probability(region, &side.input, angle, sd_deg);
            *slot = Some(BandConfidence {
                sd_deg,
                propagated_sd_deg: propagated.to_degrees(),
                probability: model.stated_probability(region, mass),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_band_is_sure_deep_inside_and_a_coin_toss_at_its_edge() {
        let i = RulaInput::neutral();
        // upper arm band 2 is 20°..45°: 32.5° is 2.5 σ from both edges at σ = 5°
        let deep = band_probability(BodyRegion::UpperArm, &i, 32.5, 5.0);
        let expected = normal_cdf(2.5) - normal_cdf(-2.5);
        assert!((deep - expected).abs() < 1e-12, "{deep} vs {expected}");
        // at 45.0° the score is already 3 (band 45..90); half the mass is below the edge
        let edge = band_probability(BodyRegion::UpperArm, &i, 45.0, 5.0);
        let expected = 0.5 - (1.0 - normal_cdf(9.0));
        assert!((edge - expected).abs() < 1e-9, "{edge} vs {expected}");
        // wider spread, less sure
        assert!(band_probability(BodyRegion::UpperArm, &i, 32.5, 10.0) < deep);
        // no spread, sure
        assert_eq!(band_probability(BodyRegion::UpperArm, &i, 44.9, 0.0), 1.0);
    }

    #[test]
    fn a_grand_score_is_misread_only_where_an_edge_that_moves_it_is_near() {
        let same = |i: RulaInput| i;
        let sd = [2.0; 5];
        // every angle at least 2.5 σ inside its band: upper arm 10°, elbow 80°, wrist 5°, neck 15°,
        // trunk extended 10° (scored erect)
        let mut deep = RulaInput::neutral();
        deep.upper_arm_flexion_deg = 10.0;
        deep.wrist_flexion_deg = 5.0;
        deep.neck_flexion_deg = 15.0;
        deep.trunk_flexion_deg = -10.0;
        let inside = grand_misread_probability(&deep, &sd, same).unwrap();
        assert!(inside < 0.05, "{inside}");
        // the neck on its 20° edge, which moves this worksheet's grand score
        let mut edge = deep;
        edge.neck_flexion_deg = 20.0;
        let g = |i: &RulaInput| crate::rula::score_worksheet(i).unwrap().scores.final_score;
        assert_ne!(
            g(&edge),
            g(&with_region_angle(BodyRegion::Neck, &edge, 19.99))
        );
        let on_edge = grand_misread_probability(&edge, &sd, same).unwrap();
        assert!(on_edge > 0.45, "{on_edge}");
        // at least the neck's missing mass, and no more than it with the others' added
        let p_neck = band_probability(BodyRegion::Neck, &edge, 20.0, 2.0);
        assert!(on_edge >= 1.0 - p_neck - 1e-12, "{on_edge} vs {p_neck}");
        assert!(
            on_edge <= 1.0 - p_neck + inside + 1e-12,
            "{on_edge} vs {p_neck}"
        );
        // on the neck's 10° edge the tables saturate (score A 2, score B 1 or 2: grand 2 either
        // way): not a misreading
        let mut saturated = deep;
        saturated.neck_flexion_deg = 10.0;
        assert_eq!(
            g(&saturated),
            g(&with_region_angle(BodyRegion::Neck, &saturated, 9.99))
        );
        let flat = grand_misread_probability(&saturated, &sd, same).unwrap();
        assert!(flat < 0.05, "{flat}");
        // no spread reads right; a narrower one misreads less
        assert_eq!(
            grand_misread_probability(&edge, &[0.0; 5], same).unwrap(),
            0.0
        );
        let mut near = edge;
        near.neck_flexion_deg = 22.0;
        let (wide, narrow) = (
            grand_misread_probability(&near, &sd, same).unwrap(),
            grand_misread_probability(&near, &[1.0; 5], same).unwrap(),
        );
        assert!(narrow < wide && wide < on_edge, "{narrow} {wide} {on_edge}");
    }

    #[test]
    fn a_misreading_counts_on_either_side_of_an_edge_and_follows_what_the_angle_decides() {
        let same = |i: RulaInput| i;
        let g = |i: &RulaInput| crate::rula::score_worksheet(i).unwrap().scores.final_score;
        // the elbow on 100°, which the lower band holds (60..=100 scores 1): with the wrist past
        // 15° the lower arm's score moves score A and the grand score
        let mut elbow = RulaInput::neutral();
        elbow.upper_arm_flexion_deg = 10.0;
        elbow.lower_arm_flexion_deg = 100.0;
        elbow.wrist_flexion_deg = 20.0;
        elbow.trunk_flexion_deg = -10.0;
        assert_ne!(
            g(&elbow),
            g(&with_region_angle(BodyRegion::LowerArm, &elbow, 100.01))
        );
        let p = grand_misread_probability(&elbow, &[2.0; 5], same).unwrap();
        assert!((0.45..0.6).contains(&p), "{p}");
        // a wrist read at exactly 0° (score 1, no width) next to a bent elbow: the wrist's
        // neighbouring band (2) gives the same score A, and nothing is misread
        let mut wrist = RulaInput::neutral();
        wrist.upper_arm_flexion_deg = 10.0;
        wrist.lower_arm_flexion_deg = 50.0;
        wrist.trunk_flexion_deg = -10.0;
        assert_eq!(
            g(&wrist),
            g(&with_region_angle(BodyRegion::Wrist, &wrist, 5.0))
        );
        let p = grand_misread_probability(&wrist, &[2.0; 5], same).unwrap();
        assert!(p < 0.05, "{p}");
        // what follows from the angle is decided again in each stretch: on the neck's 10° edge,
        // where the tables saturate, a load that a neck below 10° would carry (an artificial rule)
        // makes half the mass a misreading
        let mut neck = RulaInput::neutral();
        neck.upper_arm_flexion_deg = 10.0;
        neck.wrist_flexion_deg = 5.0;
        neck.neck_flexion_deg = 10.0;
        neck.trunk_flexion_deg = -10.0;
        let loaded_below_10 = |mut i: RulaInput| {
            if i.neck_flexion_deg < 10.0 {
                i.force_load_score_neck_trunk_legs = 3;
            }
            i
        };
        let held = grand_misread_probability(&neck, &[2.0; 5], same).unwrap();
        let followed = grand_misread_probability(&neck, &[2.0; 5], loaded_below_10).unwrap();
        assert!(held < 0.05 && followed > 0.45, "{followed} vs {held}");
    }

    #[test]
    fn stretches_with_the_same_score_add_up() {
        let i = RulaInput::neutral();
        // upper arm: extension past 20° and flexion 20..45° both score band 2
        let p = band_probability(BodyRegion::UpperArm, &i, -25.0, 20.0);
        let z = |a: f64| normal_cdf((a + 25.0) / 20.0);
        let expected = z(-20.0) + (z(45.0) - z(20.0));
        assert!((p - expected).abs() < 1e-12, "{p} vs {expected}");
        // the lower arm's outside-60..100 band is both ends
        let p = band_probability(BodyRegion::LowerArm, &i, 30.0, 40.0);
        let z = |a: f64| normal_cdf((a - 30.0) / 40.0);
        let expected = z(60.0) + (1.0 - z(100.0));
        assert!((p - expected).abs() < 1e-12, "{p} vs {expected}");
        // the wrist's 0..15 band on both sides of 0 is one stretch
        let p = band_probability(BodyRegion::Wrist, &i, 5.0, 4.0);
        let z = |a: f64| normal_cdf((a - 5.0) / 4.0);
        assert!((p - (z(15.0) - z(-15.0))).abs() < 1e-12);
    }

    #[test]
    fn propagated_spread_follows_the_landmarks_and_their_distance() {
        use ergocell_skeleton::LandmarkEstimate;
        use nalgebra::Point3;
        let place = |sd: f64, arm: f64| {
            let mut s = Skeleton3::empty(0);
            let mut put = |l: Landmark, p: Point3<f64>| {
                s.set(
                    l,
                    Some(LandmarkEstimate {
                        position_m: p,
                        confidence: 1.0,
                        reprojection_error_px: None,
                        views: 2,
                        position_sd_m: Some(sd),
                    }),
                )
                .unwrap();
            };
            put(Landmark::RightShoulder, Point3::new(0.2, 0.0, 1.4));
            put(Landmark::RightElbow, Point3::new(0.2, 0.0, 1.4 - arm));
            put(Landmark::RightWrist, Point3::new(0.2, 0.25, 1.4 - arm));
            s
        };
        let a = propagated_sd_rad(&place(0.01, 0.3), BodyRegion::LowerArm, Side::Right).unwrap();
        // two segments, each sqrt(2)·1 cm over its length
        let expected = ((0.02f64.sqrt() * 0.01 / 0.01f64.sqrt() / 0.3).powi(2)
            + (2f64.sqrt() * 0.01 / 0.25).powi(2))
        .sqrt();
        assert!((a - expected).abs() < 1e-12, "{a} vs {expected}");
        // twice the landmark spread, twice the angle's
        let b = propagated_sd_rad(&place(0.02, 0.3), BodyRegion::LowerArm, Side::Right).unwrap();
        assert!((b - 2.0 * a).abs() < 1e-12);
        // no trunk landmarks: no upper-arm spread; the legs never have one
        assert_eq!(
            propagated_sd_rad(&place(0.01, 0.3), BodyRegion::UpperArm, Side::Right),
            None
        );
        assert_eq!(
            propagated_sd_rad(&place(0.01, 0.3), BodyRegion::Legs, Side::Right),
            None
        );
    }

    #[test]
    fn the_recalibration_interpolates_its_points_and_the_identity_changes_nothing() {
        let m = ConfidenceModel::default();
        let identity = identity_recalibration();
        for p in [0.3, 0.55, 0.9, 0.97, 0.9995] {
            assert!((interpolate(&identity, p) - p).abs() < 1e-12, "{p}");
        }
        let points = [[0.5, 0.6], [0.7, 0.8], [0.9, 0.95]];
        assert!((interpolate(&points, 0.6) - 0.7).abs() < 1e-12);
        assert_eq!(interpolate(&points, 0.2), 0.6);
        assert_eq!(interpolate(&points, 0.99), 0.95);
        assert_eq!(m.stated_probability(BodyRegion::Legs, 0.5), 0.5);
        let mut fitted = m;
        fitted.recalibration[1][1] = [0.55, 0.7];
        fitted.recalibration[1][2] = [0.65, 0.7];
        assert!(fitted.validate().is_ok());
        assert!((fitted.stated_probability(BodyRegion::LowerArm, 0.6) - 0.7).abs() < 1e-12);
        // a falling recalibration would call a surer band less sure: refused
        fitted.recalibration[1][2] = [0.65, 0.6];
        assert!(matches!(
            fitted.validate(),
            Err(crate::ErgonomicsError::BadConfidenceModel {
                region: "lower_arm",
                parameter: "recalibration",
                ..
            })
        ));
    }

    #[test]
    fn the_model_refuses_a_negative_or_nan_parameter() {
        let mut m = ConfidenceModel::default();
        assert!(m.validate().is_ok());
        m.floor_rad[3] = f64::NAN;
        assert!(matches!(
            m.validate(),
            Err(crate::ErgonomicsError::BadConfidenceModel {
                region: "neck",
                parameter: "floor_rad",
                value
            }) if value.is_nan()
        ));
        m = ConfidenceModel::default();
        m.scale[0] = -1.0;
        assert!(m.validate().is_err());
        m = ConfidenceModel::default();
        m.recalibration[2][0][1] = 1.5;
        assert!(m.validate().is_err());
        // the stated spread: the floor alone at no propagated spread; the legs have none
        let m = ConfidenceModel::default();
        assert_eq!(m.stated_sd_rad(BodyRegion::Neck, 0.0), Some(m.floor_rad[3]));
        assert_eq!(m.stated_sd_rad(BodyRegion::Legs, 0.1), None);
    }
}
