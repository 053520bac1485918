//! `frictrack run`: one Moreau–Jean simulation of the reference case (MODEL.md §2–§6) with the chosen speed,
//! friction and integration settings; prints max deflections, energies, solver statistics and wall time.

use crate::Format;
use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use fem_beam::reference::uic60_on_soft_soil;
use fem_beam::{AbsorbingZones, BeamModel, Mesh};
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::{InitialState, RunSettings, Simulation, SolverKind};
use serde::Serialize;
use std::time::Instant;

/// Friction solver choice on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SolverChoice {
    /// Projection for sparse devices, interior point for dense sections.
    Auto,
    /// Projected (nonsmooth) Gauss–Seidel.
    Projection,
    /// Banded primal–dual interior point.
    InteriorPoint,
    /// Clarabel QP (cross-check; slow for many sections).
    Clarabel,
}

impl From<SolverChoice> for SolverKind {
    fn from(choice: SolverChoice) -> Self {
        match choice {
            SolverChoice::Auto => SolverKind::Auto,
            SolverChoice::Projection => SolverKind::Projection,
            SolverChoice::InteriorPoint => SolverKind::InteriorPoint,
            SolverChoice::Clarabel => SolverKind::Clarabel,
        }
    }
}

/// Options of `frictrack run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// Load speed (m/s).
    #[arg(long, default_value_t = 200.0)]
    speed: f64,
    /// Number of friction devices, evenly spaced at i·L/(N+1) and snapped to nodes.
    #[arg(long, default_value_t = 0)]
    devices: usize,
    /// Maximal force of one device F_u (N).
    #[arg(long, default_value_t = 100e3)]
    device_force: f64,
    /// Distributed friction f_u (N/m).
    #[arg(long, default_value_t = 0.0)]
    distributed_friction: f64,
    /// Foundation damping ratio ζ = c_f/c_cr.
    #[arg(long, default_value_t = 0.0)]
    damping_ratio: f64,
    /// θ of the Moreau–Jean scheme, in [0.5, 1].
    #[arg(long, default_value_t = 0.5)]
    theta: f64,
    /// Number of beam elements on the 200 m beam.
    #[arg(long, default_value_t = 200)]
    elements: usize,
    /// Load advance per time step (m): h = advance / speed.
    #[arg(long, default_value_t = 0.1)]
    load_advance: f64,
    /// Friction solver.
    #[arg(long, value_enum, default_value_t = SolverChoice::Auto)]
    solver: SolverChoice,
    /// Relative tolerance of the friction solver.
    #[arg(long, default_value_t = 1e-10)]
    tolerance: f64,
    /// Start from the analytic steady state with the load at this position (m) instead of at rest.
    #[arg(long)]
    steady_start: Option<f64>,
    /// Absorbing end zones of this length (m), foundation damping graded up to c_cr.
    #[arg(long)]
    absorbing_zones: Option<f64>,
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
    let mut case = uic60_on_soft_soil();
    case.mesh = Mesh::new(case.mesh.length, args.elements)?;
    let foundation = case.foundation.with_damping_ratio(args.damping_ratio, &case.beam)?;
    let damping = match args.absorbing_zones {
        Some(length) => AbsorbingZones { length, peak_damping: foundation.critical_damping(&case.beam) }
            .element_damping(&case.mesh, foundation.damping)?,
        None => vec![foundation.damping; case.mesh.elements],
    };
    let model = BeamModel::with_element_damping(case.beam, foundation, case.mesh, case.supports, damping)?;
    let mut contacts = ContactSet::new();
    if args.devices > 0 {
        contacts.extend(Devices::uniform(args.devices, args.device_force).contact_set(&model)?);
    }
    if !(args.distributed_friction.is_finite() && args.distributed_friction >= 0.0) {
        bail!(friction::FrictionError::InvalidField {
            field: "distributed-friction",
            value: args.distributed_friction,
            allowed: "must be finite and ≥ 0 (N/m)".into(),
        });
    }
    if args.distributed_friction > 0.0 {
        contacts.extend(DistributedFriction::new(args.distributed_friction).contact_set(&model)?);
    }
    let mut settings = RunSettings {
        speed: args.speed,
        load: case.load,
        theta: args.theta,
        load_advance: args.load_advance,
        ..RunSettings::default()
    };
    settings.solver.kind = args.solver.into();
    settings.solver.tolerance = args.tolerance;
    if let Some(position) = args.steady_start {
        settings.initial = InitialState::SteadyState { position };
    }
    let result = Simulation::new(&model, &contacts, &settings)?.run()?;
    let e = &result.energy;
    let s = &result.statistics;
    let device_positions = if args.devices > 0 {
        Devices::uniform(args.devices, args.device_force).snapped_positions(&model)?
    } else {
        Vec::new()
    };
    let report = RunReport {
        speed: args.speed,
        devices: args.devices,
        device_positions,
        distributed_friction: args.distributed_friction,
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
    println!("frictrack run — reference beam, load {:.2} m/s ({:.0} km/h)", r.speed, r.speed * 3.6);
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
