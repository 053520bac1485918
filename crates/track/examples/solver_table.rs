//! Per configuration and per friction solver: iterations, banded factorisations and solves a step, and wall time a
//! step of the reference run (200 elements, v = 200 m/s, θ = ½, the default tolerance; the soil cases at 100 m/s and
//! ζ = 5 %, as the `soil_run` bench), as a Markdown table for BENCHMARKS.md. The probe case each row matches is
//! named, for its instruction count (`probe CASE 100000 x x x SOLVER` under callgrind).
//!
//! `cargo run --release -p track --example solver_table [--features clarabel] -- [steps]` (default: the whole
//! 2000-step run). A solver that fails a step (unconverged within its iteration cap, or a law it does not take) is
//! reported with its error.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{Foundation, FoundationLaw};
use nscd::SolverKind;
use track::{BallastOnBeam, Devices, DistributedFriction, FoundationSections};
use track::{PlacedInteractions, RunSettings, Simulation};

/// One configuration: its label, the probe case it matches, whether it sits on a tensionless soil, and its
/// interactions on the model.
struct Case {
    label: &'static str,
    probe: &'static str,
    soil: bool,
    interactions: fn(&fem_beam::BeamModel) -> PlacedInteractions,
}

const CASES: [Case; 8] = [
    Case { label: "7 devices, F_u = 100 kN", probe: "devices7", soil: false, interactions: |m| devices(m, 7, 100e3) },
    Case {
        label: "31 devices, F_u = 100 kN",
        probe: "devices31",
        soil: false,
        interactions: |m| devices(m, 31, 100e3),
    },
    Case { label: "99 devices, F_u = 10 kN", probe: "devices99", soil: false, interactions: |m| devices(m, 99, 10e3) },
    Case {
        label: "distributed, f_u = 1 kN/m",
        probe: "distributed1k",
        soil: false,
        interactions: |m| ballast(m, 1e3, 4),
    },
    Case {
        label: "distributed, f_u = 5 kN/m",
        probe: "distributed5k",
        soil: false,
        interactions: |m| ballast(m, 5e3, 4),
    },
    Case {
        label: "distributed, f_u = 10 kN/m",
        probe: "distributed10k",
        soil: false,
        interactions: |m| ballast(m, 10e3, 4),
    },
    Case {
        label: "5 kN/m, one section a node (J = 1)",
        probe: "nodal5k",
        soil: false,
        interactions: |m| ballast(m, 5e3, 1),
    },
    Case {
        label: "tensionless soil, 800 sections",
        probe: "soil-tensionless",
        soil: true,
        interactions: |m| FoundationSections::default().interactions(m).expect("soil sections"),
    },
];

fn devices(model: &fem_beam::BeamModel, count: usize, capacity: f64) -> PlacedInteractions {
    Devices::uniform(count, capacity).interactions(model).expect("devices")
}

fn ballast(model: &fem_beam::BeamModel, force_per_length: f64, subdivisions: usize) -> PlacedInteractions {
    DistributedFriction { subdivisions, ..DistributedFriction::new(force_per_length) }
        .interactions(model)
        .expect("friction")
}

fn main() {
    let steps: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(usize::MAX);
    let mut solvers = vec![SolverKind::Auto, SolverKind::Projection, SolverKind::InteriorPoint, SolverKind::Homotopy];
    if cfg!(feature = "clarabel") {
        solvers.push(SolverKind::Clarabel);
    }
    println!(
        "| configuration (probe case) | solver | iterations a step (mean / max) | factorisations a step (mean / max) \
         | banded solves a step | time a step |"
    );
    println!("|---|---|---|---|---|---|");
    for case in &CASES {
        let mut reference = uic60_on_soft_soil();
        let mut base = RunSettings::default();
        if case.soil {
            let damped = reference.foundation.with_damping_ratio(0.05, &reference.beam).expect("damping");
            reference.foundation = Foundation { law: FoundationLaw::Tensionless, ..damped };
            base.moving.speed = 100.0;
        }
        let model = reference.model().expect("reference model");
        let interactions = (case.interactions)(&model);
        for &kind in &solvers {
            let mut settings = base.clone();
            settings.integration.solver.kind = kind;
            // Projection on dense sections: cap the sweeps so that a stall shows in seconds, not hours.
            settings.integration.solver.max_iterations = 2_000;
            let outcome = Simulation::new(&model, &interactions, &settings)
                .and_then(|s| s.run_observed(&mut |view| view.step < steps));
            let label = match kind {
                SolverKind::Auto => format!("auto ({})", outcome.as_ref().map_or("—", |r| r.statistics.solver_name())),
                other => other.name().to_string(),
            };
            let name = format!("{} (`{}`)", case.label, case.probe);
            match outcome {
                Ok(result) => {
                    let s = &result.statistics;
                    println!(
                        "| {name} | {label} | {:.2} / {} | {:.2} / {} | {:.2} | {:.2} µs |",
                        s.mean_iterations,
                        s.max_iterations,
                        s.work.mean_factorisations,
                        s.work.max_factorisations,
                        s.work.mean_solves,
                        1e6 * s.wall_time / s.steps as f64
                    );
                }
                Err(error) => println!("| {name} | {label} | failed: {} | | | |", first_sentence(&error.to_string())),
            }
        }
    }
}

/// An error's first sentence (up to its first colon after the step), to keep the table's rows short.
fn first_sentence(message: &str) -> &str {
    message.split("; ").next().unwrap_or(message)
}
