//! Nonsmooth (projected) Gauss–Seidel on the dense Delassus matrix (the NSCD local solver, docs/theory.md §5).
//!
//! Sweep j = 1..m: p_j ← proj_[lo_j, hi_j](p_j − r_j / (W_jj + d_j)), r_j = u_j + b_j + d_j p_j the law velocity
//! (docs/theory.md §9), warm-started from the previous step, until the largest update in a sweep,
//! |Δp_j|·(W_jj + d_j) (m/s), is below the tolerance; the law residual is then evaluated on the
//! final p with u = W p + u_free formed afresh. Within the sweeps u is kept up to date by u += Δp_j W_{·j}, only
//! for the impulses that change, so a sweep costs O(m·changed) with W dense (m × m), built once per run.
//! Fast for devices spaced wider than the coupling length ℓ = (EI h²θ²/ρA)^¼ (2–6 sweeps); it stalls for
//! distributed friction, where [`super::interior_point::BandedInteriorPoint`] is the tool.

use super::{InteractionProblem, InteractionSolver, SolverKind, StepReport, StepStatus, StepWork};
use crate::kernels::{axpy, dot};
use friction::law::project;

/// Sweeps between two looks at the contraction of the updates (`stalls`).
pub const STALL_CHECK: usize = 50;

/// The sweeps beyond which Gauss–Seidel counts as stalled: by then it has cost more than ~50 interior-point
/// iterations of the same problem (a sweep over 800 ballast sections ~20 µs, an interior-point iteration ~15 µs),
/// and a step that needs them is one for the interior point. Devices converge in 2–6 sweeps.
pub const STALL_SWEEPS: usize = 1000;

/// Whether the sweeps stall: the largest update fell from `before` to `now` over the last [`STALL_CHECK`] sweeps, a
/// contraction ρ per sweep that needs more than [`STALL_SWEEPS`] in all to reach `tolerance` (or ρ ≥ 1). Ended early
/// (within the iteration cap) the step's status is [`StepStatus::Stalled`], and the run's fallbacks take it.
fn stalls(before: f64, now: f64, tolerance: f64, sweeps: usize) -> bool {
    if !before.is_finite() || now <= tolerance {
        return false;
    }
    let rate = (now / before).powf(1.0 / STALL_CHECK as f64);
    rate >= 1.0 || sweeps as f64 + (tolerance / now).ln() / rate.ln() > STALL_SWEEPS as f64
}

/// Projected Gauss–Seidel with the dense W of the run.
#[derive(Debug, Clone)]
pub struct ProjectedGaussSeidel {
    m: usize,
    /// W row-major, m × m.
    w: Vec<f64>,
    /// Per row j, the columns [first, last) among the fixed interactions outside which |W_ji| ≤ 1e-17·√(W_ii W_jj)
    /// (round-off of W itself): W decays like e^{−|x_i − x_j|/(√2ℓ)}, so for devices a row keeps a handful of
    /// neighbours. The moving interactions' columns (fixed..m) are always taken.
    reach: Vec<(usize, usize)>,
    /// Number of fixed interactions (the moving ones follow).
    fixed: usize,
    /// 1/(W_jj + d_j): the sweep multiplies (the sweep is a chain, each update waiting on the one before).
    inverse_diagonal: Vec<f64>,
    max_sweeps: usize,
    tolerance: f64,
    u: Vec<f64>,
}

impl ProjectedGaussSeidel {
    /// Build W = H M̂⁻¹ Hᵀ (m banded solves) for `problem`.
    pub fn new(problem: &InteractionProblem, tolerance: f64, max_sweeps: usize) -> Self {
        let m = problem.len();
        let rows = problem.interactions.rows();
        let mut w = vec![0.0; m * m];
        let mut column = vec![0.0; problem.matrix.m_hat.order()];
        for (j, row) in rows.iter().enumerate() {
            column.iter_mut().for_each(|c| *c = 0.0);
            row.add_transpose(1.0, &mut column);
            problem.matrix.factor.solve_in_place(&mut column);
            for (i, other) in rows.iter().enumerate() {
                w[i * m + j] = other.dot(&column);
            }
        }
        // Symmetrise the round-off.
        for i in 0..m {
            for j in 0..i {
                let s = 0.5 * (w[i * m + j] + w[j * m + i]);
                w[i * m + j] = s;
                w[j * m + i] = s;
            }
        }
        let fixed = problem.fixed_len();
        let significant = |i: usize, j: usize| w[i * m + j].abs() > 1e-17 * (w[i * m + i] * w[j * m + j]).sqrt();
        let reach = (0..m)
            .map(|j| {
                if j >= fixed {
                    return (0, fixed);
                }
                let first = (0..fixed).find(|&i| significant(j, i)).unwrap_or(j);
                let last = (0..fixed).rfind(|&i| significant(j, i)).map_or(j + 1, |i| i + 1);
                (first.min(j), last.max(j + 1))
            })
            .collect();
        let inverse_diagonal = problem.delassus_diagonal.iter().map(|d| 1.0 / d).collect();
        Self { m, w, reach, fixed, inverse_diagonal, max_sweeps, tolerance, u: vec![0.0; m] }
    }

