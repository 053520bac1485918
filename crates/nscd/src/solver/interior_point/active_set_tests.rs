//! Tests of the active-set predictor (`active_set.rs`).

use crate::integrator::IterationMatrix;
use crate::problem::InteractionProblem;
use crate::solver::InteractionSolver;
use crate::solver::interior_point::BandedInteriorPoint;
use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

/// The beam-like M̂ of the interior point's tests on `elements` elements with a compliant support
/// at ξ = 0, ¼, ½, ¾ of every element, pressed in by up to 1 mm along a wave: some pressed, some free.
fn supports(elements: usize) -> InteractionProblem {
    let m_hat = super::super::tests::beam_like_m_hat(elements);
    let n = m_hat.order();
    let mut interactions = InteractionSet::new();
    for e in 0..elements {
        for xi in [0.0, 0.25, 0.5, 0.75] {
            let bubble = 0.1 * xi * (1.0 - xi);
            let row = InteractionRow::from_entries(
                [1.0 - xi, bubble, xi, -bubble].into_iter().enumerate().map(|(k, v)| (2 * e + k, v)),
            );
            let gap = 1e-3 * (0.37 * interactions.len() as f64).sin();
            interactions.push(row, Law::Compliant { gap, stiffness: 50.0 }, InteractionKind::Support);
        }
    }
    let integration = crate::Integration::theta(0.5, 1e-2);
    let matrix = IterationMatrix::of(m_hat, integration).expect("M̂ is SPD");
    let mut problem = InteractionProblem::with_matrix(interactions, matrix).expect("M̂ is SPD");
    problem.update(0.0, &vec![0.0; n], &vec![0.0; n]);
    problem
}

/// The factor of B after a few sections' springs are added or taken out — in two runs far apart, and in two
/// overlapping spans — is, refactored from the changes on until its rows repeat, the full factorisation of the
/// changed B to the bit; and it stops short of the end (the change fades: the cost is local).
#[test]
fn the_local_refactor_is_the_full_factor_to_the_bit() {
    let mut b = super::super::tests::beam_like_m_hat(200);
    let mut factor = b.factor().expect("SPD");
    let springs = [((40, 43), 0.7), ((41, 44), 0.4), ((300, 303), 2.5)];
    for &((first, last), k) in &springs {
        let dofs: Vec<usize> = (first..=last).collect();
        b.add_outer(&dofs, &[1.0, 0.2, 0.5, -0.1], k);
    }
    let spans: Vec<(usize, usize)> = springs.iter().map(|s| s.0).collect();
    super::refactor_changed_rows(&b, &mut factor, &spans).expect("still SPD");
    assert_eq!(factor, b.factor().expect("SPD"), "the local refactor differs from the full one");
    // One more spring: its refactor ends within a few elements of it, not at the end of the 402 rows.
    b.add_outer(&[150, 151, 152, 153], &[1.0, 0.2, 0.5, -0.1], 3.0);
    let end = factor.refactor_rows_from(&b, 150, 153, 0.0).expect("SPD");
    assert!(end < 250, "the refactor after a change at row 150 ran to row {end}");
    assert_eq!(factor, b.factor().expect("SPD"));
}

/// Coulomb sections of capacity `capacity` on the beam-like M̂ of `elements` elements: one a node (the rows
/// e_w of the nodes' first DOF: W nonsingular, sections a node apart) or, `redundant`, also at ξ = ¼, ½, ¾ of every
/// element (W singular, as with five sections an element) with the nodes' first DOFs tied by springs `chain` (N/m
/// against the blocks' 4): a stiff chain couples M̂⁻¹ over many sections, as a rail's bending stiffness does.
fn coulomb(elements: usize, capacity: f64, redundant: bool, chain: f64) -> InteractionProblem {
    let mut m_hat = super::super::tests::beam_like_m_hat(elements);
    for e in 0..elements {
        m_hat.add_outer(&[2 * e, 2 * e + 2], &[1.0, -1.0], chain);
    }
    let mut interactions = InteractionSet::new();
    let xis: &[f64] = if redundant { &[0.0, 0.25, 0.5, 0.75] } else { &[0.0] };
    for e in 0..elements {
        for &xi in xis {
            let bubble = 0.1 * xi * (1.0 - xi);
            let entries = [1.0 - xi, bubble, xi, -bubble].into_iter().enumerate().filter(|&(_, v)| v != 0.0);
            let row = InteractionRow::from_entries(entries.map(|(k, v)| (2 * e + k, v)));
            interactions.push(row, Law::Coulomb { capacity }, InteractionKind::Friction);
        }
    }
    let integration = crate::Integration::theta(0.5, 1e-2);
    let matrix = IterationMatrix::of(m_hat, integration).expect("M̂ is SPD");
    InteractionProblem::with_matrix(interactions, matrix).expect("M̂ is SPD")
}

