//! The previous step's active set as the step's predictor (primal–dual active set, Hintermüller, Ito & Kunisch 2002),
//! for a step whose every free interaction is either a compliant one-sided support — the sections of a tensionless or
//! bilinear soil: lo = 0, hi = +∞, d > 0 — or a rigid box — a Coulomb section: lo = −hF, hi = hF finite, d = 0.
//!
//! Such a step is the box QP of the module above. Once it is known which sections are *held* (set A: lo < p < hi, the
//! law's velocity r = U + b + d·p zero) and which sit at a bound (p = lo or hi), it is linear: with c = U_free + b,
//! W = H M̂⁻¹ Hᵀ and L the sections at a bound, (W_AA + D_A) p_A = −c_A − W_AL p_L. By the Woodbury identity, with
//! B = M̂ + H_Aᵀ D_A⁻¹ H_A — M̂ with the held sections' springs added, banded like M̂ —
//!
//! ```text
//! y = B⁻¹ Hᵀ g,  g_A = D_A⁻¹ c_A,  g_L = −p_L;   p_j = (H_j y − c_j)/d_j  (j ∈ A),
//! ```
//!
//! one banded factorisation and one solve — and the step's velocity with it: M̂ y = −Hᵀp, so
//! v = v_free + M̂⁻¹Hᵀp = v_free − y without a second solve.
//!
//! A rigid section (d = 0) is held by the stiff spring d_ε = ε_j = [`RIGID_HOLD`]·W_jj about the impulse p̄_j it
//! had before the round (a proximal term: r_j = U_j + ε_j(p_j − p̄_j) = 0, i.e. c_j − ε_j p̄_j in place of c_j). A
//! round leaves a held rigid section the velocity U_j = −ε_j(p_j − p̄_j): each round on the same set shrinks it by
//! ~ε_j/(ε_j + λ(W_AA)), so the answer is exact once the set has settled, with no ill-conditioned B (its springs are
//! 10⁶× a row's own mass, not infinite). Its impulse (H_j y − c_j)/ε_j + p̄_j is a difference of nearly equal
//! velocities times 1/ε_j, good to ~1e-9 of itself: with rigid sections the stepper forms v from p again (one solve)
//! instead of taking v_free − y, so that the energy identity holds at round-off.
//!
//! From one step to the next the set changes only at its edges (lift-off zones, stick–slip fronts), so the previous
//! step's set is nearly this step's. Starting from it, the update j ∈ A ⇔ lo_j < p_j − r_j/(W_jj + d_j) < hi_j (at lo
//! below, at hi above) moves the few sections at the edges; the step is accepted when the law residual on every
//! section meets the tolerance. Should it not within [`MAX_ROUNDS`], the interior point takes the step from the
//! previous impulses. (A soil's sections re-solved by the interior point every step cost ten factorisations a step:
//! a tensionless run 52× a linear one.) The update converges in a few rounds when the sections are not redundant and
//! not closer than the coupling length of M̂ (one Coulomb section a node, 1 m apart); with several sections an
//! element (W singular) it wanders, so after [`MAX_MISSES`] steps in a row that it did not take, a run with rigid
//! sections stops trying it.

use crate::integrator::IterationMatrix;
use crate::problem::InteractionProblem;
use banded::{BandedLdlt, BlockRows, SymmetricBanded};
use friction::Law;

/// Active-set rounds tried before the interior point takes the step.
pub(super) const MAX_ROUNDS: usize = 4;

/// Steps in a row the predictor may miss before a run with rigid sections stops trying it.
pub(super) const MAX_MISSES: usize = 3;

/// The holding spring of a rigid section relative to the section's own stiffness 1/W_jj: ε_j = RIGID_HOLD·W_jj (a
/// round on a settled set shrinks the held sections' velocities ~10⁶-fold; B stays as well conditioned as 10⁶ allows).
pub(super) const RIGID_HOLD: f64 = 1e-6;

