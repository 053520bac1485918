//! A sweep as CSV: every column with its unit and meaning, the header, the rows (a failed run's row empty but for
//! its speed).

use crate::sleeper_columns::SLEEPER_CSV_COLUMNS;
use crate::sweep_point::{SweepPoint, SweepRow, VEHICLE_CSV_COLUMNS};
use scenario::Scenario;
use scenario::number::row_with_gaps;
use scenario::quantities::unit;
use std::io::Write;

/// The columns of sweep output: name, unit, meaning (in this order; the user guide and the JSON beside a sweep's CSV
/// list them).
pub const CSV_COLUMNS: [(&str, &str, &str); 17] = [
    ("speed", unit("speed"), "load speed"),
    (
        "max_downward_deflection",
        unit("max_downward_deflection"),
        "largest downward deflection over all nodes and steps (magnitude)",
    ),
    (
        "max_upward_deflection",
        unit("max_upward_deflection"),
        "largest upward deflection over all nodes and steps (magnitude)",
    ),
    ("dissipated_energy", unit("dissipated_energy"), "energy removed by friction and viscous damping"),
    ("global_norm", unit("global_norm"), "W̄ = (1/t_on)∫∫|w| dx dt over the crossing"),
    (
        "max_downward_deflection_position",
        unit("max_downward_deflection_position"),
        "node of the largest downward deflection",
    ),
    ("max_downward_deflection_time", unit("max_downward_deflection_time"), "time of the largest downward deflection"),
    ("load_work", unit("load_work"), "work of the moving load"),
    ("energy_residual", unit("energy_residual"), "residual of the discrete energy balance"),
    ("mean_iterations", unit("mean_iterations"), "mean friction-solver iterations per step"),
    (
        "window_max_downward_deflection",
        unit("window_max_downward_deflection"),
        "largest downward deflection while the load is in the extremes window",
    ),
    ("window_max_downward_deflection_position", unit("window_max_downward_deflection_position"), "its node"),
    ("window_max_downward_deflection_time", unit("window_max_downward_deflection_time"), "its time"),
    (
        "window_max_upward_deflection",
        unit("window_max_upward_deflection"),
        "largest upward deflection while the load is in the extremes window",
    ),
    ("window_max_upward_deflection_position", unit("window_max_upward_deflection_position"), "its node"),
    ("window_max_upward_deflection_time", unit("window_max_upward_deflection_time"), "its time"),
    (
        "max_acceleration",
        unit("max_acceleration"),
        "largest vertical acceleration over all nodes and steps (magnitude; bridge decks)",
    ),
];

/// The band-limited acceleration's column of sweep output, last, when the sweep's runs compute one.
pub const BAND_CSV_COLUMNS: [(&str, &str, &str); 1] = [(
    "band_acceleration",
    unit("band_acceleration"),
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
                p.deflection.max_downward.value,
                p.deflection.max_upward.value,
                p.energy.dissipated,
                p.global_norm,
                missing(p.deflection.max_downward.position),
                missing(p.deflection.max_downward.time),
                p.energy.load_work,
                p.energy.residual,
                p.mean_iterations,
                p.window_deflection.max_downward.value,
                missing(p.window_deflection.max_downward.position),
                missing(p.window_deflection.max_downward.time),
                p.window_deflection.max_upward.value,
                missing(p.window_deflection.max_upward.position),
                missing(p.window_deflection.max_upward.time),
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
