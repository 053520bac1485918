//! Speed sweeps, the critical speed and the optimal device force (docs/theory.md §7).
//!
//! A sweep runs one simulation per speed, in parallel on the runner's one thread pool; every run is independent and
//! deterministic and the results are returned in speed order, so the output is identical for any thread count.
//! The critical speed is the speed of the largest max downward deflection, refined below the sweep step by a
//! golden-section search on fresh runs inside the bracket around the sweep's maximum. The optimal device force for
//! fixed N and speed minimises the max downward deflection: a log-spaced scan of the bounds, then golden section
//! around the best scanned force; every evaluated force is returned with its value.

mod critical;
mod golden;
pub(crate) use golden::golden_section;
mod optimal_force;
mod peak;

pub use critical::{CriticalSpeed, critical_speed};
pub use optimal_force::{OptimalForce, log_spaced, optimal_device_force, refine_device_force, refine_from_scan};
pub use peak::{Metric, PeakLocation, RefinedPeak, refine_maximum, unrefined};

use crate::error::{Result, StudyError, invalid};
use crate::journal::Journal;
use crate::number::row_with_gaps;
use crate::scenario::Case;
use rayon::prelude::*;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use track::simulation::StepView;
use track::{RunResult, RunSettings, Simulation};

/// What one run of a sweep reports.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct SweepPoint {
    /// Load speed (m/s).
    pub speed: f64,
    /// Max downward deflection over nodes and steps (m, magnitude).
    pub max_downward_deflection: f64,
    /// Max upward deflection (m, magnitude).
    pub max_upward_deflection: f64,
    /// Energy removed by friction and viscous damping (J).
    pub dissipated_energy: f64,
    /// W̄ (m²).
    pub global_norm: f64,
    /// Where the max downward deflection occurred (m).
    pub max_downward_deflection_position: f64,
    /// When (s).
    pub max_downward_deflection_time: f64,
    /// Work of the load (J).
    pub load_work: f64,
    /// Residual of the discrete energy balance (J).
    pub energy_residual: f64,
    /// Mean friction-solver iterations per step.
    pub mean_iterations: f64,
    /// Max downward deflection while the load was inside the extremes window (m, magnitude).
    pub window_max_downward_deflection: f64,
    /// Where (m).
    pub window_max_downward_deflection_position: f64,
    /// When (s).
    pub window_max_downward_deflection_time: f64,
    /// Max upward deflection while the load was inside the extremes window (m, magnitude).
    pub window_max_upward_deflection: f64,
    /// Where (m).
    pub window_max_upward_deflection_position: f64,
    /// When (s).
    pub window_max_upward_deflection_time: f64,
    /// Largest vertical acceleration over nodes and steps (m/s², magnitude): a bridge deck's check value.
    pub max_acceleration: f64,
    /// The vehicles' columns, in a run with vehicles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vehicles: Option<VehicleColumns>,
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
    settings.moving.speed = speed;
    settings.record.sections.clear();
    let r = simulate_until(case, &settings, stop)?;
    let window = r.window.unwrap_or_default();
    Ok(SweepPoint {
        speed,
        max_downward_deflection: r.max_downward.magnitude,
        max_upward_deflection: r.max_upward.magnitude,
        dissipated_energy: r.energy.dissipated(),
        global_norm: r.global_norm,
        max_downward_deflection_position: r.max_downward.position,
        max_downward_deflection_time: r.max_downward.time,
        load_work: r.energy.load_work,
        energy_residual: r.energy.residual(),
        mean_iterations: r.statistics.mean_iterations,
        window_max_downward_deflection: window.max_downward.magnitude,
        window_max_downward_deflection_position: window.max_downward.position,
        window_max_downward_deflection_time: window.max_downward.time,
        window_max_upward_deflection: window.max_upward.magnitude,
        window_max_upward_deflection_position: window.max_upward.position,
        window_max_upward_deflection_time: window.max_upward.time,
        max_acceleration: r.max_acceleration.magnitude,
        vehicles: r.vehicles.as_ref().map(VehicleColumns::of),
    })
}

