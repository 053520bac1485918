//! `frictrack run`: one Moreau–Jean simulation of a scenario (default: the reference case of docs/theory.md §2) with flags
//! overriding it; prints the key inputs, the whole-run extremes and the extremes while the load is in the middle
//! third (or `--extremes-window`), energies, solver statistics and wall time; with vehicles, their wheel forces,
//! losses of contact and body accelerations. With `--out DIR` it also writes `summary.json`, `histories.csv`,
//! `snapshots.csv` and their figures ([`report::run_output`]), and with vehicles `wheels.csv` and its figure
//! ([`report::vehicle_output`]).

use crate::Format;
use crate::resolution_check::Checked;
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use report::run_summary::RunSummary;
use std::path::PathBuf;
use std::time::Instant;

/// Options of `frictrack run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Write summary.json, histories.csv, snapshots.csv and figures (PNG + SVG) into this folder.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Sections (m) whose histories are recorded, e.g. 50,100 (default: the scenario's `[output]` sections, or
    /// mid-span with --out).
    #[arg(long, value_delimiter = ',', value_name = "X,…", allow_negative_numbers = true)]
    record: Vec<f64>,
    /// Load positions (m) at which whole-beam snapshots are taken, e.g. 50,100,150 (default: the scenario's
    /// `[output]` snapshots, or the first axle at ¼, ½ and ¾ of its travel: L/4, L/2, 3L/4 from rest).
    #[arg(long, value_delimiter = ',', value_name = "X,…", allow_negative_numbers = true)]
    snapshot_at_load: Vec<f64>,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
    /// Run through a window that travels with the load over any length of track (`[co_moving]` with its defaults:
    /// a 120 m window over 1000 m) instead of across the finite beam.
    #[arg(long)]
    co_moving: bool,
    /// Also run the scenario's twins at other resolutions (elements and load advance doubled and halved; about 4¼
    /// times the run's cost) and report every outcome's estimated discretisation error.
    #[arg(long)]
    check_resolution: bool,
    /// Refine (elements and load advance halved together) until every outcome's estimated error is within this
    /// relative tolerance, e.g. 0.01 for 1 %, and report the finest run with its errors.
    #[arg(long, value_name = "TOL", conflicts_with = "check_resolution", allow_negative_numbers = true)]
    accuracy: Option<f64>,
}

/// Execute `frictrack run`.
pub fn run(args: &RunArgs) -> Result<()> {
    let start = Instant::now();
    let mut scenario = args.scenario.load()?;
    if !args.record.is_empty() {
        scenario.output.sections = args.record.clone();
    }
    if !args.snapshot_at_load.is_empty() {
        scenario.output.snapshot_times.clear();
        scenario.output.snapshot_load_positions = args.snapshot_at_load.clone();
    }
    if args.co_moving && scenario.co_moving.is_none() {
        scenario.co_moving = Some(scenario::CoMovingSection::default());
    }
    let accuracy = tolerance(args, &mut scenario)?;
    check_resolution_flags(args, accuracy, scenario.co_moving.is_some())?;
    if let Some(section) = scenario.co_moving.clone() {
        return crate::co_moving::run(&scenario, &section, args.format, args.out.as_deref());
    }
    if args.out.is_some() {
        scenario = report::run_output::recording(scenario);
    }
    let case = scenario.build()?;
    let mut warnings = crate::scenario_args::print_warnings(&scenario, &case);
    let quiet = args.quiet || args.format == Format::Json;
    let twins = match args.check_resolution {
        true => Some(crate::resolution_check::twins(&scenario, quiet)?),
        false => None,
    };
    crate::interrupt::keep_nothing_in(args.out.as_deref(), |folder| report::run_folder::check("--out", folder, &case))?;
    let (scenario, case, result, snapshots, report, check_interrupted) = match accuracy.map(|(t, _)| t) {
        Some(tolerance) => {
            let refined = crate::resolution_check::refine(&scenario, tolerance, args.out.is_some(), quiet)?;
            let interrupted = refined.summary.accuracy.as_ref().is_some_and(|a| a.status.interrupted());
            // What is recorded warns of the scenario as it ran (the resolution given was refined).
            warnings = scenario::diagnostics::warnings(&refined.scenario, &refined.case)
                .iter()
                .map(ToString::to_string)
                .collect();
            (refined.scenario, refined.case, refined.result, refined.snapshots, refined.summary, interrupted)
        }
        None => {
            let (result, snapshots, mut report) = run_once(&scenario, &case, args.out.is_some(), quiet, start)?;
            let mut interrupted = false;
            if let Some(twins) = &twins {
                match crate::resolution_check::check(twins, &scenario, &report, quiet)? {
                    Checked::Done(check) => report.resolution_check = Some(check),
                    Checked::Interrupted => interrupted = true,
                }
            }
            (scenario, case, result, snapshots, report, interrupted)
        }
    };
    for warning in report::result_warnings::result_warnings(&case, &report) {
        eprintln!("warning: {warning}");
        warnings.push(warning.to_string());
    }
    crate::print_output(&report, args.format)?;
    if let Some(warning) = report.fallback_warning() {
        eprintln!("warning: {warning}");
        warnings.push(warning);
    }
    if let Some(out) = &args.out {
        let record = report::run_folder::RunRecord { provenance: &crate::provenance(), warnings: &warnings };
        report::run_folder::write(out, (&scenario, &case), (&report, record), &result, &snapshots)?;
        if args.format == Format::Text {
            let wheels = if result.vehicles.is_some() { ", wheels.csv" } else { "" };
            println!("  wrote {}/summary.json, histories.csv, snapshots.csv{wheels} and figures", out.display());
        }
    }
    if check_interrupted {
        let what = match accuracy {
            Some(_) => "the finest run finished is reported above, with what its refinement reached",
            None => "the run's report stands without its resolution check",
        };
        return Err(crate::interrupt::interrupted_after(what));
    }
    Ok(())
}

