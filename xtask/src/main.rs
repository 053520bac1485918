//! Project automation: `cargo xtask ci` runs `.ci/run`, exactly what CI runs: the format check, clippy with
//! warnings as errors, the API docs without broken links, and the README's test command (`scripts/test`: the Rust
//! tests, then the Python package's).

use anyhow::{Context, Result, bail};
use std::path::Path;
use std::process::{Command, ExitCode};

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
            eprintln!(
                "usage: cargo xtask ci    # .ci/run: format check, clippy -D warnings, rustdoc -D warnings, scripts/test"
            );
            ExitCode::from(2)
        }
    }
}

fn ci() -> Result<()> {
    // xtask/ sits in the workspace root, beside .ci/.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().context("the workspace root")?;
    let status = Command::new("bash").arg(".ci/run").current_dir(root).status().context("running .ci/run")?;
    if !status.success() {
        bail!("`.ci/run` failed ({status})");
    }
    Ok(())
}
