//! Inverse kinematics: damped least squares with joint limits, many iterations and several seeds.
//!
//! `k`'s `JacobianIkSolver` gives up after 10 iterations by default and only clamps to the limits, so
//! it fails from the straight-up pose. Here each seed runs up to `max_iterations` damped-least-squares
//! steps `Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e` (step length capped), projected into the position limits shrunk by
//! `limit_margin_rad`. Seeds are tried in order: the caller's (e.g. the previous via point), the
//! model's mid-range pose, then a deterministic Halton sequence over the limits.
//! A null-space term pulls each solve toward its seed, so the redundant joint does not drift. Among the
//! converged solutions the one closest to the first seed wins (continuity along a path); if none converges the
//! error names the target and the closest pose any seed reached.

use nalgebra::{Isometry3, Matrix6, Vector6};

use crate::model::RobotModel;
use crate::pose::{pose_error, twist_error, PoseSummary};
use crate::RobotError;

/// Tunables of [`solve_ik`].
#[derive(Debug, Clone, PartialEq)]
pub struct IkSettings {
    pub max_iterations: usize,
    pub position_tolerance_m: f64,
    pub orientation_tolerance_rad: f64,
    /// Damping λ of the least-squares step.
    pub damping: f64,
    /// Largest joint step per iteration (rad, Euclidean norm).
    pub max_step_rad: f64,
    /// Solutions stay this far inside every position limit.
    pub limit_margin_rad: f64,
    /// Gain of the null-space pull toward the seed (0 = none).
    pub nullspace_gain: f64,
    /// Number of Halton seeds tried after the caller's seeds and the mid-range pose.
    pub extra_seeds: usize,
}

impl Default for IkSettings {
    fn default() -> Self {
        Self {
            max_iterations: 300,
            position_tolerance_m: 1e-4,
            orientation_tolerance_rad: 1e-3,
            damping: 0.02,
            max_step_rad: 0.3,
            limit_margin_rad: 0.05,
            nullspace_gain: 0.2,
            extra_seeds: 12,
        }
    }
}

/// A converged IK solution.
#[derive(Debug, Clone, PartialEq)]
pub struct IkSolution {
    pub positions_rad: Vec<f64>,
    pub position_error_m: f64,
    pub orientation_error_rad: f64,
    /// Index of the seed that produced it (0 = first caller seed).
    pub seed_index: usize,
    pub iterations: usize,
}

