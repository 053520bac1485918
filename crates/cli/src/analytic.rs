//! `frictrack analytic`: the closed-form steady state of an infinite beam on a viscoelastic foundation under a
//! moving load (docs/theory.md §8), at one speed or as a dynamic-amplification curve over a speed range.

use crate::Format;
use anyhow::Result;
use clap::Args;
use scenario::SweepSection;
use scenario::{Scenario, StudyError};
use std::path::PathBuf;
use study::steady_response::SteadyResponse;
use study::steady_text::SteadyReport;

/// Options of `frictrack analytic`.
#[derive(Debug, Args)]
pub struct AnalyticArgs {
    /// Scenario file (its beam, foundation and loads: the single load or its train, as the beam carries it); without
    /// it, the reference case.
    scenario: Option<PathBuf>,
    #[command(flatten)]
    speed: SpeedChoice,
    /// Foundation damping ratio ζ = c_f / c_cr (needed > 0 at and above the critical speed); default the
    /// scenario's (0 for the reference case).
    #[arg(long, allow_negative_numbers = true)]
    damping_ratio: Option<f64>,
    /// A train (catalogue name or CSV file of offset,force) instead of the scenario's loads: its steady state is the
    /// sum of its axles' (docs/theory.md §10), extremes placed in the train's frame s = x − x_head; the axle loads
    /// as the beam carries them (`[load] carries`: one rail's half on a foundation).
    #[arg(long, value_name = "NAME|FILE")]
    train: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// One speed or a range of them, for the commands that answer per speed without running the beam (`analytic`,
/// `stationary`).
#[derive(Debug, Args)]
pub struct SpeedChoice {
    /// Load speed: m/s (`100`), or with a unit (`100m/s`, `360km/h`).
    #[arg(
        long,
        conflicts_with = "speeds",
        required_unless_present = "speeds",
        allow_negative_numbers = true,
        value_parser = scenario::units::parse_speed
    )]
    speed: Option<f64>,
    /// Speed range A:B:STEP (m/s; or all three in km/h with `A:B:STEPkm/h`), in order.
    #[arg(long, allow_negative_numbers = true)]
    speeds: Option<String>,
}

impl SpeedChoice {
    /// The speeds asked for (m/s): the range's, or the one speed.
    pub fn speeds(&self) -> Result<Vec<f64>> {
        match (&self.speeds, self.speed) {
            (Some(range), _) => parse_range(range),
            (None, Some(v)) => Ok(vec![v]),
            (None, None) => {
                Err(scenario::error::invalid("--speed", "absent", "give --speed V or --speeds A:B:STEP").into())
            }
        }
    }
}

/// Parse `A:B:STEP` (m/s, or all three in km/h with `A:B:STEPkm/h`) into the list of speeds A, A+STEP, … ≤ B
/// (inclusive up to round-off), in m/s.
pub fn parse_range(text: &str) -> Result<Vec<f64>> {
    let bad = |allowed: &str| scenario::error::invalid("--speeds", text, allowed);
    let (numbers, factor) = scenario::units::split_speed_unit(text);
    let parts: Vec<&str> = numbers.split(':').collect();
    if parts.len() != 3 {
        return Err(bad("expected A:B:STEP (m/s), e.g. 10:300:5").into());
    }
    let num = |s: &str| s.trim().parse::<f64>().map_err(|_| bad(&format!("`{s}` is not a number; expected A:B:STEP")));
    let range = SweepSection { from: num(parts[0])?, to: num(parts[1])?, step: num(parts[2])? };
    // The same checks and the same speeds as a scenario's [sweep] section.
    range.validate("--speeds").map_err(|e| match e {
        StudyError::InvalidField { path, allowed, .. } => bad(&format!("{}: {allowed}", &path["--speeds.".len()..])),
        other => other,
    })?;
    let speeds: Vec<f64> = range.speeds().into_iter().map(|v| v * factor).collect();
    scenario::speeds::check_count("--speeds", speeds.len())?;
    Ok(speeds)
}

/// Execute `frictrack analytic`.
pub fn run(args: &AnalyticArgs) -> Result<()> {
    let scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    let speeds = args.speed.speeds()?;
    let train = match &args.train {
        Some(name) => Some(scenario::trains::named_or_file(name, scenario.load.force, "--train")?),
        None => None,
    };
    let response = SteadyResponse::of(&scenario, args.damping_ratio, train, &speeds)?;
    crate::scenario_args::print_uniform_support_note(&scenario, "the closed form")?;
    for warning in response.warnings() {
        eprintln!("warning: {warning}");
    }
    crate::print_output(&SteadyReport { scenario: &scenario, response: &response }, args.format)
}
