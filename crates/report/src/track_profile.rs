//! A sample of a random rail profile with its periodogram against the target spectrum (docs/theory.md §11): the
//! data, a summary and two figures for `frictrack track-profile`, which writes them.

use crate::plot::{PlotSpec, Series, Stroke};
use irregularity::periodogram::{log_bins, periodogram};
use irregularity::{Profile, RandomProfile, RandomSettings};
use scenario::axis::{Axis, Shown};
use scenario::error::{Result, invalid};
use scenario::number::row;
use serde::Serialize;
use std::fmt::Write as _;

/// Largest number of samples written (80 MB of CSV).
pub const MAX_SAMPLES: usize = 2_000_000;
/// Work budget of the periodogram, harmonics × samples (each a sine and cosine): about a second.
const PERIODOGRAM_BUDGET: usize = 50_000_000;

/// What to sample: a random profile and the spacing of its samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileRequest {
    /// The profile's spectrum, band, length (its period) and seed.
    pub settings: RandomSettings,
    /// Sample spacing (m).
    pub spacing: f64,
}

/// What a sampled rail profile is (`track-profile --format json`, `track-profile.json`): the spectrum and band
/// (m), the length and spacing (m), the seed, the number of harmonics, the target and sample standard deviations (m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ProfileSummary {
    /// The spectrum's name.
    pub spectrum: String,
    /// The shortest and longest wavelength (m).
    pub band_wavelengths: [f64; 2],
    /// m.
    pub length: f64,
    /// m.
    pub spacing: f64,
    /// The random generator's seed.
    pub seed: u64,
    /// The harmonics summed.
    pub harmonics: usize,
    /// σ of the spectrum over the band (m).
    pub target_std: f64,
    /// σ of the sample (m).
    pub sample_std: f64,
    /// The units of the CSVs' columns.
    pub units: ProfileUnits,
    /// Where the formula is.
    pub formula: &'static str,
}

/// The units of a profile's CSV columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct ProfileUnits {
    /// x.
    pub x: &'static str,
    /// r.
    pub r: &'static str,
    /// k.
    pub wavenumber: &'static str,
    /// S(k).
    pub psd: &'static str,
}

impl ProfileRequest {
    /// Check everything, sizes included, before anything is allocated.
    pub fn validate(&self) -> Result<()> {
        self.settings.validate()?;
        let shortest = self.settings.band.0;
        if !(self.spacing.is_finite() && self.spacing > 0.0 && self.spacing <= 0.5 * shortest) {
            return Err(invalid(
                "spacing",
                self.spacing,
                format!("must be > 0 and at most half the shortest wavelength ({} m) to resolve it", 0.5 * shortest),
            ));
        }
        let count = self.settings.length / self.spacing;
        if count > MAX_SAMPLES as f64 {
            return Err(invalid(
                "spacing",
                self.spacing,
                format!("gives {count:.0} samples over {} m, over the limit of {MAX_SAMPLES}", self.settings.length),
            ));
        }
        Ok(())
    }
}

/// A sampled profile and its spectrum.
#[derive(Debug, Clone)]
pub struct ProfileSample {
    /// What was asked.
    pub request: ProfileRequest,
    /// The profile.
    pub profile: RandomProfile,
    /// (x m, r m) over one period.
    pub samples: Vec<(f64, f64)>,
    /// (Ω rad/m, periodogram, target S) at the harmonics evaluated (m²/(rad/m)).
    pub psd: Vec<(f64, f64, f64)>,
    /// The sample's variance (m²).
    pub sample_variance: f64,
}

/// Draw, sample and analyse the profile of `request`.
pub fn sample_profile(request: ProfileRequest) -> Result<ProfileSample> {
    request.validate()?;
    let profile = RandomProfile::new(request.settings)?;
    let count = (request.settings.length / request.spacing + 1e-9).floor() as usize;
    let samples = Profile::Random(profile.clone()).sample(0.0, request.spacing, count);
    let heights: Vec<f64> = samples.iter().map(|s| s.1).collect();
    let mean = heights.iter().sum::<f64>() / count as f64;
    let sample_variance = heights.iter().map(|r| (r - mean) * (r - mean)).sum::<f64>() / count as f64;
    // Every harmonic, or every k-th where that would exceed the budget.
    let stride = (profile.harmonics.len() * count).div_ceil(PERIODOGRAM_BUDGET).max(1);
    let omegas: Vec<f64> = profile.harmonics.iter().step_by(stride).map(|h| h.wavenumber).collect();
    let estimate = periodogram(&heights, request.spacing, &omegas);
    let spectrum = request.settings.spectrum;
    let psd = omegas.iter().zip(estimate).map(|(&w, p)| (w, p, spectrum.density(w))).collect();
    Ok(ProfileSample { request, profile, samples, psd, sample_variance })
}

