//! Responses to unit impulses on single DOFs, r_i = M̂⁻¹e_i, for the moving interactions' rows (docs/theory.md §9).
//!
//! A moving row H touches a handful of DOFs (a wheel: the four Hermite DOFs of the element under it and the wheel's
//! own), so its response is G = M̂⁻¹Hᵀ = Σ_i H_i r_i. Each r_i decays away from DOF i like the fixed interactions'
//! responses ([`crate::problem::responses`]) and is truncated the same way; it is solved once, on the first step whose
//! row touches DOF i, and kept while rows keep touching it — a wheel crosses an element in several steps, so most
//! steps solve nothing and assemble G from the kept columns instead of one banded solve per wheel.

use super::responses::{DROP_BELOW, significant_range};
use crate::kernels::axpy;
use banded::BandedLdlt;

/// A kept column: its first DOF, its entries, and the last update that used it.
#[derive(Debug, Clone)]
struct Column {
    start: usize,
    values: Vec<f64>,
    used: u64,
}

/// Columns unused for more than this many updates are dropped (a wheel never comes back to a DOF it has passed;
/// two updates keep the columns of wheels sharing an element).
const KEEP_UPDATES: u64 = 2;

/// The kept columns r_i, by DOF.
#[derive(Debug, Clone)]
pub(crate) struct DofResponses {
    columns: Vec<Option<Column>>,
    /// DOFs with a kept column.
    live: Vec<usize>,
    /// The current update.
    epoch: u64,
    /// n scratch for a solve.
    scratch: Vec<f64>,
}

impl DofResponses {
    /// No column kept yet, for a system of `n` DOFs.
    pub(crate) fn new(n: usize) -> Self {
        Self { columns: vec![None; n], live: Vec::new(), epoch: 0, scratch: Vec::new() }
    }

    /// Start an update: drop the columns no row has used for [`KEEP_UPDATES`] updates.
    pub(crate) fn begin_update(&mut self) {
        self.epoch += 1;
        let (columns, epoch) = (&mut self.columns, self.epoch);
        self.live.retain(|&i| {
            let keep = columns[i].as_ref().is_some_and(|c| c.used + KEEP_UPDATES >= epoch);
            if !keep {
                columns[i] = None;
            }
            keep
        });
    }

    /// column[start..] += `scale`·r_dof (solving for r_dof with `factor` if it is not kept), returning the range of
    /// `column` it wrote.
    pub(crate) fn add(&mut self, dof: usize, scale: f64, factor: &BandedLdlt, column: &mut [f64]) -> (usize, usize) {
        if self.columns[dof].is_none() {
            self.columns[dof] = Some(Self::solve(dof, factor, &mut self.scratch));
            self.live.push(dof);
        }
        let kept = self.columns[dof].as_mut().expect("kept above");
        kept.used = self.epoch;
        let end = kept.start + kept.values.len();
        axpy(scale, &kept.values, &mut column[kept.start..end]);
        (kept.start, end)
    }

    /// r_dof = M̂⁻¹e_dof by one banded solve, without the entries below
    /// [`crate::problem::responses::DROP_BELOW`] of its largest.
    fn solve(dof: usize, factor: &BandedLdlt, scratch: &mut Vec<f64>) -> Column {
        scratch.clear();
        scratch.resize(factor.order(), 0.0);
        scratch[dof] = 1.0;
        factor.solve_in_place(scratch);
        let (first, last) = significant_range(scratch, DROP_BELOW, dof);
        Column { start: first, values: scratch[first..last].to_vec(), used: 0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use banded::SymmetricBanded;

    /// A beam-like SPD matrix of band 3 (a stiff chain with a mass diagonal), 200 DOFs.
    fn factor() -> BandedLdlt {
        let n = 200;
        let mut m = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            m.add(i, i, 2.0 + 1e-3);
            if i + 1 < n {
                m.add(i + 1, i, -0.6);
            }
            if i + 3 < n {
                m.add(i + 3, i, 0.2);
            }
        }
        m.factor().unwrap()
    }

    /// Σ H_i r_i from the kept columns is the banded solve M̂⁻¹Hᵀ to round-off, and touches a short range.
    #[test]
    fn assembled_responses_are_the_solve() {
        let factor = factor();
        let n = factor.order();
        let mut responses = DofResponses::new(n);
        responses.begin_update();
        let row = [(100, -0.3), (101, 0.05), (102, -0.7), (103, -0.02), (150, 1.0)];
        let mut assembled = vec![0.0; n];
        let mut range = (n, 0);
        for (dof, value) in row {
            let (a, b) = responses.add(dof, value, &factor, &mut assembled);
            range = (range.0.min(a), range.1.max(b));
        }
        let mut solved = vec![0.0; n];
        for (dof, value) in row {
            solved[dof] += value;
        }
        factor.solve_in_place(&mut solved);
        let scale = solved.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let worst = solved.iter().zip(&assembled).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(worst <= 1e-15 * scale, "assembled response off by {worst:e} of {scale:e}");
        assert!(range.1 - range.0 < n, "the columns are truncated: {range:?}");
    }

    /// A column no row uses for more than two updates is dropped; one in use is kept and not solved again.
    #[test]
    fn unused_columns_are_dropped() {
        let factor = factor();
        let mut responses = DofResponses::new(factor.order());
        let mut column = vec![0.0; factor.order()];
        responses.begin_update();
        responses.add(10, 1.0, &factor, &mut column);
        responses.add(11, 1.0, &factor, &mut column);
        for _ in 0..3 {
            responses.begin_update();
            responses.add(11, 1.0, &factor, &mut column);
        }
        assert_eq!(responses.live, vec![11]);
        assert!(responses.columns[10].is_none() && responses.columns[11].is_some());
    }
}
