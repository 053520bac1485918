//! Symmetric banded matrices and their LDLᵀ factorisation.
//!
//! Hermite beam matrices in the DOF order (w₀, θ₀, w₁, θ₁, …) couple only DOFs of neighbouring nodes, so after
//! removing constrained DOFs they are symmetric with half-bandwidth b = 3. The time stepper factors one such
//! matrix per run and solves with it thousands of times; a banded LDLᵀ costs O(n·b²) to factor and O(n·b) to
//! solve, needs no pivoting for SPD matrices, and measured 2× faster per solve than nalgebra-sparse's
//! `CscCholesky` (see `benches/linear_solve.rs` and BENCHMARKS.md).
//!
//! Storage: the lower band, row by row; entry (i, j) with i − b ≤ j ≤ i lives at `data[i·(b+1) + b − (i − j)]`.
//! Slots that would fall before column 0 are kept at zero.

use crate::error::{BandedError, Result};
use nalgebra::DMatrix;

/// A symmetric n×n matrix with half-bandwidth b, storing its lower band.
#[derive(Debug, Clone, PartialEq)]
pub struct SymmetricBanded {
    n: usize,
    bandwidth: usize,
    data: Vec<f64>,
}

impl SymmetricBanded {
    /// The zero matrix of order `n` and half-bandwidth `bandwidth`.
    pub fn zeros(n: usize, bandwidth: usize) -> Self {
        Self { n, bandwidth, data: vec![0.0; n * (bandwidth + 1)] }
    }

    /// Order n.
    pub fn order(&self) -> usize {
        self.n
    }

    /// Half-bandwidth b.
    pub fn bandwidth(&self) -> usize {
        self.bandwidth
    }

    #[inline]
    fn slot(&self, i: usize, j: usize) -> Option<usize> {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        (i - j <= self.bandwidth && i < self.n).then(|| i * (self.bandwidth + 1) + self.bandwidth - (i - j))
    }

