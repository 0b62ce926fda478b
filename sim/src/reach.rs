//! Task-driven postures: the reaching posture is *solved*, not scripted.
//!
//! Given a target in the world (the handover point), [`solve_reach`] finds the working arm's joint
//! angles and the trunk flexion that put the grasp point (palm centre) on the target while staying as
//! comfortable as possible. It minimises, by Levenberg–Marquardt on finite-difference Jacobians,
//!
//! `‖w_reach·(grasp(q) − target)‖² + Σ_i c_i (q_i − q_i^rest)²`
//!
//! over `q` = (shoulder flexion, abduction, humeral rotation, elbow flexion, wrist flexion, trunk
//! flexion), each clamped to its joint range ([`ReachConfig`]). The comfort terms are what people
//! trade against each other: bending the trunk costs more than raising the upper arm, which costs more
//! than bending the elbow; the elbow prefers ~80° (inside RULA's 60–100° band) and the wrist neutral.
//! So a target the arm reaches comfortably is reached with the arm; one that is too low makes the
//! trunk bend (the arm alone cannot get there), and one that is too high raises the upper arm above
//! the shoulder. The reach term's weight (`w_reach` = 1000 per metre) makes a 1 cm miss cost more
//! than any comfort term, so a reachable target is reached (tested: within 1 cm).
//!
//! The head then looks at the hand: the eyes take up to [`ReachConfig::eye_down_rad`] of downward
//! gaze (and [`ReachConfig::eye_up_rad`] upward) on their own, the neck the rest; looking down or
//! ahead the head never flexes less than the base posture's habitual flexion.

use nalgebra::{DMatrix, DVector, Point3};

use crate::body::{Operator, Posture};
use crate::SimError;

/// Weights, rest values and joint ranges of the reach solver. Radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReachConfig {
    /// Weight of the reach error, per metre (default 1000).
    pub reach_weight_per_m: f64,
    /// Comfort weights `c_i` in the order shoulder flexion, abduction, humeral rotation, elbow,
    /// wrist, trunk flexion (default 1.0, 2.0, 0.3, 0.3, 1.5, 20.0: the trunk bends only when the arm
    /// cannot reach comfortably).
    pub comfort_weights: [f64; 6],
    /// Rest values `q_i^rest`, same order (default 0, 0, 0, 80°, 0, 0).
    pub rest_rad: [f64; 6],
    /// Lower joint limits, same order (default −50°, −40°, −60°, 0°, −60°, −10°).
    pub lower_rad: [f64; 6],
    /// Upper joint limits, same order (default 180°, 120°, 90°, 150°, 60°, 90°).
    pub upper_rad: [f64; 6],
    /// Downward gaze (from horizontal) the eyes take without moving the head (default 40°: the
    /// preferred viewing zone for near work reaches 15–45° below horizontal, Grandjean).
    pub eye_down_rad: f64,
    /// Upward gaze the eyes take without moving the head (default 10°).
    pub eye_up_rad: f64,
    /// Sideways gaze the eyes take without turning the head (default 20°).
    pub eye_side_rad: f64,
    /// Levenberg–Marquardt iterations per start (default 200).
    pub max_iterations: usize,
}

impl Default for ReachConfig {
    fn default() -> Self {
        let d = f64::to_radians;
        Self {
            reach_weight_per_m: 1000.0,
            comfort_weights: [1.0, 2.0, 0.3, 0.3, 1.5, 20.0],
            rest_rad: [0.0, 0.0, 0.0, d(80.0), 0.0, 0.0],
            lower_rad: [d(-50.0), d(-40.0), d(-60.0), 0.0, d(-60.0), d(-10.0)],
            upper_rad: [d(180.0), d(120.0), d(90.0), d(150.0), d(60.0), d(90.0)],
            eye_down_rad: d(40.0),
            eye_up_rad: d(10.0),
            eye_side_rad: d(20.0),
            max_iterations: 200,
        }
    }
}

/// The solved reaching posture and how well it reaches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReachSolution {
    pub posture: Posture,
    /// Distance from the grasp point to the target, metres.
    pub miss_m: f64,
    /// The comfort part of the cost (dimensionless).
    pub comfort_cost: f64,
}

fn apply(base: &Posture, right_handed: bool, q: &[f64; 6]) -> Posture {
    let mut p = *base;
    let arm = p.working_arm_mut(right_handed);
    arm.flexion_rad = q[0];
    arm.abduction_rad = q[1];
    arm.humeral_rotation_rad = q[2];
    arm.elbow_flexion_rad = q[3];
    arm.wrist_flexion_rad = q[4];
    p.trunk_flexion_rad = q[5];
    p
}