/// Scratch of the predictor, allocated once per run.
#[derive(Debug)]
pub(super) struct ActiveSet {
    /// Every row of H, four entries at a time.
    rows: BlockRows,
    matrix: SymmetricBanded,
    factor: BandedLdlt,
    /// 1/d_j on the held set, 0 elsewhere: B = M̂ + Hᵀ diag(weights) H.
    weights: Vec<f64>,
    /// 1/d_j of every section (1/ε_j for a rigid one), and the compliances they were taken from.
    inverse_compliance: (Vec<f64>, Vec<f64>),
    /// The free held set B was last factored with, and of which M̂ (its address): a step whose set is the last
    /// factored one solves with that factor as it is.
    factored: Option<(Vec<bool>, *const IterationMatrix)>,
    /// The free held set of this prediction.
    free_held: Vec<bool>,
    /// g: c_j/d_j on the held set (less p̄_j for a rigid section), −p_j elsewhere: the right-hand side is Hᵀg.
    scaled: Vec<f64>,
    /// y, with three entries past the order for the four-wide row products.
    y: Vec<f64>,
    /// H y.
    hy: Vec<f64>,
    /// The impulses before the prediction, restored when it fails.
    saved: Vec<f64>,
    /// The sides the next prediction takes: held (lo < p < hi, r = 0), else at hi where `upper`, at lo otherwise.
    held: Vec<bool>,
    upper: Vec<bool>,
    /// The DOF spans of the rows whose springs the last change of B added or took out.
    changed: Vec<(usize, usize)>,
    /// Steps in a row the predictor did not take, and whether the run has rigid sections (then it gives up after
    /// [`MAX_MISSES`]).
    misses: usize,
    rigid: bool,
}

impl ActiveSet {
    /// Scratch for `problem`; None unless every row is fixed and lies in the band (a wheel's row reaches its own
    /// DOF, which B cannot hold).
    pub(super) fn new(problem: &InteractionProblem) -> Option<Self> {
        let rows = problem.interactions.rows();
        let bandwidth = problem.matrix.m_hat.bandwidth();
        if problem.fixed_len() != rows.len() || !rows.iter().all(|r| r.lies_in_band(bandwidth)) {
            return None;
        }
        let mut block_rows = BlockRows::with_capacity(rows.len());
        for row in rows {
            block_rows.push_entries(row.dofs(), row.values());
        }
        let (n, m) = (problem.matrix.m_hat.order(), rows.len());
        Some(Self {
            rows: block_rows,
            matrix: problem.matrix.m_hat.clone(),
            factor: problem.matrix.factor.clone(),
            weights: vec![0.0; m],
            inverse_compliance: (vec![0.0; m], vec![f64::NAN; m]),
            factored: None,
            free_held: vec![false; m],
            scaled: vec![0.0; m],
            y: vec![0.0; n + 3],
            hy: vec![0.0; m],
            saved: vec![0.0; m],
            held: vec![false; m],
            upper: vec![false; m],
            changed: Vec::with_capacity(m),
            misses: 0,
            rigid: problem.law.compliance.contains(&0.0),
        })
    }

    /// Whether this step is one the predictor takes: every free interaction a compliant one-sided support of fixed
    /// compliance (no Hertz contact, whose compliance follows its linearisation) or a rigid box with finite bounds
    /// and no drift (a Coulomb section).
    pub(super) fn applies(problem: &InteractionProblem) -> bool {
        let law = &problem.law;
        let support = |j: usize| law.lower[j] == 0.0 && law.upper[j] == f64::INFINITY && law.compliance[j] > 0.0;
        let rigid_box = |j: usize| {
            law.lower[j].is_finite() && law.upper[j].is_finite() && law.compliance[j] == 0.0 && law.drift[j] == 0.0
        };
        !problem.has_hertz() && (0..problem.len()).all(|j| !law.is_free(j) || support(j) || rigid_box(j))
    }