/// Solve `T_base_tcp(q) = T_base_target` within the limits. `seeds` may be empty.
pub fn solve_ik(
    model: &RobotModel,
    T_base_target: &Isometry3<f64>,
    T_flange_tcp: &Isometry3<f64>,
    seeds: &[Vec<f64>],
    settings: &IkSettings,
) -> Result<IkSolution, RobotError> {
    for seed in seeds {
        if seed.len() != model.dof() {
            return Err(RobotError::DofMismatch {
                what: "IK seed".to_owned(),
                expected: model.dof(),
                got: seed.len(),
            });
        }
    }
    let (lower, upper): (Vec<f64>, Vec<f64>) = model
        .joints()
        .iter()
        .map(|j| {
            let m = settings
                .limit_margin_rad
                .min(0.25 * (j.upper_rad - j.lower_rad));
            (j.lower_rad + m, j.upper_rad - m)
        })
        .unzip();
    let mut all_seeds: Vec<Vec<f64>> = seeds.to_vec();
    all_seeds.push(
        lower
            .iter()
            .zip(&upper)
            .map(|(l, u)| 0.5 * (l + u))
            .collect(),
    );
    all_seeds.extend(halton_seeds(&lower, &upper, settings.extra_seeds));
    let reference = all_seeds[0].clone();

    let mut best: Option<IkSolution> = None;
    let mut closest: Option<(f64, Isometry3<f64>, f64, f64)> = None; // (score, pose, dp, dr)
    for (seed_index, seed) in all_seeds.iter().enumerate() {
        let (q, iterations, T_reached) = descend(
            model,
            T_base_target,
            T_flange_tcp,
            seed,
            &lower,
            &upper,
            settings,
        );
        let (dp, dr) = pose_error(&T_reached, T_base_target);
        let score = dp + 0.1 * dr;
        if closest.as_ref().is_none_or(|c| score < c.0) {
            closest = Some((score, T_reached, dp, dr));
        }
        if dp <= settings.position_tolerance_m && dr <= settings.orientation_tolerance_rad {
            let candidate = IkSolution {
                positions_rad: q,
                position_error_m: dp,
                orientation_error_rad: dr,
                seed_index,
                iterations,
            };
            let better = best.as_ref().is_none_or(|b| {
                distance(&candidate.positions_rad, &reference)
                    < distance(&b.positions_rad, &reference)
            });
            if better {
                best = Some(candidate);
            }
            // The caller's first seed converged: keep continuity, stop searching.
            if seed_index == 0 {
                break;
            }
        }
    }
    if let Some(solution) = best {
        return Ok(solution);
    }
    let (_, T_closest, dp, dr) = closest.unwrap_or((
        f64::INFINITY,
        Isometry3::identity(),
        f64::INFINITY,
        f64::INFINITY,
    ));
    Err(RobotError::Unreachable {
        target: Box::new(PoseSummary::new(model.base_link(), T_base_target)),
        closest: Box::new(PoseSummary::new(model.base_link(), &T_closest)),
        position_error_m: dp,
        orientation_error_rad: dr,
    })
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// Damped least squares from one seed; returns (q, iterations used, pose reached).
fn descend(
    model: &RobotModel,
    T_base_target: &Isometry3<f64>,
    T_flange_tcp: &Isometry3<f64>,
    seed: &[f64],
    lower: &[f64],
    upper: &[f64],
    s: &IkSettings,
) -> (Vec<f64>, usize, Isometry3<f64>) {
    let mut q: Vec<f64> = seed
        .iter()
        .zip(lower.iter().zip(upper))
        .map(|(&x, (&l, &u))| {
            if x.is_finite() {
                x.clamp(l, u)
            } else {
                0.5 * (l + u)
            }
        })
        .collect();
    let q_ref = q.clone();
    let lambda2 = s.damping * s.damping;
    for it in 0..s.max_iterations {
        let (T, J) = model.jacobian_unchecked(&q, T_flange_tcp);
        let (dp, dr) = pose_error(&T, T_base_target);
        if dp <= s.position_tolerance_m && dr <= s.orientation_tolerance_rad {
            return (q, it, T);
        }
        let e: Vector6<f64> = twist_error(&T, T_base_target);
        let JJt: Matrix6<f64> = &J * J.transpose() + Matrix6::identity() * lambda2;
        let Some(chol) = JJt.cholesky() else {
            break;
        };
        let mut dq = J.transpose() * chol.solve(&e);
        // Null-space pull toward the seed: keeps the redundant joint near where the path came from. It fades
        // out near convergence (the damped projector leaks a little into the task).
        let fade = ((dp + 0.1 * dr) / 0.01).min(1.0);
        let pinv_J = J.transpose() * chol.solve(&J);
        let pull = nalgebra::DVector::from_iterator(
            q.len(),
            q.iter()
                .zip(&q_ref)
                .map(|(x, r)| fade * s.nullspace_gain * (r - x)),
        );
        let null = nalgebra::DMatrix::identity(q.len(), q.len()) - pinv_J;
        dq += null * pull;
        let norm = dq.norm();
        if norm > s.max_step_rad {
            dq *= s.max_step_rad / norm;
        }
        for (i, qi) in q.iter_mut().enumerate() {
            *qi = (*qi + dq[i]).clamp(lower[i], upper[i]);
        }
    }
    let T_reached = model.fk_flange_unchecked(&q) * T_flange_tcp;
    (q, s.max_iterations, T_reached)
}

/// Deterministic quasi-random seeds inside the limits (Halton sequence, one prime base per joint).
fn halton_seeds(lower: &[f64], upper: &[f64], count: usize) -> Vec<Vec<f64>> {
    const PRIMES: [u32; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    (1..=count)
        .map(|i| {
            lower
                .iter()
                .zip(upper)
                .enumerate()
                .map(|(j, (&l, &u))| {
                    let h = radical_inverse(i as u32, PRIMES[j % PRIMES.len()]);
                    // Stay in the inner 80 % of the range: seeds at the limits converge badly.
                    let mid = 0.5 * (l + u);
                    mid + (h - 0.5) * 0.8 * (u - l)
                })
                .collect()
        })
        .collect()
}

fn radical_inverse(mut i: u32, base: u32) -> f64 {
    let mut result = 0.0;
    let mut f = 1.0 / f64::from(base);
    while i > 0 {
        result += f * f64::from(i % base);
        i /= base;
        f /= f64::from(base);
    }
    result
}
