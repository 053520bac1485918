//! The Mehrotra predictor–corrector iteration on a (sub)problem: Newton directions through the banded
//! B = M̂ + HᵀΣ⁻¹H, step lengths to the boundary, and the per-section slice kernels the compiler vectorises (built
//! twice: baseline and AVX2, the same operations in the same order).

use super::sections::Sections;
use super::terms::{affine_terms, centring_terms, corrector_terms, direction_terms, predictor_terms, take_step};
use crate::solver::{InteractionProblem, StepWork};
use banded::{BandedLdlt, SymmetricBanded};

/// Fraction of the distance to the boundary of the positive orthant taken by a step.
const FRACTION_TO_BOUNDARY: f64 = 0.995;

/// Iterations without halving the best law residual after which Mehrotra's heuristic is taken to cycle and the
/// iteration switches to safeguarded steps. Converging steps halve it every 1–3 iterations (measured: 11–26
/// iterations from 5e-3 to 3e-7 m/s on the reference distributed case), so 10 is never reached by a solve on its way.
const STALL_ITERATIONS: usize = 10;

/// Safeguarded iterations without halving the best law residual after which the solve stops as stalled (the
/// stepper then hands the step to its fallback solver instead of spending the whole iteration budget).
const GIVE_UP_ITERATIONS: usize = 60;

/// Centring parameter σ of a safeguarded step: the target σμ of a long-step path-following method.
const SAFEGUARD_CENTRING: f64 = 0.3;

/// How the iteration chooses its steps.
///
/// Mehrotra's predictor–corrector (σ = (μ_aff/μ)³, second-order correction, separate primal and dual step lengths)
/// is fast but not globally convergent: on a section that is weakly active at the solution (p at its bound with
/// u = 0, the border between stick and slip) it can fall into a limit cycle, the primal step alternating between
/// 0.995 and ~0.5 and μ between two values forever (measured: reference distributed case, f_u = 1 kN/m at 20 m/s,
/// step 1405, a period-4 cycle from iteration 20 on with the law residual between 1.7e-5 and 9.9e-5 m/s against a
/// tolerance of 3.2e-7). Like the safeguard of Salahi, Peng & Terlaky (2007, SIAM J. Optim. 18(4)), which takes
/// centring steps where Mehrotra's choice performs poorly, the iteration switches to plain path-following steps
/// once progress stops: a fixed centring target σμ without the second-order term and one common step length, which
/// brings the iterate back near the central path and breaks the cycle (that step converges in 6 more iterations;
/// docs/theory.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Steps {
    /// Mehrotra's predictor–corrector.
    Mehrotra,
    /// Safeguarded path-following steps (σ = [`SAFEGUARD_CENTRING`], common step length).
    Safeguarded,
}

/// Progress of the law residual: the best so far and the iterations since it last halved.
#[derive(Debug, Clone, Copy)]
struct Progress {
    best: f64,
    since_best: usize,
}

impl Progress {
    /// Record `residual`; true when the best residual has not halved for `patience` iterations.
    fn stalled(&mut self, residual: f64, patience: usize) -> bool {
        if residual < 0.5 * self.best {
            self.best = residual;
            self.since_best = 0;
        } else {
            self.since_best += 1;
        }
        self.since_best >= patience
    }
}

/// What one interior-point solve works on besides the sections: the step's problem, `base` = the matrix M̂ (or its
/// window condensation) over the DOFs from `offset` on — and, with a `tail` (t, a), over the DOFs from t on placed
/// from a on (a vehicle's, decoupled from the beam in M̂) — the absolute tolerance (m/s) and the iteration cap.
#[derive(Clone, Copy)]
pub(super) struct Subproblem<'s> {
    pub(super) problem: &'s InteractionProblem,
    pub(super) base: &'s SymmetricBanded,
    pub(super) offset: usize,
    pub(super) tail: Option<(usize, usize)>,
    pub(super) tolerance: f64,
    pub(super) max_iterations: usize,
}

