//! # track: a load crossing the beam, on the nonsmooth engine (docs/theory.md §3, §6, §8)
//!
//! The application layer between the engine (`nscd`, which knows systems, interactions and steps but no beam) and the
//! studies: the beam on its foundation as a [`nscd::LinearSystem`] ([`system::beam_system`]), the moving point load
//! ([`MovingLoad`]), a whole run of the load across the beam ([`Simulation`]: the automatic solver choice from EI and
//! ρA, the steady-state start from the infinite beam's closed form, observers for extremes over the run and over a
//! window of load positions, histories at sections, W̄, solver statistics), snapshots of the whole beam, and vehicles
//! ([`vehicle`]: small linear systems with wheels, rolled over rigid ground with a rail profile).

pub mod co_moving;
pub mod error;
pub mod foundation_layout;
pub mod friction_layout;
pub mod moving_load;
pub mod placed;
pub mod section_quadrature;
pub mod simulation;
pub mod sleeper_layout;
pub mod snapshots;
pub mod statics;
pub mod system;
pub mod unilateral_statics;
pub mod vehicle;

pub use error::{Refused, Result, Setting, TrackError};
pub use foundation_layout::FoundationSections;
pub use friction_layout::{BallastOnBeam, DeviceLayout, Devices, DistributedFriction, Quadrature};
pub use moving_load::MovingLoad;
pub use placed::{PlacedInteractions, SectionKind};
pub use simulation::{InitialState, Load, RunResult, RunSettings, Simulation, WindowExtremes};
pub use snapshots::{Snapshot, SnapshotAt, SnapshotTaker};
