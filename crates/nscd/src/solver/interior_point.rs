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

use super::{FrictionProblem, FrictionSolver, StepReport};
use fem_beam::{BandedLdlt, SymmetricBanded};

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

/// Interior-point state of one section (kept together: the iteration sweeps the sections in order).
#[derive(Debug, Clone, Copy, Default)]
struct Section {
    /// First DOF of the row (window-local): rows touch consecutive free DOFs.
    first: usize,
    /// Entries of the row, zero-padded to four.
    h: [f64; 4],
    /// Number of entries.
    len: usize,
    /// Bound a_j (N·s), W_jj and 1/W_jj.
    a: f64,
    w: f64,
    inv_w: f64,
    u_free: f64,
    u: f64,
    s1: f64,
    s2: f64,
    z1: f64,
    z2: f64,
    inv_s1: f64,
    inv_s2: f64,
    inv_z1: f64,
    inv_z2: f64,
    inv_sigma: f64,
    r: f64,
    c1: f64,
    c2: f64,
    dp: f64,
    dz1: f64,
    dz2: f64,
}

impl Section {
    /// The law residual at (u, p): |p − proj(p − u/W_jj)|·W_jj (m/s), as [`FrictionProblem::section_residual`]
    /// with 1/W_jj kept at hand.
    #[inline]
    fn law_residual(&self, p: f64) -> f64 {
        (p - (p - self.u * self.inv_w).clamp(-self.a, self.a)).abs() * self.w
    }

    /// H_j·x (x padded with three zeros past its end).
    #[inline]
    fn dot(&self, x: &[f64]) -> f64 {
        let x = &x[self.first..self.first + 4];
        self.h[0] * x[0] + self.h[1] * x[1] + self.h[2] * x[2] + self.h[3] * x[3]
    }

    /// out += s·H_jᵀ (out padded with three zeros past its end).
    #[inline]
    fn add_transpose(&self, s: f64, out: &mut [f64]) {
        let out = &mut out[self.first..self.first + 4];
        for k in 0..4 {
            out[k] += s * self.h[k];
        }
    }
}

/// Per-section and per-DOF scratch of the interior-point iteration.
#[derive(Debug)]
struct Work {
    active: Vec<usize>,
    sections: Vec<Section>,
    y: Vec<f64>,
    dy: Vec<f64>,
    b: SymmetricBanded,
    b_factor: BandedLdlt,
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

impl Work {
    /// From rhs = Σ H_jᵀ r_j Σ_j⁻¹ (in `dy`): dy ← B⁻¹ rhs, Δp_j = Σ_j⁻¹(r_j − H_j dy), Δz from the complementarity
    /// targets c (s₁Δz₁ = c₁ − s₁z₁ + z₁Δp, s₂Δz₂ = c₂ − s₂z₂ − z₂Δp); returns the largest feasible primal (p, s)
    /// and dual (z) steps ≤ 1. Taking them separately saves 11–13 % of the iterations (measured) and is safe here:
    /// convergence is judged on the law residual of (u, p), not on the dual residual.
    fn newton_direction(&mut self) -> (f64, f64) {
        let n = self.b_factor.order();
        self.b_factor.solve_in_place(&mut self.dy[..n]);
        let dy = &self.dy;
        // max of −Δx/x over the primal (s) and the dual (z) variables; α = 1/ratio
        let (mut primal, mut dual): (f64, f64) = (1.0, 1.0);
        for &j in &self.active {
            let q = &mut self.sections[j];
            let dp = (q.r - q.dot(dy)) * q.inv_sigma;
            let dz1 = (q.c1 + q.z1 * dp) * q.inv_s1 - q.z1;
            let dz2 = (q.c2 - q.z2 * dp) * q.inv_s2 - q.z2;
            q.dp = dp;
            q.dz1 = dz1;
            q.dz2 = dz2;
            // Plain comparisons (no NaN handling needed: every quantity is finite here) are cheaper than f64::max.
            for candidate in [dp * q.inv_s1, -dp * q.inv_s2] {
                if candidate > primal {
                    primal = candidate;
                }
            }
            for candidate in [-dz1 * q.inv_z1, -dz2 * q.inv_z2] {
                if candidate > dual {
                    dual = candidate;
                }
            }
        }
        (1.0 / primal, 1.0 / dual)
    }

