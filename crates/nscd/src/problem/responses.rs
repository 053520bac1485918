//! Velocity responses to unit section impulses, G_j = M̂⁻¹ H_jᵀ, kept when they are short.
//!
//! The step's correction v = v_free + M̂⁻¹Hᵀp is one banded solve, latency-bound (each row waits on the previous
//! one). G_j decays like e^{−|x − x_j|/(√2ℓ)} away from section j, ℓ = (EI h²θ²/ρA)^¼ (0.29 m for the reference
//! case), so each G_j is short once its entries below the solve's own round-off are dropped; with few sections
//! (devices) Σ_j p_j G_j over the non-zero impulses is several times cheaper than the solve and vectorises.

use crate::kernels::axpy;
use banded::{BandedLdlt, SymmetricBanded};
use friction::{InteractionRow, InteractionSet};

/// Entries of G_j below this fraction of max |G_j| are dropped: the banded solve that produced G_j mixes every
/// entry with its neighbours at relative precision ~1.1e-16, so such entries are below its round-off already.
pub const DROP_BELOW: f64 = 1e-17;

/// The range [first, last) of `column` outside which every entry is at most `floor` times its largest (an empty
/// range at `fallback` when all are zero).
pub(crate) fn significant_range(column: &[f64], floor: f64, fallback: usize) -> (usize, usize) {
    let largest = column.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let significant = |c: &f64| c.abs() > floor * largest;
    let first = column.iter().position(significant).unwrap_or(fallback);
    let last = column.iter().rposition(significant).map_or(first, |i| i + 1);
    (first, last)
}

/// h Z hᵀ for the row h and the band Z of a symmetric matrix, when the row's DOFs lie within one band window (every
/// Hermite element row does); None otherwise.
fn quadratic_form_in_band(row: &InteractionRow, band: &SymmetricBanded) -> Option<f64> {
    let dofs = row.dofs();
    if dofs.last()? - dofs.first()? > band.bandwidth() {
        return None;
    }
    let mut sum = 0.0;
    for (a, ha) in row.entries() {
        for (c, hc) in row.entries() {
            sum += ha * hc * band.get(a, c);
        }
    }
    Some(sum)
}

/// The columns are kept only while their total length stays below this many times the number of DOFs: beyond
/// that, a step with many active sections would cost more than the solve they replace (and memory would grow
/// with sections × DOFs for distributed friction).
pub const MAX_FILL: usize = 8;

/// The truncated columns G_j: `start[j]` is the first DOF of column j, its entries are
/// `values[offset[j]..offset[j + 1]]`.
#[derive(Debug, Clone)]
pub struct ImpulseResponses {
    start: Vec<usize>,
    offset: Vec<usize>,
    values: Vec<f64>,
}

impl ImpulseResponses {
    /// Solve for every column G_j (one banded solve each) and return the truncated columns — None once their
    /// entries exceed [`MAX_FILL`]·n — with the Delassus diagonal W_jj = H_j G_j. Once the columns are dropped, the
    /// remaining W_jj come from the band of M̂⁻¹ ([`BandedLdlt::inverse_band`], O(n·b²) once) instead of a solve
    /// per row (O(n·b) each): distributed friction on 20 000 elements has 80 000 rows, whose solves took 13 s
    /// before the first step.
    pub fn new(interactions: &InteractionSet, factor: &BandedLdlt) -> (Option<Self>, Vec<f64>) {
        let n = factor.order();
        let mut column = vec![0.0; n];
        let mut kept = Some(Self { start: Vec::new(), offset: vec![0], values: Vec::new() });
        let mut diagonal = Vec::with_capacity(interactions.len());
        let mut inverse_band: Option<SymmetricBanded> = None;
        for row in interactions.rows() {
            if kept.is_none() {
                let band = inverse_band.get_or_insert_with(|| factor.inverse_band());
                if let Some(w) = quadratic_form_in_band(row, band) {
                    diagonal.push(w);
                    continue;
                }
            }
            column.iter_mut().for_each(|c| *c = 0.0);
            row.add_transpose(1.0, &mut column);
            factor.solve_in_place(&mut column);
            diagonal.push(row.dot(&column));
            if let Some(responses) = kept.as_mut() {
                let (first, last) = significant_range(&column, DROP_BELOW, 0);
                responses.start.push(first);
                responses.values.extend_from_slice(&column[first..last]);
                responses.offset.push(responses.values.len());
                if responses.values.len() > MAX_FILL * n {
                    kept = None;
                }
            }
        }
        (kept, diagonal)
    }

    /// v += Σ_j p_j G_j over the non-zero impulses.
    pub fn add(&self, p: &[f64], v: &mut [f64]) {
        for (j, &pj) in p.iter().enumerate() {
            if pj != 0.0 {
                let g = &self.values[self.offset[j]..self.offset[j + 1]];
                axpy(pj, g, &mut v[self.start[j]..self.start[j] + g.len()]);
            }
        }
    }

    /// Stored entries (for reports and tests).
    pub fn len(&self) -> usize {
        self.values.len()
    }

    /// Whether no entry is stored.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::{ImpulseResponses, MAX_FILL};
    use banded::SymmetricBanded;
    use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

    /// A beam-like SPD band (half-bandwidth 3) with one element row h = (½, l/8, ½, −l/8) per element — far more rows
    /// than the kept columns allow: the diagonal beyond them comes from the band of M̂⁻¹ and must equal h M̂⁻¹ hᵀ by
    /// solves, to round-off (1e-12 relative: both are backward-stable evaluations of a well-conditioned form).
    #[test]
    fn the_diagonal_past_the_kept_columns_equals_full_solves() {
        let n = 400;
        let mut a = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            a.add(i, i, 4.0 + (i % 7) as f64 * 0.1);
            for j in i.saturating_sub(3)..i {
                a.add(i, j, 0.3 / (i - j) as f64);
            }
        }
        let factor = a.factor().unwrap();
        let mut interactions = InteractionSet::new();
        for e in 0..(n / 2 - 1) {
            for part in 0..4 {
                let s = (part as f64 + 0.5) / 4.0;
                let entries = [(2 * e, 1.0 - s), (2 * e + 1, 0.125 * s), (2 * e + 2, s), (2 * e + 3, -0.125 * s)];
                let row = InteractionRow::from_entries(entries);
                interactions.push(row, Law::Coulomb { capacity: 1.0 }, InteractionKind::Friction);
            }
        }
        let (kept, diagonal) = ImpulseResponses::new(&interactions, &factor);
        assert!(kept.is_none(), "{} rows over {n} DOFs must exceed the fill of {MAX_FILL}·n", interactions.len());
        for (row, w) in interactions.rows().iter().zip(&diagonal) {
            let mut column = vec![0.0; n];
            row.add_transpose(1.0, &mut column);
            factor.solve_in_place(&mut column);
            let solved = row.dot(&column);
            assert!((w - solved).abs() < 1e-12 * solved.abs(), "{w} against {solved}");
        }
    }
}
