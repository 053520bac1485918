//! The outcomes of a run that a resolution check estimates: every extreme it reports (whole run and window, the
//! accelerations where they are defined), the sleepers' largest forces and accelerations, the wheels' extreme forces,
//! the friction's dissipation and the total dissipated energy — by their JSON names.

use crate::run_summary::RunSummary;
use fem_beam::Extreme;

/// (name, SI unit, value) of one outcome.
pub type Outcome = (String, &'static str, f64);

/// The outcomes `summary` reports, in the report's order.
pub fn outcomes(summary: &RunSummary) -> Vec<Outcome> {
    let mut list: Vec<Outcome> = Vec::new();
    let mut extreme = |name: &str, unit: &'static str, e: Option<&Extreme>| {
        if let Some(e) = e.filter(|e| e.place().is_some()) {
            list.push((name.to_string(), unit, e.value));
        }
    };
    let x = &summary.extremes;
    extreme("max_downward_deflection", "m", Some(&x.deflection.max_downward));
    extreme("max_upward_deflection", "m", Some(&x.deflection.max_upward));
    extreme("window_max_downward_deflection", "m", Some(&x.window_deflection.max_downward.extreme));
    extreme("window_max_upward_deflection", "m", Some(&x.window_deflection.max_upward.extreme));
    extreme("max_acceleration", "m/s²", x.max_acceleration.as_ref());
    extreme("band_acceleration", "m/s²", x.band_acceleration.as_ref().map(|b| &b.extreme));
    extreme("filtered_acceleration", "m/s²", x.filtered_acceleration.as_ref().map(|f| &f.extreme));
    if let Some(sleepers) = &summary.sleepers {
        extreme("max_pad_force", "N", Some(&sleepers.max_pad_force));
        extreme("max_ballast_force", "N", Some(&sleepers.max_ballast_force));
        extreme("max_subgrade_force", "N", sleepers.max_subgrade_force.as_ref());
        extreme("max_sleeper_acceleration", "m/s²", Some(&sleepers.max_sleeper_acceleration));
        extreme("max_ballast_acceleration", "m/s²", sleepers.max_ballast_acceleration.as_ref());
    }
    if let Some(v) = &summary.vehicles {
        list.push(("min_wheel_force".into(), "N", v.min_wheel_force));
        list.push(("max_wheel_force".into(), "N", v.max_wheel_force));
    }
    let energy = &summary.energy;
    if energy.friction_dissipation != 0.0 {
        list.push(("friction_dissipation".into(), "J", energy.friction_dissipation));
    }
    list.push(("dissipated".into(), "J", energy.dissipated));
    list
}
