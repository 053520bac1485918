//! The embankment as a second beam under the sleepers' ballast (docs/theory.md §19, "The two-beam track in time"):
//! the part of the embankment one rail rests on — half the embankment's EI_e and ρA_e — a Hermite beam on the nodes of
//! the rail's mesh, on a foundation (a Winkler soil, or the ground's strip fitted along the load's line), each
//! element with its own dashpot (graded towards the ends where the run absorbs its waves). The sleepers' ballast
//! joins each sleeper to the embankment's w_e at its node, so a voided, tensionless or frictional sleeper acts between
//! the two, and the embankment's bending spreads what the ballast hands it — which a mass per rail seat on its own
//! spring (the ballast body) cannot.

use crate::element::{Element, ElementMatrix, hermite};
use crate::error::{FemError, Result, positive};
use crate::properties::{Beam, BeamTheory, Foundation};

/// One rail's share of the embankment, as a beam on its foundation.
#[derive(Debug, Clone, PartialEq)]
pub struct EmbankmentBeam {
    /// EI (N·m²) > 0 and ρA (kg/m) > 0 of the share, as an Euler–Bernoulli beam of unit I and A (E = EI, ρ = ρA);
    /// its loss factor the receptance's.
    pub beam: Beam,
    /// What carries it (per metre of this share), linear.
    pub foundation: Foundation,
    /// c_f of each element (N·s/m²), ≥ 0.
    pub element_damping: Vec<f64>,
}

impl EmbankmentBeam {
    /// The share with bending stiffness `bending_stiffness` (N·m²), mass `mass_per_length` (kg/m) and loss factor
    /// `loss_factor`, on `foundation`, its dashpot `element_damping` per element; every value checked.
    pub fn new(
        bending_stiffness: f64,
        mass_per_length: f64,
        loss_factor: f64,
        foundation: Foundation,
        element_damping: Vec<f64>,
    ) -> Result<Self> {
        positive("embankment.bending_stiffness", bending_stiffness)?;
        positive("embankment.mass_per_length", mass_per_length)?;
        let beam = Beam {
            youngs_modulus: bending_stiffness,
            second_moment: 1.0,
            area: 1.0,
            density: mass_per_length,
            theory: BeamTheory::EulerBernoulli,
            loss_factor,
        };
        beam.validate()?;
        foundation.validate()?;
        if !foundation.law.is_linear() {
            return Err(FemError::InvalidField {
                field: "foundation.law",
                value: foundation.law.tension_ratio(),
                allowed: "must be linear under an embankment: the embankment rests on the soil throughout",
            });
        }
        if let Some(&bad) = element_damping.iter().find(|c| !(c.is_finite() && **c >= 0.0)) {
            return Err(FemError::InvalidField {
                field: "embankment foundation damping (element)",
                value: bad,
                allowed: "must be finite and ≥ 0",
            });
        }
        Ok(Self { beam, foundation, element_damping })
    }

    /// Its element of length `l` (m).
    pub fn element(&self, l: f64) -> Element {
        Element::of(&self.beam, l)
    }

    /// The element's stiffness: bending and the foundation's spring.
    pub fn element_stiffness(&self, l: f64) -> ElementMatrix {
        let element = self.element(l);
        let bending = element.stiffness(self.beam.bending_stiffness());
        hermite::combine(1.0, &bending, 1.0, &element.distributed(self.foundation.stiffness))
    }

    /// The element's consistent mass.
    pub fn element_mass(&self, l: f64) -> ElementMatrix {
        self.element(l).mass(&self.beam)
    }

    /// Element `e`'s dashpot matrix.
    pub fn element_damping_matrix(&self, e: usize, l: f64) -> ElementMatrix {
        self.element(l).distributed(self.element_damping[e])
    }
}
