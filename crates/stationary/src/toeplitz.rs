//! A Toeplitz matrix applied by the FFT: y_i = Σ_j t(i − j) x_j for i, j < n is a circular convolution of length
//! m ≥ 2n − 1 (the matrix embedded in a circulant, Golub & Van Loan 2013, §4.8), so one forward and one inverse FFT of
//! length m, O(m log m), replace the n² products. The ground's influence between the points of a moving window is
//! Toeplitz: the wave at s_i of a unit force at s_j depends on s_i − s_j only.

use num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// A real n × n Toeplitz matrix, ready to multiply vectors.
#[derive(Clone)]
pub struct Toeplitz {
    size: usize,
    /// The FFT of the circulant's first column, divided by m (the inverse FFT is unnormalised).
    column_spectrum: Vec<Complex64>,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for Toeplitz {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Toeplitz").field("size", &self.size).field("fft_length", &self.column_spectrum.len()).finish()
    }
}

impl Toeplitz {
    /// The matrix with t(d) = `diagonals[d + n − 1]` for d = −(n − 1) … n − 1 (so `diagonals` holds 2n − 1 values,
    /// n ≥ 1; its length sets n).
    pub fn new(diagonals: &[f64]) -> Self {
        assert!(diagonals.len() % 2 == 1, "a Toeplitz matrix of order n has 2n − 1 diagonals");
        let size = diagonals.len().div_ceil(2);
        let length = (2 * size - 1).next_power_of_two().max(2);
        let mut column = vec![Complex64::new(0.0, 0.0); length];
        for d in 0..size {
            column[d] = Complex64::new(diagonals[d + size - 1], 0.0);
        }
        for d in 1..size {
            column[length - d] = Complex64::new(diagonals[size - 1 - d], 0.0);
        }
        let mut planner = FftPlanner::new();
        let (forward, inverse) = (planner.plan_fft_forward(length), planner.plan_fft_inverse(length));
        forward.process(&mut column);
        let scale = 1.0 / length as f64;
        column.iter_mut().for_each(|c| *c *= scale);
        Self { size, column_spectrum: column, forward, inverse }
    }

    /// n.
    pub fn size(&self) -> usize {
        self.size
    }

    /// T x (`x` of length n).
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        assert_eq!(x.len(), self.size, "a vector of the matrix's order");
        let mut padded = vec![Complex64::new(0.0, 0.0); self.column_spectrum.len()];
        padded.iter_mut().zip(x).for_each(|(p, x)| p.re = *x);
        self.forward.process(&mut padded);
        padded.iter_mut().zip(&self.column_spectrum).for_each(|(p, c)| *p *= c);
        self.inverse.process(&mut padded);
        padded[..self.size].iter().map(|p| p.re).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT product equals the n² sum to round-off (1e-12 of Σ|t||x|: ~log₂ m roundings of each term).
    #[test]
    fn the_fft_product_is_the_direct_one() {
        for n in [1usize, 2, 7, 64, 300] {
            let diagonals: Vec<f64> = (0..2 * n - 1).map(|d| ((d as f64) * 0.37).sin() + 0.1 * d as f64).collect();
            let x: Vec<f64> = (0..n).map(|i| ((i as f64) * 1.3).cos()).collect();
            let t = |i: usize, j: usize| diagonals[i + n - 1 - j];
            let direct: Vec<f64> = (0..n).map(|i| (0..n).map(|j| t(i, j) * x[j]).sum()).collect();
            let scale: f64 = diagonals.iter().map(|d| d.abs()).sum::<f64>() * 1.0;
            for (a, b) in Toeplitz::new(&diagonals).apply(&x).iter().zip(&direct) {
                assert!((a - b).abs() <= 1e-12 * scale, "n = {n}: {a} vs {b}");
            }
        }
    }
}
