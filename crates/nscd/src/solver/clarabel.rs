//! The friction step as a QP solved by the interior-point solver Clarabel (feature `clarabel`): an independent
//! cross-check of the other solvers (docs/theory.md §5, `DEPENDENCIES.md`).
//!
//! Sparse lifted form, so that W is never formed: unknowns x = (y, p) with y = M̂⁻¹Hᵀp the velocity correction,
//! min ½ yᵀM̂y + u_freeᵀp (= ½pᵀWp + u_freeᵀp) subject to M̂y − Hᵀp = 0 (zero cone, n rows) and p ≤ a, −p ≤ a
//! (non-negative cone, 2m rows). Only the upper triangle of P = blkdiag(M̂, 0) is passed (Clarabel ignores the rest).
//! The set-up is built once per run; each step only replaces q by `update_q`.

use super::{FrictionProblem, FrictionSolver, SolverKind, StepReport, StepStatus};
use crate::error::NscdError;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};

/// Clarabel on the lifted friction QP.
pub struct ClarabelQp {
    solver: DefaultSolver<f64>,
    n: usize,
    q: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    tolerance: f64,
    step: usize,
}

impl std::fmt::Debug for ClarabelQp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ClarabelQp").field("n", &self.n).field("tolerance", &self.tolerance).finish()
    }
}

impl ClarabelQp {
    /// Set up the QP of `problem` (tight interior-point tolerances: it is a reference).
    pub fn new(problem: &FrictionProblem, tolerance: f64) -> crate::Result<Self> {
        let n = problem.m_hat.order();
        let m = problem.len();
        let bandwidth = problem.m_hat.bandwidth();
        let (mut pi, mut pj, mut pv) = (Vec::new(), Vec::new(), Vec::new());
        let (mut ai, mut aj, mut av) = (Vec::new(), Vec::new(), Vec::new());
        for j in 0..n {
            for i in j.saturating_sub(bandwidth)..(j + bandwidth + 1).min(n) {
                let value = problem.m_hat.get(i, j);
                if value != 0.0 {
                    if i <= j {
                        pi.push(i);
                        pj.push(j);
                        pv.push(value);
                    }
                    ai.push(i);
                    aj.push(j);
                    av.push(value);
                }
            }
        }
        for (k, row) in problem.contacts.rows().iter().enumerate() {
            for (dof, value) in row.entries() {
                ai.push(dof);
                aj.push(n + k);
                av.push(-value);
            }
            ai.push(n + k);
            aj.push(n + k);
            av.push(1.0);
            ai.push(n + m + k);
            aj.push(n + k);
            av.push(-1.0);
        }
        let p_matrix = CscMatrix::new_from_triplets(n + m, n + m, pi, pj, pv);
        let a_matrix = CscMatrix::new_from_triplets(n + 2 * m, n + m, ai, aj, av);
        let mut b = vec![0.0; n + 2 * m];
        b[n..n + m].copy_from_slice(&problem.bounds);
        b[n + m..].copy_from_slice(&problem.bounds);
        let cones = [SupportedConeT::ZeroConeT(n), SupportedConeT::NonnegativeConeT(2 * m)];
        let settings = DefaultSettingsBuilder::default()
            .verbose(false)
            .presolve_enable(false)
            .max_iter(400)
            // Tighter than 1e-12 Clarabel stalls and stops early ("AlmostSolved" at a worse point); measured on
            // the 801-section step, 1e-12 gives law residuals ~1e-8 of the velocity scale.
            .tol_gap_abs(1e-12)
            .tol_gap_rel(1e-12)
            .tol_feas(1e-12)
            // The default static regularisation (1e-8) caps the accuracy: velocities 1e-8 off the other solvers on
            // the 801-section step; 1e-12 brings them to ~1e-9 (measured).
            .static_regularization_constant(1e-12)
            .build()
            .map_err(|e| NscdError::Clarabel { step: 0, status: e.to_string() })?;
        let q = vec![0.0; n + m];
        let solver = DefaultSolver::new(&p_matrix, &q, &a_matrix, &b, &cones, settings)
            .map_err(|e| NscdError::Clarabel { step: 0, status: e.to_string() })?;
        Ok(Self { solver, n, q, u: vec![0.0; m], v: vec![0.0; n], tolerance, step: 0 })
    }
}

impl FrictionSolver for ClarabelQp {
    fn kind(&self) -> SolverKind {
        SolverKind::Clarabel
    }

    fn solve(
        &mut self,
        problem: &FrictionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        self.step += 1;
        self.q[self.n..].copy_from_slice(u_free);
        self.solver.update_q(&self.q).map_err(|e| NscdError::Clarabel { step: self.step, status: e.to_string() })?;
        self.solver.solve();
        let status = self.solver.solution.status;
        if !matches!(status, SolverStatus::Solved | SolverStatus::AlmostSolved) {
            return Err(NscdError::Clarabel { step: self.step, status: format!("{status:?}") });
        }
        p.copy_from_slice(&self.solver.solution.x[self.n..]);
        // An interior point stops a hair inside or outside the box (|p_j| − a_j ~ 1e-14 seen on zero bounds): clip,
        // so that the impulses the stepper applies never exceed the device capacity.
        for (pj, &a) in p.iter_mut().zip(&problem.bounds) {
            *pj = pj.clamp(-a, a);
        }
        // The law residual on v = v_free + M̂⁻¹Hᵀp, as the stepper will form it.
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        let residual = problem.outcome(v_free, p, &mut self.v, &mut self.u);
        let iterations = self.solver.solution.iterations as usize;
        // Clarabel stops on its own duality-gap criteria: its law residuals are ~1e-9 of the velocity scale, and up
        // to ~3e-7 on degenerate steps (a section at the stick–slip boundary). It is accepted up to 1e-6 of that
        // scale (or the requested tolerance if looser); beyond, the stepper refuses the step.
        let accepted = tolerance.max(problem.absolute_tolerance(1e-6, u_free));
        // Clarabel ran to its own stopping criteria (Solved or AlmostSolved): short of the law, it stalled.
        let status = StepStatus::of(residual, accepted, iterations, usize::MAX);
        Ok(StepReport { status, iterations, residual, tolerance: accepted, sections: p.len() })
    }
}
