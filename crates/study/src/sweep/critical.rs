//! The critical speed of a configuration: the speed of the largest max downward deflection of a sweep, refined
//! below the sweep step by golden section on fresh runs — or, when that largest value lies at an end of the range,
//! the bound the sweep gives (docs/theory.md §7).

use super::golden::golden_section;
use super::{Runner, SweepPoint};
use crate::error::{Result, invalid};
use crate::scenario::Case;
use serde::Serialize;

/// Where the largest max downward deflection of a sweep lies in its speed range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PeakLocation {
    /// Inside the range: a critical speed, refined between the sweep's neighbours of the maximum.
    Interior,
    /// At the lowest speed: only a bound — the peak is at or below it.
    LowerEnd,
    /// At the highest speed: only a bound — the peak is at or above it.
    UpperEnd,
}

/// The refined critical speed of a configuration, or the bound the sweep gives when its maximum lies at an end of
/// the range.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriticalSpeed {
    /// Whether `speed` is a critical speed (interior maximum) or a bound (maximum at an end of the range).
    pub location: PeakLocation,
    /// The sweep's speed range (m/s).
    pub range: (f64, f64),
    /// Speed of the largest max downward deflection (m/s); at an end of the range, that end.
    pub speed: f64,
    /// That deflection (m).
    pub max_downward_deflection: f64,
    /// The sweep's own maximum (speed, deflection) before refinement.
    pub sweep_maximum: (f64, f64),
    /// Fresh runs of the refinement: (speed, max downward deflection).
    pub evaluations: Vec<(f64, f64)>,
}

impl CriticalSpeed {
    /// Whether `speed` is a critical speed rather than a bound.
    pub fn is_interior(&self) -> bool {
        self.location == PeakLocation::Interior
    }

    /// One sentence: the critical speed, or the bound and why.
    pub fn describe(&self) -> String {
        // Speeds to 0.1 m/s: a km/h grid gives 38.888888888888886 m/s.
        let tenth = |v: f64| crate::number::number((v * 10.0).round() / 10.0);
        let (from, to) = (tenth(self.range.0), tenth(self.range.1));
        let peak = format!("max downward deflection {:.2} mm", self.max_downward_deflection * 1e3);
        match self.location {
            PeakLocation::Interior => format!(
                "critical speed {:.2} m/s ({:.0} km/h): {peak} (sweep maximum {:.2} mm at {} m/s, {} refinement runs)",
                self.speed,
                self.speed * 3.6,
                self.sweep_maximum.1 * 1e3,
                self.sweep_maximum.0,
                self.evaluations.len()
            ),
            PeakLocation::LowerEnd => format!(
                "no interior maximum in {from}–{to} m/s: the peak is at or below {from} m/s ({peak} there); \
                 extend the range downwards"
            ),
            PeakLocation::UpperEnd => format!(
                "no interior maximum in {from}–{to} m/s: the peak is at or above {to} m/s ({peak} there); \
                 extend the range upwards"
            ),
        }
    }
}

/// Refine the sweep's maximum of the max downward deflection to `tolerance` (m/s) by golden section on fresh runs
/// inside [v_{i−1}, v_{i+1}] around the sweep's best speed v_i. A maximum at the first or last speed is no critical
/// speed: it is returned unrefined as a bound ([`PeakLocation::LowerEnd`] / [`PeakLocation::UpperEnd`]).
pub fn critical_speed(case: &Case, sweep: &[SweepPoint], tolerance: f64, runner: &Runner) -> Result<CriticalSpeed> {
    if sweep.len() < 3 {
        return Err(invalid(
            "speeds",
            format!("{} speed(s)", sweep.len()),
            "a critical speed needs a sweep of at least 3 speeds (an interior maximum)",
        ));
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(invalid("tolerance", tolerance, "must be finite and > 0 (m/s)"));
    }
    let best = (0..sweep.len())
        .max_by(|&a, &b| sweep[a].max_downward_deflection.total_cmp(&sweep[b].max_downward_deflection))
        .expect("non-empty");
    let sweep_maximum = (sweep[best].speed, sweep[best].max_downward_deflection);
    let range = (sweep[0].speed, sweep[sweep.len() - 1].speed);
    let bound = |location| CriticalSpeed {
        location,
        range,
        speed: sweep_maximum.0,
        max_downward_deflection: sweep_maximum.1,
        sweep_maximum,
        evaluations: Vec::new(),
    };
    if best == 0 {
        return Ok(bound(PeakLocation::LowerEnd));
    }
    if best == sweep.len() - 1 {
        return Ok(bound(PeakLocation::UpperEnd));
    }
    let lo = sweep[best.saturating_sub(1)].speed;
    let hi = sweep[(best + 1).min(sweep.len() - 1)].speed;
    let mut evaluations = Vec::new();
    let mut f = |v: f64| -> Result<f64> {
        let w = runner.point(case, v)?.max_downward_deflection;
        evaluations.push((v, w));
        Ok(w)
    };
    let (speed, value) = golden_section(&mut f, lo, hi, tolerance, true)?;
    // The refinement never reports less than the sweep found.
    let (speed, max_downward_deflection) = if value >= sweep_maximum.1 { (speed, value) } else { sweep_maximum };
    Ok(CriticalSpeed {
        location: PeakLocation::Interior,
        range,
        speed,
        max_downward_deflection,
        sweep_maximum,
        evaluations,
    })
}
