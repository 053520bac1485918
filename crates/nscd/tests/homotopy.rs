//! The homotopy solver on friction alone: random problems solved over several steps (each path starting from the
//! previous step's solution, as in a run), a degenerate element with five sections on one cubic, and the two ends of
//! the law — every section stuck, every section slipping. Each step must meet the law to its tolerance and agree on
//! v with the interior point held to 1e-10.

mod common;

use banded::SymmetricBanded;
use common::diagonally_dominant;
use friction::{InteractionKind, InteractionRow, InteractionSet, Law};
use nscd::SolverKind;
use nscd::integrator::IterationMatrix;
use nscd::solver::{InteractionProblem, InteractionSolver, SolverSettings, build_solver};
use proptest::prelude::*;

/// The homotopy's relative tolerance: its design point (see the test of every solver on random problems).
const TOLERANCE: f64 = 1e-6;

fn stepping(m_hat: SymmetricBanded, interactions: InteractionSet) -> InteractionProblem {
    let integration = nscd::Integration::theta(0.5, 1.0);
    InteractionProblem::with_matrix(interactions, IterationMatrix::of(m_hat, integration).expect("SPD")).expect("SPD")
}

fn solver(kind: SolverKind, problem: &InteractionProblem, tolerance: f64) -> Box<dyn InteractionSolver> {
    let settings = SolverSettings { kind, moving_window: false, tolerance, ..SolverSettings::default() };
    build_solver(kind, problem, &settings).unwrap()
}

/// Solve the steps `v_frees` in turn with the homotopy (impulses carried from step to step, as the stepper does)
/// and, from the same impulses, with the interior point at 1e-10; check the law and the agreement on v of every step.
/// Returns the homotopy's impulses of the last step.
fn solve_steps(problem: &InteractionProblem, v_frees: &[Vec<f64>]) -> Vec<f64> {
    let (n, m) = (problem.matrix.m_hat.order(), problem.len());
    let mut homotopy = solver(SolverKind::Homotopy, problem, TOLERANCE);
    let mut reference = solver(SolverKind::InteriorPoint, problem, 1e-10);
    let mut p = vec![0.0; m];
    for (k, v_free) in v_frees.iter().enumerate() {
        let mut u_free = vec![0.0; m];
        problem.interactions.velocities(v_free, &mut u_free);
        let mut p_reference = p.clone();
        let report = homotopy.solve(problem, v_free, &u_free, &mut p).unwrap();
        assert!(report.converged(), "step {k}: {report:?}");
        let (mut v, mut u) = (vec![0.0; n], vec![0.0; m]);
        let residual = problem.outcome(v_free, &p, &mut v, &mut u);
        let allowed = problem.absolute_tolerance(TOLERANCE, &u_free);
        assert!(residual <= allowed, "step {k}: law residual {residual:e} > {allowed:e}");
        assert_eq!(homotopy.velocity(), Some(v.as_slice()), "step {k}: the velocity handed back is the stepper's");
        for (j, &pj) in p.iter().enumerate() {
            assert!(pj >= problem.law.lower[j] && pj <= problem.law.upper[j], "step {k}: p_{j} = {pj} out of bounds");
        }
        reference.solve(problem, v_free, &u_free, &mut p_reference).unwrap();
        let mut v_reference = vec![0.0; n];
        problem.outcome(v_free, &p_reference, &mut v_reference, &mut u);
        // The primal is 0.1-strongly convex in v and the homotopy's residual is ≤ 1e-6 of the velocity scale: v
        // agrees to ~1e-5 of its scale.
        let scale = v_free.iter().fold(1e-12f64, |a, x| a.max(x.abs()));
        let gap = v.iter().zip(&v_reference).fold(0.0f64, |a, (x, y)| a.max((x - y).abs())) / scale;
        assert!(gap <= 1e-4, "step {k}: v differs from the interior point's by {gap:e}");
    }
    p
}

