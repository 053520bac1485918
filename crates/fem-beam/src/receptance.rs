//! The track's response to a harmonic force (docs/theory.md §17): receptance α(ω) = w(x)/F (m/N) and mobility
//! iωα (m/s/N) at a place x for a unit force F e^{iωt} at a place x_F, from the model's own matrices:
//!
//! ```text
//! (K_rail (1 + iη_r) + K_soil (1 + iη_f) + iω C − ω² M) q = f,     α = H(x) q
//! ```
//!
//! with K_rail the beam's stiffness (bending, and shear for Timoshenko), K_soil the foundation's linear part, C every
//! viscous term of the model (foundation dashpots, absorbing zones, Rayleigh on the rail's elements), M the mass,
//! η_r and η_f loss factors (hysteretic damping as the literature quotes it: `Beam::loss_factor`,
//! `Foundation::loss_factor`), f = N_w(x_F)ᵀ the consistent load and H(x) the element's N_w there; sleepers
//! (docs/theory.md §18) add their mass and, each with its loss factor, their pads and ballast (their own dashpots:
//! Rayleigh damping is not applied to them here). One complex banded LU per frequency ([`banded::general`], partial
//! pivoting).

use crate::assembly::BeamModel;
use crate::element::ElementMatrix;
use crate::element_loop::add_elements;
use crate::error::{FemError, Result};
use banded::general::GeneralBanded;
use num_complex::Complex64;

/// The harmonic response of a model.
#[derive(Debug, Clone, Copy)]
pub struct FrequencyResponse<'a> {
    model: &'a BeamModel,
}

impl<'a> FrequencyResponse<'a> {
    /// The response of `model`, with the loss factors of its beam and foundation.
    pub fn new(model: &'a BeamModel) -> Self {
        Self { model }
    }

    /// The receptances (m/N) at each of `at` (m) for a unit force at `excite` (m) at circular frequency `omega`
    /// (rad/s, ≥ 0). A singular dynamic stiffness (an undamped natural frequency hit exactly) is an error.
    pub fn receptance(&self, omega: f64, excite: f64, at: &[f64]) -> Result<Vec<Complex64>> {
        let model = self.model;
        let beam = model.discretisation();
        let dofs = model.dofs();
        let (point, shape) = beam.shape_at(excite)?;
        let mut rhs = vec![Complex64::new(0.0, 0.0); dofs.free_len()];
        for (free, n) in dofs.element_free(point.element).into_iter().zip(shape) {
            if let Some(d) = free {
                rhs[d] += n;
            }
        }
        let lu = self.dynamic_stiffness(omega).factor().map_err(|_| FemError::InvalidField {
            field: "frequency",
            value: omega / std::f64::consts::TAU,
            allowed: "must not be an undamped natural frequency of the track (give it damping or a loss factor)",
        })?;
        lu.solve_in_place(&mut rhs);
        at.iter()
            .map(|&x| {
                let (p, n) = beam.shape_at(x)?;
                Ok(dofs.element_free(p.element).into_iter().zip(n).filter_map(|(d, n)| d.map(|d| rhs[d] * n)).sum())
            })
            .collect()
    }

    /// D(ω) = K_rail(1 + iη_r) + K_soil(1 + iη_f) + iωC − ω²M over the free DOFs, element by element.
    fn dynamic_stiffness(&self, omega: f64) -> GeneralBanded<Complex64> {
        let model = self.model;
        let (dofs, element) = (model.dofs(), model.element());
        let rail = element.stiffness(model.beam().bending_stiffness());
        let soil = element.distributed(model.foundation().tension_stiffness());
        let mass = model.element_mass();
        let band = model.stiffness().bandwidth();
        let mut out = GeneralBanded::zeros(dofs.free_len(), band, band);
        let (rail_factor, soil_factor) =
            (Complex64::new(1.0, model.beam().loss_factor), Complex64::new(1.0, model.foundation().loss_factor));
        add_elements(
            &mut out,
            model.mesh().elements,
            |e| dofs.element_free(e),
            |e| {
                dynamic_element(
                    [(rail_factor, &rail), (soil_factor, &soil)],
                    &mass,
                    &model.element_damping_matrix(e),
                    omega,
                )
            },
        );
        self.add_embankment(&mut out, omega);
        if let Some((sleepers, nodes)) = model.sleepers() {
            // Each layer's spring with its own loss factor and its dashpot; the masses' inertia −ω²m.
            let layers = |s: &crate::SleeperSupport| {
                [s.pad, s.ballast, s.subgrade.unwrap_or_default()].map(|l| l.dynamic_stiffness(omega))
            };
            let inertia = |m: f64| Complex64::new(-omega * omega * m, 0.0);
            for (i, j, value) in sleepers.entries(dofs, nodes, layers, inertia) {
                out.add(i, j, value);
                if i != j {
                    out.add(j, i, value);
                }
            }
        }
        out
    }

    /// The embankment's part of D(ω), if the track has one: its bending with its loss factor, its soil's spring with
    /// the soil's, its dashpots, its mass.
    fn add_embankment(&self, out: &mut GeneralBanded<Complex64>, omega: f64) {
        let model = self.model;
        let Some(below) = model.embankment() else { return };
        let dofs = model.dofs();
        let l = model.mesh().element_length();
        let element = below.element(l);
        let bending = element.stiffness(below.beam.bending_stiffness());
        let soil = element.distributed(below.foundation.stiffness);
        let mass = below.element_mass(l);
        let (bending_factor, soil_factor) =
            (Complex64::new(1.0, below.beam.loss_factor), Complex64::new(1.0, below.foundation.loss_factor));
        add_elements(
            out,
            model.mesh().elements,
            |e| dofs.embankment_element_free(e),
            |e| {
                let parts = [(bending_factor, &bending), (soil_factor, &soil)];
                dynamic_element(parts, &mass, &below.element_damping_matrix(e, l), omega)
            },
        );
    }
}

/// An element's dynamic stiffness Σ (1 + iη) K_part − ω²M + iωC: each stiffness with its hysteretic factor.
fn dynamic_element(
    parts: [(Complex64, &ElementMatrix); 2],
    mass: &ElementMatrix,
    damping: &ElementMatrix,
    omega: f64,
) -> [[Complex64; 4]; 4] {
    std::array::from_fn(|a| {
        std::array::from_fn(|b| {
            parts.iter().map(|(factor, k)| factor * k[a][b]).sum::<Complex64>()
                + Complex64::new(-omega * omega * mass[a][b], omega * damping[a][b])
        })
    })
}
