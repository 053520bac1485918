//! The error type of the `fem-beam` crate.

use thiserror::Error;

/// Everything that can go wrong when building or solving a beam model.
///
/// Every variant names what was wrong; no input to this crate makes it panic.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FemError {
    /// A parameter is out of its allowed range (or not finite).
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// Name of the parameter, e.g. `beam.youngs_modulus`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed, in words.
        allowed: &'static str,
    },
    /// A value of a train (an axle's or a patch's) is out of range; `path` names it, e.g. `axles[3].offset`.
    #[error("invalid {path} = {value}: {allowed}")]
    InvalidTrain {
        /// Which value, e.g. `axles[3].offset`.
        path: String,
        /// The offending value.
        value: f64,
        /// What is allowed, in words.
        allowed: &'static str,
    },
    /// A value of the ground's profile is out of range; `path` names it, e.g. `ground.layers[2].thickness`.
    #[error("invalid {path} = {value}: {allowed}")]
    InvalidGround {
        /// Which value, e.g. `ground.layers[2].thickness`.
        path: String,
        /// The offending value.
        value: f64,
        /// What is allowed, in words.
        allowed: String,
    },
    /// An integral or a series did not reach its tolerance within its budget: the number it would give is not
    /// trusted and is not returned.
    #[error("{what} did not converge: error estimate {reached:e} against the tolerance {asked:e}")]
    NotConverged {
        /// What was computed, with where (e.g. `the ground's strip integral at k_x = 0.3 rad/m, ω = 12 rad/s`).
        what: String,
        /// The error estimate reached (relative).
        reached: f64,
        /// The tolerance asked for (relative).
        asked: f64,
    },
    /// No train of the catalogue has this name.
    #[error("unknown train `{name}`, expected one of {known}")]
    UnknownTrain {
        /// The name asked for.
        name: String,
        /// The catalogue's names.
        known: String,
    },
    /// A count (elements, modes, …) is out of its allowed range.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidCount {
        /// Name of the parameter.
        field: &'static str,
        /// The offending value.
        value: usize,
        /// What is allowed, in words.
        allowed: &'static str,
    },
    /// A value of a `[[sleepers.exceptions]]` entry is out of range.
    #[error("invalid sleepers.exceptions[{exception}].{key} = {value}: {allowed}")]
    InvalidSleeper {
        /// Which exception (0-based, in the order given).
        exception: usize,
        /// Which key of it.
        key: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed, in words.
        allowed: String,
    },
    /// The frequency band of a band-limited response (`output.acceleration_band`, Hz) is not usable.
    #[error("invalid output.acceleration_band = {value}: {allowed}")]
    InvalidBand {
        /// The band as given ([`crate::modal_band::BandLimit`]'s words).
        value: String,
        /// What is allowed, in words.
        allowed: String,
    },
    /// A vector does not have the length the model expects.
    #[error("{what} has length {actual}, expected {expected}")]
    LengthMismatch {
        /// Which vector.
        what: &'static str,
        /// Its length.
        actual: usize,
        /// The expected length.
        expected: usize,
    },
    /// A symmetric matrix that must be positive definite is not: the LDLᵀ factorisation met a pivot ≤ 0.
    /// Typically a beam with no supports and no foundation (a rigid-body mode).
    #[error(
        "matrix is not positive definite: pivot {pivot:e} at equation {index} (is the beam free to move as a rigid body?)"
    )]
    NonPositivePivot {
        /// Equation (free-DOF index) where the factorisation failed.
        index: usize,
        /// The pivot found there.
        pivot: f64,
    },
    /// The closed-form infinite-beam steady state does not exist for these parameters (undamped at or above
    /// the critical speed: the response is unbounded or needs a radiation condition).
    #[error(
        "no bounded steady state at speed {speed} m/s with damping ratio {damping_ratio} (critical speed {critical_speed:.3} m/s): at or above the critical speed the foundation needs damping > 0"
    )]
    NoSteadyState {
        /// Load speed (m/s).
        speed: f64,
        /// Foundation damping ratio ζ = c_f / c_cr.
        damping_ratio: f64,
        /// Critical speed of the system (m/s).
        critical_speed: f64,
    },
}

impl FemError {
    /// Whether the error is the user's input (a parameter, a train, a speed without steady state) rather than a
    /// failure of the computation.
    pub fn is_invalid_input(&self) -> bool {
        matches!(
            self,
            FemError::InvalidField { .. }
                | FemError::InvalidCount { .. }
                | FemError::InvalidSleeper { .. }
                | FemError::NoSteadyState { .. }
                | FemError::InvalidTrain { .. }
                | FemError::InvalidGround { .. }
                | FemError::InvalidBand { .. }
                | FemError::UnknownTrain { .. }
        )
    }
}

impl From<banded::BandedError> for FemError {
    fn from(error: banded::BandedError) -> Self {
        match error {
            banded::BandedError::NonPositivePivot { index, pivot } => FemError::NonPositivePivot { index, pivot },
            // Only the general LU reports singularity, and no beam matrix is factored by it: a zero pivot.
            banded::BandedError::Singular { index } => FemError::NonPositivePivot { index, pivot: 0.0 },
        }
    }
}

/// Result alias of this crate.
pub type Result<T, E = FemError> = std::result::Result<T, E>;

/// Check that `value` is finite and strictly positive.
pub fn positive(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(FemError::InvalidField { field, value, allowed: "must be finite and > 0" })
    }
}

/// Check that `value` is finite and non-negative.
pub fn non_negative(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(FemError::InvalidField { field, value, allowed: "must be finite and ≥ 0" })
    }
}
