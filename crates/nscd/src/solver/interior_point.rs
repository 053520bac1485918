//! A primal–dual interior-point method for the friction step whose Newton systems are banded: the solver built for
//! dense distributed friction (MODEL.md §5), where Gauss–Seidel stalls because W = H M̂⁻¹ Hᵀ is singular.
//!
//! The step is the box QP min ½pᵀWp + u_freeᵀp, −a ≤ p ≤ a. With slacks s₁ = a − p, s₂ = a + p and multipliers
//! z₁, z₂ ≥ 0 (velocities, m/s) the optimality conditions are
//!
//! ```text
//! W p + u_free + z₁ − z₂ = 0,   s₁∘z₁ = 0,   s₂∘z₂ = 0,   s, z ≥ 0
//! ```
//!
//! so u = W p + u_free = z₂ − z₁: a section at p_j = a_j moves backwards, one at −a_j forwards, one inside is stuck.
//! Mehrotra predictor–corrector steps keep p strictly inside the box (the slacks s₁, s₂ are carried as variables: near a bound, a − p would lose all precision). Each Newton system
//! (W + Σ)Δp = r, Σ = z₁/s₁ + z₂/s₂ > 0, is solved without ever forming W, by the Woodbury identity
//!
//! ```text
//! B = M̂ + Hᵀ Σ⁻¹ H  (banded, half-bandwidth 3: each row H_j touches one element),
//! y = B⁻¹ Hᵀ Σ⁻¹ r,   Δp = Σ⁻¹ (r − H y),   M̂⁻¹ Hᵀ Δp = y,
//! ```
//!
//! so one banded factorisation and two banded solves per iteration, O(n + m). The velocity correction
//! M̂⁻¹Hᵀp is carried along, so W p is never needed either. Redundant stuck sections (more sections than DOFs)
//! only make Σ⁻¹ large on them, which B absorbs. Iterates stop when the law residual meets the tolerance.

use super::{FrictionProblem, FrictionSolver, StepReport};
use fem_beam::{BandedLdlt, SymmetricBanded};

/// Iterations allowed per step before it is declared unconverged (typically 10–25 are needed).
const FRACTION_TO_BOUNDARY: f64 = 0.995;

/// Banded primal–dual interior-point solver; scratch allocated once per run.
#[derive(Debug)]
pub struct BandedInteriorPoint {
    tolerance: f64,
    max_iterations: usize,
    s1: Vec<f64>,
    s2: Vec<f64>,
    z1: Vec<f64>,
    z2: Vec<f64>,
    sigma: Vec<f64>,
    r: Vec<f64>,
    dp: Vec<f64>,
    dz1: Vec<f64>,
    dz2: Vec<f64>,
    dp_aff: Vec<f64>,
    dz1_aff: Vec<f64>,
    dz2_aff: Vec<f64>,
    u: Vec<f64>,
    y: Vec<f64>,
    dy: Vec<f64>,
    v: Vec<f64>,
    rhs: Vec<f64>,
    b: SymmetricBanded,
    b_factor: BandedLdlt,
}

impl BandedInteriorPoint {
    /// Scratch for `problem`.
    pub fn new(problem: &FrictionProblem<'_>, tolerance: f64, max_iterations: usize) -> Self {
        let (n, m) = (problem.m_hat.order(), problem.len());
        let zeros_m = || vec![0.0; m];
        Self {
            tolerance,
            max_iterations,
            s1: zeros_m(),
            s2: zeros_m(),
            z1: zeros_m(),
            z2: zeros_m(),
            sigma: zeros_m(),
            r: zeros_m(),
            dp: zeros_m(),
            dz1: zeros_m(),
            dz2: zeros_m(),
            dp_aff: zeros_m(),
            dz1_aff: zeros_m(),
            dz2_aff: zeros_m(),
            u: zeros_m(),
            y: vec![0.0; n],
            dy: vec![0.0; n],
            v: vec![0.0; n],
            rhs: vec![0.0; n],
            b: problem.m_hat.clone(),
            b_factor: problem.factor.clone(),
        }
    }