    /// Mehrotra predictor–corrector on the active sections, from p = 0, with `base` = the matrix M̂ (or its window
    /// condensation) over the DOFs from `offset` on and u_free set. Returns (iterations, residual).
    fn iterate(
        &mut self,
        problem: &FrictionProblem<'_>,
        base: &SymmetricBanded,
        offset: usize,
        p: &mut [f64],
        tolerance: f64,
        max_iterations: usize,
    ) -> crate::Result<(usize, f64)> {
        let a = &problem.bounds;
        let rows = problem.contacts.rows();
        let nw = base.order();
        // Three zeros of padding past the end let every row be read and written four entries wide.
        self.y.resize(nw + 3, 0.0);
        self.dy.resize(nw + 3, 0.0);
        self.y.iter_mut().for_each(|x| *x = 0.0);
        for &j in &self.active {
            let q = &mut self.sections[j];
            let row = &rows[j];
            debug_assert!(row.dofs().windows(2).all(|d| d[1] == d[0] + 1), "rows touch consecutive free DOFs");
            q.first = row.dofs()[0] - offset;
            q.len = row.len();
            q.h = [0.0; 4];
            q.h[..q.len].copy_from_slice(row.values());
            q.a = a[j];
            q.w = problem.delassus_diagonal[j];
            q.inv_w = 1.0 / q.w;
        }
        // Start at p = 0, the centre of every box: warm starts from the previous step's (p, z) were measured to
        // cost more iterations, not fewer (18.6 cold vs 19.8–23.9 warm per step, distributed 5 kN/m).
        let scale = self.active.iter().fold(super::VELOCITY_FLOOR, |s, &j| s.max(self.sections[j].u_free.abs()));
        let shift = 0.01 * scale;
        let mut residual: f64 = 0.0;
        for &j in &self.active {
            p[j] = 0.0;
            let q = &mut self.sections[j];
            q.u = q.u_free;
            q.s1 = a[j];
            q.s2 = a[j];
            // Split u into z₂ − z₁, both kept away from zero.
            q.z1 = (-q.u).max(0.0) + shift;
            q.z2 = q.u.max(0.0) + shift;
            let r = q.law_residual(0.0);
            if r > residual {
                residual = r;
            }
        }
        let inv_count = 1.0 / (2 * self.active.len().max(1)) as f64;
        let mut iterations = 0;
        while residual > tolerance && iterations < max_iterations && !self.active.is_empty() {
            iterations += 1;
            // B = base + HᵀΣ⁻¹H, Σ = z₁/s₁ + z₂/s₂, floored so that Σ⁻¹ stays finite for sections stuck to
            // round-off (z → 0): beyond ~1e15·W_jj the extra stiffness changes nothing. Predictor (affine
            // scaling, targets c = 0): r = −u, right-hand side Σ H_jᵀ r_j/Σ_j.
            self.b.copy_from(base);
            self.dy.iter_mut().for_each(|x| *x = 0.0);
            let mut mu = 0.0;
            for &j in &self.active {
                let q = &mut self.sections[j];
                mu += q.s1 * q.z1 + q.s2 * q.z2;
                q.inv_s1 = 1.0 / q.s1;
                q.inv_s2 = 1.0 / q.s2;
                q.inv_z1 = 1.0 / q.z1;
                q.inv_z2 = 1.0 / q.z2;
                q.inv_sigma = 1.0 / (q.z1 * q.inv_s1 + q.z2 * q.inv_s2).max(1e-15 * q.w);
                q.r = -q.u;
                q.c1 = 0.0;
                q.c2 = 0.0;
                self.b.add_outer_contiguous(q.first, &q.h[..q.len], q.inv_sigma);
                q.add_transpose(q.r * q.inv_sigma, &mut self.dy);
            }
            mu *= inv_count;
            self.b.factor_into(&mut self.b_factor)?;
            let (alpha_p_aff, alpha_d_aff) = self.newton_direction();
            // Corrector: targets σμ − Δs_aff∘Δz_aff (Δs₁ = −Δp, Δs₂ = Δp), σ = (μ_aff/μ)³, r = −u − c₁/s₁ + c₂/s₂.
            let mut mu_affine = 0.0;
            for &j in &self.active {
                let q = &self.sections[j];
                let dp = alpha_p_aff * q.dp;
                mu_affine += (q.s1 - dp) * (q.z1 + alpha_d_aff * q.dz1) + (q.s2 + dp) * (q.z2 + alpha_d_aff * q.dz2);
            }
            let target = (mu_affine * inv_count / mu).powi(3).min(1.0) * mu;
            self.dy.iter_mut().for_each(|x| *x = 0.0);
            for &j in &self.active {
                let q = &mut self.sections[j];
                q.c1 = target + q.dp * q.dz1;
                q.c2 = target - q.dp * q.dz2;
                q.r = -q.u - q.c1 * q.inv_s1 + q.c2 * q.inv_s2;
                q.add_transpose(q.r * q.inv_sigma, &mut self.dy);
            }
            let (alpha_p, alpha_d) = self.newton_direction();
            let (alpha, alpha_d) =
                ((FRACTION_TO_BOUNDARY * alpha_p).min(1.0), (FRACTION_TO_BOUNDARY * alpha_d).min(1.0));
            for (y, dy) in self.y.iter_mut().zip(&self.dy) {
                *y += alpha * dy;
            }
            residual = 0.0;
            for &j in &self.active {
                let q = &mut self.sections[j];
                let dp = alpha * q.dp;
                p[j] += dp;
                // Slacks are updated, not recomputed from p: near a bound a − p loses all precision.
                q.s1 -= dp;
                q.s2 += dp;
                q.z1 += alpha_d * q.dz1;
                q.z2 += alpha_d * q.dz2;
                q.u = q.u_free + q.dot(&self.y);
                let r = q.law_residual(p[j]);
                if r > residual {
                    residual = r;
                }
            }
        }
        Ok((iterations, residual))
    }
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
                active: Vec::with_capacity(m),
                sections: vec![Section::default(); m],
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
    ) -> crate::Result<(usize, f64)> {
        self.statistics.full += 1;
        self.statistics.sections_solved += self.all_active.len();
        self.work.active.clear();
        self.work.active.extend_from_slice(&self.all_active);
        for (q, &u) in self.work.sections.iter_mut().zip(u_free) {
            q.u_free = u;
        }
        self.work.iterate(problem, problem.m_hat, 0, p, tolerance, self.max_iterations)
    }

