//! A continuous posture cost beside RULA: the grand score, and inside it how far each angle lies
//! into its band.
//!
//! RULA's bands are coarse: a trunk bent 22° and one bent 58° both score 3, and a handover that
//! moves an operator from one to the other changes nothing RULA's integers can see. DULA (Yazdani
//! et al., "DULA and DEBA: Differentiable Ergonomic Risk Models for Postural Assessment and
//! Optimization in Ergonomically Intelligent pHRI", IROS 2022) showed that a continuous form of the
//! same method can rank postures inside a band. DULA smooths each band's step into a sigmoid and so
//! agrees with RULA on 99.7 % of postures; this form is built to agree on all of them:
//!
//! - **Per region**, [`RegionCost`]: the region's RULA score (with the worksheet's adjustments) plus
//!   the fraction of the way its angle lies through its band, from the band's neutral end
//!   ([`band_fraction`]), in `[0, 1)`. A neutral band is measured from its neutral point (upper arm
//!   0°, elbow 80°, wrist, neck and trunk 0°) to its edges; an open band (an upper arm raised 90° or
//!   more) to a far end past which the fraction stays just below 1 ([`OPEN_BAND_SPAN_DEG`]). So a
//!   region's cost is never below its score and never reaches the next one: where RULA's region
//!   scores differ, the costs rank the same way.
//! - **Per side**, [`PostureCost::cost`]: RULA's grand score plus the mean of the five angled
//!   regions' fractions (upper arm, lower arm, wrist, neck, trunk), in `[0, 1)`. Where the grand
//!   scores of two postures differ, their costs rank the same way; where they are equal, the
//!   posture further into its bands costs more.
//!
//! It is computed from the same worksheet ([`RulaInput`]) as RULA, so the same angles, adjustments
//! and band edges ([`crate::rula`]'s convention: an edge belongs to the higher band, elbow 60° and
//! 100° to the neutral one). Units: degrees, as the worksheet; the cost is in RULA points.

use crate::rula::{
    lower_arm_score, neck_score, score_worksheet, trunk_score, upper_arm_score, wrist_score,
    RulaInput, LOWER_ARM_EDGES_DEG, NECK_EDGES_DEG, TRUNK_EDGES_DEG, UPPER_ARM_EDGES_DEG,
    WRIST_EDGES_DEG,
};
use crate::ErgonomicsError;

/// Past an open band's edge, the angle at which its fraction reaches (nearly) 1: upper-arm
/// flexion from 90° to 180°, upper-arm extension from 20° to 60°, elbow outside 60–100° to 0° and
/// 180°, wrist from 15° to 90°, neck flexion from 20° to 60°, neck extension from 0° to 40°, trunk
/// flexion from 60° to 120°. These are the joints' usual range of motion; a value past them
/// stays just below the next score.
pub const OPEN_BAND_SPAN_DEG: OpenSpans = OpenSpans {
    upper_arm_flexion: 90.0,
    upper_arm_extension: 40.0,
    elbow_below: 60.0,
    elbow_above: 80.0,
    wrist: 75.0,
    neck_flexion: 40.0,
    neck_extension: 40.0,
    trunk_flexion: 60.0,
};

/// How far past each open band's edge its fraction reaches 1, degrees ([`OPEN_BAND_SPAN_DEG`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenSpans {
    pub upper_arm_flexion: f64,
    pub upper_arm_extension: f64,
    pub elbow_below: f64,
    pub elbow_above: f64,
    pub wrist: f64,
    pub neck_flexion: f64,
    pub neck_extension: f64,
    pub trunk_flexion: f64,
}

/// The largest fraction: a cost never reaches the next score.
const MAX_FRACTION: f64 = 0.999;

/// The elbow's neutral point inside its 60–100° band.
const ELBOW_NEUTRAL_DEG: f64 = 80.0;

/// One region of one side: its RULA score and how far into its band the angle lies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionCost {
    /// RULA's score for the region, with the worksheet's adjustments.
    pub score: u8,
    /// How far through its band the angle lies, from the neutral end, in `[0, 1)`.
    pub fraction: f64,
}

impl RegionCost {
    /// The region's continuous cost: its score plus the fraction.
    pub fn cost(&self) -> f64 {
        f64::from(self.score) + self.fraction
    }
}

/// One side's continuous posture cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PostureCost {
    /// RULA's grand score for the worksheet.
    pub grand_score: u8,
    pub upper_arm: RegionCost,
    pub lower_arm: RegionCost,
    pub wrist: RegionCost,
    pub neck: RegionCost,
    pub trunk: RegionCost,
}

