//! The events since B₀ was last factored, as a Sherman–Morrison–Woodbury correction of its inverse.
//!
//! k events since the factorisation turn B₀ into B = B₀ + U S Uᵀ, U = [h_{j₁} … h_{j_k}], S = diag(σ_i γ_{j_i})
//! (σ = +1 for a section entering the band, −1 for one leaving it). With the columns y_i = B₀⁻¹h_{j_i} — local
//! solves, significant over a few dozen DOFs — and the capacitance C = S⁻¹ + UᵀY (k × k),
//! B⁻¹r = B₀⁻¹r − Y C⁻¹ Uᵀ B₀⁻¹r. The rate of v along τ on the current partition is B⁻¹r with
//! r = r₀ + Σ_i c_i h_{j_i} (the events move their sections' p̄-rates into or out of the right-hand side):
//!
//! ```text
//! dv = dv₀ + Y w,   w = c − C⁻¹(g + G c),   g = Uᵀ dv₀,   G = UᵀY,
//! ```
//!
//! so the section rates change only where some y_i is significant: du_s = du₀_s + Σ_i w_i (h_s·y_i).

use banded::{BandedLdlt, BorderedLdlt, LocalVector};
use friction::InteractionRow;

/// The entries of y_i = B₀⁻¹h below this fraction of the largest are left out (the local solve's truncation, judged
/// on D⁻¹z: the result is exact to ~1e-14 of its largest).
pub(super) const DROP: f64 = 1e-13;

/// One event: its section, σ, its column y = B₀⁻¹h and the sections that column touches with h_s·y.
#[derive(Debug, Clone, Default)]
struct Event {
    section: usize,
    sign: f64,
    /// 1/(σγ), S⁻¹'s entry.
    inverse_s: f64,
    column: LocalVector,
    touched: Vec<(usize, f64)>,
}

/// A pivot of the capacitance's LDLᵀ below this fraction of its row's largest entry marks C as ill-conditioned
/// (cond ≳ 1e12): the event is not added and B₀ is factored afresh instead.
const PIVOT_FLOOR: f64 = 1e-12;

/// The events since the last factorisation of B₀ and the capacitance system of their correction, factored
/// incrementally: C is symmetric (indefinite: S⁻¹ has the sign of each event), and an event borders it by one row,
/// so its LDLᵀ grows by one row in O(k²) — l = (LD)⁻¹c, d = C_kk − lᵀDl — instead of being refactored in O(k³).
#[derive(Debug)]
pub(super) struct Corrections {
    /// At most this many events; C and L are stored with this row stride.
    stride: usize,
    events: Vec<Event>,
    /// Events kept for reuse of their vectors (`events` shrinks to empty at a refactorisation).
    spare: Vec<Event>,
    /// C (k × k, row-major, both triangles), and its LDLᵀ.
    capacitance: Vec<f64>,
    ldl: BorderedLdlt,
    /// c and w (k), scratch of the local solves.
    c: Vec<f64>,
    w: Vec<f64>,
    scratch: Vec<f64>,
    entries: Vec<(usize, f64)>,
}

/// Whether an event was added to the correction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Added {
    /// Added: its row borders C's factor.
    Bordered,
    /// Not added: the list is full or its pivot fell below [`PIVOT_FLOOR`]; B₀ must be factored afresh.
    Refactor,
}

impl Corrections {
    /// Room for `capacity` events.
    pub(super) fn new(capacity: usize) -> Self {
        Self {
            stride: capacity,
            events: Vec::with_capacity(capacity),
            spare: Vec::new(),
            capacitance: vec![0.0; capacity * capacity],
            ldl: BorderedLdlt::with_capacity(capacity),
            c: Vec::with_capacity(capacity),
            w: Vec::with_capacity(capacity),
            scratch: Vec::new(),
            entries: Vec::with_capacity(4),
        }
    }

    /// Forget every event (B₀ has just been factored at the current partition).
    pub(super) fn clear(&mut self) {
        self.spare.append(&mut self.events);
        self.ldl.clear(self.stride);
    }

    /// Add the event of `section` with row `row`, σ = `sign` and γ = `gamma`: its column y = B₀⁻¹h (a local solve),
    /// the sections it touches (`touching(start, end)`: the range of `order` whose rows meet DOFs [start, end)),
    /// its row and column of C, and the row of C's factor — unless the list is full or the new pivot shows C
    /// ill-conditioned ([`Added::Refactor`]: nothing is added).
    pub(super) fn push(
        &mut self,
        section: usize,
        row: &InteractionRow,
        (sign, gamma): (f64, f64),
        factor: &BandedLdlt,
        rows: &[InteractionRow],
        touching: impl Fn(usize, usize) -> std::ops::Range<usize>,
        order: &[usize],
    ) -> Added {
        let (k, stride) = (self.events.len(), self.stride);
        if k >= stride {
            return Added::Refactor;
        }
        let mut event = self.spare.pop().unwrap_or_default();
        event.section = section;
        event.sign = sign;
        event.inverse_s = 1.0 / (sign * gamma);
        self.entries.clear();
        self.entries.extend(row.entries());
        factor.solve_local(&self.entries, DROP, &mut event.column, &mut self.scratch);
        // C grows by a row and a column: C_ki = C_ik = h_{j_i}·y_k, C_kk = 1/(σγ) + h_j·y.
        for (i, other) in self.events.iter().enumerate() {
            let value = row_dot(&rows[other.section], &event.column);
            self.capacitance[i * stride + k] = value;
            self.capacitance[k * stride + i] = value;
        }
        let diagonal = event.inverse_s + row_dot(row, &event.column);
        self.capacitance[k * stride + k] = diagonal;
        // The factor's new row; its pivot judges C's conditioning.
        let row = &self.capacitance[k * stride..k * stride + k + 1];
        let largest = row.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let pivot = self.ldl.border(row);
        if pivot.is_nan() || pivot.abs() <= PIVOT_FLOOR * largest {
            self.spare.push(event);
            return Added::Refactor;
        }
        self.ldl.accept();
        event.touched.clear();
        for &s in &order[touching(event.column.start, event.column.end())] {
            let value = row_dot(&rows[s], &event.column);
            if value != 0.0 {
                event.touched.push((s, value));
            }
        }
        self.events.push(event);
        Added::Bordered
    }

