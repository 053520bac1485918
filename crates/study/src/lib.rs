//! # study: the studies, and the commands that compute more than one run (docs/theory.md §7–§14)
//!
//! The scenario and its checks are `scenario`'s; sweeps, journals, shards and cost are `runner`'s; typed run
//! summaries, files and figures are `report`'s. Here:
//!
//! - [`presets`]: the nine studies of the theory manual, with their figures and summaries.
//! - [`stationary_output`]: the stationary wave on the infinite track over speeds (continuation, error estimate,
//!   typed points; CSV in [`stationary_csv`], figures in [`stationary_figures`]); [`co_moving_output`]: a run in a
//!   window that moves with the load (figures in [`co_moving_figures`]).
//! - [`reference_check`]: the FE model against closed forms; [`steady_response`]: the infinite beam's steady state
//!   over speeds; [`metrics`]: dynamic amplification at a section.
//! - [`receptance`]: the track's receptance and mobility over frequency, its resonances ([`receptance_peaks`]) and
//!   report ([`receptance_text`]).
//! - Their reports ([`report::output::Output`]: text, JSON, CSV): [`stationary_text`], [`co_moving_text`],
//!   [`reference_text`], [`steady_text`].

pub mod co_moving_figures;
pub mod co_moving_output;
pub mod co_moving_text;
pub mod metrics;
pub mod presets;
pub mod receptance;
pub mod receptance_peaks;
pub mod receptance_text;
pub mod reference_check;
pub mod reference_text;
pub mod stationary_csv;
pub mod stationary_figures;
pub mod stationary_output;
pub mod stationary_text;
pub mod steady_response;
pub mod steady_text;
