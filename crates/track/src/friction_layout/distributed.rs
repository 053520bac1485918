//! Distributed (ballast) friction of f_u newtons per metre (docs/theory.md §4): a Coulomb law at each section of
//! [`crate::section_quadrature`] with the bound F_s = f_u·weight_s, total capacity f_u·L.

use crate::error::{Result, TrackError};
use crate::placed::{PlacedInteractions, SectionKind};
use crate::section_quadrature;
use fem_beam::BeamModel;
use friction::Law;

pub use fem_beam::DistributedFriction;

/// Ballast friction placed on a beam: a Coulomb law at each of J·n_e + 1 sections with the bound f_u·weight_s.
pub trait BallastOnBeam {
    /// The contact set on the mesh of `model`: J·n_e + 1 sections in order of x, minus those on supports.
    fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions>;
}

impl BallastOnBeam for DistributedFriction {
    fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        self.validate().map_err(TrackError::friction)?;
        let mut set = PlacedInteractions::new();
        for section in section_quadrature::sections(model, self.subdivisions, self.quadrature) {
            let law = Law::Coulomb { capacity: self.force_per_length * section.weight };
            set.push(section.row, law, section.x, SectionKind::Ballast);
        }
        Ok(set)
    }
}
