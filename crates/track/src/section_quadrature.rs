//! Sections along the beam that stand for a distributed law (docs/theory.md §4, §13): each element is cut into J
//! equal sub-intervals and the law acts at the J+1 sections of every element, integrated against the shape functions
//! with composite trapezoid weights l/J (interior) and l/(2J) (element ends), or Simpson weights
//! l/(3J)·(1, 4, 2, 4, …, 4, 1) (J even). Sections shared by neighbouring elements are merged and their weights
//! summed: J·n_e + 1 sections of total weight L. Or the four-point Gauss–Legendre rule on each sub-interval (4J
//! sections per element, none shared): exact for polynomials of degree 7, so Σ_s k·weight_s·H_sᵀH_s is the consistent
//! foundation matrix k∫ΨᵀΨ dx of the element (degree 6) to round-off. Section s has the row H_s = Ψ(x_s), the
//! Hermite shape functions of w in its element (so Hᵀr carries forces and moments). Ballast friction and the
//! unilateral part of a nonlinear foundation are both placed this way.

use crate::error::{Result, TrackError};
use fem_beam::BeamModel;
use fem_beam::element::hermite;
use friction::InteractionRow;

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

/// Weight of sub-section s ∈ 0..=J of one element, as a fraction of the element length.
/// Trapezoid or Simpson only (Gauss sections are not shared between elements and weigh by [`hermite::GAUSS_4`]).
fn weight_fraction(quadrature: Quadrature, subdivisions: usize, s: usize) -> f64 {
    let j = subdivisions as f64;
    let end = s == 0 || s == subdivisions;
    match quadrature {
        Quadrature::Trapezoid => {
            if end {
                0.5 / j
            } else {
                1.0 / j
            }
        }
        Quadrature::Simpson => {
            let c = if end {
                1.0
            } else if s % 2 == 1 {
                4.0
            } else {
                2.0
            };
            c / (3.0 * j)
        }
        Quadrature::Gauss => unreachable!("Gauss weights are per point"),
    }
}

/// The row H = Ψ(ξ) of w at the local coordinate ξ ∈ [0, 1] of element `e` over the free DOFs (a node's row at
/// ξ = 0 or 1).
fn row_at(model: &BeamModel, e: usize, xi: f64) -> InteractionRow {
    let dofs = model.dofs();
    let l = model.mesh().element_length();
    if xi == 0.0 || xi == 1.0 {
        let node = e + xi as usize;
        InteractionRow::from_entries(dofs.free_index(2 * node).map(|d| (d, 1.0)))
    } else {
        let n = hermite::shape(xi, l);
        InteractionRow::from_entries((0..4).filter_map(|k| dofs.free_index(2 * e + k).map(|d| (d, n[k]))))
    }
}

/// The J·n_e + 1 sections of the mesh of `model` in order of x (those on supports have empty rows); J checked by
/// [`validate_subdivisions`] first.
pub fn sections(model: &BeamModel, subdivisions: usize, quadrature: Quadrature) -> Vec<QuadratureSection> {
    let mesh = model.mesh();
    let (ne, j) = (mesh.elements, subdivisions);
    let l = mesh.element_length();
    if quadrature == Quadrature::Gauss {
        let sub = l / j as f64;
        return (0..ne * j)
            .flat_map(|g| hermite::GAUSS_4.iter().map(move |&(t, w)| (g, t, w)))
            .map(|(g, t, w)| {
                let (e, i) = (g / j, g % j);
                let xi = (i as f64 + t) / j as f64;
                QuadratureSection { row: row_at(model, e, xi), weight: w * sub, x: (e as f64 + xi) * l }
            })
            .collect();
    }
    let mut weights = vec![0.0; ne * j + 1];
    for e in 0..ne {
        for s in 0..=j {
            weights[e * j + s] += weight_fraction(quadrature, j, s) * l;
        }
    }
    weights
        .iter()
        .enumerate()
        .map(|(g, &weight)| {
            let (e, s) = ((g / j).min(ne - 1), g - (g / j).min(ne - 1) * j);
            let xi = s as f64 / j as f64;
            QuadratureSection { row: row_at(model, e, xi), weight, x: (e as f64 + xi) * l }
        })
        .collect()
}
