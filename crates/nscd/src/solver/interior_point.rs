//! A primal–dual interior-point method for the friction step whose Newton systems are banded: the solver built for
//! dense distributed friction (docs/theory.md §5), where Gauss–Seidel stalls because W = H M̂⁻¹ Hᵀ is singular.
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
//! Sections with a zero bound are fixed at p = 0 and left out.
//!
//! # The moving window
//! Far from the load nothing changes from one step to the next: stuck sections keep their impulses, and the
//! coupling through M̂⁻¹ decays like e^{−x/(√2ℓ)} with the coupling length ℓ = (EI h²θ²/ρA)^¼. So each step first
//! tries the previous impulses; the sections where they violate the law, widened by a margin of 30ℓ (coupling
//! below 1e-9), form the window. Only the window's impulses are re-solved, on the window's DOFs, with the rest of
//! the beam condensed exactly into the window matrix by Schur complements taken from the LDLᵀ factors of M̂ and of
//! M̂ reversed (S_W = M̂_WW − M̂_WO M̂_OO⁻¹ M̂_OW, whose inverse is the W block of M̂⁻¹). The law residual is then
//! checked on *every* section; should a section outside the window fail, the window is widened (2×, 4×) and at
//! last the whole problem is solved instead.
//! The answer is therefore exact to the same tolerance; only the cost depends on the window.

use super::{FrictionProblem, FrictionSolver, StepReport, StepStatus};
use banded::{BandedLdlt, BlockRows, SymmetricBanded};

/// Fraction of the distance to the boundary of the positive orthant taken by a step.
const FRACTION_TO_BOUNDARY: f64 = 0.995;

/// How the steps of a run were solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WindowStatistics {
    /// Steps where the previous impulses already satisfied the law.
    pub unchanged: usize,
    /// Steps solved on a window.
    pub windowed: usize,
    /// Steps solved on the whole beam.
    pub full: usize,
    /// Sections re-solved, summed over the steps.
    pub sections_solved: usize,
}

/// Interior-point state of the active sections, one array per quantity, k = 0..len in the order of `index`. The
/// per-section arithmetic runs as straight loops over contiguous arrays (which the compiler vectorises); B and the
/// right-hand side are accumulated section after section ([`BlockRows`]) and the sums μ in section order, so every
/// result is the same to the bit as section-by-section evaluation.
#[derive(Debug, Default)]
struct Sections {
    /// Section index j of each active section.
    index: Vec<usize>,
    /// The rows H_k over the window's DOFs (rows touch consecutive free DOFs).
    rows: BlockRows,
    /// Bound a_j (N·s), W_jj and 1/W_jj.
    a: Vec<f64>,
    w: Vec<f64>,
    inv_w: Vec<f64>,
    u_free: Vec<f64>,
    u: Vec<f64>,
    p: Vec<f64>,
    s1: Vec<f64>,
    s2: Vec<f64>,
    z1: Vec<f64>,
    z2: Vec<f64>,
    inv_s1: Vec<f64>,
    inv_s2: Vec<f64>,
    inv_z1: Vec<f64>,
    inv_z2: Vec<f64>,
    inv_sigma: Vec<f64>,
    r: Vec<f64>,
    c1: Vec<f64>,
    c2: Vec<f64>,
    dp: Vec<f64>,
    dz1: Vec<f64>,
    dz2: Vec<f64>,
    /// H_j·x gathered for each section, and per-section terms of the sums.
    gathered: Vec<f64>,
    /// r_k Σ_k⁻¹, the weights of the Newton right-hand side.
    weighted: Vec<f64>,
}

impl Sections {
    /// Arrays with room for `m` sections, so that no step allocates.
    fn with_capacity(m: usize) -> Self {
        let mut sections = Self { rows: BlockRows::with_capacity(m), ..Self::default() };
        sections.index.resize(m, 0);
        sections.fit();
        sections.index.clear();
        sections
    }

