//! # runner: how the runs of sweeps and studies are carried out (docs/theory.md §7)
//!
//! - Speed sweeps, the critical speed and the optimal device force (this module and [`Runner`]).
//! - [`journal`]: every finished run on disk at once, so that an interrupted sweep resumes where it stopped.
//! - [`shard`]: a deterministic 1/N of a sweep's points per machine, and the merge of the shards' outputs.
//! - [`cost`]: what a run, a batch of runs or a stationary sweep will cost, said before it starts.
//!
//! A sweep runs one simulation per speed, in parallel on the runner's one thread pool; every run is independent and
//! deterministic and the results are returned in speed order, so the output is identical for any thread count.
//! The critical speed is the speed of the largest max downward deflection, refined below the sweep step by a
//! golden-section search on fresh runs inside the bracket around the sweep's maximum. The optimal device force for
//! fixed N and speed minimises the max downward deflection: a log-spaced scan of the bounds, then golden section
//! around the best scanned force; every evaluated force is returned with its value.

pub mod cost;
mod critical;
pub mod journal;
mod optimal_force;
mod peak;
mod pool;
pub mod shard;
pub mod sleeper_columns;

pub use critical::{CriticalSpeed, critical_speed};
pub use journal::Journal;
pub use optimal_force::{OptimalForce, log_spaced, optimal_device_force, refine_device_force, refine_from_scan};
pub use peak::{Metric, PeakLocation, RefinedPeak, refine_maximum, refinement_runs, unrefined};
pub use pool::{Runner, worker_threads};
pub use sleeper_columns::{SLEEPER_CSV_COLUMNS, SleeperColumns};

use fem_beam::Extreme;
use nscd::EnergyBalance;
use scenario::error::{Result, StudyError};
use scenario::number::row_with_gaps;
use scenario::{Case, Scenario};
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};
use track::simulation::StepView;
use track::{RunResult, RunSettings, Simulation};

/// What one run of a sweep reports: extremes as [`Extreme`]s (magnitudes with node and time), the energy balance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SweepPoint {
    /// Load speed (m/s).
    pub speed: f64,
    /// Max downward deflection over nodes and steps (m, magnitude), its node and time.
    pub max_downward_deflection: Extreme,
    /// Max upward deflection (m, magnitude).
    pub max_upward_deflection: Extreme,
    /// Max downward deflection while the load was inside the extremes window (m, magnitude).
    pub window_max_downward_deflection: Extreme,
    /// Max upward deflection while the load was inside the extremes window (m, magnitude).
    pub window_max_upward_deflection: Extreme,
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

/// The vehicles' columns of sweep output, after [`CSV_COLUMNS`] when a sweep runs vehicles: name, unit, meaning.
pub const VEHICLE_CSV_COLUMNS: [(&str, &str, &str); 6] = [
    ("min_wheel_force", "N", "smallest wheel–rail contact force of any wheel (0: contact lost)"),
    ("max_wheel_force", "N", "largest wheel–rail contact force"),
    ("max_dynamic_increment", "1", "largest |Q − Q₀|/Q₀ of any wheel"),
    ("losses_of_contact", "1", "losses of contact over all wheels"),
    ("max_body_acceleration", "m/s²", "largest body acceleration of any vehicle"),
    ("rms_body_acceleration", "m/s²", "largest RMS body acceleration of any vehicle"),
];

/// A run of a sweep that failed: its speed and why. The sweep keeps every other run (see
/// [`Runner::speed_sweep_keeping`]); its CSV row has the speed and empty values.
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

/// One run of `case` at `speed` (m/s), without journal (see [`Runner::point`]).
pub fn run_point(case: &Case, speed: f64) -> Result<SweepPoint> {
    point_until(case, speed, None)
}