    /// Whether every interaction is a compliant stop, a soil section or a Coulomb section — laws whose step bounds
    /// and compliance are the run's at every step — so that [`ActiveSet::applies`] holds for the run once it holds.
    pub(super) fn applies_every_step(problem: &InteractionProblem) -> bool {
        !problem.has_hertz()
            && problem
                .interactions
                .laws()
                .iter()
                .all(|law| matches!(law, Law::Compliant { .. } | Law::Soil { .. } | Law::Coulomb { .. }))
    }

    /// Whether the predictor is still worth a try: always for compliant supports alone; with rigid sections until
    /// it missed [`MAX_MISSES`] steps in a row.
    pub(super) fn worth_trying(&self) -> bool {
        !self.rigid || self.misses < MAX_MISSES
    }

    /// Whether the run has rigid sections, whose held impulses a further round on a settled set refines.
    pub(super) fn holds_rigid(&self) -> bool {
        self.rigid
    }

    /// Count a step the predictor took (`taken`) or missed.
    pub(super) fn record(&mut self, taken: bool) {
        self.misses = if taken { 0 } else { self.misses + 1 };
    }

    /// Start from the sides of `p` (held strictly inside its bounds), keeping `p` for [`ActiveSet::restore`]; 1/d_j
    /// from the step's law (1/ε_j for a rigid section).
    pub(super) fn start(&mut self, problem: &InteractionProblem, p: &[f64]) {
        let law = &problem.law;
        let (inverse, of) = &mut self.inverse_compliance;
        if *of != law.compliance {
            of.copy_from_slice(&law.compliance);
            let diagonal = &problem.delassus_diagonal;
            for ((i, &d), &w) in inverse.iter_mut().zip(of.iter()).zip(diagonal) {
                *i = if d > 0.0 { 1.0 / d } else { 1.0 / (RIGID_HOLD * w) };
            }
        }
        self.saved.copy_from_slice(p);
        if !self.rigid {
            // Compliant supports alone (lo = 0, hi = ∞): held where pressed.
            for (held, &p) in self.held.iter_mut().zip(p) {
                *held = p > 0.0;
            }
            return;
        }
        let bounds = law.lower.iter().zip(&law.upper);
        for (((held, upper), &p), (&lo, &hi)) in self.held.iter_mut().zip(&mut self.upper).zip(p).zip(bounds) {
            *held = lo < p && p < hi;
            *upper = p >= hi;
        }
    }

    /// The active-set update from the outcome of the last prediction (`u` = H v of its impulses `p`): with
    /// s = p_j(W_jj + d_j) − r_j, held where lo_j(W_jj + d_j) < s < hi_j(W_jj + d_j), at the bound it passes
    /// otherwise; whether any side changed.
    pub(super) fn update(&mut self, problem: &InteractionProblem, u: &[f64], p: &[f64]) -> bool {
        if !self.rigid {
            return self.update_supports(problem, u, p);
        }
        let law = &problem.law;
        let mut changed = false;
        let terms = law.drift.iter().zip(&law.compliance).zip(law.lower.iter().zip(&law.upper));
        let state = u.iter().zip(p).zip(&problem.delassus_diagonal);
        let sides = self.held.iter_mut().zip(self.upper.iter_mut());
        for ((side, ((&u, &p), &w)), ((&b, &d), (&lo, &hi))) in sides.zip(state).zip(terms) {
            if lo < hi {
                let s = p * w - (u + b + d * p);
                let now = (lo * w < s && s < hi * w, s >= hi * w);
                changed |= now.0 != *side.0 || (!now.0 && now.1 != *side.1);
                (*side.0, *side.1) = now;
            }
        }
        changed
    }

    /// [`ActiveSet::update`] for compliant supports alone (lo = 0, hi = ∞): held or at lo by the sign of s.
    fn update_supports(&mut self, problem: &InteractionProblem, u: &[f64], p: &[f64]) -> bool {
        let law = &problem.law;
        let mut changed = false;
        let terms = law.drift.iter().zip(&law.compliance).zip(law.lower.iter().zip(&law.upper));
        let state = u.iter().zip(p).zip(&problem.delassus_diagonal);
        for ((held, ((&u, &p), &w)), ((&b, &d), (lo, hi))) in self.held.iter_mut().zip(state).zip(terms) {
            if lo < hi {
                let now = p * w - (u + b + d * p) > 0.0;
                changed |= now != *held;
                *held = now;
            }
        }
        changed
    }

