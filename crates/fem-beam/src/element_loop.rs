//! The one element loop (docs/theory.md §3): a global matrix is the sum over the elements of their local 4 × 4
//! contributions, each scattered to the element's global DOFs, A = Σ_e Lₑᵀ Aₑ Lₑ (as fenris assembles). The real
//! symmetric M, C, K of the model ([`crate::BeamModel`]), the complex dynamic stiffness of the receptance
//! ([`crate::receptance`]) and the moving frame's convective operator (the `stationary` crate) all add their
//! elements here: each says only what an element contributes and where its DOFs go.

use banded::SymmetricBanded;
use banded::general::{Entry, GeneralBanded};

/// A global matrix element contributions are added into.
pub trait GlobalMatrix<T> {
    /// Whether the matrix stores one triangle (symmetric): only the lower triangle of each local matrix is added.
    const LOWER_TRIANGLE: bool;

    /// Add `value` at (`i`, `j`).
    fn add_entry(&mut self, i: usize, j: usize, value: T);
}

impl GlobalMatrix<f64> for SymmetricBanded {
    const LOWER_TRIANGLE: bool = true;

    fn add_entry(&mut self, i: usize, j: usize, value: f64) {
        self.add(i, j, value);
    }
}

impl<T: Entry> GlobalMatrix<T> for GeneralBanded<T> {
    const LOWER_TRIANGLE: bool = false;

    fn add_entry(&mut self, i: usize, j: usize, value: T) {
        self.add(i, j, value);
    }
}

/// Add the local matrices `local(e)` of `elements` elements into `global`, entry (a, b) of element e at
/// (`dofs(e)[a]`, `dofs(e)[b]`) where both DOFs are free (`Some`); a symmetric store takes b ≤ a only. Each global
/// entry sums its elements in increasing e.
pub fn add_elements<T: Copy, G: GlobalMatrix<T>>(
    global: &mut G,
    elements: usize,
    dofs: impl Fn(usize) -> [Option<usize>; 4],
    local: impl Fn(usize) -> [[T; 4]; 4],
) {
    for e in 0..elements {
        let (free, matrix) = (dofs(e), local(e));
        for a in 0..4 {
            let columns = if G::LOWER_TRIANGLE { a + 1 } else { 4 };
            for b in 0..columns {
                if let (Some(i), Some(j)) = (free[a], free[b]) {
                    global.add_entry(i, j, matrix[a][b]);
                }
            }
        }
    }
}

/// The DOFs of element e of a beam whose every DOF is free and numbered in order, (w, θ) per node: 2e … 2e + 3.
pub fn consecutive_dofs(e: usize) -> [Option<usize>; 4] {
    std::array::from_fn(|k| Some(2 * e + k))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two elements on three nodes, the first DOF held: the shared node's entries sum both elements, the held row
    /// and column are left out, a symmetric store gets the lower triangle and a general one the whole matrix.
    #[test]
    fn elements_sum_at_their_shared_node() {
        let local = |e: usize| std::array::from_fn(|a| std::array::from_fn(|b| (10 * e + 4 * a + b) as f64));
        let dofs = |e: usize| consecutive_dofs(e).map(|d| d.and_then(|d| d.checked_sub(1)));
        let mut general = GeneralBanded::<f64>::zeros(5, 3, 3);
        add_elements(&mut general, 2, dofs, local);
        // Global DOF 2 (full 3) is the first element's a = 3 and the second's a = 1: 15 + 15.
        assert_eq!(general.get(2, 2), local(0)[3][3] + local(1)[1][1]);
        assert_eq!(general.get(0, 2), local(0)[1][3]);
        let mut symmetric = SymmetricBanded::zeros(5, 3);
        add_elements(&mut symmetric, 2, dofs, local);
        assert_eq!(symmetric.get(2, 0), local(0)[3][1]);
        assert_eq!(symmetric.get(2, 2), general.get(2, 2));
    }
}
