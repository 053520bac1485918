//! Sections on the rail of a sleeper track — ballast friction along the rail, a tensionless soil beside the sleepers —
//! whose rows span the sleeper's DOF numbered between two rail nodes (w_i, θ_i, z_i, w_{i+1}, θ_{i+1}: four entries
//! over five DOFs). The interior point takes them inside its band (they stopped it with "cannot solve this problem"
//! under the default solver before), and gives what the independent solvers give.

use super::sleepers::{on_sleepers, settings};
use super::solvers_agree::same_state_difference;
use analytic::reference::uic60_on_soft_soil;
use fem_beam::{BeamModel, Foundation, FoundationLaw, Mesh, Sleepers};
use nscd::solver::SolverKind;
use track::sleeper_layout::sleeper_interactions;
use track::{BallastOnBeam, DistributedFriction, FoundationSections, PlacedInteractions, RunResult, Simulation};

/// Whether some row of `interactions` spans a sleeper's DOF (else the tests would not test it).
fn spans_a_sleeper(interactions: &PlacedInteractions) -> bool {
    interactions.interactions().rows().iter().any(|r| !r.is_local() && r.len() == 4)
}

/// A run at 50 m/s over the sleepers, 480 steps, with law residuals held to `tolerance` of the velocity scale.
fn run(model: &BeamModel, interactions: &PlacedInteractions, kind: SolverKind, tolerance: f64) -> RunResult {
    let mut s = settings(50.0, 0.5, 0.0375);
    s.integration.solver.kind = kind;
    s.integration.solver.tolerance = tolerance;
    Simulation::new(model, interactions, &s).unwrap().run().unwrap()
}

/// Ballast friction (2 kN/m) along the rail on sleepers: from the same state each step's velocities are Clarabel's
/// to 2e-6 relative, both asked for 1e-9 of the velocity scale, with and without the moving window. Measured 6.6e-7
/// — Clarabel's accuracy on these redundant sections from rest, not the rows': the same comparison on the
/// continuous track of this mesh (rows of four consecutive DOFs) gives 4.6e-7; a wrong Newton matrix would leave the
/// interior point unconverged (its law residual is evaluated on the rows themselves) or off by percents. Whole runs
/// drift apart through the stick–slip history (1e-4 on the peak after 480 steps), which says nothing about a step.
/// The run under `auto` is the interior point's, with banded factorisations, and closes the energy identity to 1e-9
/// of the load's work.
#[test]
fn ballast_friction_along_the_rail_of_a_sleeper_track() {
    let model = on_sleepers(18.0, 120, Sleepers::default());
    let friction = DistributedFriction { force_per_length: 2e3, ..DistributedFriction::default() };
    let interactions = friction.interactions(&model).unwrap();
    assert!(spans_a_sleeper(&interactions));
    let mut s = settings(50.0, 0.5, 0.0375);
    s.integration.solver.tolerance = 1e-9;
    for window in [true, false] {
        s.integration.solver.moving_window = window;
        let steps = (usize::MAX, 2e-6);
        same_state_difference(&model, &interactions, SolverKind::InteriorPoint, SolverKind::Clarabel, &s, steps);
    }
    let r = run(&model, &interactions, SolverKind::Auto, 1e-10);
    assert_eq!(r.statistics.solver, Some(SolverKind::InteriorPoint));
    assert!(r.statistics.work.mean_factorisations > 0.0, "the interior point solved no step");
    let e = r.energy;
    assert!(e.residual().abs() <= 1e-9 * e.load_work, "{:e} of {} J", e.residual(), e.load_work);
}

/// A tensionless soil beside the sleepers (lifting off ahead of the load): no stick–slip history, so whole runs
/// agree — the interior point under `auto` and projection, both meeting the laws to 1e-10 of the velocity scale,
/// give the same peak, lift and final state to 1e-10 of the peak (measured 1e-14, 1e-16, 5e-14: the compliant law's
/// solution is unique), and the energy identity closes to 1e-9 of the load's work.
#[test]
fn a_tensionless_soil_beside_the_sleepers() {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { law: FoundationLaw::Tensionless, ..case.foundation };
    let model = BeamModel::new(case.beam, foundation, Mesh::new(18.0, 120).unwrap(), case.supports)
        .unwrap()
        .with_sleepers(Sleepers::default())
        .unwrap();
    let mut interactions =
        FoundationSections { self_weight: false, ..FoundationSections::default() }.interactions(&model).unwrap();
    assert!(spans_a_sleeper(&interactions));
    interactions.extend(sleeper_interactions(&model));
    let auto = run(&model, &interactions, SolverKind::Auto, 1e-10);
    let projection = run(&model, &interactions, SolverKind::Projection, 1e-10);
    assert_eq!(auto.statistics.solver, Some(SolverKind::InteriorPoint));
    let peak = auto.deflection.max_downward.value;
    let state = auto
        .final_displacement
        .iter()
        .zip(&projection.final_displacement)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    let (lift, lift_p) = (auto.deflection.max_upward.value, projection.deflection.max_upward.value);
    eprintln!(
        "peak {:e} lift {:e} state {:e}",
        (projection.deflection.max_downward.value - peak).abs() / peak,
        (lift - lift_p).abs() / peak,
        state / peak
    );
    assert!(
        (projection.deflection.max_downward.value - peak).abs() <= 1e-10 * peak,
        "{} vs {peak}",
        projection.deflection.max_downward.value
    );
    assert!((lift - lift_p).abs() <= 1e-10 * peak, "lift {lift} vs {lift_p}");
    assert!(state <= 1e-10 * peak, "final state {:e}", state / peak);
    let e = auto.energy;
    assert!(e.residual().abs() <= 1e-9 * e.load_work, "{:e} of {} J", e.residual(), e.load_work);
}
