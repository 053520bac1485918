//! # friction: Coulomb friction on the rail (docs/theory.md §4)
//!
//! A friction device with maximal force F_u on a section of velocity u applies r ∈ −F_u·Sign(u): stuck while
//! |r| ≤ F_u, slipping with |r| = F_u against the motion. Discrete devices and friction distributed in the ballast
//! both reduce to one [`ContactSet`]: rows H_j (section velocity u_j = H_j q̇ over the free DOFs) and bounds F_j
//! (N); the generalised friction force is Hᵀr.
//!
//! - [`coulomb`]: the set-valued law as a projection, and a residual measuring how far (u, p) is from it.
//! - [`contact`]: the contact set and its sparse rows.
//! - [`devices`], [`distributed`]: builders for discrete devices and for distributed friction on a beam mesh.

pub mod contact;
pub mod coulomb;
pub mod devices;
pub mod distributed;
pub mod error;

pub use contact::{ContactKind, ContactRow, ContactSet};
pub use devices::{DeviceLayout, Devices};
pub use distributed::{DistributedFriction, Quadrature};
pub use error::{FrictionError, Result};
