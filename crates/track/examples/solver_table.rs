//! Per configuration and per friction solver: iterations per step and wall time per step of the reference run
//! (200 elements, v = 200 m/s, θ = ½, the default tolerance), as a Markdown table for BENCHMARKS.md.
//!
//! `cargo run --release -p track --example solver_table -- [steps]` (default: the whole 2000-step run). A solver
//! that fails a step (unconverged within its iteration cap) is reported with the step where it stopped.

use analytic::reference::uic60_on_soft_soil;
use nscd::SolverKind;
use track::PlacedInteractions;
use track::{BallastOnBeam, Devices, DistributedFriction};
use track::{RunSettings, Simulation};

fn main() {
    let steps: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(usize::MAX);
    let model = uic60_on_soft_soil().model().expect("reference model");
    let cases: Vec<(&str, PlacedInteractions)> = vec![
        ("7 devices, F_u = 100 kN", Devices::uniform(7, 100e3).interactions(&model).expect("devices")),
        ("31 devices, F_u = 100 kN", Devices::uniform(31, 100e3).interactions(&model).expect("devices")),
        ("distributed, f_u = 1 kN/m", DistributedFriction::new(1e3).interactions(&model).expect("friction")),
        ("distributed, f_u = 5 kN/m", DistributedFriction::new(5e3).interactions(&model).expect("friction")),
        ("distributed, f_u = 10 kN/m", DistributedFriction::new(10e3).interactions(&model).expect("friction")),
    ];
    let mut solvers = vec![SolverKind::Auto, SolverKind::Projection, SolverKind::InteriorPoint];
    if cfg!(feature = "clarabel") {
        solvers.push(SolverKind::Clarabel);
    }
    println!("| configuration | solver | iterations per step (mean / max) | sections per step | time per step |");
    println!("|---|---|---|---|---|");
    for (name, interactions) in &cases {
        for &kind in &solvers {
            let mut settings = RunSettings::default();
            settings.integration.solver.kind = kind;
            // Projection on dense sections: cap the sweeps so that a stall shows in seconds, not hours.
            settings.integration.solver.max_iterations = 2_000;
            let outcome = Simulation::new(&model, interactions, &settings)
                .and_then(|s| s.run_observed(&mut |view| view.step < steps));
            let label = match kind {
                SolverKind::Auto => format!("auto ({})", outcome.as_ref().map_or("—", |r| r.statistics.solver_name())),
                other => other.name().to_string(),
            };
            match outcome {
                Ok(result) => {
                    let s = &result.statistics;
                    println!(
                        "| {name} | {label} | {:.2} / {} | {:.0} of {} | {:.2} µs |",
                        s.mean_iterations,
                        s.max_iterations,
                        s.mean_sections_solved,
                        s.sections,
                        1e6 * s.wall_time / s.steps as f64
                    );
                }
                Err(error) => println!("| {name} | {label} | failed: {error} | | |"),
            }
        }
    }
}
