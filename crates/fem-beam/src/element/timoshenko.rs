//! Two-node Timoshenko beam element of length l with interdependent interpolation (Friedman & Kosmatka, Computers
//! & Structures 47 (1993) 473–481; docs/theory.md §15): shear-locking free and exact in statics for end loads.
//!
//! The DOFs are (w_a, ψ_a, w_b, ψ_b): the deflection w (m, upward positive) and the rotation ψ of the cross-section
//! (rad), which is no longer the slope w′ — the shear strain is γ = w′ − ψ. With ξ = (x − x_a)/l and
//! φ = 12EI/(κGA·l²) (bending over shear flexibility; φ = 0 is Euler–Bernoulli):
//!
//! ```text
//! N_w = 1/(1+φ)·[2ξ³ − 3ξ² − φξ + 1 + φ,  l(ξ³ − (2 + φ/2)ξ² + (1 + φ/2)ξ),  −2ξ³ + 3ξ² + φξ,  l(ξ³ − (1 − φ/2)ξ² − φξ/2)]
//! N_ψ = 1/(1+φ)·[6(ξ² − ξ)/l,  3ξ² − (4 + φ)ξ + 1 + φ,  −6(ξ² − ξ)/l,  3ξ² − (2 − φ)ξ]
//! ```
//!
//! so γ = −φ/((1+φ)l)·[1, l/2, −1, l/2]·q is constant on the element. The bending moment is M = EI ψ′ and the shear
//! force V = κGA γ. The matrices are ∫(EI N_ψ′ᵀN_ψ′ + κGA γᵀγ) dx and ∫(ρA N_wᵀN_w + ρI N_ψᵀN_ψ) dx in closed form
//! (Przemieniecki, Theory of Matrix Structural Analysis, §11; Friedman & Kosmatka 1993):
//!
//! ```text
//! K = EI/((1+φ)l³)·[[12, 6l, −12, 6l], [6l, (4+φ)l², −6l, (2−φ)l²], [−12, −6l, 12, −6l], [6l, (2−φ)l², −6l, (4+φ)l²]]
//! ```
//!
//! and the translational and rotary masses below ([`translational_mass`], [`rotary_mass`]); at φ = 0 they are the
//! Hermite element's ([`super::hermite`]) plus the rotary inertia ρI of the Rayleigh beam.

use super::{ElementMatrix, ElementVector};

/// φ = 12EI/(κGA·l²): the element's bending flexibility over its shear flexibility (dimensionless). `ei` (N·m²),
/// `shear_stiffness` κGA (N), `l` (m).
pub fn shear_ratio(ei: f64, shear_stiffness: f64, l: f64) -> f64 {
    12.0 * ei / (shear_stiffness * l * l)
}

/// N_w(ξ): the deflection's shape functions (dimensionless for w, metres for ψ).
pub fn shape(xi: f64, l: f64, phi: f64) -> ElementVector {
    let (x2, x3, d) = (xi * xi, xi * xi * xi, 1.0 + phi);
    [
        (2.0 * x3 - 3.0 * x2 - phi * xi + 1.0 + phi) / d,
        l * (x3 - (2.0 + 0.5 * phi) * x2 + (1.0 + 0.5 * phi) * xi) / d,
        (-2.0 * x3 + 3.0 * x2 + phi * xi) / d,
        l * (x3 - (1.0 - 0.5 * phi) * x2 - 0.5 * phi * xi) / d,
    ]
}

/// dN_w/dx (1/m for w, dimensionless for ψ): the slope w′.
pub fn shape_dx(xi: f64, l: f64, phi: f64) -> ElementVector {
    let (x2, d) = (xi * xi, 1.0 + phi);
    [
        (6.0 * x2 - 6.0 * xi - phi) / (d * l),
        (3.0 * x2 - (4.0 + phi) * xi + 1.0 + 0.5 * phi) / d,
        (-6.0 * x2 + 6.0 * xi + phi) / (d * l),
        (3.0 * x2 - (2.0 - phi) * xi - 0.5 * phi) / d,
    ]
}

