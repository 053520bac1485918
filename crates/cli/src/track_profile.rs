//! `frictrack track-profile [SPECTRUM]`: a sample of a random rail profile (docs/theory.md §11) as CSV with its
//! periodogram against the target spectrum, a JSON summary and two figures.

use crate::Format;
use crate::files::{check_output_file, prepare_output_folder, write_atomically};
use anyhow::Result;
use clap::Args;
use irregularity::{RandomSettings, Spectrum};
use report::track_profile::{ProfileRequest, sample_profile};
use std::path::PathBuf;

/// Arguments of `frictrack track-profile`.
#[derive(Debug, Args)]
pub struct TrackProfileArgs {
    /// german-low, german-high, fra-1 … fra-6.
    #[arg(default_value = "german-low")]
    pub spectrum: String,
    /// Length of the profile (m): its period, at least the longest wavelength.
    #[arg(long, default_value_t = 1000.0)]
    pub length: f64,
    /// Sample spacing (m), at most half the shortest wavelength.
    #[arg(long, default_value_t = 0.1)]
    pub spacing: f64,
    /// Band of wavelengths SHORTEST:LONGEST (m); default the spectrum's usual band (0.5:80 German, 1.5:300 FRA).
    #[arg(long)]
    pub band: Option<String>,
    /// Seed of the random phases: the same seed gives the same profile on every machine.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Output folder: track-profile.csv (x, r in m), track-profile-psd.csv, track-profile.json and the figures.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Output format of the summary on stdout.
    #[arg(long, value_enum, default_value_t)]
    pub format: Format,
}

/// The band `SHORTEST:LONGEST` in m.
fn parse_band(text: &str) -> Result<(f64, f64)> {
    let parts: Vec<&str> = text.split(':').collect();
    let numbers: Option<Vec<f64>> = parts.iter().map(|p| p.trim().parse::<f64>().ok()).collect();
    match numbers.as_deref() {
        Some(&[short, long]) => Ok((short, long)),
        _ => {
            Err(scenario::error::invalid("--band", text, "expected SHORTEST:LONGEST wavelengths in m, e.g. 0.5:80")
                .into())
        }
    }
}

/// Execute `frictrack track-profile`.
pub fn run(args: &TrackProfileArgs) -> Result<()> {
    let spectrum = Spectrum::from_name(&args.spectrum).map_err(scenario::StudyError::from)?;
    let mut settings = RandomSettings::new(spectrum, args.length, args.seed);
    if let Some(band) = &args.band {
        settings.band = parse_band(band)?;
    }
    let request = ProfileRequest { settings, spacing: args.spacing };
    request.validate()?;
    let stem = "track-profile";
    prepare_output_folder("--out", &args.out)?;
    for name in [".csv", "-psd.csv", ".json", ".png", ".svg", "-psd.png", "-psd.svg"] {
        check_output_file("--out", &args.out.join(format!("{stem}{name}")))?;
    }
    let sample = sample_profile(request)?;
    let summary = sample.summary();
    write_atomically(&args.out.join(format!("{stem}.csv")), sample.profile_csv().as_bytes())?;
    write_atomically(&args.out.join(format!("{stem}-psd.csv")), sample.psd_csv().as_bytes())?;
    write_atomically(&args.out.join(format!("{stem}.json")), serde_json::to_string_pretty(&summary)?.as_bytes())?;
    for spec in sample.figures(stem) {
        report::plot::render(&spec, &args.out)?;
    }
    crate::print_output(&summary, args.format)?;
    if args.format == Format::Text {
        println!("  wrote {}/{stem}.csv, {stem}-psd.csv, {stem}.json and figures", args.out.display());
    }
    Ok(())
}
