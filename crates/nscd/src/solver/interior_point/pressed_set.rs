//! The previous step's pressed set as the step's predictor, for a step whose every free interaction is a compliant
//! one-sided support — the sections of a tensionless or bilinear soil: lo = 0, hi = +∞, d > 0.
//!
//! Such a step is the box QP of the module above with no upper bounds. Once the set A of pressed sections (p_j > 0)
//! is known it is linear: p_I = 0 and (W_AA + D_A) p_A = −c_A with c = U_free + b, W = H M̂⁻¹ Hᵀ. By the Woodbury
//! identity (W_AA + D_A)⁻¹ = D_A⁻¹ − D_A⁻¹ H_A B⁻¹ H_Aᵀ D_A⁻¹ with B = M̂ + H_Aᵀ D_A⁻¹ H_A — M̂ with the pressed
//! sections' springs added, banded like M̂ —
//!
//! ```text
//! y = B⁻¹ H_Aᵀ D_A⁻¹ c_A,   p_j = (H_j y − c_j)/d_j  (j ∈ A),
//! ```
//!
//! one banded factorisation and one solve — and the step's velocity with it: B y = H_Aᵀ D_A⁻¹ c_A gives
//! M̂ y = −H_Aᵀ p_A, so v = v_free + M̂⁻¹Hᵀp = v_free − y without a second solve. From one step to the next the pressed set changes only at the edges of
//! the lift-off zones, so the previous step's set is nearly this step's. Starting from it, the primal–dual active
//! set update (Hintermüller, Ito & Kunisch 2002) A ← {j : p_j − r_j/(W_jj + d_j) > 0}, r = U + b + d·p the law
//! velocity, moves the few sections at the edges; once A is right the solution is exact (to round-off), accepted
//! when the law residual on every section meets the tolerance. Should the set not settle within [`MAX_ROUNDS`],
//! the step is solved by the interior point as before, from the previous impulses. (A soil's sections re-solved by
//! the interior point every step cost ten factorisations a step: a tensionless run 52× a linear one.)

use crate::integrator::IterationMatrix;
use crate::problem::InteractionProblem;
use banded::{BandedLdlt, BlockRows, SymmetricBanded};
use friction::Law;

/// Active-set rounds tried before the interior point takes the step.
pub(super) const MAX_ROUNDS: usize = 4;

/// Scratch of the predictor, allocated once per run.
#[derive(Debug)]
pub(super) struct PressedSet {
    /// Every row of H, four entries at a time.
    rows: BlockRows,
    matrix: SymmetricBanded,
    factor: BandedLdlt,
    /// 1/d_j on the pressed set, 0 elsewhere: B = M̂ + Hᵀ diag(weights) H.
    weights: Vec<f64>,
    /// 1/d_j of every section, and the compliances they were taken from.
    inverse_compliance: (Vec<f64>, Vec<f64>),
    /// The free pressed set B was last factored with, and of which M̂ (its address): a step whose set is the last
    /// factored one solves with that factor as it is.
    factored: Option<(Vec<bool>, *const IterationMatrix)>,
    /// The free pressed set of this prediction.
    free_pressed: Vec<bool>,
    /// c_j/d_j on the pressed set: the right-hand side is Hᵀ of it.
    scaled: Vec<f64>,
    /// y, with three entries past the order for the four-wide row products.
    y: Vec<f64>,
    /// H y.
    hy: Vec<f64>,
    /// The impulses before the prediction, restored when it fails.
    saved: Vec<f64>,
    /// The set A the next prediction takes.
    pressed: Vec<bool>,
    /// The DOF spans of the rows whose springs the last change of B added or took out.
    changed: Vec<(usize, usize)>,
}

