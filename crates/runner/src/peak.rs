//! The maximum over speed of one metric of a sweep, refined below the sweep's spacing on fresh runs
//! (docs/theory.md §7): the one refinement behind every critical speed and every reported peak.
//!
//! Around the sweep's best speed v_i the bracket is [v_{i−1}, v_{i+1}]. With `scan` > 0 the bracket is first sampled
//! at `scan` evenly spaced interior speeds and the golden section then runs between the neighbours of the best
//! sample: a metric that is not unimodal inside the bracket — the largest deck acceleration over the nodes, whose
//! place jumps between nodes and instants as the speed changes, has two peaks 0.7 m/s apart at one resonance
//! (measured: HSLM-A3 on the 20 m example deck, 7.91 m/s² at 103.5 m/s and 7.76 m/s² at 104.2 m/s) — is then
//! still refined to its largest peak, not to whichever one golden section meets. `scan` = 0 is golden section on the
//! whole bracket. A maximum at the first or last speed is no interior peak: it is returned unrefined, as a bound.

use super::{Runner, SweepPoint};
use analytic::golden::refine_peak;
use scenario::Case;
use scenario::error::{Result, invalid};
use serde::Serialize;

/// Where the largest value of a sweep lies in its speed range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PeakLocation {
    /// Inside the range: a peak, refined between the sweep's neighbours of the maximum.
    Interior,
    /// At the lowest speed: only a bound — the peak is at or below it.
    LowerEnd,
    /// At the highest speed: only a bound — the peak is at or above it.
    UpperEnd,
}

/// A metric of a sweep point whose maximum over speed is sought.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Metric {
    /// The max downward deflection (m).
    MaxDownwardDeflection,
    /// The acceleration a deck check reads ([`SweepPoint::deck_acceleration`], m/s²).
    DeckAcceleration,
}

impl Metric {
    /// Its value at `point`.
    pub fn of(self, point: &SweepPoint) -> f64 {
        match self {
            Metric::MaxDownwardDeflection => point.deflection.max_downward.value,
            Metric::DeckAcceleration => point.deck_acceleration(),
        }
    }
}

/// The refined maximum of one metric over speed.
#[derive(Debug, Clone, PartialEq)]
pub struct RefinedPeak {
    /// Whether `speed` is an interior peak or a bound at an end of the range.
    pub location: PeakLocation,
    /// The sweep's speed range (m/s).
    pub range: (f64, f64),
    /// Speed of the largest value found (m/s); at an end of the range, that end.
    pub speed: f64,
    /// The largest value found, sweep and refinement together.
    pub value: f64,
    /// The sweep's own maximum (speed, value) before refinement.
    pub sweep_maximum: (f64, f64),
    /// The refinement's fresh runs, in the order they ran.
    pub evaluations: Vec<SweepPoint>,
    /// The width (m/s) of the bracket the refinement ended on: the peak's speed is known to about this.
    pub resolution: f64,
}

impl RefinedPeak {
    /// Whether `speed` is an interior peak rather than a bound.
    pub fn is_interior(&self) -> bool {
        self.location == PeakLocation::Interior
    }
}

/// The index of the sweep's largest `metric`, None for an empty sweep.
fn best_index(sweep: &[SweepPoint], metric: Metric) -> Option<usize> {
    (0..sweep.len()).max_by(|&a, &b| metric.of(&sweep[a]).total_cmp(&metric.of(&sweep[b])))
}

/// The sweep's own maximum of `metric`, without refinement runs (None for an empty sweep): at an end of the range a
/// bound (resolution 0, as [`refine_maximum`] returns it), inside it a peak known to the width of the bracket
/// [v_{i−1}, v_{i+1}] — what is reported when a refinement could not run.
pub fn unrefined(sweep: &[SweepPoint], metric: Metric) -> Option<RefinedPeak> {
    let best = best_index(sweep, metric)?;
    let sweep_maximum = (sweep[best].speed, metric.of(&sweep[best]));
    let (location, resolution) = if best == 0 {
        (PeakLocation::LowerEnd, 0.0)
    } else if best == sweep.len() - 1 {
        (PeakLocation::UpperEnd, 0.0)
    } else {
        (PeakLocation::Interior, sweep[best + 1].speed - sweep[best - 1].speed)
    };
    Some(RefinedPeak {
        location,
        range: (sweep[0].speed, sweep[sweep.len() - 1].speed),
        speed: sweep_maximum.0,
        value: sweep_maximum.1,
        sweep_maximum,
        evaluations: Vec::new(),
        resolution,
    })
}

