//! The thirteen studies of the theory manual as named presets: the thesis's six (docs/theory.md §7), the trains'
//! (§10), the vehicles' (§12), the stationary wave's (§14), the discrete track's three (§17, §18) and Ledsgård's on
//! the ground (§19). Each returns its data
//! as CSV (long format, one row per point, SI units), a typed JSON summary and a few human-readable lines; all runs
//! of a study share one rayon pool, and results do not depend on the thread count.
//!
//! - One file (or folder: `hslm`, `stationary_wave`) per study, each with the two sentences of its report section
//!   written from its own typed results; `curves` holds the families of speed sweeps three of them share,
//!   `discrete_track` the discrete track's set-up.
//! - The registry: [`Preset`] (`preset`) names the studies in order; `table` holds each one's row — name, title,
//!   what it sets, how it samples speeds, its run — and the accessors that read it; [`run_preset`] (`run`) runs one.
//! - What the studies share: [`StudyData`] and its typed [`StudySummary`] (`study_data`), the set-ups (`setups`),
//!   [`Resolution`] (`resolution`), the JSON beside the CSV ([`StudyFile`], `study_file`).

mod amplification;
mod curves;
mod discrete_speed;
mod discrete_track;
mod discrete_vs_distributed;
mod distributed_speed;
mod equal_cost;
pub mod hslm;
pub mod ledsgard;
mod optimal_force;
mod sleeper_friction;
mod stationary_wave;
mod study_file;
mod table;
mod track_receptance;
mod vehicle_speed;
mod voided_sleepers;

mod preset;
mod resolution;
mod run;
mod setups;
mod study_data;

pub use preset::Preset;
pub use resolution::Resolution;
pub use run::run_preset;
pub use study_data::{StudyData, StudyFailure, StudySummary};
pub use study_file::{SolverStatisticsNote, StudyFile};
