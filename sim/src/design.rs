//! Handover points designed for the people a class serves, on the twin's body model.
//!
//! A class's handover point was once set by hand; here it is chosen. For each candidate point (the
//! caller's grid, station frame) every person of the class reaches it with the twin's reach solver
//! ([`solve_reach`]: the same posture the twin's sessions hold the part in), looks at it
//! ([`look_at`]), and the ground truth's RULA worksheet of that posture is scored with the
//! continuous posture cost ([`posture_cost`]): as the handover is repeated all shift (RULA's muscle
//! use wherever the hold leaves the relaxed posture, as the cell's assessor scores a posture
//! repeated more than four times a minute: what [`rank`] orders by), and as its first repetitions
//! score, before any repetition is seen (both are required by [`shortfalls`]). How often the cell
//! would misread the hold's grand score is measured beside the cost. The candidate's cost is the
//! mean over the people
//! (and over the head's habitual flexion, a three-point Gauss–Hermite rule over the twin's
//! [`Habits::rest_neck_flexion_rad`]). [`rank`] orders the candidates by that expected cost;
//! [`choose`] takes the cheapest one the caller's validator accepts — the robot's own kinematics
//! and QP, which this crate does not know.
//!
//! The people come from the caller (ANSUR II's fitting half, [`Operator::measured`]); the figures
//! reported on the other half are [`population`]'s. No randomness: the same people and candidates
//! give the same numbers. Units: metres, the cost in RULA points.

use ergocell_anthropometry::ansur::Sex;
use ergocell_ergonomics::confidence::grand_misread_probability;
use ergocell_ergonomics::posture_cost::posture_cost;
use ergocell_ergonomics::rula::{neck_band, trunk_band, upper_arm_band, RulaInput};
use ergocell_ergonomics::{AssessmentConfig, RulaAssessor};
use ergocell_skeleton::Skeleton3;
use nalgebra::Point3;
use serde::Serialize;

use crate::body::{Operator, Posture};
use crate::experiments::{truth_config, up};
use crate::reach::{look_at, solve_reach, ReachConfig};
use crate::session::Habits;
use crate::SimError;

/// Nodes and weights of the three-point Gauss–Hermite rule for a normal variable, in σ: the exact
/// mean of any polynomial of degree ≤ 5 in it.
const GAUSS_HERMITE_3: [(f64, f64); 3] = [
    (0.0, 2.0 / 3.0),
    (-1.732_050_807_568_877_2, 1.0 / 6.0),
    (1.732_050_807_568_877_2, 1.0 / 6.0),
];

/// What the cost of a point assumes besides the person: where the part really arrives, the
/// person's habits, the reach solver, and how well the cell reads the posture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyModel {
    /// σ per axis of where the part really arrives around the point, metres (see [`hold_cost`]);
    /// 0 evaluates the point alone.
    pub placement_sigma_m: f64,
    pub habits: Habits,
    pub reach: ReachConfig,
    /// The cell's reading error of each angled region's angle, RMS degrees, in
    /// [`ergocell_ergonomics::confidence::ANGLED_REGIONS`] order: what [`HoldCost::misread`]
    /// assumes.
    pub read_sd_deg: [f64; 5],
}

/// One person holding the part at one point: as the handover is repeated all shift, and as its
/// first repetitions score, before there is any repetition to see.
///
/// Repeated, RULA's muscle use applies to a group whose posture the hold takes out of the relaxed
/// one, as the cell's assessor decides it ([`ergocell_ergonomics::assess::MuscleUseTracker`]): group
/// A when the upper arm leaves its 20° band, group B when the neck (either way) or the trunk passes
/// 20°. A hold that keeps them relaxed is not loading them, however often it is repeated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HoldCost {
    /// Expected posture cost over the head's habitual flexion and where the part arrives (RULA
    /// points), repeated.
    pub cost: f64,
    /// Expected RULA grand score over the same, repeated.
    pub grand_score: f64,
    /// The highest grand score at any node of the rules, repeated: where the part may arrive and
    /// how the head may habitually sit (a score the expectation averages away).
    pub worst_grand_score: f64,
    /// The same three for the first repetitions (no muscle use).
    pub first_cost: f64,
    pub first_grand_score: f64,
    pub first_worst_grand_score: f64,
    /// The probability that the cell reads another grand score than the truth's, repeated,
    /// expected like the cost ([`grand_misread_probability`] with [`BodyModel::read_sd_deg`]): how
    /// hard the hold is to measure. A point whose angles sit on band edges that move the grand
    /// score makes the cell's readings disagree with the truth however good the posture.
    pub misread: f64,
    /// How far the hand ends from the point, metres (the reach solver's miss).
    pub miss_m: f64,
}

