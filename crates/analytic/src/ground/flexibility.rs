//! The surface flexibility of a layered ground (docs/theory.md §19): the vertical displacement of the surface per
//! unit vertical load e^{i(ωt − kx)}, F_zz(k, ω) (m per Pa·m: m³/N per unit wavenumber), by the stiffness method —
//! the half-space's 2 × 2 stiffness condensed up through each (sub)layer, K ← K₁₁ − K₁₂(K₂₂ + K)⁻¹K₂₁, and F = K⁻¹.
//!
//! A short wave does not reach deep: below the depth where its slowest-decaying part, the shear wave
//! e^{−z·Re√(k² − ω²/C_s*²)}, has fallen by e^{−DEPTH_REACH}, what lies there returns to the surface as e^{−2·DEPTH_REACH}
//! (≈ 2e-35) and is replaced by a half-space of the material at that depth. This bounds the sublayers of short waves
//! (|k|h ≤ 1 each) by about DEPTH_REACH, whatever the layers' thickness.

use super::half_space::{decaying_root, half_space_stiffness};
use super::layer::{blocks, inverse_or_nan, layer_stiffness, sublayers};
use super::profile::{GroundProfile, SoilMaterial};
use nalgebra::Matrix2;
use num_complex::Complex64;

/// How many e-folds of the slowest evanescent wave the surface sees into the ground.
pub const DEPTH_REACH: f64 = 40.0;

/// F_zz(k, ω) of `profile` at wavenumber `k` (rad/m, ≠ 0) and circular frequency `omega` (rad/s, ≥ 0): downward
/// displacement per downward load, complex (its imaginary part the energy carried away and lost).
pub fn surface_flexibility(profile: &GroundProfile, k: f64, omega: f64) -> Complex64 {
    inverse_or_nan(surface_stiffness(profile, k, omega))[(1, 1)]
}

/// The 2 × 2 stiffness of the ground's surface, tractions per displacement (u, w) e^{i(ωt − kx)} (Pa/m): singular
/// where a free surface wave (a Rayleigh mode) travels at ω/k.
pub fn surface_stiffness(profile: &GroundProfile, k: f64, omega: f64) -> Matrix2<Complex64> {
    condensed(profile, k, omega, |_| ())
}

/// The surface stiffness, each pivot block K₂₂ + K_below of the condensation handed to `pivot` on the way up: the
/// determinant of the whole layered system's stiffness is det(surface)·Π det(pivot) (Schur's formula), a function of
/// (k, ω) without the condensation's poles.
pub(super) fn condensed(
    profile: &GroundProfile,
    k: f64,
    omega: f64,
    mut pivot: impl FnMut(&Matrix2<Complex64>),
) -> Matrix2<Complex64> {
    let (seen, half_space) = reach(profile, k, omega);
    let mut below = half_space_stiffness(&half_space, k, omega);
    for &(material, thickness) in seen.iter().rev() {
        let n = sublayers(&material, thickness, k, omega);
        let stiffness = layer_stiffness(&material, thickness / n as f64, k, omega);
        let [k11, k12, k21, k22] = blocks(&stiffness);
        for _ in 0..n {
            let block = k22 + below;
            pivot(&block);
            below = k11 - k12 * inverse_or_nan(block) * k21;
        }
    }
    below
}

/// The layers (material, thickness) a wave (k, ω) reaches from the surface down, the last one cut where
/// [`DEPTH_REACH`] e-folds are spent, and what stands in for everything below: the material at that depth.
fn reach(profile: &GroundProfile, k: f64, omega: f64) -> (Vec<(SoilMaterial, f64)>, SoilMaterial) {
    let mut seen = Vec::with_capacity(profile.layers.len());
    let mut spent = 0.0;
    for layer in &profile.layers {
        let rate = decay_rate(&layer.material, k, omega);
        let left = DEPTH_REACH - spent;
        if rate * layer.thickness >= left {
            seen.push((layer.material, left / rate));
            return (seen, layer.material);
        }
        spent += rate * layer.thickness;
        seen.push((layer.material, layer.thickness));
    }
    (seen, profile.half_space)
}

/// Re√(k² − ω²/C_s*²) (1/m): how fast the slowest wave of `material` decays with depth at (k, ω).
fn decay_rate(material: &SoilMaterial, k: f64, omega: f64) -> f64 {
    let (cs2, _) = material.wave_speeds_squared(omega);
    k.abs() * decaying_root(Complex64::new(omega * omega / (k * k), 0.0) / cs2).re
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::SoilLayer;

    fn soil(shear_wave_speed: f64) -> SoilMaterial {
        SoilMaterial {
            shear_wave_speed,
            compression_wave_speed: 4.0 * shear_wave_speed,
            density: 1600.0,
            damping_ratio: 0.03,
        }
    }

    /// 3 m of soft soil over rock, and over 60 m of soft soil then rock.
    fn profiles() -> (GroundProfile, GroundProfile) {
        let shallow =
            GroundProfile { layers: vec![SoilLayer { thickness: 3.0, material: soil(80.0) }], half_space: soil(800.0) };
        let deep = GroundProfile {
            layers: vec![SoilLayer { thickness: 60.0, material: soil(80.0) }],
            half_space: soil(800.0),
        };
        (shallow, deep)
    }

    /// Rock at depth d changes a static wave's flexibility by ~(kd)²e^{−2kd} of itself (at rest the layer's fields
    /// include z·e^{−kz}): 3 m down, it is seen at kd = 3 (change between e^{−6} ≈ 2.5e-3 and 0.1) and not at kd = 24
    /// (change < 1e-12, against ~24²e^{−48} ≈ 1e-18 and the round-off of 40 sublayers).
    #[test]
    fn rock_below_a_short_wave_is_not_seen() {
        let (shallow, deep) = profiles();
        let change = |k: f64| {
            let (a, b) = (surface_flexibility(&shallow, k, 0.0), surface_flexibility(&deep, k, 0.0));
            ((a - b) / b).norm()
        };
        assert!(change(1.0) > 2.5e-3 && change(1.0) < 0.1, "{}", change(1.0));
        assert!(change(8.0) < 1e-12, "{}", change(8.0));
    }

    /// The cut at 40 e-folds is invisible: across the wavenumber where it first cuts the 60 m layer (k h = 40 at rest)
    /// the flexibility is continuous to 1e-9 (the round-off of condensing through 40 sublayers: ~2e-10 here, as in
    /// the identical-layers test), and beyond it the layer is cut where the 40 e-folds are spent.
    #[test]
    fn the_depth_cut_is_continuous() {
        let (_, deep) = profiles();
        let k = DEPTH_REACH / 60.0;
        let (below, above) =
            (surface_flexibility(&deep, k * (1.0 - 1e-10), 0.0), surface_flexibility(&deep, k * (1.0 + 1e-10), 0.0));
        assert!(((below - above) / above).norm() < 1e-9, "{below} vs {above}");
        assert_eq!(reach(&deep, 2.0 * k, 0.0).0[0].1, 30.0);
    }
}
