//! The steady wave of a train (or one load) on the ground (`frictrack stationary` on a `[ground]`; docs/theory.md
//! §19): at each speed the moving-load spectrum of the composite beam (or of the rail on sleepers over the
//! embankment), once, and the wave along the train's frame as the superposition of its axles' shifted single-load
//! waves, W(s) = Σ_j P_j W₁(s + d_j) — under and behind the train,
//! its peaks (refined by golden section) and the upward wake behind it above the ground's wave speeds. Deflections in
//! m (upward positive, peaks as magnitudes), positions s = x − x_head in m (positive ahead of the first axle).

use crate::ground::comparison::Comparison;
use crate::ground::speeds::refined_extremes;
use analytic::ground::{GroundedBeam, LineSupport, MovingSpectrum, StripGround, TrackOnEmbankment};
use fem_beam::{Extreme, Train};
use scenario::Scenario;
use scenario::error::{Result, StudyError, invalid};
use scenario::ground::GroundTrack;
use serde::Serialize;

/// Spacing of the wave's points (m): a tenth of the shortest bowl a track on the ground carries (≳ 5 m for a
/// composite beam on soft ground, ~3 m for a rail on sleepers); the peaks are refined between points, never read off
/// them.
pub const WAVE_STEP: f64 = 0.25;
/// The most points one wave may have (the window's length over [`WAVE_STEP`]).
const MAX_POINTS: usize = 200_000;

/// Where the wave is drawn: from `behind` m behind the last axle to `ahead` m ahead of the first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveWindow {
    /// m behind the last axle, ≥ 0.
    pub behind: f64,
    /// m ahead of the first axle, ≥ 0.
    pub ahead: f64,
}

impl Default for WaveWindow {
    /// 60 m each way: the wake of a soft site's Rayleigh waves behind a train and the bow wave ahead of it.
    fn default() -> Self {
        Self { behind: 60.0, ahead: 60.0 }
    }
}

impl WaveWindow {
    /// The positions s (m, ascending, spaced [`WAVE_STEP`]) for a train `length` m long; refused by key (`domain`)
    /// where a side is negative or not finite, or the window would hold more than 200 000 points.
    pub fn positions(&self, length: f64) -> Result<Vec<f64>> {
        for (side, value) in [("behind", self.behind), ("ahead", self.ahead)] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(invalid(&format!("domain.{side}"), value, "must be finite and ≥ 0 (m)"));
            }
        }
        let span = length + self.behind + self.ahead;
        let count = (span / WAVE_STEP).ceil() as usize + 1;
        if count > MAX_POINTS {
            return Err(invalid(
                "domain",
                format!("{}:{}", self.behind, self.ahead),
                format!(
                    "the window behind the train and ahead of it spans {span:.0} m: at most 50 km (200 000 points)"
                ),
            ));
        }
        Ok((0..count).map(|i| -(length + self.behind) + i as f64 * WAVE_STEP).collect())
    }
}

/// The steady wave at one speed along the train's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundWave {
    /// v (m/s).
    pub speed: f64,
    /// s = x − x_head (m), ascending.
    pub s: Vec<f64>,
    /// W(s) (m, upward positive).
    pub deflection: Vec<f64>,
}

/// The wave at one speed, summarised (the JSON keys of `frictrack stationary`'s points where they mean the same).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroundWavePoint {
    /// v (m/s).
    pub speed: f64,
    /// "converged": the spectrum met its tolerance (a speed where it did not is an error, never a number).
    pub status: &'static str,
    /// How many wavenumbers the spectrum sampled (each a strip integral over the ground).
    pub spectrum_samples: usize,
    /// Largest downward deflection (m, magnitude) and where (s, m).
    pub max_downward_deflection: Extreme,
    /// Largest upward deflection (m) and where (s, m): ahead of the train, between its axles or in its wake.
    pub max_upward_deflection: Extreme,
    /// W under the first axle, s = 0 (m, signed).
    pub deflection_under_load: f64,
    /// W at the window's rear end (m, signed): what the wake still holds there.
    pub deflection_behind: f64,
    /// The window: m behind the last axle, m ahead of the first, spacing of its points (m).
    pub domain: (f64, f64, f64),
}

