//! The discrete energy identity (MODEL.md §6) closes to round-off for any θ and any friction.

use super::common::beam;
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::{RunSettings, Simulation};

#[test]
fn energy_balance_closes() {
    let model = beam(60.0, 60);
    let sets = [
        ("linear", ContactSet::new()),
        ("31 devices", Devices::uniform(31, 50e3).contact_set(&model).unwrap()),
        ("distributed", DistributedFriction::new(2e3).contact_set(&model).unwrap()),
    ];
    for theta in [0.5, 0.6] {
        for (name, contacts) in &sets {
            let settings = RunSettings { theta, speed: 180.0, load_advance: 0.2, ..RunSettings::default() };
            let r = Simulation::new(&model, contacts, &settings).unwrap().run().unwrap();
            let e = r.energy;
            assert!(e.load_work > 0.0);
            // Round-off of ~1e4 steps of O(1e5 J) sums: 1e-9 relative is far above it and far below any modelling term.
            assert!(
                e.residual().abs() <= 1e-9 * e.load_work,
                "{name}, θ = {theta}: residual {:e} of {:e}",
                e.residual(),
                e.load_work
            );
            assert!(e.max_step_residual <= 1e-9 * e.load_work);
            if theta == 0.5 {
                assert_eq!(e.numerical_dissipation, 0.0);
            } else {
                assert!(e.numerical_dissipation > 0.0, "{name}");
            }
            if contacts.is_empty() {
                assert_eq!(e.friction_work, 0.0);
            } else {
                // Friction removes energy over the run.
                assert!(e.friction_work < 0.0 && e.dissipated() > 0.0, "{name}: {e:?}");
            }
        }
    }
}
