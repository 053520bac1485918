//! The linear semi-discrete system M q̈ + C q̇ + K q = F(t) + Hᵀr that the stepper integrates.
//!
//! Kept independent of the beam so that the same stepper integrates any banded system: the beam on its foundation
//! ([`LinearSystem::from_beam`]) and, in tests, a single-DOF Coulomb oscillator.

use banded::SymmetricBanded;
use fem_beam::BeamModel;

/// Banded symmetric M (kg), C (N·s/m), K (N/m) over the free DOFs.
#[derive(Debug, Clone)]
pub struct LinearSystem {
    /// Mass matrix, SPD.
    pub mass: SymmetricBanded,
    /// Damping matrix, symmetric positive semi-definite.
    pub damping: SymmetricBanded,
    /// Stiffness matrix, symmetric positive semi-definite.
    pub stiffness: SymmetricBanded,
}

impl LinearSystem {
    /// The beam on its foundation.
    pub fn from_beam(model: &BeamModel) -> Self {
        Self { mass: model.mass().clone(), damping: model.damping().clone(), stiffness: model.stiffness().clone() }
    }

    /// Number of DOFs.
    pub fn dofs(&self) -> usize {
        self.mass.order()
    }

    /// Whether C has any non-zero entry (skips the viscous terms otherwise).
    pub fn has_damping(&self) -> bool {
        (0..self.damping.order()).any(|i| self.damping.get(i, i) != 0.0)
    }
}
