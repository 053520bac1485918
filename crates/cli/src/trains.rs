//! `frictrack trains`: the catalogue of trains (docs/theory.md §10), or one train's axles.

use crate::Format;
use anyhow::Result;
use clap::Args;
use fem_beam::Train;
use report::train_listing::{TrainCatalogue, TrainListing};

/// Arguments of `frictrack trains`.
#[derive(Debug, Args)]
pub struct TrainsArgs {
    /// A catalogue name (`single`, `hslm-a1` … `hslm-a10`) or a CSV file of offset,force lines; without it, the list.
    pub name: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
}

/// Execute `frictrack trains`.
pub fn run(args: &TrainsArgs) -> Result<()> {
    let single_force = scenario::load_section::LoadSection::default().force;
    let Some(name) = &args.name else {
        let trains = Train::catalogue()
            .iter()
            .map(|n| Train::named(n, single_force).map(|t| scenario::trains::TrainSummary::of(&t)))
            .collect::<Result<Vec<_>, _>>()
            .map_err(scenario::StudyError::from)?;
        crate::print_output(&TrainCatalogue { trains }, args.format)?;
        if args.format == Format::Text {
            println!("(`frictrack trains NAME` lists a train's axles; `--train NAME|FILE` runs one)");
        }
        return Ok(());
    };
    let train = scenario::trains::named_or_file(name, single_force, "train")?;
    train.validate().map_err(scenario::StudyError::from)?;
    crate::print_output(&TrainListing::of(&train), args.format)
}
