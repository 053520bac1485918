//! The closed form of a point load on an infinite beam resting on a tensionless Winkler foundation, without
//! self-weight: the soil pushes (force k⟨−w⟩₊ per unit length, w upward) but cannot pull, so the beam lifts off
//! where the linear solution would pull — the static reference of the nonlinear foundations (docs/theory.md §8).
//!
//! Derived here. With ξ = β|x|, β = (k/4EI)^¼ and w₀ = Pβ/(2k) the linear beam's peak: in the contact zone
//! EI w'''' + k w = 0 with w'(0) = 0 and the shear jump w'''(0⁺) = −P/(2EI); beyond the lift-off point a the beam
//! carries nothing, so it is straight and M(a) = V(a) = 0 (w'' = w''' = 0), and the soil's force is continuous, so
//! w(a) = 0. Solving the four linear conditions for the contact solution leaves
//! w(a) ∝ −(e^{2βa} + 1) e^{βa} cos βa / (2e^{4βa} + 4e^{2βa} sin 2βa − 2), which vanishes first at **βa = π/2**:
//! the contact length is 2a = π/β (the linear solution changes sign only at βx = 3π/4). There, with
//! K = √2/(e^π − 1),
//!
//! ```text
//! w(x) = −w₀ K (e^ξ cos(ξ + π/4) + e^{π−ξ} sin(ξ + π/4))            ξ ≤ π/2  (w(0) = −w₀ coth(π/2))
//! w(x) = w₀ (2/sinh(π/2)) (ξ − π/2)                                   ξ > π/2  (straight, lifted)
//! M(x) = EI w'' = (P/8β) 2K (e^ξ sin(ξ + π/4) + e^{π−ξ} cos(ξ + π/4)) ξ ≤ π/2, 0 beyond (M(0) = coth(π/2) P/4β)
//! ```
//!
//! so the peak deflection and the peak moment are both **coth(π/2) = 1.0903** times the linear beam's w₀ and
//! M₀ = P/(4β).

use crate::reference::InfiniteBeam;
use fem_beam::error::Result;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, SQRT_2};

/// A point load P on an infinite beam on a tensionless Winkler foundation, without self-weight, at rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TensionlessPointLoad {
    /// β = (k/4EI)^¼ (1/m).
    beta: f64,
    /// The linear beam's peak deflection w₀ = Pβ/(2k) (m).
    linear_peak: f64,
    /// P (N, downward).
    load: f64,
    /// k (N/m²).
    foundation_stiffness: f64,
}

impl TensionlessPointLoad {
    /// The load `load` (N, downward, > 0) on `beam` (its EI and k_f; mass and damping play no part at rest).
    pub fn new(beam: &InfiniteBeam, load: f64) -> Result<Self> {
        fem_beam::error::positive("load", load)?;
        let beta = beam.beta();
        let foundation_stiffness = beam.foundation_stiffness;
        Ok(Self { beta, linear_peak: load * beta / (2.0 * foundation_stiffness), load, foundation_stiffness })
    }

    /// coth(π/2): the peak deflection and peak moment over the linear beam's.
    pub fn amplification() -> f64 {
        1.0 / FRAC_PI_2.tanh()
    }

    /// a = π/(2β) (m): the beam rests on the soil over |x| ≤ a and lifts off beyond.
    pub fn contact_half_length(&self) -> f64 {
        FRAC_PI_2 / self.beta
    }

    /// K = √2/(e^π − 1).
    fn k() -> f64 {
        SQRT_2 / (PI.exp() - 1.0)
    }

    /// w(x) (m, upward > 0).
    pub fn deflection(&self, x: f64) -> f64 {
        let xi = self.beta * x.abs();
        if xi <= FRAC_PI_2 {
            -self.linear_peak
                * Self::k()
                * (xi.exp() * (xi + FRAC_PI_4).cos() + (PI - xi).exp() * (xi + FRAC_PI_4).sin())
        } else {
            self.linear_peak * 2.0 / FRAC_PI_2.sinh() * (xi - FRAC_PI_2)
        }
    }

    /// M(x) = EI w''(x) (N·m, sagging positive); zero where the beam has lifted off.
    pub fn moment(&self, x: f64) -> f64 {
        let xi = self.beta * x.abs();
        if xi > FRAC_PI_2 {
            return 0.0;
        }
        let shape = xi.exp() * (xi + FRAC_PI_4).sin() + (PI - xi).exp() * (xi + FRAC_PI_4).cos();
        self.load / (8.0 * self.beta) * 2.0 * Self::k() * shape
    }

