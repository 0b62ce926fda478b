//! The joint-space trajectory QP, solved with `clarabel`.
//!
//! Clarabel solves: minimise ½ xᵀ P x + qᵀ x subject to A x + s = b, s ∈ K.
//!
//! Model: N knots `t_k = k·dt`; per joint and knot the variables are position `q_k`, velocity `v_k` and
//! acceleration `a_k`; between knots the jerk `j_k = (a_{k+1} − a_k)/dt` is constant, so the trajectory
//! is a cubic per interval and can be re-checked exactly between knots:
//!
//! ```text
//! q_{k+1} = q_k + dt·v_k + dt²·(a_k/3 + a_{k+1}/6)      (zero cone)
//! v_{k+1} = v_k + dt·(a_k + a_{k+1})/2                   (zero cone)
//! q_0 = q_start, v_0 = a_0 = 0, q_{N−1} = q_end, v_{N−1} = a_{N−1} = 0, q_{k_i} = q_via_i
//! q_lo ≤ q_k ≤ q_hi, |v_k| ≤ v_max, |a_k| ≤ a_max           (nonnegative cone)
//! cost = Σ_k ∫ (a(t)² + w·j(t)²) dt over each interval
//! ```
//!
//! The final point is at rest: the KUKA drivers accept a moving end point, so we must not send one.
//! Every row of A (and b) is scaled to unit ∞-norm and P to unit largest entry: unscaled, problems from
//! ~100 knots ended in `InsufficientProgress`. The joints are decoupled, so A and P are block diagonal.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus,
    SupportedConeT, ZeroConeT,
};
use serde::Serialize;

use crate::RobotError;

/// Inputs of the QP. All vectors have one entry per joint.
#[derive(Debug, Clone)]
pub struct QpProblem {
    pub dt_s: f64,
    pub knots: usize,
    pub q_start: Vec<f64>,
    pub q_end: Vec<f64>,
    /// (knot index, positions) the trajectory must pass.
    pub vias: Vec<(usize, Vec<f64>)>,
    pub q_lower: Vec<f64>,
    pub q_upper: Vec<f64>,
    pub v_max: Vec<f64>,
    pub a_max: Vec<f64>,
    pub jerk_weight_s2: f64,
}

/// The solver's outcome. Only [`QpStatus::Solved`] can lead to a locked trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[non_exhaustive]
pub enum QpStatus {
    Solved,
    AlmostSolved,
    PrimalInfeasible,
    DualInfeasible,
    MaxIterations,
    MaxTime,
    NumericalError,
    InsufficientProgress,
    Other,
}

impl From<SolverStatus> for QpStatus {
    fn from(s: SolverStatus) -> Self {
        match s {
            SolverStatus::Solved => Self::Solved,
            SolverStatus::AlmostSolved => Self::AlmostSolved,
            SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
                Self::PrimalInfeasible
            }
            SolverStatus::DualInfeasible | SolverStatus::AlmostDualInfeasible => {
                Self::DualInfeasible
            }
            SolverStatus::MaxIterations => Self::MaxIterations,
            SolverStatus::MaxTime => Self::MaxTime,
            SolverStatus::NumericalError => Self::NumericalError,
            SolverStatus::InsufficientProgress => Self::InsufficientProgress,
            _ => Self::Other,
        }
    }
}

impl std::fmt::Display for QpStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{self:?}")
    }
}

/// The solver's answer: samples indexed `[knot][joint]`.
#[derive(Debug, Clone, Serialize)]
pub struct QpSolution {
    pub status: QpStatus,
    pub iterations: u32,
    /// As measured by clarabel.
    pub solve_time_s: f64,
    pub variables: usize,
    pub equality_rows: usize,
    pub inequality_rows: usize,
    pub q: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
    pub a: Vec<Vec<f64>>,
}

struct Rows {
    i: Vec<usize>,
    j: Vec<usize>,
    v: Vec<f64>,
    b: Vec<f64>,
}

impl Rows {
    fn new() -> Self {
        Self {
            i: Vec::new(),
            j: Vec::new(),
            v: Vec::new(),
            b: Vec::new(),
        }
    }
    /// Push one row `Σ coef·x = rhs` (or ≤ rhs), scaled to unit ∞-norm.
    fn push(&mut self, offset: usize, entries: &[(usize, f64)], rhs: f64) {
        let row = offset + self.b.len();
        let scale = entries.iter().fold(0.0_f64, |m, (_, c)| m.max(c.abs()));
        let scale = if scale > 0.0 { 1.0 / scale } else { 1.0 };
        for &(col, c) in entries {
            self.i.push(row);
            self.j.push(col);
            self.v.push(c * scale);
        }
        self.b.push(rhs * scale);
    }
}