impl PostureCost {
    /// The side's cost: the grand score plus the mean of the five regions' fractions, in
    /// `[grand, grand + 1)`.
    pub fn cost(&self) -> f64 {
        let fractions = [
            self.upper_arm.fraction,
            self.lower_arm.fraction,
            self.wrist.fraction,
            self.neck.fraction,
            self.trunk.fraction,
        ];
        f64::from(self.grand_score) + fractions.iter().sum::<f64>() / fractions.len() as f64
    }
}

/// `x` between `from` (0) and `to` (1), clamped to `[0, MAX_FRACTION]`; a NaN gives 0.
fn through(x: f64, from: f64, to: f64) -> f64 {
    let f = (x - from) / (to - from);
    if f.is_nan() {
        0.0
    } else {
        f.clamp(0.0, MAX_FRACTION)
    }
}

/// Which region a band fraction is asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AngledRegion {
    /// Upper-arm flexion (negative: extension).
    UpperArm,
    /// Elbow flexion.
    LowerArm,
    /// Wrist flexion or extension (only the magnitude counts).
    Wrist,
    /// Neck flexion (negative: extension).
    Neck,
    /// Trunk flexion from vertical (extension: the erect band, as RULA scores it).
    Trunk,
}

/// How far through its RULA band the angle lies, from the band's neutral end, in `[0, 1)`.
/// `seated_well_supported` puts the trunk in its first band whatever its angle (as RULA does).
pub fn band_fraction(region: AngledRegion, angle_deg: f64, seated_well_supported: bool) -> f64 {
    let s = OPEN_BAND_SPAN_DEG;
    match region {
        AngledRegion::UpperArm => {
            let [ext, low, mid, high] = UPPER_ARM_EDGES_DEG;
            let a = angle_deg;
            if a < ext {
                through(-a, -ext, -ext + s.upper_arm_extension)
            } else if a < low {
                // the neutral band, from 0° either way to its edges (−20° and 20°)
                if a < 0.0 {
                    through(-a, 0.0, -ext)
                } else {
                    through(a, 0.0, low)
                }
            } else if a < mid {
                through(a, low, mid)
            } else if a < high {
                through(a, mid, high)
            } else {
                through(a, high, high + s.upper_arm_flexion)
            }
        }
        AngledRegion::LowerArm => {
            let [low, high] = LOWER_ARM_EDGES_DEG;
            let a = angle_deg;
            if a < low {
                through(low - a, 0.0, s.elbow_below)
            } else if a > high {
                through(a, high, high + s.elbow_above)
            } else if a < ELBOW_NEUTRAL_DEG {
                through(ELBOW_NEUTRAL_DEG - a, 0.0, ELBOW_NEUTRAL_DEG - low)
            } else {
                through(a, ELBOW_NEUTRAL_DEG, high)
            }
        }
        AngledRegion::Wrist => {
            let edge = WRIST_EDGES_DEG[1];
            let w = angle_deg.abs();
            if w < edge {
                through(w, 0.0, edge)
            } else {
                through(w, edge, edge + s.wrist)
            }
        }
        AngledRegion::Neck => {
            let [ext, low, high] = NECK_EDGES_DEG;
            let a = angle_deg;
            if a < ext {
                through(-a, -ext, -ext + s.neck_extension)
            } else if a < low {
                through(a, ext, low)
            } else if a < high {
                through(a, low, high)
            } else {
                through(a, high, high + s.neck_flexion)
            }
        }
        AngledRegion::Trunk => {
            let [erect, low, high] = TRUNK_EDGES_DEG;
            let a = angle_deg;
            if seated_well_supported || a <= erect {
                0.0
            } else if a < low {
                through(a, erect, low)
            } else if a < high {
                through(a, low, high)
            } else {
                through(a, high, high + s.trunk_flexion)
            }
        }
    }
}

