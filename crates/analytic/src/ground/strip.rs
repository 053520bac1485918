//! The ground under a track: a strip of width 2b on a layered ground, loaded uniformly across its width, and the
//! equivalent stiffness per unit length it offers the track on its centre line (docs/theory.md §19; Dieterman &
//! Metrikine 1996, Sheng, Jones & Petyt 1999):
//!
//! ```text
//! k_eq(k_x, ω) = 1 / [ (1/π) ∫₀^∞ F_zz(√(k_x² + k_y²), ω) · sin(k_y b)/(k_y b) dk_y ]     (N/m²)
//! ```
//!
//! The integral runs to K = (n + ½)π/b, a zero of cos(k_y b), far enough that the surface sees only its top material
//! statically there, F_zz ≈ F_∞ = c/k with c = (1 − ν₁)/μ₁* (K ≥ 10·max(k_x, ω/C_s,1, 1/h₁), K ≥ 2ω/C_s,min and
//! K b ≥ 40); the rest
//! is the asymptotic tail, by parts with 1/(y√(y² + k_x²)) = 1/y² − k_x²/(2y⁴) + … and cos(Kb) = 0,
//!
//! ```text
//! (1/π)∫_K^∞ F_∞ sin(k_y b)/(k_y b) dk_y = c sin(Kb)/(πb) · [2/(b²K³) − (24/b⁴ + 2k_x²/b²)/K⁵
//!                                          + (720/b⁶ + 60k_x²/b⁴ + 9k_x⁴/(4b²))/K⁷ + O(K⁻⁹)],
//! ```
//!
//! ~1e-5 of the whole at Kb = 40, its neglected terms ~1e-11 of it; F_zz's own departure from F_∞ past the cut, the
//! inertia's O(ω²/k²) and what remains of the layering, is taken as α/k² relative, α measured at the cut, and adds
//! c sin(Kb)/(πb)·4α/(b²K⁵).
//! Before K, adaptive Gauss–Kronrod with breakpoints where k crosses ω/C of a layer's shear or compression wave (the
//! kinks of F_zz) and at k_x·10ʲ (a long wave's peak at k_y ≲ k_x).

use super::flexibility::surface_flexibility;
use super::profile::{GroundProfile, SoilMaterial};
use crate::quadrature::{Integral, Tolerance, integrate};
use fem_beam::FemError;
use fem_beam::error::Result;
use num_complex::Complex64;
use std::f64::consts::PI;

/// The relative tolerance asked of the strip integral. Gauss–Kronrod's error estimate (QUADPACK's scaled |K₁₅ − G₇|)
/// is pessimistic by orders here: asking 1e-7 or 1e-9 gives the same k_eq to 1e-11 (`the_strip_integral_is_converged`,
/// its changes under a 3× cut and a 1e-11 tolerance identical at both: ≤ 1.1e-9, the cut's), at 20 % fewer surface
/// flexibilities (the Ledsgård curve of 60 speeds: 39.9 → 30.9 s); the static closed form is met to 1e-8.
pub const STRIP_TOLERANCE: f64 = 1e-7;
/// The most Gauss–Kronrod intervals one strip integral may use, beyond four per half-period of sinc(k_y b) up to
/// the cut (a few hundred in all do at the sites tried).
const MAX_INTERVALS: usize = 4000;

/// A strip of width 2b (the track's footprint) on a layered ground.
#[derive(Debug, Clone, PartialEq)]
pub struct StripGround {
    /// 2b (m), > 0: the width the track spreads its load over.
    pub width: f64,
    /// The layers under it and the half-space below.
    pub profile: GroundProfile,
}

impl StripGround {
    /// The width finite and > 0 (`ground.width`), and the profile's checks.
    pub fn validate(&self) -> Result<()> {
        if !(self.width.is_finite() && self.width > 0.0) {
            return Err(FemError::InvalidGround {
                path: "ground.width".into(),
                value: self.width,
                allowed: "must be finite and > 0 (m): the width 2b of the strip the track loads".into(),
            });
        }
        self.profile.validate()
    }

