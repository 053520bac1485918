//! The run folder (`frictrack run --out DIR`, `frictrack.run(out=DIR)` in Python): summary.json (the run's summary
//! with its files' columns and units, the figures' titles and the scenario), histories.csv, snapshots.csv, with
//! vehicles wheels.csv, and the run's figures as PNG and SVG (on sleepers also `bay`, the deflection under the load
//! over a bay). Which files, checked before the run and written after
//! it, once for the command line and Python.

use crate::columns::ColumnMeta;
use crate::files::{check_output_file, prepare_output_folder, write_atomically};
use crate::provenance::Provenance;
use crate::run_output::{
    FIGURE_STEMS, HISTORY_COLUMNS, RunCurves, SNAPSHOT_COLUMNS, histories_csv, position_noun, run_plots, snapshots_csv,
};
use crate::run_summary::RunSummary;
use crate::vehicle_output::{WHEEL_COLUMNS, wheel_plot, wheels_csv};
use scenario::error::Result;
use scenario::{Case, Scenario};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;
use track::{RunResult, Snapshot, SnapshotAt};

/// How a run folder's numbers are signed.
pub const CONVENTIONS: &str = "deflection positive upward; moment sagging-positive; extremes are magnitudes";

/// A run folder's `summary.json`: the run's summary and its text report, its files' columns, the figures' titles, the
/// scenario, every warning the run gave, and where it came from.
#[derive(Debug, Clone, Serialize)]
pub struct FolderSummary<'a> {
    /// [`CONVENTIONS`].
    pub conventions: &'static str,
    /// What the figures are titled, so that `frictrack plot DIR` draws them again as they were.
    pub figures: FigureTitles,
    /// Each CSV's columns and what it holds.
    pub files: BTreeMap<&'static str, FileMeta>,
    /// The command, version, commit and date (flattened: `command`, `frictrack_version`, `git_revision`, `date`).
    #[serde(flatten)]
    pub provenance: &'a Provenance,
    /// The run's summary.
    pub report: &'a RunSummary,
    /// The scenario that ran (without the `[foundation]` a `[ground]` replaces).
    pub scenario: scenario::AsRan<'a>,
    /// The run's text report, as `frictrack run` prints it.
    pub text: String,
    /// Every warning the run gave (the scenario's, then the result's), as the command line prints them.
    pub warnings: &'a [String],
}

/// Where a run came from and what it warned of, kept in its folder.
#[derive(Debug, Clone, Copy)]
pub struct RunRecord<'a> {
    /// The command, version, commit and date.
    pub provenance: &'a Provenance,
    /// Every warning the run gave.
    pub warnings: &'a [String],
}

/// The titles of a run folder's figures.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct FigureTitles {
    /// What positions are of: "load", "first axle", "first wheel".
    pub positions_of: String,
    /// The line under each title.
    pub subtitle: String,
    /// The title.
    pub title: String,
}

impl FigureTitles {
    /// The titles a run folder's `summary.json` holds; None for a folder written before they were kept.
    pub fn of(summary: &serde_json::Value) -> Option<Self> {
        serde_json::from_value(summary.get("figures")?.clone()).ok()
    }
}

/// One CSV of a run folder: its columns, and the sections or snapshots it was asked for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FileMeta {
    /// Name and unit of each column.
    pub columns: Vec<ColumnMeta>,
    /// The snapshots asked for, in words (snapshots.csv).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub requested: Option<Vec<String>>,
    /// The sections asked for (m; histories.csv).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sections: Option<Vec<f64>>,
}

impl FileMeta {
    fn of(columns: Vec<ColumnMeta>) -> Self {
        Self { columns, requested: None, sections: None }
    }
}

/// The files a run of `case` may write into its folder (on sleepers `sleepers.csv` and the bay's figure are written
/// only where there is something to put in them).
pub fn file_names(case: &Case) -> Vec<String> {
    let files = ["summary.json", "histories.csv", "snapshots.csv"].map(String::from).into_iter();
    let figures = FIGURE_STEMS.iter().flat_map(|f| [format!("{f}.png"), format!("{f}.svg")]);
    let wheel_files = ["wheels.csv", "wheel-forces.png", "wheel-forces.svg"].map(String::from).into_iter();
    let wheel_files = wheel_files.filter(|_| case.settings.moving.load.vehicles().is_some());
    let bay_files = ["bay.png", "bay.svg", "sleepers.csv"].map(String::from);
    let bay_files = bay_files.into_iter().filter(|_| case.model.sleepers().is_some());
    files.chain(figures).chain(wheel_files).chain(bay_files).collect()
}

/// Before the run: `folder` exists (created if missing) and takes every file of [`file_names`] (none is a link, a
/// device or a folder); `option` names where the folder was given in an error. Whether the folder was created here.
pub fn check(option: &str, folder: &Path, case: &Case) -> Result<bool> {
    let created = prepare_output_folder(option, folder)?;
    file_names(case).iter().try_for_each(|name| check_output_file(option, &folder.join(name)))?;
    Ok(created)
}

