//! The interaction step as a QP solved by the interior-point solver Clarabel (feature `clarabel`): an independent
//! cross-check of the other solvers (docs/theory.md §5, §9; docs/architecture.md, Dependencies).
//!
//! Sparse lifted form, so that W is never formed: unknowns x = (y, p) with y = M̂⁻¹Hᵀp the velocity correction,
//! min ½ yᵀM̂y + ½pᵀDp + cᵀp (= ½pᵀ(W + D)p + cᵀp) subject to M̂y − Hᵀp = 0 and p_j = lo_j where lo_j = hi_j (zero
//! cone), p_j ≤ hi_j where hi_j is finite and −p_j ≤ −lo_j where lo_j is finite (non-negative cone; a bilateral
//! spring has neither). Only the upper triangle of P = blkdiag(M̂, D) is passed (Clarabel ignores the rest), D with
//! the step's compliances at each set-up (a Hertz contact's changes with its linearisation). The set-up is rebuilt
//! when the pattern of bounds changes (a contact entering or leaving the index set; never for friction alone) and
//! every step when interactions move (their rows are in A); otherwise each step only replaces q and b.

use super::{InteractionProblem, InteractionSolver, SolverKind, StepReport, StepStatus, StepWork};
use crate::error::NscdError;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
};

/// Which bounds of an interaction enter the QP this step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Bounds {
    /// lo = hi: an equality.
    Fixed,
    /// lo and hi finite (a Coulomb box).
    Box,
    /// Only lo finite (a unilateral contact).
    Lower,
    /// Neither finite (a bilateral spring): no inequality.
    Free,
}

impl Bounds {
    fn of(lower: f64, upper: f64) -> Self {
        if lower == upper {
            Bounds::Fixed
        } else if upper.is_finite() {
            Bounds::Box
        } else if lower.is_finite() {
            Bounds::Lower
        } else {
            Bounds::Free
        }
    }
}