    /// The weights w = c − C⁻¹(g + G c) for the events' right-hand-side coefficients c_i = σ_i·dp̄_{j_i}
    /// (`shift_rate` by section) and g_i = h_{j_i}·dv₀ (`base_rate`, du₀ by section); then call `add` with
    /// (section s, w_i·(h_s·y_i)) for every section every column touches: du_s − du₀_s is their sum.
    pub(super) fn rates(&mut self, shift_rate: &[f64], base_rate: &[f64], mut add: impl FnMut(usize, f64)) {
        let k = self.events.len();
        self.c.clear();
        self.c.extend(self.events.iter().map(|e| e.sign * shift_rate[e.section]));
        // x = g + G c with G = C − S⁻¹ (S⁻¹ on the diagonal only).
        self.w.clear();
        for (i, event) in self.events.iter().enumerate() {
            let mut x = base_rate[event.section] - event.inverse_s * self.c[i];
            for l in 0..k {
                x += self.capacitance[i * self.stride + l] * self.c[l];
            }
            self.w.push(x);
        }
        self.solve_capacitance();
        for i in 0..k {
            self.w[i] = self.c[i] - self.w[i];
        }
        for (event, &w) in self.events.iter().zip(&self.w) {
            for &(s, value) in &event.touched {
                add(s, w * value);
            }
        }
    }

    /// w ← C⁻¹w with the LDLᵀ factors.
    fn solve_capacitance(&mut self) {
        self.ldl.solve_in_place(&mut self.w);
    }
}

/// h·y for a row of consecutive DOFs (as every row the homotopy takes) and a local y.
fn row_dot(row: &InteractionRow, y: &LocalVector) -> f64 {
    y.dot_consecutive(row.dofs()[0], row.values())
}

#[cfg(test)]
mod tests {
    use super::*;
    use banded::SymmetricBanded;

    /// A diagonally dominant B₀ (half-bandwidth 3) and rows of four consecutive entries.
    fn setting(n: usize) -> (BandedLdlt, Vec<InteractionRow>) {
        let mut b = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            b.add(i, i, 5.0 + (i % 4) as f64);
            if i > 0 {
                b.add(i, i - 1, -1.2);
            }
            if i > 2 {
                b.add(i, i - 3, 0.4);
            }
        }
        let rows = (0..n - 3)
            .map(|f| InteractionRow::from_entries((0..4).map(|a| (f + a, [0.6, -0.2, 0.4, 0.1][a] + 0.01 * f as f64))))
            .collect();
        (b.factor().unwrap(), rows)
    }

    /// The bordered LDLᵀ of C, grown one event at a time with either sign, solves C w = x as a dense LU of C does.
    #[test]
    fn the_bordered_factor_solves_the_capacitance() {
        let (factor, rows) = setting(60);
        let order: Vec<usize> = (0..rows.len()).collect();
        let touching = |start: usize, end: usize| start.saturating_sub(3).min(rows.len())..end.min(rows.len());
        let mut corrections = Corrections::new(8);
        for (k, &(section, sign)) in
            [(20, 1.0), (22, -1.0), (21, 1.0), (40, 1.0), (23, -1.0), (19, 1.0)].iter().enumerate()
        {
            let added = corrections.push(section, &rows[section], (sign, 3.0), &factor, &rows, touching, &order);
            assert_eq!(added, Added::Bordered, "event {k}");
        }
        let k = corrections.events.len();
        let dense = nalgebra::DMatrix::from_fn(k, k, |i, j| corrections.capacitance[i * 8 + j]);
        let x: Vec<f64> = (0..k).map(|i| (1.3 * i as f64).cos()).collect();
        corrections.w = x.clone();
        corrections.solve_capacitance();
        let expected = dense.lu().solve(&nalgebra::DVector::from_vec(x)).expect("C is regular");
        let worst = corrections.w.iter().zip(expected.iter()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        assert!(worst < 1e-12, "largest difference {worst:e}");
    }

    /// The same section entering the band twice with γ → ∞ (S⁻¹ → 0) makes C singular: the second event is refused
    /// (B₀ is then factored afresh), as is any event past the capacity.
    #[test]
    fn a_singular_or_full_capacitance_asks_for_a_refactorisation() {
        let (factor, rows) = setting(30);
        let order: Vec<usize> = (0..rows.len()).collect();
        let touching = |start: usize, end: usize| start.saturating_sub(3).min(rows.len())..end.min(rows.len());
        let mut corrections = Corrections::new(2);
        let push = |c: &mut Corrections, section: usize| {
            c.push(section, &rows[section], (1.0, 1e20), &factor, &rows, touching, &order)
        };
        assert_eq!(push(&mut corrections, 10), Added::Bordered);
        assert_eq!(push(&mut corrections, 10), Added::Refactor);
        assert_eq!(corrections.events.len(), 1, "nothing added");
        assert_eq!(push(&mut corrections, 14), Added::Bordered);
        assert_eq!(push(&mut corrections, 18), Added::Refactor, "full");
    }
}
