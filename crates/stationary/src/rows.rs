//! A section's row over its element's four DOFs (w, θ at both nodes; Hermite shape values): applied to the DOF
//! vector, added to a banded matrix as a spring, and spread as a force — the operations the soil's and the ballast
//! friction's sections share.

use banded::general::GeneralBanded;

/// Σ_k row_k w_{2e+k}: a row over element `e`'s four DOFs applied to the DOF vector `w`.
pub(crate) fn row_dot(element: usize, row: &[f64; 4], w: &[f64]) -> f64 {
    let d = 2 * element;
    (0..4).map(|k| row[k] * w[d + k]).sum()
}

/// matrix += k·rowᵀrow on element `e`'s DOFs: a spring k (N/m) at a section of the element.
pub(crate) fn add_spring(matrix: &mut GeneralBanded, element: usize, row: &[f64; 4], k: f64) {
    let d = 2 * element;
    for a in 0..4 {
        for b in 0..4 {
            matrix.add(d + a, d + b, k * row[a] * row[b]);
        }
    }
}

/// out_{2e+k} += scale·row_k: a force `scale` spread over element `e`'s DOFs by `row`.
pub(crate) fn row_add(element: usize, row: &[f64; 4], scale: f64, out: &mut [f64]) {
    let d = 2 * element;
    (0..4).for_each(|k| out[d + k] += scale * row[k]);
}
