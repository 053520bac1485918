//! `frictrack init [path]`: write the documented scenario template (the reference case, every key explained).

use crate::files::write_atomically;
use anyhow::Result;
use clap::Args;
use scenario::TEMPLATE;
use std::path::PathBuf;

/// Options of `frictrack init`.
#[derive(Debug, Args)]
pub struct InitArgs {
    /// Where to write the template; without it, standard output.
    path: Option<PathBuf>,
    /// Overwrite an existing file.
    #[arg(long)]
    force: bool,
}

/// Execute `frictrack init`.
pub fn run(args: &InitArgs) -> Result<()> {
    match &args.path {
        None => print!("{TEMPLATE}"),
        Some(path) => {
            if path.exists() && !args.force {
                return Err(scenario::error::invalid(
                    "scenario file",
                    path.display(),
                    "exists already; use --force to overwrite it",
                )
                .into());
            }
            write_atomically(path, TEMPLATE.as_bytes())?;
            eprintln!("wrote {}", path.display());
        }
    }
    Ok(())
}