/// The tolerance the run refines to and where it was asked — `--accuracy`, else the scenario's
/// `integration.accuracy` (taken out of `scenario`: the refinement builds it at each resolution) — checked; None for a
/// run at the resolution given.
fn tolerance(args: &RunArgs, scenario: &mut scenario::Scenario) -> Result<Option<(f64, &'static str)>> {
    let asked = args.accuracy.map(|t| (t, "--accuracy"));
    let check = args.check_resolution.then_some("--check-resolution");
    let tolerance = scenario.take_run_tolerance(asked, check)?;
    Ok(tolerance.map(|t| (t, if asked.is_some() { "--accuracy" } else { "integration.accuracy" })))
}

/// Neither a refinement (`accuracy`, with where it was asked) nor `--check-resolution` is asked of a run through a
/// co-moving window (`co_moving`).
fn check_resolution_flags(args: &RunArgs, accuracy: Option<(f64, &str)>, co_moving: bool) -> Result<()> {
    let given = [(args.check_resolution, "--check-resolution"), (accuracy.is_some(), accuracy.map_or("", |a| a.1))];
    match given.into_iter().find_map(|(given, flag)| given.then_some(flag)).filter(|_| co_moving) {
        Some(flag) => Err(scenario::error::invalid(
            flag,
            "given",
            "is for a run across the finite beam: a run through a co-moving window is not checked",
        )
        .into()),
        None => Ok(()),
    }
}

/// One run of `case` (of `scenario`), with snapshots where a folder is written, a progress bar unless `quiet`: its
/// result, snapshots and summary (wall time from `start`).
fn run_once(
    scenario: &scenario::Scenario,
    case: &scenario::Case,
    out: bool,
    quiet: bool,
    start: Instant,
) -> Result<(track::RunResult, Vec<track::Snapshot>, RunSummary)> {
    let requests = match out {
        true => report::run_output::snapshot_requests(scenario, case),
        false => Vec::new(),
    };
    let steps = case.settings.step_count(scenario.mesh.length);
    if !quiet {
        crate::progress::announce("this run", &runner::cost::Estimate::run(runner::cost::RunCost::of(case)));
    }
    let bar = crate::progress::steps_bar(steps as u64, quiet);
    let progress = |fraction: f64| bar.set_position((fraction * steps) as u64);
    let ran = report::run_output::run_with_snapshots(case, &requests, Some(crate::interrupt::stop_flag()), &progress);
    bar.finish_and_clear();
    let (result, snapshots) = crate::interrupt::explain(ran)?;
    let report = RunSummary::of(scenario, case, &result, start)?;
    Ok((result, snapshots, report))
}
