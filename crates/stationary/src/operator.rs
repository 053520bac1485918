//! The moving-frame operator on a finite domain (docs/theory.md §14). With s = x − vt and w(x, t) = W(s) the beam
//! on its soil under a load moving at v becomes EI W'''' + ρAv² W″ − c_f v W′ + k_t W − p_soil(W) = f(s). Hermite
//! elements in the weak form
//!
//! ```text
//! ∫ (EI W″φ″ − ρAv² W′φ′ − c_f v W′φ + k_t Wφ) ds + [EI W‴φ − EI W″φ′ + ρAv² W′φ]_ends = ∫ f φ ds
//! ```
//!
//! A Timoshenko rail (docs/theory.md §16) takes its own element (W and the cross-section's rotation Ψ: the same
//! DOFs (W, θ = Ψ) per node) and its stiffness in place of EI∫W″φ″, and its rotary inertia adds the convective
//! −ρIv²∫Ψ′χ′ (χ the rotation's test function):
//!
//! ```text
//! ∫ (κGA(W′ − Ψ)(φ′ − χ) + EI Ψ′χ′ − ρAv² W′φ′ − ρIv² Ψ′χ′ − c_f v W′φ + k_t Wφ) ds
//!     + [(ρAv² W′ − Q)φ + (ρIv² − EI)Ψ′χ]_ends = ∫ f φ ds,
//! ```
//!
//! Euler–Bernoulli's form at κGA → ∞, ρI = 0. Either gives a banded non-symmetric matrix A (the convective term
//! −c_f v∫φW′ is skew), closed at both ends by the
//! transparent relations of [`crate::far_field`] substituted into the boundary terms (a nonlinear soil without
//! self-weight has free ends instead: its far field rests on the soil without force, or lifts straight off it; so
//! does a track with friction, which holds the rail still beyond the wave at both ends).
//! The soil's unilateral part (k_c − k_t)⟨−W⟩₊ acts at four Gauss sections per element, as in a run on the finite track, so that a soil that
//! never lifts off is the linear one to round-off. The load −F sits on the node at s = 0; a nonlinear soil with
//! self-weight carries −ρA·g everywhere.

use crate::error::{Result, StationaryError};
use crate::far_field::{EndRelation, FarField};
use crate::friction::{FrictionSections, JENKINS_RATIO};
use crate::problem::StationaryProblem;
use crate::rows::{add_spring, row_dot};
use banded::general::{GeneralBanded, GeneralLu};
use fem_beam::GRAVITY;
use fem_beam::element::{Element, ElementMatrix, hermite};
use fem_beam::element_loop::{add_elements, consecutive_dofs};

/// One soil section: its element, its row Ψ(ξ) over the element's four DOFs, its spring (N/m) and place s (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoilSection {
    /// The element; its DOFs are 2e … 2e + 3.
    pub element: usize,
    /// Ψ(ξ_g).
    pub row: [f64; 4],
    /// k_s = (k_c − k_t)·weight (N/m).
    pub stiffness: f64,
    /// s (m).
    pub s: f64,
}

impl SoilSection {
    /// H_s W: the deflection at the section (m).
    pub fn deflection(&self, w: &[f64]) -> f64 {
        row_dot(self.element, &self.row, w)
    }
}

/// The assembled moving-frame problem at one speed.
#[derive(Debug, Clone)]
pub struct MovingFrame {
    /// A: the linear part with the transparent ends.
    pub matrix: GeneralBanded,
    /// The right-hand side: the load, the self-weight and the far field's level through the ends (N).
    pub rhs: Vec<f64>,
    /// The soil's unilateral sections (none on a linear soil).
    pub sections: Vec<SoilSection>,
    /// The ballast's friction sections, if it has friction.
    pub friction: Option<FrictionSections>,
    /// Node positions s_i (m); the load is on node `load_node`.
    pub nodes: Vec<f64>,
    /// The load's node.
    pub load_node: usize,
    /// Element length (m).
    pub element_length: f64,
    /// The rail's element at that length (Hermite, or Timoshenko's).
    pub element: Element,
    /// The far field's relations at transparent ends; None where the ends are free.
    pub far_field: Option<FarField>,
}

/// Half-bandwidth of the Hermite operator in (W₀, W′₀, W₁, W′₁, …).
const BAND: usize = 3;