/// The continuous posture cost of one side's worksheet.
///
/// # Errors
/// As [`score_worksheet`]: a worksheet RULA cannot score (a non-finite angle, a force score out of
/// range).
pub fn posture_cost(i: &RulaInput) -> Result<PostureCost, ErgonomicsError> {
    let grand = score_worksheet(i)?.scores.final_score;
    let region = |score: u8, region: AngledRegion, angle: f64| RegionCost {
        score,
        fraction: band_fraction(region, angle, i.trunk_seated_well_supported),
    };
    Ok(PostureCost {
        grand_score: grand,
        upper_arm: region(
            upper_arm_score(
                i.upper_arm_flexion_deg,
                i.shoulder_raised,
                i.upper_arm_abducted,
                i.arm_supported_or_leaning,
            ),
            AngledRegion::UpperArm,
            i.upper_arm_flexion_deg,
        ),
        lower_arm: region(
            lower_arm_score(
                i.lower_arm_flexion_deg,
                i.lower_arm_across_midline_or_out_to_side,
            ),
            AngledRegion::LowerArm,
            i.lower_arm_flexion_deg,
        ),
        wrist: region(
            wrist_score(i.wrist_flexion_deg, i.wrist_bent_from_midline),
            AngledRegion::Wrist,
            i.wrist_flexion_deg,
        ),
        neck: region(
            neck_score(i.neck_flexion_deg, i.neck_twisted, i.neck_side_bending),
            AngledRegion::Neck,
            i.neck_flexion_deg,
        ),
        trunk: region(
            trunk_score(
                i.trunk_flexion_deg,
                i.trunk_seated_well_supported,
                i.trunk_twisted,
                i.trunk_side_bending,
            ),
            AngledRegion::Trunk,
            i.trunk_flexion_deg,
        ),
    })
}

/// The angles of one side's five angled regions, degrees, as [`RulaInput`] holds them: what a
/// recording keeps of a frame beside its scores.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SideAngles {
    pub upper_arm_flexion_deg: f64,
    pub lower_arm_flexion_deg: f64,
    pub wrist_flexion_deg: f64,
    pub neck_flexion_deg: f64,
    pub trunk_flexion_deg: f64,
}