/// ∫ N_w dx over the part [ξ₀, ξ₁] of the element (m for w, m² for ψ): the consistent nodal loads of a unit uniform
/// load there, l·(A(ξ₁) − A(ξ₀)) with the antiderivatives in ξ A₁ = (ξ⁴/2 − ξ³ − φξ²/2 + (1+φ)ξ)/(1+φ),
/// A₂ = l(ξ⁴/4 − (2 + φ/2)ξ³/3 + (1 + φ/2)ξ²/2)/(1+φ), A₃ = (−ξ⁴/2 + ξ³ + φξ²/2)/(1+φ),
/// A₄ = l(ξ⁴/4 − (1 − φ/2)ξ³/3 − φξ²/4)/(1+φ); over the whole element (l/2, l²/12, l/2, −l²/12), as Hermite's.
pub fn shape_integral(xi0: f64, xi1: f64, l: f64, phi: f64) -> ElementVector {
    let d = 1.0 + phi;
    let antiderivative = |x: f64| {
        let (x2, x3, x4) = (x * x, x * x * x, x * x * x * x);
        [
            (0.5 * x4 - x3 - 0.5 * phi * x2 + d * x) / d,
            l * (0.25 * x4 - (2.0 + 0.5 * phi) * x3 / 3.0 + 0.5 * (1.0 + 0.5 * phi) * x2) / d,
            (-0.5 * x4 + x3 + 0.5 * phi * x2) / d,
            l * (0.25 * x4 - (1.0 - 0.5 * phi) * x3 / 3.0 - 0.25 * phi * x2) / d,
        ]
    };
    let (a, b) = (antiderivative(xi0), antiderivative(xi1));
    std::array::from_fn(|k| l * (b[k] - a[k]))
}

/// N_ψ(ξ): the cross-section rotation's shape functions (1/m for w, dimensionless for ψ).
pub fn rotation(xi: f64, l: f64, phi: f64) -> ElementVector {
    let (x2, d) = (xi * xi, 1.0 + phi);
    [
        6.0 * (x2 - xi) / (d * l),
        (3.0 * x2 - (4.0 + phi) * xi + 1.0 + phi) / d,
        -6.0 * (x2 - xi) / (d * l),
        (3.0 * x2 - (2.0 - phi) * xi) / d,
    ]
}

/// dN_ψ/dx (1/m² for w, 1/m for ψ); EI·Σ N_ψ′ᵢqᵢ is the bending moment, linear on the element.
pub fn rotation_dx(xi: f64, l: f64, phi: f64) -> ElementVector {
    let d = 1.0 + phi;
    [
        6.0 * (2.0 * xi - 1.0) / (d * l * l),
        (6.0 * xi - 4.0 - phi) / (d * l),
        -6.0 * (2.0 * xi - 1.0) / (d * l * l),
        (6.0 * xi - 2.0 + phi) / (d * l),
    ]
}

/// The shear strain row γ = w′ − ψ (constant on the element): −φ/((1+φ)l)·[1, l/2, −1, l/2].
pub fn shear_strain(l: f64, phi: f64) -> ElementVector {
    let c = -phi / ((1.0 + phi) * l);
    [c, 0.5 * l * c, -c, 0.5 * l * c]
}

/// Bending and shear stiffness EI/((1+φ)l³)·[…] (see the module doc).
pub fn stiffness(ei: f64, l: f64, phi: f64) -> ElementMatrix {
    let c = ei / ((1.0 + phi) * l * l * l);
    let l2 = l * l;
    let (diagonal, off) = ((4.0 + phi) * l2 * c, (2.0 - phi) * l2 * c);
    [
        [12.0 * c, 6.0 * l * c, -12.0 * c, 6.0 * l * c],
        [6.0 * l * c, diagonal, -6.0 * l * c, off],
        [-12.0 * c, -6.0 * l * c, 12.0 * c, -6.0 * l * c],
        [6.0 * l * c, off, -6.0 * l * c, diagonal],
    ]
}