/// One run of `case` at `speed`, abandoned at the first step after `stop` is raised.
fn point_until(case: &Case, speed: f64, stop: Option<&AtomicBool>) -> Result<SweepPoint> {
    let mut settings = case.settings.clone();
    settings.moving = settings.moving.at_speed(speed)?;
    settings.record.sections.clear();
    let r = simulate_until(case, &settings, stop)?;
    let window = r.window.unwrap_or_default();
    Ok(SweepPoint {
        speed,
        max_downward_deflection: r.max_downward,
        max_upward_deflection: r.max_upward,
        window_max_downward_deflection: window.max_downward,
        window_max_upward_deflection: window.max_upward,
        max_acceleration: r.max_acceleration,
        band_acceleration: r.band_acceleration.as_ref().map(|b| b.extreme),
        global_norm: r.global_norm,
        energy: r.energy.balance(),
        mean_iterations: r.statistics.mean_iterations,
        vehicles: r.vehicles.as_ref().map(VehicleColumns::of),
        sleepers: r.sleepers.as_ref().map(|s| SleeperColumns::of(&case.model, s, settings.record.extremes_nodes)),
    })
}

/// Run `case` under `settings`, abandoned with [`StudyError::Interrupted`] at the first step after `stop` is raised
/// (a load of one atomic flag per step), so that Ctrl-C or SIGTERM ends a long run within a step.
fn simulate_until(case: &Case, settings: &RunSettings, stop: Option<&AtomicBool>) -> Result<RunResult> {
    simulate_observed(case, settings, stop, &mut |_| true)
}

/// The same, with `observer` called after every step (it may stop the run early by returning false).
pub fn simulate_observed(
    case: &Case,
    settings: &RunSettings,
    stop: Option<&AtomicBool>,
    observer: &mut dyn FnMut(&StepView<'_>) -> bool,
) -> Result<RunResult> {
    let simulation = Simulation::new(&case.model, &case.interactions, settings)?;
    let stopped = || stop.is_some_and(|s| s.load(Ordering::Relaxed));
    let result = simulation.run_observed(&mut |view| observer(view) && !stopped())?;
    if stopped() { Err(StudyError::Interrupted) } else { Ok(result) }
}

/// The columns of sweep output: name, unit, meaning (in this order; the user guide and the JSON beside a sweep's CSV
/// list them).
pub const CSV_COLUMNS: [(&str, &str, &str); 17] = [
    ("speed", "m/s", "load speed"),
    ("max_downward_deflection", "m", "largest downward deflection over all nodes and steps (magnitude)"),
    ("max_upward_deflection", "m", "largest upward deflection over all nodes and steps (magnitude)"),
    ("dissipated_energy", "J", "energy removed by friction and viscous damping"),
    ("global_norm", "m²", "W̄ = (1/t_on)∫∫|w| dx dt over the crossing"),
    ("max_downward_deflection_position", "m", "node of the largest downward deflection"),
    ("max_downward_deflection_time", "s", "time of the largest downward deflection"),
    ("load_work", "J", "work of the moving load"),
    ("energy_residual", "J", "residual of the discrete energy balance"),
    ("mean_iterations", "1", "mean friction-solver iterations per step"),
    ("window_max_downward_deflection", "m", "largest downward deflection while the load is in the extremes window"),
    ("window_max_downward_deflection_position", "m", "its node"),
    ("window_max_downward_deflection_time", "s", "its time"),
    ("window_max_upward_deflection", "m", "largest upward deflection while the load is in the extremes window"),
    ("window_max_upward_deflection_position", "m", "its node"),
    ("window_max_upward_deflection_time", "s", "its time"),
    ("max_acceleration", "m/s²", "largest vertical acceleration over all nodes and steps (magnitude; bridge decks)"),
];

/// The band-limited acceleration's column of sweep output, last, when the sweep's runs compute one.
pub const BAND_CSV_COLUMNS: [(&str, &str, &str); 1] = [(
    "band_acceleration",
    "m/s²",
    "largest acceleration in the beam's modes up to output.acceleration_band (a span's EN 1990 A2 check value)",
)];

/// The columns of a sweep's CSV of `scenario` (name, unit, meaning), as [`write_csv_rows`] writes them for its runs.
pub fn csv_columns_of(
    scenario: &Scenario,
) -> impl Iterator<Item = &'static (&'static str, &'static str, &'static str)> {
    let band = scenario.acceleration_band().is_ok_and(|b| b.is_some());
    csv_columns(scenario.vehicle.is_some(), scenario.sleepers.is_some(), band)
}

/// Every column a sweep's CSV may hold (name, unit, meaning), whatever the scenario: the units of any sweep's file.
pub fn every_csv_column() -> impl Iterator<Item = &'static (&'static str, &'static str, &'static str)> {
    csv_columns(true, true, true)
}

