//! Scratch probe.
use fem_beam::reference::uic60_on_soft_soil;
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::{RunSettings, Simulation, SolverKind};

fn main() {
    let case = uic60_on_soft_soil();
    let model = case.model().unwrap();
    let cases: Vec<(&str, ContactSet, SolverKind)> = vec![
        ("none", ContactSet::new(), SolverKind::Auto),
        ("dist 5k only", DistributedFriction::new(5e3).contact_set(&model).unwrap(), SolverKind::InteriorPoint),
        ("31 dev", Devices::uniform(31, 100e3).contact_set(&model).unwrap(), SolverKind::Auto),
        ("31 dev newton", Devices::uniform(31, 100e3).contact_set(&model).unwrap(), SolverKind::InteriorPoint),
        ("dist 1k", DistributedFriction::new(1e3).contact_set(&model).unwrap(), SolverKind::InteriorPoint),
        ("dist 5k", DistributedFriction::new(5e3).contact_set(&model).unwrap(), SolverKind::InteriorPoint),
        ("dist 10k", DistributedFriction::new(10e3).contact_set(&model).unwrap(), SolverKind::InteriorPoint),
    ];
    for (name, contacts, kind) in cases {
        let mut s = RunSettings::default();
        s.solver.kind = kind;

        let t = std::time::Instant::now();
        match Simulation::new(&model, &contacts, &s).unwrap().run() {
            Ok(r) => println!(
                "{name:>14}: down {:.5} up {:.5} solver {} mean it {:.2} max it {} res {:.2e} loop {:.3}s total {:.3}s  E resid {:.2e} load {:.3e} fric {:.3e} num {:.3e}",
                r.max_downward.magnitude,
                r.max_upward.magnitude,
                r.statistics.solver,
                r.statistics.mean_iterations,
                r.statistics.max_iterations,
                r.statistics.max_residual,
                r.statistics.wall_time,
                t.elapsed().as_secs_f64(),
                r.energy.residual(),
                r.energy.load_work,
                r.energy.friction_work,
                r.energy.numerical_dissipation
            ),
            Err(e) => println!("{name}: error {e}"),
        }
    }
}