impl Subproblem<'_> {
    /// The subproblem's DOF of system DOF `dof`.
    #[inline(always)]
    fn local(&self, dof: usize) -> usize {
        match self.tail {
            Some((first, at)) if dof >= first => at + dof - first,
            _ => dof - self.offset,
        }
    }
}

/// Per-section and per-DOF scratch of the interior-point iteration.
#[derive(Debug)]
pub(super) struct Work {
    pub(super) sections: Sections,
    pub(super) y: Vec<f64>,
    pub(super) dy: Vec<f64>,
    pub(super) b: SymmetricBanded,
    pub(super) b_factor: BandedLdlt,
    /// Scratch over all n DOFs (the start y = M̂⁻¹Hᵀp₀ when p₀ ≠ 0).
    pub(super) full: Vec<f64>,
    /// The banded factorisations and solves of the step so far.
    pub(super) counts: StepWork,
}

impl Work {
    /// From rhs = Σ H_jᵀ r_j Σ_j⁻¹ over the local rows (in `dy`): dy ← B⁻¹ rhs, Δp_j = Σ_j⁻¹(r_j − H_j dy) (the
    /// non-local rows' Δp and their share of dy from the bordered solve of [`super::extra_rows`]), Δz from the complementarity
    /// targets c (s₁Δz₁ = c₁ − s₁z₁ + z₁Δp, s₂Δz₂ = c₂ − s₂z₂ − z₂Δp); returns the largest feasible primal (p, s)
    /// and dual (z) steps ≤ 1. Taking them separately saves 11–13 % of the iterations (measured) and is safe here:
    /// convergence is judged on the law residual of (u, p), not on the dual residual.
    #[inline(always)]
    pub(super) fn newton_direction(&mut self) -> (f64, f64) {
        let n = self.b_factor.order();
        self.b_factor.solve_in_place(&mut self.dy[..n]);
        self.counts.solves += 1;
        let q = &mut self.sections;
        let extra = !q.extra.is_empty();
        if extra {
            q.extra.solve(&q.r, &mut self.dy[..n]);
        }
        q.gather(&self.dy);
        if extra {
            // Their Δp comes from the bordered solve: here a neutral Δp = 0, replaced below.
            for (k, _) in q.extra.impulses() {
                q.gathered[k] = q.r[k];
            }
        }
        let len = q.index.len();
        let (mut primal, mut dual) = direction_terms(
            [&q.r[..len], &q.gathered[..len], &q.inv_sigma[..len], &q.c1[..len], &q.c2[..len], &q.z1[..len]],
            [&q.z2[..len], &q.inv_s1[..len], &q.inv_s2[..len], &q.inv_z1[..len], &q.inv_z2[..len]],
            [&mut q.dp[..len], &mut q.dz1[..len], &mut q.dz2[..len]],
        );
        if extra {
            for (k, dp) in q.extra.impulses() {
                let dz1 = (q.c1[k] + q.z1[k] * dp) * q.inv_s1[k] - q.z1[k];
                let dz2 = (q.c2[k] - q.z2[k] * dp) * q.inv_s2[k] - q.z2[k];
                (q.dp[k], q.dz1[k], q.dz2[k]) = (dp, dz1, dz2);
                primal = primal.max(dp * q.inv_s1[k]).max(-dp * q.inv_s2[k]);
                dual = dual.max(-dz1 * q.inv_z1[k]).max(-dz2 * q.inv_z2[k]);
            }
        }
        (1.0 / primal, 1.0 / dual)
    }

