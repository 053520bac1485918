//! The banded LDLᵀ against nalgebra's dense Cholesky on random SPD band matrices.

use banded::{BandDiagonals, BlockRows, SymmetricBanded};
use nalgebra::DVector;

/// Deterministic pseudo-random numbers in [0, 1) (64-bit LCG, Knuth's constants).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn banded_ldlt_matches_dense_solve() {
    let mut rng = Lcg(7);
    // Half-bandwidths 3 (a beam) and 4 (a rail on sleepers) have kernels of their own, checked here beside the
    // general loops (b = 1, 7), from orders that use only their edge rows (n ≤ 2b) to long bands.
    for &(n, b) in
        &[(1usize, 0usize), (5, 1), (4, 3), (6, 3), (7, 3), (40, 3), (101, 3), (64, 7), (5, 4), (9, 4), (103, 4)]
    {
        let mut a = SymmetricBanded::zeros(n, b);
        for i in 0..n {
            for j in i.saturating_sub(b)..i {
                a.add(i, j, rng.next() - 0.5);
            }
            a.add(i, i, 2.0 * b as f64 + 1.0 + rng.next());
        }
        let dense = a.to_dense();
        let x: Vec<f64> = (0..n).map(|_| rng.next() - 0.5).collect();
        let mut y = vec![0.0; n];
        a.mul_vec(&x, &mut y);
        let dense_y = &dense * DVector::from_vec(x.clone());
        let mut by_diagonals = vec![f64::NAN; n];
        BandDiagonals::new(&a).mul_vec(&x, &mut by_diagonals);
        // Both products add the same ≤ 2b + 1 terms of size ≤ 2b + 2 in different orders: round-off ~1e-15.
        for i in 0..n {
            assert!((y[i] - dense_y[i]).abs() < 1e-13 * (1.0 + dense_y[i].abs()));
            assert!((by_diagonals[i] - dense_y[i]).abs() < 1e-13 * (1.0 + dense_y[i].abs()), "n = {n}, b = {b}");
        }
        let quad = dense_y.dot(&DVector::from_vec(x.clone()));
        assert!((a.quadratic_form(&x) - quad).abs() < 1e-12 * (1.0 + quad.abs()));
        let solved = a.factor().unwrap().solve(&y);
        // Diagonally dominant ⇒ condition number O(1): the solution is recovered to round-off.
        for i in 0..n {
            assert!((solved[i] - x[i]).abs() < 1e-12, "n = {n}, b = {b}, i = {i}");
        }
    }
}

#[test]
fn indefinite_matrix_is_reported_with_its_equation() {
    let mut a = SymmetricBanded::zeros(4, 1);
    for i in 0..4 {
        a.add(i, i, 1.0);
    }
    a.add(3, 2, 2.0);
    match a.factor() {
        Err(banded::BandedError::NonPositivePivot { index, .. }) => assert_eq!(index, 3),
        other => panic!("expected a pivot error, got {other:?}"),
    }
}

/// S_W = A_WW − A_WO A_OO⁻¹ A_OW from the forward and reversed factors: S_W⁻¹ b = (A⁻¹ [0; b; 0])_W.
#[test]
fn window_schur_complement_matches_block_of_the_inverse() {
    let mut rng = Lcg(11);
    let (n, b) = (60usize, 3usize);
    let mut a = SymmetricBanded::zeros(n, b);
    for i in 0..n {
        for j in i.saturating_sub(b)..i {
            a.add(i, j, rng.next() - 0.5);
        }
        a.add(i, i, 4.0 + rng.next());
    }
    let forward = a.factor().unwrap();
    let backward = a.reversed().factor().unwrap();
    for (start, end) in [(0usize, 60usize), (0, 25), (20, 60), (20, 35), (7, 11)] {
        let mut s = SymmetricBanded::zeros(1, b);
        a.principal_submatrix_into(start, end, &mut s);
        if start > 0 {
            forward.subtract_leading_schur(start, &mut s);
        }
        if end < n {
            backward.subtract_trailing_schur(end, &mut s);
        }
        let rhs: Vec<f64> = (start..end).map(|_| rng.next() - 0.5).collect();
        let local = s.factor().unwrap().solve(&rhs);
        let mut full = vec![0.0; n];
        full[start..end].copy_from_slice(&rhs);
        let reference = forward.solve(&full);
        for (k, x) in local.iter().enumerate() {
            // Diagonally dominant: both are exact to round-off.
            assert!((x - reference[start + k]).abs() < 1e-13, "window [{start}, {end}) entry {k}");
        }
    }
}

/// A window over a beam range with a decoupled trailing block appended (a vehicle's DOFs, coupled to the beam only
/// through contact rows): its inverse is the block of A⁻¹ over [start, end) ∪ [tail, n), to round-off.
#[test]
fn a_window_with_a_decoupled_tail_is_the_block_of_the_inverse() {
    let mut rng = Lcg(13);
    let (n, b, tail) = (60usize, 3usize, 55usize);
    let mut a = SymmetricBanded::zeros(n, b);
    for i in 0..n {
        for j in i.saturating_sub(b)..i {
            if (i >= tail) == (j >= tail) {
                a.add(i, j, rng.next() - 0.5);
            }
        }
        a.add(i, i, 4.0 + rng.next());
    }
    let forward = a.factor().unwrap();
    let backward = a.reversed().factor().unwrap();
    for (start, end) in [(0usize, 25usize), (20, 35), (30, 55)] {
        let mut s = SymmetricBanded::zeros(1, b);
        a.principal_submatrix_into(start, end, &mut s);
        if start > 0 {
            forward.subtract_leading_schur(start, &mut s);
        }
        backward.subtract_trailing_schur(end, &mut s);
        s.append_decoupled_block(&a, tail);
        assert_eq!(s.order(), end - start + n - tail);
        let rhs: Vec<f64> = (0..s.order()).map(|_| rng.next() - 0.5).collect();
        let local = s.factor().unwrap().solve(&rhs);
        let mut full = vec![0.0; n];
        full[start..end].copy_from_slice(&rhs[..end - start]);
        full[tail..].copy_from_slice(&rhs[end - start..]);
        let reference = forward.solve(&full);
        let dofs = (start..end).chain(tail..n);
        for (k, dof) in dofs.enumerate() {
            assert!((local[k] - reference[dof]).abs() < 1e-13, "window [{start}, {end}) ∪ [{tail}, {n}): DOF {dof}");
        }
    }
}

/// A contact row's packed Hᵀ diag(d) H update equals the generic rank-one update to the bit, rows at the start, in
/// the middle and at the end of the matrix, one to four entries.
#[test]
fn block_row_gram_matches_generic_outer_update() {
    let mut rng = Lcg(5);
    for len in 1..=4usize {
        for first in [0usize, 3, 12 - len] {
            let h: Vec<f64> = (0..len).map(|_| rng.next() - 0.5).collect();
            let base = SymmetricBanded::zeros(12, 3);
            let mut rows = BlockRows::with_capacity(1);
            rows.push(first, &h);
            let mut a = SymmetricBanded::zeros(12, 3);
            rows.weighted_gram_into(&base, &[1.7], &mut a);
            let mut b = base.clone();
            let dofs: Vec<usize> = (first..first + len).collect();
            b.add_outer(&dofs, &h, 1.7);
            for i in 0..12usize {
                for j in i.saturating_sub(3)..=i {
                    assert_eq!(a.get(i, j).to_bits(), b.get(i, j).to_bits(), "len {len}, first {first}, ({i}, {j})");
                }
            }
        }
    }
}
