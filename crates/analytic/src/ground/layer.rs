//! A layer's dynamic stiffness (docs/theory.md §19) from its transfer matrix. In z (down) the displacements (u, w)
//! and the tractions (τ_xz, σ_zz) of a motion e^{i(ωt − kx)} obey y′ = A y, with M = λ* + 2μ*,
//!
//! ```text
//! u′ = τ/μ + ik w,          w′ = (σ + ikλ u)/M,
//! τ′ = (k²(M − λ²/M) − ρω²) u + (ikλ/M) σ,          σ′ = −ρω² w + ik τ,
//! ```
//!
//! so y(h) = exp(A h) y(0) = [[T₁₁, T₁₂], [T₂₁, T₂₂]] y(0). The layer's external tractions (−t(0) on its top, t(h) on
//! its bottom) are then K (u(0), u(h)) with
//!
//! ```text
//! K = [[ T₁₂⁻¹T₁₁,               −T₁₂⁻¹    ],
//!      [ T₂₁ − T₂₂T₁₂⁻¹T₁₁,      T₂₂T₁₂⁻¹  ]]
//! ```
//!
//! — Kausel & Roësset's layer matrix, computed without its closed form's 0/0 at ω/k → 0 and used only on sublayers
//! with |k|h ≤ 1 and ωh/|C_s| ≤ 1, where T₁₂ is well conditioned (a thick layer's e^{±kh} would swamp it; a
//! sublayer's clamped resonances lie above).
//!
//! **The transfer matrix without a general matrix exponential.** A's characteristic polynomial is even,
//! (λ² − k²p²)(λ² − k²s²) with k²p² = k² − ω²/C_p*², k²s² = k² − ω²/C_s*², so by Cayley–Hamilton H = h²A² obeys
//! (H − y₁)(H − y₂) = 0 with y₁ = h²(k² − ω²/C_p*²), y₂ = h²(k² − ω²/C_s*²), at rest (y₁ = y₂, A not diagonalisable)
//! too. Then exp(Ah) = C(H) + hA·S(H) with the entire functions C(y) = cosh√y, S(y) = sinh√y/√y, and any entire g
//! has g(H) = g(y₂)·I + g[y₁, y₂]·(H − y₂I), its divided difference g[y₁, y₂] = Σ cₙ(y₁ⁿ − y₂ⁿ)/(y₁ − y₂) summed
//! as a power series without a division (|y| ≤ 2 on a sublayer: 16 terms reach 1e-20). Exact at ω = 0 and across
//! y₁ = y₂, ~10× cheaper than Padé with scaling and squaring, against which it is tested.

use super::profile::SoilMaterial;
use nalgebra::{Matrix2, Matrix4};
use num_complex::Complex64;

/// The 4 × 4 stiffness of a layer of `material`, `thickness` h (m), at wavenumber `k` (rad/m) and circular frequency
/// `omega` (rad/s): DOFs (u, w) at its top, then at its bottom. Exact for any h; well conditioned for |k|h and
/// ωh/|C_s| up to about 1 (the surface flexibility cuts layers into such sublayers).
pub fn layer_stiffness(material: &SoilMaterial, thickness: f64, k: f64, omega: f64) -> Matrix4<Complex64> {
    let transfer = transfer_matrix(material, thickness, k, omega);
    let [t11, t12, t21, t22] = blocks(&transfer);
    let t12_inverse = inverse_or_nan(t12);
    let top = t12_inverse * t11;
    let mut out = Matrix4::zeros();
    out.fixed_view_mut::<2, 2>(0, 0).copy_from(&top);
    out.fixed_view_mut::<2, 2>(0, 2).copy_from(&(-t12_inverse));
    out.fixed_view_mut::<2, 2>(2, 0).copy_from(&(t21 - t22 * top));
    out.fixed_view_mut::<2, 2>(2, 2).copy_from(&(t22 * t12_inverse));
    out
}

