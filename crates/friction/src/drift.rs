//! The drift b of a compliant law's row in the step (docs/theory.md §9, §13): a spring whose force is implicit in the
//! penetration at the step's end is the complementarity 0 ≤ p ⊥ p/c + U_{k+1} + b ≥ 0, b carrying the penetration
//! it starts from. Velocities in m/s, penetrations in m, h in s.

/// The drift of a spring law whose force is implicit in the penetration at the step's end (docs/theory.md §9):
/// b = b_r − (δ_k − h(1−θ)U_k)/(hθ) for the penetration δ_k (m) its spring starts from, U_k (m/s) and b_r (m/s).
pub fn compliant_drift(penetration: f64, u: f64, rheonomic: f64, h: f64, theta: f64) -> f64 {
    rheonomic - (penetration - h * (1.0 - theta) * u) / (h * theta)
}

/// The drift of the soil's spring, whose force is k⟨δ_w⟩₊ where the scheme's forces act, δ_w = δ_k − w·HΔq with
/// HΔq = h[(1−θ)U_k + θU_{k+1}] (docs/theory.md §13; w = θ for the θ-method, αf for the generalized-α, θ the weight
/// of U_{k+1} in the step's displacement): 0 ≤ p ⊥ p/(h²wθk) + U_{k+1} + b ≥ 0 with
/// b = b_r − (δ_k − hw(1−θ)U_k)/(hwθ), for the penetration δ_k (m), U_k (m/s) and b_r (m/s); a positive impulse is
/// p = hkδ_w. The soil is then the foundation's own stiffness K where it is pressed.
pub fn soil_drift(penetration: f64, u: f64, rheonomic: f64, h: f64, theta: f64, weight: f64) -> f64 {
    rheonomic - (penetration - h * weight * (1.0 - theta) * u) / (h * weight * theta)
}
