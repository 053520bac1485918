//! `frictrack sweep [scenario] --speeds A:B:STEP`: one run per speed, in parallel; CSV on stdout or to `--out`
//! (columns `speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm,…`; `OUT.json` beside
//! it names their units), and with `--critical` the refined critical speed — or the bound, when the largest
//! deflection lies at an end of the range — in `OUT.json` (or a `# critical_speed {…}` line after the CSV on
//! stdout) and on stderr.
//!
//! With `--out FILE`, every finished point goes to `FILE.journal` at once; the CSV is written atomically at the end
//! and the journal deleted. After an interruption (Ctrl-C, a kill, a node failure) the same command with `--resume`
//! runs only the missing points. `--shard K/N` runs a deterministic 1/N of the speeds; `frictrack merge` combines the
//! shards' files into the file one unsharded run writes.

use crate::analytic::parse_range;
use crate::files::{check_output_file, journal_beside, metadata_beside, write_atomically};
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use runner::shard::Shard;
use runner::{FailedRun, critical_speed, failures, finished, write_csv_rows};
use scenario::error::invalid;
use std::path::PathBuf;

/// Options of `frictrack sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Speeds A:B:STEP (m/s); default: the scenario's `[sweep]` section (10:300:10 for the reference case).
    #[arg(long, allow_hyphen_values = true)]
    speeds: Option<String>,
    /// Write the CSV here (atomically) instead of standard output; finished points are kept in OUT.journal.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Continue an interrupted sweep: take the points already in OUT.journal, run the others.
    #[arg(long, requires = "out")]
    resume: bool,
    /// Run only shard K of N (every N-th speed from the K-th); combine the outputs with `frictrack merge`.
    #[arg(long, value_name = "K/N", requires = "out", conflicts_with = "critical")]
    shard: Option<String>,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Also refine the critical speed below the sweep step (fresh runs) and report it.
    #[arg(long)]
    critical: bool,
    /// No progress or summary on standard error.
    #[arg(long)]
    quiet: bool,
    /// Also check the run at the sweep's peak (the refined critical speed with --critical, else the speed of the
    /// largest max downward deflection) against its twins at other resolutions, and report its errors.
    #[arg(long, conflicts_with = "shard")]
    check_resolution: bool,
}

/// Execute `frictrack sweep`.
pub fn run(args: &SweepArgs) -> Result<()> {
    if let Some(speed) = args.scenario.flags.number("speed") {
        return Err(invalid("--speed", speed, "sweep runs many speeds: give --speeds A:B:STEP").into());
    }
    let scenario = args.scenario.load()?;
    scenario.refuse_sweep_on_the_ground()?;
    let case = scenario.build()?;
    let all_speeds = match &args.speeds {
        Some(range) => parse_range(range)?,
        None => scenario.speed_range()?.speeds(),
    };
    for warning in scenario::diagnostics::sweep_warnings(&scenario, &all_speeds)? {
        eprintln!("warning: {warning}");
    }
    let shard = args.shard.as_deref().map(Shard::parse).transpose()?;
    let speeds = shard.map_or_else(|| all_speeds.clone(), |s| s.select(&all_speeds));
    if args.critical && speeds.len() < 3 {
        return Err(invalid("--speeds", speeds.len(), "--critical needs at least 3 speeds").into());
    }
    if let Some(out) = &args.out {
        check_outputs(out)?;
    }
    if let (true, Some(&first)) = (args.check_resolution, speeds.first()) {
        crate::sweep_check::refuse_early(&scenario, first)?;
    }
    let journal =
        args.out.as_deref().map(|out| runner::Journal::open(&journal_beside(out), args.resume)).transpose()?;
    if let Some(j) = journal.as_ref().filter(|j| j.resumed() > 0 && !args.quiet) {
        eprintln!("resuming: {} finished runs in {}", j.resumed(), j.path().display());
    }
    let runner = crate::jobs::runner(args.jobs, args.quiet)?;
    let bar = crate::progress::bar("sweep", Some(speeds.len() as u64), args.quiet);
    let progress = |done: usize| bar.set_position(done as u64);
    let announce = |estimate: &runner::cost::Estimate| crate::progress::announce("sweep", estimate);
    let runner =
        runner.with_progress(&progress).with_journal(journal.as_ref()).with_stop(crate::interrupt::stop_flag());
    let runner = if args.quiet { runner } else { runner.with_estimate(&announce) };
    let (step, tolerance) = critical_tolerance(&speeds);
    // With --critical the refinement's runs follow the sweep: counted in its estimate.
    let refinements = if args.critical { runner::refinement_runs(step, tolerance, 0) } else { 0 };
    let sweeping = runner.clone().with_refinement(refinements);
    crate::interrupt::keep(crate::interrupt::Kept::in_journal(journal.as_ref()));
    let rows = crate::interrupt::explain(sweeping.speed_sweep_keeping(&case, &speeds))?;
    bar.finish_and_clear();
    let (points, failed) = (finished(&rows), failures(&rows));
    let mut csv = Vec::new();
    if let Some(s) = shard {
        csv.extend_from_slice(s.header(&all_speeds, case.fingerprint).as_bytes());
        csv.push(b'\n');
    }
    write_csv_rows(&rows, &mut csv)?;
    let critical = if args.critical && failed.is_empty() {
        let c = crate::interrupt::explain(critical_speed(&case, &points, tolerance, &runner))?;
        if !args.quiet {
            eprintln!("{}", c.describe());
        }
        Some(c)
    } else {
        None
    };
    let checked = match args.check_resolution && failed.is_empty() {
        true => crate::sweep_check::at_peak(&scenario, &points, critical.as_ref(), args.quiet)?,
        false => None,
    };
    match &args.out {
        Some(path) => {
            let notes = (critical.as_ref(), checked.as_ref());
            write_files(path, &csv, &scenario, (&points, &failed), notes, shard.is_none())?
        }
        None => print_csv(csv, &scenario, &failed, (critical.as_ref(), checked.as_ref()))?,
    }
    if !failed.is_empty() {
        return Err(failed_runs(&failed, rows.len(), args.critical, journal.as_ref()));
    }
    if let Some(j) = journal {
        j.remove()?;
    }
    Ok(())
}