    /// Entry (i, j) (zero outside the band).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.slot(i, j).map_or(0.0, |s| self.data[s])
    }

    /// Add `value` to entries (i, j) and (j, i). Panics if (i, j) lies outside the band: that is a bug in the
    /// caller's assembly, never a consequence of user input.
    pub fn add(&mut self, i: usize, j: usize, value: f64) {
        let slot = self.slot(i, j).expect("entry outside the band of a SymmetricBanded matrix");
        self.data[slot] += value;
    }

    /// Add w·h hᵀ for a sparse vector h given by ascending `dofs` (all within one band window) and `values`:
    /// the rank-one update of a Newton or penalty matrix, without bounds bookkeeping per entry.
    #[inline]
    pub fn add_outer(&mut self, dofs: &[usize], values: &[f64], w: f64) {
        let stride = self.bandwidth + 1;
        for a in 0..dofs.len() {
            let i = dofs[a];
            let wa = w * values[a];
            let row = i * stride + self.bandwidth;
            for b in 0..=a {
                let j = dofs[b];
                debug_assert!(i >= j && i - j <= self.bandwidth, "add_outer: entries outside the band or unsorted");
                self.data[row - (i - j)] += wa * values[b];
            }
        }
    }

    /// y = A x, row by row from the stored lower band (the upper band by symmetry). Products repeated every time
    /// step go through [`crate::BandDiagonals`], whose layout vectorises.
    pub fn mul_vec(&self, x: &[f64], y: &mut [f64]) {
        let b = self.bandwidth;
        y.iter_mut().for_each(|v| *v = 0.0);
        for i in 0..self.n {
            let row = &self.data[i * (b + 1)..(i + 1) * (b + 1)];
            let first = i.saturating_sub(b);
            let mut acc = row[b] * x[i];
            for j in first..i {
                let a = row[b - (i - j)];
                acc += a * x[j];
                y[j] += a * x[i];
            }
            y[i] += acc;
        }
    }

    /// The quadratic form xᵀ A x.
    pub fn quadratic_form(&self, x: &[f64]) -> f64 {
        let b = self.bandwidth;
        let mut sum = 0.0;
        for i in 0..self.n {
            let row = &self.data[i * (b + 1)..(i + 1) * (b + 1)];
            let mut off = 0.0;
            for j in i.saturating_sub(b)..i {
                off += row[b - (i - j)] * x[j];
            }
            sum += x[i] * (row[b] * x[i] + 2.0 * off);
        }
        sum
    }

    /// a·A + b·B + c·C for matrices of the same order and bandwidth (e.g. M̂ = M + hθC + h²θ²K).
    pub fn linear_combination(terms: &[(f64, &SymmetricBanded)]) -> Self {
        let first = terms.first().expect("at least one term").1;
        let mut out = Self::zeros(first.n, first.bandwidth);
        for (scale, m) in terms {
            assert!(m.n == out.n && m.bandwidth == out.bandwidth, "linear_combination of mismatched matrices");
            for (o, v) in out.data.iter_mut().zip(&m.data) {
                *o += scale * v;
            }
        }
        out
    }

    /// The dense copy (tests, eigenvalues, cross-checks).
    pub fn to_dense(&self) -> DMatrix<f64> {
        DMatrix::from_fn(self.n, self.n, |i, j| self.get(i, j))
    }

    /// Change the order to `n`, all entries zero (reuses the storage once it is large enough).
    pub fn resize(&mut self, n: usize) {
        self.n = n;
        self.data.clear();
        self.data.resize(n * (self.bandwidth + 1), 0.0);
    }

    /// The same matrix with the DOF order reversed (i → n − 1 − i).
    pub fn reversed(&self) -> SymmetricBanded {
        let mut out = Self::zeros(self.n, self.bandwidth);
        for i in 0..self.n {
            for j in i.saturating_sub(self.bandwidth)..=i {
                out.add(self.n - 1 - j, self.n - 1 - i, self.get(i, j));
            }
        }
        out
    }

    /// The stored lower band, b + 1 slots per row: row i is (A_{i,i−b}, …, A_ii), the slots before column 0 zero.
    pub fn lower_band(&self) -> &[f64] {
        &self.data
    }

    /// The stored lower band, mutable (as [`Self::lower_band`]). For assembly loops that add whole band rows at a
    /// time (see [`crate::BlockRows`]).
    pub fn lower_band_mut(&mut self) -> &mut [f64] {
        &mut self.data
    }

    /// Copy the principal submatrix of rows and columns [start, end) into `out` (resized to end − start).
    pub fn principal_submatrix_into(&self, start: usize, end: usize, out: &mut SymmetricBanded) {
        assert!(start <= end && end <= self.n && out.bandwidth == self.bandwidth, "principal_submatrix_into");
        out.resize(end - start);
        let w = self.bandwidth + 1;
        out.data.copy_from_slice(&self.data[start * w..end * w]);
        // Slots that reach before `start` belong to the eliminated block: clear them.
        for i in 0..(end - start).min(self.bandwidth) {
            for slot in 0..self.bandwidth - i {
                out.data[i * w + slot] = 0.0;
            }
        }
    }

    /// Append rows and columns [start, n) of `source` as a block of their own: the order grows by n − start and the
    /// new block is not coupled to the DOFs already here (their slots reaching before `start` are left out). For a
    /// window over one beam range that takes a vehicle's DOFs, decoupled from the beam in M̂, beside it.
    pub fn append_decoupled_block(&mut self, source: &SymmetricBanded, start: usize) {
        assert!(start <= source.n && self.bandwidth == source.bandwidth, "append_decoupled_block");
        let (w, first) = (self.bandwidth + 1, self.n);
        self.n += source.n - start;
        self.data.extend_from_slice(&source.data[start * w..source.n * w]);
        for i in 0..(source.n - start).min(self.bandwidth) {
            for slot in 0..self.bandwidth - i {
                self.data[(first + i) * w + slot] = 0.0;
            }
        }
    }

    /// The factorisation for half-bandwidth 3 (every Hermite beam matrix), unrolled: row i holds
    /// (A_{i,i−3}, A_{i,i−2}, A_{i,i−1}, A_ii) and becomes (L_{i,i−3}, L_{i,i−2}, L_{i,i−1}, D_i).
    fn factor_in_place_3(n: usize, f: &mut [f64], inverse_pivots: &mut [f64]) -> Result<()> {
        let mut above = RowsAbove3::START;
        for (i, (row, inverse)) in f.chunks_exact_mut(4).zip(inverse_pivots.iter_mut()).take(n).enumerate() {
            *inverse = above.next_row(i, row)?;
        }
        Ok(())
    }

    /// Overwrite this matrix with `other` (same bandwidth; the order follows `other`), without allocating once
    /// the storage is large enough.
    pub fn copy_from(&mut self, other: &SymmetricBanded) {
        assert!(self.bandwidth == other.bandwidth, "copy_from of matrices with different bandwidths");
        self.n = other.n;
        self.data.clear();
        self.data.extend_from_slice(&other.data);
    }

    /// Factor A = L D Lᵀ (L unit lower triangular with the same band). Errors with the equation index if a pivot
    /// is not strictly positive (A not positive definite) or not finite.
    pub fn factor(&self) -> Result<BandedLdlt> {
        let mut out = BandedLdlt { n: 0, bandwidth: self.bandwidth, factors: Vec::new(), inverse_pivots: Vec::new() };
        self.factor_into(&mut out)?;
        Ok(out)
    }

    /// Factor into existing storage (reshaped to this matrix; no allocation once its capacity suffices).
    pub fn factor_into(&self, out: &mut BandedLdlt) -> Result<()> {
        out.n = self.n;
        out.bandwidth = self.bandwidth;
        out.factors.clear();
        out.factors.extend_from_slice(&self.data);
        out.inverse_pivots.clear();
        out.inverse_pivots.resize(self.n, 0.0);
        Self::factor_in_place(self.n, self.bandwidth, &mut out.factors, &mut out.inverse_pivots)
    }

    fn factor_in_place(n: usize, b: usize, f: &mut [f64], inverse_pivots: &mut [f64]) -> Result<()> {
        if b == 3 {
            return Self::factor_in_place_3(n, f, inverse_pivots);
        }
        for i in 0..n {
            Self::factor_row(f, inverse_pivots, b, i)?;
        }
        Ok(())
    }

    /// Row i of the factor in place of row i of A, `f` holding the factor's rows above it (b + 1 slots a row):
    /// L_ij D_j = A_ij − Σ_{k<j} L_ik L_jk D_k, D_i = A_ii − Σ_{k<i} L_ik² D_k, and 1/D_i into `inverse_pivots`. An
    /// error names row i if D_i is not strictly positive. The one general row formula of the full factor and of the
    /// local refactor.
    #[inline]
    pub(crate) fn factor_row(f: &mut [f64], inverse_pivots: &mut [f64], b: usize, i: usize) -> Result<()> {
        let w = b + 1;
        let first = i.saturating_sub(b);
        for j in first..i {
            let mut s = f[i * w + b - (i - j)];
            for k in first.max(j.saturating_sub(b))..j {
                s -= f[i * w + b - (i - k)] * f[j * w + b - (j - k)] * f[k * w + b];
            }
            f[i * w + b - (i - j)] = s / f[j * w + b];
        }
        let mut d = f[i * w + b];
        for k in first..i {
            let l = f[i * w + b - (i - k)];
            d -= l * l * f[k * w + b];
        }
        if !(d.is_finite() && d > 0.0) {
            return Err(BandedError::NonPositivePivot { index: i, pivot: d });
        }
        f[i * w + b] = d;
        inverse_pivots[i] = 1.0 / d;
        Ok(())
    }
}