    /// Re-solve the sections within `margin` of the ones violating the law (residuals in `self.check`, v in
    /// `self.v`), on the window's DOFs. Returns None when the window would be the whole problem.
    fn solve_window(
        &mut self,
        problem: &FrictionProblem<'_>,
        p: &mut [f64],
        tolerance: f64,
        margin: f64,
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
        self.work.active.clear();
        let (mut start, mut end) = (usize::MAX, 0);
        for &j in &self.all_active {
            if (lo..=hi).contains(&positions[j]) {
                self.work.active.push(j);
                if let Some((first, last)) = rows[j].dof_span() {
                    start = start.min(first);
                    end = end.max(last + 1);
                }
            }
        }
        let n = problem.m_hat.order();
        let bandwidth = problem.m_hat.bandwidth();
        if self.work.active.len() == self.all_active.len() || end <= start {
            return Ok(None);
        }
        // The condensation needs the window wider than the band.
        if end - start <= bandwidth {
            end = (start + bandwidth + 1).min(n);
            start = end.saturating_sub(bandwidth + 1);
        }
        // v' = v − M̂⁻¹H_Wᵀp_W: the motion with the window's impulses removed; u_free of the window from it.
        self.correction.iter_mut().for_each(|x| *x = 0.0);
        for &j in &self.work.active {
            rows[j].add_transpose(p[j], &mut self.correction);
        }
        problem.factor.solve_in_place(&mut self.correction);
        for &j in &self.work.active {
            self.work.sections[j].u_free = rows[j].dot(&self.v) - rows[j].dot(&self.correction);
        }
        problem.m_hat.principal_submatrix_into(start, end, &mut self.window_matrix);
        if start > 0 {
            problem.factor.subtract_leading_schur(start, &mut self.window_matrix);
        }
        if end < n {
            self.backward.as_ref().expect("window factors").subtract_trailing_schur(end, &mut self.window_matrix);
        }
        self.statistics.sections_solved += self.work.active.len();
        let (iterations, _) =
            self.work.iterate(problem, &self.window_matrix, start, p, tolerance, self.max_iterations)?;
        Ok(Some(iterations))
    }
}

impl BandedInteriorPoint {
    /// Window solves with growing margins (the final check on every section decides), then the whole problem.
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
            match self.solve_window(problem, p, tolerance, widen * margin)? {
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
        let (more, residual) = self.solve_whole(problem, u_free, p, tolerance)?;
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
            _ => self.solve_whole(problem, u_free, p, tolerance)?,
        };
        Ok(StepReport {
            iterations,
            residual,
            tolerance,
            converged: residual <= tolerance,
            sections: self.statistics.sections_solved - solved_before,
        })
    }
}
