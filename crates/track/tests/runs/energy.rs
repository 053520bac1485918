//! The discrete energy identity (docs/theory.md §6) closes to round-off for any θ and any friction.

use super::common::beam;
use track::PlacedInteractions;
use track::{BallastOnBeam, Devices, DistributedFriction};
use track::{RunSettings, Simulation};

#[test]
fn energy_balance_closes() {
    let model = beam(60.0, 60);
    let sets = [
        ("linear", PlacedInteractions::new()),
        ("31 devices", Devices::uniform(31, 50e3).interactions(&model).unwrap()),
        ("distributed", DistributedFriction::new(2e3).interactions(&model).unwrap()),
    ];
    for theta in [0.5, 0.6] {
        for (name, interactions) in &sets {
            let settings = {
                let mut s = RunSettings::default();
                s.integration.theta = theta;
                s.moving.speed = 180.0;
                s.integration.load_advance = 0.2;
                s
            };
            let r = Simulation::new(&model, interactions, &settings).unwrap().run().unwrap();
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
            if interactions.is_empty() {
                assert_eq!(e.friction_work, 0.0);
            } else {
                // Friction removes energy over the run.
                assert!(e.friction_work < 0.0 && e.dissipated() > 0.0, "{name}: {e:?}");
            }
        }
    }
}

/// A run may continue after the load has left (free vibration): the extra steps are taken, the load does no more
/// work, friction keeps dissipating and the balance still closes.
#[test]
fn free_vibration_after_the_load_leaves() {
    let model = beam(60.0, 60);
    let interactions = Devices::uniform(7, 20e3).interactions(&model).unwrap();
    let base = {
        let mut s = RunSettings::default();
        s.moving.speed = 150.0;
        s.integration.load_advance = 0.2;
        s
    };
    let t_on = 60.0 / 150.0;
    let crossing = Simulation::new(&model, &interactions, &base).unwrap().run().unwrap();
    let longer = {
        let mut s = base.clone();
        s.integration.end_time = Some(1.5 * t_on);
        s
    };
    let after = Simulation::new(&model, &interactions, &longer).unwrap().run().unwrap();
    assert_eq!(crossing.statistics.steps, 300);
    assert_eq!(after.statistics.steps, 450);
    assert!((after.energy.load_work - crossing.energy.load_work).abs() <= 1e-12 * crossing.energy.load_work);
    assert!(after.energy.dissipated() > crossing.energy.dissipated());
    assert!(after.energy.residual().abs() <= 1e-9 * after.energy.load_work);
    // W̄ integrates over the crossing only.
    assert_eq!(after.global_norm, crossing.global_norm);
    let too_early = {
        let mut s = base;
        s.integration.end_time = Some(0.5 * t_on);
        s
    };
    assert!(Simulation::new(&model, &interactions, &too_early).is_err());
}