    /// k_eq(k_x, ω) (N/m² — force per length per deflection), complex: its imaginary part the power the ground takes
    /// away (radiation) and dissipates. At k_x = 0 and ω = 0 it is 0 (a uniform static line load on a half-space
    /// settles without bound; the integral diverges as ln). Errs on a lossless ground under a vibrating load (its
    /// Rayleigh poles lie on the real k_y axis) and if the integral does not converge.
    pub fn equivalent_stiffness(&self, kx: f64, omega: f64) -> Result<Complex64> {
        if kx == 0.0 && omega == 0.0 {
            return Ok(Complex64::new(0.0, 0.0));
        }
        let integral = self.centre_line_flexibility(kx, omega)?;
        Ok(1.0 / integral.value)
    }

    /// (1/π)∫₀^∞ F_zz(√(k_x² + k_y²), ω)·sinc(k_y b) dk_y (m²/N), with its error estimate and cost.
    pub fn centre_line_flexibility(&self, kx: f64, omega: f64) -> Result<Integral> {
        let kx = kx.abs();
        if omega > 0.0 && self.profile.materials().all(|m| m.damping_ratio == 0.0) {
            return Err(FemError::InvalidGround {
                path: "ground.half_space.damping_ratio".into(),
                value: 0.0,
                allowed: "must be > 0 somewhere in the profile for a moving or vibrating load: on a lossless ground \
                          the Rayleigh poles lie on the real wavenumber axis"
                    .into(),
            });
        }
        let cut = self.cut(kx, omega);
        let half_periods = (cut * 0.5 * self.width / PI) as usize;
        let tolerance =
            Tolerance { relative: STRIP_TOLERANCE, absolute: 0.0, max_intervals: MAX_INTERVALS + 4 * half_periods };
        let integral = self.integral_to(cut, kx, omega, tolerance);
        if !integral.converged {
            return Err(FemError::NotConverged {
                what: format!("the ground's strip integral at k_x = {kx} rad/m, ω = {omega} rad/s"),
                reached: integral.error / integral.value.norm(),
                asked: STRIP_TOLERANCE,
            });
        }
        Ok(integral)
    }

    /// The strip integral with its head to `cut` (a zero of cos(k_y b)) by quadrature and its tail in closed form.
    fn integral_to(&self, cut: f64, kx: f64, omega: f64, tolerance: Tolerance) -> Integral {
        let b = 0.5 * self.width;
        let integrand = |ky: f64| {
            let x = ky * b;
            let sinc = if x.abs() < 1e-4 { 1.0 - x * x / 6.0 } else { x.sin() / x };
            surface_flexibility(&self.profile, kx.hypot(ky), omega) * sinc
        };
        let head = integrate(integrand, 0.0, cut, &self.breakpoints(kx, omega, cut), tolerance);
        // F_zz = (c/k)(1 + α/k²) past the cut, α measured there: the inertia's O(ω²/k²) and what is left of the
        // layering; its tail (1/π)∫ cα sin(k_y b)/(k_y⁴ b) = cα sin(Kb)/(πb)·4/(b²K⁵).
        let c = static_coefficient(self.profile.top(), omega);
        let k_cut = kx.hypot(cut);
        let alpha = (surface_flexibility(&self.profile, k_cut, omega) * k_cut / c - 1.0) * (k_cut * k_cut);
        let (b2, a2) = (b * b, kx * kx);
        let series = 2.0 / (b2 * cut.powi(3)) - (24.0 / (b2 * b2) + 2.0 * a2 / b2) / cut.powi(5)
            + (720.0 / (b2 * b2 * b2) + 60.0 * a2 / (b2 * b2) + 2.25 * a2 * a2 / b2) / cut.powi(7);
        let tail = c * (cut * b).sin() / (PI * b) * (series + alpha * 4.0 / (b * b * cut.powi(5)));
        Integral { value: head.value / PI + tail, error: head.error / PI, ..head }
    }

    /// K = (n + ½)π/b ≥ 10·max(k_x, ω/C_s,top, 1/h₁), ≥ 2ω/C_s,min and ≥ 40/b (module documentation). Past 10/h₁ a
    /// wave sees the top material alone (what lies below reaches it by e^{−2Kh₁} ≤ 2e-9), so it is the top
    /// material's shear wave that the cut must pass ten times — not a slower buried layer's, whose waves live at
    /// k < ω/C_s,min (passed twice over). On a soft layer under a crust at a supercritical speed this halves the cut.
    fn cut(&self, kx: f64, omega: f64) -> f64 {
        let b = 0.5 * self.width;
        let slowest = self.profile.slowest_shear_wave_speed();
        let top = self.profile.top().shear_wave_speed;
        let inverse_top_thickness = self.profile.layers.first().map_or(0.0, |layer| 1.0 / layer.thickness);
        let least = (10.0 * kx.max(omega / top).max(inverse_top_thickness)).max(2.0 * omega / slowest).max(40.0 / b);
        let n = (least * b / PI - 0.5).ceil().max(0.0);
        (n + 0.5) * PI / b
    }