    /// u = H(v_free + y).
    fn refresh_velocities(&mut self, problem: &FrictionProblem<'_>, v_free: &[f64]) {
        for ((v, vf), y) in self.v.iter_mut().zip(v_free).zip(&self.y) {
            *v = vf + y;
        }
        problem.contacts.velocities(&self.v, &mut self.u);
    }

    /// Solve (W + Σ)Δp = r for the current Σ (B already factored): Δp into `dp`, M̂⁻¹HᵀΔp into `dy`.
    fn solve_newton(&mut self, problem: &FrictionProblem<'_>, dp_out: Dp) {
        self.rhs.iter_mut().for_each(|x| *x = 0.0);
        for (j, row) in problem.contacts.rows().iter().enumerate() {
            row.add_transpose(self.r[j] / self.sigma[j], &mut self.rhs);
        }
        self.b_factor.solve_in_place(&mut self.rhs);
        let dp = match dp_out {
            Dp::Affine => &mut self.dp_aff,
            Dp::Combined => &mut self.dp,
        };
        for (j, row) in problem.contacts.rows().iter().enumerate() {
            dp[j] = (self.r[j] - row.dot(&self.rhs)) / self.sigma[j];
        }
        self.dy.copy_from_slice(&self.rhs);
    }

    /// Largest α ≤ 1 keeping s₁ − αΔp, s₂ + αΔp, z₁ + αΔz₁, z₂ + αΔz₂ positive.
    fn max_step(&self, dp: &[f64], dz1: &[f64], dz2: &[f64]) -> f64 {
        let mut alpha: f64 = 1.0;
        for j in 0..dp.len() {
            for (x, dx) in [(self.s1[j], -dp[j]), (self.s2[j], dp[j]), (self.z1[j], dz1[j]), (self.z2[j], dz2[j])] {
                if dx < 0.0 {
                    alpha = alpha.min(-x / dx);
                }
            }
        }
        alpha
    }
}

#[derive(Clone, Copy)]
enum Dp {
    Affine,
    Combined,
}

