//! Nonsmooth (projected) Gauss–Seidel on the dense Delassus matrix (the NSCD local solver, MODEL.md §5).
//!
//! Sweep j = 1..m: p_j ← proj_[−a_j, a_j](p_j − (W p + u_free)_j / W_jj), warm-started from the previous step,
//! until the largest update in a sweep, |Δp_j|·W_jj (m/s), is below the tolerance; the law residual is then
//! evaluated on the final p. Each sweep costs O(m²) with W dense (m × m), built once per run from m banded solves.
//! Fast for devices spaced wider than the coupling length ℓ = (EI h²θ²/ρA)^¼ (2–6 sweeps); it stalls for
//! distributed friction, where [`super::newton::SemismoothNewton`] is the tool.

use super::{FrictionProblem, FrictionSolver, StepReport};

/// Projected Gauss–Seidel with the dense W of the run.
#[derive(Debug, Clone)]
pub struct ProjectedGaussSeidel {
    m: usize,
    /// W row-major, m × m.
    w: Vec<f64>,
    max_sweeps: usize,
    tolerance: f64,
    u: Vec<f64>,
}

impl ProjectedGaussSeidel {
    /// Build W = H M̂⁻¹ Hᵀ (m banded solves) for `problem`.
    pub fn new(problem: &FrictionProblem<'_>, tolerance: f64, max_sweeps: usize) -> Self {
        let m = problem.len();
        let rows = problem.contacts.rows();
        let mut w = vec![0.0; m * m];
        let mut column = vec![0.0; problem.m_hat.order()];
        for (j, row) in rows.iter().enumerate() {
            column.iter_mut().for_each(|c| *c = 0.0);
            row.add_transpose(1.0, &mut column);
            problem.factor.solve_in_place(&mut column);
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
        Self { m, w, max_sweeps, tolerance, u: vec![0.0; m] }
    }

    fn local_velocity(&self, j: usize, u_free: &[f64], p: &[f64]) -> f64 {
        let row = &self.w[j * self.m..(j + 1) * self.m];
        u_free[j] + row.iter().zip(p).map(|(w, p)| w * p).sum::<f64>()
    }
}

impl ProjectedGaussSeidel {
    fn residual(&mut self, problem: &FrictionProblem<'_>, u_free: &[f64], p: &[f64]) -> f64 {
        for j in 0..self.m {
            self.u[j] = self.local_velocity(j, u_free, p);
        }
        problem.law_residual(&self.u, p)
    }
}

impl FrictionSolver for ProjectedGaussSeidel {
    fn name(&self) -> &'static str {
        "projection"
    }

    fn solve(
        &mut self,
        problem: &FrictionProblem<'_>,
        _: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        let mut sweeps = 0;
        let mut residual = f64::INFINITY;
        while sweeps < self.max_sweeps {
            sweeps += 1;
            let mut largest: f64 = 0.0;
            for j in 0..self.m {
                let wjj = self.w[j * self.m + j];
                let u = self.local_velocity(j, u_free, p);
                let new = (p[j] - u / wjj).clamp(-problem.bounds[j], problem.bounds[j]);
                largest = largest.max((new - p[j]).abs() * wjj);
                p[j] = new;
            }
            // The sweep's largest update is the residual met on the way; confirm on the final p.
            if largest <= tolerance {
                residual = self.residual(problem, u_free, p);
                if residual <= tolerance {
                    break;
                }
            }
        }
        if residual > tolerance {
            residual = self.residual(problem, u_free, p);
        }
        Ok(StepReport { iterations: sweeps, residual, tolerance, converged: residual <= tolerance, sections: self.m })
    }
}
