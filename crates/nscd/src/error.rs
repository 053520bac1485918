//! The error type of the `nscd` crate.

use thiserror::Error;

/// What can go wrong when setting up or running a simulation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NscdError {
    /// A setting is out of range; names the field, the value and what is allowed.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// Setting name, e.g. `integration.theta`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// The friction solver stopped short of its tolerance.
    #[error(
        "friction solver {solver} did not converge at step {step} (t = {time:.6} s), {status}: residual {residual:.3e} m/s after {iterations} iterations (tolerance {tolerance:.3e} m/s){}",
        fallbacks_tried(fallbacks)
    )]
    Unconverged {
        /// The solver.
        solver: crate::solver_choice::SolverKind,
        /// How the solver's step ended.
        status: crate::step_report::StepStatus,
        /// Step index (1-based: the step being computed).
        step: usize,
        /// Time at the end of the step (s).
        time: f64,
        /// Final residual of the friction law (m/s).
        residual: f64,
        /// Iterations spent.
        iterations: usize,
        /// The tolerance asked for (m/s).
        tolerance: f64,
        /// The fallback solvers that were tried after it and failed too (None: the run had no fallback).
        fallbacks: Option<[crate::solver_choice::SolverKind; 2]>,
    },
    /// The position projection of the rigid moving contacts stopped short of its tolerance.
    #[error(
        "position projection of the rigid contacts did not converge at step {step} (t = {time:.6} s): gap violation {violation:.3e} m after {sweeps} sweeps (tolerance {tolerance:.0e} m); try compliant contact",
        tolerance = crate::position::PROJECTION_TOLERANCE
    )]
    ProjectionUnconverged {
        /// Step index (1-based).
        step: usize,
        /// Time at the end of the step (s).
        time: f64,
        /// The largest gap violation left (m).
        violation: f64,
        /// Gauss–Seidel sweeps spent.
        sweeps: usize,
    },
    /// A state value became NaN or infinite.
    #[error("non-finite state at step {step} (t = {time:.6} s): {what}; {hint}")]
    NonFinite {
        /// Step index.
        step: usize,
        /// Time (s).
        time: f64,
        /// Which quantity.
        what: &'static str,
        /// What to try.
        hint: &'static str,
    },
    /// The requested solver is not available in this build.
    #[error("solver {0} is not available: rebuild with the cargo feature `clarabel`")]
    Unavailable(&'static str),
    /// The chosen solver cannot take these interactions.
    #[error("solver {solver} cannot solve this problem: {reason}")]
    Unsupported {
        /// The solver.
        solver: crate::solver_choice::SolverKind,
        /// Why, and what can.
        reason: &'static str,
    },
    /// The Clarabel interior-point solver failed.
    #[error("Clarabel failed at step {step}: {status}")]
    Clarabel {
        /// Step index.
        step: usize,
        /// Clarabel's status or error, as text.
        status: String,
    },
    /// A matrix of the step (M̂, or an interior-point Newton matrix) is not positive definite.
    #[error(transparent)]
    Linear(#[from] banded::BandedError),
}

/// The tail of an [`NscdError::Unconverged`] message naming the fallbacks tried.
fn fallbacks_tried(fallbacks: &Option<[crate::solver_choice::SolverKind; 2]>) -> String {
    match fallbacks {
        Some([a, b]) => format!("; the fallbacks {a} and {b} failed too (or could not take the problem)"),
        None => String::new(),
    }
}

impl NscdError {
    /// Whether the error is the user's input (a setting out of range, a solver not built in) rather than a failure
    /// of a step.
    pub fn is_invalid_input(&self) -> bool {
        matches!(self, NscdError::InvalidField { .. } | NscdError::Unavailable(_))
    }
}

/// Result alias of this crate.
pub type Result<T, E = NscdError> = std::result::Result<T, E>;
