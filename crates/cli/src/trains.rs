//! `frictrack trains`: the catalogue of trains (docs/theory.md §10), or one train's axles.

use crate::Format;
use anyhow::Result;
use clap::Args;
use fem_beam::Train;
use serde::Serialize;

/// Arguments of `frictrack trains`.
#[derive(Debug, Args)]
pub struct TrainsArgs {
    /// A catalogue name (`single`, `hslm-a1` … `hslm-a10`) or a CSV file of offset,force lines; without it, the list.
    pub name: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
}

/// One train in full, as `frictrack trains NAME --format json` prints it.
#[derive(Debug, Serialize)]
struct TrainListing {
    name: String,
    axles: Vec<AxleListing>,
    length: f64,
}

#[derive(Debug, Serialize)]
struct AxleListing {
    offset: f64,
    force: f64,
}

/// Execute `frictrack trains`.
pub fn run(args: &TrainsArgs) -> Result<()> {
    let single_force = fem_beam::reference::uic60_on_soft_soil().load;
    let Some(name) = &args.name else {
        let trains: Vec<scenario::trains::TrainSummary> = Train::catalogue()
            .iter()
            .map(|n| Train::named(n, single_force).map(|t| scenario::trains::TrainSummary::of(&t)))
            .collect::<Result<_, _>>()
            .map_err(scenario::StudyError::from)?;
        match args.format {
            Format::Json => println!("{}", serde_json::to_string_pretty(&trains)?),
            Format::Text => {
                println!("{:<10} {:>6} {:>11} {:>12}", "name", "axles", "length (m)", "weight (kN)");
                for t in &trains {
                    println!("{:<10} {:>6} {:>11.3} {:>12.1}", t.name, t.axles, t.length, t.total_force / 1e3);
                }
                println!("(`frictrack trains NAME` lists a train's axles; `--train NAME|FILE` runs one)");
            }
        }
        return Ok(());
    };
    let train = scenario::trains::named_or_file(name, single_force, "train")?;
    train.validate().map_err(scenario::StudyError::from)?;
    let listing = TrainListing {
        name: train.name.clone(),
        axles: train.axles.iter().map(|a| AxleListing { offset: a.offset, force: a.force }).collect(),
        length: train.length(),
    };
    match args.format {
        Format::Json => println!("{}", serde_json::to_string_pretty(&listing)?),
        Format::Text => {
            println!("{}: {} axles over {:.3} m", listing.name, listing.axles.len(), listing.length);
            println!("{:>10} {:>10}", "offset (m)", "force (kN)");
            for a in &listing.axles {
                println!("{:>10.3} {:>10.1}", a.offset, a.force / 1e3);
            }
        }
    }
    Ok(())
}
