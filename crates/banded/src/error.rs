//! The error type of the `banded` crate.

use thiserror::Error;

/// What can go wrong in banded linear algebra.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BandedError {
    /// A symmetric matrix that must be positive definite is not: the LDLᵀ factorisation met a pivot ≤ 0.
    #[error("matrix is not positive definite: pivot {pivot:e} at equation {index}")]
    NonPositivePivot {
        /// Equation where the factorisation failed.
        index: usize,
        /// The pivot found there.
        pivot: f64,
    },
    /// A general matrix is singular to working precision: LU found no pivot in a column.
    #[error("matrix is singular: no pivot for equation {index}")]
    Singular {
        /// Equation where the factorisation failed.
        index: usize,
    },
}

/// Result alias of this crate.
pub type Result<T, E = BandedError> = std::result::Result<T, E>;
