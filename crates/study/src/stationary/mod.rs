//! The stationary wave on the infinite track over speeds (docs/theory.md §14): the study in continuation with its
//! error estimate and typed points ([`output`]), its CSV ([`csv`]), figures ([`figures`]) and report ([`text`]).

pub mod csv;
pub mod figures;
pub mod output;
pub mod text;
