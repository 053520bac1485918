//! Times one reference run: `cargo run --release -p track --example probe -- <case>` with case one of `none`,
//! `devices7`, `devices31`, `devices99` (10 kN each, 2 m apart), `distributed1k`, `distributed10k`, `distributed5k`
//! (default), `distributed5k-whole`, `nodal5k` (5 kN/m at one section a node, J = 1), `soil-linear`,
//! `soil-tensionless` (ζ = 5 %, 100 m/s unless a speed is given: the `soil_run` bench's runs, the tensionless soil
//! through its 800 sections), optionally followed by a step count to stop early (for instruction counts under
//! callgrind), a solver tolerance, an element count (200 m beam; default 200), a speed (m/s; default 200) and a solver
//! (`auto`, `interior-point`, …). Prints the wall time of the time loop, the solver statistics and the peak resident
//! memory of the process (VmHWM, Linux).

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{Foundation, FoundationLaw};
use track::{BallastOnBeam, Devices, DistributedFriction};
use track::{FoundationSections, PlacedInteractions};
use track::{RunSettings, Simulation};

fn main() {
    let case = std::env::args().nth(1).unwrap_or_else(|| "distributed5k".into());
    let mut reference = uic60_on_soft_soil();
    if let Some(elements) = std::env::args().nth(4).and_then(|s| s.parse().ok()) {
        reference.mesh.elements = elements;
    }
    let mut settings = RunSettings::default();
    if let Some(law) = soil_law(&case) {
        reference.foundation =
            Foundation { law, ..reference.foundation.with_damping_ratio(0.05, &reference.beam).expect("damping") };
        settings.moving.speed = 100.0;
    }
    let model = reference.model().expect("reference model");
    if let Some(t) = std::env::args().nth(3).and_then(|s| s.parse().ok()) {
        settings.integration.solver.tolerance = t;
    }
    if let Some(v) = std::env::args().nth(5).and_then(|s| s.parse().ok()) {
        settings.moving.speed = v;
    }
    if let Some(kind) = std::env::args().nth(6).and_then(|s| s.parse().ok()) {
        settings.integration.solver.kind = kind;
    }
    let interactions = match case.as_str() {
        "none" | "soil-linear" => PlacedInteractions::new(),
        "soil-tensionless" => FoundationSections::default().interactions(&model).expect("soil sections"),
        "devices7" => Devices::uniform(7, 100e3).interactions(&model).expect("devices"),
        "devices31" => Devices::uniform(31, 100e3).interactions(&model).expect("devices"),
        "devices99" => Devices::uniform(99, 10e3).interactions(&model).expect("devices"),
        "distributed1k" => DistributedFriction::new(1e3).interactions(&model).expect("friction"),
        "distributed10k" => DistributedFriction::new(10e3).interactions(&model).expect("friction"),
        "nodal5k" => DistributedFriction { subdivisions: 1, ..DistributedFriction::new(5e3) }
            .interactions(&model)
            .expect("friction"),
        "distributed5k-whole" => {
            settings.integration.solver.moving_window = false;
            DistributedFriction::new(5e3).interactions(&model).expect("friction")
        }
        _ => DistributedFriction::new(5e3).interactions(&model).expect("friction"),
    };
    let steps: usize = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(usize::MAX);
    let result = Simulation::new(&model, &interactions, &settings)
        .and_then(|s| s.run_observed(&mut |view| view.step < steps))
        .expect("run");
    let s = &result.statistics;
    println!(
        "{case}: max down {:.6} m, solver {}, {:.2} iterations/step (max {}), {:.0} of {} sections re-solved per step, loop {:.3} s",
        result.deflection.max_downward.value,
        s.solver_name(),
        s.mean_iterations,
        s.max_iterations,
        s.mean_sections_solved,
        s.sections,
        s.wall_time
    );
    println!(
        "work a step: {:.3} factorisations (max {}), {:.3} solves",
        s.work.mean_factorisations, s.work.max_factorisations, s.work.mean_solves
    );
    println!(
        "bits: max down {:.17e}, max up {:.17e}, friction work {:.17e} J",
        result.deflection.max_downward.value, result.deflection.max_upward.value, result.energy.friction_work
    );
    let peak = std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|t| t.lines().find(|l| l.starts_with("VmHWM:")).map(|l| l["VmHWM:".len()..].trim().to_string()));
    println!("peak resident memory: {}", peak.unwrap_or_else(|| "unknown".into()));
}

/// The soil law of the `soil-…` cases.
fn soil_law(case: &str) -> Option<FoundationLaw> {
    match case {
        "soil-linear" => Some(FoundationLaw::Linear),
        "soil-tensionless" => Some(FoundationLaw::Tensionless),
        _ => None,
    }
}
