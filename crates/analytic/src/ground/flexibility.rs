//! The surface flexibility of a layered ground (docs/theory.md §19): the vertical displacement of the surface per
//! unit vertical load e^{i(ωt − kx)}, F_zz(k, ω) (m per Pa·m: m³/N per unit wavenumber), by the stiffness method —
//! the half-space's 2 × 2 stiffness condensed up through each (sub)layer, K ← K₁₁ − K₁₂(K₂₂ + K)⁻¹K₂₁, and F = K⁻¹.

use super::half_space::half_space_stiffness;
use super::layer::{blocks, inverse_or_nan, layer_stiffness, sublayers};
use super::profile::GroundProfile;
use num_complex::Complex64;

/// F_zz(k, ω) of `profile` at wavenumber `k` (rad/m, ≠ 0) and circular frequency `omega` (rad/s, ≥ 0): downward
/// displacement per downward load, complex (its imaginary part the energy carried away and lost).
pub fn surface_flexibility(profile: &GroundProfile, k: f64, omega: f64) -> Complex64 {
    let mut below = half_space_stiffness(&profile.half_space, k, omega);
    for layer in profile.layers.iter().rev() {
        let n = sublayers(&layer.material, layer.thickness, k, omega);
        let stiffness = layer_stiffness(&layer.material, layer.thickness / n as f64, k, omega);
        let [k11, k12, k21, k22] = blocks(&stiffness);
        for _ in 0..n {
            below = k11 - k12 * inverse_or_nan(k22 + below) * k21;
        }
    }
    inverse_or_nan(below)[(1, 1)]
}
