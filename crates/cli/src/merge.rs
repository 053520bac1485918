//! `frictrack merge --out FILE SHARD…`: combine the outputs of `frictrack sweep --shard K/N` (every shard 1/N … N/N
//! once, any order) into FILE, byte for byte the file one unsharded `frictrack sweep --out FILE` writes.

use crate::files::write_atomically;
use anyhow::{Context, Result};
use clap::Args;
use std::path::PathBuf;

/// Options of `frictrack merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The shards' output files.
    #[arg(required = true)]
    shards: Vec<PathBuf>,
    /// The merged CSV (written atomically).
    #[arg(long)]
    out: PathBuf,
}

/// Execute `frictrack merge`.
pub fn run(args: &MergeArgs) -> Result<()> {
    let inputs = args
        .shards
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).with_context(|| format!("reading {}", p.display()))?;
            Ok((p.display().to_string(), text))
        })
        .collect::<Result<Vec<_>>>()?;
    let merged = runner::shard::merge(&inputs)?;
    Ok(write_atomically(&args.out, merged.as_bytes())?)
}
