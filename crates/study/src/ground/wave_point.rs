//! A train's steady wave on the ground at one speed (docs/theory.md §19): the window it is drawn on, the wave, and
//! its summary — the peaks refined between the points, what ballast friction or the sleepers' lift-off add — the
//! numbers `frictrack stationary` prints and writes for each speed on a `[ground]`.

use crate::ground::speeds::refined_extremes;
use analytic::ground::MovingSpectrum;
use fem_beam::{DeflectionExtremes, Extreme, Train};
use scenario::error::{Result, invalid};
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
    /// With a tensionless ballast on the two-beam track: the sleepers' opening and the ballast's push at each s.
    pub ballast: Option<BallastAlong>,
}

/// The ballast under a wave with lift-off, at the wave's points.
#[derive(Debug, Clone, PartialEq)]
pub struct BallastAlong {
    /// ⟨d₀ + d⟩₊: how far the sleepers have lifted off it (m, ≥ 0).
    pub gap: Vec<f64>,
    /// (k_b/a)⟨−d₀ − d⟩₊: its push per metre of rail, the weight's included (N/m, ≥ 0).
    pub ballast_force: Vec<f64>,
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
    /// Largest downward deflection (m, magnitude) and largest upward one (m), each where (s, m): the upward one
    /// ahead of the train, between its axles or in its wake.
    #[serde(flatten)]
    pub deflection: DeflectionExtremes,
    /// W under the first axle, s = 0 (m, signed).
    pub deflection_under_load: f64,
    /// W at the window's rear end (m, signed): what the wake still holds there.
    pub deflection_behind: f64,
    /// The window: m behind the last axle, m ahead of the first, spacing of its points (m).
    pub domain: (f64, f64, f64),
    /// With ballast friction: how its wave was found and what it dissipates.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<FrictionPoint>,
    /// With a tensionless ballast on the two-beam track: where the sleepers lift off it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lift_off: Option<LiftOffPoint>,
}

/// The ballast friction's part of a speed's wave on the ground.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionPoint {
    /// Newton iterations over the continuation's stages.
    pub newton_iterations: usize,
    /// GMRES steps over them.
    pub krylov_iterations: usize,
    /// f_u v Σ h|W′| over the slipping points (W): the power the ballast takes from the train.
    pub friction_power: f64,
    /// Length of track where the rail slides over the ballast (m).
    pub slipping_length: f64,
    /// The largest |r|/f_u over the window's last tenth behind the train (1): what its rear end still holds.
    pub rear_force_ratio: f64,
}

/// Where the sleepers leave the ballast at one speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LiftOffPoint {
    /// Newton iterations of the lifted set.
    pub newton_iterations: usize,
    /// How many separate stretches lift (1).
    pub lift_off_zones: usize,
    /// Length of track where the sleepers are off the ballast (m).
    pub lifted_length: f64,
    /// The widest opening between the sleepers and the ballast (m), refined between the points, and where (s, m);
    /// 0 without a place where nothing lifts.
    pub largest_gap: Extreme,
    /// The ballast's compression under the rail's and the sleepers' weight (m, ≤ 0): what an upward wave must undo.
    pub preload: f64,
}

/// The wave of `train` at `speed` from its spectrum, at `positions` (in parallel).
pub(crate) fn wave_of(spectrum: &MovingSpectrum, train: &Train, speed: f64, positions: &[f64]) -> GroundWave {
    GroundWave { speed, s: positions.to_vec(), deflection: spectrum.wave_under(&train.axles, positions), ballast: None }
}

/// The point of `wave`: its peaks refined between its points, the deflection under the first axle and at the rear;
/// `carried` is what friction adds to the axles' linear wave at any s (m).
pub(crate) fn summary(
    spectrum: &MovingSpectrum,
    train: &Train,
    wave: &GroundWave,
    window: WaveWindow,
    carried: &dyn Fn(f64) -> f64,
) -> GroundWavePoint {
    let samples: Vec<(f64, f64)> = wave.s.iter().copied().zip(wave.deflection.iter().copied()).collect();
    let at = |s: f64| spectrum.deflection_under(&train.axles, s) + carried(s);
    let extremes = refined_extremes(&samples, &at);
    GroundWavePoint {
        speed: wave.speed,
        status: "converged",
        spectrum_samples: spectrum.samples(),
        deflection: extremes,
        deflection_under_load: at(0.0),
        deflection_behind: wave.deflection.first().copied().unwrap_or(0.0),
        domain: (window.behind, window.ahead, WAVE_STEP),
        friction: None,
        lift_off: None,
    }
}
