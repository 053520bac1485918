//! The contact set: the rows H_j and bounds F_j that both friction models reduce to (docs/theory.md §4).
//!
//! Row j maps the free-DOF velocity q̇ to the velocity of section j, u_j = H_j q̇ (m/s); its friction force r_j
//! (N) acts on the DOFs as H_jᵀ r_j. A row has at most four entries: the Hermite shape functions of the element
//! containing the section (w and θ DOFs), or a single entry for a section on a node.

/// Which friction model a row comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKind {
    /// A discrete friction device (FDD) on a node.
    Device,
    /// A section of distributed (ballast) friction.
    Distributed,
}

/// A sparse row over the free DOFs, at most four entries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactRow {
    dofs: [usize; 4],
    /// The entries, zero past `len`.
    values: [f64; 4],
    len: usize,
    /// Whether the entries sit in consecutive DOFs from the first on (every Hermite element row does): products
    /// then read four DOFs from the first, the missing entries multiplying exact zeros — the same sums without a
    /// loop of variable length.
    contiguous: bool,
}

impl ContactRow {
    /// A row from (free DOF, value) pairs; exact zeros are skipped, entries are sorted by DOF. At most four
    /// distinct entries.
    pub fn from_entries(entries: impl IntoIterator<Item = (usize, f64)>) -> Self {
        let mut pairs: Vec<(usize, f64)> = entries.into_iter().filter(|e| e.1 != 0.0).collect();
        pairs.sort_by_key(|e| e.0);
        assert!(pairs.len() <= 4, "a contact row has at most four entries");
        assert!(pairs.windows(2).all(|w| w[0].0 < w[1].0), "a contact row names each DOF once");
        let contiguous = pairs.iter().enumerate().all(|(k, e)| e.0 == pairs[0].0 + k);
        let mut row = Self { dofs: [0; 4], values: [0.0; 4], len: pairs.len(), contiguous };
        for (k, (dof, value)) in pairs.into_iter().enumerate() {
            row.dofs[k] = dof;
            row.values[k] = value;
        }
        row
    }

    /// Number of non-zero entries.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the row has no entry (a section on a support).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The (free DOF, value) entries.
    pub fn entries(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        (0..self.len).map(|k| (self.dofs[k], self.values[k]))
    }

    /// The free DOFs of the entries, ascending.
    pub fn dofs(&self) -> &[usize] {
        &self.dofs[..self.len]
    }

    /// The values of the entries, in the order of [`ContactRow::dofs`].
    pub fn values(&self) -> &[f64] {
        &self.values[..self.len]
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
        for k in 0..self.len {
            s += self.values[k] * v[self.dofs[k]];
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
        for k in 0..self.len {
            out[self.dofs[k]] += scale * self.values[k];
        }
    }

    /// Smallest and largest free DOF touched (for band structure).
    pub fn dof_span(&self) -> Option<(usize, usize)> {
        // The DOFs are sorted.
        let d = &self.dofs[..self.len];
        Some((*d.first()?, *d.last()?))
    }
}

/// Rows H_j, bounds F_j (N), section positions and kinds.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactSet {
    rows: Vec<ContactRow>,
    bounds: Vec<f64>,
    positions: Vec<f64>,
    kinds: Vec<ContactKind>,
    dropped_capacity: f64,
}

impl ContactSet {
    /// An empty set (no friction).
    pub fn new() -> Self {
        Self::default()
    }

    /// Add a section; an empty row (a section on a support, which cannot move) is dropped and its bound counted in
    /// [`ContactSet::dropped_capacity`].
    pub fn push(&mut self, row: ContactRow, bound: f64, position: f64, kind: ContactKind) {
        if row.is_empty() {
            self.dropped_capacity += bound;
        } else {
            self.rows.push(row);
            self.bounds.push(bound);
            self.positions.push(position);
            self.kinds.push(kind);
        }
    }

    /// Append all sections of another set.
    pub fn extend(&mut self, other: ContactSet) {
        self.rows.extend(other.rows);
        self.bounds.extend(other.bounds);
        self.positions.extend(other.positions);
        self.kinds.extend(other.kinds);
        self.dropped_capacity += other.dropped_capacity;
    }

    /// Number of sections m.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether there is no friction at all.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The rows H_j.
    pub fn rows(&self) -> &[ContactRow] {
        &self.rows
    }

    /// The bounds F_j (N).
    pub fn bounds(&self) -> &[f64] {
        &self.bounds
    }

    /// Section positions x_j (m).
    pub fn positions(&self) -> &[f64] {
        &self.positions
    }

    /// Kinds of the sections.
    pub fn kinds(&self) -> &[ContactKind] {
        &self.kinds
    }

    /// Σ F_j over the kept sections (N).
    pub fn total_capacity(&self) -> f64 {
        self.bounds.iter().sum()
    }

    /// Capacity of the sections dropped because they sit on a support (N).
    pub fn dropped_capacity(&self) -> f64 {
        self.dropped_capacity
    }

    /// u = H v.
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

    /// The index of the section at `x` within `tolerance` (m), if any (first match).
    pub fn section_at(&self, x: f64, tolerance: f64) -> Option<usize> {
        self.positions.iter().position(|&p| (p - x).abs() <= tolerance)
    }
}
