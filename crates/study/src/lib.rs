//! # study: scenarios, speed sweeps, critical speed, optimal device force (MODEL.md §7)
//!
//! - [`scenario`]: the TOML scenario format (every key optional, defaults = the reference case) and its validation.
//! - [`sweep`]: speed sweeps run in parallel with results in speed order, identical for any thread count; the
//!   critical speed refined below the sweep step on fresh runs; the optimal device force at a fixed speed.

pub mod error;
pub mod metrics;
pub mod plot;
pub mod presets;
pub mod scenario;
pub mod sweep;

pub use error::{Result, StudyError};
pub use scenario::{Case, Scenario};
pub use sweep::{CriticalSpeed, OptimalForce, SweepPoint};