impl HoldCost {
    /// Nothing accumulated yet, with the reach's miss.
    fn zero(miss_m: f64) -> Self {
        Self {
            cost: 0.0,
            grand_score: 0.0,
            worst_grand_score: 0.0,
            first_cost: 0.0,
            first_grand_score: 0.0,
            first_worst_grand_score: 0.0,
            misread: 0.0,
            miss_m,
        }
    }

    /// Adds `other` with weight `w` to the expectations and keeps the worst scores and miss.
    fn add(&mut self, w: f64, other: &Self) {
        self.cost += w * other.cost;
        self.grand_score += w * other.grand_score;
        self.worst_grand_score = self.worst_grand_score.max(other.worst_grand_score);
        self.first_cost += w * other.first_cost;
        self.first_grand_score += w * other.first_grand_score;
        self.first_worst_grand_score = self
            .first_worst_grand_score
            .max(other.first_worst_grand_score);
        self.misread += w * other.misread;
        self.miss_m = self.miss_m.max(other.miss_m);
    }
}

/// The twin's body model of the hold: what it costs `op` to hold the part at `target_m` (station
/// frame: the operator stands at the origin facing +x), with the model's habits, expected over
/// where the part really arrives: the twin scatters each cycle's point by
/// [`BodyModel::placement_sigma_m`] in each axis ([`crate::SessionScript::target_sigma_m`]), and a
/// point chosen on a band's edge without it would put half the cycles past the edge. Stroud's
/// degree-3 rule for a normal vector (the six points ±√3σ along each axis, equal weights) gives
/// that expectation; a σ of 0 evaluates the point alone.
///
/// # Errors
/// A non-finite target, or a posture the assessor cannot score.
pub fn hold_cost(
    op: &Operator,
    target_m: &Point3<f64>,
    model: &BodyModel,
) -> Result<HoldCost, SimError> {
    let placement_sigma_m = model.placement_sigma_m;
    if !(placement_sigma_m.is_finite() && placement_sigma_m >= 0.0) {
        return Err(SimError::BadParameter {
            name: "placement_sigma_m",
            value: placement_sigma_m,
            why: "must be finite and >= 0",
        });
    }
    if placement_sigma_m == 0.0 {
        return hold_cost_at(op, target_m, model);
    }
    let r = 3.0_f64.sqrt() * placement_sigma_m;
    let mut out = HoldCost::zero(0.0);
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let mut at = *target_m;
            at[axis] += sign * r;
            out.add(1.0 / 6.0, &hold_cost_at(op, &at, model)?);
        }
    }
    Ok(out)
}

fn hold_cost_at(
    op: &Operator,
    target_m: &Point3<f64>,
    model: &BodyModel,
) -> Result<HoldCost, SimError> {
    let (habits, reach) = (&model.habits, &model.reach);
    let mut rest = Posture {
        trunk_flexion_rad: habits.trunk_flexion_rad.0,
        neck_flexion_rad: habits.rest_neck_flexion_rad.0,
        ..Posture::default()
    };
    rest.left_arm.wrist_flexion_rad = habits.wrist_flexion_rad.0;
    rest.right_arm.wrist_flexion_rad = habits.wrist_flexion_rad.0;
    // The neck does not move the hand: one reach serves every habitual head flexion.
    let solved = solve_reach(op, &rest, target_m, reach)?;
    let config = truth_config(&AssessmentConfig::new(up()?));
    let (mean, sigma) = habits.rest_neck_flexion_rad;
    let mut out = HoldCost::zero(solved.miss_m);
    for (z, w) in GAUSS_HERMITE_3 {
        let mut posture = solved.posture;
        posture.neck_flexion_rad = mean + z * sigma;
        look_at(op, &mut posture, target_m, reach);
        let skeleton = Skeleton3::from_points(0, &op.landmarks(&posture))?;
        let assessment = RulaAssessor::new(config)?.assess(&skeleton)?;
        let Some(side) = assessment.headline() else {
            return Err(SimError::BadParameter {
                name: "target",
                value: target_m.coords.norm(),
                why: "the holding posture could not be scored",
            });
        };
        // The handover is repeated all shift, more than four times a minute: RULA's muscle use
        // where the hold leaves the relaxed posture, which one frame cannot show and the twin's
        // assessor adds once it has seen the repetitions.
        let repeated = repeated_hold(side.input);
        let (again, first) = (posture_cost(&repeated)?, posture_cost(&side.input)?);
        let (again_grand, first_grand) =
            (f64::from(again.grand_score), f64::from(first.grand_score));
        let node = HoldCost {
            cost: again.cost(),
            grand_score: again_grand,
            worst_grand_score: again_grand,
            first_cost: first.cost(),
            first_grand_score: first_grand,
            first_worst_grand_score: first_grand,
            // Muscle use held as the truth has it: the cell's tracker decides it over seconds,
            // and an excursion must last 0.8 s and a return 1 s to count
            // (`MuscleUseConfig`), so a reading's noise across a relaxed limit does not move it.
            misread: grand_misread_probability(&repeated, &model.read_sd_deg, |i| i)?,
            miss_m: solved.miss_m,
        };
        out.add(w, &node);
    }
    Ok(out)
}

