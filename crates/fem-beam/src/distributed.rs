//! A law distributed along the beam and acted at sections (docs/theory.md §4, §13): the rule that places and weighs
//! the sections of each element (`Quadrature`, J sub-intervals), and ballast friction's description, f_u newtons per
//! metre at those sections — one description for the finite track (`track`, which places the sections on its mesh)
//! and the infinite one (`stationary`, which places them in moving coordinates).

use crate::element::hermite;
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

/// Where one section of a distributed law acts and what it weighs: its element, its local coordinate ξ ∈ [0, 1]
/// there, the length of beam it stands for (m) and its place x (m) from the mesh's first node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionPlace {
    /// The element; a node shared by two elements belongs to the left one (ξ = 1) only at the mesh's last node.
    pub element: usize,
    /// ξ ∈ [0, 1].
    pub xi: f64,
    /// The length the section stands for (m).
    pub weight: f64,
    /// x = (e + ξ)·l (m).
    pub x: f64,
}

/// The sections of `elements` elements of length `l` (m), J = `subdivisions` per element, in order of x: with
/// trapezoid or Simpson weights the J·n_e + 1 sections at ξ = s/J, a node shared by two elements one section whose
/// weight is the sum of both elements' (total weight n_e·l); with Gauss the 4J Gauss–Legendre points of every
/// element, none shared — exact for polynomials of degree 7, so Σ_s k·weight_s·ΨᵀΨ(ξ_s) is the consistent foundation
/// matrix k∫ΨᵀΨ dx (degree 6) to round-off. J is checked by [`validate_subdivisions`] first. This is the one rule both the finite
/// track and the stationary wave place their sections by.
pub fn section_places(elements: usize, l: f64, subdivisions: usize, quadrature: Quadrature) -> Vec<SectionPlace> {
    let j = subdivisions;
    if quadrature == Quadrature::Gauss {
        let sub = l / j as f64;
        return (0..elements * j)
            .flat_map(|g| hermite::GAUSS_4.iter().map(move |&(t, w)| (g, t, w)))
            .map(|(g, t, w)| {
                let (element, i) = (g / j, g % j);
                let xi = (i as f64 + t) / j as f64;
                SectionPlace { element, xi, weight: w * sub, x: (element as f64 + xi) * l }
            })
            .collect();
    }
    let mut weights = vec![0.0; elements * j + 1];
    for e in 0..elements {
        for s in 0..=j {
            weights[e * j + s] += weight_fraction(quadrature, j, s) * l;
        }
    }
    weights
        .iter()
        .enumerate()
        .map(|(g, &weight)| {
            let element = (g / j).min(elements - 1);
            let xi = (g - element * j) as f64 / j as f64;
            SectionPlace { element, xi, weight, x: (element as f64 + xi) * l }
        })
        .collect()
}

/// Weight of sub-section s ∈ 0..=J of one element, as a fraction of the element length: trapezoid 1/J inside and
/// 1/(2J) at the element's ends, Simpson (1, 4, 2, 4, …, 4, 1)/(3J). (Gauss points weigh by [`hermite::GAUSS_4`].)
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

    /// Every rule's weights sum to the mesh length (to a few ulps of summing ~J·n_e terms) and its places increase;
    /// trapezoid and Simpson share the nodes between elements (J·n_e + 1 sections), Gauss does not (4J·n_e).
    #[test]
    fn sections_cover_the_mesh_once_in_order() {
        let (elements, l) = (7, 0.37);
        for (quadrature, j, count) in
            [(Quadrature::Trapezoid, 3, 22), (Quadrature::Simpson, 4, 29), (Quadrature::Gauss, 2, 56)]
        {
            let places = section_places(elements, l, j, quadrature);
            assert_eq!(places.len(), count, "{quadrature:?}");
            let total: f64 = places.iter().map(|p| p.weight).sum();
            assert!((total - elements as f64 * l).abs() < 1e-14, "{quadrature:?}: {total}");
            assert!(places.windows(2).all(|p| p[0].x < p[1].x), "{quadrature:?}");
            for p in &places {
                assert!((p.x - (p.element as f64 + p.xi) * l).abs() < 1e-15 && (0.0..=1.0).contains(&p.xi));
            }
        }
        let last = *section_places(elements, l, 3, Quadrature::Trapezoid).last().unwrap();
        assert_eq!((last.element, last.xi), (elements - 1, 1.0));
    }
}
