//! The drift b of a compliant law's row in the step (docs/theory.md §9, §13): a spring whose force is implicit in the
//! penetration at the step's end is the complementarity 0 ≤ p ⊥ p/c + U_{k+1} + b ≥ 0, b carrying the penetration
//! it starts from. Velocities in m/s, penetrations in m, h in s.

use crate::step::{RowStart, StepWeights};

/// The drift of a spring law whose force is implicit in the penetration at the step's end (docs/theory.md §9):
/// b = b_r − (δ_k − h(1−θ)U_k)/(hθ) for the penetration δ_k (m) its spring starts from, U_k (m/s) and b_r (m/s).
#[inline]
pub fn compliant_drift(penetration: f64, u: f64, rheonomic: f64, h: f64, theta: f64) -> f64 {
    rheonomic - (penetration - h * (1.0 - theta) * u) / (h * theta)
}

/// The drift of the unilateral Kelvin–Voigt soil (docs/theory.md §13), whose impulse is p = h(kδ_w + cδ̇_w) where
/// the scheme's forces act: δ_w = δ_k − w·HΔq with HΔq = h[(1−θ)U_k + θU_{k+1}] and δ̇_w = −[wU_{k+1} + (1−w)Hv_k]
/// (w = θ for the θ-method, αf for the generalized-α; θ the weight of U_{k+1} in the step's displacement). With
/// a = hw(hθk + c) this is 0 ≤ p ⊥ p/a + U_{k+1} + b ≥ 0 with
/// b = b_r − [hkδ_k − h(hkw(1−θ)U_k + c(1−w)Hv_k)]/a, for the penetration δ_k = −g_k (m), stiffness k (N/m) and
/// damping c (N·s/m). While it presses the soil is then the foundation's own K and C.
#[inline]
pub fn soil_drift(start: RowStart, weights: StepWeights, stiffness: f64, damping: f64) -> f64 {
    let RowStart { gap, velocity: u, current, rheonomic } = start;
    let StepWeights { step: h, theta, force: w } = weights;
    let (k, c) = (stiffness, damping);
    let a = h * w * (h * theta * k + c);
    rheonomic - (h * k * (-gap) - h * (h * k * w * (1.0 - theta) * u + c * (1.0 - w) * current)) / a
}
