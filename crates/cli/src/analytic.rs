//! `frictrack analytic`: the closed-form steady state of an infinite beam on a viscoelastic foundation under a
//! moving load (docs/theory.md §8), at one speed or as a dynamic-amplification curve over a speed range.

use crate::Format;
use anyhow::Result;
use clap::Args;
use fem_beam::reference::InfiniteBeam;
use serde::Serialize;
use std::path::PathBuf;
use study::scenario::SweepSection;
use study::{Scenario, StudyError};

/// Options of `frictrack analytic`.
#[derive(Debug, Args)]
pub struct AnalyticArgs {
    /// Scenario file (its beam, foundation and loads: the single load or its train, as the beam carries it); without
    /// it, the reference case.
    scenario: Option<PathBuf>,
    /// Load speed: m/s (`100`), or with a unit (`100m/s`, `360km/h`).
    #[arg(
        long,
        conflicts_with = "speeds",
        required_unless_present = "speeds",
        allow_negative_numbers = true,
        value_parser = crate::units::parse_speed
    )]
    speed: Option<f64>,
    /// Speed range A:B:STEP (m/s) for a dynamic-amplification curve.
    #[arg(long, allow_negative_numbers = true)]
    speeds: Option<String>,
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

#[derive(Debug, Serialize)]
struct Point {
    speed: f64,
    max_downward_deflection: f64,
    max_downward_position: f64,
    max_upward_deflection: f64,
    max_upward_position: f64,
    amplification_downward: f64,
    amplification_upward: f64,
}

/// Parse `A:B:STEP` (m/s, or all three in km/h with `A:B:STEPkm/h`) into the list of speeds A, A+STEP, … ≤ B
/// (inclusive up to round-off), in m/s.
pub fn parse_range(text: &str) -> Result<Vec<f64>> {
    let bad = |allowed: &str| study::error::invalid("--speeds", text, allowed);
    let (numbers, factor) = crate::units::split_speed_unit(text);
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
    if speeds.len() > 1_000_000 {
        return Err(bad(&format!("gives {} speeds, at most 1 000 000 allowed", speeds.len())).into());
    }
    Ok(speeds)
}

/// Execute `frictrack analytic`.
pub fn run(args: &AnalyticArgs) -> Result<()> {
    let scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    let case = scenario.reference_case()?;
    let foundation = match args.damping_ratio {
        Some(ratio) => case.foundation.with_damping_ratio(ratio, &case.beam)?,
        None => case.foundation,
    };
    let inf = InfiniteBeam::new(&case.beam, &foundation)?;
    let speeds = match (&args.speeds, args.speed) {
        (Some(range), _) => parse_range(range)?,
        (None, Some(v)) => vec![v],
        (None, None) => {
            return Err(study::error::invalid("--speed", "absent", "give --speed V or --speeds A:B:STEP").into());
        }
    };
    if scenario.vehicle.is_some() {
        return Err(study::error::invalid(
            "vehicle",
            "given",
            "the closed-form steady state takes moving forces, not vehicles: drop [vehicle] (the train's axles, or the \
             single load, are used) or use `frictrack run`",
        )
        .into());
    }
    // The scenario's train (or --train), as the beam carries it; None for the single load.
    let train = match &args.train {
        Some(name) => Some(study::trains::named_or_file(name, case.load, "--train")?),
        None => study::trains::resolve(&scenario.load)?,
    }
    .map(|t| scenario.on_the_beam(t));
    if let Some(t) = train.as_ref().filter(|t| !t.patches.is_empty()) {
        return Err(study::error::invalid(
            "load.patches",
            t.patches.len(),
            "the closed-form steady state takes axles only: give the train as axles, or use `frictrack run`",
        )
        .into());
    }
    let extremes = |v: f64| -> Result<fem_beam::reference::SteadyExtremes> {
        Ok(match &train {
            Some(t) => inf.train_steady_state(v, t)?.extremes(),
            None => inf.steady_state(v, case.load)?.extremes(),
        })
    };
    // The static response of the same load (v = 0): a train's superposed static shapes.
    let w0 = match &train {
        Some(_) => extremes(0.0)?.max_downward.magnitude,
        None => inf.static_deflection(case.load),
    };
    let mut points = Vec::with_capacity(speeds.len());
    for v in speeds {
        let e = extremes(v)?;
        points.push(Point {
            speed: v,
            max_downward_deflection: e.max_downward.magnitude,
            max_downward_position: e.max_downward.position,
            max_upward_deflection: e.max_upward.magnitude,
            max_upward_position: e.max_upward.position,
            amplification_downward: e.max_downward.magnitude / w0,
            amplification_upward: e.max_upward.magnitude / w0,
        });
    }
    match (args.format, points.len()) {
        (Format::Json, 1) => println!("{}", serde_json::to_string_pretty(&points[0])?),
        (Format::Json, _) => println!("{}", serde_json::to_string_pretty(&points)?),
        (Format::Text, _) => {
            println!(
                "infinite beam{}, EI = {:.4} MN·m², ρA = {:.3} kg/m, k_f = {:.1} kN/m², {}, ζ = {:.4}, \
                 v_cr = {:.2} m/s, static w₀ = {:.2} mm",
                if scenario.title.is_empty() { String::new() } else { format!(" ({})", scenario.title) },
                case.beam.bending_stiffness() / 1e6,
                case.beam.mass_per_length(),
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
                    None => format!("F = {:.1} kN", case.load / 1e3),
                },
                foundation.damping / inf.critical_damping(),
                inf.critical_speed(),
                w0 * 1e3
            );
            println!("  speed (m/s)  max down (mm)  at s (m)  max up (mm)  at s (m)   DAF down  DAF up");
            for p in &points {
                println!(
                    "  {:>10.2}  {:>13.3}  {:>8.2}  {:>11.3}  {:>8.2}  {:>8.3}  {:>6.3}",
                    p.speed,
                    p.max_downward_deflection * 1e3,
                    p.max_downward_position,
                    p.max_upward_deflection * 1e3,
                    p.max_upward_position,
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
