//! The error type of the `friction` crate.

use thiserror::Error;

/// What can go wrong when building a contact set.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FrictionError {
    /// A parameter is out of range; names the field, the value and what is allowed.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// Parameter name, e.g. `devices.force`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// A count is out of range.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidCount {
        /// Parameter name.
        field: &'static str,
        /// The offending value.
        value: usize,
        /// What is allowed.
        allowed: String,
    },
    /// An error from the beam layer (e.g. a position outside the beam).
    #[error(transparent)]
    Beam(#[from] fem_beam::FemError),
}

/// Result alias of this crate.
pub type Result<T, E = FrictionError> = std::result::Result<T, E>;
