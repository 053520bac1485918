//! The six studies of docs/theory.md §7, the train study of §10, the vehicle study of §12 and the infinite track's
//! stationary wave of §14 as named presets. Each returns its data as CSV
//! (long format, one row per point, SI units), a JSON summary (critical speeds, peaks, optimal forces) and a few
//! human-readable summary lines.
//! All runs of a study share one rayon pool; results do not depend on the thread count.
//!
//! One file per study, each with the two sentences of its report section (its headline) written from its own typed
//! results; `curves` holds the families of speed sweeps that three of them share.

mod amplification;
mod curves;
mod discrete_speed;
mod discrete_track;
mod discrete_vs_distributed;
mod distributed_speed;
mod equal_cost;
pub mod hslm;
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
mod study_data;

pub use preset::Preset;
pub use resolution::Resolution;
pub use run::run_preset;
pub use study_data::{StudyData, StudyFailure, StudySummary};
pub use study_file::{SolverStatisticsNote, StudyFile};

use run::{as_long_track, blank, mean_iterations, with_devices, with_distributed};
use study_data::{failed_runs, keep_finished, nothing_finished};