    /// u = u_free + W p, each entry a dot product of a row of W (symmetric) with p (the fixed columns in reach, then
    /// the moving ones).
    fn refresh_velocities(&mut self, u_free: &[f64], p: &[f64]) {
        let (m, fixed) = (self.m, self.fixed);
        for (j, u) in self.u.iter_mut().enumerate() {
            let (first, last) = self.reach[j];
            *u = u_free[j] + dot(&self.w[j * m + first..j * m + last], &p[first..last]);
            if fixed < m {
                *u += dot(&self.w[j * m + fixed..(j + 1) * m], &p[fixed..]);
            }
        }
    }

    /// The law residual (m/s) of p, on velocities formed afresh.
    fn residual(&mut self, problem: &InteractionProblem, u_free: &[f64], p: &[f64]) -> f64 {
        self.refresh_velocities(u_free, p);
        problem.law_residual(&self.u, p)
    }
}

impl InteractionSolver for ProjectedGaussSeidel {
    fn kind(&self) -> SolverKind {
        SolverKind::Projection
    }

    /// The moving interactions' rows and columns of W from their new responses: W_ij = H_i G_j.
    fn refresh(&mut self, problem: &InteractionProblem) -> crate::Result<()> {
        let (m, rows) = (self.m, problem.interactions.rows());
        for j in self.fixed..m {
            let response = problem.moving_response(j);
            for (i, row) in rows.iter().enumerate() {
                let wij = row.dot(response);
                self.w[i * m + j] = wij;
                self.w[j * m + i] = wij;
            }
            self.inverse_diagonal[j] = 1.0 / problem.delassus_diagonal[j];
        }
        Ok(())
    }

    fn solve(
        &mut self,
        problem: &InteractionProblem,
        _: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        let m = self.m;
        self.refresh_velocities(u_free, p);
        let mut sweeps = 0;
        let mut residual = f64::INFINITY;
        // Fixed friction alone has no drift nor compliance (r = u) and no moving columns: the sweep skips them.
        let (varying, fixed) = (problem.is_varying(), self.fixed);
        let law = &problem.law;
        let mut checkpoint = f64::INFINITY;
        while sweeps < self.max_sweeps {
            sweeps += 1;
            let mut largest: f64 = 0.0;
            for j in 0..m {
                let (first, last) = self.reach[j];
                let r = if varying { law.law_velocity(j, self.u[j], p[j]) } else { self.u[j] };
                let new = project(p[j] - r * self.inverse_diagonal[j], law.lower[j], law.upper[j]);
                let change = new - p[j];
                if change != 0.0 {
                    axpy(change, &self.w[j * m + first..j * m + last], &mut self.u[first..last]);
                    if fixed < m {
                        axpy(change, &self.w[j * m + fixed..(j + 1) * m], &mut self.u[fixed..]);
                    }
                    let diagonal = if varying { problem.delassus_diagonal[j] } else { self.w[j * m + j] };
                    largest = largest.max(change.abs() * diagonal);
                    p[j] = new;
                }
            }
            // The sweep's largest update is the residual met on the way; confirm on the final p and a fresh u.
            if largest <= tolerance {
                residual = self.residual(problem, u_free, p);
                if residual <= tolerance {
                    break;
                }
            }
            if sweeps % STALL_CHECK == 0 {
                if stalls(checkpoint, largest, tolerance, sweeps) {
                    break;
                }
                checkpoint = largest;
            }
        }
        if residual > tolerance {
            residual = self.residual(problem, u_free, p);
        }
        let status = StepStatus::of(residual, tolerance, sweeps, self.max_sweeps);
        Ok(StepReport {
            status,
            iterations: sweeps,
            residual,
            tolerance,
            sections: self.m,
            fallback: None,
            work: StepWork::default(),
        })
    }
}