impl ProfileSample {
    /// `x,r` (m) per sample.
    pub fn profile_csv(&self) -> String {
        let mut out = String::from("x,r\n");
        for &(x, r) in &self.samples {
            let _ = writeln!(out, "{}", row(&[x, r]));
        }
        out
    }

    /// `wavenumber,wavelength,periodogram,target` (rad/m, m, m²/(rad/m), m²/(rad/m)).
    pub fn psd_csv(&self) -> String {
        let mut out = String::from("wavenumber,wavelength,periodogram,target\n");
        for &(w, p, s) in &self.psd {
            let _ = writeln!(out, "{}", row(&[w, std::f64::consts::TAU / w, p, s]));
        }
        out
    }

    /// The target standard deviation √(∫_band S dΩ) (m).
    pub fn target_std(&self) -> f64 {
        let s = &self.request.settings;
        let tau = std::f64::consts::TAU;
        s.spectrum.variance(tau / s.band.1, tau / s.band.0).sqrt()
    }

    /// The settings, the target and sample standard deviations and the formula of the spectrum.
    pub fn summary(&self) -> ProfileSummary {
        let s = &self.request.settings;
        ProfileSummary {
            spectrum: s.spectrum.name(),
            band_wavelengths: [s.band.0, s.band.1],
            length: s.length,
            spacing: self.request.spacing,
            seed: s.seed,
            harmonics: self.profile.harmonics.len(),
            target_std: self.target_std(),
            sample_std: self.sample_variance.sqrt(),
            units: ProfileUnits { x: "m", r: "m", wavenumber: "rad/m", psd: "m²/(rad/m)" },
            formula: "docs/theory.md §11",
        }
    }

    /// The profile in mm against x, and the periodogram (log-binned, 10 bins a decade) against the target S.
    pub fn figures(&self, stem: &str) -> Vec<PlotSpec> {
        let s = &self.request.settings;
        let name = s.spectrum.name();
        let (x, r) = (Axis::new("x", "x", Shown::Si), Axis::new("r", "irregularity", Shown::Milli));
        let mut profile = PlotSpec::new(stem, format!("Rail profile, {name} spectrum"), &x, &r);
        profile.subtitle = format!(
            "wavelengths {}–{} m, seed {}, σ = {:.3} mm (target {:.3} mm)",
            s.band.0,
            s.band.1,
            s.seed,
            1e3 * self.sample_variance.sqrt(),
            1e3 * self.target_std()
        );
        profile.series.push(Series {
            label: Some("r(x)".into()),
            color: 4,
            stroke: Stroke::Solid,
            markers: false,
            points: self.samples.iter().map(|&(x, value)| (x, r.factor() * value)).collect(),
        });
        let mut psd = PlotSpec::new(
            format!("{stem}-psd"),
            format!("Rail profile PSD, {name} spectrum"),
            &Axis::new("wavenumber Ω = 2π/λ", "wavenumber", Shown::Si),
            &Axis::new("S", "psd", Shown::Si),
        );
        psd.log_x = true;
        psd.log_y = true;
        psd.subtitle = "periodogram of the sample, averaged over 10 bins a decade, against the target S(Ω)".into();
        let omegas: Vec<f64> = self.psd.iter().map(|p| p.0).collect();
        let values: Vec<f64> = self.psd.iter().map(|p| p.1).collect();
        let targets: Vec<f64> = self.psd.iter().map(|p| p.2).collect();
        // The sample first and the target over it, dashed: the sample follows the target so closely that drawn
        // the other way round it hid it.
        psd.series.push(Series {
            label: Some("sample (binned)".into()),
            color: 5,
            stroke: Stroke::Solid,
            markers: true,
            points: log_bins(&omegas, &values, 10),
        });
        // The target binned as the sample is: a few dozen points, drawn 2 px wide (the 2 000 harmonics drew 1 px).
        psd.series.push(Series {
            label: Some("target S(Ω), binned alike".into()),
            color: 0,
            stroke: Stroke::Dashed,
            markers: false,
            points: log_bins(&omegas, &targets, 10),
        });
        vec![profile, psd]
    }
}

impl crate::output::Output for ProfileSummary {
    fn write_text(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [short, long] = self.band_wavelengths;
        writeln!(
            f,
            "frictrack track-profile: {} spectrum, wavelengths {short}–{long} m, {} m every {} m, seed {}",
            self.spectrum, self.length, self.spacing, self.seed
        )?;
        writeln!(
            f,
            "  {} harmonics; σ = {:.4} mm (target √∫S dΩ = {:.4} mm)",
            self.harmonics,
            1e3 * self.sample_std,
            1e3 * self.target_std
        )
    }

    /// One line: the summary is short.
    fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string(self)
    }
}
