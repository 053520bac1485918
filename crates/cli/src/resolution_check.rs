//! `run --check-resolution`: the run's twins built before the run (their sizes checked, a twin that cannot be built
//! refused before any work), run after it with a progress bar each, and the check added to the run's report
//! ([`report::resolution_check`]). An interruption during the twins keeps the run's own report. And `run --accuracy`:
//! the refinement, a progress bar for each resolution.

use anyhow::{Context, Result};
use indicatif::ProgressBar;
use report::resolution_check::ResolutionCheck;
use report::resolution_check::accuracy::{LEVEL_SECONDS, Refined, Target};
use report::resolution_check::twins::{Twin, Twins};
use report::run_summary::RunSummary;
use std::cell::RefCell;

/// The twins of `scenario`, built, with the cost of running them announced unless `quiet`.
pub fn twins(scenario: &scenario::Scenario, quiet: bool) -> Result<Twins> {
    let twins = Twins::of(scenario).context("--check-resolution: the run's twins at other resolutions")?;
    if !quiet {
        let seconds: f64 = twins.0.iter().map(|t| runner::cost::RunCost::of(&t.case).seconds).sum();
        let labels: Vec<String> = twins.0.iter().map(Twin::label).collect();
        eprintln!("--check-resolution runs {} after the run (~{seconds:.0} s more)", labels.join(" and "));
    }
    Ok(twins)
}

/// What running the twins came to: the check, or an interruption (the run's report stands without it).
pub enum Checked {
    /// The check.
    Done(ResolutionCheck),
    /// Stopped by Ctrl-C or SIGTERM.
    Interrupted,
}

/// A progress bar for each twin or resolution in turn: `started` opens the next (closing the last), `progress`
/// moves it, `close` ends the last.
pub struct Bars {
    bar: RefCell<Option<(ProgressBar, f64)>>,
    quiet: bool,
}

impl Bars {
    /// No bar yet; none at all if `quiet`.
    pub fn new(quiet: bool) -> Self {
        Self { bar: RefCell::new(None), quiet }
    }

    /// The bar of `twin`, which starts now (the last one closed).
    pub fn started(&self, twin: &Twin) {
        if !self.quiet {
            eprintln!("running {}", twin.label());
        }
        let steps = twin.case.settings.step_count(twin.scenario.mesh.length);
        let new = crate::progress::steps_bar(steps as u64, self.quiet);
        if let Some((old, _)) = self.bar.borrow_mut().replace((new, steps)) {
            old.finish_and_clear();
        }
    }

    /// The running twin's fraction done.
    pub fn progress(&self, fraction: f64) {
        if let Some((bar, steps)) = &*self.bar.borrow() {
            bar.set_position((fraction * steps) as u64);
        }
    }

    /// Close the last bar.
    pub fn close(&self) {
        if let Some((bar, _)) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

/// Run `twins` of `scenario` after its run `run`, with a progress bar each unless `quiet`.
pub fn check(twins: &Twins, scenario: &scenario::Scenario, run: &RunSummary, quiet: bool) -> Result<Checked> {
    let bars = Bars::new(quiet);
    let stop = Some(crate::interrupt::stop_flag());
    let checked = twins.check(scenario, run, stop, &mut |twin| bars.started(twin), &|f| bars.progress(f));
    bars.close();
    match checked {
        Ok(check) => Ok(Checked::Done(check)),
        Err(scenario::StudyError::Interrupted) => Ok(Checked::Interrupted),
        Err(e) => Err(e).context("--check-resolution: running the run's twins"),
    }
}

/// `run --accuracy TOL`: `scenario` refined until every outcome is within `tolerance`, a progress bar for each
/// resolution unless `quiet`, snapshots taken where a folder is written (`out`).
pub fn refine(scenario: &scenario::Scenario, tolerance: f64, out: bool, quiet: bool) -> Result<Refined> {
    if !quiet {
        eprintln!(
            "--accuracy {tolerance}: refining from {} elements × {} m until every outcome is within {} % (each halving \
             of both costs ~4×; a resolution estimated beyond {:.0} s is not started)",
            scenario.mesh.elements,
            scenario.integration.load_advance,
            100.0 * tolerance,
            LEVEL_SECONDS
        );
    }
    let bars = Bars::new(quiet);
    let requests = |s: &scenario::Scenario, c: &scenario::Case| match out {
        true => report::run_output::snapshot_requests(s, c),
        false => Vec::new(),
    };
    let stop = Some(crate::interrupt::stop_flag());
    let target = Target { tolerance, level_seconds: LEVEL_SECONDS };
    let refined = report::resolution_check::accuracy::refine(
        scenario,
        target,
        &requests,
        stop,
        &mut |twin| bars.started(twin),
        &|f| bars.progress(f),
    );
    bars.close();
    crate::interrupt::explain(refined)
}