/// A side's cost from its RULA grand score and its regions' angles, where the worksheet itself is
/// gone (a recording keeps the scores and the angles): the same value as [`PostureCost::cost`] of
/// the worksheet they came from. `None` for a grand score outside 1..=7 or a non-finite angle.
pub fn cost_from_angles(
    grand_score: u8,
    angles: &SideAngles,
    trunk_seated_well_supported: bool,
) -> Option<f64> {
    if !(1..=7).contains(&grand_score) {
        return None;
    }
    let fractions = [
        (AngledRegion::UpperArm, angles.upper_arm_flexion_deg),
        (AngledRegion::LowerArm, angles.lower_arm_flexion_deg),
        (AngledRegion::Wrist, angles.wrist_flexion_deg),
        (AngledRegion::Neck, angles.neck_flexion_deg),
        (AngledRegion::Trunk, angles.trunk_flexion_deg),
    ];
    if fractions.iter().any(|(_, a)| !a.is_finite()) {
        return None;
    }
    let sum: f64 = fractions
        .iter()
        .map(|&(region, a)| band_fraction(region, a, trunk_seated_well_supported))
        .sum();
    Some(f64::from(grand_score) + sum / fractions.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rula::{lower_arm_band, neck_band, trunk_band, upper_arm_band, wrist_band};

    /// What a recording keeps (the grand score and the five angles) gives the worksheet's cost.
    #[test]
    fn the_cost_from_recorded_angles_is_the_worksheets() {
        let mut n = 0;
        for ua in [-30.0, 0.0, 19.9, 20.0, 50.0, 95.0] {
            for el in [30.0, 60.0, 85.0, 120.0] {
                for wr in [-20.0, 0.0, 10.0, 15.0, 40.0] {
                    for (ne, tr) in [(-5.0, 0.0), (8.0, 5.0), (25.0, 30.0), (12.0, 70.0)] {
                        let i = RulaInput {
                            upper_arm_flexion_deg: ua,
                            lower_arm_flexion_deg: el,
                            wrist_flexion_deg: wr,
                            neck_flexion_deg: ne,
                            trunk_flexion_deg: tr,
                            ..RulaInput::neutral()
                        };
                        let c = posture_cost(&i).unwrap();
                        let angles = SideAngles {
                            upper_arm_flexion_deg: ua,
                            lower_arm_flexion_deg: el,
                            wrist_flexion_deg: wr,
                            neck_flexion_deg: ne,
                            trunk_flexion_deg: tr,
                        };
                        let again = cost_from_angles(c.grand_score, &angles, false).unwrap();
                        assert!(
                            (again - c.cost()).abs() < 1e-12,
                            "{i:?}: {again} {}",
                            c.cost()
                        );
                        n += 1;
                    }
                }
            }
        }
        assert_eq!(n, 480);
        let ok = SideAngles {
            upper_arm_flexion_deg: 10.0,
            lower_arm_flexion_deg: 80.0,
            wrist_flexion_deg: 0.0,
            neck_flexion_deg: 5.0,
            trunk_flexion_deg: 0.0,
        };
        assert_eq!(cost_from_angles(0, &ok, false), None);
        assert_eq!(cost_from_angles(8, &ok, false), None);
        let unseen = SideAngles {
            wrist_flexion_deg: f64::NAN,
            ..ok
        };
        assert_eq!(cost_from_angles(3, &unseen, false), None);
    }

    /// Every angle from −90° to 180° in tenths of a degree.
    fn sweep() -> impl Iterator<Item = f64> {
        (-900..=1800).map(|k| f64::from(k) / 10.0)
    }

    /// Each region's cost (band + fraction) ranks every pair of angles as RULA's band does wherever
    /// the bands differ, and never reaches the next score.
    #[test]
    fn a_region_cost_ranks_as_its_rula_band_wherever_the_bands_differ() {
        type Band = fn(f64) -> u8;
        let regions: [(AngledRegion, Band); 5] = [
            (AngledRegion::UpperArm, upper_arm_band),
            (AngledRegion::LowerArm, lower_arm_band),
            (AngledRegion::Wrist, wrist_band),
            (AngledRegion::Neck, neck_band),
            (AngledRegion::Trunk, |a| trunk_band(a, false)),
        ];
        for (region, band) in regions {
            let costs: Vec<(u8, f64)> = sweep()
                .map(|a| {
                    let f = band_fraction(region, a, false);
                    assert!((0.0..1.0).contains(&f), "{region:?} {a}: {f}");
                    (band(a), f64::from(band(a)) + f)
                })
                .collect();
            for &(ba, ca) in &costs {
                for &(bb, cb) in costs.iter().step_by(7) {
                    if ba < bb {
                        assert!(
                            ca < cb,
                            "{region:?}: band {ba} cost {ca} vs band {bb} cost {cb}"
                        );
                    }
                }
            }
        }
    }

    /// The seed paper's complaint about the bands, in numbers: a trunk 2° past the 20° edge and one
    /// 38° past it score the same in RULA, and differ here, the deeper one costing more; within
    /// the neutral band the cost grows with the distance from neutral either way.
    #[test]
    fn two_degrees_and_forty_past_an_edge_differ() {
        let near = band_fraction(AngledRegion::Trunk, 22.0, false);
        let far = band_fraction(AngledRegion::Trunk, 58.0, false);
        assert_eq!(trunk_band(22.0, false), trunk_band(58.0, false));
        assert!((near - 0.05).abs() < 1e-12 && (far - 0.95).abs() < 1e-12);
        for (a, b) in [(5.0, 15.0), (-5.0, -15.0)] {
            assert!(
                band_fraction(AngledRegion::UpperArm, a, false)
                    < band_fraction(AngledRegion::UpperArm, b, false)
            );
        }
        assert!(
            band_fraction(AngledRegion::LowerArm, 85.0, false)
                < band_fraction(AngledRegion::LowerArm, 98.0, false)
        );
        assert_eq!(band_fraction(AngledRegion::Trunk, 40.0, true), 0.0);
        assert_eq!(band_fraction(AngledRegion::Neck, f64::NAN, false), 0.0);
    }

    /// A seeded set of worksheets: wherever two grand scores differ, the costs rank the same way,
    /// and every cost lies in [grand, grand + 1).
    #[test]
    fn the_cost_ranks_worksheets_as_rulas_grand_score_wherever_they_differ() {
        // A small linear congruential generator: the test takes its seed, the same numbers each run.
        let mut state: u64 = 20_261_207;
        let mut next = |lo: f64, hi: f64| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
        };
        let mut costs = Vec::new();
        for _ in 0..600 {
            let mut i = RulaInput::neutral();
            i.upper_arm_flexion_deg = next(-60.0, 180.0);
            i.lower_arm_flexion_deg = next(0.0, 180.0);
            i.wrist_flexion_deg = next(-60.0, 60.0);
            i.neck_flexion_deg = next(-30.0, 60.0);
            i.trunk_flexion_deg = next(-10.0, 110.0);
            i.shoulder_raised = next(0.0, 1.0) < 0.2;
            i.trunk_twisted = next(0.0, 1.0) < 0.2;
            i.legs_supported_and_balanced = next(0.0, 1.0) < 0.8;
            let c = posture_cost(&i).unwrap();
            let cost = c.cost();
            let g = f64::from(c.grand_score);
            assert!(cost >= g && cost < g + 1.0, "{cost} for grand {g}");
            costs.push((c.grand_score, cost));
        }
        let mut differing = 0;
        for &(ga, ca) in &costs {
            for &(gb, cb) in &costs {
                if ga < gb {
                    differing += 1;
                    assert!(ca < cb, "grand {ga} cost {ca} vs grand {gb} cost {cb}");
                }
            }
        }
        // The set covers the scale: many pairs whose grand scores differ.
        assert!(differing > 10_000, "{differing}");
    }
}
