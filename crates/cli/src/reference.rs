//! `frictrack reference`: the reference case's static response under the load at mid-span and its lowest natural
//! frequencies, each beside its closed form (docs/theory.md §2, §8).

use crate::Format;
use anyhow::Result;
use clap::Args;
use scenario::{Scenario, StudyError};
use std::path::PathBuf;
use std::time::Instant;
use study::reference_check::ReferenceCheck;
use study::reference_text::ReferenceReport;

/// Options of `frictrack reference`.
#[derive(Debug, Args)]
pub struct ReferenceArgs {
    /// Scenario file (its beam, foundation, mesh, supports and load force); without it, the reference case. A
    /// scenario whose loads are a train or vehicles is refused: this checks one load at mid-span.
    scenario: Option<PathBuf>,
    /// Number of beam elements (default: the scenario's; the reference case has 200 on 200 m).
    #[arg(long, allow_negative_numbers = true)]
    elements: Option<usize>,
    /// Number of natural frequencies to report.
    #[arg(long, default_value_t = 5, allow_negative_numbers = true)]
    modes: usize,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// Execute `frictrack reference`.
pub fn run(args: &ReferenceArgs) -> Result<()> {
    let start = Instant::now();
    let mut scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    if let Some(elements) = args.elements {
        scenario.mesh.elements = elements;
    }
    // The option is `--modes` here; the library names its parameter `modes`.
    let check = ReferenceCheck::of(&scenario, args.modes).map_err(|e| match e {
        StudyError::InvalidField { path, value, allowed } if path == "modes" => {
            StudyError::InvalidField { path: "--modes".into(), value, allowed }
        }
        other => other,
    })?;
    crate::scenario_args::print_uniform_support_note(&scenario, "the closed form")?;
    let report = ReferenceReport { check, wall_time: start.elapsed().as_secs_f64() };
    crate::print_output(&report, args.format)
}
