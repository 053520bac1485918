//! `frictrack check <scenario>`: parse and validate a scenario file without running it.

use anyhow::Result;
use clap::Args;
use friction::ContactKind;
use std::path::PathBuf;
use study::Scenario;

/// Options of `frictrack check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Scenario file (TOML).
    scenario: PathBuf,
}

/// Execute `frictrack check`.
pub fn run(args: &CheckArgs) -> Result<()> {
    let scenario = Scenario::from_path(&args.scenario)?;
    let case = scenario.build()?;
    let range = scenario.speed_range()?;
    let devices = case.contacts.kinds().iter().filter(|k| **k == ContactKind::Device).count();
    println!(
        "{}: ok — {} m beam, {} elements ({} DOFs), {} friction sections ({} devices), load {:.1} kN at {} m/s, sweep {}–{} m/s by {}",
        args.scenario.display(),
        case.model.mesh().length,
        case.model.mesh().elements,
        case.model.dofs().free_len(),
        case.contacts.len(),
        devices,
        scenario.load.force / 1e3,
        scenario.load.speed,
        range.from,
        range.to,
        range.step
    );
    Ok(())
}