impl FrictionSolver for BandedInteriorPoint {
    fn name(&self) -> &'static str {
        "interior-point"
    }

    fn solve(
        &mut self,
        problem: &FrictionProblem<'_>,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        let m = p.len();
        let a = &problem.bounds;
        // Start strictly inside the box, near the previous step's impulses.
        for j in 0..m {
            p[j] = if a[j] > 0.0 { 0.9 * p[j].clamp(-a[j], a[j]) } else { 0.0 };
        }
        self.y.iter_mut().for_each(|y| *y = 0.0);
        problem.contacts.add_transpose(p, &mut self.y);
        problem.factor.solve_in_place(&mut self.y);
        self.refresh_velocities(problem, v_free);
        let scale = u_free.iter().fold(super::VELOCITY_FLOOR, |s, u| s.max(u.abs()));
        for j in 0..m {
            self.s1[j] = a[j] - p[j];
            self.s2[j] = a[j] + p[j];
            // Split u into z₂ − z₁, both kept away from zero.
            let shift = 0.1 * scale;
            self.z1[j] = (-self.u[j]).max(0.0) + shift;
            self.z2[j] = self.u[j].max(0.0) + shift;
        }
        let active: usize = a.iter().filter(|&&x| x > 0.0).count();
        let mut residual = problem.law_residual(&self.u, p);
        let mut iterations = 0;
        while residual > tolerance && iterations < self.max_iterations && active > 0 {
            iterations += 1;
            let mu =
                (0..m).filter(|&j| a[j] > 0.0).map(|j| self.s1[j] * self.z1[j] + self.s2[j] * self.z2[j]).sum::<f64>()
                    / (2 * active) as f64;
            // B = M̂ + HᵀΣ⁻¹H; sections with a_j = 0 are fixed at p_j = 0 (Σ⁻¹ = 0).
            self.b.copy_from(problem.m_hat);
            for (j, row) in problem.contacts.rows().iter().enumerate() {
                if a[j] > 0.0 {
                    // Σ_j = z₁/s₁ + z₂/s₂, floored so that Σ⁻¹ stays finite for sections that are stuck
                    // to round-off (z → 0): beyond ~1e15 relative the extra stiffness changes nothing.
                    let (s1, s2, z1, z2) = (self.s1[j], self.s2[j], self.z1[j], self.z2[j]);
                    self.sigma[j] = (z1 / s1 + z2 / s2).max(1e-15 * problem.delassus_diagonal[j]);
                    let w = 1.0 / self.sigma[j];
                    for (i, vi) in row.entries() {
                        for (k, vk) in row.entries() {
                            if k <= i {
                                self.b.add(i, k, w * vi * vk);
                            }
                        }
                    }
                } else {
                    self.sigma[j] = f64::INFINITY;
                }
            }
            self.b.factor_into(&mut self.b_factor)?;
            // Predictor (affine scaling): r = −(u + z₁ − z₂) + z₁ − z₂ = −u.
            for j in 0..m {
                self.r[j] = if a[j] > 0.0 { -self.u[j] } else { 0.0 };
            }
            self.solve_newton(problem, Dp::Affine);
            for j in 0..m {
                if a[j] > 0.0 {
                    self.dz1_aff[j] = (-self.s1[j] * self.z1[j] + self.z1[j] * self.dp_aff[j]) / self.s1[j];
                    self.dz2_aff[j] = (-self.s2[j] * self.z2[j] - self.z2[j] * self.dp_aff[j]) / self.s2[j];
                } else {
                    (self.dp_aff[j], self.dz1_aff[j], self.dz2_aff[j]) = (0.0, 0.0, 0.0);
                }
            }
            let alpha_aff = self.max_step(&self.dp_aff, &self.dz1_aff, &self.dz2_aff);
            let mu_aff = (0..m)
                .filter(|&j| a[j] > 0.0)
                .map(|j| {
                    (self.s1[j] - alpha_aff * self.dp_aff[j]) * (self.z1[j] + alpha_aff * self.dz1_aff[j])
                        + (self.s2[j] + alpha_aff * self.dp_aff[j]) * (self.z2[j] + alpha_aff * self.dz2_aff[j])
                })
                .sum::<f64>()
                / (2 * active) as f64;
            let centring = (mu_aff / mu).powi(3).min(1.0);
            // Corrector: complementarity targets σμ − Δs_aff∘Δz_aff (Δs₁ = −Δp, Δs₂ = Δp).
            for j in 0..m {
                if a[j] > 0.0 {
                    let c1 = centring * mu + self.dp_aff[j] * self.dz1_aff[j];
                    let c2 = centring * mu - self.dp_aff[j] * self.dz2_aff[j];
                    self.r[j] = -self.u[j] - c1 / self.s1[j] + c2 / self.s2[j];
                    self.dz1[j] = c1; // keep the targets for the multiplier update below
                    self.dz2[j] = c2;
                } else {
                    self.r[j] = 0.0;
                }
            }
            self.solve_newton(problem, Dp::Combined);
            for j in 0..m {
                if a[j] > 0.0 {
                    let (c1, c2) = (self.dz1[j], self.dz2[j]);
                    self.dz1[j] = (c1 - self.s1[j] * self.z1[j] + self.z1[j] * self.dp[j]) / self.s1[j];
                    self.dz2[j] = (c2 - self.s2[j] * self.z2[j] - self.z2[j] * self.dp[j]) / self.s2[j];
                } else {
                    (self.dp[j], self.dz1[j], self.dz2[j]) = (0.0, 0.0, 0.0);
                }
            }
            let alpha = (FRACTION_TO_BOUNDARY * self.max_step(&self.dp, &self.dz1, &self.dz2)).min(1.0);
            for j in 0..m {
                p[j] += alpha * self.dp[j];
                self.z1[j] += alpha * self.dz1[j];
                self.z2[j] += alpha * self.dz2[j];
                // Slacks are updated, not recomputed from p: near a bound a − p loses all precision.
                self.s1[j] -= alpha * self.dp[j];
                self.s2[j] += alpha * self.dp[j];
            }
            for (y, dy) in self.y.iter_mut().zip(&self.dy) {
                *y += alpha * dy;
            }
            self.refresh_velocities(problem, v_free);
            residual = problem.law_residual(&self.u, p);
        }
        Ok(StepReport { iterations, residual, tolerance, converged: residual <= tolerance })
    }
}