/// The three factor rows above row i of a half-bandwidth-3 LDLᵀ, as the b = 3 kernels carry them: the L entries of
/// rows i − 1 and i − 2, and D (with 1/D) of rows i − 1 … i − 3; rows before the first are zero with D = 1.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RowsAbove3 {
    /// (L_{i−1,i−4}, L_{i−1,i−3}, L_{i−1,i−2}).
    pub(crate) r1: [f64; 3],
    /// (L_{i−2,i−5}, L_{i−2,i−4}, L_{i−2,i−3}).
    pub(crate) r2: [f64; 3],
    pub(crate) d1: f64,
    pub(crate) d2: f64,
    pub(crate) d3: f64,
    pub(crate) e1: f64,
    pub(crate) e2: f64,
    pub(crate) e3: f64,
}

impl RowsAbove3 {
    /// Before row 0.
    pub(crate) const START: Self =
        Self { r1: [0.0; 3], r2: [0.0; 3], d1: 1.0, d2: 1.0, d3: 1.0, e1: 1.0, e2: 1.0, e3: 1.0 };

    /// Above row `i` of the factor `f` (rows of 4 slots: L_{i,i−3}, L_{i,i−2}, L_{i,i−1}, D_i) with its `inverse`
    /// pivots.
    pub(crate) fn of(f: &[f64], inverse: &[f64], i: usize) -> Self {
        let mut above = Self::START;
        for k in i.saturating_sub(3)..i {
            let row = &f[4 * k..4 * k + 4];
            above.shift([row[0], row[1], row[2]], row[3], inverse[k]);
        }
        above
    }