/// The CSV on standard output, then comment lines (pandas: comment="#") so that --quiet never loses the answer: the
/// critical speed, the check at the peak, the failed runs and the columns' units.
fn print_csv(
    csv: Vec<u8>,
    scenario: &scenario::Scenario,
    failed: &[FailedRun],
    (critical, checked): (Option<&runner::CriticalSpeed>, Option<&report::resolution_check::point::PointCheck>),
) -> Result<()> {
    print!("{}", String::from_utf8(csv)?);
    if let Some(c) = critical {
        println!("# critical_speed {}", serde_json::to_string(c)?);
    }
    if let Some(c) = checked {
        println!("# resolution_check {}", serde_json::to_string(c)?);
    }
    for f in failed {
        println!("# failed_run {}", serde_json::to_string(f)?);
    }
    let units = runner::csv_columns_of(scenario).map(|(name, unit, _)| (*name, *unit));
    println!("# {}", report::columns::units_line(units));
    Ok(())
}

/// The error that ends a sweep in which some runs failed (after every other run finished and was written): the
/// failed speeds with their errors, and what was kept.
fn failed_runs(failed: &[FailedRun], total: usize, critical: bool, journal: Option<&runner::Journal>) -> anyhow::Error {
    let list: Vec<String> = failed.iter().map(|f| format!("  {} m/s: {}", f.speed, f.error)).collect();
    let kept = match journal {
        Some(j) => format!(
            "the CSV has every other run (the failed rows are empty; their errors are in the JSON beside it), and {} \
             keeps the finished runs for --resume",
            j.path().display()
        ),
        None => "the CSV above has every other run (the failed rows are empty, `# failed_run` lines say why)".into(),
    };
    let critical = if critical { "; no critical speed was refined over a sweep with failed runs" } else { "" };
    anyhow::anyhow!("{} of {total} runs failed:\n{}\n{kept}{critical}", failed.len(), list.join("\n"))
}

/// Refuse before any run an output that cannot be written: the CSV, its metadata and its figures beside it.
fn check_outputs(out: &std::path::Path) -> Result<()> {
    check_output_file("--out", out)?;
    check_output_file("--out", &metadata_beside(out))?;
    let stem = out.file_stem().map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
    let folder = out.parent().unwrap_or(std::path::Path::new("."));
    for suffix in report::sweep_figures::FIGURE_SUFFIXES {
        for extension in ["png", "svg"] {
            check_output_file("--out", &folder.join(format!("{stem}-{suffix}.{extension}")))?;
        }
    }
    Ok(())
}

/// Write the sweep's files at `path`: the CSV (`csv`), its figures (a whole sweep of ≥ 2 finished runs; a shard's
/// few speeds are drawn by `plot` after merge) and its metadata (columns with units, the critical speed, the
/// `failed` runs, the scenario, the check at the peak).
fn write_files(
    path: &std::path::Path,
    csv: &[u8],
    scenario: &scenario::Scenario,
    (points, failed): (&[runner::SweepPoint], &[runner::FailedRun]),
    (critical, checked): (Option<&runner::CriticalSpeed>, Option<&report::resolution_check::point::PointCheck>),
    whole: bool,
) -> Result<()> {
    write_atomically(path, csv)?;
    // The swept metrics against speed, beside the CSV (a shard's few speeds are drawn by `plot` after merge).
    if whole && points.len() >= 2 {
        let stem = path.file_stem().map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
        let plots = report::sweep_figures::sweep_plots(points, &stem, Some(scenario), critical);
        crate::files::write_figures("--out", &plots, path.parent().unwrap_or(std::path::Path::new(".")))?;
    }
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    let mut metadata = report::sweep_file::SweepFile::of(name, scenario, critical, failed);
    metadata.resolution_check = checked.map(serde_json::to_value).transpose()?;
    write_atomically(&metadata_beside(path), serde_json::to_string_pretty(&metadata)?.as_bytes())?;
    Ok(())
}

/// The sweep's smallest speed step and the tolerance (m/s) `--critical` refines the critical speed to: 1 % of that
/// step (at least 1 mm/s; 0.1 m/s for a single speed, whose step counts as 10 m/s).
fn critical_tolerance(speeds: &[f64]) -> (f64, f64) {
    let step = speeds.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    if step.is_finite() { (step, (0.01 * step).max(1e-3)) } else { (10.0, 0.1) }
}
