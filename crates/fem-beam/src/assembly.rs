//! Global assembly of the semi-discrete beam–foundation system M q̈ + C q̇ + K q = f (docs/theory.md §3).
//!
//! M = Σ ρA·l/420·P, K = Σ (EI/l³·[…] + k_f·l/420·P), C = Σ c_f,e·l/420·P over the elements, assembled into
//! [`SymmetricBanded`] matrices over the free DOFs (half-bandwidth 3). The foundation damping may vary from element
//! to element (absorbing end zones); by default it is the uniform c_f of the [`Foundation`].

use crate::discretisation::Discretisation;
use crate::element::{Element, ElementMatrix, hermite};
use crate::element_loop::add_elements;
use crate::embankment::EmbankmentBeam;
use crate::error::{FemError, Result};
use crate::mesh::Mesh;
use crate::properties::{Beam, Foundation, Rayleigh};
use crate::sleepers::Sleepers;
use crate::supports::{DofMap, Supports};
use banded::SymmetricBanded;

/// Half-bandwidth of assembled beam matrices: 3; with sleepers 3 + their DOFs per sleeper (4, or 5 under ballast
/// bodies: a sleeper's DOFs sit between its node's and the next's), and 2 more over an embankment beam.
pub const BANDWIDTH: usize = 3;

/// The assembled beam on its foundation: parameters, DOF map and the banded M, C, K over the free DOFs.
#[derive(Debug, Clone)]
pub struct BeamModel {
    beam: Beam,
    foundation: Foundation,
    mesh: Mesh,
    supports: Supports,
    dofs: DofMap,
    element_damping: Vec<f64>,
    mass: SymmetricBanded,
    stiffness: SymmetricBanded,
    damping: SymmetricBanded,
    rayleigh: Rayleigh,
    sleepers: Option<(Sleepers, Vec<usize>)>,
    embankment: Option<EmbankmentBeam>,
}

impl BeamModel {
    /// Validate the parameters and assemble, with the foundation's uniform damping on every element.
    pub fn new(beam: Beam, foundation: Foundation, mesh: Mesh, supports: Supports) -> Result<Self> {
        mesh.validate()?;
        let damping = vec![foundation.damping; mesh.elements];
        Self::with_element_damping(beam, foundation, mesh, supports, damping)
    }

    /// Validate and assemble with a foundation damping c_f,e (N·s/m²) given per element (e.g. graded absorbing
    /// zones at the ends). `foundation.damping` is then only informative.
    pub fn with_element_damping(
        beam: Beam,
        foundation: Foundation,
        mesh: Mesh,
        supports: Supports,
        element_damping: Vec<f64>,
    ) -> Result<Self> {
        beam.validate()?;
        foundation.validate()?;
        mesh.validate()?;
        if element_damping.len() != mesh.elements {
            return Err(FemError::LengthMismatch {
                what: "element damping",
                actual: element_damping.len(),
                expected: mesh.elements,
            });
        }
        if let Some(&bad) = element_damping.iter().find(|c| !(c.is_finite() && **c >= 0.0)) {
            return Err(FemError::InvalidField {
                field: "foundation.damping (element)",
                value: bad,
                allowed: "must be finite and ≥ 0",
            });
        }
        Self::assemble(beam, foundation, mesh, supports, element_damping, None, None)
    }

    /// The model with `sleepers` under the rail (docs/theory.md §18): a DOF per sleeper beside its node (two under
    /// a ballast body), the masses, pad, ballast and subgrade in M, C, K (Rayleigh damping, if any, applied again over them).
    pub fn with_sleepers(self, sleepers: Sleepers) -> Result<Self> {
        self.with_track(sleepers, None)
    }

    /// The model with `sleepers` under the rail whose ballast rests on `embankment`, a second beam on the same nodes
    /// (docs/theory.md §19): its w_e, θ_e beside each node's, its bending, mass, foundation and dashpots in K, M, C,
    /// and the ballast between each sleeper's z and the w_e at its node. The ballast cannot then be a body of its own.
    pub fn with_sleepers_on_embankment(self, sleepers: Sleepers, embankment: EmbankmentBeam) -> Result<Self> {
        if let Some(body) = sleepers.ballast_body {
            return Err(FemError::InvalidField {
                field: "sleepers.ballast.mass",
                value: body.mass,
                allowed: "must be left out over an embankment: the ballast is the layer between the sleepers and it",
            });
        }
        if embankment.element_damping.len() != self.mesh.elements {
            return Err(FemError::LengthMismatch {
                what: "embankment element damping",
                actual: embankment.element_damping.len(),
                expected: self.mesh.elements,
            });
        }
        self.with_track(sleepers, Some(embankment))
    }

