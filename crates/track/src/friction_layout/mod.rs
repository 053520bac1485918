//! Friction placed on a beam mesh (docs/theory.md §4): discrete devices on nodes and friction distributed in the
//! ballast, each reduced to the engine's [`friction::InteractionSet`] — rows over the beam's free DOFs with a
//! Coulomb law each, kinds [`friction::InteractionKind::Device`] and [`friction::InteractionKind::Ballast`].

pub mod devices;
pub mod distributed;

pub use devices::{DeviceLayout, Devices};
pub use distributed::{DistributedFriction, Quadrature};
