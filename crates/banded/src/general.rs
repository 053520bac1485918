//! General (non-symmetric) banded matrices and their LU factorisation with partial pivoting, as LAPACK's `dgbtrf`
//! (Golub & Van Loan 2013, §4.3.5): the moving-frame operator of a beam, EI∂⁴ + ρAv²∂² − c_f v∂ + k, is banded but
//! not symmetric (the convective term), and indefinite above the critical speed.
//!
//! Storage: row i holds columns i − kl … i + kl + ku (the ku upper diagonals plus the kl more that row exchanges can
//! fill in), entry (i, j) at `data[i·w + (j + kl − i)]` with w = 2kl + ku + 1. Factor O(n·kl·(kl + ku)), solve
//! O(n·(2kl + ku)).

use crate::error::{BandedError, Result};
use num_complex::Complex64;
use std::ops::{Add, AddAssign, Div, Mul, Sub, SubAssign};

/// An entry of a general banded matrix: real (f64) or complex (a dynamic stiffness K + iωC − ω²M, Complex64).
pub trait Entry:
    Copy
    + PartialEq
    + std::fmt::Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + AddAssign
    + SubAssign
    + std::iter::Sum
{
    /// 0.
    const ZERO: Self;
    /// |x|: what partial pivoting compares.
    fn magnitude(self) -> f64;
}

impl Entry for f64 {
    const ZERO: Self = 0.0;
    fn magnitude(self) -> f64 {
        self.abs()
    }
}

impl Entry for Complex64 {
    const ZERO: Self = Complex64::new(0.0, 0.0);
    fn magnitude(self) -> f64 {
        self.norm()
    }
}

/// An n×n matrix with kl sub- and ku super-diagonals, of real entries unless said otherwise.
#[derive(Debug, Clone, PartialEq)]
pub struct GeneralBanded<T = f64> {
    n: usize,
    lower: usize,
    upper: usize,
    data: Vec<T>,
}

impl<T: Entry> GeneralBanded<T> {
    /// The zero matrix of order `n` with `lower` sub- and `upper` super-diagonals.
    pub fn zeros(n: usize, lower: usize, upper: usize) -> Self {
        Self { n, lower, upper, data: vec![T::ZERO; n * (2 * lower + upper + 1)] }
    }

    /// Order n.
    pub fn order(&self) -> usize {
        self.n
    }

    fn width(&self) -> usize {
        2 * self.lower + self.upper + 1
    }

    #[inline]
    fn slot(&self, i: usize, j: usize) -> Option<usize> {
        let offset = (j + self.lower).checked_sub(i)?;
        (i < self.n && j < self.n && offset < self.width()).then(|| i * self.width() + offset)
    }

    /// Entry (i, j) (zero outside the stored band).
    pub fn get(&self, i: usize, j: usize) -> T {
        self.slot(i, j).map_or(T::ZERO, |s| self.data[s])
    }

    /// Add `value` to entry (i, j). Panics outside the band (i − kl ≤ j ≤ i + ku): an assembly bug of the caller,
    /// never a consequence of user input.
    pub fn add(&mut self, i: usize, j: usize, value: T) {
        assert!(j + self.lower >= i && j <= i + self.upper, "entry ({i}, {j}) outside the band");
        let slot = self.slot(i, j).expect("entry outside the matrix");
        self.data[slot] += value;
    }

    /// y = A x.
    pub fn mul_vec(&self, x: &[T], y: &mut [T]) {
        for (i, yi) in y.iter_mut().enumerate().take(self.n) {
            let (first, last) = (i.saturating_sub(self.lower), (i + self.upper).min(self.n - 1));
            *yi = (first..=last).map(|j| self.data[i * self.width() + j + self.lower - i] * x[j]).sum();
        }
    }

    /// LU with partial pivoting; a zero pivot column (the matrix singular to working precision: every candidate
    /// below 1e-300 of the column's scale) is an error naming the equation.
    pub fn factor(mut self) -> Result<GeneralLu<T>> {
        let (n, kl, w) = (self.n, self.lower, self.width());
        let mut pivots = vec![0usize; n];
        // The last column row i can reach after fill-in.
        let reach = |i: usize| (i + kl + self.upper).min(n - 1);
        for k in 0..n {
            let last_row = (k + kl).min(n - 1);
            let (mut p, mut best) = (k, 0.0f64);
            for i in k..=last_row {
                let v = self.data[i * w + k + kl - i].magnitude();
                if v > best {
                    (p, best) = (i, v);
                }
            }
            if best.is_nan() || best <= 1e-300 || best.is_infinite() {
                return Err(BandedError::Singular { index: k });
            }
            pivots[k] = p;
            if p != k {
                for j in k..=reach(k) {
                    let (a, b) = (k * w + j + kl - k, p * w + j + kl - p);
                    self.data.swap(a, b);
                }
            }
            let pivot = self.data[k * w + kl];
            for i in k + 1..=last_row {
                let factor = self.data[i * w + k + kl - i] / pivot;
                self.data[i * w + k + kl - i] = factor;
                if factor != T::ZERO {
                    for j in k + 1..=reach(k) {
                        let u = self.data[k * w + j + kl - k];
                        self.data[i * w + j + kl - i] -= factor * u;
                    }
                }
            }
        }
        Ok(GeneralLu { matrix: self, pivots })
    }
}

