//! One point of a sweep: a run's results at one speed (extremes, energy, solver work; the vehicles' and sleepers'
//! columns where it has them), or why it failed.

use crate::sleeper_columns::SleeperColumns;
use fem_beam::{DeflectionExtremes, Extreme};
use nscd::EnergyBalance;
use scenario::quantities::unit;
use serde::{Deserialize, Serialize};

/// What one run of a sweep reports: extremes as [`Extreme`]s (magnitudes with node and time), the energy balance.
/// A journal of another version's points is refused by its format line ([`crate::journal`]), not by their fields.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct SweepPoint {
    /// Load speed (m/s).
    pub speed: f64,
    /// Max downward and upward deflections over nodes and steps (m, magnitudes), their nodes and times.
    #[serde(flatten)]
    pub deflection: DeflectionExtremes,
    /// The same while the load was inside the extremes window.
    #[serde(flatten, with = "fem_beam::extreme::in_window")]
    pub window_deflection: DeflectionExtremes,
    /// Largest vertical acceleration over nodes and steps (m/s², magnitude); None where undefined (a Timoshenko rail:
    /// [`track::RunResult::max_acceleration`]).
    #[serde(default)]
    pub max_acceleration: Option<Extreme>,
    /// Largest band-limited acceleration (m/s², magnitude), where the run asked for one: a bridge deck's check value
    /// ([`track::RunResult::band_acceleration`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub band_acceleration: Option<Extreme>,
    /// W̄ (m²).
    pub global_norm: f64,
    /// The energy balance (J).
    pub energy: EnergyBalance,
    /// Mean friction-solver iterations per step.
    pub mean_iterations: f64,
    /// The vehicles' columns, in a run with vehicles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vehicles: Option<VehicleColumns>,
    /// The sleepers' columns, in a run on sleepers.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sleepers: Option<SleeperColumns>,
}

impl SweepPoint {
    /// The acceleration a deck check reads (m/s²): the band-limited one where the run computed it (a span: EN 1990
    /// A2's modes up to f_max), else the nodal one; NaN where neither is defined.
    pub fn deck_acceleration(&self) -> f64 {
        self.band_acceleration.or(self.max_acceleration).map_or(f64::NAN, |a| a.value)
    }
}

/// What a sweep point reports of the vehicles (docs/theory.md §12), over the wheels and bodies of the run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct VehicleColumns {
    /// Smallest wheel–rail force of any wheel (N).
    pub min_wheel_force: f64,
    /// Largest wheel–rail force (N).
    pub max_wheel_force: f64,
    /// Largest ΔQ/Q₀ of any wheel.
    pub max_dynamic_increment: f64,
    /// Losses of contact over all wheels.
    pub losses_of_contact: usize,
    /// Largest body acceleration of any vehicle (m/s²).
    pub max_body_acceleration: f64,
    /// Largest body RMS acceleration (m/s²).
    pub rms_body_acceleration: f64,
}

impl VehicleColumns {
    /// The columns of a run's vehicle results.
    pub fn of(results: &track::simulation::VehicleResults) -> Self {
        let wheels = &results.wheels;
        let largest = |values: &mut dyn Iterator<Item = f64>| values.fold(0.0, f64::max);
        Self {
            min_wheel_force: wheels.iter().map(|w| w.min_force).fold(f64::INFINITY, f64::min),
            max_wheel_force: largest(&mut wheels.iter().map(|w| w.max_force)),
            max_dynamic_increment: largest(&mut wheels.iter().map(|w| w.dynamic_increment())),
            losses_of_contact: wheels.iter().map(|w| w.losses.len()).sum(),
            max_body_acceleration: largest(&mut results.bodies.iter().map(|b| b.max_acceleration)),
            rms_body_acceleration: largest(&mut results.bodies.iter().map(|b| b.rms_acceleration)),
        }
    }

    /// The values in the order of [`VEHICLE_CSV_COLUMNS`].
    pub fn values(&self) -> [f64; 6] {
        [
            self.min_wheel_force,
            self.max_wheel_force,
            self.max_dynamic_increment,
            self.losses_of_contact as f64,
            self.max_body_acceleration,
            self.rms_body_acceleration,
        ]
    }
}

/// The vehicles' columns of sweep output, after [`crate::CSV_COLUMNS`] when a sweep runs vehicles: name, unit, meaning.
pub const VEHICLE_CSV_COLUMNS: [(&str, &str, &str); 6] = [
    ("min_wheel_force", unit("min_wheel_force"), "smallest wheel–rail contact force of any wheel (0: contact lost)"),
    ("max_wheel_force", unit("max_wheel_force"), "largest wheel–rail contact force"),
    ("max_dynamic_increment", unit("max_dynamic_increment"), "largest |Q − Q₀|/Q₀ of any wheel"),
    ("losses_of_contact", unit("losses_of_contact"), "losses of contact over all wheels"),
    ("max_body_acceleration", unit("max_body_acceleration"), "largest body acceleration of any vehicle"),
    ("rms_body_acceleration", unit("rms_body_acceleration"), "largest RMS body acceleration of any vehicle"),
];

/// A run of a sweep that failed: its speed and why. The sweep keeps every other run (see
/// [`crate::Runner::speed_sweep_keeping`]); its CSV row has the speed and empty values.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FailedRun {
    /// Load speed (m/s).
    pub speed: f64,
    /// The run's error, as text.
    pub error: String,
}

/// One speed of a sweep: its finished point, or why it failed.
pub type SweepRow = std::result::Result<SweepPoint, FailedRun>;

/// The finished points of sweep rows, in order (the failed runs left out).
pub fn finished(rows: &[SweepRow]) -> Vec<SweepPoint> {
    rows.iter().filter_map(|r| r.as_ref().ok().cloned()).collect()
}

/// The failed runs of sweep rows, in order.
pub fn failures(rows: &[SweepRow]) -> Vec<FailedRun> {
    rows.iter().filter_map(|r| r.as_ref().err().cloned()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pairs are written flat under the names every JSON file and Python use — `max_downward_deflection`,
    /// `max_upward_deflection` and their `window_` twins — and a point reads back from them to the bit (a journal);
    /// a point missing one of them is refused.
    #[test]
    fn a_point_keeps_its_flat_names_and_reads_back() {
        let point = SweepPoint {
            speed: 50.0,
            deflection: DeflectionExtremes {
                max_downward: Extreme::at(0.01, 100.0, 0.5),
                max_upward: Extreme::default(),
            },
            window_deflection: DeflectionExtremes {
                max_downward: Extreme::at(0.009, 99.0, 0.45),
                max_upward: Extreme::at(1e-4, 98.0, 0.44),
            },
            max_acceleration: Some(Extreme::at(3.0, 101.0, 0.6)),
            ..SweepPoint::default()
        };
        let json = serde_json::to_value(&point).unwrap();
        let keys: Vec<&str> = json.as_object().unwrap().keys().map(String::as_str).collect();
        for name in [
            "max_downward_deflection",
            "max_upward_deflection",
            "window_max_downward_deflection",
            "window_max_upward_deflection",
        ] {
            assert!(keys.contains(&name), "{name} not in {keys:?}");
        }
        assert!(!keys.iter().any(|k| k.contains("window_deflection") || *k == "deflection"), "{keys:?}");
        assert_eq!(json["window_max_upward_deflection"]["position"], 98.0);
        assert_eq!(serde_json::from_value::<SweepPoint>(json.clone()).unwrap(), point);
        let mut partial = json;
        partial.as_object_mut().unwrap().remove("window_max_upward_deflection");
        assert!(serde_json::from_value::<SweepPoint>(partial).is_err());
    }
}
