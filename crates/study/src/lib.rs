//! # study: the studies, and the commands that compute more than one run (docs/theory.md §7–§14)
//!
//! The scenario and its checks are `scenario`'s; sweeps, journals, shards and cost are `runner`'s; typed run
//! summaries, files and figures are `report`'s. Here:
//!
//! - [`presets`]: the thirteen studies of the theory manual, with their figures and summaries.
//! - [`stationary`]: the stationary wave on the infinite track over speeds (continuation, error estimate, typed
//!   points, CSV, figures); [`co_moving`]: a run in a window that moves with the load.
//! - [`reference_check`]: the FE model against closed forms; [`steady_response`]: the infinite beam's steady state
//!   over speeds; [`metrics`]: dynamic amplification at a section.
//! - [`ground`]: the scenario's beam on its layered `[ground]` — Rayleigh modes, the Winkler control, the critical
//!   speed on the ground.
//! - [`receptance`]: the track's receptance and mobility over frequency, its resonances and report.
//! - Their reports ([`report::output::Output`]: text, JSON, CSV) in each folder's `text`, and [`reference_text`],
//!   [`steady_text`].

pub mod co_moving;
pub mod ground;
pub mod metrics;
pub mod presets;
pub mod receptance;
pub mod reference_check;
pub mod reference_text;
pub mod stationary;
pub mod steady_response;
pub mod steady_text;
