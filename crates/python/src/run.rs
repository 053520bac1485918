//! `frictrack.run`: one recorded run, as `frictrack run SCENARIO --format json --out DIR` makes it — the scenario
//! with its overrides, mid-span recorded when it names no section, the snapshots it asks for — returning the
//! summary's JSON, its text report and the CSV text of its tables.

use crate::errors::to_python;
use crate::interruptible;
use crate::scenario_input::{Source, overrides};
use pyo3::prelude::*;
use report::output::Output;
use report::resolution_check::accuracy::{LEVEL_SECONDS, Target, refine};
use report::resolution_check::twins::{Twin, Twins};
use report::run_output::{histories_csv, recording, run_with_snapshots, snapshot_requests, snapshots_csv};
use report::run_summary::RunSummary;
use scenario::overrides::{OVERRIDES, OverrideKind};

/// What a run returns to Python: the summary (JSON text, as `frictrack run --format json`), its text report (as
/// `frictrack run` prints it), `histories.csv`, `snapshots.csv`, `wheels.csv` (None without vehicles),
/// `sleepers.csv` (None where no recorded section is over a sleeper) and the warnings the command line prints.
type RunTexts = (String, String, String, String, Option<String>, Option<String>, Vec<String>);

/// Run the scenario (`kind` "reference", "path", "toml" or "json" with its `text`) with the keyword `overrides`,
/// telling `progress` (a callable of the fraction done), if given; with `out`, the run folder is written there as
/// `frictrack run --out` writes it (its files checked before the run starts), its `command` (the Python call, in
/// words) recorded beside the build's commit and the date.
#[pyfunction]
#[pyo3(signature = (kind, text, keywords, progress=None, out=None, command=String::new(), check_resolution=false, accuracy=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn run(
    py: Python<'_>,
    kind: &str,
    text: Option<String>,
    keywords: Vec<(String, Bound<'_, PyAny>)>,
    progress: Option<Bound<'_, PyAny>>,
    out: Option<std::path::PathBuf>,
    command: String,
    check_resolution: bool,
    accuracy: Option<f64>,
) -> PyResult<RunTexts> {
    let started = std::time::Instant::now();
    let scenario = Source::of(kind, text)?.read()?;
    let overrides = overrides(&keywords)?;
    let mut scenario = recording(overrides.apply(scenario).map_err(to_python)?);
    // accuracy=, else the scenario's integration.accuracy (taken out: the refinement builds it at each resolution).
    let check = check_resolution.then_some("check_resolution=True");
    let accuracy = scenario.take_run_tolerance(accuracy.map(|t| (t, "accuracy")), check).map_err(to_python)?;
    let case = scenario.build().map_err(to_python)?;
    // The twins of check_resolution are built (their sizes checked) before any work.
    let twins = check_resolution.then(|| Twins::of(&scenario)).transpose().map_err(to_python)?;
    if let Some(folder) = &out {
        report::run_folder::check("out", folder, &case).map_err(to_python)?;
    }
    let mut warnings: Vec<String> =
        scenario::diagnostics::warnings(&scenario, &case).iter().map(ToString::to_string).collect();
    let before = warnings.clone();
    let provenance = report::provenance::Provenance::now(command, frictrack_cli::COMMIT);
    let outcome = interruptible::run_reporting(py, progress, move |stop, told| {
        // Each twin or resolution announced as it starts, when it is long.
        let mut announce = |twin: &Twin| {
            told.announce(&twin.label(), &runner::cost::Estimate::run(runner::cost::RunCost::of(&twin.case)));
        };
        let (scenario, case, result, snapshots, summary) = match accuracy {
            Some(tolerance) => {
                let target = Target { tolerance, level_seconds: LEVEL_SECONDS };
                let refined =
                    refine(&scenario, target, &snapshot_requests, Some(stop), &mut announce, &|f| told.set(f))?;
                if refined.summary.accuracy.as_ref().is_some_and(|a| a.status.interrupted()) {
                    return Err(scenario::error::StudyError::Interrupted);
                }
                (refined.scenario, refined.case, refined.result, refined.snapshots, refined.summary)
            }
            None => {
                told.announce("frictrack.run", &runner::cost::Estimate::run(runner::cost::RunCost::of(&case)));
                let requests = snapshot_requests(&scenario, &case);
                let (result, snapshots) = run_with_snapshots(&case, &requests, Some(stop), &|f| told.set(f))?;
                let mut summary = RunSummary::of(&scenario, &case, &result, started)?;
                if let Some(twins) = &twins {
                    let check = twins.check(&scenario, &summary, Some(stop), &mut announce, &|f| told.set(f))?;
                    summary.resolution_check = Some(check);
                }
                (scenario, case, result, snapshots, summary)
            }
        };
        let mut after: Vec<String> =
            report::result_warnings::result_warnings(&case, &summary).iter().map(ToString::to_string).collect();
        after.extend(summary.fallback_warning());
        let json = summary
            .json()
            .map_err(|e| scenario::error::StudyError::Io { path: "summary".into(), message: e.to_string() })?;
        let text = summary.text();
        if let Some(folder) = &out {
            let every: Vec<String> = before.iter().chain(&after).cloned().collect();
            let record = report::run_folder::RunRecord { provenance: &provenance, warnings: &every };
            report::run_folder::write(folder, (&scenario, &case), (&summary, record), &result, &snapshots)?;
        }
        let wheels = result.vehicles.as_ref().map(report::vehicle_output::wheels_csv);
        let sleepers = report::sleeper_output::sleepers_csv(result.sleepers.as_ref());
        let tables = (histories_csv(&result), snapshots_csv(&snapshots), wheels, sleepers);
        Ok::<_, scenario::error::StudyError>((json, text, tables, after))
    })?;
    let (json, text, (histories, snapshots, wheels, sleepers), after) = outcome.map_err(to_python)?;
    warnings.extend(after);
    Ok((json, text, histories, snapshots, wheels, sleepers, warnings))
}