    fn with_track(self, sleepers: Sleepers, embankment: Option<EmbankmentBeam>) -> Result<Self> {
        let nodes = sleepers.nodes(&self.mesh)?;
        let Self { beam, foundation, mesh, supports, element_damping, rayleigh, .. } = self;
        let model =
            Self::assemble(beam, foundation, mesh, supports, element_damping, Some((sleepers, nodes)), embankment)?;
        if rayleigh.is_zero() { Ok(model) } else { model.with_rayleigh(rayleigh) }
    }

    fn assemble(
        beam: Beam,
        foundation: Foundation,
        mesh: Mesh,
        supports: Supports,
        element_damping: Vec<f64>,
        sleepers: Option<(Sleepers, Vec<usize>)>,
        embankment: Option<EmbankmentBeam>,
    ) -> Result<Self> {
        let (dofs, band) = match &sleepers {
            None => (DofMap::new(mesh.nodes(), supports), BANDWIDTH),
            Some((s, nodes)) => {
                let per = s.dofs_per_sleeper();
                let below = embankment.is_some();
                let band = BANDWIDTH + per + if below { 2 } else { 0 };
                (DofMap::with_track(mesh.nodes(), supports, nodes, per, below), band)
            }
        };
        let l = mesh.element_length();
        let element = Element::of(&beam, l);
        let me = element.mass(&beam);
        let ke = Self::element_stiffness_of(&beam, &foundation, l);
        let n = dofs.free_len();
        let (mut mass, mut stiffness, mut damping) =
            (SymmetricBanded::zeros(n, band), SymmetricBanded::zeros(n, band), SymmetricBanded::zeros(n, band));
        let free = |e: usize| dofs.element_free(e);
        add_elements(&mut mass, mesh.elements, free, |_| me);
        add_elements(&mut stiffness, mesh.elements, free, |_| ke);
        add_elements(&mut damping, mesh.elements, free, |e| element.distributed(element_damping[e]));
        if let Some(below) = &embankment {
            let lower = |e: usize| dofs.embankment_element_free(e);
            let (me, ke) = (below.element_mass(l), below.element_stiffness(l));
            add_elements(&mut mass, mesh.elements, lower, |_| me);
            add_elements(&mut stiffness, mesh.elements, lower, |_| ke);
            add_elements(&mut damping, mesh.elements, lower, |e| below.element_damping_matrix(e, l));
        }
        if let Some((layers, nodes)) = &sleepers {
            type Layers = fn(&crate::SleeperSupport) -> [f64; 3];
            let entries = |matrix: &mut SymmetricBanded, layers_of: Layers, mass: fn(f64) -> f64| {
                for (i, j, value) in layers.entries(&dofs, nodes, layers_of, mass) {
                    matrix.add(i, j, value);
                }
            };
            entries(&mut mass, |_| [0.0; 3], |m| m);
            entries(
                &mut damping,
                |s| [s.pad.damping, s.bonded_damping(), s.subgrade.unwrap_or_default().damping],
                |_| 0.0,
            );
            entries(
                &mut stiffness,
                |s| [s.pad.stiffness, s.bonded_stiffness(), s.subgrade.unwrap_or_default().stiffness],
                |_| 0.0,
            );
        }
        let rayleigh = Rayleigh::default();
        Ok(Self {
            beam,
            foundation,
            mesh,
            supports,
            dofs,
            element_damping,
            mass,
            stiffness,
            damping,
            rayleigh,
            sleepers,
            embankment,
        })
    }

    /// The model with Rayleigh damping α M + β K added to C (docs/theory.md §10); its element damping matrices
    /// (for section results) include it too.
    pub fn with_rayleigh(mut self, rayleigh: Rayleigh) -> Result<Self> {
        rayleigh.validate()?;
        self.damping = SymmetricBanded::linear_combination(&[
            (1.0, &self.damping),
            (rayleigh.mass_coefficient, &self.mass),
            (rayleigh.stiffness_coefficient, &self.stiffness),
        ]);
        self.rayleigh = rayleigh;
        Ok(self)
    }

