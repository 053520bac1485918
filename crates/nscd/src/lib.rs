//! # nscd: nonsmooth contact dynamics for frictrack (docs/theory.md §5, §6, §9)
//!
//! The Moreau–Jean θ-method integrates M q̈ + C q̇ + K q ∈ F(t) + Hᵀr, the interaction forces r set-valued (Coulomb
//! friction, rigid and compliant unilateral contact), with *impulses* per step found by a per-step solver of one box
//! QP, and an exact discrete energy balance. The engine knows systems, loads as forcings and interactions as rows
//! with laws; it knows no beam (the `track` crate above it runs a load across the beam).
//!
//! - [`system`]: the banded linear system, one block or several stacked, with their [`system::DofLayout`].
//! - [`forcing`]: the interface of external loads F(t).
//! - [`integrator`]: the θ-method's step and its iteration matrix M̂.
//! - [`problem`]: the one-step [`InteractionProblem`] and its update phase (the step's law from the state).
//! - [`moving`]: interactions whose rows are rebuilt every step (a wheel).
//! - [`position`]: the position projection of rigid moving contacts after each step.
//! - [`solver`]: projected Gauss–Seidel, a banded interior point, a parametric active set (homotopy) on a
//!   regularised Coulomb law, Clarabel (feature `clarabel`), chosen by [`solver_choice`], each ending a
//!   step with a [`step_report`].
//! - [`fallback`]: the other solvers, tried in turn on a step the run's solver cannot solve.
//! - [`stepper`]: [`MoreauJean`], one step at a time, with its [`EnergyLedger`] ([`ledger`]).

pub mod error;
pub mod fallback;
pub mod forcing;
pub mod integrator;
mod kernels;
pub mod ledger;
pub mod moving;
pub mod position;
pub mod problem;
pub mod solver;
pub mod solver_choice;
pub mod step_report;
pub mod stepper;
pub mod system;

pub use error::{NscdError, Result};
pub use forcing::Forcing;
pub use ledger::EnergyBalance;
pub use moving::{Interactions, MovingInteraction, MovingState};
pub use problem::{InteractionProblem, StepLaw, pack_rows};
pub use solver::{SolverKind, SolverSettings, StepReport, StepStatus, StepWork};
pub use stepper::{EnergyLedger, Integration, MoreauJean};
pub use system::{DofLayout, LinearSystem};
