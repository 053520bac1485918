//! Distributed (ballast) friction of f_u newtons per metre (docs/theory.md §4).
//!
//! Each element is cut into J equal sub-intervals; the law is applied at the J+1 sections of every element, and the
//! distributed impulses are integrated against the shape functions with composite trapezoid weights l/J (interior)
//! and l/(2J) (element ends), or Simpson weights l/(3J)·(1, 4, 2, 4, …, 4, 1) (J even). Sections shared by
//! neighbouring elements are merged and their weights summed: J·n_e + 1 sections, total capacity f_u·L. Section s
//! has the row H_s = Ψ(x_s), the Hermite shape functions of w in its element (so Hᵀr carries forces and moments),
//! and the bound F_s = f_u·weight_s.

use crate::error::{Result, TrackError};
use crate::placed::{PlacedInteractions, SectionKind};
use fem_beam::BeamModel;
use fem_beam::element::hermite;
use friction::{InteractionRow, Law};

/// Quadrature of the distributed friction along each element.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Quadrature {
    /// Composite trapezoid rule (default).
    #[default]
    Trapezoid,
    /// Composite Simpson rule; needs an even number of sub-intervals.
    Simpson,
}

/// Friction distributed along the whole beam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistributedFriction {
    /// Maximal friction force per unit length f_u (N/m), ≥ 0. Studies use 0–10 kN/m.
    pub force_per_length: f64,
    /// Sub-intervals per element J ≥ 1. Default 4.
    pub subdivisions: usize,
    /// Quadrature rule. Default trapezoid.
    pub quadrature: Quadrature,
}

impl Default for DistributedFriction {
    fn default() -> Self {
        Self { force_per_length: 0.0, subdivisions: 4, quadrature: Quadrature::Trapezoid }
    }
}

impl DistributedFriction {
    /// f_u (N/m) with the default J = 4 and trapezoid weights.
    pub fn new(force_per_length: f64) -> Self {
        Self { force_per_length, ..Self::default() }
    }

    /// Check the parameters.
    pub fn validate(&self) -> Result<()> {
        if !(self.force_per_length.is_finite() && self.force_per_length >= 0.0) {
            return Err(TrackError::InvalidField {
                field: "distributed.force_per_length",
                value: self.force_per_length,
                allowed: "must be finite and ≥ 0 (N/m)".into(),
            });
        }
        if self.subdivisions == 0 || self.subdivisions > Self::MAX_SUBDIVISIONS {
            return Err(TrackError::InvalidCount {
                field: "distributed.subdivisions",
                value: self.subdivisions,
                allowed: format!(
                    "must lie in [1, {}]: finer sections than that add nothing a cubic element can show",
                    Self::MAX_SUBDIVISIONS
                ),
            });
        }
        if self.quadrature == Quadrature::Simpson && self.subdivisions % 2 == 1 {
            return Err(TrackError::InvalidCount {
                field: "distributed.subdivisions",
                value: self.subdivisions,
                allowed: "must be even with Simpson weights".into(),
            });
        }
        Ok(())
    }

    /// The most sub-intervals per element accepted (checked before the sections are allocated).
    pub const MAX_SUBDIVISIONS: usize = 64;

    /// Weight of sub-section s ∈ 0..=J of one element, as a fraction of the element length.
    fn weight_fraction(&self, s: usize) -> f64 {
        let j = self.subdivisions as f64;
        let end = s == 0 || s == self.subdivisions;
        match self.quadrature {
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
        }
    }

    /// The contact set on the mesh of `model`: J·n_e + 1 sections in order of x, minus those on supports.
    pub fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        self.validate()?;
        let mesh = model.mesh();
        let dofs = model.dofs();
        let (ne, j) = (mesh.elements, self.subdivisions);
        let l = mesh.element_length();
        let mut weights = vec![0.0; ne * j + 1];
        for e in 0..ne {
            for s in 0..=j {
                weights[e * j + s] += self.weight_fraction(s) * l;
            }
        }
        let mut set = PlacedInteractions::new();
        for (g, weight) in weights.iter().enumerate() {
            let (e, s) = ((g / j).min(ne - 1), g - (g / j).min(ne - 1) * j);
            let row = if s == 0 || s == j {
                let node = e + s / j;
                InteractionRow::from_entries(dofs.free_index(2 * node).map(|d| (d, 1.0)))
            } else {
                let n = hermite::shape(s as f64 / j as f64, l);
                InteractionRow::from_entries((0..4).filter_map(|k| dofs.free_index(2 * e + k).map(|d| (d, n[k]))))
            };
            let x = (e as f64 + s as f64 / j as f64) * l;
            set.push(row, Law::Coulomb { capacity: self.force_per_length * weight }, x, SectionKind::Ballast);
        }
        Ok(set)
    }
}
