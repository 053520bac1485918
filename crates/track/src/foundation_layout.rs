//! The unilateral part of a nonlinear foundation placed on the beam (docs/theory.md §13). A foundation of law
//! tensionless or bilinear resists with k_c in compression and k_t = α·k_c in tension: K holds k_t
//! ([`fem_beam::Foundation::tension_stiffness`]) and the rest, (k_c − k_t)⟨−w⟩₊ per unit length, is a compliant
//! unilateral law at the sections of [`crate::section_quadrature`], stiffness k_s = (k_c − k_t)·weight_s (N/m) —
//! so it goes through the one interaction engine, alone or beside ballast friction.
//!
//! The rail's self-weight q = ρA·g is kept (with a nonlinear law the static settlement q/k_c decides where the rail
//! lifts off): [`crate::unilateral_statics::settle`] places the sections in the static state q_s under it, as their
//! gaps g₀ₛ = H_s q_s, and the run's preload f₀ = P − K q_s keeps q = 0 (the state a run reports deflections from) in
//! equilibrium.

use crate::error::Result;
use crate::placed::{PlacedInteractions, SectionKind};
use crate::section_quadrature::{self, Quadrature, QuadratureSection};
use crate::unilateral_statics::settle;
use fem_beam::BeamModel;
use friction::Law;

/// The sections of a nonlinear foundation and its self-weight.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoundationSections {
    /// Sub-intervals per element J. Default 1.
    pub subdivisions: usize,
    /// Quadrature rule. Default Gauss: four sections per sub-interval, whose springs sum to the consistent
    /// foundation matrix, so that a soil the rail never leaves is the linear foundation to round-off.
    pub quadrature: Quadrature,
    /// Whether the rail's self-weight ρA·g rests on the soil. Default true.
    pub self_weight: bool,
}

impl Default for FoundationSections {
    fn default() -> Self {
        Self { subdivisions: 1, quadrature: Quadrature::Gauss, self_weight: true }
    }
}

impl FoundationSections {
    /// Check the parameters.
    pub fn validate(&self) -> Result<()> {
        section_quadrature::validate_subdivisions("foundation.subdivisions", self.subdivisions, self.quadrature)
    }

    /// The sections of `model`'s foundation, placed in the static state under the self-weight (kind
    /// [`SectionKind::Foundation`]), with the preload that holds it; none for a linear foundation, which K holds
    /// whole.
    pub fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        self.validate()?;
        let foundation = model.foundation();
        if foundation.law.is_linear() {
            return Ok(PlacedInteractions::new());
        }
        let unilateral = foundation.unilateral_stiffness();
        let mut untouched = PlacedInteractions::new();
        for QuadratureSection { row, weight, x } in
            section_quadrature::sections(model, self.subdivisions, self.quadrature)
        {
            untouched.push(
                row,
                Law::Soil { gap: 0.0, stiffness: unilateral * weight, damping: 0.0 },
                x,
                SectionKind::Foundation,
            );
        }
        if !self.self_weight {
            return Ok(untouched);
        }
        Ok(settle(model, untouched, &model.self_weight()?)?.0)
    }
}
