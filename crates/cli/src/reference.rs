//! `frictrack reference`: the reference case's static response under the load at mid-span and its lowest natural
//! frequencies, each beside its closed form (docs/theory.md §2, §8).

use crate::Format;
use anyhow::Result;
use clap::Args;
use scenario::{Scenario, StudyError};
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;
use study::reference_check::ReferenceCheck;

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

/// The JSON of `frictrack reference`: the check and the wall time (s).
#[derive(Debug, Serialize)]
struct ReferenceReport {
    #[serde(flatten)]
    check: ReferenceCheck,
    wall_time: f64,
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
    let report = ReferenceReport { check, wall_time: start.elapsed().as_secs_f64() };
    match args.format {
        Format::Json => println!("{}", serde_json::to_string_pretty(&report)?),
        Format::Text => print_text(&report),
    }
    Ok(())
}

fn print_text(report: &ReferenceReport) {
    let r = &report.check;
    println!(
        "frictrack — {}: {} m beam ({} ends), {} elements ({} DOFs)",
        r.title, r.length, r.supports, r.elements, r.dofs
    );
    println!(
        "static load {:.1} kN at mid-span                  FE            closed form (infinite beam)",
        r.load / 1e3
    );
    println!(
        "  deflection under the load           {:>10.3} mm   {:>10.3} mm",
        r.midspan_deflection * 1e3,
        r.midspan_deflection_closed_form * 1e3
    );
    println!(
        "  bending moment under the load       {:>10.3} kN·m {:>10.3} kN·m",
        r.midspan_moment / 1e3,
        r.midspan_moment_closed_form / 1e3
    );
    println!("critical speed v_cr = {:.2} m/s ({:.0} km/h)", r.critical_speed, r.critical_speed * 3.6);
    println!("natural circular frequencies (pinned beam)     FE            closed form");
    for m in &r.modes {
        println!(
            "  ω{:<3}                               {:>10.4} rad/s {:>10.4} rad/s",
            m.n, m.omega, m.omega_closed_form
        );
    }
    println!("wall time {:.3} s", report.wall_time);
}
