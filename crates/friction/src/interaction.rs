//! Interactions: the rows H_α, laws and kinds that friction, contact and compliant supports all reduce to
//! (docs/theory.md §4, §9).
//!
//! Row α maps the free-DOF velocity q̇ to the interaction's relative velocity U_α = H_α q̇ (m/s): the velocity of a
//! friction section, or the rate of a contact gap g_α = g₀ + H_α q. Its force r_α (N) acts on the DOFs as H_αᵀ r_α.
//! A row has at most four entries: the Hermite shape functions of the element containing the section (w and θ
//! DOFs), or a single entry for a section on a node.

use crate::law::Law;

/// Which account of the energy ledger an interaction's work is booked to (docs/theory.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InteractionKind {
    /// Coulomb friction: its work is dissipated.
    Friction,
    /// A unilateral contact between two bodies (a wheel on the rail, a stop).
    Contact,
    /// A unilateral support of the structure (a foundation that cannot pull).
    Support,
}

impl InteractionKind {
    /// Whether the kind is friction (its work is friction work).
    pub fn is_friction(self) -> bool {
        self == InteractionKind::Friction
    }
}

/// A sparse row over the free DOFs. Rows of at most four entries (a friction section on one element, a node) are
/// stored inline and, when their DOFs are consecutive, multiplied four at a time; longer rows (a wheel: four rail DOFs
/// and its own) keep their entries in vectors, which [`InteractionRow::set_entries`] reuses.
#[derive(Debug, Clone, PartialEq)]
pub struct InteractionRow {
    dofs: [usize; 4],
    /// The entries, zero past `len`.
    values: [f64; 4],
    len: usize,
    /// Whether the row is stored inline (at most four entries) in consecutive DOFs from the first on (every Hermite
    /// element row is): products then read four DOFs from the first, the missing entries multiplying exact zeros —
    /// the same sums without a loop of variable length. False for every long row.
    contiguous: bool,
    /// All entries of a row longer than four (`len` is then 0 and the arrays unused).
    long_dofs: Vec<usize>,
    long_values: Vec<f64>,
}

impl Default for InteractionRow {
    fn default() -> Self {
        Self::from_entries([])
    }
}

impl InteractionRow {
    /// A row from (free DOF, value) pairs; exact zeros are skipped, entries are sorted by DOF, each DOF once.
    pub fn from_entries(entries: impl IntoIterator<Item = (usize, f64)>) -> Self {
        let mut row = Self {
            dofs: [0; 4],
            values: [0.0; 4],
            len: 0,
            contiguous: true,
            long_dofs: Vec::new(),
            long_values: Vec::new(),
        };
        row.set_entries(entries);
        row
    }

    /// Replace the entries (as [`InteractionRow::from_entries`]); a long row reuses its vectors, so a moving
    /// interaction rebuilt every step allocates only when its row first grows.
    pub fn set_entries(&mut self, entries: impl IntoIterator<Item = (usize, f64)>) {
        self.long_dofs.clear();
        self.long_values.clear();
        for (dof, value) in entries {
            if value != 0.0 {
                self.long_dofs.push(dof);
                self.long_values.push(value);
            }
        }
        let count = self.long_dofs.len();
        // Sort by DOF (rows are short: insertion sort, no allocation).
        for i in 1..count {
            let mut k = i;
            while k > 0 && self.long_dofs[k - 1] > self.long_dofs[k] {
                self.long_dofs.swap(k - 1, k);
                self.long_values.swap(k - 1, k);
                k -= 1;
            }
        }
        assert!(self.long_dofs.windows(2).all(|w| w[0] < w[1]), "an interaction row names each DOF once");
        self.dofs = [0; 4];
        self.values = [0.0; 4];
        if count <= 4 {
            self.dofs[..count].copy_from_slice(&self.long_dofs);
            self.values[..count].copy_from_slice(&self.long_values);
            self.len = count;
            self.contiguous = (0..count).all(|k| self.dofs[k] == self.dofs[0] + k);
            self.long_dofs.clear();
            self.long_values.clear();
        } else {
            self.len = 0;
            self.contiguous = false;
        }
    }

    /// Whether the row is stored inline (at most four entries).
    fn is_short(&self) -> bool {
        self.long_dofs.is_empty()
    }

    /// Number of non-zero entries.
    pub fn len(&self) -> usize {
        if self.is_short() { self.len } else { self.long_dofs.len() }
    }

    /// Whether the row has no entry (a section on a support).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the row has at most four entries in consecutive DOFs (what the interior point's banded Newton
    /// matrices take).
    pub fn is_local(&self) -> bool {
        self.contiguous
    }

    /// Whether the row has at most four entries within `bandwidth` of each other (what the interior point's banded
    /// Newton matrices of that half-bandwidth take: a local row, or a rail element's four DOFs with a sleeper's
    /// numbered between them).
    pub fn lies_in_band(&self, bandwidth: usize) -> bool {
        self.is_short() && self.dof_span().is_none_or(|(first, last)| last - first <= bandwidth)
    }

