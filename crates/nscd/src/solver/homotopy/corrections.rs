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

use banded::{BandedLdlt, LocalVector};
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

/// The events since the last factorisation of B₀ and the dense capacitance system of their correction.
#[derive(Debug)]
pub(super) struct Corrections {
    /// At most this many events; C is stored with this row stride.
    stride: usize,
    events: Vec<Event>,
    /// Events kept for reuse of their vectors (`events` shrinks to empty at a refactorisation).
    spare: Vec<Event>,
    /// C (k × k, row-major), and its LU factors with the row permutation (rebuilt at every event).
    capacitance: Vec<f64>,
    lu: Vec<f64>,
    permutation: Vec<usize>,
    /// c and w (k), scratch of the local solves and of the capacitance solve.
    c: Vec<f64>,
    w: Vec<f64>,
    scratch: Vec<f64>,
    entries: Vec<(usize, f64)>,
}

impl Corrections {
    /// Number of events k.
    pub(super) fn len(&self) -> usize {
        self.events.len()
    }

    /// Room for `capacity` events.
    pub(super) fn new(capacity: usize) -> Self {
        Self {
            stride: capacity,
            events: Vec::with_capacity(capacity),
            spare: Vec::new(),
            capacitance: vec![0.0; capacity * capacity],
            lu: Vec::with_capacity(capacity * capacity),
            permutation: Vec::with_capacity(capacity),
            c: Vec::with_capacity(capacity),
            w: Vec::with_capacity(capacity),
            scratch: Vec::new(),
            entries: Vec::with_capacity(4),
        }
    }

    /// Forget every event (B₀ has just been factored at the current partition).
    pub(super) fn clear(&mut self) {
        self.spare.append(&mut self.events);
    }

    /// Add the event of `section` with row `row`, σ = `sign` and γ = `gamma`: its column y = B₀⁻¹h (a local solve),
    /// the sections it touches (`touching(start, end)`: the range of `order` whose rows meet DOFs [start, end)),
    /// and its row and column of C.
    pub(super) fn push(
        &mut self,
        section: usize,
        row: &InteractionRow,
        (sign, gamma): (f64, f64),
        factor: &BandedLdlt,
        rows: &[InteractionRow],
        touching: impl Fn(usize, usize) -> std::ops::Range<usize>,
        order: &[usize],
    ) {
        let mut event = self.spare.pop().unwrap_or_default();
        event.section = section;
        event.sign = sign;
        event.inverse_s = 1.0 / (sign * gamma);
        self.entries.clear();
        self.entries.extend(row.entries());
        factor.solve_local(&self.entries, DROP, &mut event.column, &mut self.scratch);
        event.touched.clear();
        for &s in &order[touching(event.column.start, event.column.end())] {
            let value = row_dot(&rows[s], &event.column);
            if value != 0.0 {
                event.touched.push((s, value));
            }
        }
        // C grows by a row and a column: C_ki = C_ik = h_{j_i}·y_k, C_kk = 1/(σγ) + h_j·y.
        let (k, stride) = (self.events.len(), self.stride);
        assert!(k < stride, "at most {stride} corrections");
        if self.capacitance.len() < stride * stride {
            self.capacitance.resize(stride * stride, 0.0);
        }
        for (i, other) in self.events.iter().enumerate() {
            let value = row_dot(&rows[other.section], &event.column);
            self.capacitance[i * stride + k] = value;
            self.capacitance[k * stride + i] = value;
        }
        self.capacitance[k * stride + k] = event.inverse_s + row_dot(row, &event.column);
        self.events.push(event);
        self.factor_capacitance();
    }

    /// LU with partial pivoting of C (k × k, at most `stride`).
    fn factor_capacitance(&mut self) {
        let (k, stride) = (self.events.len(), self.stride);
        self.lu.clear();
        self.lu.extend_from_slice(&self.capacitance[..stride * stride]);
        self.permutation.clear();
        self.permutation.extend(0..k);
        let lu = &mut self.lu;
        for col in 0..k {
            let mut pivot = col;
            for r in col + 1..k {
                if lu[r * stride + col].abs() > lu[pivot * stride + col].abs() {
                    pivot = r;
                }
            }
            if pivot != col {
                for x in 0..k {
                    lu.swap(pivot * stride + x, col * stride + x);
                }
                self.permutation.swap(pivot, col);
            }
            let d = lu[col * stride + col];
            for r in col + 1..k {
                let factor = lu[r * stride + col] / d;
                lu[r * stride + col] = factor;
                for x in col + 1..k {
                    lu[r * stride + x] -= factor * lu[col * stride + x];
                }
            }
        }
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

    /// w ← C⁻¹w with the LU factors.
    fn solve_capacitance(&mut self) {
        let k = self.events.len();
        self.scratch.clear();
        self.scratch.extend(self.permutation.iter().map(|&p| self.w[p]));
        let stride = self.stride;
        for r in 0..k {
            let mut s = self.scratch[r];
            for x in 0..r {
                s -= self.lu[r * stride + x] * self.scratch[x];
            }
            self.scratch[r] = s;
        }
        for r in (0..k).rev() {
            let mut s = self.scratch[r];
            for x in r + 1..k {
                s -= self.lu[r * stride + x] * self.scratch[x];
            }
            self.scratch[r] = s / self.lu[r * stride + r];
        }
        self.w.copy_from_slice(&self.scratch);
    }
}

/// h·y for a row of consecutive DOFs (as every row the homotopy takes) and a local y.
fn row_dot(row: &InteractionRow, y: &LocalVector) -> f64 {
    y.dot_consecutive(row.dofs()[0], row.values())
}