    /// Size every array to `index.len()` (no allocation once the capacity is there).
    fn fit(&mut self) {
        let len = self.index.len();
        for v in [
            &mut self.a,
            &mut self.w,
            &mut self.inv_w,
            &mut self.u_free,
            &mut self.u,
            &mut self.p,
            &mut self.s1,
            &mut self.s2,
            &mut self.z1,
            &mut self.z2,
            &mut self.inv_s1,
            &mut self.inv_s2,
            &mut self.inv_z1,
            &mut self.inv_z2,
            &mut self.inv_sigma,
            &mut self.r,
            &mut self.c1,
            &mut self.c2,
            &mut self.dp,
            &mut self.dz1,
            &mut self.dz2,
            &mut self.gathered,
            &mut self.weighted,
        ] {
            v.resize(len, 0.0);
        }
    }

    /// gathered_k = H_k·x (x padded with three zeros past its end).
    #[inline(always)]
    fn gather(&mut self, x: &[f64]) {
        self.rows.mul(x, &mut self.gathered);
    }

    /// The Newton right-hand side out = Σ_k H_kᵀ r_k Σ_k⁻¹, summed in section order (out padded with three zeros
    /// past its end).
    #[inline(always)]
    fn right_hand_side(&mut self, out: &mut [f64]) {
        let len = self.index.len();
        let (r, inv_sigma, weighted) = (&self.r[..len], &self.inv_sigma[..len], &mut self.weighted[..len]);
        for k in 0..len {
            weighted[k] = r[k] * inv_sigma[k];
        }
        self.rows.transpose_mul(weighted, out);
    }

    /// max_k of the law residual |p − proj(p − u/W)|·W (m/s).
    #[inline(always)]
    fn law_residual(&self) -> f64 {
        let mut residual: f64 = 0.0;
        for ((((&p, &u), &a), &w), &inv_w) in self.p.iter().zip(&self.u).zip(&self.a).zip(&self.w).zip(&self.inv_w) {
            residual = residual.max((p - (p - u * inv_w).clamp(-a, a)).abs() * w);
        }
        residual
    }
}

/// What one interior-point solve works on besides the sections: the step's problem, `base` = the matrix M̂ (or its
/// window condensation) over the DOFs from `offset` on, the absolute tolerance (m/s) and the iteration cap.
#[derive(Clone, Copy)]
struct Subproblem<'s, 'a> {
    problem: &'s FrictionProblem<'a>,
    base: &'s SymmetricBanded,
    offset: usize,
    tolerance: f64,
    max_iterations: usize,
}

/// Per-section and per-DOF scratch of the interior-point iteration.
#[derive(Debug)]
struct Work {
    sections: Sections,
    y: Vec<f64>,
    dy: Vec<f64>,
    b: SymmetricBanded,
    b_factor: BandedLdlt,
}

impl Work {
    /// From rhs = Σ H_jᵀ r_j Σ_j⁻¹ (in `dy`): dy ← B⁻¹ rhs, Δp_j = Σ_j⁻¹(r_j − H_j dy), Δz from the complementarity
    /// targets c (s₁Δz₁ = c₁ − s₁z₁ + z₁Δp, s₂Δz₂ = c₂ − s₂z₂ − z₂Δp); returns the largest feasible primal (p, s)
    /// and dual (z) steps ≤ 1. Taking them separately saves 11–13 % of the iterations (measured) and is safe here:
    /// convergence is judged on the law residual of (u, p), not on the dual residual.
    #[inline(always)]
    fn newton_direction(&mut self) -> (f64, f64) {
        let n = self.b_factor.order();
        self.b_factor.solve_in_place(&mut self.dy[..n]);
        let q = &mut self.sections;
        q.gather(&self.dy);
        let len = q.index.len();
        let (primal, dual) = direction_terms(
            [&q.r[..len], &q.gathered[..len], &q.inv_sigma[..len], &q.c1[..len], &q.c2[..len], &q.z1[..len]],
            [&q.z2[..len], &q.inv_s1[..len], &q.inv_s2[..len], &q.inv_z1[..len], &q.inv_z2[..len]],
            [&mut q.dp[..len], &mut q.dz1[..len], &mut q.dz2[..len]],
        );
        (1.0 / primal, 1.0 / dual)
    }