    /// The (free DOF, value) entries.
    pub fn entries(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.dofs().iter().copied().zip(self.values().iter().copied())
    }

    /// The free DOFs of the entries, ascending.
    pub fn dofs(&self) -> &[usize] {
        if self.is_short() { &self.dofs[..self.len] } else { &self.long_dofs }
    }

    /// The values of the entries, in the order of [`InteractionRow::dofs`].
    pub fn values(&self) -> &[f64] {
        if self.is_short() { &self.values[..self.len] } else { &self.long_values }
    }

    /// H_j·v.
    #[inline]
    pub fn dot(&self, v: &[f64]) -> f64 {
        let first = self.dofs[0];
        if self.contiguous && first + 4 <= v.len() {
            let (h, x) = (&self.values, &v[first..first + 4]);
            return h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3] * x[3];
        }
        let mut s = 0.0;
        for (d, h) in self.dofs().iter().zip(self.values()) {
            s += h * v[*d];
        }
        s
    }

    /// out += scale·H_jᵀ.
    #[inline]
    pub fn add_transpose(&self, scale: f64, out: &mut [f64]) {
        let first = self.dofs[0];
        if self.contiguous && first + 4 <= out.len() {
            let out = &mut out[first..first + 4];
            for k in 0..4 {
                out[k] += scale * self.values[k];
            }
            return;
        }
        for (d, h) in self.dofs().iter().zip(self.values()) {
            out[*d] += scale * h;
        }
    }

    /// Smallest and largest free DOF touched (for band structure).
    pub fn dof_span(&self) -> Option<(usize, usize)> {
        // The DOFs are sorted.
        let d = self.dofs();
        Some((*d.first()?, *d.last()?))
    }
}

/// Rows H_α with their laws and ledger kinds.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct InteractionSet {
    rows: Vec<InteractionRow>,
    laws: Vec<Law>,
    kinds: Vec<InteractionKind>,
    dropped_capacity: f64,
}

impl InteractionSet {
    /// An empty set (no friction, no contact).
    pub fn new() -> Self {
        Self::default()
    }

    /// Add an interaction and return its index; an empty row (a section on a support, which cannot move) is
    /// dropped — None — and its Coulomb capacity counted in [`InteractionSet::dropped_capacity`].
    pub fn push(&mut self, row: InteractionRow, law: Law, kind: InteractionKind) -> Option<usize> {
        if row.is_empty() {
            self.dropped_capacity += law.capacity();
            return None;
        }
        Some(self.push_moving(row, law, kind))
    }

    /// Add an interaction that is kept even with an empty row (a moving interaction, whose row the engine rewrites
    /// every step); returns its index.
    pub fn push_moving(&mut self, row: InteractionRow, law: Law, kind: InteractionKind) -> usize {
        self.rows.push(row);
        self.laws.push(law);
        self.kinds.push(kind);
        self.rows.len() - 1
    }

    /// The row of interaction j, to rewrite in place (a moving interaction's update).
    pub fn row_mut(&mut self, j: usize) -> &mut InteractionRow {
        &mut self.rows[j]
    }

    /// The law of interaction j, to change in place (a gap moved to a settled state).
    pub fn law_mut(&mut self, j: usize) -> &mut Law {
        &mut self.laws[j]
    }

    /// Append all interactions of another set.
    pub fn extend(&mut self, other: InteractionSet) {
        self.rows.extend(other.rows);
        self.laws.extend(other.laws);
        self.kinds.extend(other.kinds);
        self.dropped_capacity += other.dropped_capacity;
    }

    /// Number of interactions m.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether there is no interaction at all.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The rows H_α.
    pub fn rows(&self) -> &[InteractionRow] {
        &self.rows
    }

    /// The laws.
    pub fn laws(&self) -> &[Law] {
        &self.laws
    }

    /// The Coulomb capacity F_α of interaction α (N; zero for a unilateral law).
    pub fn capacity(&self, j: usize) -> f64 {
        self.laws[j].capacity()
    }

    /// Kinds.
    pub fn kinds(&self) -> &[InteractionKind] {
        &self.kinds
    }

    /// Whether every law is Coulomb friction: then the step's bounds are fixed for the whole run.
    pub fn is_friction_only(&self) -> bool {
        !self.laws.iter().any(Law::depends_on_state)
    }

    /// Σ F_α over the kept friction sections (N).
    pub fn total_capacity(&self) -> f64 {
        self.laws.iter().map(Law::capacity).sum()
    }

    /// Coulomb capacity of the sections dropped because they sit on a support (N).
    pub fn dropped_capacity(&self) -> f64 {
        self.dropped_capacity
    }

    /// U = H v.
    pub fn velocities(&self, v: &[f64], u: &mut [f64]) {
        for (uj, row) in u.iter_mut().zip(&self.rows) {
            *uj = row.dot(v);
        }
    }

    /// out += Hᵀ p.
    pub fn add_transpose(&self, p: &[f64], out: &mut [f64]) {
        for (row, &pj) in self.rows.iter().zip(p) {
            row.add_transpose(pj, out);
        }
    }
}