impl PressedSet {
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
            free_pressed: vec![false; m],
            scaled: vec![0.0; m],
            y: vec![0.0; n + 3],
            hy: vec![0.0; m],
            saved: vec![0.0; m],
            pressed: vec![false; m],
            changed: Vec::with_capacity(m),
        })
    }

    /// Whether this step is one the predictor takes: every free interaction a compliant one-sided support of fixed
    /// compliance (no Hertz contact, whose compliance follows its linearisation).
    pub(super) fn applies(problem: &InteractionProblem) -> bool {
        let law = &problem.law;
        !problem.has_hertz()
            && (0..problem.len()).all(|j| {
                !law.is_free(j) || (law.lower[j] == 0.0 && law.upper[j] == f64::INFINITY && law.compliance[j] > 0.0)
            })
    }

    /// Whether every interaction is a compliant stop or a soil section — laws whose step bounds are (0, ∞) and whose
    /// compliance is the run's at every step — so that [`PressedSet::applies`] holds for the run once it holds.
    pub(super) fn applies_every_step(problem: &InteractionProblem) -> bool {
        !problem.has_hertz()
            && problem.interactions.laws().iter().all(|law| matches!(law, Law::Compliant { .. } | Law::Soil { .. }))
    }

    /// Start from the pressed set of `p` (p_j > 0), keeping `p` for [`PressedSet::restore`]; 1/d_j from the step's
    /// law.
    pub(super) fn start(&mut self, problem: &InteractionProblem, p: &[f64]) {
        let (inverse, of) = &mut self.inverse_compliance;
        if *of != problem.law.compliance {
            of.copy_from_slice(&problem.law.compliance);
            inverse.iter_mut().zip(of.iter()).for_each(|(i, d)| *i = 1.0 / d);
        }
        self.saved.copy_from_slice(p);
        for (pressed, &p) in self.pressed.iter_mut().zip(p) {
            *pressed = p > 0.0;
        }
    }

    /// The active-set update from the outcome of the last prediction (`u` = H v of its impulses `p`): A ← {j :
    /// p_j − r_j/(W_jj + d_j) > 0}, taken as p_j(W_jj + d_j) − r_j > 0; whether the set changed.
    pub(super) fn update(&mut self, problem: &InteractionProblem, u: &[f64], p: &[f64]) -> bool {
        let law = &problem.law;
        let mut changed = false;
        let terms = law.drift.iter().zip(&law.compliance).zip(law.lower.iter().zip(&law.upper));
        let state = u.iter().zip(p).zip(&problem.delassus_diagonal);
        for ((pressed, ((&u, &p), &w)), ((&b, &d), (lo, hi))) in self.pressed.iter_mut().zip(state).zip(terms) {
            if lo < hi {
                let now = p * w - (u + b + d * p) > 0.0;
                changed |= now != *pressed;
                *pressed = now;
            }
        }
        changed
    }

    /// Replace `p` by the solution on the current pressed set and its velocities U = U_free − H y into `u`
    /// (y = −M̂⁻¹Hᵀp: [`PressedSet::y`]); whether B was factored anew. `u_free` = H v_free.
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
        let sets = self.free_pressed.iter_mut().zip(&self.pressed);
        let weights = self.weights.iter_mut().zip(self.scaled.iter_mut());
        let c = u_free.iter().zip(&law.drift).map(|(u, b)| u + b);
        for ((((free_pressed, &pressed), (weight, scaled)), (lo, hi)), (c, &inverse)) in
            sets.zip(weights).zip(bounds).zip(c.zip(inverse.iter()))
        {
            *free_pressed = lo < hi && pressed;
            *weight = if *free_pressed { inverse } else { 0.0 };
            *scaled = *weight * c;
        }
        let m_hat = std::sync::Arc::as_ptr(&problem.matrix);
        let (rows, matrix) = (problem.interactions.rows(), &mut self.matrix);
        let refactored = match &mut self.factored {
            Some((set, of)) if *of == m_hat && *set == self.free_pressed => Ok(false),
            Some((set, of)) if *of == m_hat => {
                // B of the last set, with the springs of the sections that changed added or taken out: a few
                // outer products where the whole gram would cost all of them (as exact, to round-off of B), and
                // the factor's rows recomputed from each change on until they repeat to the bit.
                let changed = &mut self.changed;
                changed.clear();
                for (j, (was, &is)) in
                    set.iter_mut().zip(&self.free_pressed).enumerate().filter(|(_, (w, i))| **w != **i)
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
                self.factored = Some((self.free_pressed.clone(), m_hat));
                self.matrix.factor_into(&mut self.factor).map(|()| true).map_err(Into::into)
            }
        };
        // A factorisation that failed leaves no factor to keep: the next prediction factors B afresh.
        let refactored = match refactored {
            Ok(refactored) => refactored,
            Err(error) => {
                self.factored = None;
                return Err(error);
            }
        };
        let n = self.factor.order();
        self.rows.transpose_mul(&self.scaled, &mut self.y);
        self.factor.solve_in_place(&mut self.y[..n]);
        self.rows.mul(&self.y, &mut self.hy);
        let c = u_free.iter().zip(&law.drift).map(|(u, b)| u + b);
        let outcome = u.iter_mut().zip(p.iter_mut()).zip(u_free.iter().zip(&self.hy));
        let law_terms = c.zip(inverse.iter()).zip(law.lower.iter().zip(&law.upper)).zip(&self.pressed);
        for (((u, p), (u_free, hy)), (((c, inverse), (lo, hi)), &pressed)) in outcome.zip(law_terms) {
            *u = u_free - hy;
            if lo < hi {
                *p = if pressed { (hy - c) * inverse } else { 0.0 };
            }
        }
        Ok(refactored)
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
mod tests {
    use crate::integrator::IterationMatrix;
    use crate::problem::InteractionProblem;
    use crate::solver::InteractionSolver;
    use crate::solver::interior_point::BandedInteriorPoint;
    use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