fn residuals(
    op: &Operator,
    base: &Posture,
    target: &Point3<f64>,
    cfg: &ReachConfig,
    q: &[f64; 6],
) -> DVector<f64> {
    let g = op.grasp_point(&apply(base, op.right_handed, q));
    let e = (g - target) * cfg.reach_weight_per_m;
    let mut r = DVector::zeros(9);
    r[0] = e.x;
    r[1] = e.y;
    r[2] = e.z;
    for i in 0..6 {
        r[3 + i] = cfg.comfort_weights[i].sqrt() * (q[i] - cfg.rest_rad[i]);
    }
    r
}

fn clamp(q: &mut [f64; 6], cfg: &ReachConfig) {
    for i in 0..6 {
        q[i] = q[i].clamp(cfg.lower_rad[i], cfg.upper_rad[i]);
    }
}

fn levenberg_marquardt(
    op: &Operator,
    base: &Posture,
    target: &Point3<f64>,
    cfg: &ReachConfig,
    start: [f64; 6],
) -> ([f64; 6], f64) {
    let mut q = start;
    clamp(&mut q, cfg);
    let mut r = residuals(op, base, target, cfg, &q);
    let mut cost = r.norm_squared();
    let mut lambda = 1e-2;
    let h = 1e-6;
    for _ in 0..cfg.max_iterations {
        let mut j = DMatrix::zeros(9, 6);
        for c in 0..6 {
            let (mut qp, mut qm) = (q, q);
            qp[c] += h;
            qm[c] -= h;
            let d = (residuals(op, base, target, cfg, &qp) - residuals(op, base, target, cfg, &qm))
                / (2.0 * h);
            j.set_column(c, &d);
        }
        let jtj = j.transpose() * &j;
        let g = j.transpose() * &r;
        let mut improved = false;
        for _ in 0..10 {
            let mut a = jtj.clone();
            for d in 0..6 {
                a[(d, d)] += lambda * (1.0 + jtj[(d, d)]);
            }
            let Some(step) = a.lu().solve(&(-&g)) else {
                lambda *= 10.0;
                continue;
            };
            let mut qn = q;
            for i in 0..6 {
                qn[i] += step[i];
            }
            clamp(&mut qn, cfg);
            let rn = residuals(op, base, target, cfg, &qn);
            let cn = rn.norm_squared();
            if cn < cost {
                let gain = cost - cn;
                q = qn;
                r = rn;
                cost = cn;
                lambda = (lambda * 0.3).max(1e-9);
                improved = gain > 1e-12 * cost.max(1.0);
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    (q, cost)
}

/// Solves the posture that reaches `target` (world frame) with the operator's working hand from the
/// standing posture `base` (its position, heading, legs and other arm are kept), and turns the head to
/// look at the hand. Errors on a non-finite target; an unreachable target is not an error: the
/// solution reports how far it misses.
pub fn solve_reach(
    op: &Operator,
    base: &Posture,
    target: &Point3<f64>,
    cfg: &ReachConfig,
) -> Result<ReachSolution, SimError> {
    if !(target.x.is_finite() && target.y.is_finite() && target.z.is_finite()) {
        return Err(SimError::BadParameter {
            name: "target",
            value: target.x + target.y + target.z,
            why: "not finite",
        });
    }
    let d = f64::to_radians;
    let starts = [
        [d(20.0), d(5.0), 0.0, d(80.0), 0.0, 0.0],
        [d(60.0), d(10.0), 0.0, d(40.0), 0.0, d(10.0)],
        [d(120.0), d(10.0), 0.0, d(20.0), 0.0, 0.0],
        [d(40.0), 0.0, 0.0, d(20.0), 0.0, d(40.0)],
    ];
    let mut best: Option<([f64; 6], f64)> = None;
    for s in starts {
        let (q, c) = levenberg_marquardt(op, base, target, cfg, s);
        if best.is_none_or(|(_, bc)| c < bc) {
            best = Some((q, c));
        }
    }
    let (q, _) = best.unwrap_or((starts[0], f64::INFINITY));
    let mut posture = apply(base, op.right_handed, &q);
    look_at(op, &mut posture, target, cfg);
    let miss_m = (op.grasp_point(&posture) - target).norm();
    let comfort_cost = (0..6)
        .map(|i| cfg.comfort_weights[i] * (q[i] - cfg.rest_rad[i]).powi(2))
        .sum();
    Ok(ReachSolution {
        posture,
        miss_m,
        comfort_cost,
    })
}

/// Sets neck flexion and yaw so the eyes look at `target`, the eyes taking the first part of the gaze.
pub fn look_at(op: &Operator, posture: &mut Posture, target: &Point3<f64>, cfg: &ReachConfig) {
    let habitual_neck = posture.neck_flexion_rad;
    posture.neck_flexion_rad = 0.0;
    posture.neck_yaw_rad = 0.0;
    let p = op.landmarks(posture);
    let eye = Point3::from(
        (p[ergocell_skeleton::Landmark::LeftEye.index()].coords
            + p[ergocell_skeleton::Landmark::RightEye.index()].coords)
            * 0.5,
    );
    let v = target - eye;
    // Direction in the body's heading frame.
    let (s, c) = posture.heading_rad.sin_cos();
    let fwd = v.x * c + v.y * s;
    let left = -v.x * s + v.y * c;
    let horizontal = fwd.hypot(left).max(1e-6);
    let depression = (-v.z).atan2(horizontal);
    let head_pitch = if depression > cfg.eye_down_rad {
        depression - cfg.eye_down_rad
    } else if depression < -cfg.eye_up_rad {
        depression + cfg.eye_up_rad
    } else {
        0.0
    };
    // Sideways angle of the line of sight (in 3D, so a target straight below is not "to the side").
    let bearing = (left / v.norm().max(1e-9)).clamp(-1.0, 1.0).asin();
    let yaw = if bearing.abs() > cfg.eye_side_rad {
        bearing - cfg.eye_side_rad * bearing.signum()
    } else {
        0.0
    };
    // Looking down or ahead the head keeps at least its habitual flexion; looking up it extends.
    let neck = head_pitch - posture.trunk_flexion_rad;
    let neck = if head_pitch < 0.0 {
        neck
    } else {
        neck.max(habitual_neck)
    };
    posture.neck_flexion_rad = neck.clamp(d(-40.0), d(60.0));
    posture.neck_yaw_rad = yaw.clamp(d(-70.0), d(70.0));
}

fn d(x: f64) -> f64 {
    x.to_radians()
}

/// The longest reach of the working hand's grasp point from the shoulder, metres (arm straight).
pub fn arm_reach_m(op: &Operator) -> f64 {
    let b = op.body();
    b.upper_arm_m + b.forearm_m + 0.5 * 0.45 * b.hand_m
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_skeleton::Landmark;

    #[test]
    fn reachable_targets_are_reached_within_a_centimetre() {
        for (h, target) in [
            (1.75, Point3::new(0.41, -0.10, 1.055)),
            (1.55, Point3::new(0.38, -0.10, 0.97)),
            (1.95, Point3::new(0.45, -0.10, 1.13)),
            (1.75, Point3::new(0.30, -0.25, 1.30)),
            (1.75, Point3::new(0.35, -0.05, 0.80)),
        ] {
            let op = Operator::new(h).unwrap();
            let sol =
                solve_reach(&op, &Posture::default(), &target, &ReachConfig::default()).unwrap();
            assert!(
                sol.miss_m < 0.01,
                "{h} m to {target:?}: missed by {} m",
                sol.miss_m
            );
        }
    }

    #[test]
    fn a_low_target_bends_the_trunk_and_a_high_one_raises_the_arm() {
        let op = Operator::new(1.75).unwrap();
        let cfg = ReachConfig::default();
        let base = Posture::default();
        let comfy = solve_reach(&op, &base, &Point3::new(0.41, -0.10, 1.055), &cfg).unwrap();
        let low = solve_reach(&op, &base, &Point3::new(0.45, -0.10, 0.70), &cfg).unwrap();
        let high = solve_reach(&op, &base, &Point3::new(0.30, -0.20, 1.80), &cfg).unwrap();
        assert!(comfy.posture.trunk_flexion_rad < 10f64.to_radians());
        assert!(comfy.posture.right_arm.flexion_rad < 45f64.to_radians());
        assert!(
            low.posture.trunk_flexion_rad > 20f64.to_radians(),
            "{:?}",
            low.posture
        );
        assert!(high.posture.right_arm.flexion_rad > 90f64.to_radians());
        assert!(low.miss_m < 0.01 && high.miss_m < 0.01);
        // The hand above the shoulder.
        let p = op.landmarks(&high.posture);
        assert!(p[Landmark::RightWrist.index()].z > p[Landmark::RightShoulder.index()].z);
    }

    #[test]
    fn unreachable_targets_report_the_miss_and_non_finite_ones_error() {
        let op = Operator::new(1.6).unwrap();
        let far = solve_reach(
            &op,
            &Posture::default(),
            &Point3::new(2.0, 0.0, 1.0),
            &ReachConfig::default(),
        )
        .unwrap();
        assert!(far.miss_m > 0.5);
        assert!(solve_reach(
            &op,
            &Posture::default(),
            &Point3::new(f64::NAN, 0.0, 1.0),
            &ReachConfig::default()
        )
        .is_err());
        assert!(arm_reach_m(&op) > 0.5);
    }
}
