//! The mesh of a beam together with the element its theory uses: where a point x of the beam lies (its element and
//! local coordinate ξ) and the shape functions there — what a load, a contact or a friction section needs to act on
//! the beam consistently with its matrices.

use crate::element::{Element, ElementVector};
use crate::error::Result;
use crate::mesh::{ElementPoint, Mesh};

/// A mesh and its element, paired by the model ([`crate::BeamModel::discretisation`]) so that a caller cannot act
/// on a Timoshenko beam with Euler–Bernoulli shape functions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Discretisation {
    mesh: Mesh,
    element: Element,
}

impl Discretisation {
    /// An Euler–Bernoulli beam's: the Hermite element on `mesh`.
    pub fn euler_bernoulli(mesh: Mesh) -> Self {
        Self { mesh, element: Element::Hermite { length: mesh.element_length() } }
    }

    /// `mesh` with `element` (of its element length): the model's.
    pub(crate) fn new(mesh: Mesh, element: Element) -> Self {
        Self { mesh, element }
    }

    /// The mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The element.
    pub fn element(&self) -> Element {
        self.element
    }

    /// Where `x` (m) lies ([`Mesh::locate`]) and N_w there.
    pub fn shape_at(&self, x: f64) -> Result<(ElementPoint, ElementVector)> {
        let p = self.mesh.locate(x)?;
        Ok((p, self.element.shape(p.xi)))
    }
}
