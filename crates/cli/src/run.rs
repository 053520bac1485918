//! `frictrack run`: one Moreau–Jean simulation of a scenario (default: the reference case of MODEL.md §2) with flags
//! overriding it; prints max deflections, energies, solver statistics and wall time.

use crate::Format;
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use friction::ContactKind;
use nscd::Simulation;
use serde::Serialize;
use std::time::Instant;

/// Options of `frictrack run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// The JSON report of `frictrack run`. Deflections are positive magnitudes (m), relative to the self-weight state.
#[derive(Debug, Serialize)]
pub struct RunReport {
    speed: f64,
    devices: usize,
    device_positions: Vec<f64>,
    distributed_friction: f64,
    max_downward_deflection: f64,
    max_downward_deflection_position: f64,
    max_downward_deflection_time: f64,
    max_upward_deflection: f64,
    max_upward_deflection_position: f64,
    max_upward_deflection_time: f64,
    global_norm: f64,
    load_work: f64,
    friction_work: f64,
    viscous_dissipation: f64,
    dissipated_energy: f64,
    numerical_dissipation: f64,
    energy_residual: f64,
    steps: usize,
    time_step: f64,
    sections: usize,
    mean_iterations: f64,
    max_iterations: usize,
    max_residual: f64,
    mean_sections_solved: f64,
    solver: String,
    wall_time: f64,
}

/// Execute `frictrack run`.
pub fn run(args: &RunArgs) -> Result<()> {
    let start = Instant::now();
    let scenario = args.scenario.load()?;
    let case = scenario.build()?;
    let result = Simulation::new(&case.model, &case.contacts, &case.settings)?.run()?;
    let e = &result.energy;
    let s = &result.statistics;
    let device_positions: Vec<f64> = (0..case.contacts.len())
        .filter(|&j| case.contacts.kinds()[j] == ContactKind::Device)
        .map(|j| case.contacts.positions()[j])
        .collect();
    let report = RunReport {
        speed: case.settings.speed,
        devices: device_positions.len(),
        device_positions,
        distributed_friction: scenario.friction.distributed.as_ref().map_or(0.0, |d| d.force_per_length),
        max_downward_deflection: result.max_downward.magnitude,
        max_downward_deflection_position: result.max_downward.position,
        max_downward_deflection_time: result.max_downward.time,
        max_upward_deflection: result.max_upward.magnitude,
        max_upward_deflection_position: result.max_upward.position,
        max_upward_deflection_time: result.max_upward.time,
        global_norm: result.global_norm,
        load_work: e.load_work,
        friction_work: e.friction_work,
        viscous_dissipation: e.viscous_dissipation,
        dissipated_energy: e.dissipated(),
        numerical_dissipation: e.numerical_dissipation,
        energy_residual: e.residual(),
        steps: s.steps,
        time_step: result.step,
        sections: s.sections,
        mean_iterations: s.mean_iterations,
        max_iterations: s.max_iterations,
        max_residual: s.max_residual,
        mean_sections_solved: s.mean_sections_solved,
        solver: s.solver.to_string(),
        wall_time: start.elapsed().as_secs_f64(),
    };
    match args.format {
        Format::Json => println!("{}", serde_json::to_string_pretty(&report)?),
        Format::Text => print_text(&report),
    }
    Ok(())
}

fn print_text(r: &RunReport) {
    println!("frictrack run — load {:.2} m/s ({:.0} km/h)", r.speed, r.speed * 3.6);
    if r.devices > 0 {
        println!(
            "  friction devices     {} (snapped to {:?} … m)",
            r.devices,
            &r.device_positions[..r.device_positions.len().min(5)]
        );
    }
    if r.distributed_friction > 0.0 {
        println!("  distributed friction {:.1} N/m", r.distributed_friction);
    }
    println!(
        "  max downward deflection {:>9.3} mm at x = {:.1} m, t = {:.4} s",
        r.max_downward_deflection * 1e3,
        r.max_downward_deflection_position,
        r.max_downward_deflection_time
    );
    println!(
        "  max upward deflection   {:>9.3} mm at x = {:.1} m, t = {:.4} s",
        r.max_upward_deflection * 1e3,
        r.max_upward_deflection_position,
        r.max_upward_deflection_time
    );
    println!("  global norm W̄          {:>9.4} m²", r.global_norm);
    println!(
        "  energy (J): load work {:.4e}, dissipated {:.4e} (friction {:.4e}, viscous {:.4e}), numerical {:.4e}, balance residual {:.2e}",
        r.load_work,
        r.dissipated_energy,
        0.0 - r.friction_work,
        r.viscous_dissipation,
        r.numerical_dissipation,
        r.energy_residual
    );
    println!(
        "  {} steps of {:.3e} s, {} friction sections ({:.0} re-solved per step), solver {}: {:.2} iterations/step \
         (max {}), max residual {:.2e} m/s",
        r.steps,
        r.time_step,
        r.sections,
        r.mean_sections_solved,
        r.solver,
        r.mean_iterations,
        r.max_iterations,
        r.max_residual
    );
    println!("  wall time {:.3} s", r.wall_time);
}
