//! A Winkler foundation fitted to a line support along a moving load's own line ω = kv (docs/theory.md §19): what a
//! run in time can take for the ground, whose k_eq(k_x, ω) no local spring, dashpot and mass reproduces exactly.
//!
//! The run's beam is EI k⁴ − (ρA + m)v²k² on a foundation k_f + iωc (no loss factor: it is a frequency-domain
//! quantity), so in the moving frame its operator is D_fit(k) = EI k⁴ − (ρA + m)v²k² + k_f − ickv against the exact
//! D(k) = EI(1 − iη)k⁴ − ρAv²k² + conj k_s(k, kv). Equal where
//!
//! ```text
//! Re k_s(k, kv) ≈ k_f − m (kv)²,      Im k_s(k, kv) + ηEI k⁴ ≈ c kv,
//! ```
//!
//! fitted by least squares with weights |G(k)|⁴ dk over the exact spectrum's samples: a change δD of the operator moves
//! the wave by δG = G²δD, so by Parseval these weights minimise ‖W_fit − W‖₂ to first order — the fit is best on the
//! wavenumbers that carry the response — then reweighted with |G|²/|D_fit|² until it settles (the exact
//! G_fit − G = G G_fit δD). c ≥ 0, m ≥ 0 and k_f > 0 are kept (a negative m is refitted with m = 0; at
//! rest c and m are 0). Its error is measured, not assumed: both waves every 0.25 m from 60 m behind the load to
//! 60 m ahead, max|W_fit − W| over max|W|.

use super::line_support::LineSupport;
use super::moving_load::{GroundedBeam, MovingSpectrum};
use fem_beam::error::Result;
use fem_beam::properties::{Beam, Foundation};
use num_complex::Complex64;
use rayon::prelude::*;

/// Samples whose weight is below this share of the largest leave the fit (their k_s is not computed).
const NEGLIGIBLE_WEIGHT: f64 = 1e-12;
/// The most reweightings of the fit (it settles to 1e-9 in ~5–15).
const REWEIGHTINGS: usize = 30;
/// Where the error is measured: every `ERROR_STEP` m over [−`ERROR_REACH`, `ERROR_REACH`].
const ERROR_REACH: f64 = 60.0;
const ERROR_STEP: f64 = 0.25;

/// A foundation fitted to a line support at one speed, and how far its wave is from the exact one.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FittedFoundation {
    /// v (m/s) it is fitted at.
    pub speed: f64,
    /// k_f (N/m²).
    pub stiffness: f64,
    /// c (N·s/m²).
    pub damping: f64,
    /// m (kg/m): the support's mass that moves with the beam.
    pub co_vibrating_mass: f64,
    /// The wavenumbers it is fitted over (rad/m): the range holding all but 1 % of the final weights at each end.
    pub wavenumbers: (f64, f64),
    /// max|W_fit − W| / max|W| of one load's steady wave (1).
    pub wave_error: f64,
    /// (max downward of W_fit − max downward of W) / max downward of W (1, signed).
    pub peak_error: f64,
}

impl FittedFoundation {
    /// `fit` at `speed` over `wavenumbers`, with its (wave, peak) `errors`.
    pub(super) fn of(speed: f64, fit: &Fit, wavenumbers: (f64, f64), (wave_error, peak_error): (f64, f64)) -> Self {
        Self {
            speed,
            stiffness: fit.stiffness,
            damping: fit.damping,
            co_vibrating_mass: fit.mass,
            wavenumbers,
            wave_error,
            peak_error,
        }
    }
}

