//! Progress bars for long commands: drawn on standard error only when it is a terminal and not `--quiet`.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Say on standard error what `what` ("this run", "sweep", a study's name, "stationary") will take when that is
/// long ([`runner::cost::Estimate::is_long`]): how many runs or solves, the size of the largest, the threads and the
/// estimate — terminal or not, so that nobody waits blind for a run of hours.
pub fn announce(what: &str, estimate: &runner::cost::Estimate) {
    if estimate.is_long() {
        eprintln!("{what}: {}; Ctrl-C stops it, a progress bar follows on a terminal", estimate.describe());
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