    /// Replace `p` by the solution on the current sides and its velocities U = U_free − H y into `u`
    /// (y = −M̂⁻¹Hᵀp: [`ActiveSet::y`]); whether B was factored anew. `u_free` = H v_free.
    pub(super) fn predict(
        &mut self,
        problem: &InteractionProblem,
        u_free: &[f64],
        p: &mut [f64],
        u: &mut [f64],
    ) -> crate::Result<bool> {
        let law = &problem.law;
        let inverse = &self.inverse_compliance.0;
        // c_j = U_free,j + b_j; the loops zip their arrays (no index checks: they run over every section a round).
        let bounds = law.lower.iter().zip(&law.upper);
        let weights = self.weights.iter_mut().zip(self.scaled.iter_mut());
        let c = u_free.iter().zip(&law.drift).map(|(u, b)| u + b);
        if !self.rigid {
            // Compliant supports alone: g_j = c_j/d_j held, 0 at lo = 0 — branch-free, the soils' loop.
            let sets = self.free_held.iter_mut().zip(&self.held);
            for ((((free_held, &held), (weight, scaled)), (lo, hi)), (c, &inverse)) in
                sets.zip(weights).zip(bounds).zip(c.zip(inverse.iter()))
            {
                *free_held = lo < hi && held;
                *weight = if *free_held { inverse } else { 0.0 };
                *scaled = *weight * c;
            }
        } else {
            let sets = self.free_held.iter_mut().zip(self.held.iter().zip(&self.upper));
            let own = inverse.iter().zip(&law.compliance).zip(p.iter());
            for ((((free_held, (&held, &upper)), (weight, scaled)), (&lo, &hi)), (c, ((&inverse, &d), &p))) in
                sets.zip(weights).zip(bounds).zip(c.zip(own))
            {
                *free_held = lo < hi && held;
                *weight = if *free_held { inverse } else { 0.0 };
                *scaled = match (lo < hi, held, upper) {
                    (false, _, _) => -p,
                    (true, true, _) if d == 0.0 => inverse * c - p,
                    (true, true, _) => inverse * c,
                    (true, false, true) => -hi,
                    (true, false, false) => -lo,
                };
            }
        }
        let refactored = self.factor_held(problem)?;
        let n = self.factor.order();
        self.rows.transpose_mul(&self.scaled, &mut self.y);
        self.factor.solve_in_place(&mut self.y[..n]);
        self.rows.mul(&self.y, &mut self.hy);
        self.outcome(problem, u_free, p, u);
        Ok(refactored)
    }

    /// The impulses of the current sides from H y, and U = U_free − H y: p_j = (H_j y − c_j)/d_j held (+ p̄_j for a
    /// rigid section, p̄ its impulse before the round), lo_j or hi_j at a bound.
    fn outcome(&self, problem: &InteractionProblem, u_free: &[f64], p: &mut [f64], u: &mut [f64]) {
        let law = &problem.law;
        let c = u_free.iter().zip(&law.drift).map(|(u, b)| u + b);
        let inverse = &self.inverse_compliance.0;
        let outcome = u.iter_mut().zip(p.iter_mut()).zip(u_free.iter().zip(&self.hy));
        if !self.rigid {
            // Compliant supports alone: held or at lo = 0 — the soils' loop.
            let law_terms = c.zip(inverse.iter()).zip(law.lower.iter().zip(&law.upper)).zip(&self.held);
            for (((u, p), (u_free, hy)), (((c, inverse), (lo, hi)), &held)) in outcome.zip(law_terms) {
                *u = u_free - hy;
                if lo < hi {
                    *p = if held { (hy - c) * inverse } else { 0.0 };
                }
            }
            return;
        }
        let own = inverse.iter().zip(&law.compliance).zip(law.lower.iter().zip(&law.upper));
        let sections = outcome.zip(c.zip(own).zip(self.held.iter().zip(&self.upper)));
        for (((u, p), (u_free, hy)), ((c, ((inverse, &d), (&lo, &hi))), (&held, &upper))) in sections {
            *u = u_free - hy;
            if lo < hi {
                *p = match (held, upper) {
                    (true, _) if d == 0.0 => (hy - c) * inverse + *p,
                    (true, _) => (hy - c) * inverse,
                    (false, true) => hi,
                    (false, false) => lo,
                };
            }
        }
    }

