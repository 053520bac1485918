//! # runner: how the runs of sweeps and studies are carried out (docs/theory.md §7)
//!
//! - [`Runner`] (`pool`): speed sweeps on one thread pool; one run as a sweep point (`run_point`), the point itself
//!   ([`SweepPoint`], `sweep_point`) and the sweep's CSV with every column's unit (`sweep_csv`).
//! - The critical speed (`critical`, refined by `peak`) and the optimal device force (`optimal_force`).
//! - [`journal`]: every finished run on disk at once, so that an interrupted sweep resumes where it stopped.
//! - [`shard`]: a deterministic 1/N of a sweep's points per machine, and the merge of the shards' outputs.
//! - [`cost`]: what a run, a batch of runs or a stationary sweep will cost, said before it starts.
//!
//! A sweep runs one simulation per speed, in parallel on the runner's one thread pool; every run is independent and
//! deterministic and the results are returned in speed order, so the output is identical for any thread count.
//! The critical speed is the speed of the largest max downward deflection, refined below the sweep step by a
//! golden-section search on fresh runs inside the bracket around the sweep's maximum. The optimal device force for
//! fixed N and speed minimises the max downward deflection: a log-spaced scan of the bounds, then golden section
//! around the best scanned force; every evaluated force is returned with its value.

pub mod cost;
mod critical;
pub mod journal;
mod optimal_force;
mod peak;
mod pool;
mod run_point;
pub mod shard;
pub mod sleeper_columns;
mod sweep_csv;
mod sweep_point;

pub use critical::{CriticalSpeed, critical_speed};
pub use journal::Journal;
pub use optimal_force::{OptimalForce, log_spaced, optimal_device_force, refine_device_force, refine_from_scan};
pub use peak::{Metric, PeakLocation, RefinedPeak, refine_maximum, refinement_runs, unrefined};
pub use pool::{Runner, worker_threads};
pub use run_point::{run_point, simulate_observed};
pub use sleeper_columns::{SLEEPER_CSV_COLUMNS, SleeperColumns};
pub use sweep_csv::{
    BAND_CSV_COLUMNS, CSV_COLUMNS, csv_columns_of, csv_header, every_csv_column, write_csv, write_csv_rows,
};
pub use sweep_point::{FailedRun, SweepPoint, SweepRow, VEHICLE_CSV_COLUMNS, VehicleColumns, failures, finished};
