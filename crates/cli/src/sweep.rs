//! `frictrack sweep [scenario] --speeds A:B:STEP`: one run per speed, in parallel; CSV on stdout or to `--out`
//! (columns `speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm,…`), and the refined
//! critical speed on stderr with `--critical`.

use crate::analytic::parse_range;
use crate::files::write_atomically;
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use std::path::PathBuf;
use study::sweep::{critical_speed, speed_sweep, write_csv};

/// Options of `frictrack sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Speeds A:B:STEP (m/s); default: the scenario's [sweep] section (10:300:10 for the reference case).
    #[arg(long)]
    speeds: Option<String>,
    /// Write the CSV here (atomically) instead of standard output.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Also refine the critical speed below the sweep step (fresh runs) and report it.
    #[arg(long)]
    critical: bool,
    /// No progress or summary on standard error.
    #[arg(long)]
    quiet: bool,
}

/// Execute `frictrack sweep`.
pub fn run(args: &SweepArgs) -> Result<()> {
    let scenario = args.scenario.load()?;
    let case = scenario.build()?;
    let speeds = match &args.speeds {
        Some(range) => parse_range(range)?,
        None => scenario.sweep.speeds(),
    };
    let bar = crate::progress::bar("sweep", Some(speeds.len() as u64), args.quiet);
    let points = speed_sweep(&case, &speeds, args.jobs, &|done| bar.set_position(done as u64))?;
    bar.finish_and_clear();
    let mut csv = Vec::new();
    write_csv(&points, &mut csv)?;
    match &args.out {
        Some(path) => write_atomically(path, &csv)?,
        None => print!("{}", String::from_utf8(csv)?),
    }
    if args.critical {
        let step = speeds.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
        let tolerance = if step.is_finite() { (0.01 * step).max(1e-3) } else { 0.1 };
        let c = critical_speed(&case, &points, tolerance)?;
        if !args.quiet {
            eprintln!(
                "critical speed {:.2} m/s ({:.0} km/h): max downward deflection {:.2} mm (sweep maximum {:.2} mm at {} m/s, {} refinement runs)",
                c.speed,
                c.speed * 3.6,
                c.max_downward_deflection * 1e3,
                c.sweep_maximum.1 * 1e3,
                c.sweep_maximum.0,
                c.evaluations.len()
            );
        }
    }
    Ok(())
}
