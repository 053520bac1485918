//! # study: the studies and what a run, a sweep or a study reports (docs/theory.md §7–§14)
//!
//! The scenario and its checks are `scenario`'s; sweeps, journals, shards and cost are `runner`'s. Here:
//!
//! - [`presets`]: the nine studies of the theory manual, with their figures and summaries.
//! - the typed results and files of one run ([`run_summary`], [`run_output`], [`vehicle_output`],
//!   [`co_moving_output`]), of a sweep ([`sweep_figures`]) and of the infinite track ([`stationary_output`]), and
//!   the checks of a run's result ([`result_warnings`]).
//! - [`plot`]: figures as PNG and SVG; [`track_profile`]: a sample of a random rail profile with its periodogram
//!   against the target spectrum.

pub mod axis_grid;
pub mod co_moving_output;
pub mod columns;
pub mod figures;
pub mod mesh_ripple;
pub mod metrics;
pub mod plot;
pub mod presets;
pub mod reference_check;
pub mod result_warnings;
pub mod run_output;
pub mod run_summary;
pub mod soil_output;
pub mod stationary_csv;
pub mod stationary_output;
pub mod steady_response;
pub mod sweep_figures;
pub mod tables;
pub mod track_profile;
pub mod typeset;
pub mod vehicle_output;