/// The names `run` takes as keyword overrides (the command line's flags, with underscores).
#[pyfunction]
pub(crate) fn override_names() -> Vec<&'static str> {
    OVERRIDES.iter().map(|o| o.name).collect()
}

/// The table of overrides as Python sees it: (keyword, type in the stubs, unit or "", what it sets) per override,
/// in the table's order — what the package's docs and type stubs are held against.
#[pyfunction]
pub(crate) fn override_table() -> Vec<(&'static str, &'static str, &'static str, &'static str)> {
    OVERRIDES
        .iter()
        .map(|o| {
            let (python_type, unit) = match o.kind {
                OverrideKind::Speed => ("Union[float, str]", "m/s"),
                OverrideKind::Number { unit } => ("float", unit),
                OverrideKind::Count => ("int", ""),
                OverrideKind::Text | OverrideKind::Solver => ("str", ""),
                OverrideKind::Pair { unit } => ("Sequence[float]", unit),
            };
            (o.name, python_type, unit, o.help)
        })
        .collect()
}

/// The train catalogue's names (`frictrack trains`).
#[pyfunction]
pub(crate) fn trains() -> Vec<String> {
    fem_beam::Train::catalogue()
}

/// The columns of the tables with their units, as the library writes them: a run's "histories", "snapshots",
/// "wheels" and "sleepers", a stationary wave's "stationary_wave" (on a ground "ground_wave"), a receptance's "receptance" and the ground's "dispersion",
/// "ground_speeds" and "equivalent_stiffness" (name, unit) lists.
#[pyfunction]
pub(crate) fn columns() -> Vec<(&'static str, Vec<(&'static str, &'static str)>)> {
    vec![
        ("histories", report::run_output::HISTORY_COLUMNS.to_vec()),
        ("snapshots", report::run_output::SNAPSHOT_COLUMNS.to_vec()),
        ("wheels", report::vehicle_output::WHEEL_COLUMNS.to_vec()),
        ("sleepers", report::sleeper_output::SLEEPER_COLUMNS.to_vec()),
        ("stationary_wave", study::stationary::output::WAVE_COLUMNS.to_vec()),
        ("ground_wave", study::ground::wave_text::LIFT_OFF_WAVE_COLUMNS.to_vec()),
        ("receptance", study::receptance::text::RECEPTANCE_COLUMNS.to_vec()),
        ("dispersion", study::ground::text::DISPERSION_COLUMNS.to_vec()),
        ("ground_speeds", study::ground::text::SPEED_COLUMNS.to_vec()),
        ("equivalent_stiffness", study::ground::text::STIFFNESS_COLUMNS.to_vec()),
    ]
}
