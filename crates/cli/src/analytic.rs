//! `frictrack analytic`: the closed-form steady state of an infinite beam on a viscoelastic foundation under a
//! moving load (docs/theory.md §8), at one speed or as a dynamic-amplification curve over a speed range.

use crate::Format;
use anyhow::Result;
use clap::Args;
use scenario::SweepSection;
use scenario::{Scenario, StudyError};
use std::path::PathBuf;
use study::steady_response::SteadyResponse;

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
    for warning in response.warnings() {
        eprintln!("warning: {warning}");
    }
    let (points, train, inf, foundation) = (&response.points, &response.train, &response.beam, &response.foundation);
    let w0 = response.static_deflection;
    match (args.format, points.len()) {
        (Format::Json, 1) => println!("{}", serde_json::to_string_pretty(&points[0])?),
        (Format::Json, _) => println!("{}", serde_json::to_string_pretty(&points)?),
        (Format::Text, _) => {
            println!(
                "infinite beam{}, EI = {:.4} MN·m², ρA = {:.3} kg/m, k_f = {:.1} kN/m², {}, ζ = {:.4}, \
                 v_cr = {:.2} m/s, static w₀ = {:.2} mm",
                if scenario.title.is_empty() { String::new() } else { format!(" ({})", scenario.title) },
                scenario.beam.bending_stiffness() / 1e6,
                scenario.beam.mass_per_length(),
                foundation.stiffness / 1e3,
                match &train {
                    Some(t) => format!(
                        "train {} ({} axles, {:.3} m, {:.1} kN on the beam: {})",
                        t.name,
                        t.axles.len(),
                        t.length(),
                        t.total_force() / 1e3,
                        scenario.axle_share().describe()
                    ),
                    None => format!("F = {:.1} kN", response.load / 1e3),
                },
                foundation.damping / inf.critical_damping(),
                inf.critical_speed(),
                w0 * 1e3
            );
            println!("  speed (m/s)  max down (mm)  at s (m)  max up (mm)  at s (m)   DAF down  DAF up");
            for p in points {
                println!(
                    "  {:>10.2}  {:>13.3}  {:>8.2}  {:>11.3}  {:>8.2}  {:>8.3}  {:>6.3}",
                    p.speed,
                    p.max_downward_deflection.value * 1e3,
                    p.max_downward_deflection.position.unwrap_or(f64::NAN),
                    p.max_upward_deflection.value * 1e3,
                    p.max_upward_deflection.position.unwrap_or(f64::NAN),
                    p.amplification_downward,
                    p.amplification_upward
                );
            }
            match &train {
                Some(_) => println!("  (s = x − x_head: positive ahead of the first axle, axle i at s = −d_i)"),
                None => println!("  (s = x − vt: positive ahead of the load)"),
            }
        }
    }
    Ok(())
}