/// The runs [`refine_maximum`] adds to a sweep of speed step `step` (m/s) for `tolerance` and `scan`, for estimates
/// made before the sweep: `scan` evenly spaced speeds in the bracket of two steps around the sweep's best, then golden
/// section between the neighbours of the best of them (a bracket of 2·2step/(scan + 1)).
pub fn refinement_runs(step: f64, tolerance: f64, scan: usize) -> usize {
    let bracket = 2.0 * step;
    let golden = if scan > 0 { 2.0 * bracket / (scan + 1) as f64 } else { bracket };
    scan + analytic::golden::golden_section_evaluations(golden, tolerance)
}

/// Refine the sweep's maximum of `metric` to `tolerance` (m/s) on fresh runs of `case` (see the module
/// documentation); `scan` interior samples of the bracket first (0: golden section alone). The sweep must be in
/// increasing speed; its spacing need not be even.
pub fn refine_maximum(
    case: &Case,
    sweep: &[SweepPoint],
    metric: Metric,
    (tolerance, scan): (f64, usize),
    runner: &Runner,
) -> Result<RefinedPeak> {
    if sweep.len() < 3 {
        return Err(invalid(
            "speeds",
            format!("{} speed(s)", sweep.len()),
            "a peak needs a sweep of at least 3 speeds (an interior maximum)",
        ));
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(invalid("tolerance", tolerance, "must be finite and > 0 (m/s)"));
    }
    let start = unrefined(sweep, metric).expect("3+ points");
    if !start.is_interior() {
        return Ok(start);
    }
    let (range, sweep_maximum) = (start.range, start.sweep_maximum);
    let best = best_index(sweep, metric).expect("3+ points");
    let (mut lo, mut hi) = (sweep[best - 1].speed, sweep[best + 1].speed);
    let mut evaluations = Vec::new();
    let mut run = |v: f64| -> Result<f64> {
        let point = runner.point(case, v)?;
        let value = metric.of(&point);
        evaluations.push(point);
        Ok(value)
    };
    if scan > 0 {
        // The bracket's samples, the sweep's own three among them; golden section between the best one's neighbours.
        let spacing = (hi - lo) / (scan + 1) as f64;
        let mut samples = vec![(lo, metric.of(&sweep[best - 1])), (hi, metric.of(&sweep[best + 1]))];
        samples.push(sweep_maximum);
        for k in 1..=scan {
            let v = lo + k as f64 * spacing;
            if (v - sweep_maximum.0).abs() > 1e-9 * v {
                samples.push((v, run(v)?));
            }
        }
        samples.sort_by(|a, b| a.0.total_cmp(&b.0));
        let top = (0..samples.len()).max_by(|&a, &b| samples[a].1.total_cmp(&samples[b].1)).expect("samples");
        lo = samples[top.saturating_sub(1)].0;
        hi = samples[(top + 1).min(samples.len() - 1)].0;
    }
    let resolution = tolerance.min(hi - lo);
    let refined = refine_peak(&mut run, (lo, hi), sweep_maximum, tolerance)?;
    // The refinement never reports less than it has seen, the scan included.
    let seen = evaluations.iter().map(|p| (p.speed, metric.of(p)));
    let (speed, value) = seen.fold(refined, |best, s| if s.1 > best.1 { s } else { best });
    Ok(RefinedPeak { location: PeakLocation::Interior, range, speed, value, sweep_maximum, evaluations, resolution })
}