/// The factors L U = P A of a [`GeneralBanded`] matrix.
#[derive(Debug, Clone)]
pub struct GeneralLu<T = f64> {
    matrix: GeneralBanded<T>,
    pivots: Vec<usize>,
}

impl<T: Entry> GeneralLu<T> {
    /// Solve A x = b in place (b in, x out).
    pub fn solve_in_place(&self, b: &mut [T]) {
        let a = &self.matrix;
        let (n, kl, w) = (a.n, a.lower, a.width());
        for k in 0..n {
            b.swap(k, self.pivots[k]);
            let bk = b[k];
            for i in k + 1..=(k + kl).min(n - 1) {
                b[i] -= a.data[i * w + k + kl - i] * bk;
            }
        }
        for k in (0..n).rev() {
            let last = (k + kl + a.upper).min(n - 1);
            let mut s = b[k];
            for j in k + 1..=last {
                s -= a.data[k * w + j + kl - k] * b[j];
            }
            b[k] = s / a.data[k * w + kl];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// A random non-symmetric banded matrix whose diagonal is small, so that pivoting must exchange rows (with both
    /// bands present: a triangular matrix with a tiny diagonal would be hopelessly ill-conditioned, so that one gets a
    /// dominant diagonal).
    fn sample(n: usize, kl: usize, ku: usize, seed: u64) -> (GeneralBanded, DMatrix<f64>) {
        let mut state = seed;
        let mut next = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        let mut banded = GeneralBanded::zeros(n, kl, ku);
        let mut dense = DMatrix::zeros(n, n);
        for i in 0..n {
            for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                let v = match (i == j, kl > 0 && ku > 0) {
                    (true, true) => 1e-3 * next(),
                    (true, false) => 2.0 + next(),
                    (false, _) => next(),
                };
                banded.add(i, j, v);
                dense[(i, j)] = v;
            }
        }
        (banded, dense)
    }

    #[test]
    fn solves_as_the_dense_lu_with_row_exchanges() {
        for (n, kl, ku, seed) in [(40, 3, 3, 1), (57, 7, 7, 2), (30, 2, 5, 3), (12, 0, 4, 4), (25, 4, 0, 5)] {
            let (banded, dense) = sample(n, kl, ku, seed);
            let b: Vec<f64> = (0..n).map(|i| (i as f64).sin()).collect();
            let mut x = b.clone();
            banded.clone().factor().unwrap().solve_in_place(&mut x);
            let reference = dense.clone().lu().solve(&DVector::from_vec(b.clone())).unwrap();
            // Both are backward stable; the condition numbers of these samples are below 1e6.
            let error = (DVector::from_vec(x.clone()) - &reference).amax() / reference.amax();
            assert!(error <= 1e-9, "n {n} kl {kl} ku {ku}: {error:e}");
            let mut y = vec![0.0; n];
            banded.mul_vec(&x, &mut y);
            // Backward stability: ‖Ax − b‖ ≤ c·ε‖A‖‖x‖ (x is large where a tiny pivot sits on the diagonal).
            let residual = y.iter().zip(&b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            let scale = dense.abs().row_sum().amax() * x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            assert!(residual <= 1e-13 * scale, "{residual:e} of {scale:e}");
        }
    }

    /// Complex entries (a dynamic stiffness): the same LU against nalgebra's dense complex LU, to the same bound.
    #[test]
    fn complex_entries_solve_as_the_dense_lu() {
        let (n, kl, ku) = (40, 3, 3);
        let ((re, dense_re), (im, dense_im)) = (sample(n, kl, ku, 7), sample(n, kl, ku, 8));
        let mut banded = GeneralBanded::<Complex64>::zeros(n, kl, ku);
        for i in 0..n {
            for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                banded.add(i, j, Complex64::new(re.get(i, j), im.get(i, j)));
            }
        }
        let dense = DMatrix::from_fn(n, n, |i, j| Complex64::new(dense_re[(i, j)], dense_im[(i, j)]));
        let b: Vec<Complex64> = (0..n).map(|i| Complex64::new((i as f64).sin(), (i as f64).cos())).collect();
        let mut x = b.clone();
        banded.factor().unwrap().solve_in_place(&mut x);
        let reference = dense.lu().solve(&DVector::from_vec(b)).unwrap();
        let scale = reference.iter().fold(0.0f64, |m, v| m.max(v.norm()));
        let error = x.iter().zip(reference.iter()).fold(0.0f64, |m, (a, b)| m.max((a - b).norm())) / scale;
        assert!(error <= 1e-9, "{error:e}");
    }

    #[test]
    fn a_singular_matrix_is_an_error_naming_the_equation() {
        let mut a = GeneralBanded::zeros(3, 1, 1);
        a.add(0, 0, 1.0);
        a.add(1, 0, 0.0);
        a.add(2, 2, 1.0);
        assert_eq!(a.factor().unwrap_err(), BandedError::Singular { index: 1 });
    }
}
