//! Progress bars for long commands: drawn on standard error only when it is a terminal and not `--quiet`.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

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
    bar
}