    /// Mehrotra predictor–corrector on the active sections (`sections.index`, with `u_free` set), from p = 0, on
    /// `subproblem`. Writes the impulses of the active sections into `p`. Returns (iterations, residual).
    ///
    /// Compiled twice: for AVX2 where the CPU has it (detected at run time; four sections per instruction in the
    /// per-section loops instead of two), and for the baseline. Both execute the same operations in the same order
    /// — no fused multiply–add, sums still in section order — so they give the same bits.
    fn iterate(&mut self, subproblem: &Subproblem<'_, '_>, p: &mut [f64]) -> crate::Result<(usize, f64)> {
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code)]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above); the body is plain safe Rust.
            return unsafe { self.iterate_avx2(subproblem, p) };
        }
        self.iterate_body(subproblem, p)
    }

    /// [`Work::iterate`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[allow(unsafe_code)]
    unsafe fn iterate_avx2(&mut self, subproblem: &Subproblem<'_, '_>, p: &mut [f64]) -> crate::Result<(usize, f64)> {
        self.iterate_body(subproblem, p)
    }

    /// The body of [`Work::iterate`], inlined into the baseline and the AVX2 build.
    #[inline(always)]
    fn iterate_body(&mut self, subproblem: &Subproblem<'_, '_>, p: &mut [f64]) -> crate::Result<(usize, f64)> {
        let Subproblem { problem, base, offset, tolerance, max_iterations } = *subproblem;
        let rows = problem.contacts.rows();
        let nw = base.order();
        // Three zeros of padding past the end let every row be read and written four entries wide.
        self.y.resize(nw + 3, 0.0);
        self.dy.resize(nw + 3, 0.0);
        self.y.iter_mut().for_each(|x| *x = 0.0);
        let q = &mut self.sections;
        let len = q.index.len();
        q.rows.clear();
        for k in 0..len {
            let j = q.index[k];
            let row = &rows[j];
            debug_assert!(row.dofs().windows(2).all(|d| d[1] == d[0] + 1), "rows touch consecutive free DOFs");
            q.rows.push(row.dofs()[0] - offset, row.values());
            q.a[k] = problem.bounds[j];
            q.w[k] = problem.delassus_diagonal[j];
            q.inv_w[k] = 1.0 / q.w[k];
        }
        // Start at p = 0, the centre of every box: warm starts from the previous step's (p, z) were measured to
        // cost more iterations, not fewer (18.6 cold vs 19.8–23.9 warm per step, distributed 5 kN/m).
        let scale = q.u_free.iter().fold(super::VELOCITY_FLOOR, |s, u| s.max(u.abs()));
        let shift = 0.01 * scale;
        for k in 0..len {
            q.p[k] = 0.0;
            q.u[k] = q.u_free[k];
            q.s1[k] = q.a[k];
            q.s2[k] = q.a[k];
            // Split u into z₂ − z₁, both kept away from zero.
            q.z1[k] = (-q.u[k]).max(0.0) + shift;
            q.z2[k] = q.u[k].max(0.0) + shift;
        }
        let mut residual = q.law_residual();
        let inv_count = 1.0 / (2 * len.max(1)) as f64;
        let mut iterations = 0;
        while residual > tolerance && iterations < max_iterations && len > 0 {
            iterations += 1;
            // B = base + HᵀΣ⁻¹H, Σ = z₁/s₁ + z₂/s₂, floored so that Σ⁻¹ stays finite for sections stuck to
            // round-off (z → 0): beyond ~1e15·W_jj the extra stiffness changes nothing. Predictor (affine
            // scaling, targets c = 0): r = −u, right-hand side Σ H_jᵀ r_j/Σ_j.
            let q = &mut self.sections;
            predictor_terms(
                [&q.s1[..len], &q.s2[..len], &q.z1[..len], &q.z2[..len], &q.w[..len], &q.u[..len]],
                [&mut q.inv_s1[..len], &mut q.inv_s2[..len], &mut q.inv_z1[..len], &mut q.inv_z2[..len]],
                [&mut q.inv_sigma[..len], &mut q.r[..len], &mut q.c1[..len], &mut q.c2[..len]],
            );
            let mut mu = 0.0;
            for (((s1, z1), s2), z2) in q.s1.iter().zip(&q.z1).zip(&q.s2).zip(&q.z2) {
                mu += s1 * z1 + s2 * z2;
            }
            mu *= inv_count;
            q.rows.weighted_gram_into(base, &q.inv_sigma, &mut self.b);
            q.right_hand_side(&mut self.dy);
            self.b.factor_into(&mut self.b_factor)?;
            let (alpha_p_aff, alpha_d_aff) = self.newton_direction();
            // Corrector: targets σμ − Δs_aff∘Δz_aff (Δs₁ = −Δp, Δs₂ = Δp), σ = (μ_aff/μ)³, r = −u − c₁/s₁ + c₂/s₂.
            let q = &mut self.sections;
            affine_terms(
                (alpha_p_aff, alpha_d_aff),
                [&q.s1[..len], &q.s2[..len], &q.z1[..len], &q.z2[..len]],
                [&q.dp[..len], &q.dz1[..len], &q.dz2[..len]],
                &mut q.gathered[..len],
            );
            let mut mu_affine = 0.0;
            for term in &q.gathered {
                mu_affine += term;
            }
            let target = (mu_affine * inv_count / mu).powi(3).min(1.0) * mu;
            corrector_terms(
                target,
                [&q.dp[..len], &q.dz1[..len], &q.dz2[..len], &q.u[..len], &q.inv_s1[..len], &q.inv_s2[..len]],
                [&mut q.c1[..len], &mut q.c2[..len], &mut q.r[..len]],
            );
            q.right_hand_side(&mut self.dy);
            let (alpha_p, alpha_d) = self.newton_direction();
            let (alpha, alpha_d) =
                ((FRACTION_TO_BOUNDARY * alpha_p).min(1.0), (FRACTION_TO_BOUNDARY * alpha_d).min(1.0));
            for (y, dy) in self.y.iter_mut().zip(&self.dy) {
                *y += alpha * dy;
            }
            let q = &mut self.sections;
            q.gather(&self.y);
            take_step(
                (alpha, alpha_d),
                [&q.dp[..len], &q.dz1[..len], &q.dz2[..len], &q.u_free[..len], &q.gathered[..len]],
                [
                    &mut q.p[..len],
                    &mut q.s1[..len],
                    &mut q.s2[..len],
                    &mut q.z1[..len],
                    &mut q.z2[..len],
                    &mut q.u[..len],
                ],
            );
            residual = q.law_residual();
        }
        for (&j, &pk) in self.sections.index.iter().zip(&self.sections.p) {
            p[j] = pk;
        }
        Ok((iterations, residual))
    }
}

