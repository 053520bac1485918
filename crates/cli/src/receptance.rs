//! `frictrack receptance`: the track's point or transfer receptance (m/N) and mobility over frequency, from the
//! scenario's own model in the frequency domain (docs/theory.md §17), with its resonances and a figure.

use crate::TableFormat;
use anyhow::Result;
use clap::Args;
use scenario::Scenario;
use std::path::PathBuf;
use study::receptance::text::check_folder;
use study::receptance::{ReceptanceRequest, ReceptanceStudy, frequency_range};

/// Options of `frictrack receptance`.
#[derive(Debug, Args)]
pub struct ReceptanceArgs {
    /// Scenario file (its rail — Euler–Bernoulli or Timoshenko —, linear foundation with its damping and loss
    /// factors, mesh and supports); without it, the reference case.
    scenario: Option<PathBuf>,
    /// Frequencies A:B:STEP (Hz), A > 0.
    #[arg(long, value_name = "A:B:STEP", allow_hyphen_values = true)]
    frequencies: String,
    /// Where the response is read (m). Default mid-track.
    #[arg(long, allow_negative_numbers = true)]
    at: Option<f64>,
    /// Where the harmonic force acts (m). Default: where the response is read (the point receptance).
    #[arg(long, allow_negative_numbers = true)]
    excite: Option<f64>,
    /// Output format on standard output (csv: one row per frequency).
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    format: TableFormat,
    /// Folder for receptance.csv, receptance.json and the figure.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
}

/// Parse `A:B:STEP` (Hz), errors naming `--frequencies` (`frictrack receptance` and `frictrack ground`).
pub(crate) fn parse_frequencies(text: &str) -> Result<Vec<f64>> {
    let bad = |allowed: &str| scenario::error::invalid("--frequencies", text, allowed);
    let parts: Vec<&str> = text.split(':').collect();
    let [a, b, step] = parts.as_slice() else {
        return Err(bad("expected A:B:STEP (Hz), e.g. 10:3000:2").into());
    };
    let number =
        |s: &str| s.trim().parse::<f64>().map_err(|_| bad(&format!("`{s}` is not a number; expected A:B:STEP")));
    frequency_range(number(a)?, number(b)?, number(step)?).map_err(|e| rename(e, "--frequencies").into())
}

/// The library names the request's inputs as Python does (`frequencies`, `at`, `excite`); here they are flags
/// (`frequencies` as `flag`). Every other field (the scenario's keys) keeps its name.
fn rename(error: scenario::StudyError, flag: &str) -> scenario::StudyError {
    match error {
        scenario::StudyError::InvalidField { path, value, allowed }
            if matches!(path.as_str(), "frequencies" | "at" | "excite") =>
        {
            let flag = if path == "frequencies" { flag.to_string() } else { format!("--{path}") };
            scenario::StudyError::InvalidField { path: flag, value, allowed }
        }
        other => other,
    }
}

/// Execute `frictrack receptance`.
pub fn run(args: &ReceptanceArgs) -> Result<()> {
    let scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    let frequencies = parse_frequencies(&args.frequencies)?;
    let at = args.at.unwrap_or(0.5 * scenario.mesh.length);
    let request = ReceptanceRequest { frequencies, excite: args.excite.unwrap_or(at), at };
    crate::interrupt::keep_nothing_in(args.out.as_deref(), |folder| check_folder(folder, "--out"))?;
    let runner = crate::jobs::runner(args.jobs, args.format != TableFormat::Text)?;
    let announce = |estimate: &runner::cost::Estimate| crate::progress::announce("receptance", estimate);
    let runner = runner.with_estimate(&announce).with_stop(crate::interrupt::stop_flag());
    let study = ReceptanceStudy::of(&scenario, &request, &runner).map_err(|e| rename(e, "--frequencies"));
    let study = crate::interrupt::explain(study)?;
    for warning in &study.warnings {
        eprintln!("warning: {warning}");
    }
    crate::print_output(&study, args.format)?;
    if let Some(folder) = &args.out {
        let drawn = study.write_folder(folder, "--out")?;
        eprintln!("wrote {} (receptance.csv, receptance.json, {})", folder.display(), drawn.join(", "));
    }
    Ok(())
}