/// The worksheet of a hold repeated more than four times a minute: RULA's muscle use for each
/// group the hold takes out of the relaxed posture, as the cell's assessor decides it (group A: the
/// upper arm out of its 20° band; group B: the neck, either way, or the trunk past 20°).
fn repeated_hold(i: RulaInput) -> RulaInput {
    RulaInput {
        muscle_use_arm_wrist: upper_arm_band(i.upper_arm_flexion_deg) != 1,
        muscle_use_neck_trunk_legs: neck_band(i.neck_flexion_deg.abs()) > 2
            || trunk_band(i.trunk_flexion_deg, i.trunk_seated_well_supported) > 2,
        ..i
    }
}

/// What a class's point must do for every stature of its class (operators of Drillis & Contini's
/// proportions, the body model of [`hold_cost`], and each corner of the habits a session may draw:
/// see [`habit_corners`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Requirements {
    /// The unadapted cell's single point: the class's point must lower the posture cost below it
    /// by at least `margin` and never raise the expected RULA grand score, both repeated and as the
    /// first repetitions score (so also any mix of the two, as a session has). `None`: no
    /// comparison.
    pub before: Option<[f64; 3]>,
    pub margin: f64,
    /// The highest RULA grand score any stature may hold the part at, at every node of
    /// [`hold_cost`]'s rules, as the first repetitions score
    /// ([`HoldCost::first_worst_grand_score`]): not only on average.
    pub grand_ceiling: f64,
}

/// The habits a requirement is checked with: the model's own and the four corners of the trunk's
/// lean and the wrists' flexion at ±1.99σ. The twin draws each session's habits within ±2σ
/// ([`crate::SessionScript`]), and each seed is judged alone: a point that beats the single point
/// only on average habits loses to it in some sessions. (The head's flexion is already expected
/// over in [`hold_cost`].)
pub fn habit_corners(h: &Habits) -> [Habits; 5] {
    // Just inside ±2σ: the default habits' −2σ is exactly 0° for the trunk and the wrists, RULA's
    // band edges, where a corner's band would come down to rounding.
    const K: f64 = 1.99;
    let at = |(m, s): (f64, f64), k: f64| (m + k * s, s);
    let corner = |t: f64, w: f64| Habits {
        trunk_flexion_rad: at(h.trunk_flexion_rad, t),
        wrist_flexion_rad: at(h.wrist_flexion_rad, w),
        ..*h
    };
    [
        *h,
        corner(-K, -K),
        corner(-K, K),
        corner(K, -K),
        corner(K, K),
    ]
}

