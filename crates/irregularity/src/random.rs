//! A random rail profile from a spectrum by spectral representation (Shinozuka & Deodatis 1991, Appl. Mech. Rev.
//! 44:191–204; docs/theory.md §11):
//!
//!   r(x) = Σ_k A_k cos(Ω_k x + φ_k),  Ω_k = k·ΔΩ,  ΔΩ = 2π/L_p,  A_k = √(2·∫_{bin k} S dΩ),  φ_k uniform on [0, 2π).
//!
//! The frequencies are the harmonics of the period L_p (the requested length, so the profile does not repeat within
//! it); bin k is [Ω_k − ΔΩ/2, Ω_k + ΔΩ/2] clipped to the band, so the bins tile the band and the variance Σ A_k²/2
//! is ∫_band S dΩ exactly. Sampled over a whole period at a spacing dividing it, the harmonics are orthogonal: the
//! sample variance is that integral to round-off, and the periodogram at Ω_k is the bin's mean of S. Phases come
//! from [`SplitMix64`] and cosines from [`crate::trig`]: the same seed gives the same bits on every machine.

use crate::error::{Result, invalid};
use crate::rng::SplitMix64;
use crate::spectrum::Spectrum;
use crate::trig::{MAX_ARGUMENT, sin_cos};
use std::f64::consts::TAU;

/// Largest number of harmonics of one profile (1 MB of components; 1000 m over 0.5–80 m takes ~2000).
pub const MAX_COMPONENTS: usize = 100_000;

/// What a random profile is drawn from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RandomSettings {
    /// The spectrum.
    pub spectrum: Spectrum,
    /// Band of wavelengths (m): (shortest, longest).
    pub band: (f64, f64),
    /// Period L_p (m): the profile repeats after it; give at least the length of track a run covers.
    pub length: f64,
    /// Seed of the phases.
    pub seed: u64,
}

impl RandomSettings {
    /// `spectrum` over its usual band, `length` m, seed `seed`.
    pub fn new(spectrum: Spectrum, length: f64, seed: u64) -> Self {
        Self { spectrum, band: spectrum.default_band(), length, seed }
    }

    /// Check the band and length, and the number of harmonics they need, before anything is allocated.
    pub fn validate(&self) -> Result<()> {
        let (short, long) = self.band;
        if !(short.is_finite() && long.is_finite() && short > 0.0 && short < long) {
            return Err(invalid("band", format!("{short}:{long}"), "needs wavelengths 0 < shortest < longest (m)"));
        }
        if !(self.length.is_finite() && self.length >= long) {
            return Err(invalid(
                "length",
                self.length,
                format!("must be finite and at least the longest wavelength, {long} m"),
            ));
        }
        let count = self.length / short;
        if count > MAX_COMPONENTS as f64 {
            return Err(invalid(
                "length",
                self.length,
                format!(
                    "needs {count:.0} harmonics down to {short} m, over the limit of {MAX_COMPONENTS}: shorten the \
                     profile or raise the shortest wavelength"
                ),
            ));
        }
        Ok(())
    }
}

/// One harmonic A cos(Ω x + φ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    /// Ω (rad/m).
    pub wavenumber: f64,
    /// A (m).
    pub amplitude: f64,
    /// φ (rad).
    pub phase: f64,
}

/// A random profile: its harmonics.
#[derive(Debug, Clone, PartialEq)]
pub struct RandomProfile {
    /// What it was drawn from.
    pub settings: RandomSettings,
    /// The harmonics, by rising Ω.
    pub harmonics: Vec<Harmonic>,
}

impl RandomProfile {
    /// Draw the profile of `settings`.
    pub fn new(settings: RandomSettings) -> Result<Self> {
        settings.validate()?;
        let (short, long) = settings.band;
        let (low, high) = (TAU / long, TAU / short);
        let step = TAU / settings.length;
        let first = (low / step).round().max(1.0) as usize;
        let last = (high / step).round() as usize;
        let mut rng = SplitMix64::new(settings.seed);
        let harmonics = (first..=last)
            .filter_map(|k| {
                let centre = k as f64 * step;
                let (a, b) = ((centre - 0.5 * step).max(low), (centre + 0.5 * step).min(high));
                // Every harmonic draws its phase, inside the band or not, so a seed's phases do not shift with it.
                let phase = TAU * rng.next_unit();
                (b > a).then(|| Harmonic {
                    wavenumber: centre,
                    amplitude: (2.0 * settings.spectrum.variance(a, b)).sqrt(),
                    phase,
                })
            })
            .collect();
        Ok(Self { settings, harmonics })
    }

    /// The variance of the profile, Σ A_k²/2 = ∫_band S dΩ (m²).
    pub fn variance(&self) -> f64 {
        self.harmonics.iter().map(|h| 0.5 * h.amplitude * h.amplitude).sum()
    }

    /// (r(x), r′(x)) in m and m/m; x within ±[`MAX_ARGUMENT`]/Ω_max of 0 (about 100 km at 0.5 m).
    pub fn height_slope(&self, x: f64) -> (f64, f64) {
        self.harmonics.iter().fold((0.0, 0.0), |(r, s), h| {
            let (sin, cos) = sin_cos(h.wavenumber * x + h.phase);
            (r + h.amplitude * cos, s - h.amplitude * h.wavenumber * sin)
        })
    }

    /// The farthest |x| (m) at which [`RandomProfile::height_slope`] keeps its accuracy.
    pub fn reach(&self) -> f64 {
        let top = self.harmonics.last().map_or(1.0, |h| h.wavenumber);
        (MAX_ARGUMENT - TAU) / top
    }
}