    /// The track's weight (N over the free DOFs, downward negative): the rail's ρA·g as consistent loads (a
    /// Timoshenko element's over a whole element are Hermite's), each sleeper's m_s·g on its z and each ballast
    /// body's m_b·g on its y (docs/theory.md §13, §18).
    pub fn self_weight(&self) -> Result<Vec<f64>> {
        let rail = crate::load::LoadVector::uniform(&self.mesh, -self.beam.mass_per_length() * crate::GRAVITY)?;
        let mut weight = rail.to_free(&self.mesh, &self.dofs);
        if let Some((sleepers, nodes)) = &self.sleepers {
            for s in 0..nodes.len() {
                weight[self.dofs.sleeper(s)] -= sleepers.mass * crate::GRAVITY;
                if let (Some(y), Some(body)) = (self.dofs.ballast_body(s), sleepers.ballast_body) {
                    weight[y] -= body.mass * crate::GRAVITY;
                }
            }
        }
        Ok(weight)
    }

    /// The sleepers and the node under each, if the rail lies on discrete supports.
    pub fn sleepers(&self) -> Option<(&Sleepers, &[usize])> {
        self.sleepers.as_ref().map(|(s, nodes)| (s, nodes.as_slice()))
    }

    /// The embankment beam under the sleepers' ballast, if the track has one.
    pub fn embankment(&self) -> Option<&EmbankmentBeam> {
        self.embankment.as_ref()
    }

    /// The Rayleigh damping in C (zero unless [`BeamModel::with_rayleigh`]).
    pub fn rayleigh(&self) -> Rayleigh {
        self.rayleigh
    }

    fn element_stiffness_of(beam: &Beam, foundation: &Foundation, l: f64) -> ElementMatrix {
        let element = Element::of(beam, l);
        let kb = element.stiffness(beam.bending_stiffness());
        let kf = element.distributed(foundation.tension_stiffness());
        hermite::combine(1.0, &kb, 1.0, &kf)
    }

    /// The element of the mesh (all elements are alike): its theory's shape functions and matrices.
    pub fn element(&self) -> Element {
        Element::of(&self.beam, self.mesh.element_length())
    }

    /// The mesh with its element: where loads, contacts and sections act on this beam.
    pub fn discretisation(&self) -> Discretisation {
        Discretisation::new(self.mesh, self.element())
    }

    /// Beam (rail) parameters.
    pub fn beam(&self) -> &Beam {
        &self.beam
    }

    /// Foundation parameters.
    pub fn foundation(&self) -> &Foundation {
        &self.foundation
    }

    /// The mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The end supports.
    pub fn supports(&self) -> Supports {
        self.supports
    }

    /// Full ↔ free DOF map.
    pub fn dofs(&self) -> &DofMap {
        &self.dofs
    }

    /// Foundation damping c_f of each element (N·s/m²).
    pub fn element_damping(&self) -> &[f64] {
        &self.element_damping
    }

    /// Mass matrix M (free DOFs).
    pub fn mass(&self) -> &SymmetricBanded {
        &self.mass
    }

    /// Stiffness matrix K, bending plus the foundation's linear part k_t ([`Foundation::tension_stiffness`]; k_f for
    /// a linear foundation) (free DOFs).
    pub fn stiffness(&self) -> &SymmetricBanded {
        &self.stiffness
    }

    /// Damping matrix C from the foundation dashpots (free DOFs).
    pub fn damping(&self) -> &SymmetricBanded {
        &self.damping
    }

    /// Element stiffness (bending + foundation), identical for all elements.
    pub fn element_stiffness(&self) -> ElementMatrix {
        Self::element_stiffness_of(&self.beam, &self.foundation, self.mesh.element_length())
    }

    /// Element mass matrix, identical for all elements.
    pub fn element_mass(&self) -> ElementMatrix {
        self.element().mass(&self.beam)
    }

    /// Element damping matrix of element `e`: its foundation dashpots and the Rayleigh terms α M_e + β K_e.
    pub fn element_damping_matrix(&self, e: usize) -> ElementMatrix {
        let foundation = self.element().distributed(self.element_damping[e]);
        if self.rayleigh.is_zero() {
            return foundation;
        }
        let r = self.rayleigh;
        let structure = hermite::combine(
            r.mass_coefficient,
            &self.element_mass(),
            r.stiffness_coefficient,
            &self.element_stiffness(),
        );
        hermite::combine(1.0, &foundation, 1.0, &structure)
    }
}
