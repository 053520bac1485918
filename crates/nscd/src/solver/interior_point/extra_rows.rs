//! Rows the band cannot hold — a wheel's contact couples the rail element under it to the wheel's own DOF, far
//! from it in the system's numbering — in the interior point's Newton systems, by a bordered solve.
//!
//! With E the k such rows (their impulses Δp_E) and the banded B_loc = M̂ + H_locᵀ(Σ + D)⁻¹H_loc of the others, the
//! Newton equations M̂ dy = HᵀΔp, (Σ + D)Δp + H dy = r become, eliminating the local impulses,
//!
//! ```text
//! B_loc dy = x_loc + EᵀΔp_E,   (Σ_E + D_E)Δp_E + E dy = r_E,   x_loc = H_locᵀ(Σ + D)⁻¹r_loc
//! ⇒  C Δp_E = r_E − E B_loc⁻¹x_loc,   C = Σ_E + D_E + E Z,   Z = B_loc⁻¹Eᵀ,   dy = B_loc⁻¹x_loc + Z Δp_E
//! ```
//!
//! (the Sherman–Morrison–Woodbury identity, solved for the impulses). Each factorisation of B_loc costs k more banded
//! solves (the columns of Z) and a k × k LDLᵀ of C (symmetric positive definite: Σ + D > 0 and E Z ⪰ 0); each
//! direction k dot products and k axpys over the DOFs. Δp_E comes out of C directly, never as (Σ + D)⁻¹(r − E dy):
//! a closed contact carries Σ → 0, and that quotient would multiply the round-off of E dy by (Σ + D)⁻¹ ~ 1e15/W_jj.
//! (docs/theory.md §5.)

use banded::{BandedError, BandedLdlt, BorderedLdlt};

/// The non-local rows of the active sections, their Z = B_loc⁻¹Eᵀ and the factor of C. Allocates only while a run
/// grows its number of such rows.
#[derive(Debug, Default)]
pub(super) struct ExtraRows {
    /// Position k (in the sections' arrays) of each row.
    sections: Vec<usize>,
    /// Entries of row e: `dofs[starts[e]..starts[e + 1]]` (DOFs of the subproblem) and `values` alike.
    starts: Vec<usize>,
    dofs: Vec<usize>,
    values: Vec<f64>,
    /// Column e of Z over the subproblem's DOFs at `e * order`.
    columns: Vec<f64>,
    order: usize,
    /// The factor of C, and a row of C as it is bordered on.
    capacitance: BorderedLdlt,
    row: Vec<f64>,
    /// r_E − E dy, then Δp_E.
    coefficients: Vec<f64>,
}

impl ExtraRows {
    /// Forget every row.
    pub(super) fn clear(&mut self) {
        self.sections.clear();
        self.starts.clear();
        self.starts.push(0);
        self.dofs.clear();
        self.values.clear();
    }

    /// Number of rows.
    pub(super) fn len(&self) -> usize {
        self.sections.len()
    }

    /// Whether there is none (the Newton systems are then the band's alone).
    pub(super) fn is_empty(&self) -> bool {
        self.sections.is_empty()
    }

