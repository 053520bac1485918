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
    /// `scratch` have grown to the range's length. For half-bandwidth 3 the substitutions keep their three
    /// neighbours in registers instead of indexed loops, in the same order of operations (the same bits).
    pub fn solve_local(&self, entries: &[(usize, f64)], drop: f64, out: &mut LocalVector, scratch: &mut Vec<f64>) {
        let (b, w, f) = (self.bandwidth, self.bandwidth + 1, &self.factors);
        if b != 3 {
            // z_i −= Σ_{j<i} L_ij z_j over the z found so far (`done`, index j at j − first); x_i −= Σ_{k>i} L_ki x_k
            // over the x found so far (`done` reversed: x_k at done.len() − (k − i)).
            let forward = |i: usize, first: usize, mut s: f64, done: &[f64]| {
                for j in i.saturating_sub(b).max(first)..i {
                    s -= f[i * w + b - (i - j)] * done[j - first];
                }
                s
            };
            let backward = |i: usize, end: usize, mut s: f64, done: &[f64]| {
                for k in (i + 1)..(i + 1 + b).min(end) {
                    s -= f[k * w + b - (k - i)] * done[done.len() - (k - i)];
                }
                s
            };
            return self.substitute_locally(entries, drop, out, scratch, forward, backward);
        }
        // z_{i−1}, z_{i−2}, z_{i−3} (zero before the first entry), then x_{i+1}, x_{i+2}, x_{i+3} (zero from the
        // forward pass's end on).
        let (mut z1, mut z2, mut z3) = (0.0f64, 0.0f64, 0.0f64);
        let forward = |i: usize, _: usize, mut s: f64, _: &[f64]| {
            let row = &f[4 * i..4 * i + 4];
            s -= row[0] * z3;
            s -= row[1] * z2;
            s -= row[2] * z1;
            (z3, z2, z1) = (z2, z1, s);
            s
        };
        let (mut x1, mut x2, mut x3) = (0.0f64, 0.0f64, 0.0f64);
        let backward = |i: usize, end: usize, mut s: f64, _: &[f64]| {
            let below = |k: usize, slot: usize| if k < end { f[4 * k + slot] } else { 0.0 };
            s -= below(i + 1, 2) * x1;
            s -= below(i + 2, 1) * x2;
            s -= below(i + 3, 0) * x3;
            (x3, x2, x1) = (x2, x1, s);
            s
        };
        self.substitute_locally(entries, drop, out, scratch, forward, backward)
    }

    /// The two substitutions of [`Self::solve_local`] and where they stop; `forward(i, first, h_i, z so far)` gives
    /// z_i, `backward(i, forward_end, D⁻¹z_i, x so far, reversed)` gives x_i.
    fn substitute_locally(
        &self,
        entries: &[(usize, f64)],
        drop: f64,
        out: &mut LocalVector,
        scratch: &mut Vec<f64>,
        mut forward: impl FnMut(usize, usize, f64, &[f64]) -> f64,
        mut backward: impl FnMut(usize, usize, f64, &[f64]) -> f64,
    ) {
        let (n, b) = (self.n, self.bandwidth);
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
            let s = forward(i, first, s, scratch);
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
            let s = backward(i, forward_end, if i >= first { scratch[i - first] } else { 0.0 }, &out.values);
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