/// The steady waves of the scenario's axles on its ground over speeds.
#[derive(Debug, Clone)]
pub struct GroundWaveStudy {
    /// The scenario's title.
    pub title: String,
    /// The beam's EI (N·m²) and ρA (kg/m): the composite beam's, or the rail's.
    pub beam: (f64, f64),
    /// The strip of ground under it.
    pub strip: StripGround,
    /// The composite beam, or one rail on sleepers over an embankment.
    pub track: GroundTrack,
    /// The axles as the beam carries them.
    pub train: Train,
    /// One point per speed.
    pub points: Vec<GroundWavePoint>,
    /// The waves, one per speed.
    pub waves: Vec<GroundWave>,
    /// A measured record beside the wave (one speed only), where one was given.
    pub comparison: Option<Comparison>,
}

impl GroundWaveStudy {
    /// The waves at `speeds` (m/s, each ≥ 0) of the scenario's axles ([`Scenario::axles_on_the_ground`]) on
    /// `window`; stops with [`StudyError::Interrupted`] before the next speed once `stop` is raised, telling
    /// `progress` the speeds done. A speed costs a spectrum (0.1–0.5 s on a soft site, 2 threads) and the wave's
    /// points (a train's read from one load's wave every 5 cm: 0.5 s for the X2000 at Ledsgård in all).
    pub fn of(
        scenario: &Scenario,
        speeds: &[f64],
        window: WaveWindow,
        stop: Option<&std::sync::atomic::AtomicBool>,
        progress: &dyn Fn(usize),
    ) -> Result<Self> {
        let (beam, strip, track) = scenario.ground_track()?;
        let train = scenario.axles_on_the_ground()?;
        let positions = window.positions(train.length())?;
        let on_embankment;
        let support: &dyn LineSupport = match &track {
            GroundTrack::Composite => &strip,
            GroundTrack::RailOnEmbankment { sleepers, embankment } => {
                on_embankment = TrackOnEmbankment { sleepers, embankment: *embankment, ground: &strip };
                &on_embankment
            }
        };
        let grounded = GroundedBeam::new(&beam, support).map_err(StudyError::from)?;
        let (mut points, mut waves) = (Vec::with_capacity(speeds.len()), Vec::with_capacity(speeds.len()));
        for &speed in speeds {
            if stop.is_some_and(|s| s.load(std::sync::atomic::Ordering::Relaxed)) {
                return Err(StudyError::Interrupted);
            }
            let spectrum = grounded.spectrum(speed).map_err(StudyError::from)?;
            let wave = wave_of(&spectrum, &train, speed, &positions);
            points.push(summary(&spectrum, &train, &wave, window));
            waves.push(wave);
            progress(points.len());
        }
        let beam = (beam.bending_stiffness(), beam.mass_per_length());
        let title = scenario.title.clone();
        Ok(Self { title, beam, strip: strip.clone(), track: track.clone(), train, points, waves, comparison: None })
    }
}

/// The wave of `train` at `speed` from its spectrum, at `positions` (in parallel).
fn wave_of(spectrum: &MovingSpectrum, train: &Train, speed: f64, positions: &[f64]) -> GroundWave {
    GroundWave { speed, s: positions.to_vec(), deflection: spectrum.wave_under(&train.axles, positions) }
}

/// The point of `wave`: its peaks refined between its points, the deflection under the first axle and at the rear.
fn summary(spectrum: &MovingSpectrum, train: &Train, wave: &GroundWave, window: WaveWindow) -> GroundWavePoint {
    let samples: Vec<(f64, f64)> = wave.s.iter().copied().zip(wave.deflection.iter().copied()).collect();
    let extremes = refined_extremes(&samples, &|s| spectrum.deflection_under(&train.axles, s));
    GroundWavePoint {
        speed: wave.speed,
        status: "converged",
        spectrum_samples: spectrum.samples(),
        max_downward_deflection: extremes.max_downward,
        max_upward_deflection: extremes.max_upward,
        deflection_under_load: spectrum.deflection_under(&train.axles, 0.0),
        deflection_behind: wave.deflection.first().copied().unwrap_or(0.0),
        domain: (window.behind, window.ahead, WAVE_STEP),
    }
}