// The per-section loops of the iteration, as functions of slices so that the compiler knows the arrays do not
// overlap (and, all of one length, needs no bounds checks): it then vectorises them.

/// Predictor set-up: 1/s₁, 1/s₂, 1/z₁, 1/z₂, Σ⁻¹ = 1/max(z₁/s₁ + z₂/s₂, 1e-15·W), r = −u, c₁ = c₂ = 0.
#[inline(always)]
fn predictor_terms(input: [&[f64]; 6], inverses: [&mut [f64]; 4], out: [&mut [f64]; 4]) {
    let [s1, s2, z1, z2, w, u] = input;
    let [inv_s1, inv_s2, inv_z1, inv_z2] = inverses;
    let [inv_sigma, r, c1, c2] = out;
    let len = s1.len();
    let (s2, z1, z2, w, u) = (&s2[..len], &z1[..len], &z2[..len], &w[..len], &u[..len]);
    let (inv_s1, inv_s2, inv_z1, inv_z2) =
        (&mut inv_s1[..len], &mut inv_s2[..len], &mut inv_z1[..len], &mut inv_z2[..len]);
    let (inv_sigma, r, c1, c2) = (&mut inv_sigma[..len], &mut r[..len], &mut c1[..len], &mut c2[..len]);
    for k in 0..len {
        inv_s1[k] = 1.0 / s1[k];
        inv_s2[k] = 1.0 / s2[k];
        inv_z1[k] = 1.0 / z1[k];
        inv_z2[k] = 1.0 / z2[k];
        inv_sigma[k] = 1.0 / (z1[k] * inv_s1[k] + z2[k] * inv_s2[k]).max(1e-15 * w[k]);
        r[k] = -u[k];
        c1[k] = 0.0;
        c2[k] = 0.0;
    }
}