/// Why `point` fails `req`, or `None` when it meets it at every stature of `statures_m` and every
/// one of [`habit_corners`]. The first failure found is the reason (statures in order, the model's
/// own habits first).
///
/// # Errors
/// As [`hold_cost`]; a stature outside 0.5–2.5 m.
pub fn shortfalls(
    point: [f64; 3],
    req: &Requirements,
    statures_m: &[f64],
    model: &BodyModel,
) -> Result<Option<String>, SimError> {
    for &h in statures_m {
        let op = Operator::new(h)?;
        for (corner, habits) in habit_corners(&model.habits).into_iter().enumerate() {
            let model = BodyModel { habits, ..*model };
            let habits_text = if corner == 0 {
                String::new()
            } else {
                format!(
                    " (trunk lean {:.1}°, wrists {:.1}°)",
                    habits.trunk_flexion_rad.0.to_degrees(),
                    habits.wrist_flexion_rad.0.to_degrees()
                )
            };
            let after = hold_cost(&op, &point.into(), &model)?;
            // At most the ceiling at every node before repetitions add muscle use, and against the
            // single point lower by the margin and no higher in RULA, repeated and first.
            if after.first_worst_grand_score > req.grand_ceiling + 1e-9 {
                return Ok(Some(format!(
                    "{h:.2} m{habits_text}: RULA up to {:.0} above {:.0}",
                    after.first_worst_grand_score, req.grand_ceiling
                )));
            }
            let Some(before) = req.before else {
                continue;
            };
            let was = hold_cost(&op, &before.into(), &model)?;
            for (how, cost, grand, cost_was, grand_was) in [
                (
                    "repeated",
                    after.cost,
                    after.grand_score,
                    was.cost,
                    was.grand_score,
                ),
                (
                    "first",
                    after.first_cost,
                    after.first_grand_score,
                    was.first_cost,
                    was.first_grand_score,
                ),
            ] {
                if cost > cost_was - req.margin {
                    return Ok(Some(format!(
                        "{h:.2} m{habits_text}: posture cost ({how}) {cost:.3} not below \
                         {cost_was:.3} − {}",
                        req.margin
                    )));
                } else if grand > grand_was + 1e-9 {
                    return Ok(Some(format!(
                        "{h:.2} m{habits_text}: RULA ({how}) {grand:.2} above {grand_was:.2} before"
                    )));
                }
            }
        }
    }
    Ok(None)
}

/// One candidate handover point and what it costs the class's people.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CandidateCost {
    /// Station frame: forward, lateral, height, metres.
    pub station_m: [f64; 3],
    /// Mean posture cost over the people, repeated ([`HoldCost::cost`]): what ranks candidates.
    pub mean_cost: f64,
    /// Mean RULA grand score over the people, the same way.
    pub mean_grand_score: f64,
    /// The two as the first repetitions score.
    pub mean_first_cost: f64,
    pub mean_first_grand_score: f64,
    /// Mean probability that the cell misreads the grand score ([`HoldCost::misread`]).
    pub mean_misread: f64,
    /// The largest reach miss over the people, metres (a point someone cannot reach costs them
    /// the posture of their best try).
    pub worst_miss_m: f64,
}

/// The costs of every candidate for `people`, cheapest first (ties: the earlier candidate).
///
/// # Errors
/// As [`hold_cost`]; an empty set of people or candidates.
pub fn rank(
    people: &[Operator],
    candidates: &[[f64; 3]],
    model: &BodyModel,
) -> Result<Vec<CandidateCost>, SimError> {
    if people.is_empty() || candidates.is_empty() {
        return Err(SimError::BadParameter {
            name: if people.is_empty() {
                "people"
            } else {
                "candidates"
            },
            value: 0.0,
            why: "a design needs at least one person and one candidate point",
        });
    }
    let one = |c: [f64; 3]| -> Result<CandidateCost, SimError> {
        let point = Point3::from(c);
        let mut sum = HoldCost::zero(0.0);
        for op in people {
            sum.add(1.0, &hold_cost(op, &point, model)?);
        }
        let n = people.len() as f64;
        Ok(CandidateCost {
            station_m: c,
            mean_cost: sum.cost / n,
            mean_grand_score: sum.grand_score / n,
            mean_first_cost: sum.first_cost / n,
            mean_first_grand_score: sum.first_grand_score / n,
            mean_misread: sum.misread / n,
            worst_miss_m: sum.miss_m,
        })
    };
    // Each candidate is independent: split them over the cores (the result does not depend on
    // how, each is summed over the people in the same order).
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let chunk = candidates.len().div_ceil(threads);
    let parts: Vec<Result<Vec<CandidateCost>, SimError>> = std::thread::scope(|s| {
        let handles: Vec<_> = candidates
            .chunks(chunk)
            .map(|part| s.spawn(move || part.iter().map(|&c| one(c)).collect()))
            .collect();
        handles
            .into_iter()
            .map(|h| {
                h.join().unwrap_or(Err(SimError::BadParameter {
                    name: "candidates",
                    value: 0.0,
                    why: "a design thread panicked",
                }))
            })
            .collect()
    });
    let mut out = Vec::with_capacity(candidates.len());
    for p in parts {
        out.extend(p?);
    }
    out.sort_by(|a, b| a.mean_cost.total_cmp(&b.mean_cost));
    Ok(out)
}