/// Free velocities along a wave of `phase`, and their section velocities H v.
fn free_step(problem: &InteractionProblem, phase: f64) -> (Vec<f64>, Vec<f64>) {
    let n = problem.matrix.m_hat.order();
    let v: Vec<f64> = (0..n).map(|i| 0.02 * (0.11 * i as f64 + phase).sin() - 0.01).collect();
    let mut u = vec![0.0; problem.len()];
    problem.interactions.velocities(&v, &mut u);
    (v, u)
}

/// The step of phase 0.3 solved by the interior point alone (a fresh solver solves its first step whole), and by a
/// solver that solved the step of phase 0 first — so that it predicts the second from the first's impulses: the
/// reference impulses, the predicted ones, the first step's and the second step's report.
fn predicted_and_whole(problem: &InteractionProblem) -> (Vec<f64>, Vec<f64>, Vec<f64>, super::super::StepReport) {
    let m = problem.len();
    let ((v1, u1), (v2, u2)) = (free_step(problem, 0.0), free_step(problem, 0.3));
    let mut reference = vec![0.0; m];
    let mut whole = BandedInteriorPoint::new(problem, 1e-10, 200, true).unwrap();
    whole.solve(problem, &v2, &u2, &mut reference).unwrap();
    let mut solver = BandedInteriorPoint::new(problem, 1e-10, 200, true).unwrap();
    let mut p = vec![0.0; m];
    solver.solve(problem, &v1, &u1, &mut p).unwrap();
    let before = p.clone();
    let report = solver.solve(problem, &v2, &u2, &mut p).unwrap();
    assert_eq!(solver.statistics.predicted, 1, "{:?}", solver.statistics);
    assert!(report.residual <= report.tolerance && report.iterations >= 2, "{report:?}");
    (reference, p, before, report)
}

/// Every impulse within the error a law residual of the tolerance allows: tolerance/min(W_jj + d_j), times
/// `condition` where W + D is not diagonally dominant enough for its smallest diagonal to bound it.
fn assert_impulses_agree(problem: &InteractionProblem, p: &[f64], reference: &[f64], tolerance: f64, condition: f64) {
    let smallest = problem.delassus_diagonal.iter().fold(f64::INFINITY, |a, &w| a.min(w));
    let allowed = condition * tolerance / smallest;
    for (j, (a, b)) in p.iter().zip(reference).enumerate() {
        assert!((a - b).abs() <= allowed, "section {j}: {a} against {b} (allowed {allowed:e})");
    }
}

/// A step of compliant supports alone, solved again from the last step's impulses with free velocities that moved
/// (so its pressed set moves): the predictor takes it in a few active-set rounds and its impulses are the interior
/// point's own on that step, to the solver tolerance (1e-10 of the velocity scale, times 1/min(W_jj + d_j): the
/// impulse error a residual of that size allows).
#[test]
fn the_pressed_set_gives_the_interior_points_step() {
    let problem = supports(60);
    let m = problem.len();
    let (reference, p, before, report) = predicted_and_whole(&problem);
    let moved = p.iter().zip(&before).filter(|&(&x, &was)| (x > 0.0) != (was > 0.0)).count();
    let pressed = p.iter().filter(|&&x| x > 0.0).count();
    assert!(moved > 0 && pressed > 20 && pressed < m - 20, "{moved} moved, {pressed} of {m} pressed");
    assert_impulses_agree(&problem, &p, &reference, report.tolerance, 1.0);
}

