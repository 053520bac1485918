//! Errors of this crate: an input out of range, named by its field.

/// What went wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IrregularityError {
    /// A value out of its range.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidField {
        /// The field, e.g. `band`.
        field: String,
        /// The value, as text.
        value: String,
        /// What is allowed.
        allowed: String,
    },
}

/// Result alias of this crate.
pub type Result<T, E = IrregularityError> = std::result::Result<T, E>;

/// An [`IrregularityError::InvalidField`].
pub(crate) fn invalid(field: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> IrregularityError {
    IrregularityError::InvalidField { field: field.into(), value: value.to_string(), allowed: allowed.into() }
}
