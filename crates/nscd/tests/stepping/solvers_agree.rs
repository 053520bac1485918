//! Independent solvers agree on v_{k+1} (MODEL.md §5: p need not be unique, v is).

use super::common::{reference, relative_difference};
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::simulation::coupling_length;
use nscd::solver::interior_point::BandedInteriorPoint;
use nscd::solver::{FrictionProblem, FrictionSolver, SolverSettings, build_solver};
use nscd::stepper::{Integration, iteration_matrix};
use nscd::{InitialState, LinearSystem, MoreauJean, MovingLoad, RunSettings, Simulation, SolverKind};

/// Velocities after each of the first `steps` steps, and the run result.
fn velocities(
    contacts: &ContactSet,
    kind: SolverKind,
    settings: &RunSettings,
    steps: usize,
) -> (Vec<Vec<f64>>, nscd::RunResult) {
    let model = reference();
    let mut settings = settings.clone();
    settings.solver.kind = kind;
    let mut out = Vec::new();
    let result = Simulation::new(&model, contacts, &settings)
        .unwrap()
        .run_observed(&mut |s| {
            out.push(s.velocity.to_vec());
            s.step < steps
        })
        .unwrap();
    (out, result)
}

fn compare(contacts: &ContactSet, a: SolverKind, b: SolverKind, settings: &RunSettings, steps: usize) {
    // The bound; the solvers stop at law residuals ≤ 1e-10 relative, Clarabel at 1e-12 gaps.
    compare_settings(contacts, (a, settings), (b, settings), steps, 1e-8);
}

fn compare_settings(
    contacts: &ContactSet,
    a: (SolverKind, &RunSettings),
    b: (SolverKind, &RunSettings),
    steps: usize,
    bound: f64,
) {
    let ((a, sa), (b, sb)) = (a, b);
    let (va, ra) = velocities(contacts, a, sa, steps);
    let (vb, rb) = velocities(contacts, b, sb, steps);
    assert_eq!(va.len(), steps.min(va.len()));
    let mut worst: f64 = 0.0;
    for (k, (x, y)) in va.iter().zip(&vb).enumerate() {
        let d = relative_difference(x, y);
        worst = worst.max(d);
        assert!(d <= bound, "{a:?} vs {b:?}, step {}: {d:e}", k + 1);
    }
    eprintln!("{a:?} vs {b:?}: largest per-step velocity difference {worst:.2e} over {} steps", va.len());
    let (wa, wb) = (ra.max_downward.magnitude, rb.max_downward.magnitude);
    assert!((wa - wb).abs() <= 1e-6 * wb, "max deflection {wa} vs {wb}");
}

#[test]
fn clarabel_agrees_with_projection_for_devices() {
    let model = reference();
    let contacts = Devices::uniform(31, 100e3).contact_set(&model).unwrap();
    let settings = RunSettings { speed: 200.0, ..RunSettings::default() };
    compare(&contacts, SolverKind::Projection, SolverKind::Clarabel, &settings, 400);
    compare(&contacts, SolverKind::Projection, SolverKind::InteriorPoint, &settings, 400);
}

#[test]
fn clarabel_agrees_with_interior_point_for_distributed_friction() {
    let model = reference();
    let contacts = DistributedFriction::new(5e3).contact_set(&model).unwrap();
    // Start in the steady state with the load at mid-span, so that the whole window around it moves at once.
    let settings =
        RunSettings { speed: 200.0, initial: InitialState::SteadyState { position: 95.0 }, ..RunSettings::default() };
    compare(&contacts, SolverKind::InteriorPoint, SolverKind::Clarabel, &settings, 25);
}

/// The moving window re-solves only part of the beam but checks every section: from the same state, each step
/// gives the velocity of a whole-beam solve (along a 600-step windowed trajectory with distributed friction).
#[test]
fn moving_window_agrees_with_whole_beam_solve_every_step() {
    let model = reference();
    let contacts = DistributedFriction::new(2e3).contact_set(&model).unwrap();
    let (speed, theta) = (150.0, 0.5);
    let h = 0.1 / speed;
    let system = LinearSystem::from_beam(&model);
    let integration = Integration { theta, step: h };
    let m_hat = iteration_matrix(&system, integration);
    let factor = m_hat.factor().unwrap();
    let settings = SolverSettings { kind: SolverKind::InteriorPoint, ..SolverSettings::default() };
    let margin = 30.0 * coupling_length(&model, h, theta);
    let stepping = FrictionProblem::new(&contacts, &m_hat, &factor, h);
    let windowed = build_solver(SolverKind::InteriorPoint, &stepping, &settings, Some(margin)).unwrap();
    let checking = FrictionProblem::new(&contacts, &m_hat, &factor, h);
    let mut whole = BandedInteriorPoint::new(&checking, settings.tolerance, settings.max_iterations, None).unwrap();
    let load = MovingLoad::new(*model.mesh(), model.dofs(), 83.4e3, speed, 0.0);
    let n = system.dofs();
    let mut stepper = MoreauJean::new(&system, &contacts, integration, stepping, windowed, vec![0.0; n], vec![0.0; n]);
    let (mut u_free, mut p) = (vec![0.0; contacts.len()], vec![0.0; contacts.len()]);
    let mut worst: f64 = 0.0;
    for step in 1..=600 {
        let v_free = stepper.free_velocity(&load).to_vec();
        contacts.velocities(&v_free, &mut u_free);
        whole.solve(&checking, &v_free, &u_free, &mut p).unwrap();
        let mut v_whole = vec![0.0; n];
        contacts.add_transpose(&p, &mut v_whole);
        factor.solve_in_place(&mut v_whole);
        v_whole.iter_mut().zip(&v_free).for_each(|(v, f)| *v += f);
        stepper.step(&load).unwrap();
        let d = relative_difference(&stepper.v, &v_whole);
        worst = worst.max(d);
        // The per-step bound for two exact solvers.
        assert!(d <= 1e-8, "step {step}: {d:e}");
    }
    eprintln!("window vs whole: largest per-step velocity difference {worst:.2e}");
}

/// Whole runs (release build: `cargo test --release -p nscd -- --ignored`).
#[test]
#[ignore = "whole runs with Clarabel take minutes"]
fn whole_runs_agree() {
    let model = reference();
    let devices = Devices::uniform(31, 100e3).contact_set(&model).unwrap();
    let settings = RunSettings { speed: 200.0, ..RunSettings::default() };
    compare(&devices, SolverKind::Projection, SolverKind::Clarabel, &settings, usize::MAX);
    let distributed = DistributedFriction::new(5e3).contact_set(&model).unwrap();
    compare(&distributed, SolverKind::InteriorPoint, SolverKind::Clarabel, &settings, usize::MAX);
}
