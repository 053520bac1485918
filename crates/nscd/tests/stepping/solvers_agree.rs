//! Independent solvers agree on v_{k+1} (MODEL.md §5: p need not be unique, v is).

use super::common::{reference, relative_difference};
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::{InitialState, RunSettings, Simulation, SolverKind};

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
    compare_settings(contacts, (a, settings), (b, settings), steps);
}

fn compare_settings(contacts: &ContactSet, a: (SolverKind, &RunSettings), b: (SolverKind, &RunSettings), steps: usize) {
    let ((a, sa), (b, sb)) = (a, b);
    let (va, ra) = velocities(contacts, a, sa, steps);
    let (vb, rb) = velocities(contacts, b, sb, steps);
    assert_eq!(va.len(), steps);
    for (k, (x, y)) in va.iter().zip(&vb).enumerate() {
        // The bound; both solvers stop at law residuals ≤ 1e-10 relative, Clarabel at 1e-13 gaps.
        let d = relative_difference(x, y);
        assert!(d <= 1e-8, "{a:?} vs {b:?}, step {}: {d:e}", k + 1);
    }
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

/// The moving window re-solves only part of the beam but checks every section: same answer as the whole solve.
#[test]
fn moving_window_agrees_with_whole_beam_solve() {
    let model = reference();
    let contacts = DistributedFriction::new(2e3).contact_set(&model).unwrap();
    let windowed = RunSettings { speed: 150.0, ..RunSettings::default() };
    let mut whole = windowed.clone();
    whole.solver.moving_window = false;
    compare_settings(&contacts, (SolverKind::InteriorPoint, &windowed), (SolverKind::InteriorPoint, &whole), 600);
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
