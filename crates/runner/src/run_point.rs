//! One run of a case at one speed, as a sweep point: the simulation with an optional stop flag and observer.

use crate::sleeper_columns::SleeperColumns;
use crate::sweep_point::{SweepPoint, VehicleColumns};
use scenario::Case;
use scenario::error::{Result, StudyError};
use std::sync::atomic::{AtomicBool, Ordering};
use track::simulation::StepView;
use track::{RunResult, RunSettings, Simulation};

/// One run of `case` at `speed` (m/s), without journal (see [`crate::Runner::point`]).
pub fn run_point(case: &Case, speed: f64) -> Result<SweepPoint> {
    point_until(case, speed, None)
}

/// One run of `case` at `speed`, abandoned at the first step after `stop` is raised.
pub(crate) fn point_until(case: &Case, speed: f64, stop: Option<&AtomicBool>) -> Result<SweepPoint> {
    let mut settings = case.settings.clone();
    settings.moving = settings.moving.at_speed(speed)?;
    settings.record.sections.clear();
    let r = simulate_until(case, &settings, stop)?;
    let window = r.window.unwrap_or_default();
    Ok(SweepPoint {
        speed,
        deflection: r.deflection,
        window_deflection: window.deflection,
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
pub(crate) fn simulate_until(case: &Case, settings: &RunSettings, stop: Option<&AtomicBool>) -> Result<RunResult> {
    simulate_observed(case, settings, stop, &mut |_| true)
}

/// The same, with `observer` called after every step (it may stop the run early by returning false). A case on a
/// foundation fitted to the ground runs at the speed it was fitted at only.
pub fn simulate_observed(
    case: &Case,
    settings: &RunSettings,
    stop: Option<&AtomicBool>,
    observer: &mut dyn FnMut(&StepView<'_>) -> bool,
) -> Result<RunResult> {
    if let Some(fit) = &case.ground_fit {
        let speed = settings.moving.speed;
        if (speed - fit.speed).abs() > 1e-9 * fit.speed.max(1.0) || !settings.moving.profile.is_empty() {
            return Err(scenario::error::invalid(
                "ground",
                format!("fitted at {} m/s", fit.speed),
                format!(
                    "a run at {speed} m/s needs the foundation fitted at its own speed: set load.speed (or --speed) \
                     and run each speed alone; `frictrack stationary --speeds` gives the exact linear wave over speeds"
                ),
            ));
        }
    }
    let simulation = Simulation::new(&case.model, &case.interactions, settings)?;
    let stopped = || stop.is_some_and(|s| s.load(Ordering::Relaxed));
    let result = simulation.run_observed(&mut |view| observer(view) && !stopped())?;
    if stopped() { Err(StudyError::Interrupted) } else { Ok(result) }
}
