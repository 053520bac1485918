//! A local change of a factored matrix: after rows [first, last] of A change (a rank-one term γ h hᵀ added to or
//! taken from a few neighbouring rows), the factor rows from `first` on are recomputed in place, and only until they
//! stop changing.
//!
//! Row i of L D Lᵀ depends on row i of A and factor rows i − b … i − 1 alone, so nothing above `first` moves, and
//! below `last` a row moves only through the rows before it: the change decays as the influence of a local load on
//! a beam does. Once b consecutive rows past `last` have changed by no more than `drop` of their size, the rows after
//! them would change by less again (to the decay's constant) and are left as they are. The cost is the decay length
//! times b², not the order of A (issue 53: the homotopy's event, priced before a solver is built on it).

use crate::error::Result;
use crate::symmetric::{BandedLdlt, RowsAbove3, SymmetricBanded};

impl BandedLdlt {
    /// Refactor in place after rows `first..=last` of `a` changed (this is the factor of `a` before the change, of
    /// the same order and bandwidth): rows from `first` on are recomputed, by the full factor's own row formula (the
    /// same bits), until b consecutive rows past `last` differ from their old values by at most `drop` × their
    /// largest L entry (at least 1) and `drop` × D. Returns one past the last row recomputed. An error names the row
    /// whose pivot is not strictly positive (`a` no longer positive definite); the factor is then unusable and must
    /// be rebuilt.
    pub fn refactor_rows_from(&mut self, a: &SymmetricBanded, first: usize, last: usize, drop: f64) -> Result<usize> {
        let (n, b, w) = (self.n, self.bandwidth, self.bandwidth + 1);
        assert!(a.order() == n && a.bandwidth() == b, "the factor of another matrix");
        if b == 3 {
            return self.refactor_rows_from_3(a, first, last, drop);
        }
        let source = a.lower_band();
        // The row's old values: on the stack for the bands a track has (b ≤ 7), so that a refactor in a run's step
        // loop (the pressed-set predictor's) allocates nothing; on the heap past that.
        let (mut stack, mut heap) = ([0.0; 8], Vec::new());
        let old: &mut [f64] = match stack.get_mut(..w) {
            Some(old) => old,
            None => {
                heap.resize(w, 0.0);
                &mut heap
            }
        };
        let mut quiet = 0;
        let mut i = first;
        while i < n {
            let slots = i * w..(i + 1) * w;
            old.copy_from_slice(&self.factors[slots.clone()]);
            self.factors[slots.clone()].copy_from_slice(&source[slots.clone()]);
            SymmetricBanded::factor_row(&mut self.factors, &mut self.inverse_pivots, b, i)?;
            i += 1;
            quiet = if row_is_quiet(&self.factors[slots], old, drop) { quiet + 1 } else { 0 };
            if i > last && quiet >= b {
                break;
            }
        }
        Ok(i)
    }

    /// [`Self::refactor_rows_from`] for half-bandwidth 3: the rows in fixed-size arrays and the state above in
    /// registers ([`RowsAbove3`], the b = 3 full factor's own row formula).
    fn refactor_rows_from_3(&mut self, a: &SymmetricBanded, first: usize, last: usize, drop: f64) -> Result<usize> {
        let n = self.n;
        let source = a.lower_band();
        let mut above = RowsAbove3::of(&self.factors, &self.inverse_pivots, first);
        let mut quiet = 0;
        let mut i = first;
        while i < n {
            let row = &mut self.factors[4 * i..4 * i + 4];
            let old = [row[0], row[1], row[2], row[3]];
            row.copy_from_slice(&source[4 * i..4 * i + 4]);
            self.inverse_pivots[i] = above.next_row(i, row)?;
            i += 1;
            quiet = if row_is_quiet(row, &old, drop) { quiet + 1 } else { 0 };
            if i > last && quiet >= 3 {
                break;
            }
        }
        Ok(i)
    }
}

