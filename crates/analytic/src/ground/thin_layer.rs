//! The thin-layer method (Kausel 1981; Kausel 2006 ch. 6): the second, independent way to the Rayleigh modes of a
//! layered ground, by finite elements in depth instead of exact layer matrices (docs/theory.md §19). The ground is cut
//! into thin sublayers, displacements linear across each, down to a fixed base deep enough that the mode has died
//! out; with û = iu (so every matrix is real) a wave e^{i(ωt − kx)} obeys the symmetric eigenproblem
//!
//! ```text
//! (k²A + kB + G) φ = ω² M φ,     per sublayer of thickness h with Q = h/6·[[2, 1], [1, 2]], D = [[1, −1], [−1, 1]]/h,
//! A = diag(M_p Q, μ Q),  G = diag(μ D, M_p D),  B_ûw = −λP + μPᵀ (P = [[−½, ½], [−½, ½]], P_ab = ∫N_a N_b′),
//! M = ρ·diag(Q, Q),
//! ```
//!
//! from the strain energy M_p k²û² − 2λk û w′ + M_p w′² + μ(û′ + kw)² and the kinetic energy ρω²(û² + w²)
//! (M_p = λ + 2μ). At a wavenumber k the fundamental mode is the least ω², found by inverse iteration with the banded
//! LDLᵀ of the positive definite k²A + kB + G. Linear elements err by O((kh)²): Richardson's extrapolation from h
//! and h/2 removes the leading term.

use super::profile::{GroundProfile, SoilMaterial};
use banded::SymmetricBanded;
use fem_beam::FemError;
use fem_beam::error::Result;

/// The most inverse-iteration steps: the fundamental's ω² is separated from the next (a mode or a box mode of the
/// truncated half-space) by a ratio of at least ~(c/C_s,half-space)²; a few hundred steps reach round-off unless the
/// mode is barely trapped.
const MAX_ITERATIONS: usize = 5000;

/// The thin-layer discretisation of a profile: sublayers of at most `sublayer` (m), the half-space continued down to
/// `depth` (m) below the surface, where the base is fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThinLayerMesh {
    /// The largest sublayer thickness (m).
    pub sublayer: f64,
    /// The depth of the fixed base (m), below the last layer.
    pub depth: f64,
}

/// The fundamental mode's phase velocity ω/k (m/s) at wavenumber `k` (rad/m, > 0) of the undamped `profile`, by the
/// thin-layer method on `mesh` and on the mesh with sublayers halved, extrapolated (Richardson, O(h⁴)).
pub fn thin_layer_phase_velocity(profile: &GroundProfile, k: f64, mesh: ThinLayerMesh) -> Result<f64> {
    let coarse = fundamental_omega_squared(profile, k, mesh)?;
    let fine = fundamental_omega_squared(profile, k, ThinLayerMesh { sublayer: 0.5 * mesh.sublayer, ..mesh })?;
    Ok(((4.0 * fine - coarse) / 3.0).sqrt() / k)
}

/// The least ω² (rad²/s²) of the thin-layer eigenproblem at wavenumber `k` on `mesh`.
fn fundamental_omega_squared(profile: &GroundProfile, k: f64, mesh: ThinLayerMesh) -> Result<f64> {
    let sublayers = sublayers(profile, mesh);
    let dofs = 2 * sublayers.len(); // the base's node is fixed
    let (mut stiffness, mut mass) = (SymmetricBanded::zeros(dofs, 3), SymmetricBanded::zeros(dofs, 3));
    for (i, &(material, h)) in sublayers.iter().enumerate() {
        let (element_stiffness, element_mass) = element(&material, h, k);
        for a in 0..4 {
            for b in 0..=a {
                let (row, column) = (2 * i + a, 2 * i + b);
                if row < dofs {
                    stiffness.add(row, column, element_stiffness[a][b]);
                    mass.add(row, column, element_mass[a][b]);
                }
            }
        }
    }
    let factor = stiffness.factor()?;
    let mut x = vec![1.0; dofs];
    let (mut omega2, mut mx) = (f64::NAN, vec![0.0; dofs]);
    for _ in 0..MAX_ITERATIONS {
        mass.mul_vec(&x, &mut mx);
        let norm = dot(&x, &mx).sqrt();
        let quotient = stiffness.quadratic_form(&x) / (norm * norm);
        if (quotient - omega2).abs() <= 1e-12 * quotient {
            return Ok(quotient);
        }
        omega2 = quotient;
        x = mx.iter().map(|v| v / norm).collect();
        factor.solve_in_place(&mut x);
    }
    Err(FemError::NotConverged {
        what: format!("the thin-layer fundamental mode at k = {k} rad/m"),
        reached: f64::NAN,
        asked: 1e-12,
    })
}

/// The sublayers (material, thickness) from the surface to `mesh.depth`.
fn sublayers(profile: &GroundProfile, mesh: ThinLayerMesh) -> Vec<(SoilMaterial, f64)> {
    let layers_depth: f64 = profile.layers.iter().map(|layer| layer.thickness).sum();
    let below = (mesh.depth - layers_depth).max(0.0);
    let pieces = profile
        .layers
        .iter()
        .map(|layer| (layer.material, layer.thickness))
        .chain(std::iter::once((profile.half_space, below)))
        .filter(|&(_, thickness)| thickness > 0.0);
    pieces
        .flat_map(|(material, thickness)| {
            let n = (thickness / mesh.sublayer).ceil().max(1.0) as usize;
            std::iter::repeat_n((material, thickness / n as f64), n)
        })
        .collect()
}

/// The 4 × 4 stiffness k²A + kB + G and mass of a sublayer, DOFs (û₁, w₁, û₂, w₂) top then bottom.
fn element(material: &SoilMaterial, h: f64, k: f64) -> ([[f64; 4]; 4], [[f64; 4]; 4]) {
    let (mu, modulus) = (material.shear_modulus(0.0).re, material.p_wave_modulus(0.0).re);
    let lambda = modulus - 2.0 * mu;
    let q = [[h / 3.0, h / 6.0], [h / 6.0, h / 3.0]];
    let d = [[1.0 / h, -1.0 / h], [-1.0 / h, 1.0 / h]];
    let p = [[-0.5, 0.5], [-0.5, 0.5]];
    let (mut stiffness, mut mass) = ([[0.0; 4]; 4], [[0.0; 4]; 4]);
    for a in 0..2 {
        for b in 0..2 {
            let (ua, wa, ub, wb) = (2 * a, 2 * a + 1, 2 * b, 2 * b + 1);
            stiffness[ua][ub] = k * k * modulus * q[a][b] + mu * d[a][b];
            stiffness[wa][wb] = k * k * mu * q[a][b] + modulus * d[a][b];
            stiffness[ua][wb] = k * (-lambda * p[a][b] + mu * p[b][a]);
            stiffness[wb][ua] = stiffness[ua][wb];
            mass[ua][ub] = material.density * q[a][b];
            mass[wa][wb] = material.density * q[a][b];
        }
    }
    (stiffness, mass)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
