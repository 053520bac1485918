//! The device force that minimises the max downward deflection at a fixed speed: a log-spaced scan, then golden
//! section in log F_u around the best scanned force (docs/theory.md §7).

use super::Runner;
use analytic::golden::golden_section;
use scenario::Scenario;
use scenario::error::{Result, invalid};
use serde::Serialize;

/// The device force minimising the max downward deflection.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OptimalForce {
    /// F_u (N).
    pub force: f64,
    /// Max downward deflection there (m).
    pub max_downward_deflection: f64,
    /// Every evaluated (F_u, max downward deflection), in evaluation order.
    pub explored: Vec<(f64, f64)>,
}

/// Minimise the max downward deflection of `scenario` (which must have `[friction.devices]`) over the device force
/// in [lower, upper] (N) at `speed` (m/s): `scan` log-spaced forces, then golden section to a relative `tolerance`.
pub fn optimal_device_force(
    scenario: &Scenario,
    speed: f64,
    (lower, upper): (f64, f64),
    scan: usize,
    tolerance: f64,
    runner: &Runner,
) -> Result<OptimalForce> {
    if scenario.friction.devices.is_none() {
        return Err(invalid("friction.devices", "absent", "the optimal force needs [friction.devices]"));
    }
    if !(lower.is_finite() && lower > 0.0 && upper.is_finite() && upper > lower) {
        return Err(invalid("force bounds", format!("{lower}:{upper}"), "need 0 < lower < upper (N)"));
    }
    if scan < 3 {
        return Err(invalid("scan", scan, "needs at least 3 forces"));
    }
    let forces = log_spaced(lower, upper, scan);
    let values = runner.map(&forces, |&force| {
        Ok(runner.point(&with_device_force(scenario, force).build()?, speed)?.deflection.max_downward.value)
    })?;
    let mut explored: Vec<(f64, f64)> = forces.iter().copied().zip(values.iter().copied()).collect();
    let mut refined = refine_from_scan(scenario, speed, &forces, &values, tolerance, runner)?;
    explored.append(&mut refined.explored);
    Ok(OptimalForce { explored, ..refined })
}

/// From a scan of device forces (ascending) and their max downward deflections: golden section in the bracket
/// around the best scanned force, keeping the scanned point if the refinement finds nothing lower. `explored`
/// holds the refinement's runs only.
pub fn refine_from_scan(
    scenario: &Scenario,
    speed: f64,
    forces: &[f64],
    values: &[f64],
    tolerance: f64,
    runner: &Runner,
) -> Result<OptimalForce> {
    let best = (0..forces.len()).min_by(|&a, &b| values[a].total_cmp(&values[b])).expect("a non-empty scan");
    let bracket = (forces[best.saturating_sub(1)], forces[(best + 1).min(forces.len() - 1)]);
    let mut refined = refine_device_force(scenario, speed, bracket, tolerance, runner)?;
    if values[best] < refined.max_downward_deflection {
        (refined.force, refined.max_downward_deflection) = (forces[best], values[best]);
    }
    Ok(refined)
}

/// `scenario` with device force `force` (N).
fn with_device_force(scenario: &Scenario, force: f64) -> Scenario {
    let mut s = scenario.clone();
    if let Some(d) = s.friction.devices.as_mut() {
        d.force = Some(force);
    }
    s
}

/// `count` log-spaced values from `lower` to `upper` (both included).
pub fn log_spaced(lower: f64, upper: f64, count: usize) -> Vec<f64> {
    let ratio = (upper / lower).powf(1.0 / (count.max(2) - 1) as f64);
    (0..count).map(|i| lower * ratio.powi(i as i32)).collect()
}

/// Golden section in log F_u on `bracket` (N) for the device force minimising the max downward deflection of
/// `scenario` at `speed`, to a relative `tolerance` in F_u.
pub fn refine_device_force(
    scenario: &Scenario,
    speed: f64,
    (lo, hi): (f64, f64),
    tolerance: f64,
    runner: &Runner,
) -> Result<OptimalForce> {
    let mut explored = Vec::new();
    let mut f = |log_force: f64| -> Result<f64> {
        let force = log_force.exp();
        let w = runner.point(&with_device_force(scenario, force).build()?, speed)?.deflection.max_downward.value;
        explored.push((force, w));
        Ok(-w)
    };
    let (log_force, value) = golden_section(&mut f, lo.ln(), hi.ln(), tolerance, true)?;
    Ok(OptimalForce { force: log_force.exp(), max_downward_deflection: -value, explored })
}