impl MovingFrame {
    /// Assemble `problem` (validated).
    pub fn new(problem: &StationaryProblem) -> Result<Self> {
        problem.validate()?;
        let (beam, foundation, v) = (&problem.beam, &problem.foundation, problem.speed);
        let (ei, rho_a, c) = (beam.bending_stiffness(), beam.mass_per_length(), foundation.damping);
        // Free ends need no far field (and exist where none decays: friction undamped above v_cr).
        let far_field = match problem.has_free_ends() {
            true => None,
            false => Some(FarField::new(beam, c, foundation.stiffness, v)?),
        };
        let (behind, ahead, l) = problem.domain.elements();
        let elements = behind + ahead;
        let n = 2 * (elements + 1);
        let k_t = foundation.tension_stiffness();
        let element = Element::of(beam, l);
        let convective = Convective { rho_a: rho_a * v * v, rho_i: beam.rotary_inertia() * v * v, damping: c * v };
        let matrix_e = element_matrix(&element, ei, convective, k_t);
        let mut matrix = GeneralBanded::zeros(n, BAND, BAND);
        add_elements(&mut matrix, elements, consecutive_dofs, |_| matrix_e);
        let mut rhs = vec![0.0; n];
        rhs[2 * behind] -= problem.load;
        let level = problem.far_level();
        if level != 0.0 {
            // Consistent loads of a uniform load: the Timoshenko element's over a whole element are Hermite's.
            let weight = hermite::uniform_load(-rho_a * GRAVITY, l);
            for e in 0..elements {
                (0..4).for_each(|k| rhs[2 * e + k] += weight[k]);
            }
        }
        let rho_v2 = rho_a * v * v;
        // A free end carries no moment and no shear (W″ = W‴ = 0; for Timoshenko Ψ′ = 0 and W′ = Ψ), only the
        // convective term ρAv² W′ on the rotation DOF.
        match &far_field {
            None => {
                matrix.add(n - 2, n - 1, rho_v2);
                matrix.add(0, 1, -rho_v2);
            }
            Some(far) => {
                close_end(&mut matrix, &mut rhs, n - 2, &far.ahead, level, 1.0);
                close_end(&mut matrix, &mut rhs, 0, &far.behind, level, -1.0);
            }
        }
        let unilateral = foundation.unilateral_stiffness();
        let sections = match problem.is_nonlinear() {
            true => (0..elements)
                .flat_map(|e| {
                    hermite::GAUSS_4.iter().map(move |&(xi, w)| SoilSection {
                        element: e,
                        row: element.shape(xi),
                        stiffness: unilateral * w * l,
                        s: (e as f64 + xi - behind as f64) * l,
                    })
                })
                .collect(),
            false => Vec::new(),
        };
        let nodes = (0..=elements).map(|i| (i as f64 - behind as f64) * l).collect();
        let friction = problem.has_friction().then(|| {
            let stiffness = JENKINS_RATIO * foundation.stiffness;
            FrictionSections::new(&problem.friction, elements, behind, &element, stiffness, level)
        });
        Ok(Self { matrix, rhs, sections, friction, nodes, load_node: behind, element_length: l, element, far_field })
    }

    /// A + Σ_pressed k_s H_sᵀH_s, to which friction's stuck springs may be added before it is factored.
    pub fn with_pressed(&self, pressed: &[bool]) -> GeneralBanded {
        let mut jacobian = self.matrix.clone();
        for (section, _) in self.sections.iter().zip(pressed).filter(|(_, p)| **p) {
            add_spring(&mut jacobian, section.element, &section.row, section.stiffness);
        }
        jacobian
    }
}

/// `matrix` factored; `speed` names it when singular.
pub fn factor(matrix: GeneralBanded, speed: f64) -> Result<GeneralLu> {
    matrix.factor().map_err(|e| match e {
        banded::BandedError::Singular { index } => StationaryError::Singular { speed, equation: index },
        other => unreachable!("an LU reports only singularity: {other}"),
    })
}

/// The convective coefficients at speed v: ρAv² (N), ρIv² (N·m²), c_f v (N/m²).
#[derive(Debug, Clone, Copy)]
struct Convective {
    rho_a: f64,
    rho_i: f64,
    damping: f64,
}

/// K(EI) − ρAv²·Kg − ρIv²·Kr − c_f v·D + k_t·Mf of one element, with Kg = ∫N_w′ᵀN_w′, Kr = ∫N_ψ′ᵀN_ψ′ (Timoshenko
/// only) and D_ij = ∫N_wi N_wj′ by four-point Gauss (exact: degrees 4, 2 and 5).
fn element_matrix(element: &Element, ei: f64, v: Convective, k_t: f64) -> ElementMatrix {
    let kb = element.stiffness(ei);
    let mf = element.distributed(k_t);
    let mut a = [[0.0; 4]; 4];
    for (i, row) in a.iter_mut().enumerate() {
        for (j, value) in row.iter_mut().enumerate() {
            *value = kb[i][j] + mf[i][j];
        }
    }
    let l = element.length();
    for &(xi, w) in &hermite::GAUSS_4 {
        let (n, dn) = (element.shape(xi), element.shape_dx(xi));
        for i in 0..4 {
            for j in 0..4 {
                a[i][j] -= w * l * (v.rho_a * dn[i] * dn[j] + v.damping * n[i] * dn[j]);
            }
        }
        if let Element::Timoshenko { .. } = element {
            let dpsi = element.curvature(xi);
            for i in 0..4 {
                for j in 0..4 {
                    a[i][j] -= w * l * v.rho_i * dpsi[i] * dpsi[j];
                }
            }
        }
    }
    a
}

/// The boundary terms ±[(ρAv² W′ − Q)φ + (ρIv² − EI)Ψ′χ] at the end whose W DOF is `w` (θ = w + 1), from the
/// end's transparent relation T·(W − W_far, θ) ([`EndRelation::traction`]); `sign` +1 at the front end, −1 at the rear.
fn close_end(matrix: &mut GeneralBanded, rhs: &mut [f64], w: usize, end: &EndRelation, level: f64, sign: f64) {
    let t = end.traction;
    for (row, dof) in [(0, w), (1, w + 1)] {
        matrix.add(dof, w, sign * t[row][0]);
        matrix.add(dof, w + 1, sign * t[row][1]);
        rhs[dof] += sign * t[row][0] * level;
    }
}
