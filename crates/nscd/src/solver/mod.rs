//! Per-step friction solvers (docs/theory.md §5).
//!
//! Each step poses: find impulses p with v = v_free + M̂⁻¹Hᵀp, u = H v = W p + u_free, W = H M̂⁻¹ Hᵀ, and
//! p_j ∈ −a_j Sign(u_j), a_j = h F_j. Equivalently the box QP min ½pᵀWp + u_freeᵀp, |p_j| ≤ a_j, or the strongly
//! convex primal min_v ½‖v − v_free‖²_M̂ + Σ a_j |H_j v|. v is unique; p need not be (W is singular when sections
//! outnumber DOFs), so solvers are compared on v and Hᵀp.
//!
//! - [`projection::ProjectedGaussSeidel`]: nonsmooth Gauss–Seidel on the dense W, the NSCD default for devices.
//! - [`interior_point::BandedInteriorPoint`]: a primal–dual interior-point method whose Newton systems are banded
//!   (Woodbury on M̂ + HᵀΣ⁻¹H); built for dense distributed friction, where Gauss–Seidel stalls.
//! - `clarabel::ClarabelQp` (feature `clarabel`): the interior-point QP solver Clarabel on the sparse lifted form,
//!   an independent cross-check.
//!
//! Every solver reports its iterations and the final residual of the law, max_j |p_j − proj(p_j − u_j/W_jj)|·W_jj
//! (m/s), and the stepper refuses an unconverged step.

pub mod interior_point;
pub mod projection;
pub mod response;

#[cfg(feature = "clarabel")]
pub mod clarabel;

use crate::kernels::axpy;
use crate::stepper::{Integration, iteration_matrix};
use crate::system::LinearSystem;
use banded::{BandedLdlt, SymmetricBanded};
use friction::ContactSet;
use friction::coulomb::natural_residual;
use response::ImpulseResponses;

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
}

impl StepReport {
    /// Whether the residual met the tolerance.
    pub fn converged(&self) -> bool {
        self.status == StepStatus::Converged
    }
}

/// The data of every friction step of a run: M̂ and its LDLᵀ factors (always of that matrix: both are made here),
/// the contact rows, the bounds a_j = h·F_j and the diagonal of the Delassus matrix W_jj = H_j M̂⁻¹ H_jᵀ. It owns
/// all of it, so a stepper built on it borrows nothing.
#[derive(Debug)]
pub struct FrictionProblem {
    /// Contact rows.
    pub contacts: ContactSet,
    /// M̂ = M + hθC + h²θ²K.
    pub m_hat: SymmetricBanded,
    /// LDLᵀ factors of M̂.
    pub factor: BandedLdlt,
    /// The step h and θ the problem is built for.
    pub integration: Integration,
    /// a_j = h·F_j (N·s).
    pub bounds: Vec<f64>,
    /// W_jj (m/s per N·s).
    pub delassus_diagonal: Vec<f64>,
    /// G_j = M̂⁻¹H_jᵀ, truncated to round-off, when few and short enough to beat a solve (see [`response`]).
    pub responses: Option<ImpulseResponses>,
}

impl FrictionProblem {
    /// The friction problem of a step of `integration` on `system`: M̂ = M + hθC + h²θ²K is built and factored here
    /// (docs/theory.md §5).
    pub fn new(system: &LinearSystem, contacts: ContactSet, integration: Integration) -> crate::Result<Self> {
        Self::with_matrix(contacts, iteration_matrix(system, integration), integration)
    }

    /// The same for a given SPD iteration matrix `m_hat` (e.g. a test problem), factored here.
    pub fn with_matrix(contacts: ContactSet, m_hat: SymmetricBanded, integration: Integration) -> crate::Result<Self> {
        let factor = m_hat.factor()?;
        let bounds = contacts.bounds().iter().map(|f| integration.step * f).collect();
        let (responses, delassus_diagonal) = ImpulseResponses::new(&contacts, &factor);
        Ok(Self { contacts, m_hat, factor, integration, bounds, delassus_diagonal, responses })
    }

    /// v += M̂⁻¹Hᵀp: from the stored responses when there are any, else by one banded solve (`work`: n scratch).
    pub fn add_response(&self, p: &[f64], v: &mut [f64], work: &mut [f64]) {
        match &self.responses {
            Some(responses) => responses.add(p, v),
            None => {
                self.solve_response(p, work);
                axpy(1.0, work, v);
            }
        }
    }

    /// out = M̂⁻¹Hᵀp by one banded solve.
    fn solve_response(&self, p: &[f64], out: &mut [f64]) {
        out.iter_mut().for_each(|x| *x = 0.0);
        self.contacts.add_transpose(p, out);
        self.factor.solve_in_place(out);
    }

    /// Number of sections.
    pub fn len(&self) -> usize {
        self.bounds.len()
    }

    /// Whether there is no section.
    pub fn is_empty(&self) -> bool {
        self.bounds.is_empty()
    }

    /// |p_j − proj(p_j − u_j/W_jj)|·W_jj (m/s) of section j: zero exactly when (u_j, p_j) satisfy the law.
    #[inline]
    pub fn section_residual(&self, j: usize, u: f64, p: f64) -> f64 {
        natural_residual(u, p, self.bounds[j], 1.0 / self.delassus_diagonal[j])
    }

    /// max_j of [`FrictionProblem::section_residual`] (m/s).
    pub fn law_residual(&self, u: &[f64], p: &[f64]) -> f64 {
        (0..self.len()).map(|j| self.section_residual(j, u[j], p[j])).fold(0.0, f64::max)
    }

    /// The step's outcome for impulses p, as the stepper will form it: v = v_free + M̂⁻¹Hᵀp and u = H v (into the
    /// given buffers), and the law residual (m/s).
    pub fn outcome(&self, v_free: &[f64], p: &[f64], v: &mut [f64], u: &mut [f64]) -> f64 {
        if let Some(responses) = &self.responses {
            v.copy_from_slice(v_free);
            responses.add(p, v);
        } else {
            self.solve_response(p, v);
            axpy(1.0, v_free, v);
        }
        self.contacts.velocities(v, u);
        self.law_residual(u, p)
    }

    /// Absolute tolerance (m/s) for a relative tolerance and the free velocities u_free.
    pub fn absolute_tolerance(&self, relative: f64, u_free: &[f64]) -> f64 {
        relative * u_free.iter().fold(VELOCITY_FLOOR, |m, u| m.max(u.abs()))
    }
}

/// A per-step friction solver. `p` holds the warm start (the previous step's impulses) on entry and the solution
/// on exit; `u_free = H v_free`. The stepper then sets v = v_free + M̂⁻¹Hᵀp.
pub trait FrictionSolver {
    /// Which solver this is.
    fn kind(&self) -> SolverKind;
    /// Solve one step.
    fn solve(
        &mut self,
        problem: &FrictionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport>;
}

/// Build the solver `kind` (not `Auto`: resolve it first) for `problem`. `window_margin` (m) is the interior
/// point's moving-window margin, used when `settings.moving_window` is set (30 coupling lengths is safe).
pub fn build_solver<'a>(
    kind: SolverKind,
    problem: &FrictionProblem,
    settings: &SolverSettings,
    window_margin: Option<f64>,
) -> crate::Result<Box<dyn FrictionSolver + 'a>> {
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
