//! A symmetric banded matrix stored by diagonals, for products repeated thousands of times.
//!
//! [`SymmetricBanded`] keeps its lower band row by row, the layout the LDLᵀ factorisation wants; a product in that
//! layout gathers 13 scattered entries per row and does not vectorise. Stored by diagonals — `e_k[i]` = A_{i,i−k}
//! (zero for i < k), k = 0…b — the product
//!
//! ```text
//! y_i = e_0[i] x_i + Σ_{k=1..b} ( e_k[i] x_{i−k} + e_k[i+k] x_{i+k} )
//! ```
//!
//! reads only contiguous slices, so the compiler turns each term into packed multiply–adds over whole rows.

use crate::symmetric::SymmetricBanded;

/// The diagonals e_0…e_b of a symmetric banded matrix (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct BandDiagonals {
    n: usize,
    diagonals: Vec<Vec<f64>>,
}

impl BandDiagonals {
    /// The diagonals of `a`.
    pub fn new(a: &SymmetricBanded) -> Self {
        let n = a.order();
        let diagonals =
            (0..=a.bandwidth()).map(|k| (0..n).map(|i| if i >= k { a.get(i, i - k) } else { 0.0 }).collect()).collect();
        Self { n, diagonals }
    }

    /// Order n.
    pub fn order(&self) -> usize {
        self.n
    }

    /// y = A x.
    pub fn mul_vec(&self, x: &[f64], y: &mut [f64]) {
        let n = self.n;
        assert!(x.len() == n && y.len() == n, "BandDiagonals::mul_vec: vectors of length {n} expected");
        match self.diagonals.len() {
            4 if n > 6 => return self.mul_vec_fixed::<3>(x, y),
            5 if n > 8 => return self.mul_vec_fixed::<4>(x, y),
            _ => {}
        }
        for ((y, e), x) in y.iter_mut().zip(&self.diagonals[0]).zip(x) {
            *y = e * x;
        }
        for (k, e) in self.diagonals.iter().enumerate().skip(1).filter(|&(k, _)| k < n) {
            // Below the diagonal: y_i += A_{i,i−k} x_{i−k} for i ≥ k; above: y_i += A_{i+k,i} x_{i+k} for i < n − k.
            let m = n - k;
            for ((y, e), x) in y[k..].iter_mut().zip(&e[k..]).zip(&x[..m]) {
                *y += e * x;
            }
            for ((y, e), x) in y[..m].iter_mut().zip(&e[k..]).zip(&x[k..]) {
                *y += e * x;
            }
        }
    }

    /// y = A x for half-bandwidth B (3: every Hermite beam matrix; 4: a rail on sleepers) in one pass over the rows:
    /// the interior rows read 4B + 2 equally long, shifted slices, so the loop has no bounds checks and runs on packed
    /// registers. It agrees with [`SymmetricBanded::mul_vec`] to round-off (the terms are summed in another order).
    /// (Fusing the three products of a time step into one pass over x measured no faster: 1.68 against 1.88 µs,
    /// within the noise.)
    fn mul_vec_fixed<const B: usize>(&self, x: &[f64], y: &mut [f64]) {
        let n = self.n;
        let entry = |i: usize, j: usize| if i >= j { self.diagonals[i - j][i] } else { self.diagonals[j - i][j] };
        for i in (0..B).chain(n - B..n) {
            y[i] = (i.saturating_sub(B)..(i + B + 1).min(n)).map(|j| entry(i, j) * x[j]).sum();
        }
        let m = n - 2 * B;
        // Interior row i (B ≤ i < n − B) is element i − B of every slice below: x_{i∓k} and A_{i,i−k} = e_k[i]
        // (lower), A_{i,i+k} = e_k[i+k] (upper), k = 1…B.
        let rows = Interior::<B> {
            diagonal: &self.diagonals[0][B..B + m],
            x: &x[B..B + m],
            lower: std::array::from_fn(|k| &self.diagonals[k + 1][B..B + m]),
            x_lower: std::array::from_fn(|k| &x[B - k - 1..B - k - 1 + m]),
            upper: std::array::from_fn(|k| &self.diagonals[k + 1][B + k + 1..B + k + 1 + m]),
            x_upper: std::array::from_fn(|k| &x[B + k + 1..B + k + 1 + m]),
        };
        let y = &mut y[B..B + m];
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code)]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above); the kernel is plain safe Rust otherwise.
            return unsafe { rows.product_avx2(y) };
        }
        rows.product(y);
    }
}

/// The interior rows of a half-bandwidth-B product as equally long slices (see [`BandDiagonals::mul_vec`]); index k
/// of each array is the (k + 1)-th diagonal.
struct Interior<'a, const B: usize> {
    diagonal: &'a [f64],
    x: &'a [f64],
    lower: [&'a [f64]; B],
    x_lower: [&'a [f64]; B],
    upper: [&'a [f64]; B],
    x_upper: [&'a [f64]; B],
}

impl<const B: usize> Interior<'_, B> {
    /// y_i = A_ii x_i + Σ_k (A_{i,i−k} x_{i−k} + A_{i,i+k} x_{i+k}), summed in that order, each pair first.
    #[inline(always)]
    fn product(&self, y: &mut [f64]) {
        let m = y.len();
        // Every slice is m long: said once, so that the loop below indexes without checks.
        let (d, x) = (&self.diagonal[..m], &self.x[..m]);
        let lower = self.lower.map(|s| &s[..m]);
        let x_lower = self.x_lower.map(|s| &s[..m]);
        let upper = self.upper.map(|s| &s[..m]);
        let x_upper = self.x_upper.map(|s| &s[..m]);
        for (i, y) in y.iter_mut().enumerate() {
            let mut sum = d[i] * x[i];
            for k in 0..B {
                sum += lower[k][i] * x_lower[k][i] + upper[k][i] * x_upper[k][i];
            }
            *y = sum;
        }
    }

    /// [`Interior::product`] compiled for AVX2: four rows per instruction instead of two, the same operations in
    /// the same order (no fused multiply–add), so the same bits: 0.55 against 0.60–0.68 µs for 402 rows.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[allow(unsafe_code)]
    unsafe fn product_avx2(&self, y: &mut [f64]) {
        self.product(y)
    }
}
