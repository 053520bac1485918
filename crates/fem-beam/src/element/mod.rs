//! Beam elements. Only the Hermite cubic Euler–Bernoulli element is provided ([`hermite`]).
//!
//! Element DOFs are ordered (w_a, θ_a, w_b, θ_b) for the element's left node a and right node b, with
//! w the deflection (m, positive upward) and θ = dw/dx the rotation (rad).

pub mod hermite;

/// A 4×4 element matrix in the element DOF order (w_a, θ_a, w_b, θ_b).
pub type ElementMatrix = [[f64; 4]; 4];

/// A 4-vector in the element DOF order (w_a, θ_a, w_b, θ_b).
pub type ElementVector = [f64; 4];
