//! # banded: the linear algebra under frictrack
//!
//! The bottom layer: matrices of a 1-D finite-element mesh are symmetric and banded (half-bandwidth 3 for Hermite
//! beam elements in the DOF order (w₀, θ₀, w₁, θ₁, …)). Everything the layers above need of them, and nothing about
//! beams (docs/theory.md §3, §5):
//!
//! - [`symmetric`]: [`SymmetricBanded`] storage and its [`BandedLdlt`] factorisation (factor once, solve many
//!   times, O(n·b²) and O(n·b)), principal submatrices and the Schur condensation of leading or trailing blocks.
//! - [`local_refactor`]: the factor brought up to date in place after a few rows of A changed, only as far as the
//!   change reaches ([`BandedLdlt::refactor_rows_from`]).
//! - [`local_solve`]: A⁻¹h for a right-hand side of a few neighbouring non-zeros, computed only where it is
//!   significant ([`BandedLdlt::solve_local`]).
//! - [`selected_inverse`]: the entries of A⁻¹ inside the band in O(n·b²) ([`BandedLdlt::inverse_band`]), for the
//!   Delassus diagonal of many short rows.
//! - [`general`]: [`GeneralBanded`] non-symmetric banded matrices and their LU with partial pivoting
//!   ([`GeneralLu`]), for the moving-frame operator of the stationary wave.
//! - [`diagonals`]: [`BandDiagonals`], the band as diagonals for fast products.
//! - [`block_rows`]: [`BlockRows`], rows of at most four nonzeros (consecutive, or spread within the band) and the products H x, Hᵀs and
//!   A + Hᵀ diag(d) H, four entries at a time.

pub mod block_rows;
pub mod bordered;
pub mod diagonals;
pub mod error;
pub mod general;
pub mod local_refactor;
pub mod local_solve;
pub mod selected_inverse;
pub mod symmetric;

pub use block_rows::BlockRows;
pub use bordered::BorderedLdlt;
pub use diagonals::BandDiagonals;
pub use error::{BandedError, Result};
pub use general::{GeneralBanded, GeneralLu};
pub use local_solve::LocalVector;
pub use symmetric::{BandedLdlt, SymmetricBanded};