/// The 2 × 2 blocks [top-left, top-right, bottom-left, bottom-right] of a 4 × 4 matrix.
pub(super) fn blocks(m: &Matrix4<Complex64>) -> [Matrix2<Complex64>; 4] {
    [(0, 0), (0, 2), (2, 0), (2, 2)].map(|(r, c)| m.fixed_view::<2, 2>(r, c).into_owned())
}

/// The inverse of `m`, or NaN everywhere where it is singular (a result that says it has none, never a panic).
pub(super) fn inverse_or_nan(m: Matrix2<Complex64>) -> Matrix2<Complex64> {
    m.try_inverse().unwrap_or_else(|| Matrix2::from_element(Complex64::new(f64::NAN, 0.0)))
}

/// exp(A h) by the Cayley–Hamilton reduction to C(H) + hA·S(H), H = h²A² (module documentation).
fn transfer_matrix(material: &SoilMaterial, thickness: f64, k: f64, omega: f64) -> Matrix4<Complex64> {
    let a = system(material, k, omega) * Complex64::new(thickness, 0.0);
    let h = a * a;
    let (cs2, cp2) = material.wave_speeds_squared(omega);
    let (h2, w2) = (thickness * thickness, omega * omega);
    let (y1, y2) = ((k * k - w2 / cp2) * h2, (k * k - w2 / cs2) * h2);
    let [cosh_value, cosh_slope, sinh_value, sinh_slope] = even_series(y1, y2);
    let identity = Matrix4::identity();
    let shifted = h - identity * y2;
    identity * cosh_value + shifted * cosh_slope + a * (identity * sinh_value + shifted * sinh_slope)
}

/// [C(y₂), C[y₁, y₂], S(y₂), S[y₁, y₂]] for C(y) = Σ yⁿ/(2n)! and S(y) = Σ yⁿ/(2n + 1)!, the divided differences
/// from dₙ = (y₁ⁿ − y₂ⁿ)/(y₁ − y₂) = y₁dₙ₋₁ + y₂ⁿ⁻¹.
fn even_series(y1: Complex64, y2: Complex64) -> [Complex64; 4] {
    const TERMS: usize = 16;
    let zero = Complex64::new(0.0, 0.0);
    let (mut power, mut divided) = (Complex64::new(1.0, 0.0), zero);
    let (mut cosh_coefficient, mut sinh_coefficient) = (1.0, 1.0);
    let mut out = [Complex64::new(1.0, 0.0), zero, Complex64::new(1.0, 0.0), zero];
    for n in 1..=TERMS {
        divided = y1 * divided + power;
        power *= y2;
        let twice = (2 * n) as f64;
        cosh_coefficient /= (twice - 1.0) * twice;
        sinh_coefficient /= twice * (twice + 1.0);
        out[0] += power * cosh_coefficient;
        out[1] += divided * cosh_coefficient;
        out[2] += power * sinh_coefficient;
        out[3] += divided * sinh_coefficient;
    }
    out
}

/// A of y′ = A y, y = (u, w, τ, σ).
fn system(material: &SoilMaterial, k: f64, omega: f64) -> Matrix4<Complex64> {
    let (mu, m) = (material.shear_modulus(omega), material.p_wave_modulus(omega));
    let lambda = m - mu * 2.0;
    let rho_omega2 = Complex64::new(material.density * omega * omega, 0.0);
    let ik = Complex64::new(0.0, k);
    let zero = Complex64::new(0.0, 0.0);
    let one = Complex64::new(1.0, 0.0);
    Matrix4::new(
        zero,
        ik,
        one / mu,
        zero, //
        ik * lambda / m,
        zero,
        zero,
        one / m, //
        (m - lambda * lambda / m) * (k * k) - rho_omega2,
        zero,
        zero,
        ik * lambda / m, //
        zero,
        -rho_omega2,
        ik,
        zero,
    )
}

