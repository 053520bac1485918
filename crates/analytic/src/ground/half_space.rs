//! The half-space's dynamic stiffness (docs/theory.md §19): the tractions its surface takes, t = K (u, w), when it
//! moves as (u, w) e^{i(ωt − kx)} and its waves decay downward (z down, w positive downward).
//!
//! With p = √(1 − ω²/(k²C_p²)), s = √(1 − ω²/(k²C_s²)) (Re ≥ 0: decaying, or radiating with damping) the P and SV
//! waves give (the displacement and traction vectors of e^{−kpz} and e^{−ksz}, solved for K)
//!
//! ```text
//! K = μk/(1 − ps) · [[ p(1 − s²),          i(1 + s² − 2ps) ],
//!                    [ −i(1 + s² − 2ps),   s(1 − s²)       ]]
//! ```
//!
//! which is 0/0 as ω/k → 0 (p, s → 1). With a = ω²/k², 1 − s² = a/C_s² and (1 − ps)(1 + ps) = a/C_p² + a/C_s² −
//! a²/(C_p²C_s²), the ratios are written without the cancellation:
//! (1 − s²)/(1 − ps) = (1 + ps)C_p²/(C_p² + C_s² − a) and (1 + s² − 2ps)/(1 − ps) = 1 − s(1 + ps)(C_p² − C_s²)/
//! ((p + s)(C_p² + C_s² − a)). At rest K = μk/(C_p² + C_s²)·[[2C_p², 2iC_s²], [−2iC_s², 2C_p²]], whose vertical
//! flexibility is (1 − ν)/(μk), Boussinesq's in the wavenumber domain.

use super::profile::SoilMaterial;
use nalgebra::Matrix2;
use num_complex::Complex64;

/// The root of 1 − x with a non-negative real part (the wave decays downward or, damped, radiates away).
pub(super) fn decaying_root(x: Complex64) -> Complex64 {
    let r = (Complex64::new(1.0, 0.0) - x).sqrt();
    if r.re < 0.0 { -r } else { r }
}

/// The stiffness (N/m³ per unit wavenumber area: Pa/m) of a half-space of `material` at wavenumber `k` (rad/m, ≠ 0)
/// and circular frequency `omega` (rad/s, ≥ 0), DOFs (u, w).
pub fn half_space_stiffness(material: &SoilMaterial, k: f64, omega: f64) -> Matrix2<Complex64> {
    let k = k.abs();
    let (cs2, cp2) = material.wave_speeds_squared(omega);
    let mu = material.shear_modulus(omega);
    let a = Complex64::new(omega * omega / (k * k), 0.0);
    let (p, s) = (decaying_root(a / cp2), decaying_root(a / cs2));
    let one = Complex64::new(1.0, 0.0);
    let denominator = cp2 + cs2 - a;
    let q = (one + p * s) * cp2 / denominator;
    let r = one - s * (one + p * s) * (cp2 - cs2) / ((p + s) * denominator);
    let i = Complex64::new(0.0, 1.0);
    Matrix2::new(p * q, i * r, -i * r, s * q) * (mu * k)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn soil() -> SoilMaterial {
        SoilMaterial { shear_wave_speed: 100.0, compression_wave_speed: 500.0, density: 1500.0, damping_ratio: 0.0 }
    }

    /// Static: the vertical flexibility is (1 − ν)/(μk) (the Boussinesq half-space in the wavenumber domain), to
    /// round-off.
    #[test]
    fn at_rest_the_vertical_flexibility_is_boussinesqs() {
        let m = soil();
        for k in [0.01, 0.7, 30.0] {
            let f = half_space_stiffness(&m, k, 0.0).try_inverse().unwrap()[(1, 1)];
            let exact = (1.0 - m.poisson_ratio()) / (m.shear_modulus(0.0).re * k);
            assert!((f.re / exact - 1.0).abs() < 1e-13 && f.im.abs() < 1e-13 * exact, "k {k}: {f} vs {exact}");
        }
    }

    /// The closed form without the cancellation equals the plain one where that one is accurate (ω/k well away from
    /// 0 and from the Rayleigh pole), to 1e-12.
    #[test]
    fn the_rewritten_ratios_equal_the_plain_form() {
        let m = SoilMaterial { damping_ratio: 0.03, ..soil() };
        let (k, omega) = (0.8, 60.0);
        let (cs2, cp2) = m.wave_speeds_squared(omega);
        let a = Complex64::new(omega * omega / (k * k), 0.0);
        let (p, s) = (decaying_root(a / cp2), decaying_root(a / cs2));
        let one = Complex64::new(1.0, 0.0);
        let i = Complex64::new(0.0, 1.0);
        let plain = Matrix2::new(
            p * (one - s * s),
            i * (one + s * s - p * s * 2.0),
            -i * (one + s * s - p * s * 2.0),
            s * (one - s * s),
        ) * (m.shear_modulus(omega) * k / (one - p * s));
        let rewritten = half_space_stiffness(&m, k, omega);
        assert!((plain - rewritten).norm() <= 1e-12 * plain.norm(), "{plain} vs {rewritten}");
    }
}
