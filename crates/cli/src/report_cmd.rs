//! `frictrack report DIR [--out FILE.html]`: a run, study or `reproduce` folder as one self-contained HTML file
//! ([`report::html`]): figures inline as SVG, the tables and verdicts, every warning, the scenario as it ran, the
//! command line, version, commit and date, a table of contents and a print stylesheet.

use anyhow::Result;
use clap::Args;
use std::path::PathBuf;

/// Options of `frictrack report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    /// The folder: written by `frictrack run --out`, `frictrack study --out` or `frictrack reproduce --out`.
    #[arg(value_name = "DIR")]
    dir: PathBuf,
    /// The HTML file to write (default: DIR/report.html).
    #[arg(long, value_name = "FILE.html")]
    out: Option<PathBuf>,
}

/// Execute `frictrack report`.
pub fn run(args: &ReportArgs) -> Result<()> {
    let written = report::html::write_report(&args.dir, args.out.as_deref(), "--out")?;
    println!("wrote {}", written.display());
    Ok(())
}
