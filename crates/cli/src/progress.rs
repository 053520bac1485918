//! Progress bars for long commands: drawn on standard error only when it is a terminal and not `--quiet`.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Runs estimated to take longer than this (s) are announced with their size and estimate before they start.
const ANNOUNCE_ABOVE: f64 = 10.0;

/// Say on standard error what `runs` runs of this cost will take on `threads` threads, when that is long: the steps,
/// the DOFs, the sections and wheels, and the estimate — so that nobody waits blind for a run of hours.
pub fn announce_cost(cost: &study::cost::RunCost, runs: usize, threads: usize) {
    let seconds = cost.seconds * runs as f64 / threads.max(1).min(runs.max(1)) as f64;
    if seconds < ANNOUNCE_ABOVE {
        return;
    }
    let size = format!(
        "{:.0} steps over {} DOFs, {} friction sections, {} wheels",
        cost.steps, cost.dofs, cost.sections, cost.wheels
    );
    let what =
        if runs == 1 { format!("this run: {size}") } else { format!("{runs} runs of {size} on {threads} threads") };
    eprintln!(
        "{what}: estimated {} (within a factor of 2–3; Ctrl-C stops it, a progress bar follows on a terminal)",
        duration(seconds)
    );
}

/// A duration in the unit a reader wants: s, min or h.
fn duration(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 7200.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

/// A bar of `total` steps (or a spinner-like counter when the total is unknown, `None`), hidden unless standard
/// error is a terminal and `quiet` is off.
pub fn bar(message: &str, total: Option<u64>, quiet: bool) -> ProgressBar {
    let bar = match total {
        Some(total) => ProgressBar::new(total),
        None => ProgressBar::no_length(),
    };
    if quiet || !std::io::stderr().is_terminal() {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    let template = match total {
        Some(_) => "{msg} [{bar:40}] {pos}/{len} runs, {elapsed} elapsed, ~{eta} left",
        None => "{msg}: {pos} runs, {elapsed} elapsed",
    };
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(message.to_string());
    bar
}

/// A bar over the `total` time steps of one run, hidden unless standard error is a terminal and `quiet` is off
/// (cleared when the run ends).
pub fn steps_bar(total: u64, quiet: bool) -> ProgressBar {
    let bar = ProgressBar::new(total);
    if quiet || !std::io::stderr().is_terminal() {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template("run [{bar:40}] {pos}/{len} steps, {elapsed} elapsed, ~{eta} left")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    // Drawn from the start, the elapsed time ticking, also while the set-up and the first steps run.
    bar.enable_steady_tick(Duration::from_millis(500));
    bar
}