    /// Row `i` of the factor in place of row `row` of A = (A_{i,i−3}, A_{i,i−2}, A_{i,i−1}, A_ii): it becomes
    /// (L_{i,i−3}, L_{i,i−2}, L_{i,i−1}, D_i), this state moves down a row, and 1/D_i is returned. An error names
    /// row `i` if its pivot is not strictly positive. The one b = 3 row formula of the full factor and of the local
    /// refactor.
    #[inline(always)]
    pub(crate) fn next_row(&mut self, i: usize, row: &mut [f64]) -> Result<f64> {
        let a = [row[0], row[1], row[2], row[3]];
        let l3 = if i >= 3 { a[0] * self.e3 } else { 0.0 };
        let l2 = if i >= 2 { (a[1] - l3 * self.r2[2] * self.d3) * self.e2 } else { 0.0 };
        let l1 = if i >= 1 { (a[2] - l3 * self.r1[1] * self.d3 - l2 * self.r1[2] * self.d2) * self.e1 } else { 0.0 };
        let d = a[3] - l3 * l3 * self.d3 - l2 * l2 * self.d2 - l1 * l1 * self.d1;
        if !(d.is_finite() && d > 0.0) {
            return Err(BandedError::NonPositivePivot { index: i, pivot: d });
        }
        let e = 1.0 / d;
        row[0] = l3;
        row[1] = l2;
        row[2] = l1;
        row[3] = d;
        self.shift([l3, l2, l1], d, e);
        Ok(e)
    }

    /// Move down a row past the factor row (`l`, `d`, `e` = 1/d).
    #[inline(always)]
    fn shift(&mut self, l: [f64; 3], d: f64, e: f64) {
        (self.r2, self.r1) = (self.r1, l);
        (self.d3, self.d2, self.d1) = (self.d2, self.d1, d);
        (self.e3, self.e2, self.e1) = (self.e2, self.e1, e);
    }
}

/// The LDLᵀ factors of a [`SymmetricBanded`] SPD matrix: L's strict lower band and D on the diagonal slots, and
/// 1/D apart so that solves multiply instead of divide.
#[derive(Debug, Clone, PartialEq)]
pub struct BandedLdlt {
    pub(crate) n: usize,
    pub(crate) bandwidth: usize,
    /// Row i holds L_{i,i−b} … L_{i,i−1} and D_i, `bandwidth + 1` entries a row.
    pub(crate) factors: Vec<f64>,
    pub(crate) inverse_pivots: Vec<f64>,
}

impl BandedLdlt {
    /// Order n.
    pub fn order(&self) -> usize {
        self.n
    }

    /// Solve A x = rhs in place (forward substitution, diagonal scaling, back substitution): O(n·b) flops,
    /// no allocation.
    pub fn solve_in_place(&self, x: &mut [f64]) {
        assert_eq!(x.len(), self.n, "right-hand side length");
        match self.bandwidth {
            3 => return self.solve_in_place_3(x),
            4 => return self.solve_in_place_4(x),
            _ => {}
        }
        let b = self.bandwidth;
        let w = b + 1;
        let f = &self.factors;
        for i in 0..self.n {
            let row = &f[i * w..(i + 1) * w];
            let mut s = x[i];
            for j in i.saturating_sub(b)..i {
                s -= row[b - (i - j)] * x[j];
            }
            x[i] = s;
        }
        for (x, e) in x.iter_mut().zip(&self.inverse_pivots) {
            *x *= e;
        }
        for i in (0..self.n).rev() {
            let xi = x[i];
            let row = &f[i * w..(i + 1) * w];
            for j in i.saturating_sub(b)..i {
                x[j] -= row[b - (i - j)] * xi;
            }
        }
    }

    /// [`BandedLdlt::solve_in_place`] unrolled for half-bandwidth 3.
    fn solve_in_place_3(&self, x: &mut [f64]) {
        let f = &self.factors;
        let n = self.n;
        let (mut y1, mut y2, mut y3) = (0.0, 0.0, 0.0);
        // Rows of 4 zipped with x: no bounds checks in the loops.
        debug_assert_eq!(f.len(), 4 * n);
        // Each row waits only on y_{i−1}: the terms in y_{i−3}, y_{i−2} are formed first, off the critical path
        // (one multiply and one subtraction per row instead of three of each; about twice as fast, the pass being
        // latency-bound).
        for (row, xi) in f.chunks_exact(4).zip(x.iter_mut()) {
            let y = (*xi - row[0] * y3 - row[1] * y2) - row[2] * y1;
            *xi = y;
            (y3, y2, y1) = (y2, y1, y);
        }
        // Backward: x_i = y_i/D_i − L_{i+1,i} x_{i+1} − L_{i+2,i} x_{i+2} − L_{i+3,i} x_{i+3}, carrying the L rows
        // below (zero past the end) instead of testing bounds.
        let (mut x1, mut x2, mut x3) = (0.0, 0.0, 0.0);
        let (mut below1, mut below2, mut below3) = ([0.0f64; 3], [0.0f64; 3], [0.0f64; 3]);
        for ((row, x_i), e) in f.chunks_exact(4).zip(x.iter_mut()).zip(&self.inverse_pivots).rev() {
            let xi = (*x_i * e - below3[0] * x3 - below2[1] * x2) - below1[2] * x1;
            *x_i = xi;
            (x3, x2, x1) = (x2, x1, xi);
            (below3, below2, below1) = (below2, below1, [row[0], row[1], row[2]]);
        }
    }

