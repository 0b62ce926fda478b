//! A small Levenberg–Marquardt solver for block-sparse least squares (Marquardt 1963, the damping
//! `JᵀJ + λ diag(JᵀJ)`), with Jacobians by central finite differences.
//!
//! Calibration residuals come in blocks (one view of the board by one camera) that each depend on a
//! few parameters (that camera's intrinsics and pose, that frame's board pose), so each block's
//! Jacobian is differenced over its own parameters only and accumulated straight into the dense
//! normal equations (a hundred or so unknowns: a dense Cholesky is faster than anything sparse).

use nalgebra::{DMatrix, DVector};

/// A least-squares problem `min Σ_b ‖r_b(x)‖²` made of residual blocks.
pub trait BlockProblem {
    /// Number of residual blocks.
    fn blocks(&self) -> usize;
    /// The parameters block `b` depends on (indices into `x`).
    fn block_params(&self, b: usize) -> &[usize];
    /// Writes block `b`'s residuals at `x` into `out` (cleared first).
    fn block_residuals(&self, b: usize, x: &[f64], out: &mut Vec<f64>);
}

/// How a solve ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LmStatus {
    /// The relative cost decrease or the step fell below tolerance.
    Converged,
    /// The iteration limit was reached (the estimate is still the best seen).
    MaxIterations,
    /// No step reduced the cost even with heavy damping (a minimum, to numerical precision).
    Stalled,
}

/// The outcome of a solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LmReport {
    pub status: LmStatus,
    pub iterations: usize,
    /// Sum of squared residuals before and after.
    pub initial_cost: f64,
    pub final_cost: f64,
}

fn total_cost(problem: &dyn BlockProblem, x: &[f64], buf: &mut Vec<f64>) -> f64 {
    let mut cost = 0.0;
    for b in 0..problem.blocks() {
        problem.block_residuals(b, x, buf);
        cost += buf.iter().map(|r| r * r).sum::<f64>();
    }
    if cost.is_finite() {
        cost
    } else {
        f64::INFINITY
    }
}

/// Minimises the problem from `x`, leaving parameters with `fixed[i] == true` unchanged.
pub fn solve(
    problem: &dyn BlockProblem,
    x: &mut [f64],
    fixed: &[bool],
    max_iterations: usize,
) -> LmReport {
    let n = x.len();
    let mut buf = Vec::new();
    let mut plus = Vec::new();
    let mut minus = Vec::new();
    let mut cost = total_cost(problem, x, &mut buf);
    let initial_cost = cost;
    let mut lambda = 1e-3;
    let mut status = LmStatus::MaxIterations;
    let mut iterations = 0;
    let mut xt = x.to_vec();
    while iterations < max_iterations {
        iterations += 1;
        let mut jtj = DMatrix::<f64>::zeros(n, n);
        let mut jtr = DVector::<f64>::zeros(n);
        let mut jac: Vec<Vec<f64>> = Vec::new();
        for b in 0..problem.blocks() {
            let params = problem.block_params(b);
            problem.block_residuals(b, x, &mut buf);
            jac.clear();
            for &p in params {
                if fixed[p] {
                    jac.push(Vec::new());
                    continue;
                }
                let h = 1e-6 * x[p].abs().max(1e-2);
                xt[p] = x[p] + h;
                problem.block_residuals(b, &xt, &mut plus);
                xt[p] = x[p] - h;
                problem.block_residuals(b, &xt, &mut minus);
                xt[p] = x[p];
                jac.push(
                    plus.iter()
                        .zip(&minus)
                        .map(|(a, m)| (a - m) / (2.0 * h))
                        .collect(),
                );
            }
            for (ia, &pa) in params.iter().enumerate() {
                if jac[ia].is_empty() {
                    continue;
                }
                jtr[pa] += jac[ia].iter().zip(&buf).map(|(j, r)| j * r).sum::<f64>();
                for (ib, &pb) in params.iter().enumerate() {
                    if jac[ib].is_empty() {
                        continue;
                    }
                    jtj[(pa, pb)] += jac[ia]
                        .iter()
                        .zip(&jac[ib])
                        .map(|(a, c)| a * c)
                        .sum::<f64>();
                }
            }
        }
        let mut improved = false;
        while lambda < 1e16 {
            let mut a = jtj.clone();
            for i in 0..n {
                if fixed[i] || a[(i, i)] == 0.0 {
                    a[(i, i)] = 1.0;
                } else {
                    a[(i, i)] *= 1.0 + lambda;
                }
            }
            let Some(chol) = a.cholesky() else {
                lambda *= 10.0;
                continue;
            };
            let delta = chol.solve(&(-&jtr));
            for i in 0..n {
                xt[i] = if fixed[i] { x[i] } else { x[i] + delta[i] };
            }
            let new_cost = total_cost(problem, &xt, &mut buf);
            if new_cost < cost {
                let decrease = (cost - new_cost) / cost.max(1e-300);
                let step = delta.norm() / (x.iter().map(|v| v * v).sum::<f64>().sqrt() + 1e-12);
                x.copy_from_slice(&xt);
                cost = new_cost;
                lambda = (lambda / 10.0).max(1e-12);
                improved = true;
                if decrease < 1e-12 || step < 1e-12 {
                    status = LmStatus::Converged;
                }
                break;
            }
            lambda *= 10.0;
        }
        xt.copy_from_slice(x);
        if !improved {
            status = LmStatus::Stalled;
            break;
        }
        if status == LmStatus::Converged {
            break;
        }
    }
    LmReport {
        status,
        iterations,
        initial_cost,
        final_cost: cost,
    }
}
