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
//! - `clarabel::ClarabelQp` (feature `clarabel`): the interior-point QP solver Clarabel on the sparse lifted form,
//!   an independent cross-check.
//!
//! Every solver reports its iterations and the final residual of the law,
//! max_j |p_j − proj_[lo_j, hi_j](p_j − r_j/(W_jj + d_j))|·(W_jj + d_j) (m/s), and the stepper refuses an
//! unconverged step.

pub mod interior_point;
pub mod projection;
pub mod response;

#[cfg(feature = "clarabel")]
pub mod clarabel;

pub use crate::problem::InteractionProblem;

/// Which per-step friction solver to use: the one choice type of every layer (scenario files through the `serde`
/// feature, the command line through [`SolverKind::ALL`] and `FromStr`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum SolverKind {
    /// Projection for sections spaced wider than twice the coupling length, interior point otherwise.
    #[default]
    Auto,
    /// Nonsmooth (projected) Gauss–Seidel.
    Projection,
    /// Banded primal–dual interior point.
    InteriorPoint,
    /// Clarabel interior-point QP (feature `clarabel`).
    Clarabel,
}

impl SolverKind {
    /// Every choice, in the order they are documented.
    pub const ALL: [SolverKind; 4] =
        [SolverKind::Auto, SolverKind::Projection, SolverKind::InteriorPoint, SolverKind::Clarabel];

    /// Lower-case name, as used in scenario files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SolverKind::Auto => "auto",
            SolverKind::Projection => "projection",
            SolverKind::InteriorPoint => "interior-point",
            SolverKind::Clarabel => "clarabel",
        }
    }
}

impl std::fmt::Display for SolverKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for SolverKind {
    type Err = String;

    /// The kind named `name` ([`SolverKind::name`]); the error lists the names.
    fn from_str(name: &str) -> Result<Self, String> {
        Self::ALL.into_iter().find(|k| k.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|k| k.name()).collect();
            format!("unknown solver `{name}`, expected one of {}", names.join(", "))
        })
    }
}

/// Tolerances and limits of the friction solvers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    /// Solver choice. Default [`SolverKind::Auto`].
    pub kind: SolverKind,
    /// Relative tolerance on the law residual, relative to max_j |u_free,j| (m/s). Default 1e-6; in (0, 1e-2].
    /// Tighter buys no digit of a run's results: with distributed friction the outcomes scatter over tolerances
    /// 1e-12…1e-6 without a trend (stick–slip transitions move by a step under any perturbation; BENCHMARKS.md),
    /// while 1e-8 costs ~40 % more interior-point iterations than 1e-6, 1e-10 ~85 %, and the interior point stalls
    /// near 1e-12. From 1e-5 on, peaks at 200 m/s start to leave that scatter.
    pub tolerance: f64,
    /// Iteration cap per step: sweeps for projection, iterations for interior point. Default 20 000.
    pub max_iterations: usize,
    /// Let the interior point re-solve only a moving window around the sections that change (exact to the same
    /// tolerance: every section is checked; see [`interior_point`]). Default true.
    pub moving_window: bool,
}

impl Default for SolverSettings {
    fn default() -> Self {
        Self { kind: SolverKind::Auto, tolerance: 1e-6, max_iterations: 20_000, moving_window: true }
    }
}

/// Below this velocity (m/s) a section is considered at rest when scaling tolerances.
pub const VELOCITY_FLOOR: f64 = 1e-14;

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
}

impl StepReport {
    /// Whether the residual met the tolerance.
    pub fn converged(&self) -> bool {
        self.status == StepStatus::Converged
    }
}

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

/// Build the solver `kind` (not `Auto`: resolve it first) for `problem`. `window_margin` (m) is the interior
/// point's moving-window margin, used when `settings.moving_window` is set (30 coupling lengths is safe).
pub fn build_solver<'a>(
    kind: SolverKind,
    problem: &InteractionProblem,
    settings: &SolverSettings,
    window_margin: Option<f64>,
) -> crate::Result<Box<dyn InteractionSolver + 'a>> {
    Ok(match kind {
        SolverKind::Projection | SolverKind::Auto => {
            Box::new(projection::ProjectedGaussSeidel::new(problem, settings.tolerance, settings.max_iterations))
        }
        SolverKind::InteriorPoint => Box::new(interior_point::BandedInteriorPoint::new(
            problem,
            settings.tolerance,
            settings.max_iterations,
            window_margin.filter(|_| settings.moving_window),
        )?),
        #[cfg(feature = "clarabel")]
        SolverKind::Clarabel => Box::new(clarabel::ClarabelQp::new(problem, settings.tolerance)?),
        #[cfg(not(feature = "clarabel"))]
        SolverKind::Clarabel => return Err(crate::NscdError::Unavailable("clarabel")),
    })
}