impl<S: LineSupport + ?Sized> GroundedBeam<'_, S> {
    /// The foundation fitted at `speed` (m/s), as the module says, with its error.
    pub fn fitted_foundation(&self, speed: f64) -> Result<FittedFoundation> {
        let exact = self.spectrum(speed)?;
        let (fit, wavenumbers) = self.fit(&exact, speed)?;
        let errors = self.error_of(&exact, &fit, speed)?;
        Ok(FittedFoundation::of(speed, &fit, wavenumbers, errors))
    }

    /// The foundation fitted to `exact`, this beam's spectrum at `speed`, without measuring its error: `beam` (this
    /// one's section) carrying its co-vibrating mass, ρA + m, on its spring and dashpot, Foundation::linear(k_f, c) —
    /// a local operator near the exact one.
    pub fn local_fit(&self, beam: &Beam, exact: &MovingSpectrum, speed: f64) -> Result<(Beam, Foundation)> {
        let (fit, _) = self.fit(exact, speed)?;
        let carrying = Beam { density: (self.mass_per_length + fit.mass) / beam.area, ..*beam };
        Ok((carrying, Foundation::linear(fit.stiffness, fit.damping)))
    }

    /// The fit to `exact` at `speed` and the wavenumbers it is fitted over.
    fn fit(&self, exact: &MovingSpectrum, speed: f64) -> Result<(Fit, (f64, f64))> {
        let target = |k: f64| -> Result<(Complex64, f64)> {
            let s = self.support.line_stiffness(k, k * speed)?;
            Ok((s + Complex64::new(0.0, self.loss_factor * self.bending_stiffness * k.powi(4)), 1.0))
        };
        let fitted = |fit: &Fit, k: f64| self.on_fit(fit, |beam| beam.response(k, speed));
        fit_along(exact, speed, target, fitted)
    }

    /// The fitted beam's wave against `exact` at `speed`: (max|W_fit − W| / max|W|, the peaks' signed difference over
    /// the exact peak).
    fn error_of(&self, exact: &MovingSpectrum, fit: &Fit, speed: f64) -> Result<(f64, f64)> {
        Ok(wave_error(exact, &self.on_fit(fit, |beam| beam.spectrum(speed))?))
    }

    /// `with` applied to the beam the run in time takes with `fit`: carrying the co-vibrating mass, without a loss
    /// factor, on the fitted spring and dashpot.
    fn on_fit<T>(&self, fit: &Fit, with: impl Fn(&GroundedBeam<'_, Foundation>) -> Result<T>) -> Result<T> {
        let foundation = Foundation::linear(fit.stiffness, fit.damping);
        with(&GroundedBeam {
            bending_stiffness: self.bending_stiffness,
            mass_per_length: self.mass_per_length + fit.mass,
            loss_factor: 0.0,
            support: &foundation,
        })
    }
}

/// The fit of a support along the load's line ω = kv to the samples of `exact`, a response's spectrum at `speed`,
/// and the wavenumbers it is fitted over. `target(k)` gives what the fitted k_f − mω² + icω stands for there
/// (the exact support, with any hysteretic loss the run in time lacks added to its imaginary part) and |σ|², with
/// σ = ∂D/∂k_s how much the response's operator D moves with it; `fitted(fit, k)` the response G_fit of the
/// operator with the fit in place. Weights |G|⁴|σ|² dk, then |G|²|G_fit|²|σ|² dk until the fit settles: a change
/// δk_s moves the wave by δG = G G_fit σ δk_s.
pub(super) fn fit_along(
    exact: &MovingSpectrum,
    speed: f64,
    target: impl Fn(f64) -> Result<(Complex64, f64)> + Sync,
    fitted: impl Fn(&Fit, f64) -> Result<Complex64>,
) -> Result<(Fit, (f64, f64))> {
    let samples = exact.samples_in_k();
    let heaviest = samples.iter().map(|(_, g, dk)| g.norm().powi(4) * dk).fold(0.0, f64::max);
    let kept: Vec<(f64, Complex64, f64)> =
        samples.into_iter().filter(|(_, g, dk)| g.norm().powi(4) * dk > NEGLIGIBLE_WEIGHT * heaviest).collect();
    let targets: Vec<(Complex64, f64)> = kept.par_iter().map(|&(k, _, _)| target(k)).collect::<Result<_>>()?;
    let mut rows: Vec<Row> = kept
        .iter()
        .zip(&targets)
        .map(|(&(k, g, dk), &(s, sensitivity))| Row {
            weight: g.norm().powi(4) * sensitivity * dk,
            omega: k * speed,
            real: s.re,
            imaginary: s.im,
        })
        .collect();
    let mut fit = least_squares(&rows);
    // |G|⁴ is |G|²/|D|²: with the fitted D in place of the exact one the weights make ∫|G|²|G_fit|²|σ δk_s|² dk,
    // the wave's squared error to first order in δk_s (G_fit − G = G G_fit δD); the fixed point of this reweighting
    // (Steiglitz & McBride's iteration) minimises it.
    for _ in 0..REWEIGHTINGS {
        for ((row, &(k, g, dk)), &(_, sensitivity)) in rows.iter_mut().zip(&kept).zip(&targets) {
            row.weight = (g.norm() * fitted(&fit, k)?.norm()).powi(2) * sensitivity * dk;
        }
        let next = least_squares(&rows);
        let settled = next.close_to(&fit);
        fit = next;
        if settled {
            break;
        }
    }
    Ok((fit, central_range(&kept, &rows)))
}

