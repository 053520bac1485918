//! What carries a beam along its length in the frequency–wavenumber domain: a stiffness per unit length for each
//! wave e^{i(ωt − k_x x)} (docs/theory.md §19). A Winkler foundation answers the same k_f(1 + iη) + iωc_f for every
//! k_x; the ground's strip answers k_eq(k_x, ω), non-local. The moving-load solution takes either, so a Winkler
//! foundation checks it against the closed forms.

use super::strip::StripGround;
use fem_beam::error::Result;
use fem_beam::properties::Foundation;
use num_complex::Complex64;

/// A linear support of a beam: force per length per deflection for a wave e^{i(ωt − k_x x)}.
pub trait LineSupport: Sync {
    /// The stiffness (N/m², complex) at wavenumber `kx` (rad/m) and circular frequency `omega` (rad/s, ≥ 0).
    fn line_stiffness(&self, kx: f64, omega: f64) -> Result<Complex64>;

    /// An upper estimate of |stiffness| at (`kx`, `omega`) that costs nothing (N/m²): where the beam's own EI k_x⁴ is
    /// 1e4 times larger, the support is left out of the beam's operator.
    fn stiffness_bound(&self, kx: f64, omega: f64) -> f64;
}

impl LineSupport for Foundation {
    fn line_stiffness(&self, _kx: f64, omega: f64) -> Result<Complex64> {
        Ok(self.dynamic_stiffness(omega))
    }

    fn stiffness_bound(&self, _kx: f64, omega: f64) -> f64 {
        self.dynamic_stiffness(omega).norm()
    }
}

impl LineSupport for StripGround {
    fn line_stiffness(&self, kx: f64, omega: f64) -> Result<Complex64> {
        self.equivalent_stiffness(kx, omega)
    }

    /// The static strip on a half-space of the profile's stiffest material is below 2μk_x b/(1 − ν)·4 for k_x b ≥
    /// 1 (its short-wave limit 2μk_x b/(1 − ν), with room for inertia and the ln of long waves), and 4μ/(1 − ν) below.
    fn stiffness_bound(&self, kx: f64, _omega: f64) -> f64 {
        let stiffest = self
            .profile
            .materials()
            .map(|m| m.shear_modulus(1.0).norm() / (1.0 - m.poisson_ratio()))
            .fold(0.0, f64::max);
        8.0 * stiffest * (kx.abs() * 0.5 * self.width).max(0.5)
    }
}
