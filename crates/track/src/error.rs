//! The error type of the `track` crate: the engine's errors and the beam layer's, one type.

use thiserror::Error;

/// What can go wrong when setting up or running a load across the track.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrackError {
    /// An error of the engine: a setting out of range, an unconverged or non-finite step, a solver failure.
    #[error(transparent)]
    Engine(#[from] nscd::NscdError),
    /// An error from the beam layer.
    #[error(transparent)]
    Beam(#[from] fem_beam::FemError),
    /// A rail profile or wheel flat out of range.
    #[error(transparent)]
    Irregularity(#[from] irregularity::IrregularityError),
    /// A setting of this crate out of range (the friction on the beam, the load, the run); names the field, the value
    /// and what is allowed.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// Setting name, e.g. `devices.force`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// A choice that does not fit the rest of the run (a solver that cannot take its interactions).
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidChoice {
        /// Setting name, e.g. `solver`.
        field: &'static str,
        /// The choice, by its name.
        value: &'static str,
        /// What is allowed.
        allowed: String,
    },
    /// The beam has no static equilibrium on its unilateral supports (nothing holds it, or the contact set does not
    /// settle).
    #[error("no static equilibrium on the unilateral foundation: {reason}")]
    NoStaticEquilibrium {
        /// Why, in words.
        reason: String,
    },
    /// A count out of range.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidCount {
        /// Setting name, e.g. `devices.count`.
        field: &'static str,
        /// The offending value.
        value: usize,
        /// What is allowed.
        allowed: String,
    },
}

impl From<banded::BandedError> for TrackError {
    fn from(error: banded::BandedError) -> Self {
        TrackError::Engine(error.into())
    }
}

impl TrackError {
    /// A beam-layer error about a setting of a run (a field or a count, e.g. `distributed.subdivisions`) as this
    /// crate's own, so that the layers above name it by its place in their input as they name this crate's settings;
    /// any other beam error as it is.
    pub fn setting(error: fem_beam::FemError) -> Self {
        match error {
            fem_beam::FemError::InvalidField { field, value, allowed } => {
                TrackError::InvalidField { field, value, allowed: allowed.into() }
            }
            fem_beam::FemError::InvalidCount { field, value, allowed } => {
                TrackError::InvalidCount { field, value, allowed: allowed.into() }
            }
            other => other.into(),
        }
    }

    /// Whether the error is the user's input rather than a failure of the run; each layer answers for its own.
    pub fn is_invalid_input(&self) -> bool {
        match self {
            TrackError::Engine(e) => e.is_invalid_input(),
            TrackError::Beam(e) => e.is_invalid_input(),
            TrackError::Irregularity(_)
            | TrackError::InvalidField { .. }
            | TrackError::InvalidChoice { .. }
            | TrackError::InvalidCount { .. }
            | TrackError::NoStaticEquilibrium { .. } => true,
        }
    }
}

/// A setting of this crate out of range ([`TrackError::InvalidField`]): the field, its value, what is allowed.
pub(crate) fn invalid(field: &'static str, value: f64, allowed: impl Into<String>) -> TrackError {
    TrackError::InvalidField { field, value, allowed: allowed.into() }
}

/// Result alias of this crate.
pub type Result<T, E = TrackError> = std::result::Result<T, E>;