    /// Where the partition starts: the k_y where k = √(k_x² + k_y²) crosses ω/C_s or ω/C_p of a material (kinks of
    /// F_zz), and k_x·10ʲ, graded toward k_y = 0 where a long wave's static F_zz ~ 1/√(k_x² + k_y²) peaks within k_x.
    fn breakpoints(&self, kx: f64, omega: f64, cut: f64) -> Vec<f64> {
        let kinks = self
            .profile
            .wave_speeds()
            .into_iter()
            .map(|c| omega / c)
            .filter(|&k| k > kx)
            .map(|k| (k * k - kx * kx).sqrt());
        let graded = (0..).map(|j| kx * 10f64.powi(j)).take_while(|&k| k > 0.0 && k < cut);
        kinks.chain(graded).collect()
    }
}

/// F_∞·k = (1 − ν)/μ* (1/Pa): the static half-space's flexibility times k, of `material` with its modulus at ω.
fn static_coefficient(material: &SoilMaterial, omega: f64) -> Complex64 {
    (1.0 - material.poisson_ratio()) / material.shear_modulus(omega)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::SoilLayer;

    /// A soft layered site (a crust over soft clay over stiffer clay on a half-space, all damped).
    fn site() -> StripGround {
        let soil = |shear_wave_speed: f64, damping_ratio: f64| SoilMaterial {
            shear_wave_speed,
            compression_wave_speed: 500.0,
            density: 1500.0,
            damping_ratio,
        };
        let layers = [(1.1, 72.0), (3.0, 41.0), (4.5, 65.0)]
            .map(|(thickness, cs)| SoilLayer { thickness, material: soil(cs, 0.03) })
            .to_vec();
        StripGround { width: 3.0, profile: GroundProfile { layers, half_space: soil(100.0, 0.05) } }
    }

    /// The strip integral is converged in its cut and its tolerance: moving the cut ~3× further out and asking 100×
    /// tighter changes k_eq by < 1e-8, below, near and above the site's wave speeds (v = 20, 50, 90 and 120 m/s along
    /// the load's line ω = k_x v: above the buried clay's 41 m/s the cut follows the top layer's 72 m/s) and for long
    /// and short waves.
    #[test]
    fn the_strip_integral_is_converged() {
        let strip = site();
        let tight = Tolerance { relative: 1e-11, absolute: 0.0, max_intervals: 20_000 };
        for v in [20.0, 50.0, 90.0, 120.0] {
            for kx in [0.05, 0.8, 4.0] {
                let omega = kx * v;
                let cut = strip.cut(kx, omega);
                let further = cut + 2.0 * cut.div_euclid(PI / 1.5) * PI / 1.5;
                let default = 1.0 / strip.centre_line_flexibility(kx, omega).unwrap().value;
                let refined = 1.0 / strip.integral_to(further, kx, omega, tight).value;
                let change = ((default - refined) / refined).norm();
                assert!(change < 1e-8, "v {v}, k_x {kx}: {default} vs {refined} ({change:.1e})");
            }
        }
    }

    /// A lossless ground under a vibrating load is refused by key; at rest it is fine; k_eq(0, 0) is 0.
    #[test]
    fn a_lossless_ground_is_refused_under_a_vibrating_load() {
        let mut strip = site();
        for layer in &mut strip.profile.layers {
            layer.material.damping_ratio = 0.0;
        }
        strip.profile.half_space.damping_ratio = 0.0;
        let refused = strip.equivalent_stiffness(0.3, 10.0).unwrap_err().to_string();
        assert!(refused.contains("ground.half_space.damping_ratio = 0"), "{refused}");
        assert!(strip.equivalent_stiffness(0.3, 0.0).unwrap().re > 0.0);
        assert_eq!(strip.equivalent_stiffness(0.0, 0.0).unwrap().norm(), 0.0);
        let narrow = StripGround { width: -1.0, ..site() };
        assert!(narrow.validate().unwrap_err().to_string().contains("ground.width = -1"));
    }
}
