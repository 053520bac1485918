//! The critical speed of a configuration: the speed of the largest max downward deflection of a sweep, refined
//! below the sweep step by golden section on fresh runs — or, when that largest value lies at an end of the range,
//! the bound the sweep gives (docs/theory.md §7).

use super::peak::{Metric, PeakLocation, RefinedPeak, refine_maximum};
use super::{Runner, SweepPoint};
use scenario::Case;
use scenario::error::Result;
use serde::Serialize;

/// The refined critical speed of a configuration, or the bound the sweep gives when its maximum lies at an end of
/// the range.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
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
        let tenth = |v: f64| scenario::number::number((v * 10.0).round() / 10.0);
        let (from, to) = (tenth(self.range.0), tenth(self.range.1));
        let peak = format!("max downward deflection {:.2} mm", self.max_downward_deflection * 1e3);
        match self.location {
            PeakLocation::Interior => format!(
                "critical speed {:.2} m/s ({:.0} km/h): {peak} (sweep maximum {:.2} mm at {} m/s, {} refinement runs)",
                self.speed,
                self.speed * scenario::units::KMH,
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
/// inside [v_{i−1}, v_{i+1}] around the sweep's best speed v_i ([`refine_maximum`] without a scan). A maximum at the
/// first or last speed is no critical speed: it is returned unrefined as a bound ([`PeakLocation::LowerEnd`] /
/// [`PeakLocation::UpperEnd`]).
pub fn critical_speed(case: &Case, sweep: &[SweepPoint], tolerance: f64, runner: &Runner) -> Result<CriticalSpeed> {
    Ok(refine_maximum(case, sweep, Metric::MaxDownwardDeflection, (tolerance, 0), runner)?.into())
}

impl From<RefinedPeak> for CriticalSpeed {
    /// The critical speed of a refined peak of the max downward deflection.
    fn from(peak: RefinedPeak) -> Self {
        CriticalSpeed {
            location: peak.location,
            range: peak.range,
            speed: peak.speed,
            max_downward_deflection: peak.value,
            sweep_maximum: peak.sweep_maximum,
            evaluations: peak.evaluations.iter().map(|p| (p.speed, p.deflection.max_downward.value)).collect(),
        }
    }
}
