//! The track's weight on sleepers (docs/theory.md §18): settled under it, ballast that cannot pull is pressed by its
//! share of the rail's and sleepers' weight — a light load that would lift weightless sleepers off it leaves the
//! weighted track the bonded one —, a void keeps the gap it is measured with in the settled state, and the energy
//! identity still closes with the weight's preload.

use super::sleepers::{exception, on_sleepers, run, settings, voided};
use fem_beam::Train;
use fem_beam::{BeamModel, SleeperException, Sleepers};
use friction::Law;
use track::sleeper_layout::sleeper_interactions;
use track::unilateral_statics::settle;
use track::{Load, PlacedInteractions, RunResult, RunSettings, Simulation};

fn weighted(model: &BeamModel) -> PlacedInteractions {
    settle(model, sleeper_interactions(model), &model.self_weight().unwrap()).unwrap().0
}

fn run_with(model: &BeamModel, placed: &PlacedInteractions, s: &RunSettings) -> RunResult {
    Simulation::new(model, placed, s).unwrap().run().unwrap()
}

/// A 20 kN load at 50 m/s over sleepers whose ballast cannot pull: settled under the track's weight (1.8 kN a
/// sleeper: 0.6 m of rail and 150 kg) each sleeper keeps pressing — the bonded track's ballast never pulls harder
/// than that here — and the run is the bonded one to the solver's tolerance (1e-6); weightless, the sleepers ahead
/// of the load lift off and the run is not.
#[test]
fn the_weight_keeps_a_light_load_from_lifting_tensionless_sleepers() {
    let mut s = settings(50.0, 0.5, 0.0375);
    s.moving.load = Load::Train(Train::single(20e3));
    let bonded = run(&on_sleepers(60.0, 400, Sleepers::default()), &s);
    let model = on_sleepers(60.0, 400, Sleepers { exceptions: vec![voided(0, 99, 0.0)], ..Sleepers::default() });
    let (heavy, light) = (run_with(&model, &weighted(&model), &s), run_with(&model, &sleeper_interactions(&model), &s));
    let difference =
        |r: &RunResult| super::common::relative_difference(&r.final_displacement, &bonded.final_displacement);
    let peak = |r: &RunResult| (r.deflection.max_downward.value / bonded.deflection.max_downward.value - 1.0).abs();
    let lifted =
        |r: &RunResult| r.sleepers.as_ref().unwrap().sleepers.iter().filter(|p| p.largest_gap > Some(0.0)).count();
    assert_eq!(lifted(&heavy), 0, "the weight must hold every sleeper down");
    assert!(difference(&heavy) <= 1e-6 && peak(&heavy) <= 1e-6, "{:e} {:e}", difference(&heavy), peak(&heavy));
    assert!(lifted(&light) > 10, "weightless, the sleepers ahead lift: {}", lifted(&light));
    assert!(peak(&light) > 1e-3, "{:e}", peak(&light));
}

/// Settled under its weight, a voided sleeper keeps the gap it was given (measured in the settled state: it hangs,
/// carrying nothing), its tensionless neighbours are pressed (negative gaps, the weight's share over their
/// stiffness), and the energy identity closes to 1e-9 of the load's work with voids, tensionless ballast, friction
/// and the weight's preload.
#[test]
fn a_settled_void_keeps_its_gap_and_the_energy_closes() {
    let exceptions =
        vec![voided(0, 99, 0.0), SleeperException { friction: 2e3, ..exception(40, 60) }, voided(49, 50, 1e-3)];
    let model = on_sleepers(60.0, 400, Sleepers { exceptions, ..Sleepers::default() });
    let placed = weighted(&model);
    let gaps: Vec<f64> = placed
        .interactions()
        .laws()
        .iter()
        .filter_map(|l| match l {
            Law::Soil { gap, .. } => Some(*gap),
            _ => None,
        })
        .collect();
    assert_eq!(gaps.iter().filter(|&&g| g == 1e-3).count(), 2, "the voids keep their gaps");
    // The rest press with their share of the weight, (0.6 m × ρA + 150 kg)·g over k_b = 100 MN/m.
    let share = (0.6 * model.beam().mass_per_length() + 150.0) * fem_beam::GRAVITY / 100e6;
    let pressed: Vec<f64> = gaps.iter().copied().filter(|&g| g < 0.0).collect();
    // The 79 tensionless ones (40–60 are bonded with friction, 49–50 voided); all but those near the pinned ends
    // and beside the hanging sleepers carry their share to 1 % (measured: 69 of them).
    let carrying = pressed.iter().filter(|&&g| (-g / share - 1.0).abs() < 0.01).count();
    assert!(pressed.len() == 79 && carrying >= 65, "{carrying} of {}: {pressed:?}", pressed.len());
    for theta in [0.5, 0.6] {
        let e = run_with(&model, &placed, &settings(50.0, theta, 0.0375)).energy;
        assert!(e.residual().abs() <= 1e-9 * e.load_work, "θ = {theta}: {:e}", e.residual());
    }
}
