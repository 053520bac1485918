//! Beam elements: the Hermite cubic Euler–Bernoulli element ([`hermite`]) and the two-node Timoshenko element with
//! interdependent interpolation ([`timoshenko`]), which is the Hermite element at φ = 0.
//!
//! Element DOFs are ordered (w_a, θ_a, w_b, θ_b) for the element's left node a and right node b, with
//! w the deflection (m, positive upward) and θ the rotation (rad): θ = dw/dx for Euler–Bernoulli, the cross-section's
//! rotation ψ for Timoshenko.

pub mod hermite;
pub mod timoshenko;

/// A 4×4 element matrix in the element DOF order (w_a, θ_a, w_b, θ_b).
pub type ElementMatrix = [[f64; 4]; 4];

/// A 4-vector in the element DOF order (w_a, θ_a, w_b, θ_b).
pub type ElementVector = [f64; 4];

use crate::properties::Beam;

/// The element of a beam's mesh: its theory's shape functions and matrices at the element length. Euler–Bernoulli
/// evaluates [`hermite`] as it is (bit for bit); Timoshenko [`timoshenko`] at φ = 12EI/(κGA·l²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Element {
    /// The Hermite cubic of length `length` (m).
    Hermite {
        /// l (m).
        length: f64,
    },
    /// The interdependent-interpolation Timoshenko element of length `length` (m) and shear ratio `phi`.
    Timoshenko {
        /// l (m).
        length: f64,
        /// φ = 12EI/(κGA·l²).
        phi: f64,
    },
}

impl Element {
    /// The element of `beam` at length `l` (m).
    pub fn of(beam: &Beam, l: f64) -> Self {
        match beam.shear_stiffness() {
            None => Element::Hermite { length: l },
            Some(kga) => {
                Element::Timoshenko { length: l, phi: timoshenko::shear_ratio(beam.bending_stiffness(), kga, l) }
            }
        }
    }

    /// l (m).
    pub fn length(&self) -> f64 {
        match *self {
            Element::Hermite { length } | Element::Timoshenko { length, .. } => length,
        }
    }

    /// N_w(ξ): the deflection's shape functions at ξ ∈ [0, 1].
    pub fn shape(&self, xi: f64) -> ElementVector {
        match *self {
            Element::Hermite { length } => hermite::shape(xi, length),
            Element::Timoshenko { length, phi } => timoshenko::shape(xi, length, phi),
        }
    }

    /// dN_w/dx: the slope w′ at ξ (1/m for w).
    pub fn shape_dx(&self, xi: f64) -> ElementVector {
        match *self {
            Element::Hermite { length } => hermite::shape_dx(xi, length),
            Element::Timoshenko { length, phi } => timoshenko::shape_dx(xi, length, phi),
        }
    }

    /// ∫ N_w dx over [ξ₀, ξ₁]: the consistent loads of a unit uniform load on that part of the element.
    pub fn shape_integral(&self, xi0: f64, xi1: f64) -> ElementVector {
        match *self {
            Element::Hermite { length } => hermite::shape_integral(xi0, xi1, length),
            Element::Timoshenko { length, phi } => timoshenko::shape_integral(xi0, xi1, length, phi),
        }
    }

    /// The rotation row θ(ξ), work-conjugate to a point moment: w′ (Euler–Bernoulli), ψ (Timoshenko).
    pub fn rotation(&self, xi: f64) -> ElementVector {
        match *self {
            Element::Hermite { length } => hermite::shape_dx(xi, length),
            Element::Timoshenko { length, phi } => timoshenko::rotation(xi, length, phi),
        }
    }

    /// The curvature row κ(ξ) = dθ/dx (w″ for Euler–Bernoulli, ψ′ for Timoshenko): the bending moment is EI·κ·q.
    pub fn curvature(&self, xi: f64) -> ElementVector {
        match *self {
            Element::Hermite { length } => hermite::shape_dxx(xi, length),
            Element::Timoshenko { length, phi } => timoshenko::rotation_dx(xi, length, phi),
        }
    }

    /// The shear strain row γ = w′ − ψ, constant on the element: zero for Euler–Bernoulli, [`timoshenko::shear_strain`]
    /// for Timoshenko.
    pub fn shear_strain(&self) -> ElementVector {
        match *self {
            Element::Hermite { .. } => [0.0; 4],
            Element::Timoshenko { length, phi } => timoshenko::shear_strain(length, phi),
        }
    }

    /// The beam's stiffness at bending stiffness `ei` (N·m²), with shear for Timoshenko.
    pub fn stiffness(&self, ei: f64) -> ElementMatrix {
        match *self {
            Element::Hermite { length } => hermite::bending_stiffness(ei, length),
            Element::Timoshenko { length, phi } => timoshenko::stiffness(ei, length, phi),
        }
    }

    /// ∫μ N_wᵀN_w dx: a quantity μ per unit length acting on w — the mass ρA, a Winkler foundation's k_f or c_f.
    pub fn distributed(&self, per_length: f64) -> ElementMatrix {
        match *self {
            Element::Hermite { length } => hermite::consistent_mass(per_length, length),
            Element::Timoshenko { length, phi } => timoshenko::translational_mass(per_length, length, phi),
        }
    }

    /// The beam's mass: ∫ρA N_wᵀN_w dx, plus the rotary inertia ∫ρI N_ψᵀN_ψ dx for Timoshenko.
    pub fn mass(&self, beam: &Beam) -> ElementMatrix {
        let translational = self.distributed(beam.mass_per_length());
        match *self {
            Element::Hermite { .. } => translational,
            Element::Timoshenko { length, phi } => {
                hermite::combine(1.0, &translational, 1.0, &timoshenko::rotary_mass(beam.rotary_inertia(), length, phi))
            }
        }
    }
}