    /// B = M̂ + Hᵀ diag(weights) H of this prediction's held set factored: as it is when the set is the last factored
    /// one, refactored from the sections that changed otherwise, afresh the first time; whether it was factored.
    fn factor_held(&mut self, problem: &InteractionProblem) -> crate::Result<bool> {
        let m_hat = std::sync::Arc::as_ptr(&problem.matrix);
        let (rows, matrix) = (problem.interactions.rows(), &mut self.matrix);
        let inverse = &self.inverse_compliance.0;
        let refactored = match &mut self.factored {
            Some((set, of)) if *of == m_hat && *set == self.free_held => Ok(false),
            Some((set, of)) if *of == m_hat => {
                // B of the last set, with the springs of the sections that changed added or taken out: a few
                // outer products where the whole gram would cost all of them (as exact, to round-off of B), and
                // the factor's rows recomputed from each change on until they repeat to the bit.
                let changed = &mut self.changed;
                changed.clear();
                for (j, (was, &is)) in set.iter_mut().zip(&self.free_held).enumerate().filter(|(_, (w, i))| **w != **i)
                {
                    let sign = if is { 1.0 } else { -1.0 };
                    matrix.add_outer(rows[j].dofs(), rows[j].values(), sign * inverse[j]);
                    *was = is;
                    if let Some(span) = rows[j].dof_span() {
                        changed.push(span);
                    }
                }
                changed.sort_unstable();
                refactor_changed_rows(matrix, &mut self.factor, changed).map(|()| true)
            }
            _ => {
                self.rows.weighted_gram_into(&problem.matrix.m_hat, &self.weights, matrix);
                self.factored = Some((self.free_held.clone(), m_hat));
                self.matrix.factor_into(&mut self.factor).map(|()| true).map_err(Into::into)
            }
        };
        // A factorisation that failed leaves no factor to keep: the next prediction factors B afresh.
        if refactored.is_err() {
            self.factored = None;
        }
        refactored
    }

    /// The last prediction's y = −M̂⁻¹Hᵀp: the step's velocity is v = v_free − y.
    pub(super) fn y(&self) -> &[f64] {
        &self.y[..self.factor.order()]
    }

    /// Put back the impulses the last prediction replaced.
    pub(super) fn restore(&self, p: &mut [f64]) {
        p.copy_from_slice(&self.saved);
    }
}

/// The factor of B refactored after the rows of the DOF `spans` (ascending) changed: from each run of
/// overlapping spans on, until the recomputed rows repeat their old values to the bit
/// ([`BandedLdlt::refactor_rows_from`] with drop 0) — from there on a full factorisation would give the old rows
/// again, so the factor is the full one's, bit for bit, at the cost of the rows the change reaches (the influence of a
/// section's spring on M̂'s factor fades within a few elements).
fn refactor_changed_rows(
    matrix: &SymmetricBanded,
    factor: &mut BandedLdlt,
    spans: &[(usize, usize)],
) -> crate::Result<()> {
    let mut reached = 0;
    let mut k = 0;
    while k < spans.len() {
        let (first, mut last) = spans[k];
        k += 1;
        while k < spans.len() && spans[k].0 <= last + 1 {
            last = last.max(spans[k].1);
            k += 1;
        }
        if last < reached {
            continue;
        }
        // Rows before `reached` were recomputed from the changed B already.
        reached = factor.refactor_rows_from(matrix, first.max(reached), last, 0.0)?;
    }
    Ok(())
}

#[cfg(test)]
#[path = "active_set_tests.rs"]
mod tests;