/// Run `case` under `settings`, abandoned with [`StudyError::Interrupted`] at the first step after `stop` is raised
/// (a load of one atomic flag per step), so that Ctrl-C or SIGTERM ends a long run within a step.
fn simulate_until(case: &Case, settings: &RunSettings, stop: Option<&AtomicBool>) -> Result<RunResult> {
    simulate_observed(case, settings, stop, &mut |_| true)
}

/// The same, with `observer` called after every step (it may stop the run early by returning false).
pub(crate) fn simulate_observed(
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

/// The worker threads a request for `jobs` gets: all cores for 0, and never more than the cores the machine
/// has (`std::thread::available_parallelism`): more threads than cores only add memory and switching.
pub fn worker_threads(jobs: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    if jobs == 0 { cores } else { jobs.min(cores) }
}

/// How the runs of a sweep or study are carried out: on one thread pool built once (see [`worker_threads`]),
/// reporting the number of finished runs to `progress`, keeping every finished run in an optional [`Journal`] (and
/// taking runs already there from it), and stopping once an optional `stop` flag is raised (Ctrl-C, SIGTERM): runs
/// not started fail with [`StudyError::Interrupted`], runs in flight are abandoned at their next step.
#[derive(Clone)]
pub struct Runner<'a> {
    pool: Arc<rayon::ThreadPool>,
    /// Called with the number of finished runs of the current parallel loop after each one.
    pub progress: &'a (dyn Fn(usize) + Sync),
    /// Finished runs, on disk.
    pub journal: Option<&'a Journal>,
    /// Raised to stop: runs not yet started fail with [`StudyError::Interrupted`], runs in flight stop at their next
    /// step.
    pub stop: Option<&'a AtomicBool>,
}

static NO_PROGRESS: fn(usize) = |_| {};

impl Runner<'static> {
    /// A pool of [`worker_threads`]`(jobs)` threads, no progress, no journal, no stop flag.
    pub fn new(jobs: usize) -> Result<Self> {
        let threads = worker_threads(jobs);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| invalid("jobs", jobs, format!("cannot start {threads} worker threads: {e}")))?;
        Ok(Runner { pool: Arc::new(pool), progress: &NO_PROGRESS, journal: None, stop: None })
    }
}

