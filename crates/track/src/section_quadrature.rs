//! The sections of a distributed law on the beam's mesh (docs/theory.md §4, §13): placed and weighed by
//! [`fem_beam::distributed::section_places`] (J sub-intervals per element; trapezoid, Simpson or Gauss weights), each
//! given its row H_s = Ψ(x_s) over the free DOFs — the Hermite shape functions of w in its element, so Hᵀr carries
//! forces and moments. Ballast friction and the unilateral part of a nonlinear foundation are both placed this way.

use crate::error::{Result, TrackError};
use fem_beam::BeamModel;
use friction::InteractionRow;

use fem_beam::distributed::section_places;
pub use fem_beam::distributed::{MAX_SUBDIVISIONS, Quadrature};

/// One section of a distributed law: its row over the free DOFs (empty on a support), its weight (m) and place (m).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadratureSection {
    /// H_s = Ψ(x_s) over the beam's free DOFs.
    pub row: InteractionRow,
    /// The length the section stands for (m).
    pub weight: f64,
    /// x_s (m).
    pub x: f64,
}

/// Check J ∈ [1, [`MAX_SUBDIVISIONS`]] (even with Simpson weights) as fem-beam does; `field` names it in the error.
pub fn validate_subdivisions(field: &'static str, subdivisions: usize, quadrature: Quadrature) -> Result<()> {
    fem_beam::distributed::validate_subdivisions(field, subdivisions, quadrature).map_err(TrackError::setting)
}

/// The row H = Ψ(ξ) of w at the local coordinate ξ ∈ [0, 1] of element `e` over the free DOFs (a node's row at
/// ξ = 0 or 1).
fn row_at(model: &BeamModel, e: usize, xi: f64) -> InteractionRow {
    let dofs = model.dofs();
    if xi == 0.0 || xi == 1.0 {
        let node = e + xi as usize;
        InteractionRow::from_entries(dofs.free_index(2 * node).map(|d| (d, 1.0)))
    } else {
        let n = model.element().shape(xi);
        InteractionRow::from_entries(dofs.element_free(e).into_iter().zip(n).filter_map(|(d, n)| d.map(|d| (d, n))))
    }
}

/// The sections of the mesh of `model` in order of x, placed and weighed by [`fem_beam::distributed::section_places`]
/// (those on supports have empty rows); J checked by [`validate_subdivisions`] first.
pub fn sections(model: &BeamModel, subdivisions: usize, quadrature: Quadrature) -> Vec<QuadratureSection> {
    let mesh = model.mesh();
    section_places(mesh.elements, mesh.element_length(), subdivisions, quadrature)
        .into_iter()
        .map(|p| QuadratureSection { row: row_at(model, p.element, p.xi), weight: p.weight, x: p.x })
        .collect()
}
