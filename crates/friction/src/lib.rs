//! # friction: the nonsmooth laws and the friction interactions (docs/theory.md §4, §9)
//!
//! A friction device with maximal force F_u on a section of velocity u applies r ∈ −F_u·Sign(u): stuck while
//! |r| ≤ F_u, slipping with |r| = F_u against the motion. Discrete devices and friction distributed in the ballast
//! both reduce to an [`InteractionSet`]: rows H_α (the relative velocity U_α = H_α q̇ over the free DOFs) with a
//! [`Law`] each — Coulomb friction, rigid (Signorini) contact with Newton impact, or a compliant unilateral stop;
//! the generalised force is Hᵀr.
//!
//! - [`law`]: the one law of every interaction (an impulse in [lo, hi] against its velocity) as a projection, and
//!   its natural residual.
//! - [`interaction`]: interaction sets, their sparse rows, laws and kinds.
//! - [`devices`], [`distributed`]: builders for discrete devices and for distributed friction on a beam mesh.

pub mod devices;
pub mod distributed;
pub mod error;
pub mod interaction;
pub mod law;

pub use devices::{DeviceLayout, Devices};
pub use distributed::{DistributedFriction, Quadrature};
pub use error::{FrictionError, Result};
pub use interaction::{InteractionKind, InteractionRow, InteractionSet, Law};