    /// Add the row of the section at position `k`, its entries already in the subproblem's DOFs.
    pub(super) fn push(&mut self, k: usize, entries: impl Iterator<Item = (usize, f64)>) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.sections.push(k);
        for (dof, value) in entries {
            self.dofs.push(dof);
            self.values.push(value);
        }
        self.starts.push(self.dofs.len());
    }

    /// E_e·x.
    #[inline]
    fn dot(&self, e: usize, x: &[f64]) -> f64 {
        let range = self.starts[e]..self.starts[e + 1];
        let mut sum = 0.0;
        for (&d, &h) in self.dofs[range.clone()].iter().zip(&self.values[range]) {
            sum += h * x[d];
        }
        sum
    }

    /// gathered_k = E_e·x for each row (their band rows are empty, so this is H_k·x).
    pub(super) fn gather(&self, x: &[f64], gathered: &mut [f64]) {
        for e in 0..self.len() {
            gathered[self.sections[e]] = self.dot(e, x);
        }
    }

    /// The rows' positions k and their impulses Δp_E of the last [`ExtraRows::solve`].
    pub(super) fn impulses(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.sections.iter().copied().zip(self.coefficients.iter().copied())
    }

    /// With B_loc factored (`factor`) and the sections' (Σ + D)⁻¹ in `inv_sigma`: Z = B_loc⁻¹Eᵀ (one banded solve
    /// per row, returned as the count) and C = S⁻¹ + E Z factored as LDLᵀ.
    pub(super) fn factor(&mut self, factor: &BandedLdlt, inv_sigma: &[f64]) -> Result<usize, BandedError> {
        let (k, n) = (self.len(), factor.order());
        self.order = n;
        self.columns.resize(k * n, 0.0);
        for e in 0..k {
            let column = &mut self.columns[e * n..(e + 1) * n];
            column.iter_mut().for_each(|x| *x = 0.0);
            let range = self.starts[e]..self.starts[e + 1];
            for (&d, &h) in self.dofs[range.clone()].iter().zip(&self.values[range]) {
                column[d] += h;
            }
            factor.solve_in_place(column);
        }
        self.capacitance.clear(k);
        for a in 0..k {
            self.row.clear();
            for b in 0..=a {
                self.row.push(self.dot(a, &self.columns[b * n..(b + 1) * n]));
            }
            self.row[a] += 1.0 / inv_sigma[self.sections[a]];
            let pivot = self.capacitance.border(&self.row);
            if pivot.is_nan() || pivot <= 0.0 {
                return Err(BandedError::NonPositivePivot { index: a, pivot });
            }
            self.capacitance.accept();
        }
        Ok(k)
    }

    /// From dy = B_loc⁻¹x_loc: Δp_E = C⁻¹(r_E − E dy) (kept for [`ExtraRows::impulses`]) and dy += Z Δp_E; `r` is
    /// indexed by section position.
    pub(super) fn solve(&mut self, r: &[f64], dy: &mut [f64]) {
        let (k, n) = (self.len(), self.order);
        self.coefficients.resize(k, 0.0);
        for e in 0..k {
            self.coefficients[e] = r[self.sections[e]] - self.dot(e, dy);
        }
        self.capacitance.solve_in_place(&mut self.coefficients);
        for e in 0..k {
            let s = self.coefficients[e];
            for (y, z) in dy[..n].iter_mut().zip(&self.columns[e * n..(e + 1) * n]) {
                *y += s * z;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use banded::SymmetricBanded;

    /// The bordered solve equals the dense solve of [B_loc, −Eᵀ; E, Σ_E + D_E][dy; Δp_E] = [x_loc; r_E], with E two
    /// long rows (each reaching a DOF far outside the band), to round-off of the well-conditioned test matrix — and
    /// keeps Δp_E exact where Σ_E + D_E is 1e-15 (a closed contact), where (Σ + D)⁻¹(r − E dy) would not.
    #[test]
    fn the_bordered_solve_solves_the_newton_equations() {
        let n = 40;
        let mut b_loc = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            b_loc.add(i, i, 4.0 + (i % 3) as f64);
            if i > 0 {
                b_loc.add(i, i - 1, -1.0);
            }
            if i > 2 {
                b_loc.add(i, i - 3, 0.3);
            }
        }
        let factor = b_loc.factor().expect("SPD");
        let rows: [Vec<(usize, f64)>; 2] =
            [vec![(10, -0.4), (11, 0.1), (12, -0.6), (13, -0.05), (38, 1.0)], vec![(20, -0.5), (23, 0.2), (39, 1.0)]];
        for sigma in [[0.4, 1.4], [1e-15, 2.0]] {
            let inv_sigma = [0.0, 1.0 / sigma[0], 0.0, 1.0 / sigma[1]];
            let r = [0.0, 0.8, 0.0, -0.3];
            let mut extra = ExtraRows::default();
            extra.clear();
            extra.push(1, rows[0].iter().copied());
            extra.push(3, rows[1].iter().copied());
            assert_eq!(extra.factor(&factor, &inv_sigma).expect("C is SPD"), 2);
            let x: Vec<f64> = (0..n).map(|i| (0.37 * i as f64).sin()).collect();
            let mut dy = x.clone();
            factor.solve_in_place(&mut dy);
            extra.solve(&r, &mut dy);
            let impulses: Vec<f64> = extra.impulses().map(|(_, p)| p).collect();
            let mut dense = nalgebra::DMatrix::zeros(n + 2, n + 2);
            dense.view_mut((0, 0), (n, n)).copy_from(&b_loc.to_dense());
            for (e, row) in rows.iter().enumerate() {
                for &(d, h) in row {
                    dense[(d, n + e)] = -h;
                    dense[(n + e, d)] = h;
                }
                dense[(n + e, n + e)] = sigma[e];
            }
            let mut rhs = x.clone();
            rhs.extend([r[1], r[3]]);
            let expected = dense.lu().solve(&nalgebra::DVector::from_vec(rhs)).expect("regular");
            let worst = dy.iter().chain(&impulses).zip(expected.iter()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            assert!(worst < 1e-13, "Σ = {sigma:?}: largest difference {worst:e}");
        }
    }
}