/// The columns of a sweep's CSV (name, unit, meaning): [`CSV_COLUMNS`], then [`VEHICLE_CSV_COLUMNS`] for a sweep of
/// vehicles, [`SLEEPER_CSV_COLUMNS`] for a sweep on sleepers, [`BAND_CSV_COLUMNS`] for runs with an acceleration
/// band.
fn csv_columns(
    vehicles: bool,
    sleepers: bool,
    band: bool,
) -> impl Iterator<Item = &'static (&'static str, &'static str, &'static str)> {
    CSV_COLUMNS
        .iter()
        .chain(VEHICLE_CSV_COLUMNS.iter().filter(move |_| vehicles))
        .chain(SLEEPER_CSV_COLUMNS.iter().filter(move |_| sleepers))
        .chain(BAND_CSV_COLUMNS.iter().filter(move |_| band))
}

/// The CSV header line of sweep output (no newline).
pub fn csv_header() -> String {
    CSV_COLUMNS.map(|(name, _, _)| name).join(",")
}

/// Write sweep points as CSV (header + one line per point, full precision), with the vehicles' columns
/// ([`VEHICLE_CSV_COLUMNS`]) and the sleepers' ([`SLEEPER_CSV_COLUMNS`]) when the points have them.
pub fn write_csv(points: &[SweepPoint], out: &mut dyn Write) -> std::io::Result<()> {
    let rows: Vec<SweepRow> = points.iter().cloned().map(Ok).collect();
    write_csv_rows(&rows, out)
}

/// A place or time that may be absent (an extreme that never happened) as a CSV cell: NaN, written as an empty
/// field, not a placeholder 0.
fn missing(value: Option<f64>) -> f64 {
    value.unwrap_or(f64::NAN)
}

/// Write sweep rows as CSV like [`write_csv`]; a failed run's line has its speed and every other field empty (read
/// as missing by CSV readers; why it failed is beside it, in the sweep's JSON).
pub fn write_csv_rows(rows: &[SweepRow], out: &mut dyn Write) -> std::io::Result<()> {
    let vehicles = rows.iter().any(|r| r.as_ref().is_ok_and(|p| p.vehicles.is_some()));
    let sleepers = rows.iter().any(|r| r.as_ref().is_ok_and(|p| p.sleepers.is_some()));
    let band = rows.iter().any(|r| r.as_ref().is_ok_and(|p| p.band_acceleration.is_some()));
    let names: Vec<&str> = csv_columns(vehicles, sleepers, band).map(|(name, _, _)| *name).collect();
    writeln!(out, "{}", names.join(","))?;
    let columns = names.len();
    for line in rows {
        let p = match line {
            Ok(p) => p,
            Err(failed) => {
                writeln!(out, "{}{}", scenario::number::number(failed.speed), ",".repeat(columns - 1))?;
                continue;
            }
        };
        write!(
            out,
            "{}",
            row_with_gaps(&[
                p.speed,
                p.max_downward_deflection.value,
                p.max_upward_deflection.value,
                p.energy.dissipated,
                p.global_norm,
                missing(p.max_downward_deflection.position),
                missing(p.max_downward_deflection.time),
                p.energy.load_work,
                p.energy.residual,
                p.mean_iterations,
                p.window_max_downward_deflection.value,
                missing(p.window_max_downward_deflection.position),
                missing(p.window_max_downward_deflection.time),
                p.window_max_upward_deflection.value,
                missing(p.window_max_upward_deflection.position),
                missing(p.window_max_upward_deflection.time),
                p.max_acceleration.map_or(f64::NAN, |a| a.value),
            ])
        )?;
        if vehicles {
            write!(out, ",{}", row_with_gaps(&p.vehicles.map_or([f64::NAN; 6], |v| v.values())))?;
        }
        if sleepers {
            write!(out, ",{}", row_with_gaps(&p.sleepers.map_or([f64::NAN; 5], |s| s.values())))?;
        }
        if band {
            write!(out, ",{}", row_with_gaps(&[p.band_acceleration.map_or(f64::NAN, |a| a.value)]))?;
        }
        writeln!(out)?;
    }
    Ok(())
}
