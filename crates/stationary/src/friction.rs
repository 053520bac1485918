//! Ballast friction in the moving frame (docs/theory.md §14.4). A material point meets the wave at s = +∞ and
//! leaves it at s = −∞: its friction force depends on what the wave did to it *ahead* of where it stands, so the
//! force along s is a hysteresis (a play operator) of W, marched from the front. Each section is a Jenkins element —
//! a spring κ (N/m², per unit length) in series with a Coulomb slider of strength f_u (N/m):
//!
//! ```text
//! r_i = clamp(r_{i+1} + κ (W_i − W_{i+1}), −f_u, f_u),     r at the front = 0, W beyond the front = W_far,
//! ```
//!
//! from the front section to the rear one (W_i = H_i W, the deflection at section i). A section whose trial force
//! passes ±f_u slips (the material point moves, r = f_u·sign of its velocity −vW′); one within it is stuck, and its
//! force is r_a + κ (W_i − W_a) after the last slipping section a ahead of it (or κ (W_i − W_far) if none: the rail
//! has not moved since it left the far field). As κ → ∞ this is the rigid Coulomb law of a time-domain run: a stuck
//! point does not move. κ = [`JENKINS_RATIO`]·k_c moves a stuck point by at most f_u/κ, 1e-6 of the largest
//! deflection friction can hold, f_u/k_c.
//!
//! The sections are placed and weighed by the rule a time-domain run uses (`fem_beam::distributed::section_places`,
//! trapezoid: J per element, shared nodes, weights l/J and l/2J at the domain's ends), so the two methods discretise
//! the same ballast.

use crate::rows::{add_spring, row_add, row_dot};
use banded::general::GeneralBanded;
use fem_beam::DistributedFriction;
use fem_beam::distributed::section_places;
use fem_beam::element::Element;

/// κ/k_c: the Jenkins stiffness over the soil's (see the module doc).
pub const JENKINS_RATIO: f64 = 1e6;

/// One friction section: its element, its row Ψ(ξ) over the element's four DOFs, its length of ballast (m) and
/// its place s (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionSection {
    /// The element; its DOFs are 2e … 2e + 3.
    pub element: usize,
    /// Ψ(ξ).
    pub row: [f64; 4],
    /// The ballast length the section stands for (m).
    pub weight: f64,
    /// s (m).
    pub s: f64,
    /// Its place ξ ∈ [0, 1] in the element.
    pub xi: f64,
}

impl FrictionSection {
    /// H_i W (m).
    pub fn deflection(&self, w: &[f64]) -> f64 {
        row_dot(self.element, &self.row, w)
    }

    /// W′ at the section (rad), from the element's derivative row.
    pub fn slope(&self, w: &[f64], element: &Element) -> f64 {
        row_dot(self.element, &element.shape_dx(self.xi), w)
    }
}

/// What each section does in the wave.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SectionState {
    /// The rail slides over the ballast there: r = sign·f_u, sign that of the velocity −vW′.
    Slipping {
        /// ±1.
        sign: f64,
    },
    /// The rail is held: r = r_a + κ (W_i − W_a) after the slipping section `anchor` ahead, or κ (W_i − W_far) if
    /// none has slipped ahead of it.
    Stuck {
        /// The last slipping section ahead.
        anchor: Option<usize>,
    },
}

/// The friction forces along the wave and each section's state.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionState {
    /// r_i (N/m, upward positive: the resistance on the left-hand side, so the rail feels −r_i).
    pub force: Vec<f64>,
    /// Slipping or stuck.
    pub states: Vec<SectionState>,
}

/// The ballast's sections on a domain, front last (ascending s).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionSections {
    /// The sections.
    pub sections: Vec<FrictionSection>,
    /// f_u (N/m).
    pub capacity: f64,
    /// κ (N/m²).
    pub stiffness: f64,
    /// W_far: where the rail rests beyond the front (m).
    pub rest: f64,
}

/// One stick segment's coupling to its anchor: the Newton matrix carries −u·H_aᵀ, u = κ Σ_i weight_i H_iᵀ over the
/// segment's sections.
#[derive(Debug, Clone, PartialEq)]
pub struct AnchorCoupling {
    /// u (length of the DOF vector).
    pub column: Vec<f64>,
    /// The anchor section a.
    pub anchor: usize,
}

impl FrictionSections {
    /// The sections of `elements` elements like `element`, the first starting `behind` elements behind the load.
    pub fn new(
        friction: &DistributedFriction,
        elements: usize,
        behind: usize,
        element: &Element,
        stiffness: f64,
        rest: f64,
    ) -> Self {
        let l = element.length();
        let places = section_places(elements, l, friction.subdivisions, friction.quadrature);
        let sections = places
            .into_iter()
            .map(|p| FrictionSection {
                element: p.element,
                row: element.shape(p.xi),
                weight: p.weight,
                s: p.x - behind as f64 * l,
                xi: p.xi,
            })
            .collect();
        Self { sections, capacity: friction.force_per_length, stiffness, rest }
    }