    /// [`BandedLdlt::solve_in_place_3`] for half-bandwidth 4 (a rail on sleepers), in the same order: each row's
    /// terms in y_{i−4} … y_{i−2} first, y_{i−1} last, the last four values and the L rows below carried in
    /// registers (a const-generic loop shifting arrays instead spent 66 % of the discrete-track benchmark's run in
    /// this solve, against 45 % here: perf, 2026-11-27).
    fn solve_in_place_4(&self, x: &mut [f64]) {
        let f = &self.factors;
        debug_assert_eq!(f.len(), 5 * self.n);
        let (mut y1, mut y2, mut y3, mut y4) = (0.0, 0.0, 0.0, 0.0);
        for (row, xi) in f.chunks_exact(5).zip(x.iter_mut()) {
            let y = (*xi - row[0] * y4 - row[1] * y3 - row[2] * y2) - row[3] * y1;
            *xi = y;
            (y4, y3, y2, y1) = (y3, y2, y1, y);
        }
        let (mut x1, mut x2, mut x3, mut x4) = (0.0, 0.0, 0.0, 0.0);
        let (mut below1, mut below2, mut below3, mut below4) = ([0.0f64; 4], [0.0f64; 4], [0.0f64; 4], [0.0f64; 4]);
        for ((row, x_i), e) in f.chunks_exact(5).zip(x.iter_mut()).zip(&self.inverse_pivots).rev() {
            let xi = (*x_i * e - below4[0] * x4 - below3[1] * x3 - below2[2] * x2) - below1[3] * x1;
            *x_i = xi;
            (x4, x3, x2, x1) = (x3, x2, x1, xi);
            (below4, below3, below2, below1) = (below3, below2, below1, [row[0], row[1], row[2], row[3]]);
        }
    }

    /// Solve A x = rhs, returning x.
    pub fn solve(&self, rhs: &[f64]) -> Vec<f64> {
        let mut x = rhs.to_vec();
        self.solve_in_place(&mut x);
        x
    }

    /// Subtract from `target` — the principal submatrix A[start..start + target.order()] of the factored matrix A —
    /// the Schur-complement correction of eliminating the leading block [0, start):
    /// C_ij = Σ_{k<start} L_ik D_k L_jk, non-zero only for i, j < start + b.
    pub fn subtract_leading_schur(&self, start: usize, target: &mut SymmetricBanded) {
        self.subtract_schur(start, target, |i| i - start);
    }

    /// For the factor of the *reversed* matrix (see [`SymmetricBanded::reversed`]), subtract from `target` — the
    /// principal submatrix A[start..end] of the original A, end = start + target.order() — the Schur-complement
    /// correction of eliminating the trailing block [end, n) of A.
    pub fn subtract_trailing_schur(&self, end: usize, target: &mut SymmetricBanded) {
        let start = end - target.order();
        let n = self.n;
        self.subtract_schur(n - end, target, |i| n - 1 - i - start);
    }

    fn subtract_schur(&self, eliminated: usize, target: &mut SymmetricBanded, local: impl Fn(usize) -> usize) {
        let (b, w) = (self.bandwidth, self.bandwidth + 1);
        let f = &self.factors;
        let last = (eliminated + b).min(self.n).min(eliminated + target.order());
        for i in eliminated..last {
            for j in eliminated..=i {
                let mut c = 0.0;
                for k in i.saturating_sub(b)..eliminated {
                    c += f[i * w + b - (i - k)] * f[k * w + b] * f[j * w + b - (j - k)];
                }
                if c != 0.0 {
                    target.add(local(i), local(j), -c);
                }
            }
        }
    }

    /// The diagonal pivots D (all > 0).
    pub fn pivots(&self) -> impl Iterator<Item = f64> + '_ {
        let w = self.bandwidth + 1;
        (0..self.n).map(move |i| self.factors[i * w + self.bandwidth])
    }
}
