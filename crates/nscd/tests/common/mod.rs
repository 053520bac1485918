//! What the solver tests share: random iteration matrices.

use banded::SymmetricBanded;

/// A strictly diagonally dominant banded M̂ of order n, half-bandwidth 3 (so SPD): the off-diagonal entries from
/// `off` (3 per row, in [−1, 1]), the diagonal their row sums plus `diagonal` (in [0.1, 10]): eigenvalues in
/// [0.1, 16].
pub fn diagonally_dominant(n: usize, off: &[f64], diagonal: &[f64]) -> SymmetricBanded {
    let mut m = SymmetricBanded::zeros(n, 3);
    let mut row_sum = vec![0.0; n];
    for i in 0..n {
        for k in 1..=3 {
            if i + k < n {
                let a = off[3 * i + k - 1];
                m.add(i, i + k, a);
                row_sum[i] += a.abs();
                row_sum[i + k] += a.abs();
            }
        }
    }
    for i in 0..n {
        m.add(i, i, row_sum[i] + diagonal[i]);
    }
    m
}
