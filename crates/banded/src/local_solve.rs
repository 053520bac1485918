//! Local solves: A⁻¹h for a right-hand side h with a few neighbouring non-zeros, computed only where it matters.
//!
//! For a banded SPD A whose inverse decays away from the diagonal (a beam's iteration matrix M̂, or M̂ plus stiff
//! terms), x = A⁻¹h is significant only near h's support. The forward substitution L z = h starts at h's first
//! non-zero (z is zero before it) and stops once b consecutive entries of D⁻¹z past h's last non-zero have fallen
//! below `drop` times the largest; the back substitution Lᵀx = D⁻¹z starts there and stops the same way above h's first
//! non-zero. The entries left out are below `drop` of the largest (up to the decay rate's constant): the cost is
//! the support's length, not the order of A.

use crate::symmetric::BandedLdlt;

/// A vector kept on an index range [start, start + values.len()) of a longer one, zero elsewhere.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LocalVector {
    /// The first index kept.
    pub start: usize,
    /// The entries from `start` on.
    pub values: Vec<f64>,
}

impl LocalVector {
    /// One past the last index kept.
    pub fn end(&self) -> usize {
        self.start + self.values.len()
    }

    /// Σ_k a_k x_{first+k}: the product with a row of consecutive entries `a` from index `first` (entries outside
    /// the kept range count as zero).
    #[inline]
    pub fn dot_consecutive(&self, first: usize, a: &[f64]) -> f64 {
        // The overlap of [first, first + a.len()) with the kept range, summed in ascending order.
        let (low, high) = (first.max(self.start), (first + a.len()).min(self.end()));
        let mut s = 0.0;
        for i in low..high {
            s += a[i - first] * self.values[i - self.start];
        }
        s
    }
}

impl BandedLdlt {
    /// x ≈ A⁻¹h for the sparse h of (index, value) `entries` (ascending indices), into `out`: exact on the range
    /// kept, every entry left out below `drop` × max|x| (to the decay's constant). No allocation once `out` and
    /// `scratch` have grown to the range's length.
    pub fn solve_local(&self, entries: &[(usize, f64)], drop: f64, out: &mut LocalVector, scratch: &mut Vec<f64>) {
        if self.bandwidth == 3 {
            return self.solve_local_3(entries, drop, out, scratch);
        }
        let (n, b, w) = (self.n, self.bandwidth, self.bandwidth + 1);
        let f = &self.factors;
        out.values.clear();
        let Some(&(first, _)) = entries.first() else {
            out.start = 0;
            return;
        };
        let last = entries.last().map_or(first, |e| e.0);
        // Forward: z_i = h_i − Σ_{j<i} L_ij z_j from `first` on, into `scratch` (index i at i − first).
        scratch.clear();
        let mut largest: f64 = 0.0;
        let mut quiet = 0;
        let mut next_entry = 0;
        let mut i = first;
        while i < n {
            let mut s = 0.0;
            if next_entry < entries.len() && entries[next_entry].0 == i {
                s = entries[next_entry].1;
                next_entry += 1;
            }
            for j in i.saturating_sub(b).max(first)..i {
                s -= f[i * w + b - (i - j)] * scratch[j - first];
            }
            scratch.push(s);
            // Judged on D⁻¹z, what the back substitution takes: with stiff terms on some DOFs D varies by orders
            // of magnitude, and z alone would stop too early where D is small.
            let scaled = (s * self.inverse_pivots[i]).abs();
            largest = largest.max(scaled);
            quiet = if scaled <= drop * largest { quiet + 1 } else { 0 };
            i += 1;
            if i > last && quiet >= b {
                break;
            }
        }
        let forward_end = i;
        for (k, z) in scratch.iter_mut().enumerate() {
            *z *= self.inverse_pivots[first + k];
        }
        // Backward: x_i = z_i − Σ_{k>i} L_ki x_k from `forward_end − 1` down, below `first` with z = 0, kept in
        // reverse order in `out.values` and turned round at the end.
        let mut largest: f64 = 0.0;
        let mut quiet = 0;
        let mut i = forward_end;
        while i > 0 {
            i -= 1;
            let mut s = if i >= first { scratch[i - first] } else { 0.0 };
            let count = out.values.len();
            for k in (i + 1)..(i + 1 + b).min(forward_end) {
                // x_k sits at position forward_end − 1 − k of the reversed values.
                s -= f[k * w + b - (k - i)] * out.values[count - (k - i)];
            }
            out.values.push(s);
            largest = largest.max(s.abs());
            quiet = if s.abs() <= drop * largest { quiet + 1 } else { 0 };
            if i < first && quiet >= b {
                break;
            }
        }
        out.values.reverse();
        out.start = i;
    }
}

impl BandedLdlt {
    /// [`Self::solve_local`] for half-bandwidth 3: the same substitutions and stopping rules, in the same order of
    /// operations (the same bits), with the three neighbours in registers instead of indexed loops.
    fn solve_local_3(&self, entries: &[(usize, f64)], drop: f64, out: &mut LocalVector, scratch: &mut Vec<f64>) {
        let (n, f) = (self.n, &self.factors);
        out.values.clear();
        let Some(&(first, _)) = entries.first() else {
            out.start = 0;
            return;
        };
        let last = entries.last().map_or(first, |e| e.0);
        scratch.clear();
        let (mut largest, mut quiet, mut next_entry, mut i) = (0.0f64, 0, 0, first);
        // z_{i−1}, z_{i−2}, z_{i−3} (zero before `first`).
        let (mut z1, mut z2, mut z3) = (0.0f64, 0.0f64, 0.0f64);
        while i < n {
            let mut s = 0.0;
            if next_entry < entries.len() && entries[next_entry].0 == i {
                s = entries[next_entry].1;
                next_entry += 1;
            }
            let row = &f[4 * i..4 * i + 4];
            s -= row[0] * z3;
            s -= row[1] * z2;
            s -= row[2] * z1;
            scratch.push(s);
            (z3, z2, z1) = (z2, z1, s);
            let scaled = (s * self.inverse_pivots[i]).abs();
            largest = largest.max(scaled);
            quiet = if scaled <= drop * largest { quiet + 1 } else { 0 };
            i += 1;
            if i > last && quiet >= 3 {
                break;
            }
        }
        let forward_end = i;
        for (k, z) in scratch.iter_mut().enumerate() {
            *z *= self.inverse_pivots[first + k];
        }
        // x_{i+1}, x_{i+2}, x_{i+3} (zero from `forward_end` on), and L_{i+1,i}, L_{i+2,i}, L_{i+3,i} read as i falls.
        let (mut x1, mut x2, mut x3) = (0.0f64, 0.0f64, 0.0f64);
        let below = |k: usize, slot: usize| if k < forward_end { f[4 * k + slot] } else { 0.0 };
        let (mut largest, mut quiet, mut i) = (0.0f64, 0, forward_end);
        while i > 0 {
            i -= 1;
            let mut s = if i >= first { scratch[i - first] } else { 0.0 };
            s -= below(i + 1, 2) * x1;
            s -= below(i + 2, 1) * x2;
            s -= below(i + 3, 0) * x3;
            out.values.push(s);
            (x3, x2, x1) = (x2, x1, s);
            largest = largest.max(s.abs());
            quiet = if s.abs() <= drop * largest { quiet + 1 } else { 0 };
            if i < first && quiet >= 3 {
                break;
            }
        }
        out.values.reverse();
        out.start = i;
    }
}
