//! Study 9 (docs/theory.md §14): the stationary wave on the infinite track over speeds beside the finite beam's
//! curves — the run (`study`), the infinite track's curves and their peaks (`curves`), the figures.

mod curves;
mod figures;
mod study;

pub(super) use study::{overrides, study};
