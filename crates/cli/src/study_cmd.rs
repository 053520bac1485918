//! `frictrack study <preset>`: run one of the thirteen studies (docs/theory.md §7, §10, §12, §14, §17–§19) and write
//! `<preset>.csv` (the data), `<preset>.json` (scenario, version, git revision, resolution, summary, wall time) and
//! its figures (PNG and SVG) into the output folder.

use crate::files::{check_output_file, prepare_output_folder, write_atomically};
use anyhow::Result;
use clap::Args;
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use runner::Runner;
use scenario::DeckTrack;
use scenario::Scenario;
use std::path::PathBuf;
use std::time::Instant;
use study::presets::{Preset, Resolution, StudyData, run_preset};

/// `--resolution NAME`: the names of [`Resolution::ALL`] with what each samples, checked by clap.
fn resolution_parser() -> impl TypedValueParser<Value = Resolution> {
    PossibleValuesParser::new(Resolution::ALL.map(|r| PossibleValue::new(r.name()).help(r.description())))
        .try_map(|name| Resolution::from_name(&name))
}

/// Options shared by `frictrack study` and `frictrack reproduce`.
#[derive(Debug, Args)]
pub struct StudyOptions {
    /// Base scenario (default: the reference case); the studies vary friction and speed on top of it.
    #[arg(long)]
    scenario: Option<PathBuf>,
    /// Speed and force sampling.
    #[arg(long, value_parser = resolution_parser(), default_value = "coarse")]
    pub resolution: Resolution,
    /// Output folder (created if needed).
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// No progress on standard error.
    #[arg(long)]
    pub quiet: bool,
    /// Continue after an interruption: take the runs already in OUT/.STUDY.journal, run the others.
    #[arg(long)]
    resume: bool,
    /// The track on a bridge deck, which sets the EN 1990 acceleration limit the hslm study checks a span against:
    /// ballasted (3.5 m/s²) or direct-fastening (5 m/s²). Default: the scenario's `[output] deck_track`, else
    /// ballasted.
    #[arg(long, value_name = "TRACK", value_parser = |s: &str| s.parse::<DeckTrack>())]
    deck_track: Option<DeckTrack>,
}

impl StudyOptions {
    /// The command's one pool of worker threads (`--jobs`, capped at the cores).
    pub fn workers(&self) -> Result<Runner<'static>> {
        crate::jobs::runner(self.jobs, self.quiet)
    }

    /// The base scenario: the file given, or the reference case, with `--deck-track` on it.
    pub fn base(&self) -> Result<Scenario> {
        let mut base = match &self.scenario {
            Some(path) => Scenario::from_path(path)?,
            None => Scenario::default(),
        };
        if let Some(track) = self.deck_track {
            base.output.deck_track = track;
        }
        Ok(base)
    }
}

/// Options of `frictrack study`.
#[derive(Debug, Args)]
pub struct StudyArgs {
    /// discrete-speed, equal-cost, optimal-force, distributed-speed, amplification, discrete-vs-distributed, hslm,
    /// vehicle-speed, stationary-wave (the nine `reproduce` runs), voided-sleepers, sleeper-friction, receptance or ledsgard.
    preset: String,
    #[command(flatten)]
    options: StudyOptions,
}

/// Execute `frictrack study`.
pub fn run(args: &StudyArgs) -> Result<()> {
    let preset = Preset::from_name(&args.preset)?;
    let workers = args.options.workers()?;
    let (data, journal) = run_study(preset, &args.options, &args.options.base()?, &workers, &[])?;
    for line in &data.lines {
        println!("{line}");
    }
    if !data.failures.is_empty() {
        return Err(failed_runs(&data, &journal));
    }
    journal.remove()?;
    Ok(())
}

/// The failed runs of a study, one line each ("  devices = 31, … at 210 m/s: …").
pub fn failure_lines(data: &StudyData) -> Vec<String> {
    data.failures
        .iter()
        .map(|f| match f.speed {
            Some(v) => format!("  {} at {v} m/s: {}", f.case, f.error),
            None => format!("  {}: {}", f.case, f.error),
        })
        .collect()
}

/// The error that ends a study in which some runs failed (after every other run finished and its data, figures and
/// JSON were written): the failed runs with their errors, and what was kept.
fn failed_runs(data: &StudyData, journal: &runner::Journal) -> anyhow::Error {
    anyhow::anyhow!(
        "{} run(s) of {} failed:\n{}\nthe study's CSV, JSON and figures have every other run (the JSON lists the \
         failures), and {} keeps the finished runs for --resume",
        data.failures.len(),
        data.name,
        failure_lines(data).join("\n"),
        journal.path().display()
    )
}

/// Run a preset on `base` and write its CSV, JSON and figures into the output folder; finished runs are kept in
/// `OUT/.<preset>.journal` (taken from there with `--resume`), returned for the caller to remove once nothing else
/// depends on them.
pub fn run_study(
    preset: Preset,
    options: &StudyOptions,
    base: &Scenario,
    workers: &Runner<'static>,
    borrowed: &[std::path::PathBuf],
) -> Result<(StudyData, runner::Journal)> {
    let (out, quiet) = (options.out.as_path(), options.quiet);
    base.refuse_sweep_on_the_ground()?;
    let case = base.build()?;
    let warnings = crate::scenario_args::print_warnings(base, &case);
    prepare_output_folder("--out", out)?;
    for extension in ["csv", "json"] {
        check_output_file("--out", &out.join(format!("{}.{extension}", preset.name())))?;
    }
    // Every file a study writes is named after it (its figures too): any such name taken by a link, device or FIFO
    // is refused before the first run.
    for entry in std::fs::read_dir(out).into_iter().flatten().flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with(preset.name()) && [".png", ".svg"].iter().any(|e| name.ends_with(e)) {
            check_output_file("--out", &entry.path())?;
        }
    }
    let mut journal = runner::Journal::open(&out.join(format!(".{}.journal", preset.name())), options.resume)?;
    if journal.resumed() > 0 && !quiet {
        eprintln!("{}: resuming with {} finished runs", preset.name(), journal.resumed());
    }
    // Runs another study of the same command finished (the same case at the same speed, the same key) are not run
    // again.
    for path in borrowed {
        journal.borrow_from(path)?;
    }
    let resolution = options.resolution;
    let overrides = preset.overrides(base);
    for note in &overrides {
        eprintln!("note: {}: {note}", preset.name());
    }
    let bar = crate::progress::bar(preset.name(), None, quiet);
    let progress = |done: usize| bar.set_position(done as u64);
    let announce = |estimate: &runner::cost::Estimate| crate::progress::announce(preset.name(), estimate);
    let runner =
        workers.clone().with_progress(&progress).with_journal(Some(&journal)).with_stop(crate::interrupt::stop_flag());
    let runner = if quiet { runner } else { runner.with_estimate(&announce) };
    let start = Instant::now();
    crate::interrupt::keep(crate::interrupt::Kept::in_journal(Some(&journal)));
    let data = crate::interrupt::explain(run_preset(preset, resolution, base, &runner))?;
    let wall_time = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    write_atomically(&out.join(format!("{}.csv", preset.name())), data.csv.as_bytes())?;
    let provenance = crate::provenance();
    let metadata = data.file((preset, resolution, base), (overrides, &warnings), (wall_time, &provenance))?;
    write_atomically(
        &out.join(format!("{}.json", preset.name())),
        serde_json::to_string_pretty(&metadata)?.as_bytes(),
    )?;
    for spec in &data.plots {
        report::plot::render(spec, out)?;
    }
    Ok((data, journal))
}
