//! Per-step solvers of the interaction problem (docs/theory.md §5, §9).
//!
//! Each step poses the box-constrained convex QP of [`InteractionProblem`]: min ½pᵀ(W + D)p + cᵀp, lo ≤ p ≤ hi,
//! W = H M̂⁻¹Hᵀ, c = H v_free + b, with v = v_free + M̂⁻¹Hᵀp. For friction alone (D = 0, b = 0, lo = −hF, hi = hF) it is
//! equivalent to the strongly convex primal min_v ½‖v − v_free‖²_M̂ + Σ hF_j |H_j v|: v is unique, p need not be (W
//! is singular when sections outnumber DOFs), so solvers are compared on v and Hᵀp.
//!
//! - [`projection::ProjectedGaussSeidel`]: nonsmooth Gauss–Seidel on the dense W, the NSCD default for devices.
//! - [`interior_point::BandedInteriorPoint`]: a primal–dual interior-point method whose Newton systems are banded
//!   (Woodbury on M̂ + Hᵀ(Σ + D)⁻¹H); built for dense distributed friction, where Gauss–Seidel stalls.
//! - [`homotopy::ParametricActiveSet`]: a parametric active-set method on the shifted Huber law, the path from the
//!   previous step's solution to this one through the events where sections change between stick and slip; about
//!   events are rank-one corrections of one factorisation (Sherman–Morrison–Woodbury, local solves); exact to the
//!   tolerance by construction.
//! - `clarabel::ClarabelQp` (feature `clarabel`): the interior-point QP solver Clarabel on the sparse lifted form,
//!   an independent cross-check.
//!
//! Every solver reports its iterations and the final residual of the law,
//! max_j |p_j − proj_[lo_j, hi_j](p_j − r_j/(W_jj + d_j))|·(W_jj + d_j) (m/s), and the stepper refuses an
//! unconverged step.

pub mod homotopy;
pub mod interior_point;
pub mod projection;

#[cfg(feature = "clarabel")]
pub mod clarabel;

pub use crate::problem::InteractionProblem;
pub use crate::solver_choice::{SolverKind, SolverSettings};
pub use crate::step_report::{StepReport, StepStatus, StepWork};

/// A per-step friction solver. `p` holds the warm start (the previous step's impulses) on entry and the solution
/// on exit; `u_free = H v_free`. The stepper then sets v = v_free + M̂⁻¹Hᵀp.
pub trait InteractionSolver {
    /// Which solver this is.
    fn kind(&self) -> SolverKind;
    /// The new velocity v = v_free + M̂⁻¹Hᵀp of the last solve's impulses, when the solver formed it to check the law
    /// (written back: the stepper then need not form it again). The same arithmetic as
    /// [`InteractionProblem::add_response`], so the same bits.
    fn velocity(&self) -> Option<&[f64]> {
        None
    }
    /// Take in the rows the update phase rebuilt (moving interactions) before the next solve.
    fn refresh(&mut self, _problem: &InteractionProblem) -> crate::Result<()> {
        Ok(())
    }
    /// Solve one step.
    fn solve(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport>;
}

/// Build the solver `kind` (not `Auto`: resolve it first) for `problem`; the interior point solves on a moving
/// window when `settings.moving_window` is set.
pub fn build_solver<'a>(
    kind: SolverKind,
    problem: &InteractionProblem,
    settings: &SolverSettings,
) -> crate::Result<Box<dyn InteractionSolver + 'a>> {
    Ok(match kind {
        SolverKind::Projection | SolverKind::Auto => {
            Box::new(projection::ProjectedGaussSeidel::new(problem, settings.tolerance, settings.max_iterations))
        }
        SolverKind::InteriorPoint => Box::new(interior_point::BandedInteriorPoint::new(
            problem,
            settings.tolerance,
            settings.max_iterations,
            settings.moving_window,
        )?),
        SolverKind::Homotopy => {
            Box::new(homotopy::ParametricActiveSet::new(problem, settings.tolerance, settings.max_iterations)?)
        }
        #[cfg(feature = "clarabel")]
        SolverKind::Clarabel => Box::new(clarabel::ClarabelQp::new(problem, settings.tolerance)?),
        #[cfg(not(feature = "clarabel"))]
        SolverKind::Clarabel => return Err(crate::NscdError::Unavailable("clarabel")),
    })
}