    /// The play operator's march from the front (see the module doc).
    pub fn march(&self, w: &[f64]) -> FrictionState {
        self.march_by(w, |_, trial| (trial.abs() > self.capacity).then(|| trial.signum()))
    }

    /// The march with each section's state chosen by `slips(i, trial force)`: Some(sign) where section i slips,
    /// None where it sticks. [`Self::march`] chooses by the law; a path through the law's pieces
    /// ([`crate::path_search`]) by the states it holds.
    pub fn march_by(&self, w: &[f64], slips: impl Fn(usize, f64) -> Option<f64>) -> FrictionState {
        let n = self.sections.len();
        let mut force = vec![0.0; n];
        let mut states = vec![SectionState::Stuck { anchor: None }; n];
        let (mut r, mut previous, mut anchor) = (0.0, self.rest, None);
        for i in (0..n).rev() {
            let here = self.sections[i].deflection(w);
            let trial = r + self.stiffness * (here - previous);
            (r, states[i]) = match slips(i, trial) {
                Some(sign) => {
                    anchor = Some(i);
                    (sign * self.capacity, SectionState::Slipping { sign })
                }
                None => (trial, SectionState::Stuck { anchor }),
            };
            force[i] = r;
            previous = here;
        }
        FrictionState { force, states }
    }

    /// Σ_i weight_i H_iᵀ r_i added to `out` (N): the friction forces' share of A W + … − f.
    pub fn add_forces(&self, force: &[f64], out: &mut [f64]) {
        for (section, r) in self.sections.iter().zip(force) {
            row_add(section.element, &section.row, section.weight * r, out);
        }
    }

    /// The affine friction of `state` in the Newton system: each stuck section's κ weight_i H_iᵀH_i added to
    /// `matrix`, the forces that do not depend on W moved to `rhs`, and each stick segment's coupling to its anchor
    /// returned (the matrix of the system is `matrix` − Σ u H_aᵀ).
    pub fn linearise(&self, state: &FrictionState, matrix: &mut GeneralBanded, rhs: &mut [f64]) -> Vec<AnchorCoupling> {
        let mut couplings: Vec<AnchorCoupling> = Vec::new();
        for (i, section) in self.sections.iter().enumerate() {
            let (row, weight) = (section.row, section.weight);
            if let SectionState::Stuck { anchor } = state.states[i] {
                let spring = self.stiffness * weight;
                add_spring(matrix, section.element, &row, spring);
                if let Some(a) = anchor {
                    let coupling = match couplings.last_mut().filter(|c| c.anchor == a) {
                        Some(c) => c,
                        None => {
                            couplings.push(AnchorCoupling { column: vec![0.0; rhs.len()], anchor: a });
                            couplings.last_mut().expect("just pushed")
                        }
                    };
                    row_add(section.element, &row, spring, &mut coupling.column);
                }
            }
            row_add(section.element, &row, -weight * self.constant_force(state, i), rhs);
        }
        couplings
    }

    /// The part of section i's force r_i (N/m) that does not depend on W in `state`: ±f_u where it slips, the
    /// anchor's force less κW_far where it sticks ([`SectionState::Stuck`]).
    pub fn constant_force(&self, state: &FrictionState, i: usize) -> f64 {
        match state.states[i] {
            SectionState::Slipping { sign } => sign * self.capacity,
            SectionState::Stuck { anchor: None } => -self.stiffness * self.rest,
            SectionState::Stuck { anchor: Some(a) } => state.force[a],
        }
    }

    /// The part of each section's force r_i (N/m) that is linear in W in `state`: κ (W_i − W_a) where it sticks
    /// behind the slipping section a (κ W_i before any), 0 where it slips; with [`Self::constant_force`] the affine
    /// force of `state`, and its derivative with respect to W.
    pub fn stuck_forces(&self, state: &FrictionState, w: &[f64]) -> Vec<f64> {
        let deflections: Vec<f64> = self.sections.iter().map(|s| s.deflection(w)).collect();
        (0..self.sections.len())
            .map(|i| match state.states[i] {
                SectionState::Slipping { .. } => 0.0,
                SectionState::Stuck { anchor: None } => self.stiffness * deflections[i],
                SectionState::Stuck { anchor: Some(a) } => self.stiffness * (deflections[i] - deflections[a]),
            })
            .collect()
    }

    /// f_u v Σ_slipping weight_i |W′_i| (W): the power the slipping ballast dissipates at speed `speed`.
    pub fn dissipation(&self, state: &FrictionState, w: &[f64], element: &Element, speed: f64) -> f64 {
        self.sections
            .iter()
            .zip(&state.states)
            .filter(|(_, s)| matches!(s, SectionState::Slipping { .. }))
            .map(|(section, _)| self.capacity * speed * section.weight * section.slope(w, element).abs())
            .sum()
    }
}
