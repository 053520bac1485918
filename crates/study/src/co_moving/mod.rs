//! A run in a window that moves with the load (docs/theory.md §14): the window sized from the wave's decay, the run
//! and its settling ([`output`]), its figures ([`figures`]) and report ([`text`]).

pub mod figures;
pub mod output;
pub mod text;