/// How many equal sublayers a layer of `thickness` needs at (k, ω): enough that |k|h and ωh/|C_s| are ≤ 1 in each.
pub(super) fn sublayers(material: &SoilMaterial, thickness: f64, k: f64, omega: f64) -> usize {
    let reach = thickness * k.abs().max(omega / material.shear_wave_speed);
    (reach.ceil() as usize).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn soil() -> SoilMaterial {
        SoilMaterial { shear_wave_speed: 80.0, compression_wave_speed: 400.0, density: 1600.0, damping_ratio: 0.02 }
    }

    /// A thin layer at low frequency is two springs: μ/h horizontally and (λ + 2μ)/h vertically, top against bottom,
    /// to O(kh) = 1e-4 (bound 1e-3).
    #[test]
    fn a_thin_layer_is_two_springs() {
        let m = soil();
        let (h, k) = (0.01, 0.01);
        let stiffness = layer_stiffness(&m, h, k, 0.0);
        let (shear, axial) = (m.shear_modulus(0.0) / h, m.p_wave_modulus(0.0) / h);
        for (row, column, expected) in [(0, 0, shear), (1, 1, axial), (0, 2, -shear), (1, 3, -axial), (3, 3, axial)] {
            let value = stiffness[(row, column)];
            assert!((value - expected).norm() <= 1e-3 * expected.norm(), "({row}, {column}): {value} vs {expected}");
        }
    }

    /// As ω/k → 0 the layer's stiffness tends to its static one, finite (the closed form is 0/0 there): ω = 1e-6 rad/s
    /// against ω = 0 to 1e-9, on an undamped soil (hysteretic damping, 2iξ sgn ω, jumps at ω = 0 by its definition:
    /// at rest the damped soil's stiffness is real, checked too).
    #[test]
    fn the_static_limit_is_finite_and_continuous() {
        assert!(layer_stiffness(&soil(), 1.0, 0.5, 0.0).iter().all(|v| v.im == 0.0 || (v.re == 0.0)));
        let m = SoilMaterial { damping_ratio: 0.0, ..soil() };
        let at_rest = layer_stiffness(&m, 1.0, 0.5, 0.0);
        assert!(at_rest.iter().all(|v| v.re.is_finite() && v.im.is_finite()));
        let slow = layer_stiffness(&m, 1.0, 0.5, 1e-6);
        assert!((slow - at_rest).norm() <= 1e-9 * at_rest.norm(), "{}", (slow - at_rest).norm() / at_rest.norm());
    }

    /// The Cayley–Hamilton transfer matrix is the general matrix exponential (nalgebra's Padé with scaling and
    /// squaring) to 1e-12 of its norm over the sublayer range |k|h, ωh/C_s ≤ 1: at rest (A not diagonalisable), near
    /// y₁ = y₂, propagating and evanescent, damped and not.
    #[test]
    fn the_transfer_matrix_is_the_exponential() {
        for (damping, h, k, omega) in [
            (0.0, 0.5, 2.0, 0.0),
            (0.02, 1.0, 1.0, 1e-3),
            (0.02, 1.0, 0.1, 80.0),
            (0.05, 0.3, -3.0, 200.0),
            (0.0, 1.0, 1.0, 79.0),
        ] {
            let m = SoilMaterial { damping_ratio: damping, ..soil() };
            let exact = (system(&m, k, omega) * Complex64::new(h, 0.0)).exp();
            let fast = transfer_matrix(&m, h, k, omega);
            assert!(
                (exact - fast).norm() <= 1e-12 * exact.norm(),
                "{h} {k} {omega}: {}",
                (exact - fast).norm() / exact.norm()
            );
        }
    }

    /// The stiffness is symmetric (reciprocity) once the DOFs' i is taken out: K_uw = −K_wu within each face.
    #[test]
    fn the_stiffness_is_reciprocal() {
        let m = soil();
        let stiffness = layer_stiffness(&m, 0.7, 1.3, 90.0);
        for (r, c) in [(0, 2), (1, 3), (0, 3), (1, 2)] {
            let (a, b) = (stiffness[(r, c)], stiffness[(c, r)]);
            let sign = if (r + c) % 2 == 0 { 1.0 } else { -1.0 };
            assert!((a - b * sign).norm() <= 1e-9 * stiffness.norm(), "({r}, {c}): {a} vs {b}");
        }
    }
}