/// Translational mass ∫ρA N_wᵀN_w dx = ρA·l/(1+φ)²·[…]: with m₁ = 13/35 + 7φ/10 + φ²/3, m₂ = (11/210 + 11φ/120 +
/// φ²/24)l, m₃ = 9/70 + 3φ/10 + φ²/6, m₄ = (13/420 + 3φ/40 + φ²/24)l, m₅ = (1/105 + φ/60 + φ²/120)l²,
/// m₆ = (1/140 + φ/60 + φ²/120)l²: [[m₁, m₂, m₃, −m₄], [m₂, m₅, m₄, −m₆], [m₃, m₄, m₁, −m₂], [−m₄, −m₆, −m₂, m₅]].
pub fn translational_mass(rho_a: f64, l: f64, phi: f64) -> ElementMatrix {
    let (p, p2, l2) = (phi, phi * phi, l * l);
    let c = rho_a * l / ((1.0 + phi) * (1.0 + phi));
    let m1 = c * (13.0 / 35.0 + 7.0 * p / 10.0 + p2 / 3.0);
    let m2 = c * l * (11.0 / 210.0 + 11.0 * p / 120.0 + p2 / 24.0);
    let m3 = c * (9.0 / 70.0 + 3.0 * p / 10.0 + p2 / 6.0);
    let m4 = c * l * (13.0 / 420.0 + 3.0 * p / 40.0 + p2 / 24.0);
    let m5 = c * l2 * (1.0 / 105.0 + p / 60.0 + p2 / 120.0);
    let m6 = c * l2 * (1.0 / 140.0 + p / 60.0 + p2 / 120.0);
    [[m1, m2, m3, -m4], [m2, m5, m4, -m6], [m3, m4, m1, -m2], [-m4, -m6, -m2, m5]]
}

