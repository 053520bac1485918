//! # study: scenarios, speed sweeps, critical speed, optimal device force (docs/theory.md §7)
//!
//! - [`scenario`]: the TOML scenario format (every key optional, defaults = the reference case) and its validation.
//! - [`sweep`]: speed sweeps run in parallel with results in speed order, identical for any thread count; the
//!   critical speed refined below the sweep step on fresh runs; the optimal device force at a fixed speed.
//! - [`shard`]: a deterministic 1/N of a sweep's points per machine, and the merge of the shards' outputs.
//! - [`journal`]: every finished run on disk at once, so that an interrupted sweep resumes where it stopped.
//! - [`track_profile`]: a sample of a random rail profile with its periodogram against the target spectrum.

pub mod axis_grid;
pub mod co_moving_output;
pub mod columns;
pub mod cost;
pub mod diagnostics;
pub mod error;
pub mod figures;
pub mod journal;
pub mod mesh_ripple;
pub mod metrics;
pub mod number;
pub mod overrides;
pub mod plausibility;
pub mod plot;
pub mod presets;
pub mod reference_check;
pub mod run_output;
pub mod run_summary;
pub mod scenario;
pub mod shard;
pub mod soil_output;
pub mod speeds;
pub mod stationary_csv;
pub mod stationary_output;
pub mod steady_response;
pub mod sweep;
pub mod sweep_figures;
pub mod tables;
pub mod track_profile;
pub mod trains;
pub mod typeset;
pub mod vehicle_output;

pub use error::{Result, StudyError};
pub use journal::Journal;
pub use scenario::{Case, Scenario};
pub use sweep::{CriticalSpeed, OptimalForce, PeakLocation, SweepPoint};
