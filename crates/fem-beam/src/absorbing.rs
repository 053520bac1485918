//! Absorbing end zones: foundation damping graded up towards the beam ends (docs/theory.md §8).
//!
//! A finite beam reflects the waves a moving load radiates (the wave train that trails a supercritical load reaches
//! the left end). Grading the foundation damping quadratically from the base value c_f to a peak c_peak over end
//! zones of length L_z absorbs them: in element e with midpoint at depth d into a zone,
//! c_e = c_f + (c_peak − c_f)·(d/L_z)². Measured on the 200 m beam (v = 250 m/s, ζ = 0.05, start at 60 m): the max
//! downward deflection is +3.9 % off the infinite-beam value untreated and +0.7 % with 40 m zones graded to c_cr.

use crate::error::{Result, non_negative, positive};
use crate::mesh::Mesh;

/// Quadratically graded damping zones at both ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AbsorbingZones {
    /// Length of each end zone L_z (m) > 0; at most half the beam. Default 40 m.
    pub length: f64,
    /// Damping reached at the very ends c_peak (N·s/m²) ≥ 0. Default: c_cr of the reference case, 7742 N·s/m².
    pub peak_damping: f64,
}

impl Default for AbsorbingZones {
    fn default() -> Self {
        Self { length: 40.0, peak_damping: 2.0 * (250.0e3f64 * 59.935).sqrt() }
    }
}

impl AbsorbingZones {
    /// Per-element foundation damping (N·s/m²) on `mesh`, starting from the uniform `base`.
    pub fn element_damping(&self, mesh: &Mesh, base: f64) -> Result<Vec<f64>> {
        positive("absorbing_zones.length", self.length)?;
        non_negative("absorbing_zones.peak_damping", self.peak_damping)?;
        if self.length > 0.5 * mesh.length {
            return Err(crate::FemError::InvalidField {
                field: "absorbing_zones.length",
                value: self.length,
                allowed: "must be at most half the beam length",
            });
        }
        let l = mesh.element_length();
        Ok((0..mesh.elements)
            .map(|e| {
                let x = (e as f64 + 0.5) * l;
                let depth = (self.length - x).max(x - (mesh.length - self.length)).max(0.0);
                let extra = (self.peak_damping - base).max(0.0);
                base + extra * (depth / self.length).powi(2)
            })
            .collect())
    }
}
