//! The one-step integrator's data (docs/theory.md §5): the step h and the scheme — the Moreau–Jean θ-method or the
//! first-order generalized-α — and the iteration matrix M̂ both schemes share in form, which the stepper's free
//! velocity and the interaction problem's W = H M̂⁻¹Hᵀ use.
//!
//! Both are members of one family (Jansen, Whiting & Hulbert 2000, applied to (q, v) as Kadapa, Dettmer & Perić 2017
//! do for structural dynamics): with the rates Q ≈ q̇ and A ≈ v̇ carried as state and X_{n+α} = (1−α)X_n + αX_{n+1},
//!
//! ```text
//! q_{n+1} = q_n + h[(1−γ)Q_n + γQ_{n+1}]          Q_{n+αm} = v_{n+αf}
//! v_{n+1} = v_n + h[(1−γ)A_n + γA_{n+1}]          M A_{n+αm} = F_{n+αf} − C v_{n+αf} − K q_{n+αf} + Hᵀr
//! ```
//!
//! γ = αm gives the θ-method with θ = αf (Δq = h v_θ, MΔv = h(F_θ − C v_θ − K q_θ) + Hᵀp: the rates drop out);
//! αm = ½(3 − ρ∞)/(1 + ρ∞), αf = 1/(1 + ρ∞), γ = ½ + αm − αf gives the generalized-α of spectral radius ρ∞ at
//! infinite frequency, second order for every ρ∞ ∈ [0, 1] (ρ∞ = 1: the trapezoidal rule, θ = ½).

use crate::error::{NscdError, Result};
use crate::system::LinearSystem;
use banded::{BandedLdlt, SymmetricBanded};
use std::sync::Arc;

/// The time-stepping scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scheme {
    /// The Moreau–Jean θ-method, θ ∈ [½, 1]: second order and non-dissipative at θ = ½, first order above.
    Theta(f64),
    /// The first-order generalized-α (Jansen, Whiting & Hulbert 2000) of spectral radius ρ∞ ∈ [0, 1] at infinite
    /// frequency: second order with the highest (unresolved) modes damped by the factor ρ∞ per step.
    GeneralizedAlpha {
        /// ρ∞ ∈ [0, 1]: 1 keeps every mode's energy (the trapezoidal rule), 0 annihilates the unresolved ones.
        spectral_radius: f64,
    },
}

/// The family's coefficients αm, αf, γ (see the module) and what the step derives from them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// αm: where the rates' equation is taken.
    pub alpha_m: f64,
    /// αf: where the forces act (θ of the θ-method): F, C v, K q and the interactions' work at t_{n+αf}.
    pub alpha_f: f64,
    /// γ: the rates' weight in the update of q and v.
    pub gamma: f64,
}

impl Coefficients {
    /// θ_e = γαf/αm: the weight of v_{n+1} in the step's displacement, Δq = h(d_n + θ_e v_{n+1}) (θ for the θ-method).
    pub fn position_weight(&self) -> f64 {
        self.gamma * self.alpha_f / self.alpha_m
    }

    /// Whether the rates Q and A are state (γ ≠ αm): false for the θ-method.
    pub fn has_rates(&self) -> bool {
        self.gamma != self.alpha_m
    }

    /// αm/γ: M̂'s factor over the θ-method's form, so that the impulse of the step stays p = h·r.
    pub fn mass_scale(&self) -> f64 {
        self.alpha_m / self.gamma
    }
}

impl Scheme {
    /// The scheme's αm, αf, γ.
    pub fn coefficients(&self) -> Coefficients {
        match *self {
            Scheme::Theta(theta) => Coefficients { alpha_m: 1.0, alpha_f: theta, gamma: 1.0 },
            Scheme::GeneralizedAlpha { spectral_radius: rho } => {
                let alpha_m = 0.5 * (3.0 - rho) / (1.0 + rho);
                let alpha_f = 1.0 / (1.0 + rho);
                Coefficients { alpha_m, alpha_f, gamma: 0.5 + alpha_m - alpha_f }
            }
        }
    }
}

