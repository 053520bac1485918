//! # fem-beam: an Euler–Bernoulli or Timoshenko rail on a viscoelastic Winkler foundation
//!
//! The first layer of frictrack (docs/theory.md §2–§3, §15): Hermite cubic beam elements on [0, L] (or the
//! Timoshenko element of [`element::timoshenko`], which is Hermite's at φ = 0), the consistent mass
//! ρA·l/420·[…], bending stiffness EI/l³·[…] and consistent foundation stiffness/damping k_f·l/420·[…],
//! c_f·l/420·[…], assembled into symmetric banded matrices of half-bandwidth 3 over the DOFs left free by the
//! supports, for the semi-discrete equation M q̈ + C q̇ + K q = f. Units are SI; w is positive upward.
//!
//! - [`properties`]: [`Beam`] (E, I, A, ρ) and [`Foundation`] (k_f, c_f) with UIC60 / soft-soil defaults.
//! - [`mesh`], [`supports`]: the uniform mesh, end supports and the full ↔ free DOF map.
//! - [`element`]: Hermite and Timoshenko shape functions and element matrices; [`element_loop`]: the one loop
//!   that adds elements into a global matrix (real, complex, symmetric or not); [`assembly`]: the global
//!   [`BeamModel`]; [`discretisation`]: its mesh paired with its element, where loads and contacts act.
//! - Matrices are the `banded` crate's [`banded::SymmetricBanded`] (storage, LDLᵀ, Schur condensation), the layer
//!   below this one.
//! - [`load`]: consistent point forces/moments and uniform loads; [`section`]: w, θ, M from a DOF vector.
//! - [`distributed`]: the sections of a law distributed along the beam, and ballast friction's description.
//! - [`extreme`]: the [`Extreme`] and [`LiftOffZone`] every response is reported in.
//! - [`embankment`]: [`EmbankmentBeam`], a second beam under the sleepers' ballast (the two-beam track in time).
//! - [`statics`], [`modal`]: K q = f and K φ = ω² M φ; [`modal_band`]: a field's part in the modes below a frequency.
//! - [`motion`]: how the loads move — constant speed or a speed profile over position ([`Motion`]).
//!
//! The closed forms these elements are checked against live one floor up, in the `analytic` crate.

pub mod absorbing;
pub mod assembly;
#[cfg(feature = "serde")]
pub mod beam_keys;
pub mod discretisation;
pub mod distributed;
pub mod element;
pub mod element_loop;
pub mod embankment;
pub mod error;
pub mod extreme;
pub mod load;
pub mod mesh;
pub mod modal;
pub mod modal_band;
pub mod motion;
pub mod properties;
pub mod receptance;
pub mod section;
pub mod sleeper_exceptions;
pub mod sleepers;
pub mod statics;
pub mod supports;
pub mod train;

pub use absorbing::AbsorbingZones;
pub use assembly::BeamModel;
pub use discretisation::Discretisation;
pub use distributed::DistributedFriction;
pub use embankment::EmbankmentBeam;
pub use error::{FemError, Result};
pub use extreme::{DeflectionExtremes, Extreme, LiftOffZone};
pub use load::LoadVector;
pub use mesh::Mesh;
pub use motion::Motion;
pub use properties::{Beam, BeamTheory, Foundation, FoundationLaw, Rayleigh};
pub use sleeper_exceptions::{BallastContact, SleeperException};
pub use sleepers::{BallastBody, BayResonances, Layer, SleeperSupport, Sleepers};
pub use supports::{DofMap, Support, Supports};
pub use train::{Axle, Patch, Train};

/// Standard gravity g (m/s²), for self-weight.
pub const GRAVITY: f64 = 9.81;