/// Solve the QP. `Err` only for malformed input; an unsolved QP is an `Ok` with a non-`Solved` status.
pub fn solve(p: &QpProblem) -> Result<QpSolution, RobotError> {
    let n_j = p.q_start.len();
    let n = p.knots;
    for (what, len) in [
        ("q_end", p.q_end.len()),
        ("q_lower", p.q_lower.len()),
        ("q_upper", p.q_upper.len()),
        ("v_max", p.v_max.len()),
        ("a_max", p.a_max.len()),
    ] {
        if len != n_j {
            return Err(RobotError::DofMismatch {
                what: format!("QP {what}"),
                expected: n_j,
                got: len,
            });
        }
    }
    if n < 4 || !(p.dt_s.is_finite() && p.dt_s > 0.0) {
        return Err(RobotError::Qp {
            reason: format!("need ≥ 4 knots and dt > 0 (got {n} knots, dt {} s)", p.dt_s),
        });
    }
    for (k, q) in &p.vias {
        if *k == 0 || *k >= n - 1 || q.len() != n_j {
            return Err(RobotError::Qp {
                reason: format!(
                    "via at knot {k} must be strictly inside 1..{} with {n_j} joints",
                    n - 1
                ),
            });
        }
    }
    let dt = p.dt_s;
    let n_var = 3 * n * n_j;
    // Knot-major ordering (all joints, q v a, of knot k together) keeps the KKT matrix banded.
    let idx = |j: usize, kind: usize, k: usize| k * 3 * n_j + kind * n_j + j;

    // P: ∫ a² over an interval with linear a = dt/3 (a_k² + a_k a_{k+1} + a_{k+1}²);
    // ∫ w j² = w (a_{k+1} − a_k)² / dt. Written as ½ xᵀ P x, so P = 2 × the quadratic form (upper triangle).
    let (mut pi, mut pj, mut pv) = (Vec::new(), Vec::new(), Vec::new());
    let w = p.jerk_weight_s2 / dt;
    let diag = 2.0 * (dt / 3.0 + w);
    let off = 2.0 * (dt / 6.0 - w);
    let scale_p = 1.0 / (2.0 * diag).max(off.abs());
    for j in 0..n_j {
        for k in 0..n - 1 {
            let (a0, a1) = (idx(j, 2, k), idx(j, 2, k + 1));
            pi.extend([a0, a1, a0]);
            pj.extend([a0, a1, a1]);
            pv.extend([diag * scale_p, diag * scale_p, off * scale_p]);
        }
    }
    let P = CscMatrix::new_from_triplets(n_var, n_var, pi, pj, pv);
    let q_lin = vec![0.0; n_var];

    let mut eq = Rows::new();
    for j in 0..n_j {
        for k in 0..n - 1 {
            eq.push(
                0,
                &[
                    (idx(j, 0, k + 1), 1.0),
                    (idx(j, 0, k), -1.0),
                    (idx(j, 1, k), -dt),
                    (idx(j, 2, k), -dt * dt / 3.0),
                    (idx(j, 2, k + 1), -dt * dt / 6.0),
                ],
                0.0,
            );
            eq.push(
                0,
                &[
                    (idx(j, 1, k + 1), 1.0),
                    (idx(j, 1, k), -1.0),
                    (idx(j, 2, k), -dt / 2.0),
                    (idx(j, 2, k + 1), -dt / 2.0),
                ],
                0.0,
            );
        }
        eq.push(0, &[(idx(j, 0, 0), 1.0)], p.q_start[j]);
        eq.push(0, &[(idx(j, 1, 0), 1.0)], 0.0);
        eq.push(0, &[(idx(j, 2, 0), 1.0)], 0.0);
        eq.push(0, &[(idx(j, 0, n - 1), 1.0)], p.q_end[j]);
        eq.push(0, &[(idx(j, 1, n - 1), 1.0)], 0.0);
        eq.push(0, &[(idx(j, 2, n - 1), 1.0)], 0.0);
        for (k, q) in &p.vias {
            eq.push(0, &[(idx(j, 0, *k), 1.0)], q[j]);
        }
    }
    let n_eq = eq.b.len();
    let mut ineq = Rows::new();
    for j in 0..n_j {
        for k in 0..n {
            ineq.push(n_eq, &[(idx(j, 0, k), 1.0)], p.q_upper[j]);
            ineq.push(n_eq, &[(idx(j, 0, k), -1.0)], -p.q_lower[j]);
            ineq.push(n_eq, &[(idx(j, 1, k), 1.0)], p.v_max[j]);
            ineq.push(n_eq, &[(idx(j, 1, k), -1.0)], p.v_max[j]);
            ineq.push(n_eq, &[(idx(j, 2, k), 1.0)], p.a_max[j]);
            ineq.push(n_eq, &[(idx(j, 2, k), -1.0)], p.a_max[j]);
        }
    }
    let n_ineq = ineq.b.len();
    let mut ai = eq.i;
    ai.extend(ineq.i);
    let mut aj = eq.j;
    aj.extend(ineq.j);
    let mut av = eq.v;
    av.extend(ineq.v);
    let mut b = eq.b;
    b.extend(ineq.b);
    let A = CscMatrix::new_from_triplets(n_eq + n_ineq, n_var, ai, aj, av);
    let cones: [SupportedConeT<f64>; 2] = [ZeroConeT(n_eq), NonnegativeConeT(n_ineq)];

    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(200)
        .build()
        .map_err(|e| RobotError::Qp {
            reason: e.to_string(),
        })?;
    let mut solver =
        DefaultSolver::new(&P, &q_lin, &A, &b, &cones, settings).map_err(|e| RobotError::Qp {
            reason: e.to_string(),
        })?;
    solver.solve();
    let sol = &solver.solution;
    let x = &sol.x;
    let sample = |kind: usize| -> Vec<Vec<f64>> {
        (0..n)
            .map(|k| {
                (0..n_j)
                    .map(|j| x.get(idx(j, kind, k)).copied().unwrap_or(f64::NAN))
                    .collect()
            })
            .collect()
    };
    Ok(QpSolution {
        status: sol.status.into(),
        iterations: sol.iterations,
        solve_time_s: sol.solve_time,
        variables: n_var,
        equality_rows: n_eq,
        inequality_rows: n_ineq,
        q: sample(0),
        v: sample(1),
        a: sample(2),
    })
}
