//! The steady response of the beam on the ground over speeds (docs/theory.md §19): at each speed the moving-load
//! spectrum of one force, its largest downward and upward deflections along the beam (sampled, then refined by
//! golden section), and the speed of the largest downward one — the critical speed of the track on the ground.

use analytic::golden::refine_peak;
use analytic::ground::{GroundedBeam, LineSupport, MovingSpectrum};
use fem_beam::{DeflectionExtremes, Extreme};
use scenario::error::{Result, StudyError};
use serde::Serialize;

/// The steady wave's extremes at one speed, for the scenario's force.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpeedPoint {
    /// v (m/s).
    pub speed: f64,
    /// The largest downward deflection (m, positive down) and the largest upward one (m), the wake behind the load
    /// above the ground's waves.
    #[serde(flatten)]
    pub deflection: DeflectionExtremes<f64>,
}

/// Where along the beam the extremes are sought: from `BEHIND` m behind the load to `AHEAD` m ahead, every `STEP`.
const BEHIND: f64 = 60.0;
const AHEAD: f64 = 20.0;
const STEP: f64 = 0.5;
/// How finely the peak's position and the critical speed are refined (m, m/s).
const POSITION_TOLERANCE: f64 = 1e-3;
const SPEED_TOLERANCE: f64 = 0.05;

/// The extremes of the wave of `force` (N, downward) whose spectrum is `spectrum`, at `speed`.
pub fn extremes(spectrum: &MovingSpectrum, speed: f64, force: f64) -> SpeedPoint {
    let samples: Vec<(f64, f64)> = (0..=((BEHIND + AHEAD) / STEP) as usize)
        .map(|i| -BEHIND + i as f64 * STEP)
        .map(|s| (s, spectrum.deflection(s) * force))
        .collect();
    let extremes = refined_extremes(&samples, &|s| spectrum.deflection(s) * force);
    SpeedPoint { speed, deflection: extremes.map(|e| e.value) }
}

/// The largest downward and upward deflections (magnitudes, m; the upward one 0 where the wave never rises) of the
/// wave `deflection` (m, upward) sampled at `samples` (s, W), each refined by golden section between the
/// neighbours of its best sample to 1 mm in s, with where they are (s, m).
pub fn refined_extremes(samples: &[(f64, f64)], deflection: &dyn Fn(f64) -> f64) -> DeflectionExtremes {
    let refined = |sign: f64| {
        let best = (0..samples.len()).max_by(|&i, &j| (sign * samples[i].1).total_cmp(&(sign * samples[j].1)));
        let i = best.unwrap_or(0);
        let bracket = (samples[i.saturating_sub(1)].0, samples[(i + 1).min(samples.len() - 1)].0);
        let mut f = |s: f64| -> std::result::Result<f64, ()> { Ok(sign * deflection(s)) };
        let (s, value) =
            refine_peak(&mut f, bracket, (samples[i].0, sign * samples[i].1), POSITION_TOLERANCE).unwrap_or((0.0, 0.0));
        Extreme::in_frame(value.max(0.0), s)
    };
    DeflectionExtremes { max_downward: refined(-1.0), max_upward: refined(1.0) }
}

/// The extremes at `speed` of the beam on its support.
pub fn point<S: LineSupport + ?Sized>(grounded: &GroundedBeam<'_, S>, speed: f64, force: f64) -> Result<SpeedPoint> {
    Ok(extremes(&grounded.spectrum(speed).map_err(StudyError::from)?, speed, force))
}

/// The critical speed from the sampled curve `points` (ascending speeds): the largest downward deflection refined
/// between its neighbours by golden section; `None` where it lies at either end of the range (the curve still
/// rising: the peak is not inside it).
pub fn critical_speed(
    points: &[SpeedPoint],
    evaluate: &mut dyn FnMut(f64) -> Result<f64>,
) -> Result<Option<(f64, f64)>> {
    let best = (0..points.len())
        .max_by(|&i, &j| points[i].deflection.max_downward.total_cmp(&points[j].deflection.max_downward));
    let Some(i) = best.filter(|&i| i > 0 && i + 1 < points.len()) else { return Ok(None) };
    let bracket = (points[i - 1].speed, points[i + 1].speed);
    let sample = (points[i].speed, points[i].deflection.max_downward);
    refine_peak(evaluate, bracket, sample, SPEED_TOLERANCE).map(Some)
}
