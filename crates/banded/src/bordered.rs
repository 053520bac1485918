//! The LDLᵀ factors of a small dense symmetric matrix grown one row and column at a time (bordering): the
//! capacitance systems of low-rank corrections, whose order grows with the corrections.
//!
//! With C = L D Lᵀ (L unit lower triangular) and C bordered by a row (cᵀ, γ), the factors grow by one row:
//!
//! ```text
//! u = L⁻¹c (forward substitution),   l = D⁻¹u,   d = γ − lᵀu,
//! ```
//!
//! O(k²) for the k-th row, so k rows cost O(k³/3) in all — the same arithmetic as a column-wise LDLᵀ of the whole
//! matrix. No pivoting: for a symmetric positive definite C every d > 0; for an indefinite one (a correction that
//! adds and removes terms) the caller judges each new pivot and refuses a row whose d is tiny against its entries.

/// LDLᵀ of a symmetric k × k matrix, k ≤ the capacity, stored row-major with a fixed stride: L's entries below the
/// diagonal, D on it.
#[derive(Debug, Clone, Default)]
pub struct BorderedLdlt {
    stride: usize,
    len: usize,
    factors: Vec<f64>,
}

impl BorderedLdlt {
    /// Room for `capacity` rows without allocating.
    pub fn with_capacity(capacity: usize) -> Self {
        Self { stride: capacity, len: 0, factors: vec![0.0; capacity * capacity] }
    }

    /// Forget every row, keeping room for at least `capacity` (reallocates only to grow).
    pub fn clear(&mut self, capacity: usize) {
        self.len = 0;
        if capacity > self.stride {
            *self = Self::with_capacity(capacity);
        }
    }

    /// The order k.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no row has been added.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Rows the factor holds without reallocating.
    pub fn capacity(&self) -> usize {
        self.stride
    }

    /// The pivot d the row `row` = (C_k0, …, C_k,k−1, C_kk) would get, its factor row computed into the next slot
    /// (which [`BorderedLdlt::accept`] then makes part of the factor). Panics beyond the capacity.
    pub fn border(&mut self, row: &[f64]) -> f64 {
        let (k, stride) = (self.len, self.stride);
        assert!(k < stride && row.len() == k + 1, "BorderedLdlt::border: row {} of {stride}", row.len());
        let f = &mut self.factors;
        let mut pivot = row[k];
        for i in 0..k {
            let mut u = row[i];
            for l in 0..i {
                u -= f[i * stride + l] * f[k * stride + l] * f[l * stride + l];
            }
            let value = u / f[i * stride + i];
            f[k * stride + i] = value;
            pivot -= value * u;
        }
        f[k * stride + k] = pivot;
        pivot
    }

    /// Take the row last passed to [`BorderedLdlt::border`] into the factor.
    pub fn accept(&mut self) {
        assert!(self.len < self.stride, "BorderedLdlt::accept without a row");
        self.len += 1;
    }

    /// x ← C⁻¹x (the first k entries).
    pub fn solve_in_place(&self, x: &mut [f64]) {
        let (k, stride, f) = (self.len, self.stride, &self.factors);
        for r in 0..k {
            let mut s = x[r];
            for c in 0..r {
                s -= f[r * stride + c] * x[c];
            }
            x[r] = s;
        }
        for r in 0..k {
            x[r] /= f[r * stride + r];
        }
        for r in (0..k).rev() {
            let mut s = x[r];
            for c in r + 1..k {
                s -= f[c * stride + r] * x[c];
            }
            x[r] = s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Grown row by row, the factor of an indefinite symmetric matrix solves it as a dense LU does; a row it is not
    /// told to accept leaves it unchanged, and growing past the capacity in `clear` reallocates.
    #[test]
    fn bordering_solves_the_matrix() {
        let k = 6;
        let entry = |i: usize, j: usize| {
            let (i, j) = (i.max(j), i.min(j));
            if i == j { [3.0, -2.5, 4.0, -1.5, 5.0, 2.0][i] } else { 0.3 * ((i * 7 + j * 3) % 5) as f64 - 0.6 }
        };
        let mut ldlt = BorderedLdlt::with_capacity(2);
        ldlt.clear(k);
        assert_eq!(ldlt.capacity(), k);
        for i in 0..k {
            let row: Vec<f64> = (0..=i).map(|j| entry(i, j)).collect();
            if i == 3 {
                ldlt.border(&[1.0, 1.0, 1.0, 1.0]);
            }
            let pivot = ldlt.border(&row);
            assert!(pivot.abs() > 1e-3, "row {i}: pivot {pivot}");
            ldlt.accept();
        }
        let dense = nalgebra::DMatrix::from_fn(k, k, entry);
        let mut x: Vec<f64> = (0..k).map(|i| (0.7 * i as f64).sin()).collect();
        let expected = dense.lu().solve(&nalgebra::DVector::from_vec(x.clone())).expect("regular");
        ldlt.solve_in_place(&mut x);
        let worst = x.iter().zip(expected.iter()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        assert!(worst < 1e-12, "largest difference {worst:e}");
    }
}
