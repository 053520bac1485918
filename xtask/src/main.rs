//! Project automation: `cargo xtask ci` runs exactly what `.ci/run` runs.

use anyhow::{Context, Result, bail};
use std::process::Command;

/// The CI steps, in order: format check, lints, tests (the README's test command).
const CI_STEPS: &[&[&str]] = &[
    &["fmt", "--all", "--", "--check"],
    &["clippy", "--workspace", "--all-targets", "--", "-D", "warnings"],
    &["test", "--workspace"],
];

fn main() -> Result<()> {
    let task = std::env::args().nth(1);
    match task.as_deref() {
        Some("ci") => ci(),
        _ => {
            eprintln!("usage: cargo xtask ci    # format check, clippy -D warnings, cargo test --workspace");
            bail!("unknown or missing task")
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
