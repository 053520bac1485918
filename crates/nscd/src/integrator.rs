//! The one-step integrator's data (docs/theory.md §5): the θ-method's step h and θ, and its iteration matrix
//! M̂ = M + hθC + h²θ²K, which the stepper's free velocity and the interaction problem's W = H M̂⁻¹Hᵀ both use.

use crate::error::{NscdError, Result};
use crate::system::LinearSystem;
use banded::{BandedLdlt, SymmetricBanded};
use std::sync::Arc;

/// Integration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Integration {
    /// θ ∈ [½, 1]. Default ½ (no numerical dissipation of the linear part).
    pub theta: f64,
    /// Time step h (s) > 0.
    pub step: f64,
}

impl Integration {
    /// Check θ and h.
    pub fn validate(&self) -> Result<()> {
        if !(self.theta.is_finite() && (0.5..=1.0).contains(&self.theta)) {
            return Err(NscdError::InvalidField {
                field: "integration.theta",
                value: self.theta,
                allowed: "must lie in [0.5, 1]".into(),
            });
        }
        if !(self.step.is_finite() && self.step > 0.0) {
            return Err(NscdError::InvalidField {
                field: "integration.step",
                value: self.step,
                allowed: "must be finite and > 0 (s)".into(),
            });
        }
        Ok(())
    }
}

/// M̂ = M + hθC + h²θ²K.
pub fn iteration_matrix(system: &LinearSystem, integration: Integration) -> SymmetricBanded {
    let (h, theta) = (integration.step, integration.theta);
    SymmetricBanded::linear_combination(&[
        (1.0, &system.mass),
        (h * theta, &system.damping),
        (h * h * theta * theta, &system.stiffness),
    ])
}

/// The one-step integrator's matrix: M̂ for one [`Integration`] and its LDLᵀ factors, made together so that they
/// cannot be mismatched. Shared (read-only) by the stepper, for the free velocity, and by the interaction problem,
/// for W = H M̂⁻¹Hᵀ and the impulses' responses.
#[derive(Debug)]
pub struct IterationMatrix {
    /// The step h and θ M̂ is built for.
    pub integration: Integration,
    /// M̂ = M + hθC + h²θ²K.
    pub m_hat: SymmetricBanded,
    /// LDLᵀ factors of M̂.
    pub factor: BandedLdlt,
}

impl IterationMatrix {
    /// M̂ of `system` for `integration`, factored.
    pub fn new(system: &LinearSystem, integration: Integration) -> Result<Arc<Self>> {
        Self::of(iteration_matrix(system, integration), integration)
    }

    /// A given SPD matrix `m_hat` (e.g. a test problem) as the iteration matrix of `integration`, factored.
    pub fn of(m_hat: SymmetricBanded, integration: Integration) -> Result<Arc<Self>> {
        let factor = m_hat.factor()?;
        Ok(Arc::new(Self { integration, m_hat, factor }))
    }

    /// Number of DOFs n.
    pub fn order(&self) -> usize {
        self.m_hat.order()
    }
}