impl std::fmt::Display for Scheme {
    /// The scheme as a report names it: "θ-method (θ = 0.5)" or "generalized-α (ρ∞ = 0.5)".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Scheme::Theta(theta) => write!(f, "θ-method (θ = {theta})"),
            Scheme::GeneralizedAlpha { spectral_radius } => write!(f, "generalized-α (ρ∞ = {spectral_radius})"),
        }
    }
}

/// Integration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Integration {
    /// The scheme. Default θ = ½ (no numerical dissipation of the linear part).
    pub scheme: Scheme,
    /// Time step h (s) > 0.
    pub step: f64,
}

impl Integration {
    /// The θ-method with step h (s).
    pub fn theta(theta: f64, step: f64) -> Self {
        Self { scheme: Scheme::Theta(theta), step }
    }

    /// Check the scheme's parameter and h.
    pub fn validate(&self) -> Result<()> {
        match self.scheme {
            Scheme::Theta(theta) if !(theta.is_finite() && (0.5..=1.0).contains(&theta)) => {
                return Err(NscdError::InvalidField {
                    field: "integration.theta",
                    value: theta,
                    allowed: "must lie in [0.5, 1]".into(),
                });
            }
            Scheme::GeneralizedAlpha { spectral_radius: rho } if !(rho.is_finite() && (0.0..=1.0).contains(&rho)) => {
                return Err(NscdError::InvalidField {
                    field: "integration.spectral_radius",
                    value: rho,
                    allowed: "must lie in [0, 1] (1: no numerical dissipation; 0: the unresolved modes removed)".into(),
                });
            }
            _ => {}
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

    /// The scheme's coefficients.
    pub fn coefficients(&self) -> Coefficients {
        self.scheme.coefficients()
    }

    /// The step's weights for the laws ([`friction::law::StepWeights`]): h, θ_e and αf.
    pub fn weights(&self) -> friction::law::StepWeights {
        let c = self.coefficients();
        friction::law::StepWeights { step: self.step, theta: c.position_weight(), force: c.alpha_f }
    }
}

/// M̂ = M + hθC + h²θ²K for the θ-method; (αm/γ)(M + hθ_eC + h²θ_e²K) for the generalized-α, so that a step's
/// impulse is p = h·r in both (docs/theory.md §5).
pub fn iteration_matrix(system: &LinearSystem, integration: Integration) -> SymmetricBanded {
    // The θ-method's scale is exactly 1 and θ_e = 1·θ/1 exactly θ: the same bits as M + hθC + h²θ²K.
    let (h, c) = (integration.step, integration.coefficients());
    let (scale, theta) = (c.mass_scale(), c.position_weight());
    SymmetricBanded::linear_combination(&[
        (scale, &system.mass),
        (scale * h * theta, &system.damping),
        (scale * h * h * theta * theta, &system.stiffness),
    ])
}

/// The one-step integrator's matrix: M̂ for one [`Integration`] and its LDLᵀ factors, made together so that they
/// cannot be mismatched. Shared (read-only) by the stepper, for the free velocity, and by the interaction problem,
/// for W = H M̂⁻¹Hᵀ and the impulses' responses.
#[derive(Debug)]
pub struct IterationMatrix {
    /// The step h and scheme M̂ is built for.
    pub integration: Integration,
    /// M̂ ([`iteration_matrix`]).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_theta_method_is_the_family_with_gamma_equal_to_alpha_m() {
        let c = Scheme::Theta(0.6).coefficients();
        assert!(!c.has_rates());
        assert_eq!((c.position_weight(), c.mass_scale(), c.alpha_f), (0.6, 1.0, 0.6));
    }

    #[test]
    fn generalized_alpha_coefficients_at_the_ends_of_its_range() {
        // ρ∞ = 1: αm = αf = γ = ½, the trapezoidal rule; ρ∞ = 0: αm = 3/2, αf = 1, γ = 1, θ_e = 2/3.
        let one = Scheme::GeneralizedAlpha { spectral_radius: 1.0 }.coefficients();
        assert_eq!((one.alpha_m, one.alpha_f, one.gamma), (0.5, 0.5, 0.5));
        let zero = Scheme::GeneralizedAlpha { spectral_radius: 0.0 }.coefficients();
        assert_eq!((zero.alpha_m, zero.alpha_f, zero.gamma), (1.5, 1.0, 1.0));
        assert!((zero.position_weight() - 2.0 / 3.0).abs() < 1e-15);
    }
}
