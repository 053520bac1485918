//! Ballast friction at one section a node (J = 1: W nonsingular, sections about a coupling length apart) solved by
//! the interior point's active-set predictor (docs/theory.md §5, "Coulomb sections in the same active set"): the
//! step's answer against Clarabel from the same states, the whole run against projection, the work it takes and the
//! energy identity.

use super::common::reference;
use super::solvers_agree::{same_state_difference, tight};
use nscd::SolverKind;
use track::{BallastOnBeam, Devices, DistributedFriction, InitialState, PlacedInteractions, RunSettings, Simulation};

/// 5 kN/m at one section a node: 199 Coulomb sections 1 m apart on the reference track.
fn nodal_friction() -> DistributedFriction {
    DistributedFriction { subdivisions: 1, ..DistributedFriction::new(5e3) }
}

/// Step by step from the steady state at mid-span (the window of sticking and slipping sections all moving), v of
/// the active set against Clarabel's from the same state, both held to 1e-10: within 1e-8, the bound of the other
/// exact solvers' comparisons (`solvers_agree`).
#[test]
fn the_active_set_agrees_with_clarabel_step_by_step() {
    let model = reference();
    let interactions = nodal_friction().interactions(&model).unwrap();
    let mut settings = tight(200.0);
    settings.moving.initial = InitialState::SteadyState { position: 95.0 };
    let (a, b) = (SolverKind::InteriorPoint, SolverKind::Clarabel);
    same_state_difference(&model, &interactions, a, b, &settings, (60, 1e-8));
}

/// The whole 5 kN/m reference run at one section a node, by the interior point (whose predictor takes the steps)
/// and by projection (which converges here in a few sweeps), both at 1e-10: peaks and friction work within 1e-9
/// (measured 1e-11); the interior point's mean factorisations a step at most 1.5 (measured 1.2; issue 53's target
/// is 3, the interior point alone takes nine); and the energy identity at round-off — within 1e-13 of the load
/// work (4e-8 J; measured 5e-10 J, the projection's 3e-10 J), where v taken from the predictor's own solve instead
/// of from p gave 2.7e-6 J.
#[test]
fn a_run_at_one_section_a_node_is_the_projections_in_about_one_factorisation_a_step() {
    let model = reference();
    let interactions = nodal_friction().interactions(&model).unwrap();
    let run = |kind| {
        let mut settings = tight(200.0);
        settings.integration.solver.kind = kind;
        Simulation::new(&model, &interactions, &settings).unwrap().run().unwrap()
    };
    let (active, projection) = (run(SolverKind::InteriorPoint), run(SolverKind::Projection));
    let pairs = [
        (active.deflection.max_downward.value, projection.deflection.max_downward.value),
        (active.deflection.max_upward.value, projection.deflection.max_upward.value),
        (active.energy.friction_work, projection.energy.friction_work),
    ];
    for (a, p) in pairs {
        assert!((a - p).abs() <= 1e-9 * p.abs(), "{a} against the projection's {p}");
    }
    let work = &active.statistics.work;
    assert!(work.mean_factorisations <= 1.5, "{work:?}");
    let energy = &active.energy;
    assert!(energy.residual().abs() <= 1e-13 * energy.load_work, "{} J of {} J", energy.residual(), energy.load_work);
}

/// `auto` on the reference track at 200 m/s (h = 0.5 ms, 2ℓ = 0.8 m; 400 DOFs): five sections an element (0.25 m
/// apart) and one a node (1 m apart, but 199² > 50·400 entries of a dense W) go to the interior point; 31 and 99
/// devices (6.25 and 2 m apart, 31² and 99² ≤ 50·400) to projection, and so do the 199 sections when vehicles ride
/// on them (their wheels' rows keep the active set out).
#[test]
fn auto_takes_the_active_set_where_the_dense_delassus_matrix_is_large() {
    let model = reference();
    let step = (RunSettings::default().integration.load_advance / 200.0, 0.5);
    let nodal = nodal_friction().interactions(&model).unwrap();
    let sections = DistributedFriction::new(5e3).interactions(&model).unwrap();
    let devices = |n| Devices::uniform(n, 10e3).interactions(&model).unwrap();
    let auto = |interactions: &PlacedInteractions, vehicles| {
        track::simulation::resolve_solver(SolverKind::Auto, &model, interactions, step, vehicles)
    };
    assert_eq!(auto(&sections, false), SolverKind::InteriorPoint);
    assert_eq!(auto(&nodal, false), SolverKind::InteriorPoint);
    assert_eq!(auto(&devices(31), false), SolverKind::Projection);
    assert_eq!(auto(&devices(99), false), SolverKind::Projection);
    assert_eq!(auto(&nodal, true), SolverKind::Projection);
}
