//! `frictrack plot PATH…`: draw the figures of outputs already on disk, without running anything — a sweep's CSV
//! (its figures beside it, as `sweep --out` draws them) or a run's folder (`run --out DIR`: the histories and
//! snapshots figures again, from `histories.csv` and `snapshots.csv`).

use crate::files::write_figures;
use anyhow::{Context, Result};
use clap::Args;
use std::path::{Path, PathBuf};

/// Options of `frictrack plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// Sweep CSV files (`frictrack sweep --out FILE.csv`) or run folders (`frictrack run --out DIR`).
    #[arg(required = true)]
    paths: Vec<PathBuf>,
}

/// Execute `frictrack plot`.
pub fn run(args: &PlotArgs) -> Result<()> {
    for path in &args.paths {
        let drawn = if path.is_dir() { run_folder(path)? } else { sweep_file(path)? };
        println!("{}: drew {}", path.display(), drawn.join(", "));
    }
    Ok(())
}

/// The title a run gave itself in its summary, if any: `scenario.title`, else `report.title`.
fn title_in(value: &serde_json::Value) -> Option<String> {
    [&value["scenario"]["title"], &value["report"]["title"]]
        .into_iter()
        .find_map(|t| t.as_str().filter(|t| !t.is_empty()).map(str::to_string))
}

fn read(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))
}

/// A sweep's figures beside its CSV, `{stem}-deflection.png` …
fn sweep_file(path: &Path) -> Result<Vec<String>> {
    let points = report::sweep_figures::read_sweep_csv(&read(path)?, &path.display().to_string())?;
    if points.is_empty() {
        return Err(scenario::error::invalid(&path.display().to_string(), "no finished run", "nothing to draw").into());
    }
    let stem = path.file_stem().map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
    // The scenario and the refined critical speed from the JSON `sweep --out` wrote beside the CSV, where there is one
    // (a merged shard's CSV has none: its figures name no case and mark no critical speed).
    let metadata = std::fs::read_to_string(crate::files::metadata_beside(path))
        .ok()
        .and_then(|text| report::sweep_file::SweepFile::read(&text));
    let scenario = metadata.as_ref().map(|m| m.scenario.clone());
    let critical = metadata.and_then(|m| m.critical_speed).map(|c| c.result);
    let plots = report::sweep_figures::sweep_plots(&points, &stem, scenario.as_ref(), critical.as_ref());
    Ok(write_figures("--out", &plots, path.parent().unwrap_or(Path::new(".")))?)
}

/// A run folder's history and snapshot figures again, titled as `run --out` titled them (`figures` in its
/// `summary.json`).
fn run_folder(folder: &Path) -> Result<Vec<String>> {
    let histories = read(&folder.join("histories.csv"))?;
    let snapshots = read(&folder.join("snapshots.csv"))?;
    let curves = report::run_output::RunCurves::from_csv(&histories, &snapshots)?;
    let summary: serde_json::Value = serde_json::from_str(&read(&folder.join("summary.json"))?)
        .with_context(|| format!("reading {}", folder.join("summary.json").display()))?;
    // A folder written before the titles were kept: the scenario's title, positions of the load, no subtitle.
    let figures = report::run_folder::FigureTitles::of(&summary).unwrap_or_else(|| report::run_folder::FigureTitles {
        positions_of: "load".into(),
        subtitle: String::new(),
        title: title_in(&summary).unwrap_or_default(),
    });
    // The sleepers of the exceptions, drawn across the snapshots as the run drew them.
    let listed = summary["report"]["sleepers"]["exceptions"].as_array().cloned().unwrap_or_default();
    let exceptions: Vec<(f64, String)> =
        listed.iter().filter_map(|e| Some((e["x"].as_f64()?, e["what"].as_str()?.to_string()))).collect();
    let mut plots = report::run_output::run_plots(&curves, &figures.title, &figures.positions_of, &exceptions);
    for spec in &mut plots {
        spec.subtitle.clone_from(&figures.subtitle);
    }
    Ok(write_figures("--out", &plots, folder)?)
}
