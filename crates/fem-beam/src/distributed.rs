//! A law distributed along the beam and acted at sections (docs/theory.md §4, §13): the rule that places and weighs
//! the sections of each element (`Quadrature`, J sub-intervals), and ballast friction's description, f_u newtons per
//! metre at those sections — one description for the finite track (`track`, which places the sections on its mesh)
//! and the infinite one (`stationary`, which places them in moving coordinates).

use crate::error::{FemError, Result};

/// Quadrature of a distributed law along each element.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Quadrature {
    /// Composite trapezoid rule (default).
    #[default]
    Trapezoid,
    /// Composite Simpson rule; needs an even number of sub-intervals.
    Simpson,
    /// Four-point Gauss–Legendre rule on each sub-interval: the consistent foundation matrix exactly.
    Gauss,
}

impl Quadrature {
    /// Its name in scenario files and messages: "trapezoid", "simpson" or "gauss".
    pub fn name(self) -> &'static str {
        match self {
            Quadrature::Trapezoid => "trapezoid",
            Quadrature::Simpson => "simpson",
            Quadrature::Gauss => "gauss",
        }
    }
}

/// The most sub-intervals per element accepted (checked before the sections are allocated).
pub const MAX_SUBDIVISIONS: usize = 64;

/// Check J ∈ [1, [`MAX_SUBDIVISIONS`]] (even with Simpson weights); `field` names it in the error.
pub fn validate_subdivisions(field: &'static str, subdivisions: usize, quadrature: Quadrature) -> Result<()> {
    if subdivisions == 0 || subdivisions > MAX_SUBDIVISIONS {
        return Err(FemError::InvalidCount {
            field,
            value: subdivisions,
            allowed: "must lie in [1, 64]: finer sections than that add nothing a cubic element can show",
        });
    }
    if quadrature == Quadrature::Simpson && subdivisions % 2 == 1 {
        return Err(FemError::InvalidCount {
            field,
            value: subdivisions,
            allowed: "must be even with Simpson weights",
        });
    }
    Ok(())
}

/// Friction distributed along the whole beam: a Coulomb law at each section with the bound f_u·weight.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistributedFriction {
    /// Maximal friction force per unit length f_u (N/m), ≥ 0; 0 = none. Studies use 0–10 kN/m.
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

    /// Check f_u and J, named `distributed.force_per_length` and `distributed.subdivisions`.
    pub fn validate(&self) -> Result<()> {
        if !(self.force_per_length.is_finite() && self.force_per_length >= 0.0) {
            return Err(FemError::InvalidField {
                field: "distributed.force_per_length",
                value: self.force_per_length,
                allowed: "must be finite and ≥ 0 (N/m)",
            });
        }
        validate_subdivisions("distributed.subdivisions", self.subdivisions, self.quadrature)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_the_message_states_is_the_one_checked() {
        let error = validate_subdivisions("j", MAX_SUBDIVISIONS + 1, Quadrature::Gauss).unwrap_err().to_string();
        assert!(error.contains(&format!("[1, {MAX_SUBDIVISIONS}]")), "{error}");
        assert!(validate_subdivisions("j", MAX_SUBDIVISIONS, Quadrature::Trapezoid).is_ok());
        assert!(validate_subdivisions("j", 3, Quadrature::Simpson).is_err());
        let negative = DistributedFriction::new(-1.0).validate().unwrap_err().to_string();
        assert!(negative.contains("distributed.force_per_length = -1"), "{negative}");
    }
}