    /// Mehrotra predictor–corrector on the active sections (`sections.index`, with `u_free` set), from p = 0, on
    /// `subproblem`, with the safeguard of [`Steps`] once it stops making progress. Writes the impulses of the active
    /// sections into `p`. Returns (iterations, residual); stops short of the tolerance and of the iteration cap when
    /// the safeguarded steps make no progress either ([`GIVE_UP_ITERATIONS`]).
    ///
    /// Compiled twice: for AVX2 where the CPU has it (detected at run time; four sections per instruction in the
    /// per-section loops instead of two), and for the baseline. Both execute the same operations in the same order
    /// — no fused multiply–add, sums still in section order — so they give the same bits.
    pub(super) fn iterate(&mut self, subproblem: &Subproblem<'_>, p: &mut [f64]) -> crate::Result<(usize, f64)> {
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
    pub(super) unsafe fn iterate_avx2(
        &mut self,
        subproblem: &Subproblem<'_>,
        p: &mut [f64],
    ) -> crate::Result<(usize, f64)> {
        self.iterate_body(subproblem, p)
    }

    /// The body of [`Work::iterate`], inlined into the baseline and the AVX2 build: load the sections, start inside
    /// every interval, then predictor–corrector (or safeguarded) iterations until the law residual meets the
    /// tolerance, the cap is reached or the safeguard gives up.
    #[inline(always)]
    pub(super) fn iterate_body(&mut self, subproblem: &Subproblem<'_>, p: &mut [f64]) -> crate::Result<(usize, f64)> {
        let Subproblem { base, tolerance, max_iterations, .. } = *subproblem;
        let len = self.sections.index.len();
        let open_count = self.load_sections(subproblem);
        self.start(subproblem);
        let mut residual = self.sections.law_residual();
        let inv_count = 1.0 / (2 * len - open_count).max(1) as f64;
        let mut iterations = 0;
        let mut steps = Steps::Mehrotra;
        let mut progress = Progress { best: residual, since_best: 0 };
        while residual > tolerance && iterations < max_iterations && len > 0 {
            iterations += 1;
            let mu = self.factor_newton_matrix(base, inv_count)?;
            let (alpha, alpha_d) = match steps {
                Steps::Mehrotra => self.mehrotra_steps(mu, inv_count),
                Steps::Safeguarded => self.safeguarded_steps(mu),
            };
            residual = self.take_steps(alpha, alpha_d);
            match steps {
                Steps::Mehrotra if progress.stalled(residual, STALL_ITERATIONS) => {
                    steps = Steps::Safeguarded;
                    progress.since_best = 0;
                }
                Steps::Safeguarded if progress.stalled(residual, GIVE_UP_ITERATIONS) => break,
                _ => {}
            }
        }
        for (&j, &pk) in self.sections.index.iter().zip(&self.sections.p) {
            p[j] = pk;
        }
        Ok((iterations, residual))
    }

    /// Copy the active sections' rows (shifted to the subproblem's DOFs), bounds, compliances, W_jj and drifts into
    /// the section arrays; zero y (with three entries of padding past the end, so that every row can be read and
    /// written four entries wide). Returns the number of sections without an upper bound.
    #[inline(always)]
    fn load_sections(&mut self, subproblem: &Subproblem<'_>) -> usize {
        let Subproblem { problem, base, .. } = *subproblem;
        let rows = problem.interactions.rows();
        let nw = base.order();
        self.y.resize(nw + 3, 0.0);
        self.dy.resize(nw + 3, 0.0);
        self.y.iter_mut().for_each(|x| *x = 0.0);
        let q = &mut self.sections;
        let law = &problem.law;
        q.rows.clear();
        q.extra.clear();
        let mut open_count = 0;
        let bandwidth = base.bandwidth();
        for k in 0..q.index.len() {
            let j = q.index[k];
            let row = &rows[j];
            debug_assert!(law.lower[j].is_finite(), "lower bounds are finite");
            if row.is_local() {
                q.rows.push(subproblem.local(row.dofs()[0]), row.values());
            } else if row.lies_in_band(bandwidth) {
                let mut columns = [0; 4];
                for (column, &dof) in columns.iter_mut().zip(row.dofs()) {
                    *column = subproblem.local(dof);
                }
                q.rows.push_entries(&columns[..row.len()], row.values());
            } else {
                // Empty in the band; the bordered solve takes it.
                q.rows.push(0, &[]);
                q.extra.push(k, row.entries().map(|(d, h)| (subproblem.local(d), h)));
            }
            q.lower[k] = law.lower[j];
            q.upper[k] = law.upper[j];
            q.compliance[k] = law.compliance[j];
            let open = law.upper[j] == f64::INFINITY;
            open_count += usize::from(open);
            q.closed[k] = if open { 0.0 } else { 1.0 };
            q.open[k] = 1.0 - q.closed[k];
            q.w[k] = problem.delassus_diagonal[j];
            q.inv_w[k] = 1.0 / q.w[k];
            q.u_free[k] += law.drift[j];
        }
        open_count
    }

    /// The starting point, inside every interval: a box at its centre (p = 0 for friction, where warm starts from
    /// the previous step's (p, z) were measured to cost more iterations, not fewer: 18.6 cold vs 19.8–23.9 warm per
    /// step, distributed 5 kN/m), a one-sided interval at the impulse scale max(|c|, shift)/w above its bound; u
    /// and y for that p, and z₂ − z₁ = u split with both kept away from zero (z₁ = 0 without an upper bound).
    #[inline(always)]
    fn start(&mut self, subproblem: &Subproblem<'_>) {
        let Subproblem { problem, base, offset, .. } = *subproblem;
        let rows = problem.interactions.rows();
        let nw = base.order();
        let q = &mut self.sections;
        let len = q.index.len();
        let scale = q.u_free.iter().fold(crate::problem::VELOCITY_FLOOR, |s, u| s.max(u.abs()));
        let shift = 0.01 * scale;
        let mut started_off_zero = false;
        for k in 0..len {
            q.p[k] = if q.closed[k] == 1.0 {
                0.5 * (q.lower[k] + q.upper[k])
            } else {
                q.lower[k] + q.u_free[k].abs().max(shift) * q.inv_w[k]
            };
            started_off_zero |= q.p[k] != 0.0;
            q.s1[k] = if q.closed[k] == 1.0 { q.upper[k] - q.p[k] } else { 1.0 };
            q.s2[k] = q.p[k] - q.lower[k];
        }
        if started_off_zero {
            // y = M̂⁻¹Hᵀp₀ on the window's DOFs (the window's Schur complement inverts to the window block of M̂⁻¹).
            self.full.iter_mut().for_each(|x| *x = 0.0);
            for k in 0..len {
                rows[q.index[k]].add_transpose(q.p[k], &mut self.full);
            }
            problem.matrix.factor.solve_in_place(&mut self.full);
            self.counts.solves += 1;
            match subproblem.tail {
                Some((first, at)) => {
                    self.y[..at].copy_from_slice(&self.full[offset..offset + at]);
                    self.y[at..nw].copy_from_slice(&self.full[first..]);
                }
                None => self.y[..nw].copy_from_slice(&self.full[offset..offset + nw]),
            }
            q.gather(&self.y);
            for k in 0..len {
                q.u[k] = q.u_free[k] + q.gathered[k] + q.compliance[k] * q.p[k];
            }
        } else {
            q.u[..len].copy_from_slice(&q.u_free[..len]);
        }
        for k in 0..len {
            q.z1[k] = if q.closed[k] == 1.0 { (-q.u[k]).max(0.0) + shift } else { 0.0 };
            q.z2[k] = q.u[k].max(0.0) + shift;
        }
    }

    /// B = base + HᵀΣ⁻¹H, Σ = z₁/s₁ + z₂/s₂, factored, with the predictor's terms (affine scaling, targets c = 0:
    /// r = −u, right-hand side Σ H_jᵀ r_j/Σ_j); Σ is floored so that Σ⁻¹ stays finite for sections stuck to
    /// round-off (z → 0): beyond ~1e15·W_jj the extra stiffness changes nothing. Returns μ = sᵀz/(number of
    /// complementarity pairs), `inv_count` being 1/that number.
    #[inline(always)]
    fn factor_newton_matrix(&mut self, base: &SymmetricBanded, inv_count: f64) -> crate::Result<f64> {
        let q = &mut self.sections;
        let len = q.index.len();
        predictor_terms(
            [&q.s1[..len], &q.s2[..len], &q.z1[..len], &q.z2[..len], &q.w[..len], &q.u[..len]],
            [&q.closed[..len], &q.open[..len], &q.compliance[..len]],
            [&mut q.inv_s1[..len], &mut q.inv_s2[..len], &mut q.inv_z1[..len], &mut q.inv_z2[..len]],
            [&mut q.inv_sigma[..len], &mut q.r[..len], &mut q.c1[..len], &mut q.c2[..len]],
        );
        let mut mu = 0.0;
        for (((s1, z1), s2), z2) in q.s1.iter().zip(&q.z1).zip(&q.s2).zip(&q.z2) {
            mu += s1 * z1 + s2 * z2;
        }
        mu *= inv_count;
        q.rows.weighted_gram_into(base, &q.inv_sigma, &mut self.b);
        self.b.factor_into(&mut self.b_factor)?;
        self.counts.factorisations += 1;
        if !q.extra.is_empty() {
            self.counts.solves += q.extra.factor(&self.b_factor, &q.inv_sigma)?;
        }
        Ok(mu)
    }

    /// Mehrotra's predictor, then the corrector targeting σμ − Δs_aff∘Δz_aff (Δs₁ = −Δp, Δs₂ = Δp),
    /// σ = (μ_aff/μ)³, r = −u − c₁/s₁ + c₂/s₂; returns the primal and dual step lengths.
    #[inline(always)]
    fn mehrotra_steps(&mut self, mu: f64, inv_count: f64) -> (f64, f64) {
        let len = self.sections.index.len();
        self.sections.right_hand_side(&mut self.dy);
        let (alpha_p_aff, alpha_d_aff) = self.newton_direction();
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
        ((FRACTION_TO_BOUNDARY * alpha_p).min(1.0), (FRACTION_TO_BOUNDARY * alpha_d).min(1.0))
    }

    /// A safeguarded path-following direction (target [`SAFEGUARD_CENTRING`]·μ, no second-order term); returns
    /// one common step length, twice.
    #[inline(always)]
    fn safeguarded_steps(&mut self, mu: f64) -> (f64, f64) {
        let q = &mut self.sections;
        let len = q.index.len();
        centring_terms(
            SAFEGUARD_CENTRING * mu,
            [&q.u[..len], &q.inv_s1[..len], &q.inv_s2[..len]],
            [&mut q.c1[..len], &mut q.c2[..len], &mut q.r[..len]],
        );
        q.right_hand_side(&mut self.dy);
        let (alpha_p, alpha_d) = self.newton_direction();
        let alpha = (FRACTION_TO_BOUNDARY * alpha_p.min(alpha_d)).min(1.0);
        (alpha, alpha)
    }

    /// Move y, (p, s) by `alpha` and z by `alpha_d` along the direction, u with them; returns the law residual.
    #[inline(always)]
    fn take_steps(&mut self, alpha: f64, alpha_d: f64) -> f64 {
        for (y, dy) in self.y.iter_mut().zip(&self.dy) {
            *y += alpha * dy;
        }
        let q = &mut self.sections;
        let len = q.index.len();
        q.gather(&self.y);
        take_step(
            (alpha, alpha_d),
            [&q.dp[..len], &q.dz1[..len], &q.dz2[..len], &q.u_free[..len], &q.gathered[..len], &q.compliance[..len]],
            [&mut q.p[..len], &mut q.s1[..len], &mut q.s2[..len], &mut q.z1[..len], &mut q.z2[..len], &mut q.u[..len]],
        );
        q.law_residual()
    }
}