/// Coulomb sections one a node, the step's stick and slip zones moved by the new free velocities: the predictor
/// takes the step (held sections by their stiff spring, refined until the residual meets 1e-10) and its impulses
/// are the interior point's, to the error the tolerance allows (W is nonsingular here, and its smallest eigenvalue
/// no less than a tenth of its smallest diagonal on this diagonally dominant M̂: the factor 10).
#[test]
fn the_active_set_gives_the_interior_points_friction_step() {
    let problem = coulomb(60, 3.0, false, 0.0);
    let (reference, p, before, report) = predicted_and_whole(&problem);
    let bound = problem.law.upper[0];
    let side = |x: f64| {
        if x >= bound {
            1
        } else if x <= -bound {
            -1
        } else {
            0
        }
    };
    let moved = p.iter().zip(&before).filter(|&(&x, &was)| side(x) != side(was)).count();
    let (up, down) = (p.iter().filter(|&&x| side(x) == 1).count(), p.iter().filter(|&&x| side(x) == -1).count());
    let stuck = p.len() - up - down;
    assert!(moved > 0 && up > 5 && down > 5 && stuck > 5, "{moved} moved; {up} at +a, {down} at −a, {stuck} stuck");
    assert_impulses_agree(&problem, &p, &reference, report.tolerance, 10.0);
}

/// Coulomb sections at the nodes and a compliant stop at the middle of every element (a frictional ballast over a
/// tensionless soil) in one step: both kinds move sides, and the predicted impulses are the interior point's to the
/// error the tolerance allows.
#[test]
fn coulomb_sections_and_compliant_stops_share_the_active_set() {
    let elements = 60;
    let m_hat = super::super::tests::beam_like_m_hat(elements);
    let n = m_hat.order();
    let mut interactions = InteractionSet::new();
    for e in 0..elements {
        interactions.push(
            InteractionRow::from_entries([(2 * e, 1.0)]),
            Law::Coulomb { capacity: 3.0 },
            InteractionKind::Friction,
        );
        let row = InteractionRow::from_entries(
            [0.5, 0.025, 0.5, -0.025].into_iter().enumerate().map(|(k, v)| (2 * e + k, v)),
        );
        let gap = 1e-3 * (0.37 * e as f64).sin();
        interactions.push(row, Law::Compliant { gap, stiffness: 50.0 }, InteractionKind::Support);
    }
    let integration = crate::Integration::theta(0.5, 1e-2);
    let matrix = IterationMatrix::of(m_hat, integration).expect("M̂ is SPD");
    let mut problem = InteractionProblem::with_matrix(interactions, matrix).expect("M̂ is SPD");
    problem.update(0.0, &vec![0.0; n], &vec![0.0; n]);
    let (reference, p, before, report) = predicted_and_whole(&problem);
    let law = &problem.law;
    let side = |j: usize, x: f64| match law.upper[j].is_finite() {
        true if x >= law.upper[j] => 1,
        true if x <= law.lower[j] => -1,
        _ => i32::from(x > 0.0) * 2,
    };
    let moved = (0..p.len()).filter(|&j| side(j, p[j]) != side(j, before[j])).count();
    let pressed = (1..p.len()).step_by(2).filter(|&j| p[j] > 0.0).count();
    let slipping = (0..p.len()).step_by(2).filter(|&j| side(j, p[j]) != 0).count();
    assert!(moved > 0 && pressed > 5 && slipping > 5, "{moved} moved, {pressed} stops pressed, {slipping} slipping");
    assert_impulses_agree(&problem, &p, &reference, report.tolerance, 10.0);
}

/// With several Coulomb sections an element (W singular), most of them stuck, on a stiff chain, the predictor misses
/// (the held impulses are not unique and the updates wander), and after [`super::MAX_MISSES`] steps in a row the run
/// stops trying it; every step is still solved to its tolerance by the interior point.
#[test]
fn redundant_sections_stop_the_predictor() {
    let problem = coulomb(60, 3.0, true, 1e3);
    let mut solver = BandedInteriorPoint::new(&problem, 1e-10, 200, true).unwrap();
    let mut p = vec![0.0; problem.len()];
    for step in 0..2 * super::MAX_MISSES {
        let (v, u) = free_step(&problem, 0.3 * step as f64);
        let report = solver.solve(&problem, &v, &u, &mut p).unwrap();
        assert!(report.residual <= report.tolerance, "step {step}: {report:?}");
    }
    assert_eq!(solver.statistics.predicted, 0, "{:?}", solver.statistics);
    assert!(!solver.active.as_ref().expect("rows in the band").worth_trying());
}