impl<'a> Runner<'a> {
    /// The same with progress reported to `progress`.
    pub fn with_progress<'b>(self, progress: &'b (dyn Fn(usize) + Sync)) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { progress, ..self }
    }

    /// The same keeping finished runs in `journal`.
    pub fn with_journal<'b>(self, journal: Option<&'b Journal>) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { journal, ..self }
    }

    /// The same, stopping once `stop` is raised.
    pub fn with_stop<'b>(self, stop: &'b AtomicBool) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { stop: Some(stop), ..self }
    }

    /// The same without progress reports.
    pub fn silent(&self) -> Self {
        Runner { progress: &NO_PROGRESS, ..self.clone() }
    }

    /// The number of worker threads.
    pub fn threads(&self) -> usize {
        self.pool.current_num_threads()
    }

    /// One run of `case` under `settings` that stops with [`StudyError::Interrupted`] when the stop flag is raised.
    pub fn simulate(&self, case: &Case, settings: &RunSettings) -> Result<RunResult> {
        simulate_until(case, settings, self.stop)
    }

    /// `run` unless the journal already holds the result under `key`; a fresh result is journaled at once.
    pub fn cached<R: Serialize + DeserializeOwned>(&self, key: &str, run: impl FnOnce() -> Result<R>) -> Result<R> {
        if let Some(done) = self.journal.and_then(|j| j.get(key)) {
            return Ok(done);
        }
        if self.stop.is_some_and(|s| s.load(Ordering::Relaxed)) {
            return Err(StudyError::Interrupted);
        }
        let result = run()?;
        if let Some(journal) = self.journal {
            journal.record(key, &result)?;
        }
        Ok(result)
    }

    /// One run of `case` at `speed` (m/s), through the journal.
    pub fn point(&self, case: &Case, speed: f64) -> Result<SweepPoint> {
        self.cached(&format!("{:016x}@{speed}", case.fingerprint), || point_until(case, speed, self.stop))
    }

    /// `f` over `items` on the pool, results in the order of `items` whatever the thread count; the first error
    /// is returned (after the runs in flight end, so that their results reach the journal).
    pub fn map<T: Sync, R: Send>(&self, items: &[T], f: impl Fn(&T) -> Result<R> + Sync) -> Result<Vec<R>> {
        // An interruption is reported only if nothing worse happened.
        let mut interrupted = false;
        let mut out = Vec::with_capacity(items.len());
        for result in self.run_all(items, f) {
            match result {
                Ok(r) => out.push(r),
                Err(StudyError::Interrupted) => interrupted = true,
                Err(e) => return Err(e),
            }
        }
        if interrupted { Err(StudyError::Interrupted) } else { Ok(out) }
    }

    /// `f` over `items` on the pool like [`Runner::map`], but a failed item does not end the loop: every item's
    /// result, in the order of `items`. Only an interruption is an error (the finished runs are in the journal).
    pub fn map_each<T: Sync, R: Send>(
        &self,
        items: &[T],
        f: impl Fn(&T) -> Result<R> + Sync,
    ) -> Result<Vec<Result<R>>> {
        let results = self.run_all(items, f);
        if results.iter().any(|r| matches!(r, Err(StudyError::Interrupted))) {
            return Err(StudyError::Interrupted);
        }
        Ok(results)
    }

    /// Every item's result of `f` on the pool, in the order of `items`, progress reported after each.
    fn run_all<T: Sync, R: Send>(&self, items: &[T], f: impl Fn(&T) -> Result<R> + Sync) -> Vec<Result<R>> {
        let done = AtomicUsize::new(0);
        self.pool.install(|| {
            items
                .par_iter()
                .map(|item| {
                    let result = f(item);
                    (self.progress)(done.fetch_add(1, Ordering::Relaxed) + 1);
                    result
                })
                .collect()
        })
    }

    /// Run `case` at every speed, keeping going past a failed run: one row per speed, in the order of `speeds`
    /// (an interruption is still an error).
    pub fn speed_sweep_keeping(&self, case: &Case, speeds: &[f64]) -> Result<Vec<SweepRow>> {
        Ok(self.sweep_many_keeping(std::slice::from_ref(case), speeds)?.pop().expect("one case"))
    }

    /// Run every case at every speed like [`Runner::sweep_many`], keeping going past a failed run: per case, one
    /// row per speed in the order of `speeds` (an interruption is still an error).
    pub fn sweep_many_keeping(&self, cases: &[Case], speeds: &[f64]) -> Result<Vec<Vec<SweepRow>>> {
        self.sweep_grids_keeping(cases, &vec![speeds.to_vec(); cases.len()])
    }

    /// Run each case over its own grid of speeds (`grids[c]` for `cases[c]`), all on one pool, keeping going past
    /// a failed run: per case, one row per speed of its grid, in its order (an interruption is still an error).
    pub fn sweep_grids_keeping(&self, cases: &[Case], grids: &[Vec<f64>]) -> Result<Vec<Vec<SweepRow>>> {
        grids.iter().try_for_each(|g| check_speeds(g))?;
        let pairs: Vec<(usize, f64)> =
            grids.iter().enumerate().flat_map(|(c, g)| g.iter().map(move |&v| (c, v))).collect();
        let rows = self.map_each(&pairs, |&(c, speed)| self.point(&cases[c], speed))?;
        let mut rows = rows
            .into_iter()
            .zip(&pairs)
            .map(|(row, &(_, speed))| row.map_err(|e| FailedRun { speed, error: e.to_string() }));
        Ok(grids.iter().map(|g| rows.by_ref().take(g.len()).collect()).collect())
    }

    /// Run `case` at every speed; results in the order of `speeds`.
    pub fn speed_sweep(&self, case: &Case, speeds: &[f64]) -> Result<Vec<SweepPoint>> {
        Ok(self.sweep_many(std::slice::from_ref(case), speeds)?.pop().expect("one case"))
    }

    /// Run every case at every speed, all (case, speed) pairs on one pool; results per case in the order of
    /// `speeds`, identical for any thread count.
    pub fn sweep_many(&self, cases: &[Case], speeds: &[f64]) -> Result<Vec<Vec<SweepPoint>>> {
        check_speeds(speeds)?;
        let pairs = case_speed_pairs(cases.len(), speeds);
        let mut points = self.map(&pairs, |&(c, speed)| self.point(&cases[c], speed))?.into_iter();
        Ok((0..cases.len()).map(|_| points.by_ref().take(speeds.len()).collect()).collect())
    }
}