/// Coarse to fine over a band: [`rank`] on the grid of `2·step_m`, then on the grid of `step_m`
/// around the `keep` cheapest of those that `admit` accepts (each one's eight neighbours inside the
/// ranges: refining around a point the caller will not take is wasted), every candidate evaluated
/// once; all of them, cheapest first. About a third of the work of the fine
/// grid over the whole band; a minimum sharper than the coarse grid sees can be missed.
///
/// # Errors
/// As [`rank`].
#[allow(clippy::too_many_arguments)]
pub fn search(
    people: &[Operator],
    forward_m: [f64; 2],
    height_m: [f64; 2],
    lateral_m: f64,
    step_m: f64,
    keep: usize,
    admit: impl Fn(&CandidateCost) -> bool,
    model: &BodyModel,
) -> Result<Vec<CandidateCost>, SimError> {
    let coarse = grid(forward_m, height_m, lateral_m, 2.0 * step_m);
    let mut ranked = rank(people, &coarse, model)?;
    let fine = grid(forward_m, height_m, lateral_m, step_m);
    let near = |a: &[f64; 3], b: &[f64; 3]| {
        (a[0] - b[0]).abs() <= step_m * 1.001 && (a[2] - b[2]).abs() <= step_m * 1.001
    };
    let seen = |p: &[f64; 3]| coarse.iter().any(|c| c == p);
    let around: Vec<[f64; 3]> = fine
        .into_iter()
        .filter(|p| {
            !seen(p)
                && ranked
                    .iter()
                    .filter(|c| admit(c))
                    .take(keep)
                    .any(|c| near(&c.station_m, p))
        })
        .collect();
    if !around.is_empty() {
        ranked.extend(rank(people, &around, model)?);
        ranked.sort_by(|a, b| a.mean_cost.total_cmp(&b.mean_cost));
    }
    Ok(ranked)
}

/// The design of one class: the cheapest candidate the validator accepts, and why the cheaper ones
/// were refused.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Choice {
    pub chosen: Option<CandidateCost>,
    /// Cheaper candidates the validator refused, with its reason, cheapest first.
    pub refused: Vec<(CandidateCost, String)>,
}

/// Walks `ranked` cheapest first and returns the first candidate `validate` accepts (`Ok(None)`);
/// `Ok(Some(reason))` refuses one. At most `max_refusals` are tried before giving up.
///
/// # Errors
/// The validator's own error (an input it cannot judge) stops the walk.
pub fn choose<E>(
    ranked: &[CandidateCost],
    max_refusals: usize,
    mut validate: impl FnMut([f64; 3]) -> Result<Option<String>, E>,
) -> Result<Choice, E> {
    let mut refused = Vec::new();
    for c in ranked {
        match validate(c.station_m)? {
            None => {
                return Ok(Choice {
                    chosen: Some(*c),
                    refused,
                })
            }
            Some(why) => {
                refused.push((*c, why));
                if refused.len() >= max_refusals {
                    break;
                }
            }
        }
    }
    Ok(Choice {
        chosen: None,
        refused,
    })
}

/// The grid of candidate points: the multiples of `step_m` inside `forward_m` and `height_m`
/// (round numbers a reviewer can read, never past an edge), at one lateral offset. Empty when a
/// range holds no multiple or the step is not positive.
pub fn grid(forward_m: [f64; 2], height_m: [f64; 2], lateral_m: f64, step_m: f64) -> Vec<[f64; 3]> {
    let axis = |[lo, hi]: [f64; 2]| -> Vec<f64> {
        if !(step_m > 0.0 && lo.is_finite() && hi.is_finite() && lo <= hi) {
            return Vec::new();
        }
        let (first, last) = ((lo / step_m).ceil() as i64, (hi / step_m).floor() as i64);
        (first..=last)
            .map(|i| (i as f64 * step_m * 1e6).round() / 1e6)
            .filter(|x| (lo..=hi).contains(x))
            .collect()
    };
    let (f, h) = (axis(forward_m), axis(height_m));
    f.iter()
        .flat_map(|&x| h.iter().map(move |&z| [x, lateral_m, z]))
        .collect()
}

/// Statures from `lo_m` up to (not including) `hi_m`, every `step_m`, rounded to the millimetre.
pub fn statures(lo_m: f64, hi_m: f64, step_m: f64) -> Vec<f64> {
    if !(step_m > 0.0 && lo_m.is_finite() && hi_m.is_finite()) {
        return Vec::new();
    }
    let n = ((hi_m - lo_m) / step_m - 1e-9).ceil().max(0.0) as usize;
    (0..n)
        .map(|i| ((lo_m + step_m * i as f64) * 1e3).round() / 1e3)
        .collect()
}

