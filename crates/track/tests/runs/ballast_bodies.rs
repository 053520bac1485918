//! Runs on sleepers over ballast bodies (Zhai's two layers, docs/theory.md §18): the energy identity with voided,
//! tensionless and frictional sleepers whose laws act between sleeper and ballast mass (u = z − y); Clarabel on the
//! same; a body on a rigid subgrade is the one-layer track, voids and all.

use super::sleepers::{clarabel_agrees_on, exception, on_sleepers, run, settings, voided, voided_and_frictional};
use fem_beam::{BallastBody, Layer, SleeperException, Sleepers};

/// Zhai's values per rail seat: ballast 180 MN/m on a ballast mass of 500 kg on the typical subgrade.
fn two_layers(exceptions: Vec<SleeperException>) -> Sleepers {
    let typical = Sleepers::default();
    Sleepers {
        ballast: Layer { stiffness: 180e6, damping: 60e3, ..typical.ballast },
        ballast_body: Some(BallastBody { mass: 500.0, subgrade: BallastBody::TYPICAL_SUBGRADE }),
        exceptions,
        ..typical
    }
}

/// Voids, tensionless ballast everywhere and friction at twenty sleepers over ballast bodies, θ = ½ and 0.6: the
/// identity closes to 1e-9 of the load's work (the interior point's tolerance, as on one layer; measured 8e-15 and
/// 5e-14); the subgrade carries the load (33 kN under a sleeper next to the one under the 83.4 kN load).
#[test]
fn energy_closes_over_ballast_bodies() {
    // The later exception decides: the voided sleepers have no friction.
    let all = vec![voided(0, 99, 0.0), SleeperException { friction: 2e3, ..exception(40, 60) }, voided(49, 50, 1e-3)];
    for theta in [0.5, 0.6] {
        let model = on_sleepers(60.0, 400, two_layers(all.clone()));
        let r = run(&model, &settings(50.0, theta, 0.0375));
        let e = r.energy;
        assert!(e.load_work > 0.0 && e.friction_work < 0.0 && e.support_work != 0.0, "{e:?}");
        assert!(e.residual().abs() <= 1e-9 * e.load_work, "θ = {theta}: {:e}", e.residual());
        let sleepers = r.sleepers.unwrap();
        let middle = &sleepers.sleepers[44];
        let (subgrade, _) = middle.subgrade_force.expect("a ballast body has a subgrade force");
        assert!(subgrade > 0.1 * 83.4e3 && subgrade < 83.4e3, "{middle:?}");
        let voided = &sleepers.sleepers[49];
        assert!(voided.first_contact.is_some() && voided.largest_gap.unwrap() >= 1e-3, "{voided:?}");
    }
}

/// The interior point and Clarabel on voided and frictional sleepers over ballast bodies, both at 1e-10: the same
/// peak, final state and friction work to 1e-8 (measured 2e-12, 3e-9, 1e-10).
#[test]
fn clarabel_agrees_over_ballast_bodies() {
    clarabel_agrees_on(two_layers(voided_and_frictional()));
}

/// A ballast body of 1 g on a subgrade 10⁵ times stiffer than the ballast is the ballast on rigid ground: a run over
/// two voided sleepers and ten frictional ones matches the one-layer run's peak, final rail deflection and the voided
/// sleeper's forces to 1e-4 (the subgrade's share of the ballast's compliance is 1e-5; measured 3e-6 on the peak,
/// 1.3e-5 on the final state by the voided sleepers, where friction holds the track where it stuck).
#[test]
fn a_body_on_a_rigid_subgrade_is_the_one_layer_track_in_time() {
    let exceptions = vec![SleeperException { friction: 2e3, ..exception(45, 55) }, voided(49, 50, 0.5e-3)];
    let one = Sleepers { exceptions: exceptions.clone(), ..Sleepers::default() };
    let rigid = BallastBody { mass: 1e-3, subgrade: Layer { stiffness: 1e13, damping: 0.0, loss_factor: 0.0 } };
    let two = Sleepers { ballast_body: Some(rigid), ..one.clone() };
    let s = settings(50.0, 0.5, 0.0375);
    let (model_a, model_b) = (on_sleepers(60.0, 400, one), on_sleepers(60.0, 400, two));
    let (a, b) = (run(&model_a, &s), run(&model_b, &s));
    let close = |x: f64, y: f64, scale: f64| (x - y).abs() <= 1e-4 * scale;
    let peak = a.deflection.max_downward.value;
    assert!(close(peak, b.deflection.max_downward.value, peak), "peak {peak} vs {}", b.deflection.max_downward.value);
    for x in (1..12).map(|i| 5.0 * i as f64) {
        let w = |model: &fem_beam::BeamModel, q: &[f64]| model.deflection_at(&model.dofs().expand(q), x).unwrap();
        let (wa, wb) = (w(&model_a, &a.final_displacement), w(&model_b, &b.final_displacement));
        assert!(close(wa, wb, peak), "x = {x}: {wa} vs {wb}");
    }
    let (pa, pb) = (&a.sleepers.unwrap().sleepers[49], &b.sleepers.unwrap().sleepers[49]);
    assert!(pa.first_contact.is_some(), "the void must close: {pa:?}");
    assert!(close(pa.ballast_force.0, pb.ballast_force.0, pa.ballast_force.0), "{pa:?} vs {pb:?}");
    assert!(close(pa.lowest, pb.lowest, pa.lowest), "{pa:?} vs {pb:?}");
}
