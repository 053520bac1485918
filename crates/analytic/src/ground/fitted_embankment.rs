//! The ground under the two-beam track fitted for a run in time (docs/theory.md §19, "The two-beam track in time"):
//! a spring k_f, a dashpot c and a co-vibrating mass m under the whole embankment in place of the strip's
//! k_eq(k_x, ω), fitted along the load's line ω = kv as the composite beam's foundation is (`fitted`), but to what
//! the rail feels. The rail's operator is D(k) = EI_r k⁴ − ρA_r v²k² + conj k_rail(k, kv) with
//! k_rail = k̃_p/a ∥ (−ω²m_s/a + k̃_b/a ∥ Z/2), Z = EI_e(1 + iη_e)k⁴ − ρA_e ω² + k_eq ([`TrackOnEmbankment`]); the fit
//! stands for k_eq + iη_e EI_e k⁴ (the run in time has no hysteretic loss: the embankment's goes into the dashpot),
//! and a change δk_eq moves D by σ δk_eq with σ = ∂k_rail/∂k_eq = ½ (k̃_p/a)²/(k̃_p/a + B)² · (k̃_b/a)²/(k̃_b/a + Z/2)²
//! (B = −ω²m_s/a + k̃_b/a ∥ Z/2), so the weights are the composite's times |σ|². The fitted track — the rail, pads,
//! sleepers and ballast without their loss factors, the embankment carrying m on k_f + iωc — is the track the run
//! in time assembles (its sleepers spread as their long-wave twin); its rail's wave against the exact one is the
//! error reported.

use super::FittedFoundation;
use super::fitted::{Fit, fit_along, wave_error};
use super::line_support::LineSupport;
use super::moving_load::GroundedBeam;
use super::track_on_embankment::{Embankment, TrackOnEmbankment, hysteretic};
use fem_beam::error::Result;
use fem_beam::properties::{Beam, Foundation};
use fem_beam::sleepers::{Layer, Sleepers};
use num_complex::Complex64;

impl<S: LineSupport + ?Sized> TrackOnEmbankment<'_, S> {
    /// The ground under the whole embankment fitted at `speed` (m/s) to what `rail` feels, as the module says:
    /// k_f (N/m²) and c (N·s/m²) under the whole embankment, m (kg/m) moving with it; the error that of the rail's
    /// single-load wave.
    pub fn fitted_ground(&self, rail: &Beam, speed: f64) -> Result<FittedFoundation> {
        let exact = GroundedBeam::new(rail, self)?.spectrum(speed)?;
        let e = self.embankment;
        let target = |k: f64| -> Result<(Complex64, f64)> {
            let omega = k * speed;
            let loss = if omega > 0.0 { e.loss_factor } else { 0.0 };
            let ground = self.ground.line_stiffness(k, omega)?;
            let sensitivity = self.ground_sensitivity(k, omega)?.norm_sqr();
            Ok((ground + Complex64::new(0.0, loss * e.bending_stiffness * k.powi(4)), sensitivity))
        };
        let fitted = |fit: &Fit, k: f64| self.fitted_rail(rail, fit, |beam| beam.response(k, speed));
        let (fit, wavenumbers) = fit_along(&exact, speed, target, fitted)?;
        let fitted_wave = self.fitted_rail(rail, &fit, |beam| beam.spectrum(speed))?;
        Ok(FittedFoundation::of(speed, &fit, wavenumbers, wave_error(&exact, &fitted_wave)))
    }

    /// σ = ∂k_rail/∂k_ground at (`kx`, `omega`): how the rail's support moves with the ground's.
    fn ground_sensitivity(&self, kx: f64, omega: f64) -> Result<Complex64> {
        let a = self.sleepers.spacing;
        let pad = hysteretic(&self.sleepers.pad, omega) / a;
        let ballast = hysteretic(&self.sleepers.ballast, omega) / a;
        let half = self.half_embankment(kx, omega)?;
        let below = Complex64::new(-omega * omega * self.sleepers.mass / a, 0.0) + ballast * half / (ballast + half);
        Ok(0.5 * (pad / (pad + below)).powi(2) * (ballast / (ballast + half)).powi(2))
    }

    /// `with` applied to the rail on the track the run in time takes with `fit` for the ground: no loss factors, the
    /// embankment carrying the co-vibrating mass on the fitted spring and dashpot.
    fn fitted_rail<T>(
        &self,
        rail: &Beam,
        fit: &Fit,
        with: impl Fn(&GroundedBeam<'_, TrackOnEmbankment<'_, Foundation>>) -> Result<T>,
    ) -> Result<T> {
        let elastic = |layer: Layer| Layer { loss_factor: 0.0, ..layer };
        let sleepers = Sleepers {
            pad: elastic(self.sleepers.pad),
            ballast: elastic(self.sleepers.ballast),
            ..self.sleepers.clone()
        };
        let ground = Foundation::linear(fit.stiffness, fit.damping);
        let embankment = Embankment {
            bending_stiffness: self.embankment.bending_stiffness,
            mass_per_length: self.embankment.mass_per_length + fit.mass,
            loss_factor: 0.0,
        };
        let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &ground };
        with(&GroundedBeam {
            bending_stiffness: rail.bending_stiffness(),
            mass_per_length: rail.mass_per_length(),
            loss_factor: 0.0,
            support: &track,
        })
    }
}
