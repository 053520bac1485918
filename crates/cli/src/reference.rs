//! `frictrack reference`: the reference case's static response under the load at mid-span and its lowest natural
//! frequencies, each beside its closed form (docs/theory.md §2, §8).

use crate::Format;
use anyhow::Result;
use clap::Args;
use fem_beam::LoadVector;
use fem_beam::section::Motion;
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;
use study::Scenario;

/// Options of `frictrack reference`.
#[derive(Debug, Args)]
pub struct ReferenceArgs {
    /// Scenario file (its beam, foundation, mesh, supports and load force); without it, the reference case. A
    /// scenario whose loads are a train or vehicles is refused: this checks one load at mid-span.
    scenario: Option<PathBuf>,
    /// Number of beam elements (default: the scenario's; the reference case has 200 on 200 m).
    #[arg(long, allow_negative_numbers = true)]
    elements: Option<usize>,
    /// Number of natural frequencies to report.
    #[arg(long, default_value_t = 5, allow_negative_numbers = true)]
    modes: usize,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Debug, Serialize)]
struct Mode {
    n: usize,
    omega: f64,
    omega_closed_form: f64,
}

#[derive(Debug, Serialize)]
struct ReferenceReport {
    title: String,
    length: f64,
    supports: String,
    elements: usize,
    dofs: usize,
    load: f64,
    midspan_deflection: f64,
    midspan_deflection_closed_form: f64,
    midspan_moment: f64,
    midspan_moment_closed_form: f64,
    critical_speed: f64,
    modes: Vec<Mode>,
    wall_time: f64,
}

/// Execute `frictrack reference`.
pub fn run(args: &ReferenceArgs) -> Result<()> {
    let start = Instant::now();
    let mut scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    if let Some(elements) = args.elements {
        scenario.mesh.elements = elements;
    }
    // One load at mid-span against its closed form: a train or vehicles cannot be expressed, and using the single
    // load's force instead would silently answer another question.
    let load = &scenario.load;
    let (field, value) = match (&scenario.vehicle, &load.train, load.axles.len(), load.patches.len()) {
        (Some(_), _, _, _) => ("vehicle", "given".to_string()),
        (None, Some(train), _, _) => ("load.train", train.clone()),
        (None, None, axles, _) if axles > 0 => ("load.axles", format!("{axles} axles")),
        (None, None, _, patches) if patches > 0 => ("load.patches", format!("{patches} patches")),
        _ => ("", String::new()),
    };
    if !field.is_empty() {
        return Err(study::error::invalid(
            field,
            value,
            "`frictrack reference` checks one load of [load] force at mid-span against its closed form; for this \
             scenario's loads use `frictrack analytic SCENARIO --speed V` (a train's steady state) or `frictrack run`",
        )
        .into());
    }
    let case = scenario.reference_case()?;
    let model = case.model()?;
    let inf = case.infinite_beam()?;
    let mid = case.mesh.length / 2.0;
    let load = LoadVector::point_force(&case.mesh, mid, -case.load)?;
    let q = model.static_solve(&load)?;
    let moments = model.nodal_moments(&q, &load, Motion::default())?;
    let free = model.dofs().free_len();
    if args.modes == 0 || args.modes > free {
        return Err(study::error::invalid(
            "--modes",
            args.modes,
            format!("must lie in [1, {free}], the number of free DOFs of this mesh"),
        )
        .into());
    }
    let omega = model.natural_frequencies(args.modes)?;
    let report = ReferenceReport {
        title: if scenario.title.is_empty() {
            "reference case: UIC60 rail on soft soil".into()
        } else {
            scenario.title.clone()
        },
        length: case.mesh.length,
        supports: format!("{:?}/{:?}", case.supports.left, case.supports.right).to_lowercase(),
        elements: case.mesh.elements,
        dofs: model.dofs().free_len(),
        load: case.load,
        midspan_deflection: model.deflection_at(&q, mid)?,
        midspan_deflection_closed_form: -inf.static_deflection(case.load),
        midspan_moment: moments.at(mid),
        midspan_moment_closed_form: inf.static_moment(case.load),
        critical_speed: inf.critical_speed(),
        modes: omega
            .iter()
            .enumerate()
            .map(|(i, &w)| Mode { n: i + 1, omega: w, omega_closed_form: case.pinned_natural_frequency(i + 1) })
            .collect(),
        wall_time: start.elapsed().as_secs_f64(),
    };
    match args.format {
        Format::Json => println!("{}", serde_json::to_string_pretty(&report)?),
        Format::Text => print_text(&report),
    }
    Ok(())
}

fn print_text(r: &ReferenceReport) {
    println!(
        "frictrack — {}: {} m beam ({} ends), {} elements ({} DOFs)",
        r.title, r.length, r.supports, r.elements, r.dofs
    );
    println!(
        "static load {:.1} kN at mid-span                  FE            closed form (infinite beam)",
        r.load / 1e3
    );
    println!(
        "  deflection under the load           {:>10.3} mm   {:>10.3} mm",
        r.midspan_deflection * 1e3,
        r.midspan_deflection_closed_form * 1e3
    );
    println!(
        "  bending moment under the load       {:>10.3} kN·m {:>10.3} kN·m",
        r.midspan_moment / 1e3,
        r.midspan_moment_closed_form / 1e3
    );
    println!("critical speed v_cr = {:.2} m/s ({:.0} km/h)", r.critical_speed, r.critical_speed * 3.6);
    println!("natural circular frequencies (pinned beam)     FE            closed form");
    for m in &r.modes {
        println!(
            "  ω{:<3}                               {:>10.4} rad/s {:>10.4} rad/s",
            m.n, m.omega, m.omega_closed_form
        );
    }
    println!("wall time {:.3} s", r.wall_time);
}
