//! `run --check-resolution`: the run's twins built before the run (their sizes checked, a twin that cannot be built
//! refused before any work), run after it with a progress bar each, and the check added to the run's report
//! ([`report::resolution_check`]). An interruption during the twins keeps the run's own report.

use anyhow::{Context, Result};
use indicatif::ProgressBar;
use report::resolution_check::ResolutionCheck;
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

/// Run `twins` of `scenario` after its run `run`, with a progress bar each unless `quiet`.
pub fn check(twins: &Twins, scenario: &scenario::Scenario, run: &RunSummary, quiet: bool) -> Result<Checked> {
    let bar: RefCell<Option<(ProgressBar, f64)>> = RefCell::new(None);
    let mut started = |twin: &Twin| {
        let steps = twin.case.settings.step_count(twin.scenario.mesh.length);
        let new = crate::progress::steps_bar(steps as u64, quiet);
        new.set_message(twin.label());
        if let Some((old, _)) = bar.borrow_mut().replace((new, steps)) {
            old.finish_and_clear();
        }
    };
    let progress = |fraction: f64| {
        if let Some((bar, steps)) = &*bar.borrow() {
            bar.set_position((fraction * steps) as u64);
        }
    };
    let stop = Some(crate::interrupt::stop_flag());
    let checked = twins.check(scenario, run, stop, &mut started, &progress);
    if let Some((bar, _)) = bar.take() {
        bar.finish_and_clear();
    }
    match checked {
        Ok(check) => Ok(Checked::Done(check)),
        Err(scenario::StudyError::Interrupted) => Ok(Checked::Interrupted),
        Err(e) => Err(e).context("--check-resolution: running the run's twins"),
    }
}