/// The posture costs of a population, one group apart.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PopulationCost {
    pub people: usize,
    pub mean: f64,
    /// The 95th percentile (nearest rank).
    pub p95: f64,
}

/// Mean and 95th percentile of each sex's costs; `None` for a sex with nobody.
pub fn population(costs: &[(Sex, f64)]) -> [Option<PopulationCost>; 2] {
    [Sex::Female, Sex::Male].map(|sex| {
        let mut v: Vec<f64> = costs
            .iter()
            .filter(|(s, _)| *s == sex)
            .map(|&(_, c)| c)
            .collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let rank = ((0.95 * v.len() as f64).ceil() as usize).clamp(1, v.len());
        Some(PopulationCost {
            people: v.len(),
            mean: v.iter().sum::<f64>() / v.len() as f64,
            p95: v[rank - 1],
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn op(h: f64) -> Operator {
        Operator::new(h).unwrap()
    }

    fn model(placement_sigma_m: f64) -> BodyModel {
        BodyModel {
            placement_sigma_m,
            habits: Habits::default(),
            reach: ReachConfig::default(),
            read_sd_deg: [2.0; 5],
        }
    }

    #[test]
    fn a_point_far_below_the_hand_costs_more_than_one_at_elbow_height() {
        let o = op(1.75);
        let elbow = hold_cost(&o, &Point3::new(0.40, -0.10, 1.08), &model(0.0)).unwrap();
        let low = hold_cost(&o, &Point3::new(0.40, -0.10, 0.75), &model(0.0)).unwrap();
        let scattered = hold_cost(&o, &Point3::new(0.40, -0.10, 0.75), &model(0.01)).unwrap();
        assert!(
            (scattered.cost - low.cost).abs() < 0.5,
            "{scattered:?} vs {low:?}"
        );
        assert!(hold_cost(&o, &Point3::new(0.4, 0.0, 1.0), &model(-0.01)).is_err());
        assert!(elbow.miss_m < 0.01, "reached: {elbow:?}");
        assert!(
            low.cost > elbow.cost + 0.2,
            "bending to 0.75 m must cost: {low:?} vs {elbow:?}"
        );
    }

    #[test]
    fn the_misreading_is_a_probability_that_needs_a_reading_error() {
        let at = Point3::new(0.40, -0.10, 1.08);
        let mut perfect = model(0.01);
        perfect.read_sd_deg = [0.0; 5];
        let exact = hold_cost(&op(1.75), &at, &perfect).unwrap();
        assert_eq!(exact.misread, 0.0);
        let (mut narrow, mut wide) = (model(0.01), model(0.01));
        narrow.read_sd_deg = [1.0; 5];
        wide.read_sd_deg = [4.0; 5];
        let mut widest = 0.0_f64;
        for h in [1.55, 1.65, 1.75, 1.85, 1.95] {
            let n = hold_cost(&op(h), &at, &narrow).unwrap().misread;
            let w = hold_cost(&op(h), &at, &wide).unwrap().misread;
            assert!(
                (0.0..=1.0).contains(&n) && (0.0..=1.0).contains(&w),
                "{n} {w}"
            );
            // a wider reading error misreads at least as often
            assert!(n <= w + 1e-12, "{h} m: {n} > {w}");
            widest = widest.max(w);
        }
        // somewhere in five statures an angle lies within a few degrees of an edge that matters
        assert!(widest > 0.01, "{widest}");
        // the candidate's figure is the mean over its people
        let people = [op(1.60), op(1.90)];
        let ranked = rank(&people, &[[0.40, -0.10, 1.08]], &wide).unwrap();
        let mean = people
            .iter()
            .map(|o| hold_cost(o, &at, &wide).unwrap().misread)
            .sum::<f64>()
            / 2.0;
        assert!((ranked[0].mean_misread - mean).abs() < 1e-12);
    }

    #[test]
    fn the_repeated_hold_never_scores_below_its_first_repetitions() {
        for (h, z) in [(1.55, 0.95), (1.75, 1.08), (1.95, 1.25)] {
            let c = hold_cost(&op(h), &Point3::new(0.40, -0.10, z), &model(0.01)).unwrap();
            assert!(
                c.cost >= c.first_cost && c.grand_score >= c.first_grand_score,
                "{c:?}"
            );
            assert!(c.first_worst_grand_score >= c.first_grand_score, "{c:?}");
        }
    }

    #[test]
    fn shortfalls_refuse_the_single_point_itself_and_a_score_above_the_ceiling() {
        let p = [0.40, -0.10, 1.08];
        let statures = [1.70, 1.75];
        let short = |req: Requirements| shortfalls(p, &req, &statures, &model(0.0)).unwrap();
        let against_itself = Requirements {
            before: Some(p),
            margin: 0.02,
            grand_ceiling: 7.0,
        };
        assert!(short(against_itself).is_some_and(|why| why.contains("not below")));
        let low_ceiling = Requirements {
            before: None,
            margin: 0.0,
            grand_ceiling: 1.0,
        };
        assert!(short(low_ceiling).is_some_and(|why| why.contains("RULA up to")));
        let anything = Requirements {
            before: None,
            margin: 0.0,
            grand_ceiling: 7.0,
        };
        assert_eq!(short(anything), None);
    }

    #[test]
    fn habit_corners_hold_the_model_first_then_trunk_and_wrists_at_two_sigma() {
        let h = Habits::default();
        let corners = habit_corners(&h);
        assert_eq!(corners[0], h);
        let (t, w) = (h.trunk_flexion_rad, h.wrist_flexion_rad);
        let mut seen = Vec::new();
        for c in &corners[1..] {
            // the head's habit and every spread as the model has them
            assert_eq!(c.rest_neck_flexion_rad, h.rest_neck_flexion_rad);
            assert_eq!((c.trunk_flexion_rad.1, c.wrist_flexion_rad.1), (t.1, w.1));
            let kt = ((c.trunk_flexion_rad.0 - t.0) / t.1).round() as i32;
            let kw = ((c.wrist_flexion_rad.0 - w.0) / w.1).round() as i32;
            for (x, (m, sd)) in [(c.trunk_flexion_rad.0, t), (c.wrist_flexion_rad.0, w)] {
                assert!((((x - m) / sd).abs() - 1.99).abs() < 1e-9, "{x} {m} {sd}");
            }
            seen.push((kt, kw));
        }
        seen.sort_unstable();
        assert_eq!(seen, vec![(-2, -2), (-2, 2), (2, -2), (2, 2)]);
        // never exactly on the 0° edges the default habits' −2σ would reach
        assert!(corners[1..]
            .iter()
            .all(|c| c.trunk_flexion_rad.0 > 0.0 && c.wrist_flexion_rad.0 > 0.0));
    }

    #[test]
    fn shortfalls_hold_equal_as_not_worse_and_name_the_first_failure() {
        let p = [0.41, -0.10, 1.055];
        let against_itself = |margin: f64| Requirements {
            before: Some(p),
            margin,
            grand_ceiling: 7.0,
        };
        let statures = [1.82, 1.68];
        // equal at every stature and corner is not worse
        assert_eq!(
            shortfalls(p, &against_itself(0.0), &statures, &model(0.01)).unwrap(),
            None
        );
        // any margin refuses it: at the first stature given, on the model's own habits first
        let why = shortfalls(p, &against_itself(0.001), &statures, &model(0.01))
            .unwrap()
            .unwrap();
        assert!(why.starts_with("1.82 m: posture cost (repeated)"), "{why}");
    }

    #[test]
    fn shortfalls_compare_rula_with_the_single_point_and_need_one_to_compare() {
        let bent = [0.40, -0.10, 0.75];
        let comfy = [0.40, -0.10, 1.08];
        let statures = [1.75];
        // a point where the operator bends scores a higher RULA than the comfortable one: refused
        // on RULA once the cost is let through (a margin no cost can miss)
        let rula_only = Requirements {
            before: Some(comfy),
            margin: -100.0,
            grand_ceiling: 7.0,
        };
        let why = shortfalls(bent, &rula_only, &statures, &model(0.0))
            .unwrap()
            .expect("a higher RULA than before is refused");
        assert!(why.contains("RULA (repeated)"), "{why}");
        // the comfortable point against the bent one: lower in cost and RULA, both ways
        let against_bent = Requirements {
            before: Some(bent),
            margin: 0.02,
            grand_ceiling: 7.0,
        };
        assert_eq!(
            shortfalls(comfy, &against_bent, &statures, &model(0.0)).unwrap(),
            None
        );
        // no single point to compare with: only the ceiling applies
        let alone = Requirements {
            before: None,
            margin: 100.0,
            grand_ceiling: 7.0,
        };
        assert_eq!(
            shortfalls(bent, &alone, &statures, &model(0.0)).unwrap(),
            None
        );
    }

    #[test]
    fn rank_puts_the_cheapest_first_and_choose_skips_refusals() {
        let people = [op(1.60), op(1.75)];
        let candidates = [
            [0.40, -0.10, 0.70],
            [0.40, -0.10, 1.00],
            [0.40, -0.10, 1.40],
        ];
        let ranked = rank(&people, &candidates, &model(0.0)).unwrap();
        assert_eq!(ranked[0].station_m, candidates[1]);
        assert!(ranked.windows(2).all(|w| w[0].mean_cost <= w[1].mean_cost));
        let choice = choose::<()>(&ranked, 5, |p| {
            Ok((p == candidates[1]).then(|| "refused".to_owned()))
        })
        .unwrap();
        assert_eq!(choice.refused.len(), 1);
        assert_eq!(
            choice.chosen.map(|c| c.station_m),
            Some(ranked[1].station_m)
        );
        let none = choose::<()>(&ranked, 2, |_| Ok(Some("no".to_owned()))).unwrap();
        assert_eq!((none.chosen, none.refused.len()), (None, 2));
        assert!(rank(&[], &candidates, &model(0.0)).is_err());
    }

    #[test]
    fn search_refines_around_the_cheapest_coarse_points() {
        let people = [op(1.75)];
        let all = rank(
            &people,
            &grid([0.30, 0.40], [1.00, 1.10], -0.1, 0.025),
            &model(0.0),
        )
        .unwrap();
        let found = search(
            &people,
            [0.30, 0.40],
            [1.00, 1.10],
            -0.1,
            0.025,
            3,
            |_| true,
            &model(0.0),
        )
        .unwrap();
        // Fewer evaluations than the whole fine grid, each point once, cheapest first.
        assert!(found.len() < all.len());
        let mut points: Vec<[f64; 3]> = found.iter().map(|c| c.station_m).collect();
        points.sort_by(|a, b| a.partial_cmp(b).unwrap());
        points.dedup();
        assert_eq!(points.len(), found.len());
        assert!(found.windows(2).all(|w| w[0].mean_cost <= w[1].mean_cost));
        // Every fine point next to one of the three cheapest coarse points was evaluated (a
        // sharper minimum elsewhere can be missed: coarse to fine is a heuristic, and says so).
        let coarse = rank(
            &people,
            &grid([0.30, 0.40], [1.00, 1.10], -0.1, 0.05),
            &model(0.0),
        )
        .unwrap();
        for c in coarse.iter().take(3) {
            for p in grid([0.30, 0.40], [1.00, 1.10], -0.1, 0.025) {
                if (p[0] - c.station_m[0]).abs() <= 0.0251
                    && (p[2] - c.station_m[2]).abs() <= 0.0251
                {
                    assert!(points.contains(&p), "{p:?} next to {c:?}");
                }
            }
        }
    }

    #[test]
    fn grid_holds_the_round_points_inside_the_ranges() {
        let g = grid([0.295, 0.32], [0.9999, 1.0151], -0.1, 0.005);
        let f: Vec<f64> = g.iter().map(|p| p[0]).step_by(4).collect();
        assert_eq!(f, vec![0.295, 0.30, 0.305, 0.31, 0.315, 0.32]);
        let z: Vec<f64> = g.iter().take(4).map(|p| p[2]).collect();
        assert_eq!(z, vec![1.0, 1.005, 1.01, 1.015]);
        assert!(g.iter().all(|p| p[1] == -0.1));
        assert!(grid([0.3, 0.2], [1.0, 1.1], 0.0, 0.01).is_empty());
        assert!(grid([0.2, 0.3], [1.0, 1.1], 0.0, 0.0).is_empty());
    }

    #[test]
    fn statures_stop_before_the_upper_bound() {
        assert_eq!(statures(1.50, 1.53, 0.01), vec![1.50, 1.51, 1.52]);
        assert_eq!(statures(1.82, 1.845, 0.01), vec![1.82, 1.83, 1.84]);
        assert!(statures(1.8, 1.7, 0.01).is_empty());
        assert!(statures(1.7, 1.8, 0.0).is_empty());
    }

    #[test]
    fn population_splits_by_sex_with_nearest_rank_p95() {
        let mut costs: Vec<(Sex, f64)> = (1..=20).map(|i| (Sex::Female, f64::from(i))).collect();
        costs.push((Sex::Male, 3.0));
        let [f, m] = population(&costs);
        let f = f.unwrap();
        assert_eq!((f.people, f.mean, f.p95), (20, 10.5, 19.0));
        assert_eq!(m.unwrap().p95, 3.0);
        assert!(population(&[])[0].is_none());
    }
}