/// Every (case index, speed) of `cases` cases swept over `speeds`, case by case: one pool runs them all.
fn case_speed_pairs(cases: usize, speeds: &[f64]) -> Vec<(usize, f64)> {
    (0..cases).flat_map(|c| speeds.iter().map(move |&v| (c, v))).collect()
}

/// Every speed of a sweep must be finite and positive.
fn check_speeds(speeds: &[f64]) -> Result<()> {
    match speeds.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        Some(&v) => Err(invalid("speeds", v, "every speed must be finite and > 0 (m/s)")),
        None => Ok(()),
    }
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

/// The CSV header line of sweep output (no newline).
pub fn csv_header() -> String {
    CSV_COLUMNS.map(|(name, _, _)| name).join(",")
}

/// Write sweep points as CSV (header + one line per point, full precision), with the vehicles' columns
/// ([`VEHICLE_CSV_COLUMNS`]) when the points have them.
pub fn write_csv(points: &[SweepPoint], out: &mut dyn Write) -> std::io::Result<()> {
    let rows: Vec<SweepRow> = points.iter().cloned().map(Ok).collect();
    write_csv_rows(&rows, out)
}

/// Where and when an extreme of `magnitude` happened: `value`, or missing (NaN, an empty field) when it never
/// happened (magnitude 0: no step deflected that way while the load was in the window), not a placeholder 0 — the
/// rule of [`track::simulation::Extreme::happened`] on the point's flattened fields.
fn where_if(magnitude: f64, value: f64) -> f64 {
    if magnitude > 0.0 { value } else { f64::NAN }
}

/// Write sweep rows as CSV like [`write_csv`]; a failed run's line has its speed and every other field empty (read
/// as missing by CSV readers; why it failed is beside it, in the sweep's JSON).
pub fn write_csv_rows(rows: &[SweepRow], out: &mut dyn Write) -> std::io::Result<()> {
    let vehicles = rows.iter().any(|r| r.as_ref().is_ok_and(|p| p.vehicles.is_some()));
    let columns = CSV_COLUMNS.len() + if vehicles { VEHICLE_CSV_COLUMNS.len() } else { 0 };
    if vehicles {
        writeln!(out, "{},{}", csv_header(), VEHICLE_CSV_COLUMNS.map(|(name, _, _)| name).join(","))?;
    } else {
        writeln!(out, "{}", csv_header())?;
    }
    for line in rows {
        let p = match line {
            Ok(p) => p,
            Err(failed) => {
                writeln!(out, "{}{}", crate::number::number(failed.speed), ",".repeat(columns - 1))?;
                continue;
            }
        };
        write!(
            out,
            "{}",
            row_with_gaps(&[
                p.speed,
                p.max_downward_deflection,
                p.max_upward_deflection,
                p.dissipated_energy,
                p.global_norm,
                p.max_downward_deflection_position,
                p.max_downward_deflection_time,
                p.load_work,
                p.energy_residual,
                p.mean_iterations,
                p.window_max_downward_deflection,
                where_if(p.window_max_downward_deflection, p.window_max_downward_deflection_position),
                where_if(p.window_max_downward_deflection, p.window_max_downward_deflection_time),
                p.window_max_upward_deflection,
                where_if(p.window_max_upward_deflection, p.window_max_upward_deflection_position),
                where_if(p.window_max_upward_deflection, p.window_max_upward_deflection_time),
                p.max_acceleration,
            ])
        )?;
        match (vehicles, p.vehicles) {
            (true, Some(v)) => writeln!(out, ",{}", row_with_gaps(&v.values()))?,
            (true, None) => writeln!(out, ",{}", row_with_gaps(&[f64::NAN; 6]))?,
            (false, _) => writeln!(out)?,
        }
    }
    Ok(())
}