/// Random friction sections on random local rows (up to twice as many as DOFs: stuck impulses not unique), and
/// four free velocities, each a random change of the one before.
fn friction_steps() -> impl Strategy<Value = (SymmetricBanded, InteractionSet, Vec<Vec<f64>>)> {
    (6usize..40).prop_flat_map(|n| {
        let off = proptest::collection::vec(-1.0f64..1.0, 3 * n);
        let diagonal = proptest::collection::vec(0.1f64..10.0, n);
        let rows = proptest::collection::vec(
            (0..n, 1usize..=4, proptest::collection::vec((0.1f64..1.0, any::<bool>()), 4), 0.0f64..2.0),
            1..2 * n,
        );
        let signed = (0.1f64..1.0, any::<bool>()).prop_map(|(a, s)| if s { a } else { -a });
        let v_frees = proptest::collection::vec(proptest::collection::vec(signed, n), 4);
        (off, diagonal, rows, v_frees).prop_map(move |(off, diagonal, rows, v_frees)| {
            let mut interactions = InteractionSet::new();
            for (start, span, values, capacity) in rows {
                let start = start.min(n - span);
                let entries = (0..span).map(|k| (start + k, if values[k].1 { values[k].0 } else { -values[k].0 }));
                interactions.push(
                    InteractionRow::from_entries(entries),
                    Law::Coulomb { capacity },
                    InteractionKind::Friction,
                );
            }
            // Successive free velocities move by a fifth of a random field: paths with a few events each.
            let mut steps: Vec<Vec<f64>> = Vec::new();
            for change in v_frees {
                let next = match steps.last() {
                    Some(last) => last.iter().zip(&change).map(|(a, d)| a + 0.2 * d).collect(),
                    None => change,
                };
                steps.push(next);
            }
            (diagonally_dominant(n, &off, &diagonal), interactions, steps)
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 300,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(
            std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(20261125),
        ),
        ..ProptestConfig::default()
    })]

    /// Every step of four meets the law and agrees with the interior point, each path starting from the step before.
    #[test]
    fn the_homotopy_meets_the_law_step_after_step((m_hat, interactions, steps) in friction_steps()) {
        let problem = stepping(m_hat, interactions);
        solve_steps(&problem, &steps);
    }
}

/// A Hermite element of length 1 on a beam-like M̂ (mass and stiffness of a few elements, θh² folded in) with five
/// friction sections on its one cubic, at ξ = 0, ¼, ½, ¾, 1: five rows over four DOFs, so the stuck impulses are
/// not unique. Returns the problem and the element's first free DOF.
fn five_sections_on_one_cubic(capacity: f64) -> (InteractionProblem, usize) {
    let elements = 4;
    let n = 2 * (elements + 1);
    let mut m = SymmetricBanded::zeros(n, 3);
    // Consistent mass of a unit element (ρA = 1) plus stiffness (EI θ²h² = 0.01), Hermite cubic of length 1.
    let mass =
        [[156.0, 22.0, 54.0, -13.0], [22.0, 4.0, 13.0, -3.0], [54.0, 13.0, 156.0, -22.0], [-13.0, -3.0, -22.0, 4.0]];
    let stiffness = [[12.0, 6.0, -12.0, 6.0], [6.0, 4.0, -6.0, 2.0], [-12.0, -6.0, 12.0, -6.0], [6.0, 2.0, -6.0, 4.0]];
    for e in 0..elements {
        for i in 0..4 {
            for j in 0..=i {
                m.add(2 * e + i, 2 * e + j, mass[i][j] / 420.0 + 0.01 * stiffness[i][j]);
            }
        }
    }
    let element = 1;
    let first = 2 * element;
    let mut interactions = InteractionSet::new();
    for xi in [0.0, 0.25, 0.5, 0.75, 1.0] {
        let shape = [
            1.0 - 3.0 * xi * xi + 2.0 * xi * xi * xi,
            xi - 2.0 * xi * xi + xi * xi * xi,
            3.0 * xi * xi - 2.0 * xi * xi * xi,
            -xi * xi + xi * xi * xi,
        ];
        let row = InteractionRow::from_entries(shape.iter().enumerate().map(|(k, &s)| (first + k, s)));
        interactions.push(row, Law::Coulomb { capacity }, InteractionKind::Friction);
    }
    (stepping(m, interactions), first)
}

/// A smooth free velocity over the beam: w-DOFs a sine, θ-DOFs its slope, times `amplitude`.
fn smooth_velocity(n: usize, amplitude: f64) -> Vec<f64> {
    (0..n)
        .map(|d| amplitude * if d % 2 == 0 { (0.7 * (d / 2) as f64).sin() } else { 0.7 * (0.7 * (d / 2) as f64).cos() })
        .collect()
}

/// Five sections on one cubic, every one stuck: capacities far above what the free motion asks, so the element's
/// motion at the sections is held to the band, |u_j| ≤ 2ε ≤ 1e-6 of the velocity scale, and v agrees with the
/// interior point although the impulses are not unique.
#[test]
fn five_sections_on_one_cubic_all_stuck() {
    let (problem, _) = five_sections_on_one_cubic(1e3);
    let n = problem.matrix.m_hat.order();
    let steps: Vec<Vec<f64>> = (1..=3).map(|k| smooth_velocity(n, 0.1 * k as f64)).collect();
    let p = solve_steps(&problem, &steps);
    assert!(p.iter().all(|&pj| pj.abs() < 1e3), "every section stuck: {p:?}");
}

/// Five sections on one cubic, every one slipping: capacities far below what the free motion asks, so every impulse
/// sits at the bound that opposes its section's motion (p_j = −F_j sign u_j).
#[test]
fn five_sections_on_one_cubic_all_slipping() {
    let (problem, _) = five_sections_on_one_cubic(1e-4);
    let n = problem.matrix.m_hat.order();
    let steps: Vec<Vec<f64>> = (1..=3).map(|k| smooth_velocity(n, 0.1 * k as f64)).collect();
    let p = solve_steps(&problem, &steps);
    let (mut v, mut u) = (vec![0.0; n], vec![0.0; problem.len()]);
    problem.outcome(steps.last().unwrap(), &p, &mut v, &mut u);
    for (j, (&pj, &uj)) in p.iter().zip(&u).enumerate() {
        assert!(uj.abs() > 1e-3, "section {j} moves: u = {uj:e}");
        assert_eq!(pj, -1e-4 * uj.signum(), "section {j} slips against its motion");
    }
}

/// What the homotopy cannot take it refuses when it is built, saying why: a tolerance below 1e-8 (γ = a/ε would
/// amplify round-off past it), and interactions other than fixed Coulomb friction.
#[test]
fn the_homotopy_refuses_what_it_cannot_solve() {
    let (problem, _) = five_sections_on_one_cubic(1.0);
    let settings = SolverSettings { kind: SolverKind::Homotopy, tolerance: 1e-10, ..SolverSettings::default() };
    let error = build_solver(SolverKind::Homotopy, &problem, &settings).err().expect("refused").to_string();
    assert!(error.contains("at least 1e-8"), "{error}");
    let mut contact = InteractionSet::new();
    let stop = Law::Signorini { gap: 0.0, restitution: 0.0 };
    contact.push(InteractionRow::from_entries([(0, 1.0)]), stop, InteractionKind::Contact);
    let problem = stepping(problem.matrix.m_hat.clone(), contact);
    let settings = SolverSettings { kind: SolverKind::Homotopy, ..SolverSettings::default() };
    let error = build_solver(SolverKind::Homotopy, &problem, &settings).err().expect("refused").to_string();
    assert!(error.contains("Coulomb friction"), "{error}");
}
