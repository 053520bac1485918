//! The error type of the `stationary` crate.

use thiserror::Error;

/// What can go wrong setting up a stationary wave.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StationaryError {
    /// A parameter out of range: the field, its value, what is allowed.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// Parameter name, e.g. `speed`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// A choice the stationary solver does not take: the field, the choice by its name, what is allowed.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidChoice {
        /// Parameter name, e.g. `distributed.quadrature`.
        field: &'static str,
        /// The choice, by its name.
        value: &'static str,
        /// What is allowed.
        allowed: &'static str,
    },
    /// No far-field mode decays at this speed (undamped at or above the critical speed): no transparent end selects
    /// the physical wave.
    #[error(
        "no stationary wave at v = {speed} m/s: undamped at or above the critical speed no far-field mode decays, so \
         nothing selects the outgoing wave; give the foundation damping, or run the co-moving or long finite track \
         in time"
    )]
    NoRadiationCondition {
        /// v (m/s).
        speed: f64,
    },
    /// The solve was stopped (Ctrl-C, SIGTERM) between two Newton iterations.
    #[error("interrupted")]
    Interrupted,
    /// An error of the beam layer.
    #[error(transparent)]
    Beam(#[from] fem_beam::FemError),
    /// The moving-frame operator is singular at this speed (a resonance of the truncated domain).
    #[error("the moving-frame operator is singular at v = {speed} m/s (equation {equation})")]
    Singular {
        /// v (m/s).
        speed: f64,
        /// Where the factorisation met a zero pivot.
        equation: usize,
    },
}

impl StationaryError {
    /// Whether the error is the user's input.
    pub fn is_invalid_input(&self) -> bool {
        match self {
            StationaryError::InvalidField { .. }
            | StationaryError::InvalidChoice { .. }
            | StationaryError::NoRadiationCondition { .. } => true,
            StationaryError::Beam(e) => e.is_invalid_input(),
            StationaryError::Singular { .. } | StationaryError::Interrupted => false,
        }
    }
}

/// Result alias of this crate.
pub type Result<T, E = StationaryError> = std::result::Result<T, E>;

pub(crate) fn invalid(field: &'static str, value: f64, allowed: impl Into<String>) -> StationaryError {
    StationaryError::InvalidField { field, value, allowed: allowed.into() }
}