/// Newton direction per section: Δp = (r − H dy)Σ⁻¹, Δz₁ = (c₁ + z₁Δp)/s₁ − z₁, Δz₂ = (c₂ − z₂Δp)/s₂ − z₂; returns
/// the largest ratios −Δx/x over the primal (s) and dual (z) variables, at least 1.
#[inline(always)]
fn direction_terms(first: [&[f64]; 6], second: [&[f64]; 5], out: [&mut [f64]; 3]) -> (f64, f64) {
    let [r, g, inv_sigma, c1, c2, z1] = first;
    let [z2, inv_s1, inv_s2, inv_z1, inv_z2] = second;
    let [dp_out, dz1_out, dz2_out] = out;
    let len = r.len();
    let (g, inv_sigma, c1, c2, z1) = (&g[..len], &inv_sigma[..len], &c1[..len], &c2[..len], &z1[..len]);
    let (z2, inv_s1, inv_s2, inv_z1, inv_z2) =
        (&z2[..len], &inv_s1[..len], &inv_s2[..len], &inv_z1[..len], &inv_z2[..len]);
    let (dp_out, dz1_out, dz2_out) = (&mut dp_out[..len], &mut dz1_out[..len], &mut dz2_out[..len]);
    let (mut primal, mut dual): (f64, f64) = (1.0, 1.0);
    for k in 0..len {
        let dp = (r[k] - g[k]) * inv_sigma[k];
        let dz1 = (c1[k] + z1[k] * dp) * inv_s1[k] - z1[k];
        let dz2 = (c2[k] - z2[k] * dp) * inv_s2[k] - z2[k];
        dp_out[k] = dp;
        dz1_out[k] = dz1;
        dz2_out[k] = dz2;
        primal = primal.max(dp * inv_s1[k]).max(-dp * inv_s2[k]);
        dual = dual.max(-dz1 * inv_z1[k]).max(-dz2 * inv_z2[k]);
    }
    (primal, dual)
}

/// Terms of μ_aff: (s₁ − α_pΔp)(z₁ + α_dΔz₁) + (s₂ + α_pΔp)(z₂ + α_dΔz₂).
#[inline(always)]
fn affine_terms((alpha_p, alpha_d): (f64, f64), state: [&[f64]; 4], direction: [&[f64]; 3], out: &mut [f64]) {
    let [s1, s2, z1, z2] = state;
    let [dp, dz1, dz2] = direction;
    let len = out.len();
    let (s1, s2, z1, z2, dp, dz1, dz2) =
        (&s1[..len], &s2[..len], &z1[..len], &z2[..len], &dp[..len], &dz1[..len], &dz2[..len]);
    for k in 0..len {
        let step = alpha_p * dp[k];
        out[k] = (s1[k] - step) * (z1[k] + alpha_d * dz1[k]) + (s2[k] + step) * (z2[k] + alpha_d * dz2[k]);
    }
}

