//! # nscd: nonsmooth contact dynamics for frictrack (docs/theory.md §5–§6)
//!
//! The Moreau–Jean θ-method integrates M q̈ + C q̇ + K q ∈ F(t) + R(q̇), the friction R set-valued, with friction
//! *impulses* per step found by a per-step solver, and an exact discrete energy balance.
//!
//! - [`system`], [`forcing`]: the banded linear system and the moving load.
//! - [`stepper`]: [`MoreauJean`], one step at a time, with its [`EnergyLedger`].
//! - [`solver`]: projected Gauss–Seidel, a banded interior point, Clarabel (feature `clarabel`).
//! - [`simulation`]: a whole run of the beam under a moving load, with its observers (extremes, histories at
//!   sections, the global norm W̄, solver statistics).

pub mod error;
pub mod forcing;
mod kernels;
pub mod problem;
pub mod simulation;
pub mod snapshots;
pub mod solver;
pub mod stepper;
pub mod system;

pub use error::{NscdError, Result};
pub use forcing::{Forcing, MovingLoad};
pub use simulation::{InitialState, RunResult, RunSettings, Simulation, WindowExtremes};
pub use snapshots::{Snapshot, SnapshotAt, SnapshotTaker};
pub use solver::{SolverKind, SolverSettings, StepReport, StepStatus};
pub use stepper::{EnergyLedger, Integration, MoreauJean};
pub use system::LinearSystem;
