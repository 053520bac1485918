//! Consistent load vectors: point forces and moments anywhere on the beam, uniform distributed loads.
//!
//! A point force P at x (N, positive upward) contributes P·N(ξ) to the four DOFs of the one element containing x
//! (forces *and* moments at its two nodes); a point moment C (N·m, counter-clockwise) contributes C·N_θ(ξ), the
//! rotation's row (N′ for Euler–Bernoulli, N_ψ for Timoshenko). N is the beam's element's
//! ([`Discretisation`]). A load on a node is assigned to a single element (see [`crate::Mesh::locate`]), so it is
//! never counted twice. A uniform load q (N/m) contributes (ql/2, ql²/12, ql/2, −ql²/12) per element, for either
//! theory.
//!
//! Loads are kept per element so that element end forces (hence bending moments at nodes) can be recovered.

use crate::discretisation::Discretisation;
use crate::element::{ElementVector, hermite};
use crate::error::{FemError, Result};
use crate::mesh::Mesh;
use crate::supports::DofMap;

/// The consistent nodal loads of one element, in element DOF order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementLoad {
    /// Element index.
    pub element: usize,
    /// Nodal forces (N) and moments (N·m) on (w_a, θ_a, w_b, θ_b).
    pub nodal: ElementVector,
}

impl ElementLoad {
    /// The consistent nodal loads F·Ψ(ξ) of a point force `force` (N, positive upward) at `x` (m), on the element
    /// that owns x ([`Mesh::locate`]: [x_a, x_b), the last element closed): nodal forces and moments, the one
    /// formula every point load of frictrack uses (static loads, the moving load, section results).
    pub fn point_force(beam: &Discretisation, x: f64, force: f64) -> Result<Self> {
        let (p, n) = beam.shape_at(x)?;
        Ok(Self { element: p.element, nodal: n.map(|v| v * force) })
    }
}

impl ElementLoad {
    /// The consistent nodal loads q·∫Ψᵀdx of a uniform load `per_length` (N/m, positive upward) over the part of
    /// [a, b] (m) that lies on the beam, one contribution per element it covers (none when it misses the beam):
    /// the closed-form integrals of the shape functions over partial elements ([`crate::element::Element::shape_integral`]).
    pub fn uniform_patch(
        beam: &Discretisation,
        a: f64,
        b: f64,
        per_length: f64,
    ) -> impl Iterator<Item = ElementLoad> + '_ {
        let (mesh, shape) = (beam.mesh(), beam.element());
        let l = mesh.element_length();
        let (a, b) = (a.max(0.0), b.min(mesh.length));
        let (first, last) =
            if b > a { ((a / l).floor() as usize, ((b / l).ceil() as usize).min(mesh.elements)) } else { (0, 0) };
        (first..last).filter_map(move |e| {
            let x_a = mesh.node_x(e);
            let (xi0, xi1) = (((a - x_a) / l).clamp(0.0, 1.0), ((b - x_a) / l).clamp(0.0, 1.0));
            (xi1 > xi0)
                .then(|| ElementLoad { element: e, nodal: shape.shape_integral(xi0, xi1).map(|v| v * per_length) })
        })
    }
}

/// A load case: a list of element contributions.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadVector {
    contributions: Vec<ElementLoad>,
}

fn finite(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() { Ok(value) } else { Err(FemError::InvalidField { field, value, allowed: "must be finite" }) }
}

impl LoadVector {
    /// No load.
    pub fn new() -> Self {
        Self::default()
    }

    /// A point force `force` (N, positive upward) at `x` (m).
    pub fn point_force(beam: &Discretisation, x: f64, force: f64) -> Result<Self> {
        let mut load = Self::new();
        load.add_point_force(beam, x, force)?;
        Ok(load)
    }

    /// Add a point force `force` (N, positive upward) at `x` (m).
    pub fn add_point_force(&mut self, beam: &Discretisation, x: f64, force: f64) -> Result<()> {
        finite("force", force)?;
        self.contributions.push(ElementLoad::point_force(beam, x, force)?);
        Ok(())
    }

    /// Add a point moment `moment` (N·m, positive counter-clockwise, i.e. work-conjugate to the rotation θ) at `x`.
    pub fn add_point_moment(&mut self, beam: &Discretisation, x: f64, moment: f64) -> Result<()> {
        finite("moment", moment)?;
        let p = beam.mesh().locate(x)?;
        let n = beam.element().rotation(p.xi);
        self.contributions.push(ElementLoad { element: p.element, nodal: n.map(|v| v * moment) });
        Ok(())
    }

    /// Add one element's consistent loads.
    pub fn push(&mut self, load: ElementLoad) {
        self.contributions.push(load);
    }

    /// Add a uniform load `per_length` (N/m, positive upward) over the part of [a, b] (m) on the beam.
    pub fn add_patch(&mut self, beam: &Discretisation, a: f64, b: f64, per_length: f64) -> Result<()> {
        finite("patch load", per_length)?;
        finite("patch start", a)?;
        finite("patch end", b)?;
        self.contributions.extend(ElementLoad::uniform_patch(beam, a, b, per_length));
        Ok(())
    }

    /// A uniform load `per_length` (N/m, positive upward) over the whole beam, e.g. self-weight −ρA·g: the same
    /// nodal loads for either theory (∫N_w dx over an element does not depend on φ).
    pub fn uniform(mesh: &Mesh, per_length: f64) -> Result<Self> {
        finite("uniform load", per_length)?;
        let l = mesh.element_length();
        let nodal = hermite::uniform_load(per_length, l);
        Ok(Self { contributions: (0..mesh.elements).map(|element| ElementLoad { element, nodal }).collect() })
    }

    /// Append another load case.
    pub fn extend(&mut self, other: &LoadVector) {
        self.contributions.extend_from_slice(&other.contributions);
    }

    /// The element contributions.
    pub fn contributions(&self) -> &[ElementLoad] {
        &self.contributions
    }

    /// Assembled full-DOF vector (length 2·(n_e + 1)).
    pub fn to_full(&self, mesh: &Mesh) -> Vec<f64> {
        let mut full = vec![0.0; 2 * mesh.nodes()];
        for c in &self.contributions {
            for k in 0..4 {
                full[2 * c.element + k] += c.nodal[k];
            }
        }
        full
    }

    /// Assembled free-DOF vector (loads on constrained DOFs are taken by the supports).
    pub fn to_free(&self, mesh: &Mesh, dofs: &DofMap) -> Vec<f64> {
        let mut full = self.to_full(mesh);
        // Sleepers' DOFs (after the rail's) carry no load of their own.
        full.resize(dofs.full_len(), 0.0);
        dofs.reduce(&full)
    }

    /// Sum of all nodal forces (the w components), N: equals the total applied force.
    pub fn total_force(&self) -> f64 {
        self.contributions.iter().map(|c| c.nodal[0] + c.nodal[2]).sum()
    }
}