/// Corrector targets c₁ = t + Δp Δz₁, c₂ = t − Δp Δz₂ and r = −u − c₁/s₁ + c₂/s₂.
#[inline(always)]
fn corrector_terms(target: f64, input: [&[f64]; 6], out: [&mut [f64]; 3]) {
    let [dp, dz1, dz2, u, inv_s1, inv_s2] = input;
    let [c1, c2, r] = out;
    let len = dp.len();
    let (dz1, dz2, u, inv_s1, inv_s2) = (&dz1[..len], &dz2[..len], &u[..len], &inv_s1[..len], &inv_s2[..len]);
    let (c1, c2, r) = (&mut c1[..len], &mut c2[..len], &mut r[..len]);
    for k in 0..len {
        c1[k] = target + dp[k] * dz1[k];
        c2[k] = target - dp[k] * dz2[k];
        r[k] = -u[k] - c1[k] * inv_s1[k] + c2[k] * inv_s2[k];
    }
}

/// The step: p += αΔp, s₁ −= αΔp, s₂ += αΔp (slacks are updated, not recomputed from p: near a bound a − p loses
/// all precision), z += α_dΔz, u = u_free + H y.
#[inline(always)]
fn take_step((alpha, alpha_d): (f64, f64), input: [&[f64]; 5], state: [&mut [f64]; 6]) {
    let [dp, dz1, dz2, u_free, hy] = input;
    let [p, s1, s2, z1, z2, u] = state;
    let len = dp.len();
    let (dz1, dz2, u_free, hy) = (&dz1[..len], &dz2[..len], &u_free[..len], &hy[..len]);
    let (p, s1, s2, z1, z2, u) =
        (&mut p[..len], &mut s1[..len], &mut s2[..len], &mut z1[..len], &mut z2[..len], &mut u[..len]);
    for k in 0..len {
        let step = alpha * dp[k];
        p[k] += step;
        s1[k] -= step;
        s2[k] += step;
        z1[k] += alpha_d * dz1[k];
        z2[k] += alpha_d * dz2[k];
        u[k] = u_free[k] + hy[k];
    }
}

/// Banded primal–dual interior-point solver with a moving window; scratch allocated once per run.
#[derive(Debug)]
pub struct BandedInteriorPoint {
    tolerance: f64,
    max_iterations: usize,
    /// Window margin (m); None solves the whole beam every step.
    margin: Option<f64>,
    all_active: Vec<usize>,
    backward: Option<BandedLdlt>,
    window_matrix: SymmetricBanded,
    work: Work,
    v: Vec<f64>,
    correction: Vec<f64>,
    check: Vec<f64>,
    started: bool,
    /// How the steps were solved.
    pub statistics: WindowStatistics,
}

impl BandedInteriorPoint {
    /// Scratch for `problem`. With `window_margin` = Some(m) (metres; 30 coupling lengths is safe) each step
    /// re-solves only a window around the sections that change; None always solves the whole problem.
    pub fn new(
        problem: &FrictionProblem<'_>,
        tolerance: f64,
        max_iterations: usize,
        window_margin: Option<f64>,
    ) -> crate::Result<Self> {
        let (n, m) = (problem.m_hat.order(), problem.len());
        let backward = match window_margin {
            Some(_) => Some(problem.m_hat.reversed().factor()?),
            None => None,
        };
        Ok(Self {
            tolerance,
            max_iterations,
            margin: window_margin,
            all_active: (0..m).filter(|&j| problem.bounds[j] > 0.0).collect(),
            backward,
            window_matrix: problem.m_hat.clone(),
            work: Work {
                sections: Sections::with_capacity(m),
                y: vec![0.0; n],
                dy: vec![0.0; n],
                b: problem.m_hat.clone(),
                b_factor: problem.factor.clone(),
            },
            v: vec![0.0; n],
            correction: vec![0.0; n],
            check: vec![0.0; m],
            started: false,
            statistics: WindowStatistics::default(),
        })
    }

    /// v = v_free + M̂⁻¹Hᵀp and the law residual of every section, into `self.check` (u) — one banded solve.
    fn full_residual(&mut self, problem: &FrictionProblem<'_>, v_free: &[f64], p: &[f64]) -> f64 {
        problem.outcome(v_free, p, &mut self.v, &mut self.check)
    }