/// Rotary inertia ∫ρI N_ψᵀN_ψ dx = ρI/((1+φ)²l)·[…]: with r₁ = 6/5, r₂ = (1/10 − φ/2)l,
/// r₃ = (2/15 + φ/6 + φ²/3)l², r₄ = (1/30 + φ/6 − φ²/6)l²:
/// [[r₁, r₂, −r₁, r₂], [r₂, r₃, −r₂, −r₄], [−r₁, −r₂, r₁, −r₂], [r₂, −r₄, −r₂, r₃]].
pub fn rotary_mass(rho_i: f64, l: f64, phi: f64) -> ElementMatrix {
    let (p, p2, l2) = (phi, phi * phi, l * l);
    let c = rho_i / ((1.0 + phi) * (1.0 + phi) * l);
    let r1 = c * 6.0 / 5.0;
    let r2 = c * l * (0.1 - 0.5 * p);
    let r3 = c * l2 * (2.0 / 15.0 + p / 6.0 + p2 / 3.0);
    let r4 = c * l2 * (1.0 / 30.0 + p / 6.0 - p2 / 6.0);
    [[r1, r2, -r1, r2], [r2, r3, -r2, -r4], [-r1, -r2, r1, -r2], [r2, -r4, -r2, r3]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::hermite::{self, GAUSS_4};

    /// ∫₀ˡ a(x)b(x)ᵀ dx by four-point Gauss: exact for the products here (degree ≤ 6).
    fn integral(l: f64, a: impl Fn(f64) -> ElementVector, b: impl Fn(f64) -> ElementVector) -> ElementMatrix {
        let mut out = [[0.0; 4]; 4];
        for &(xi, w) in &GAUSS_4 {
            let (u, v) = (a(xi), b(xi));
            for i in 0..4 {
                for j in 0..4 {
                    out[i][j] += w * l * u[i] * v[j];
                }
            }
        }
        out
    }

    fn assert_close(a: &ElementMatrix, b: &ElementMatrix, what: &str) {
        let scale = a.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
        for i in 0..4 {
            for j in 0..4 {
                // Round-off of a dozen products and sums: 1e-13 of the largest entry.
                assert!((a[i][j] - b[i][j]).abs() <= 1e-13 * scale, "{what}[{i}][{j}]: {} vs {}", a[i][j], b[i][j]);
            }
        }
    }

    /// The closed forms are the integrals of the shape functions (an independent derivation, by quadrature), for a
    /// slender element (φ = 0.02), a deep one (φ = 3) and Euler–Bernoulli (φ = 0, where they are Hermite's).
    #[test]
    fn closed_forms_are_the_integrals_of_the_shape_functions() {
        let (ei, rho_a, rho_i, l) = (6.4155e6, 59.935, 0.2383, 0.15);
        for phi in [0.0, 0.02, 3.0] {
            let gamma = shear_strain(l, phi);
            let kga = if phi > 0.0 { 12.0 * ei / (phi * l * l) } else { 0.0 };
            let mut k = integral(l, |x| rotation_dx(x, l, phi), |x| rotation_dx(x, l, phi));
            for i in 0..4 {
                for j in 0..4 {
                    k[i][j] = ei * k[i][j] + kga * l * gamma[i] * gamma[j];
                }
            }
            assert_close(&stiffness(ei, l, phi), &k, "K");
            let m = integral(l, |x| shape(x, l, phi), |x| shape(x, l, phi));
            assert_close(&translational_mass(rho_a, l, phi), &hermite::combine(rho_a, &m, 0.0, &m), "M_ρA");
            let r = integral(l, |x| rotation(x, l, phi), |x| rotation(x, l, phi));
            assert_close(&rotary_mass(rho_i, l, phi), &hermite::combine(rho_i, &r, 0.0, &r), "M_ρI");
        }
        assert_close(&stiffness(ei, l, 0.0), &hermite::bending_stiffness(ei, l), "K at φ = 0");
        assert_close(&translational_mass(rho_a, l, 0.0), &hermite::consistent_mass(rho_a, l), "M at φ = 0");
    }

    /// The partial integrals of N_w are Simpson's rule on [ξ₀, ξ₁] (exact for cubics), and the whole element's is
    /// the uniform load (l/2, l²/12, l/2, −l²/12) whatever φ.
    #[test]
    fn shape_integrals_are_the_integrals_of_the_shapes() {
        let (l, phi) = (0.25, 5.0);
        let (a, b) = (0.2, 0.7);
        let exact = shape_integral(a, b, l, phi);
        let (n0, n1, n2) = (shape(a, l, phi), shape(0.5 * (a + b), l, phi), shape(b, l, phi));
        for k in 0..4 {
            let simpson = (b - a) * l / 6.0 * (n0[k] + 4.0 * n1[k] + n2[k]);
            assert!((exact[k] - simpson).abs() < 1e-15, "{k}: {} vs {simpson}", exact[k]);
        }
        let whole = shape_integral(0.0, 1.0, l, phi);
        let uniform = hermite::uniform_load(1.0, l);
        assert!((0..4).all(|k| (whole[k] - uniform[k]).abs() < 1e-15), "{whole:?}");
    }

    /// The shape functions interpolate the nodal values (w and ψ at both ends), the slope minus the rotation is the
    /// constant shear strain, and at φ = 0 they are Hermite's with ψ = w′.
    #[test]
    fn shapes_interpolate_and_shear_is_their_difference() {
        let (l, phi) = (0.6, 0.7);
        let unit = |k: usize| std::array::from_fn::<f64, 4, _>(|i| if i == k { 1.0 } else { 0.0 });
        for (xi, w_dof, psi_dof) in [(0.0, 0, 1), (1.0, 2, 3)] {
            let (w, psi) = (shape(xi, l, phi), rotation(xi, l, phi));
            for k in 0..4 {
                assert!((w[k] - unit(w_dof)[k]).abs() < 1e-15 && (psi[k] - unit(psi_dof)[k]).abs() < 1e-15, "{xi} {k}");
            }
        }
        for xi in [0.0, 0.3, 0.8] {
            let (slope, psi, gamma) = (shape_dx(xi, l, phi), rotation(xi, l, phi), shear_strain(l, phi));
            let (h, hx) = (hermite::shape(xi, l), hermite::shape_dx(xi, l));
            for k in 0..4 {
                assert!((slope[k] - psi[k] - gamma[k]).abs() < 1e-14, "γ at {xi}, {k}");
                assert!((shape(xi, l, 0.0)[k] - h[k]).abs() < 1e-15 && (rotation(xi, l, 0.0)[k] - hx[k]).abs() < 1e-14);
            }
        }
    }
}