/// Whether a recomputed factor row (L entries, then D) moved from its `old` value by at most `drop` × its largest L
/// entry (at least 1) in L and `drop` × D in D.
#[inline(always)]
fn row_is_quiet(new: &[f64], old: &[f64], drop: f64) -> bool {
    let b = new.len() - 1;
    let moved = new[..b].iter().zip(&old[..b]).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    let size = new[..b].iter().fold(1.0f64, |m, x| m.max(x.abs()));
    moved <= drop * size && (new[b] - old[b]).abs() <= drop * new[b]
}

#[cfg(test)]
mod tests {
    use crate::symmetric::SymmetricBanded;

    /// A beam-like SPD band: a stiff second-difference-squared stencil over a mass diagonal.
    fn beam(n: usize, mass: f64) -> SymmetricBanded {
        let mut a = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            a.add(i, i, mass + 6.0);
            if i + 1 < n {
                a.add(i + 1, i, -4.0);
            }
            if i + 2 < n {
                a.add(i + 2, i, 1.0);
            }
            if i + 3 < n {
                a.add(i + 3, i, 0.05);
            }
        }
        a
    }

    #[test]
    fn a_local_rank_one_change_refactors_only_where_it_reaches_and_as_a_full_factor_would() {
        let mut a = beam(400, 0.5);
        let mut factor = a.factor().unwrap();
        // A stiff rank-one term on four rows in the middle (a section's shape functions on one element).
        let (dofs, values) = ([200, 201, 202, 203], [0.4, 0.1, 0.6, -0.05]);
        a.add_outer(&dofs, &values, 1e4);
        let end = factor.refactor_rows_from(&a, 200, 203, 1e-15).unwrap();
        let full = a.factor().unwrap();
        let worst =
            factor.factors.iter().zip(&full.factors).fold(0.0f64, |m, (x, y)| m.max((x - y).abs() / y.abs().max(1.0)));
        assert!(worst <= 1e-13, "{worst:e}");
        assert!(end > 203 && end < 300, "recomputed up to row {end}");
        // And back: the term taken away again restores the first factor.
        a.add_outer(&dofs, &values, -1e4);
        factor.refactor_rows_from(&a, 200, 203, 1e-15).unwrap();
        let first = a.factor().unwrap();
        let worst =
            factor.factors.iter().zip(&first.factors).fold(0.0f64, |m, (x, y)| m.max((x - y).abs() / y.abs().max(1.0)));
        assert!(worst <= 1e-12, "{worst:e}");
    }

    #[test]
    fn a_wider_band_refactors_the_same_way() {
        // Half-bandwidths 5 and 9 (the general kernel; its old row on the stack, then on the heap): the b = 3 beam
        // with two more couplings, the last at the band's edge.
        for b in [5, 9] {
            let mut a = SymmetricBanded::zeros(300, b);
            for i in 0..300 {
                a.add(i, i, 8.0);
                for (k, v) in [(1, -3.0), (2, 1.0), (4, 0.2), (b, 0.1)] {
                    if i + k < 300 {
                        a.add(i + k, i, v);
                    }
                }
            }
            let mut factor = a.factor().unwrap();
            a.add_outer(&[150, 151, 153], &[0.5, -0.3, 0.2], 1e3);
            let end = factor.refactor_rows_from(&a, 150, 153, 1e-15).unwrap();
            let full = a.factor().unwrap();
            let worst = factor
                .factors
                .iter()
                .zip(&full.factors)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs() / y.abs().max(1.0)));
            assert!(worst <= 1e-13 && end < 300, "b = {b}: {worst:e}, up to row {end}");
        }
    }

    #[test]
    fn a_change_that_breaks_definiteness_is_named() {
        let mut a = beam(50, 0.5);
        let mut factor = a.factor().unwrap();
        a.add(20, 20, -1e3);
        let error = factor.refactor_rows_from(&a, 20, 20, 1e-15).unwrap_err();
        assert!(error.to_string().contains("20"), "{error}");
    }
}