/// (max|W_fit − W| / max|W|, the peaks' signed difference over the exact peak) of two spectra's single-load waves,
/// every [`ERROR_STEP`] m over ±[`ERROR_REACH`].
pub(super) fn wave_error(exact: &MovingSpectrum, fitted: &MovingSpectrum) -> (f64, f64) {
    let count = (2.0 * ERROR_REACH / ERROR_STEP) as usize;
    let positions: Vec<f64> = (0..=count).map(|i| -ERROR_REACH + i as f64 * ERROR_STEP).collect();
    let (w, w_fit): (Vec<f64>, Vec<f64>) =
        positions.par_iter().map(|&s| (exact.deflection(s), fitted.deflection(s))).unzip();
    let largest = w.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let difference = w.iter().zip(&w_fit).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    let deepest = |values: &[f64]| values.iter().fold(0.0f64, |a, x| a.max(-x));
    (difference / largest, (deepest(&w_fit) - deepest(&w)) / deepest(&w))
}

/// k_f (N/m²), c (N·s/m²), m (kg/m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Fit {
    pub(super) stiffness: f64,
    pub(super) damping: f64,
    pub(super) mass: f64,
}

impl Fit {
    /// Each parameter within 1e-9 of `other`'s (relative; c and m absolutely below 1).
    fn close_to(&self, other: &Fit) -> bool {
        let near = |a: f64, b: f64, floor: f64| (a - b).abs() <= 1e-9 * b.abs().max(floor);
        near(self.stiffness, other.stiffness, 0.0)
            && near(self.damping, other.damping, 1.0)
            && near(self.mass, other.mass, 1.0)
    }
}

/// The wavenumbers of `samples` (ascending k) between which all but 1 % of the `rows`' weight at either end lies.
fn central_range(samples: &[(f64, Complex64, f64)], rows: &[Row]) -> (f64, f64) {
    let total: f64 = rows.iter().map(|r| r.weight).sum();
    let mut running = 0.0;
    let (mut from, mut to) = (samples.first().map_or(0.0, |s| s.0), samples.last().map_or(0.0, |s| s.0));
    for (sample, row) in samples.iter().zip(rows) {
        let before = running;
        running += row.weight;
        if before <= 0.01 * total && running > 0.01 * total {
            from = sample.0;
        }
        if before < 0.99 * total && running >= 0.99 * total {
            to = sample.0;
        }
    }
    (from, to)
}

/// One sample of the fit: its weight, ω = kv, and the targets Re k_s and Im k_s + ηEIk⁴.
struct Row {
    weight: f64,
    omega: f64,
    real: f64,
    imaginary: f64,
}

/// (k_f, c, m) by weighted least squares: c from the imaginary parts alone, (k_f, m) from the real parts, m ≥ 0 and
/// c ≥ 0 kept; at rest (every ω = 0) c = m = 0.
fn least_squares(rows: &[Row]) -> Fit {
    let sum = |f: &dyn Fn(&Row) -> f64| rows.iter().map(|r| r.weight * f(r)).sum::<f64>();
    let (s0, s2, s4) = (sum(&|_| 1.0), sum(&|r| r.omega.powi(2)), sum(&|r| r.omega.powi(4)));
    let (t0, t2) = (sum(&|r| r.real), sum(&|r| r.real * r.omega.powi(2)));
    let damping = match s2 > 0.0 {
        true => (sum(&|r| r.imaginary * r.omega) / s2).max(0.0),
        false => 0.0,
    };
    // Normal equations of min Σ w (k_f − m ω² − Re)²: s0 k_f − s2 m = t0, s2 k_f − s4 m = t2.
    let determinant = s0 * s4 - s2 * s2;
    if determinant > 1e-12 * s0 * s4 {
        let (stiffness, mass) = ((t0 * s4 - t2 * s2) / determinant, (t0 * s2 - s0 * t2) / determinant);
        if mass >= 0.0 {
            return Fit { stiffness, damping, mass };
        }
    }
    Fit { stiffness: t0 / s0, damping, mass: 0.0 }
}
