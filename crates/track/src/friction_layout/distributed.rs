//! Distributed (ballast) friction of f_u newtons per metre (docs/theory.md §4): a Coulomb law at each section of
//! [`crate::section_quadrature`] with the bound F_s = f_u·weight_s, total capacity f_u·L.

use crate::error::{Result, TrackError};
use crate::placed::{PlacedInteractions, SectionKind};
use crate::section_quadrature::{self, Quadrature};
use fem_beam::BeamModel;
use friction::Law;

/// Friction distributed along the whole beam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistributedFriction {
    /// Maximal friction force per unit length f_u (N/m), ≥ 0. Studies use 0–10 kN/m.
    pub force_per_length: f64,
    /// Sub-intervals per element J ≥ 1. Default 4.
    pub subdivisions: usize,
    /// Quadrature rule. Default trapezoid.
    pub quadrature: Quadrature,
}

impl Default for DistributedFriction {
    fn default() -> Self {
        Self { force_per_length: 0.0, subdivisions: 4, quadrature: Quadrature::Trapezoid }
    }
}

impl DistributedFriction {
    /// f_u (N/m) with the default J = 4 and trapezoid weights.
    pub fn new(force_per_length: f64) -> Self {
        Self { force_per_length, ..Self::default() }
    }

    /// Check the parameters.
    pub fn validate(&self) -> Result<()> {
        if !(self.force_per_length.is_finite() && self.force_per_length >= 0.0) {
            return Err(TrackError::InvalidField {
                field: "distributed.force_per_length",
                value: self.force_per_length,
                allowed: "must be finite and ≥ 0 (N/m)".into(),
            });
        }
        section_quadrature::validate_subdivisions("distributed.subdivisions", self.subdivisions, self.quadrature)?;
        Ok(())
    }

    /// The most sub-intervals per element accepted (checked before the sections are allocated).
    pub const MAX_SUBDIVISIONS: usize = section_quadrature::MAX_SUBDIVISIONS;

    /// The contact set on the mesh of `model`: J·n_e + 1 sections in order of x, minus those on supports.
    pub fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        self.validate()?;
        let mut set = PlacedInteractions::new();
        for section in section_quadrature::sections(model, self.subdivisions, self.quadrature) {
            let law = Law::Coulomb { capacity: self.force_per_length * section.weight };
            set.push(section.row, law, section.x, SectionKind::Ballast);
        }
        Ok(set)
    }
}
