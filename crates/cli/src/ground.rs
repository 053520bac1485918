//! `frictrack ground`: the scenario's composite beam (or two-beam track) on its `[ground]` (docs/theory.md §19) — the
//! soil's Rayleigh modes and their least phase velocity, the static strip stiffness and the Winkler control, where
//! the beam's and the soil's dispersion curves meet, and the critical speed of the track on the ground, with three
//! figures.

use crate::TableFormat;
use anyhow::Result;
use clap::Args;
use scenario::Scenario;
use std::path::PathBuf;
use study::ground::text::check_folder;
use study::ground::{GroundRequest, GroundStudy};

/// Options of `frictrack ground`.
#[derive(Debug, Args)]
pub struct GroundArgs {
    /// Scenario file with a `[ground]` section (its beam the composite track-and-embankment beam, or a rail on
    /// `[sleepers]` over an `[embankment]`).
    scenario: PathBuf,
    /// Frequencies A:B:STEP (Hz) of the dispersion curves, A > 0. Default 1:50:1.
    #[arg(long, value_name = "A:B:STEP", allow_hyphen_values = true)]
    frequencies: Option<String>,
    /// Output format on standard output (csv: the fundamental mode, one row per frequency).
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    format: TableFormat,
    /// Folder for ground.json, the tables (CSV) and the figures.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
}

/// Execute `frictrack ground`.
pub fn run(args: &GroundArgs) -> Result<()> {
    let scenario = Scenario::from_path(&args.scenario)?;
    let request = match &args.frequencies {
        Some(text) => GroundRequest { frequencies: crate::receptance::parse_frequencies(text)? },
        None => GroundRequest::default(),
    };
    crate::interrupt::keep_nothing_in(args.out.as_deref(), |folder| check_folder(folder, "--out"))?;
    let runner = crate::jobs::runner(args.jobs, args.format != TableFormat::Text)?;
    let quiet = args.format != TableFormat::Text;
    let bar = crate::progress::bar("ground", None, quiet);
    let progress = |done: usize| bar.set_position(done as u64);
    let announce = |estimate: &runner::cost::Estimate| crate::progress::announce("ground", estimate);
    let runner = runner.with_progress(&progress).with_estimate(&announce).with_stop(crate::interrupt::stop_flag());
    let study = crate::interrupt::explain(GroundStudy::of(&scenario, &request, &runner))?;
    bar.finish_and_clear();
    for warning in &study.warnings {
        eprintln!("warning: {warning}");
    }
    crate::print_output(&study, args.format)?;
    if let Some(folder) = &args.out {
        let drawn = study.write_folder(folder, "--out")?;
        eprintln!(
            "wrote {} (ground.json, dispersion.csv, modes.csv, speeds.csv, equivalent_stiffness.csv, {})",
            folder.display(),
            drawn.join(", ")
        );
    }
    Ok(())
}