/// Clarabel on the lifted interaction QP.
pub struct ClarabelQp {
    solver: Option<DefaultSolver<f64>>,
    /// The upper triangle of P and the M̂ columns of the equality M̂y − Hᵀp = 0, as triplets (the Hᵀ columns are
    /// added at each set-up from the rows as they are then).
    p_triplets: (Vec<usize>, Vec<usize>, Vec<f64>),
    a_triplets: (Vec<usize>, Vec<usize>, Vec<f64>),
    pattern: Vec<Bounds>,
    b: Vec<f64>,
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
    pub fn new(problem: &InteractionProblem, tolerance: f64) -> crate::Result<Self> {
        let n = problem.matrix.m_hat.order();
        let m = problem.len();
        let bandwidth = problem.matrix.m_hat.bandwidth();
        let (mut pi, mut pj, mut pv) = (Vec::new(), Vec::new(), Vec::new());
        let (mut ai, mut aj, mut av) = (Vec::new(), Vec::new(), Vec::new());
        for j in 0..n {
            for i in j.saturating_sub(bandwidth)..(j + bandwidth + 1).min(n) {
                let value = problem.matrix.m_hat.get(i, j);
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
        Ok(Self {
            solver: None,
            p_triplets: (pi, pj, pv),
            a_triplets: (ai, aj, av),
            pattern: Vec::with_capacity(m),
            b: Vec::new(),
            n,
            q: vec![0.0; n + m],
            u: vec![0.0; m],
            v: vec![0.0; n],
            tolerance,
            step: 0,
        })
    }

    fn settings() -> crate::Result<DefaultSettings<f64>> {
        DefaultSettingsBuilder::default()
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
            .map_err(|e| NscdError::Clarabel { step: 0, status: e.to_string() })
    }

    /// Bring the solver to the step's bounds: rebuilt when their pattern changed, else b replaced.
    fn set_bounds(&mut self, problem: &InteractionProblem) -> crate::Result<()> {
        let n = self.n;
        let law = &problem.law;
        let m = problem.len();
        let unchanged = self.solver.is_some()
            && !problem.has_moving()
            && (0..m).all(|j| self.pattern[j] == Bounds::of(law.lower[j], law.upper[j]));
        self.pattern.clear();
        self.pattern.extend((0..m).map(|j| Bounds::of(law.lower[j], law.upper[j])));
        // Rows: n equalities, the fixed impulses, then the upper bounds and the lower bounds (in that order).
        self.b.clear();
        self.b.resize(n, 0.0);
        let fixed: Vec<usize> = (0..m).filter(|&j| self.pattern[j] == Bounds::Fixed).collect();
        self.b.extend(fixed.iter().map(|&j| law.lower[j]));
        let boxed: Vec<usize> = (0..m).filter(|&j| self.pattern[j] == Bounds::Box).collect();
        self.b.extend(boxed.iter().map(|&j| law.upper[j]));
        let lower: Vec<usize> = (0..m).filter(|&j| matches!(self.pattern[j], Bounds::Box | Bounds::Lower)).collect();
        self.b.extend(lower.iter().map(|&j| -law.lower[j]));
        if unchanged {
            let solver = self.solver.as_mut().expect("checked");
            return solver
                .update_b(&self.b)
                .map_err(|e| NscdError::Clarabel { step: self.step, status: e.to_string() });
        }
        let (mut ai, mut aj, mut av) = self.a_triplets.clone();
        for (k, row) in problem.interactions.rows().iter().enumerate() {
            for (dof, value) in row.entries() {
                ai.push(dof);
                aj.push(n + k);
                av.push(-value);
            }
        }
        let mut row = n;
        for (&j, sign) in
            fixed.iter().map(|j| (j, 1.0)).chain(boxed.iter().map(|j| (j, 1.0))).chain(lower.iter().map(|j| (j, -1.0)))
        {
            ai.push(row);
            aj.push(n + j);
            av.push(sign);
            row += 1;
        }
        // P = blkdiag(M̂, D) with the step's compliances: a Hertz contact's changes with its linearisation.
        let (mut pi, mut pj, mut pv) = self.p_triplets.clone();
        for (k, &d) in law.compliance.iter().enumerate().filter(|(_, d)| **d != 0.0) {
            pi.push(n + k);
            pj.push(n + k);
            pv.push(d);
        }
        let p_matrix = CscMatrix::new_from_triplets(n + m, n + m, pi, pj, pv);
        let a_matrix = CscMatrix::new_from_triplets(row, n + m, ai, aj, av);
        let cones =
            [SupportedConeT::ZeroConeT(n + fixed.len()), SupportedConeT::NonnegativeConeT(boxed.len() + lower.len())];
        let solver = DefaultSolver::new(&p_matrix, &self.q, &a_matrix, &self.b, &cones, Self::settings()?)
            .map_err(|e| NscdError::Clarabel { step: self.step, status: e.to_string() })?;
        self.solver = Some(solver);
        Ok(())
    }
}

impl InteractionSolver for ClarabelQp {
    fn kind(&self) -> SolverKind {
        SolverKind::Clarabel
    }

    /// v of the final (clipped) impulses, formed for the law residual.
    fn velocity(&self) -> Option<&[f64]> {
        (self.step > 0).then_some(self.v.as_slice())
    }

    fn solve(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        self.step += 1;
        for ((q, u), b) in self.q[self.n..].iter_mut().zip(u_free).zip(&problem.law.drift) {
            *q = u + b;
        }
        let rebuilt = self.solver.is_none();
        self.set_bounds(problem)?;
        let solver = self.solver.as_mut().expect("set up above");
        if !rebuilt {
            solver.update_q(&self.q).map_err(|e| NscdError::Clarabel { step: self.step, status: e.to_string() })?;
        }
        solver.solve();
        let status = solver.solution.status;
        if !matches!(status, SolverStatus::Solved | SolverStatus::AlmostSolved) {
            return Err(NscdError::Clarabel { step: self.step, status: format!("{status:?}") });
        }
        p.copy_from_slice(&solver.solution.x[self.n..]);
        let iterations = solver.solution.iterations as usize;
        // An interior point stops a hair inside or outside the box (|p_j| − a_j ~ 1e-14 seen on zero bounds): clip,
        // so that the impulses the stepper applies never exceed the device capacity nor pull on a contact.
        problem.clamp_to_bounds(p);
        // The law residual on v = v_free + M̂⁻¹Hᵀp, as the stepper will form it.
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        let residual = problem.outcome(v_free, p, &mut self.v, &mut self.u);
        // Clarabel stops on its own duality-gap criteria: its law residuals are ~1e-9 of the velocity scale, and up
        // to ~3e-7 on degenerate steps (a section at the stick–slip boundary). It is accepted up to 1e-6 of that
        // scale (or the requested tolerance if looser); beyond, the stepper refuses the step.
        let accepted = tolerance.max(problem.absolute_tolerance(1e-6, u_free));
        // Clarabel ran to its own stopping criteria (Solved or AlmostSolved): short of the law, it stalled.
        let status = StepStatus::of(residual, accepted, iterations, usize::MAX);
        Ok(StepReport {
            status,
            iterations,
            residual,
            tolerance: accepted,
            sections: p.len(),
            fallback: None,
            work: StepWork::default(),
        })
    }
}
