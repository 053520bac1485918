//! The run folder (`frictrack run --out DIR`, `frictrack.run(out=DIR)` in Python): summary.json (the run's summary
//! with its files' columns and units, the figures' titles and the scenario), histories.csv, snapshots.csv, with
//! vehicles wheels.csv, and the run's figures as PNG and SVG. Which files, checked before the run and written after
//! it, once for the command line and Python.

use crate::files::{check_output_file, prepare_output_folder, write_atomically};
use crate::run_output::{
    FIGURE_STEMS, HISTORY_COLUMNS, RunCurves, SNAPSHOT_COLUMNS, histories_csv, position_noun, run_plots, snapshots_csv,
};
use crate::run_summary::RunSummary;
use crate::vehicle_output::{WHEEL_COLUMNS, wheel_plot, wheels_csv};
use scenario::error::Result;
use scenario::{Case, Scenario};
use std::path::Path;
use track::{RunResult, Snapshot, SnapshotAt};

/// The files a run of `case` writes into its folder.
pub fn file_names(case: &Case) -> Vec<String> {
    let files = ["summary.json", "histories.csv", "snapshots.csv"].map(String::from).into_iter();
    let figures = FIGURE_STEMS.iter().flat_map(|f| [format!("{f}.png"), format!("{f}.svg")]);
    let wheel_files = ["wheels.csv", "wheel-forces.png", "wheel-forces.svg"].map(String::from).into_iter();
    let wheel_files = wheel_files.filter(|_| case.settings.moving.load.vehicles().is_some());
    files.chain(figures).chain(wheel_files).collect()
}

/// Before the run: `folder` exists (created if missing) and takes every file of [`file_names`] (none is a link, a
/// device or a folder); `option` names where the folder was given in an error.
pub fn check(option: &str, folder: &Path, case: &Case) -> Result<()> {
    prepare_output_folder(option, folder)?;
    file_names(case).iter().try_for_each(|name| check_output_file(option, &folder.join(name)))
}

/// After the run: write the folder's files, each atomically.
pub fn write(
    folder: &Path,
    (scenario, case): (&Scenario, &Case),
    report: &RunSummary,
    result: &RunResult,
    snapshots: &[Snapshot],
) -> Result<()> {
    let load = position_noun(&case.settings.moving.load);
    let columns = |list: &[(&'static str, &'static str)]| crate::columns::json(list.iter().copied());
    let requested: Vec<String> = snapshots
        .iter()
        .map(|s| match s.requested {
            SnapshotAt::Time(t) => format!("time {t} s"),
            SnapshotAt::LoadPosition(x) => format!("{load} at {x} m"),
        })
        .collect();
    let mut files = serde_json::json!({
        "histories.csv": { "columns": columns(&HISTORY_COLUMNS), "sections": scenario.output.sections },
        "snapshots.csv": { "columns": columns(&SNAPSHOT_COLUMNS), "requested": requested },
    });
    if result.vehicles.is_some() {
        files["wheels.csv"] = serde_json::json!({ "columns": columns(&WHEEL_COLUMNS) });
    }
    let title = if scenario.title.is_empty() { format!("v = {} m/s", report.speed) } else { scenario.title.clone() };
    let subtitle = report.figure_subtitle();
    let summary = serde_json::json!({
        "report": report,
        "files": files,
        // What the figures are titled, so that `frictrack plot DIR` draws them again as they were.
        "figures": { "title": title, "subtitle": subtitle, "positions_of": load },
        "conventions": "deflection positive upward; moment sagging-positive; extremes are magnitudes",
        "frictrack_version": env!("CARGO_PKG_VERSION"),
        "scenario": scenario,
    });
    let text = serde_json::to_string_pretty(&summary).map_err(|e| scenario::error::StudyError::Io {
        path: folder.join("summary.json").display().to_string(),
        message: e.to_string(),
    })?;
    write_atomically(&folder.join("summary.json"), text.as_bytes())?;
    write_atomically(&folder.join("histories.csv"), histories_csv(result).as_bytes())?;
    write_atomically(&folder.join("snapshots.csv"), snapshots_csv(snapshots).as_bytes())?;
    for mut spec in run_plots(&RunCurves::of(result, snapshots), &title, load) {
        spec.subtitle.clone_from(&subtitle);
        crate::plot::render(&spec, folder)?;
    }
    if let Some(vehicles) = &result.vehicles {
        write_atomically(&folder.join("wheels.csv"), wheels_csv(vehicles).as_bytes())?;
        let range = report.extremes.extremes_nodes.unwrap_or((0.0, scenario.mesh.length));
        let mut spec = wheel_plot(vehicles, &title, range);
        // The run's line (vehicles, speed, friction) before what the figure says of its wheels.
        spec.subtitle = format!("{subtitle}; {}", spec.subtitle);
        crate::plot::render(&spec, folder)?;
    }
    Ok(())
}
