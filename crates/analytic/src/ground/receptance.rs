//! The point receptance of a beam on a line support (docs/theory.md §19): a harmonic force F e^{iωt} on the infinite
//! beam, its deflection under the force per newton,
//!
//! ```text
//! α(ω) = w(0)/F = (1/π) ∫₀^∞ dk / (EI(1 + iη)k⁴ − ρAω² + k_support(k, ω))     (m/N)
//! ```
//!
//! (the integrand even in k). On a Winkler foundation it is the closed form of `dispersion::point_receptance`; on
//! the ground's strip each k costs a strip integral, so the integral is adaptive Gauss–Kronrod over k with
//! breakpoints where k crosses ω/C of a material (the ground's kinks) and at decades of the beam's characteristic
//! wavenumber, the support left out where EI k⁴ dwarfs it (as in the moving load's spectrum).

use super::line_support::LineSupport;
use super::moving_load::GroundedBeam;
use crate::quadrature::{Tolerance, integrate};
use fem_beam::FemError;
use fem_beam::error::Result;
use num_complex::Complex64;
use std::f64::consts::PI;

/// The relative tolerance of the receptance's integral.
pub const RECEPTANCE_TOLERANCE: f64 = 1e-7;

impl<S: LineSupport + ?Sized> GroundedBeam<'_, S> {
    /// α(ω) (m/N) at circular frequency `omega` (rad/s, ≥ 0): the deflection under a harmonic force per newton,
    /// downward per downward force (the force's own sign convention), with `speeds` the wave speeds (m/s) where the
    /// support has kinks (a ground's materials'; none for a spring).
    pub fn point_receptance(&self, omega: f64, speeds: &[f64]) -> Result<Complex64> {
        let stiffness = Complex64::new(self.bending_stiffness, self.bending_stiffness * self.loss_factor);
        let inertia = self.mass_per_length * omega * omega;
        let failed = std::cell::Cell::new(None);
        let integrand = |k: f64| {
            let bending = self.bending_stiffness * k.powi(4);
            let support = match bending > 1e4 * self.support.stiffness_bound(k, omega) {
                true => Ok(Complex64::new(0.0, 0.0)),
                false => self.support.line_stiffness(k, omega),
            };
            match support {
                Ok(support) => 1.0 / (stiffness * k.powi(4) - inertia + support),
                Err(e) => {
                    failed.set(Some(e));
                    Complex64::new(0.0, 0.0)
                }
            }
        };
        let characteristic = self.characteristic_wavenumber(omega);
        let top = 300.0 * characteristic;
        let mut breakpoints: Vec<f64> = (-6..=2).map(|e| characteristic * 10f64.powi(e)).collect();
        breakpoints.extend(speeds.iter().map(|c| omega / c));
        let tolerance = Tolerance { relative: RECEPTANCE_TOLERANCE, absolute: 0.0, max_intervals: 4000 };
        let integral = integrate(integrand, 0.0, top, &breakpoints, tolerance);
        if let Some(error) = failed.take() {
            return Err(error);
        }
        if !integral.converged {
            return Err(FemError::NotConverged {
                what: format!("the point receptance at ω = {omega} rad/s"),
                reached: integral.error / integral.value.norm(),
                asked: RECEPTANCE_TOLERANCE,
            });
        }
        // Beyond 300 k_c the integrand is 1/(EI k⁴) to 1e-9: its tail 1/(3EI k³) in closed form.
        Ok((integral.value + 1.0 / (3.0 * stiffness * top.powi(3))) / PI)
    }

    /// Where EI k⁴ meets the support's bound and the inertia ρAω² (rad/m), by doubling from 1e-3.
    fn characteristic_wavenumber(&self, omega: f64) -> f64 {
        let mut k: f64 = 1e-3;
        let inertia = self.mass_per_length * omega * omega;
        while self.bending_stiffness * k.powi(4) < self.support.stiffness_bound(k, omega) + inertia {
            k *= 2.0;
        }
        k
    }
}
