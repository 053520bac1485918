//! `frictrack sweep [scenario] --speeds A:B:STEP`: one run per speed, in parallel; CSV on stdout or to `--out`
//! (columns `speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm,…`), and the refined
//! critical speed on stderr with `--critical`.
//!
//! With `--out FILE`, every finished point goes to `FILE.journal` at once; the CSV is written atomically at the end
//! and the journal deleted. After an interruption (Ctrl-C, a kill, a node failure) the same command with `--resume`
//! runs only the missing points. `--shard K/N` runs a deterministic 1/N of the speeds; `frictrack merge` combines the
//! shards' files into the file one unsharded run writes.

use crate::analytic::parse_range;
use crate::files::{journal_beside, write_atomically};
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use std::path::PathBuf;
use study::shard::Shard;
use study::sweep::{Runner, critical_speed, write_csv};

/// Options of `frictrack sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Speeds A:B:STEP (m/s); default: the scenario's [sweep] section (10:300:10 for the reference case).
    #[arg(long)]
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
}

/// Execute `frictrack sweep`.
pub fn run(args: &SweepArgs) -> Result<()> {
    let scenario = args.scenario.load()?;
    let case = scenario.build()?;
    let all_speeds = match &args.speeds {
        Some(range) => parse_range(range)?,
        None => scenario.sweep.speeds(),
    };
    let shard = args.shard.as_deref().map(Shard::parse).transpose()?;
    let speeds = shard.map_or_else(|| all_speeds.clone(), |s| s.select(&all_speeds));
    let journal = args.out.as_deref().map(|out| study::Journal::open(&journal_beside(out), args.resume)).transpose()?;
    if let Some(j) = journal.as_ref().filter(|j| j.resumed() > 0 && !args.quiet) {
        eprintln!("resuming: {} finished runs in {}", j.resumed(), j.path().display());
    }
    let bar = crate::progress::bar("sweep", Some(speeds.len() as u64), args.quiet);
    let progress = |done: usize| bar.set_position(done as u64);
    let runner = Runner::new(args.jobs)
        .with_progress(&progress)
        .with_journal(journal.as_ref())
        .with_stop(crate::interrupt::stop_flag());
    let points = crate::interrupt::explain(runner.speed_sweep(&case, &speeds), journal.as_ref())?;
    bar.finish_and_clear();
    let mut csv = Vec::new();
    if let Some(s) = shard {
        csv.extend_from_slice(s.header(&all_speeds, case.fingerprint).as_bytes());
        csv.push(b'\n');
    }
    write_csv(&points, &mut csv)?;
    if args.critical {
        let step = speeds.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
        let tolerance = if step.is_finite() { (0.01 * step).max(1e-3) } else { 0.1 };
        let c = crate::interrupt::explain(critical_speed(&case, &points, tolerance, &runner), journal.as_ref())?;
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
    match &args.out {
        Some(path) => write_atomically(path, &csv)?,
        None => print!("{}", String::from_utf8(csv)?),
    }
    if let Some(j) = journal {
        j.remove()?;
    }
    Ok(())
}