/// After the run: write the folder's files, each atomically; `record` says where the run came from and what it warned
/// of.
pub fn write(
    folder: &Path,
    (scenario, case): (&Scenario, &Case),
    (report, record): (&RunSummary, RunRecord<'_>),
    result: &RunResult,
    snapshots: &[Snapshot],
) -> Result<()> {
    let load = position_noun(&case.settings.moving.load);
    let sleepers = crate::sleeper_output::sleepers_csv(result.sleepers.as_ref());
    let files = files_written(scenario, (result, snapshots), load, sleepers.is_some());
    // An untitled run is titled by its speed: the one it ran at, or the two it changed between.
    let title = match (&scenario.title, &report.speed_change) {
        (t, _) if !t.is_empty() => t.clone(),
        (_, None) => format!("v = {} m/s", report.speed),
        (_, Some(c)) => format!("v = {:.2} → {:.2} m/s", c.start_speed, c.end_speed),
    };
    let subtitle = report.figure_subtitle();
    let summary = FolderSummary {
        conventions: CONVENTIONS,
        figures: FigureTitles { positions_of: load.to_string(), subtitle: subtitle.clone(), title: title.clone() },
        files,
        provenance: record.provenance,
        report,
        scenario: scenario::AsRan(scenario),
        text: crate::output::Output::text(report),
        warnings: record.warnings,
    };
    let text = serde_json::to_string_pretty(&summary).map_err(|e| scenario::error::StudyError::Io {
        path: folder.join("summary.json").display().to_string(),
        message: e.to_string(),
    })?;
    write_atomically(&folder.join("summary.json"), text.as_bytes())?;
    write_atomically(&folder.join("histories.csv"), histories_csv(result).as_bytes())?;
    write_atomically(&folder.join("snapshots.csv"), snapshots_csv(snapshots).as_bytes())?;
    match sleepers {
        Some(table) => write_atomically(&folder.join("sleepers.csv"), table.as_bytes())?,
        None => remove_stale(folder, &["sleepers.csv"])?,
    }
    let exceptions: Vec<(f64, String)> =
        report.sleepers.iter().flat_map(|s| &s.exceptions).map(|e| (e.x, e.what.clone())).collect();
    for mut spec in run_plots(&RunCurves::of(result, snapshots), &title, load, &exceptions) {
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
    let bay = report.sleepers.as_ref().and_then(|s| Some((s, crate::sleeper_output::bay_plot(s, &title)?)));
    match bay {
        Some((sleepers, mut spec)) => {
            spec.subtitle = format!("{subtitle}; {}; {}", sleepers.track, spec.subtitle);
            crate::plot::render(&spec, folder)?;
        }
        None => remove_stale(folder, &["bay.png", "bay.svg"])?,
    }
    Ok(())
}

/// The CSV files a run writes with their columns (and the recorded sections, the snapshots asked for), as
/// summary.json lists them; `load` names what moves ("load", "first axle"); `sleepers` whether `sleepers.csv` is
/// written.
fn files_written(
    scenario: &Scenario,
    (result, snapshots): (&RunResult, &[Snapshot]),
    load: &str,
    sleepers: bool,
) -> BTreeMap<&'static str, FileMeta> {
    let columns = |list: &[(&'static str, &'static str)]| crate::columns::listed(list.iter().copied());
    let requested: Vec<String> = snapshots
        .iter()
        .map(|s| match s.requested {
            SnapshotAt::Time(t) => format!("time {t} s"),
            SnapshotAt::LoadPosition(x) => format!("{load} at {x} m"),
        })
        .collect();
    let mut files = BTreeMap::from([
        (
            "histories.csv",
            FileMeta { sections: Some(scenario.output.sections.clone()), ..FileMeta::of(columns(&HISTORY_COLUMNS)) },
        ),
        ("snapshots.csv", FileMeta { requested: Some(requested), ..FileMeta::of(columns(&SNAPSHOT_COLUMNS)) }),
    ]);
    if result.vehicles.is_some() {
        files.insert("wheels.csv", FileMeta::of(columns(&WHEEL_COLUMNS)));
    }
    if sleepers {
        files.insert("sleepers.csv", FileMeta::of(columns(&crate::sleeper_output::SLEEPER_COLUMNS)));
    }
    files
}

/// Remove `names` from `folder` where an earlier run left them and this one writes none: a report made from the
/// folder must not show another run's file as this one's.
fn remove_stale(folder: &Path, names: &[&str]) -> Result<()> {
    for name in names {
        let path = folder.join(name);
        if path.is_file() {
            std::fs::remove_file(&path).map_err(|e| scenario::error::StudyError::Io {
                path: path.display().to_string(),
                message: e.to_string(),
            })?;
        }
    }
    Ok(())
}
