//! Local solves against the full solve: a beam-like matrix (a Hermite element's mass plus a stiff term, the
//! homotopy's B) and right-hand sides of one to four neighbouring entries, in the middle and at both ends.

use banded::{LocalVector, SymmetricBanded};

/// A Hermite beam of `elements` unit elements: consistent mass plus `stiffness` × bending stiffness, and a penalty
/// `penalty` on the w DOFs of every other node (the stiff terms of stuck sections).
fn beam_like(elements: usize, stiffness: f64, penalty: f64) -> SymmetricBanded {
    let n = 2 * (elements + 1);
    let mut a = SymmetricBanded::zeros(n, 3);
    let mass =
        [[156.0, 22.0, 54.0, -13.0], [22.0, 4.0, 13.0, -3.0], [54.0, 13.0, 156.0, -22.0], [-13.0, -3.0, -22.0, 4.0]];
    let bending = [[12.0, 6.0, -12.0, 6.0], [6.0, 4.0, -6.0, 2.0], [-12.0, -6.0, 12.0, -6.0], [6.0, 2.0, -6.0, 4.0]];
    for e in 0..elements {
        for i in 0..4 {
            for j in 0..=i {
                a.add(2 * e + i, 2 * e + j, mass[i][j] / 420.0 + stiffness * bending[i][j]);
            }
        }
    }
    for node in (0..=elements).step_by(2) {
        a.add(2 * node, 2 * node, penalty);
    }
    a
}

/// Every local solve, truncated at 1e-13, equals the full solve to 1e-12 of max|x| everywhere — on the range it
/// keeps and outside it (measured ≤ 2.3e-15 at a drop of 1e-14, the stiff case included: the truncation is judged
/// on D⁻¹z, so pivots six orders apart do not amplify it) — and keeps far fewer entries than the order.
#[test]
fn local_solves_match_the_full_solve_where_they_keep_it_and_are_short() {
    for (stiffness, penalty) in [(1e-3, 0.0), (1e-2, 0.0), (1e-3, 1e6)] {
        let a = beam_like(200, stiffness, penalty);
        let factor = a.factor().unwrap();
        let n = a.order();
        let (mut out, mut scratch) = (LocalVector::default(), Vec::new());
        let mut worst: f64 = 0.0;
        for first in [0, 1, 57, 200, n - 4, n - 1] {
            for len in 1..=4usize.min(n - first) {
                let entries: Vec<(usize, f64)> = (0..len).map(|k| (first + k, 1.0 - 0.3 * k as f64)).collect();
                let mut full = vec![0.0; n];
                for &(i, v) in &entries {
                    full[i] = v;
                }
                factor.solve_in_place(&mut full);
                factor.solve_local(&entries, 1e-13, &mut out, &mut scratch);
                let largest = full.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                for (i, &x) in full.iter().enumerate() {
                    let kept = if i >= out.start && i < out.end() { out.values[i - out.start] } else { 0.0 };
                    worst = worst.max((kept - x).abs() / largest);
                }
                assert!(out.values.len() < n / 2, "{} of {n} entries kept", out.values.len());
                assert!(out.start <= first && out.end() > first + len - 1, "the rhs's own DOFs are kept");
            }
        }
        assert!(worst <= 1e-12, "k = {stiffness}, penalty {penalty}: local and full solves differ by {worst:e}");
    }
}