    /// The soil's pressure k⟨−w⟩₊ (N/m): what the foundation pushes with, zero where the beam has lifted off.
    pub fn soil_pressure(&self, x: f64) -> f64 {
        self.foundation_stiffness * (-self.deflection(x)).max(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference() -> (InfiniteBeam, TensionlessPointLoad) {
        let case = crate::reference::uic60_on_soft_soil();
        let beam = InfiniteBeam::new(&case.beam, &case.foundation).unwrap();
        (beam, TensionlessPointLoad::new(&beam, 83.4e3).unwrap())
    }

    /// The closed form solves the problem it is derived from, checked by finite differences of w alone (an
    /// independent check of the stated moment too): EI w'''' + k w = 0 inside the contact, w'(0) = 0, the shear jump
    /// EI w'''(0⁺) = −P/2, and w = M = V = 0 at the lift-off point; w ≤ 0 (pressed) inside, > 0 (lifted) beyond,
    /// the soil's pressures balancing the load. Tolerances: central differences of step δ = 1e-3/β carry O(δ²)
    /// ≈ 1e-6 relative truncation, and the 4th difference amplifies round-off to ~1e-16/δ⁴·w ≈ 1e-4 of k w.
    #[test]
    fn the_closed_form_solves_the_tensionless_beam() {
        let (beam, t) = reference();
        let (ei, k, beta, p) = (beam.bending_stiffness, beam.foundation_stiffness, beam.beta(), 83.4e3);
        let a = t.contact_half_length();
        let d = 1e-3 / beta;
        let w = |x: f64| t.deflection(x);
        let second = |x: f64| (w(x + d) - 2.0 * w(x) + w(x - d)) / (d * d);
        let third = |x: f64| (w(x + 2.0 * d) - 2.0 * w(x + d) + 2.0 * w(x - d) - w(x - 2.0 * d)) / (2.0 * d * d * d);
        let fourth =
            |x: f64| (w(x + 2.0 * d) - 4.0 * w(x + d) + 6.0 * w(x) - 4.0 * w(x - d) + w(x - 2.0 * d)) / d.powi(4);
        let w0 = t.linear_peak;
        for i in 1..20 {
            let x = a * i as f64 / 20.0;
            assert!((ei * fourth(x) + k * w(x)).abs() <= 1e-3 * k * w0, "equilibrium at x = {x}");
            assert!(w(x) < 0.0, "pressed at x = {x}");
            assert!((ei * second(x) - t.moment(x)).abs() <= 1e-5 * p / beta, "moment at x = {x}");
        }
        assert!(w(1.5 * a) > 0.0 && w(3.0 * a) > w(1.5 * a), "lifted and straight beyond a");
        assert!(w(a).abs() <= 1e-15 * w0, "w(a) = {}", w(a));
        assert!(t.moment(a).abs() <= 1e-12 * p / beta, "M(a) = {}", t.moment(a));
        // V(a⁻) from inside the contact (one-sided: the third derivative jumps nowhere, the beam beyond is straight).
        assert!((ei * third(a - 2.0 * d)).abs() <= 2e-3 * p, "V(a) = {}", ei * third(a - 2.0 * d));
        assert!((ei * third(2.0 * d) + p / 2.0).abs() <= 2e-3 * p, "shear jump: {}", ei * third(2.0 * d));
        // The soil carries the load: ∫ k⟨−w⟩₊ dx = P (trapezoid over 4000 intervals, O(1e-7)).
        let n = 4000;
        let h = 2.0 * a / n as f64;
        let carried: f64 = (0..=n)
            .map(|i| {
                let x = -a + i as f64 * h;
                let weight = if i == 0 || i == n { 0.5 } else { 1.0 };
                weight * h * t.soil_pressure(x)
            })
            .sum();
        assert!((carried - p).abs() <= 1e-6 * p, "the soil carries {carried} N of {p} N");
    }

    /// Peaks: w(0) and M(0) are coth(π/2) = 1.0903 times the linear beam's w₀ = Pβ/(2k) and M₀ = P/(4β), to
    /// round-off; the contact is shorter than the linear solution's pressed zone (βx = 3π/4).
    #[test]
    fn the_tensionless_peaks_are_coth_half_pi_times_the_linear_ones() {
        let (beam, t) = reference();
        let (w0, m0) = (beam.static_deflection(83.4e3), beam.static_moment(83.4e3));
        let amplification = TensionlessPointLoad::amplification();
        assert!((amplification - 1.090_331_410_727_37).abs() < 1e-13);
        assert!((-t.deflection(0.0) / w0 - amplification).abs() < 1e-13, "{}", -t.deflection(0.0) / w0);
        assert!((t.moment(0.0) / m0 - amplification).abs() < 1e-13, "{}", t.moment(0.0) / m0);
        assert!(beam.beta() * t.contact_half_length() < 0.75 * PI);
    }
}
