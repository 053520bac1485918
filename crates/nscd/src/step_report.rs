//! How a step of the interaction problem ended: its status and its numbers.

use crate::solver_choice::SolverKind;

/// How a friction solver's step ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StepStatus {
    /// The law residual met the tolerance.
    #[default]
    Converged,
    /// The solver used its whole iteration budget without meeting the tolerance.
    IterationLimit,
    /// The solver stopped on its own criteria, within its budget, short of the tolerance.
    Stalled,
    /// The residual is not a finite number.
    NumericalError,
}

impl StepStatus {
    /// The status of a step that ended with `residual` against `tolerance` (m/s) after `iterations` of a budget
    /// of `limit`.
    pub fn of(residual: f64, tolerance: f64, iterations: usize, limit: usize) -> Self {
        if !residual.is_finite() {
            StepStatus::NumericalError
        } else if residual <= tolerance {
            StepStatus::Converged
        } else if iterations >= limit {
            StepStatus::IterationLimit
        } else {
            StepStatus::Stalled
        }
    }
}

impl std::fmt::Display for StepStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            StepStatus::Converged => "converged",
            StepStatus::IterationLimit => "iteration limit reached",
            StepStatus::Stalled => "stalled before the iteration limit",
            StepStatus::NumericalError => "numerical error (non-finite residual)",
        })
    }
}

/// How one friction step ended.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepReport {
    /// How it ended.
    pub status: StepStatus,
    /// Iterations: sweeps (projection), interior-point iterations (interior point, Clarabel).
    pub iterations: usize,
    /// Final law residual (m/s).
    pub residual: f64,
    /// The tolerance it had to meet (m/s).
    pub tolerance: f64,
    /// Sections actually re-solved this step (all of them, except with the interior point's moving window).
    pub sections: usize,
    /// The fallback solver that solved this step after the run's solver failed on it (None: the run's solver did;
    /// see [`crate::fallback`]).
    pub fallback: Option<SolverKind>,
    /// The banded linear algebra and events the step took (a fallback's step includes the failed attempt's).
    pub work: StepWork,
}

/// The linear algebra of one step, what the solvers are compared on besides time: banded factorisations and solves
/// (of M̂ plus terms — the interior point's Newton matrices, the homotopy's B — over the whole problem or its
/// window; zero for projection, which works on the dense W, and for Clarabel, which factors its own sparse KKT
/// system), and the homotopy's events and repair rounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct StepWork {
    /// Banded factorisations.
    pub factorisations: usize,
    /// Banded solves.
    pub solves: usize,
    /// Sections changing between stick and slip along the homotopy's path.
    pub events: usize,
    /// The homotopy's polish rounds beyond the first.
    pub repairs: usize,
}

impl std::ops::AddAssign for StepWork {
    fn add_assign(&mut self, other: Self) {
        self.factorisations += other.factorisations;
        self.solves += other.solves;
        self.events += other.events;
        self.repairs += other.repairs;
    }
}

impl StepReport {
    /// Whether the residual met the tolerance.
    pub fn converged(&self) -> bool {
        self.status == StepStatus::Converged
    }
}
