//! A uniform mesh of n_e equal beam elements on [0, L], nodes x_i = i·L/n_e.

use crate::error::{FemError, Result, positive};

/// Uniform 1-D mesh of equal Hermite elements.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(default, deny_unknown_fields))]
pub struct Mesh {
    /// Beam length L (m). Default 200 m; must be > 0.
    pub length: f64,
    /// Number of elements n_e. Default 200; must lie in [1, [`Mesh::MAX_ELEMENTS`]].
    pub elements: usize,
}

impl Default for Mesh {
    fn default() -> Self {
        Self { length: 200.0, elements: 200 }
    }
}

/// Where a point of the beam lies: its element and the local coordinate ξ = (x − x_e)/l ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementPoint {
    /// Element index, 0-based.
    pub element: usize,
    /// Local coordinate in [0, 1].
    pub xi: f64,
}

impl Mesh {
    /// The largest mesh accepted: 10⁶ elements (2·10⁶ DOFs, a few hundred MB of banded matrices and state).
    pub const MAX_ELEMENTS: usize = 1_000_000;

    /// A mesh of `elements` equal elements on [0, `length`], validated.
    pub fn new(length: f64, elements: usize) -> Result<Self> {
        let mesh = Self { length, elements };
        mesh.validate()?;
        Ok(mesh)
    }

    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<()> {
        positive("mesh.length", self.length)?;
        if self.elements == 0 || self.elements > Self::MAX_ELEMENTS {
            return Err(FemError::InvalidCount {
                field: "mesh.elements",
                value: self.elements,
                allowed: "must lie in [1, 1000000] (checked before any memory is allocated)",
            });
        }
        Ok(())
    }

    /// Element length l = L / n_e (m).
    pub fn element_length(&self) -> f64 {
        self.length / self.elements as f64
    }

    /// Number of nodes n_e + 1.
    pub fn nodes(&self) -> usize {
        self.elements + 1
    }

    /// Abscissa of node `i` (m).
    pub fn node_x(&self, node: usize) -> f64 {
        self.length * node as f64 / self.elements as f64
    }

    /// The element containing `x` and the local coordinate there.
    ///
    /// Each point belongs to exactly one element: an interior node belongs to the element on its right (the last
    /// node to the last element), so a load on a node is never counted twice. Errors if `x` is not finite or
    /// outside [0, L].
    pub fn locate(&self, x: f64) -> Result<ElementPoint> {
        if !(x.is_finite() && (0.0..=self.length).contains(&x)) {
            return Err(FemError::InvalidField {
                field: "position",
                value: x,
                allowed: "must lie on the beam, in [0, L]",
            });
        }
        let l = self.element_length();
        let element = ((x / l).floor() as usize).min(self.elements - 1);
        let xi = ((x - element as f64 * l) / l).clamp(0.0, 1.0);
        Ok(ElementPoint { element, xi })
    }

    /// The node nearest to `x`, a tie going to the node of larger x. Errors like [`Mesh::locate`].
    pub fn nearest_node(&self, x: f64) -> Result<usize> {
        self.locate(x)?;
        let node = (x / self.element_length() + 0.5).floor() as usize;
        Ok(node.min(self.elements))
    }
}
