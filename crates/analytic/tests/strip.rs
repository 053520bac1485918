//! The track's strip on the ground (docs/theory.md §19): its equivalent stiffness k_eq(k_x, ω) against the closed
//! form of a static strip on a homogeneous half-space, and its limits.

use analytic::ground::{GroundProfile, SoilLayer, SoilMaterial, StripGround};

fn clay(damping_ratio: f64) -> SoilMaterial {
    SoilMaterial { shear_wave_speed: 72.0, compression_wave_speed: 500.0, density: 1500.0, damping_ratio }
}

/// ∫₀ˣ K₀(u) du = ∫₀^∞ (1 − e^{−x cosh t})/cosh t dt (from K₀(u) = ∫₀^∞ e^{−u cosh t} dt), by composite Simpson on
/// t ∈ [0, 40] with 40 000 panels: the integrand is smooth and below 2e^{−t}, so ~1e-15.
fn integral_of_k0(x: f64) -> f64 {
    let (n, end) = (40_000, 40.0);
    let h = end / n as f64;
    let f = |t: f64| -(-x * f64::cosh(t)).exp_m1() / t.cosh();
    let inner: f64 = (1..n).map(|i| f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 }).sum();
    (f(0.0) + inner + f(end)) * h / 3.0
}

/// A static strip of half-width b on a homogeneous half-space: k_eq = πμk_x b/((1 − ν)∫₀^{k_x b} K₀(u) du), since
/// ∫₀^∞ sin(by)/(y√(y² + a²)) dy = ∫₀^b K₀(at) dt. The strip integral (adaptive, its tail in closed form) matches it
/// to 1e-8 from long waves (k_x b = 0.03, where k_eq → 0 as 1/ln) to short ones (k_x b = 15, k_eq → 2μk_x b/(1 − ν)),
/// through a layered description of the same soil too; the integral's tolerance is 1e-7 (its estimate pessimistic by
/// orders: met to 1e-8 at 1e-7 as at 1e-9) and its tail's neglected terms O((Kb)⁻⁵) ~ 1e-10.
#[test]
fn a_static_strip_on_a_half_space_is_the_closed_form() {
    let soil = clay(0.0);
    let (mu, nu) = (soil.shear_modulus(0.0).re, soil.poisson_ratio());
    let layered = GroundProfile { layers: vec![SoilLayer { thickness: 2.0, material: soil }], half_space: soil };
    for profile in [GroundProfile::half_space(soil), layered] {
        let strip = StripGround { width: 3.0, profile };
        let b = 1.5;
        for kx in [0.02, 0.3, 2.0, 10.0] {
            let exact = std::f64::consts::PI * mu * kx * b / ((1.0 - nu) * integral_of_k0(kx * b));
            let k_eq = strip.equivalent_stiffness(kx, 0.0).unwrap();
            assert!(
                (k_eq.re / exact - 1.0).abs() < 1e-8 && k_eq.im.abs() < 1e-12 * exact,
                "k_x {kx}: {k_eq} vs {exact}"
            );
        }
    }
}
