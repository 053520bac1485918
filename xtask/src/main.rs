//! Project automation: `cargo xtask ci` runs exactly what `.ci/run` runs.

use anyhow::{Context, Result, bail};
use std::process::{Command, ExitCode};

/// The CI steps, in order: format check, lints, tests (the README's test command).
const CI_STEPS: &[&[&str]] = &[
    &["fmt", "--all", "--", "--check"],
    &["clippy", "--workspace", "--all-targets", "--", "-D", "warnings"],
    &["test", "--workspace"],
];

fn main() -> ExitCode {
    let task = std::env::args().nth(1);
    match task.as_deref() {
        Some("ci") => match ci() {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error:#}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!("usage: cargo xtask ci    # format check, clippy -D warnings, cargo test --workspace");
            ExitCode::from(2)
        }
    }
}

fn ci() -> Result<()> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    for step in CI_STEPS {
        eprintln!("$ cargo {}", step.join(" "));
        let status =
            Command::new(&cargo).args(*step).status().with_context(|| format!("running cargo {}", step.join(" ")))?;
        if !status.success() {
            bail!("`cargo {}` failed ({status})", step.join(" "));
        }
    }
    Ok(())
}
