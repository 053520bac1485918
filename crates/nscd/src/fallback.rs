//! The fallback of a step that the run's solver cannot solve: the same interaction problem handed to the other
//! solvers in turn, each built on first need, so that one hard step does not end a run (docs/theory.md §5).
//!
//! Every solver solves the one box QP of [`InteractionProblem`] to the same law residual, so a step solved by a
//! fallback is as exact as any other; only its cost differs. The step's [`StepReport::fallback`] names the solver
//! that solved it, and runs count such steps in their statistics: a fallback is never silent.
//!
//! The order, from the run's solver:
//! - interior point → Clarabel → projection (an interior point that stalls — a degenerate step — is best taken over
//!   by the other interior-point method, which has its own centring and stopping rules);
//! - projection → interior point → Clarabel (Gauss–Seidel stalls on dense sections, where the interior point is
//!   made for them);
//! - Clarabel → interior point → projection.
//!
//! A fallback that cannot take the problem (the interior point with moving rows, Clarabel in a build without it)
//! is skipped; one that fails (unconverged, or an error of its own) hands on to the next.
//!
//! A run's solver that keeps failing is not tried on every step: each failure costs it its whole iteration cap
//! (projection on 800 ballast sections: 20 000 sweeps, ~1.5 s a step — a run of 2000 steps took ~45 min, every step
//! solved by the fallback). After [`HANDOVER_AFTER`] failures in a row the fallbacks take the next
//! [`FIRST_HANDOVER`] steps straight away; the run's solver is then tried again, and each failure of it doubles the
//! hand-over, each success ends it. The steps stay counted as fallback steps: a hand-over is never silent.

use crate::error::Result;
use crate::solver::{InteractionProblem, InteractionSolver, SolverKind, SolverSettings, StepReport, build_solver};

/// Failures in a row of the run's solver after which the fallbacks take steps without it.
pub const HANDOVER_AFTER: usize = 3;

/// The steps of the first hand-over; each later one is twice the last.
pub const FIRST_HANDOVER: usize = 8;

/// The fallbacks of one run: their order, the settings to build them with, and those built.
pub struct Fallbacks {
    settings: SolverSettings,
    order: [SolverKind; 2],
    /// Built on first need; `Some(None)` remembers one that cannot take this problem.
    built: [Option<Option<Box<dyn InteractionSolver>>>; 2],
    /// The run's solver's failures in a row.
    streak: usize,
    /// Steps left of the current hand-over.
    handed_over: usize,
    /// The next hand-over's length.
    next_handover: usize,
}

impl std::fmt::Debug for Fallbacks {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Fallbacks").field("order", &self.order).finish()
    }
}

impl Fallbacks {
    /// The fallbacks of a run whose solver is `primary` (a resolved kind), built with `settings` (their kind
    /// aside).
    pub fn new(primary: SolverKind, settings: &SolverSettings) -> Self {
        Self {
            settings: *settings,
            order: Self::order(primary),
            built: [None, None],
            streak: 0,
            handed_over: 0,
            next_handover: FIRST_HANDOVER,
        }
    }

    /// Whether this step goes to the fallbacks without the run's solver (a hand-over is under way).
    pub fn takes_the_step(&mut self) -> bool {
        let taking = self.handed_over > 0;
        self.handed_over = self.handed_over.saturating_sub(1);
        taking
    }

    /// The run's solver solved a step: any hand-over ends.
    pub fn solver_succeeded(&mut self) {
        (self.streak, self.next_handover) = (0, FIRST_HANDOVER);
    }

    /// The run's solver failed a step: after [`HANDOVER_AFTER`] in a row, the next steps are handed over.
    pub fn solver_failed(&mut self) {
        self.streak += 1;
        if self.streak >= HANDOVER_AFTER {
            self.handed_over = self.next_handover;
            self.next_handover = self.next_handover.saturating_mul(2);
        }
    }

    /// The solvers tried after `primary`, in order.
    pub fn order(primary: SolverKind) -> [SolverKind; 2] {
        use SolverKind::{Clarabel, InteriorPoint, Projection};
        match primary {
            InteriorPoint => [Clarabel, Projection],
            Clarabel => [InteriorPoint, Projection],
            Projection | SolverKind::Homotopy | SolverKind::Auto => [InteriorPoint, Clarabel],
        }
    }

    /// Solve the step with the fallbacks in turn, from the impulses `p` the failed solver left (a warm start for
    /// projection; the interior-point methods start from the centre). `failed` is the failed solver's report, if it
    /// returned one: a fallback must then meet the tolerance that solver was held to (Clarabel on its own accepts
    /// up to 1e-6 of the velocity scale, which would loosen a run asked for less), and its iterations are counted
    /// in. Returns the first report that meets it, with [`StepReport::fallback`] set; None when every fallback
    /// failed or none could take the problem (the caller reports the run's solver's failure).
    pub fn solve(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
        failed: Option<&StepReport>,
    ) -> Option<StepReport> {
        for slot in 0..self.order.len() {
            let kind = self.order[slot];
            if self.built[slot].is_none() {
                let mut settings = self.settings;
                settings.kind = kind;
                self.built[slot] = Some(build_solver(kind, problem, &settings).ok());
            }
            let Some(Some(solver)) = self.built[slot].as_mut() else { continue };
            let attempt: Result<StepReport> =
                solver.refresh(problem).and_then(|()| solver.solve(problem, v_free, u_free, p));
            // Without the run's solver's report (a hand-over), the tolerance it would have been held to.
            let required =
                failed.map_or_else(|| problem.absolute_tolerance(self.settings.tolerance, u_free), |f| f.tolerance);
            if let Ok(mut report) = attempt
                && report.converged()
                && report.residual <= required
            {
                report.iterations += failed.map_or(0, |f| f.iterations);
                if let Some(failed) = failed {
                    report.work += failed.work;
                }
                report.fallback = Some(kind);
                return Some(report);
            }
        }
        None
    }

    /// v = v_free + M̂⁻¹Hᵀp as the fallback of `report` formed it, if it did (see [`InteractionSolver::velocity`]).
    pub fn velocity(&self, report: &StepReport) -> Option<&[f64]> {
        let kind = report.fallback?;
        let slot = self.order.iter().position(|&k| k == kind)?;
        self.built[slot].as_ref()?.as_ref()?.velocity()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three failures in a row hand the next 8 steps over; a failed retry doubles the hand-over (16, 32, …), a
    /// solved one ends it.
    #[test]
    fn a_solver_that_keeps_failing_is_handed_over_for_doubling_spells() {
        let mut f = Fallbacks::new(SolverKind::Projection, &SolverSettings::default());
        let handed = |f: &mut Fallbacks| (0..100).take_while(|_| f.takes_the_step()).count();
        f.solver_failed();
        f.solver_failed();
        assert_eq!(handed(&mut f), 0, "two failures are not a streak");
        f.solver_failed();
        assert_eq!(handed(&mut f), FIRST_HANDOVER);
        f.solver_failed();
        assert_eq!(handed(&mut f), 2 * FIRST_HANDOVER);
        f.solver_failed();
        assert_eq!(handed(&mut f), 4 * FIRST_HANDOVER);
        f.solver_succeeded();
        f.solver_failed();
        assert_eq!(handed(&mut f), 0, "a success ends the streak");
    }
}