    fn solve_whole(
        &mut self,
        problem: &FrictionProblem<'_>,
        u_free: &[f64],
        p: &mut [f64],
        tolerance: f64,
        budget: usize,
    ) -> crate::Result<(usize, f64)> {
        self.statistics.full += 1;
        self.statistics.sections_solved += self.all_active.len();
        let q = &mut self.work.sections;
        q.index.clear();
        q.index.extend_from_slice(&self.all_active);
        q.fit();
        for (u, &j) in q.u_free.iter_mut().zip(&q.index) {
            *u = u_free[j];
        }
        let subproblem = Subproblem { problem, base: problem.m_hat, offset: 0, tolerance, max_iterations: budget };
        self.work.iterate(&subproblem, p)
    }

    /// Re-solve the sections within `margin` of the ones violating the law (residuals in `self.check`, v in
    /// `self.v`), on the window's DOFs. Returns None when the window would be the whole problem.
    fn solve_window(
        &mut self,
        problem: &FrictionProblem<'_>,
        p: &mut [f64],
        tolerance: f64,
        margin: f64,
        budget: usize,
    ) -> crate::Result<Option<usize>> {
        let positions = problem.contacts.positions();
        let rows = problem.contacts.rows();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for &j in &self.all_active {
            if problem.section_residual(j, self.check[j], p[j]) > tolerance {
                lo = lo.min(positions[j]);
                hi = hi.max(positions[j]);
            }
        }
        let (lo, hi) = (lo - margin, hi + margin);
        self.work.sections.index.clear();
        let (mut start, mut end) = (usize::MAX, 0);
        for &j in &self.all_active {
            if (lo..=hi).contains(&positions[j]) {
                self.work.sections.index.push(j);
                if let Some((first, last)) = rows[j].dof_span() {
                    start = start.min(first);
                    end = end.max(last + 1);
                }
            }
        }
        let n = problem.m_hat.order();
        let bandwidth = problem.m_hat.bandwidth();
        if self.work.sections.index.len() == self.all_active.len() || end <= start {
            return Ok(None);
        }
        // The condensation needs the window wider than the band.
        if end - start <= bandwidth {
            end = (start + bandwidth + 1).min(n);
            start = end.saturating_sub(bandwidth + 1);
        }
        // v' = v − M̂⁻¹H_Wᵀp_W: the motion with the window's impulses removed; u_free of the window from it.
        self.correction.iter_mut().for_each(|x| *x = 0.0);
        for &j in &self.work.sections.index {
            rows[j].add_transpose(p[j], &mut self.correction);
        }
        problem.factor.solve_in_place(&mut self.correction);
        let q = &mut self.work.sections;
        q.fit();
        for (u, &j) in q.u_free.iter_mut().zip(&q.index) {
            *u = rows[j].dot(&self.v) - rows[j].dot(&self.correction);
        }
        problem.m_hat.principal_submatrix_into(start, end, &mut self.window_matrix);
        if start > 0 {
            problem.factor.subtract_leading_schur(start, &mut self.window_matrix);
        }
        if end < n {
            self.backward.as_ref().expect("window factors").subtract_trailing_schur(end, &mut self.window_matrix);
        }
        self.statistics.sections_solved += self.work.sections.index.len();
        let (iterations, _) = self.work.iterate(
            &Subproblem { problem, base: &self.window_matrix, offset: start, tolerance, max_iterations: budget },
            p,
        )?;
        Ok(Some(iterations))
    }
}

