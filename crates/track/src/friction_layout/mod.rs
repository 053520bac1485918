//! Friction placed on a beam mesh (docs/theory.md §4): discrete devices on nodes and friction distributed in the
//! ballast, each reduced to [`crate::PlacedInteractions`] — rows over the beam's free DOFs with a Coulomb law each,
//! placed at their sections, kinds [`crate::SectionKind::Device`] and [`crate::SectionKind::Ballast`].

pub mod devices;
pub mod distributed;

pub use crate::section_quadrature::Quadrature;
pub use devices::{DeviceLayout, Devices};
pub use distributed::{BallastOnBeam, DistributedFriction};