    /// The beam-like M̂ of the interior point's tests on `elements` elements with a compliant support
    /// at ξ = 0, ¼, ½, ¾ of every element, pressed in by up to 1 mm along a wave: some pressed, some free.
    fn supports(elements: usize) -> InteractionProblem {
        let m_hat = super::super::tests::beam_like_m_hat(elements);
        let n = m_hat.order();
        let mut interactions = InteractionSet::new();
        for e in 0..elements {
            for xi in [0.0, 0.25, 0.5, 0.75] {
                let bubble = 0.1 * xi * (1.0 - xi);
                let row = InteractionRow::from_entries(
                    [1.0 - xi, bubble, xi, -bubble].into_iter().enumerate().map(|(k, v)| (2 * e + k, v)),
                );
                let gap = 1e-3 * (0.37 * interactions.len() as f64).sin();
                interactions.push(row, Law::Compliant { gap, stiffness: 50.0 }, InteractionKind::Support);
            }
        }
        let integration = crate::Integration::theta(0.5, 1e-2);
        let matrix = IterationMatrix::of(m_hat, integration).expect("M̂ is SPD");
        let mut problem = InteractionProblem::with_matrix(interactions, matrix).expect("M̂ is SPD");
        problem.update(0.0, &vec![0.0; n], &vec![0.0; n]);
        problem
    }

    /// The factor of B after a few sections' springs are added or taken out — in two runs far apart, and in two
    /// overlapping spans — is, refactored from the changes on until its rows repeat, the full factorisation of the
    /// changed B to the bit; and it stops short of the end (the change fades: the cost is local).
    #[test]
    fn the_local_refactor_is_the_full_factor_to_the_bit() {
        let mut b = super::super::tests::beam_like_m_hat(200);
        let mut factor = b.factor().expect("SPD");
        let springs = [((40, 43), 0.7), ((41, 44), 0.4), ((300, 303), 2.5)];
        for &((first, last), k) in &springs {
            let dofs: Vec<usize> = (first..=last).collect();
            b.add_outer(&dofs, &[1.0, 0.2, 0.5, -0.1], k);
        }
        let spans: Vec<(usize, usize)> = springs.iter().map(|s| s.0).collect();
        super::refactor_changed_rows(&b, &mut factor, &spans).expect("still SPD");
        assert_eq!(factor, b.factor().expect("SPD"), "the local refactor differs from the full one");
        // One more spring: its refactor ends within a few elements of it, not at the end of the 402 rows.
        b.add_outer(&[150, 151, 152, 153], &[1.0, 0.2, 0.5, -0.1], 3.0);
        let end = factor.refactor_rows_from(&b, 150, 153, 0.0).expect("SPD");
        assert!(end < 250, "the refactor after a change at row 150 ran to row {end}");
        assert_eq!(factor, b.factor().expect("SPD"));
    }

    /// A step of compliant supports alone, solved again from the last step's impulses with free velocities that moved
    /// (so its pressed set moves): the predictor takes it in a few active-set rounds and its impulses are the interior
    /// point's own on that step, to the solver tolerance (1e-10 of the velocity scale, times 1/min(W_jj + d_j): the
    /// impulse error a residual of that size allows).
    #[test]
    fn the_pressed_set_gives_the_interior_points_step() {
        let problem = supports(60);
        let (n, m) = (problem.matrix.m_hat.order(), problem.len());
        let free = |phase: f64| -> Vec<f64> { (0..n).map(|i| 0.02 * (0.11 * i as f64 + phase).sin() - 0.01).collect() };
        let velocities = |v: &[f64]| {
            let mut u = vec![0.0; m];
            problem.interactions.velocities(v, &mut u);
            u
        };
        let (v1, v2) = (free(0.0), free(0.3));
        let (u1, u2) = (velocities(&v1), velocities(&v2));
        // The interior point alone on the second step (a fresh solver solves its first step whole).
        let mut reference = vec![0.0; m];
        let mut whole = BandedInteriorPoint::new(&problem, 1e-10, 200, true).unwrap();
        whole.solve(&problem, &v2, &u2, &mut reference).unwrap();
        // The first step whole, the second by the predictor from the first's impulses.
        let mut solver = BandedInteriorPoint::new(&problem, 1e-10, 200, true).unwrap();
        let mut p = vec![0.0; m];
        solver.solve(&problem, &v1, &u1, &mut p).unwrap();
        let pressed_before: Vec<bool> = p.iter().map(|&x| x > 0.0).collect();
        let report = solver.solve(&problem, &v2, &u2, &mut p).unwrap();
        assert_eq!(solver.statistics.predicted, 1, "{:?}", solver.statistics);
        assert!(report.residual <= report.tolerance && report.iterations >= 2, "{report:?}");
        let moved = p.iter().zip(&pressed_before).filter(|&(&x, &was)| (x > 0.0) != was).count();
        let pressed = p.iter().filter(|&&x| x > 0.0).count();
        assert!(moved > 0 && pressed > 20 && pressed < m - 20, "{moved} moved, {pressed} of {m} pressed");
        let smallest = problem.delassus_diagonal.iter().fold(f64::INFINITY, |a, &w| a.min(w));
        let allowed = report.tolerance / smallest;
        for (j, (a, b)) in p.iter().zip(&reference).enumerate() {
            assert!((a - b).abs() <= allowed, "section {j}: {a} against {b} (allowed {allowed:e})");
        }
    }
}