impl BandedInteriorPoint {
    /// Window solves with growing margins (the final check on every section decides), then the whole problem; all
    /// of them together within `max_iterations`.
    fn solve_windows(
        &mut self,
        problem: &FrictionProblem<'_>,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
        tolerance: f64,
        margin: f64,
    ) -> crate::Result<(usize, f64)> {
        let mut iterations = 0;
        for widen in [1.0, 2.0, 4.0] {
            let budget = self.max_iterations - iterations;
            match self.solve_window(problem, p, tolerance, widen * margin, budget)? {
                Some(used) => {
                    iterations += used;
                    let residual = self.full_residual(problem, v_free, p);
                    if residual <= tolerance {
                        self.statistics.windowed += 1;
                        return Ok((iterations, residual));
                    }
                }
                None => break,
            }
        }
        if iterations >= self.max_iterations {
            return Ok((iterations, self.full_residual(problem, v_free, p)));
        }
        let (more, residual) = self.solve_whole(problem, u_free, p, tolerance, self.max_iterations - iterations)?;
        Ok((iterations + more, residual))
    }
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
        let solved_before = self.statistics.sections_solved;
        let first = !self.started;
        self.started = true;
        let (iterations, residual) = match self.margin {
            Some(margin) if !first => {
                let predicted = self.full_residual(problem, v_free, p);
                if predicted <= tolerance {
                    self.statistics.unchanged += 1;
                    (0, predicted)
                } else {
                    self.solve_windows(problem, v_free, u_free, p, tolerance, margin)?
                }
            }
            _ => self.solve_whole(problem, u_free, p, tolerance, self.max_iterations)?,
        };
        Ok(StepReport {
            status: StepStatus::of(residual, tolerance, iterations, self.max_iterations),
            iterations,
            residual,
            tolerance,
            sections: self.statistics.sections_solved - solved_before,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fem_beam::reference::uic60_on_soft_soil;
    use friction::DistributedFriction;

    /// The AVX2 build of the iteration must give the same bits as the baseline build: same operations, same order,
    /// no fused multiply–add. A whole-beam step of the reference case with distributed friction and a wavy free
    /// velocity (stick and slip of both signs), solved by both. (Without AVX2 there is only the baseline build and
    /// nothing to compare.)
    #[test]
    fn avx2_and_baseline_iterations_agree_to_the_bit() {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            let model = uic60_on_soft_soil().model().expect("reference model");
            let contacts = DistributedFriction::new(5e3).contact_set(&model).expect("distributed friction");
            let h = 0.1 / 200.0;
            let system = crate::LinearSystem::from_beam(&model);
            let m_hat = crate::stepper::iteration_matrix(&system, crate::Integration { theta: 0.5, step: h });
            let factor = m_hat.factor().expect("M̂ is SPD");
            let problem = FrictionProblem::new(&contacts, &m_hat, &factor, h);
            let v_free: Vec<f64> = (0..m_hat.order()).map(|i| 0.3 * (0.05 * i as f64).sin() - 0.05).collect();
            let mut u_free = vec![0.0; contacts.len()];
            contacts.velocities(&v_free, &mut u_free);
            let tolerance = problem.absolute_tolerance(1e-8, &u_free);
            let subproblem = Subproblem { problem: &problem, base: &m_hat, offset: 0, tolerance, max_iterations: 200 };
            let solve = |avx2: bool| {
                let mut solver = BandedInteriorPoint::new(&problem, 1e-8, 200, None).expect("solver");
                let work = &mut solver.work;
                work.sections.index.extend(0..contacts.len());
                work.sections.fit();
                work.sections.u_free.copy_from_slice(&u_free);
                let mut p = vec![0.0; contacts.len()];
                #[allow(unsafe_code)]
                let (iterations, residual) = if avx2 {
                    // SAFETY: AVX2 detected above.
                    unsafe { work.iterate_avx2(&subproblem, &mut p) }
                } else {
                    work.iterate_body(&subproblem, &mut p)
                }
                .expect("iterate");
                assert!(residual <= tolerance, "{residual} > {tolerance}");
                (iterations, p)
            };
            let (baseline, avx2) = (solve(false), solve(true));
            assert!(baseline.0 > 3, "a nontrivial step: {} iterations", baseline.0);
            let slipping = baseline.1.iter().zip(&problem.bounds).filter(|(p, a)| p.abs() > 0.999 * *a).count();
            assert!(slipping > 10 && slipping < contacts.len() - 10, "stick and slip: {slipping} slipping");
            assert_eq!(baseline.0, avx2.0);
            assert!(baseline.1.iter().zip(&avx2.1).all(|(a, b)| a.to_bits() == b.to_bits()));
        }
    }
}
