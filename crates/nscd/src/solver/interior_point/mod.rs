//! A primal–dual interior-point method for the friction step whose Newton systems are banded: the solver built for
//! dense distributed friction (docs/theory.md §5), where Gauss–Seidel stalls because W = H M̂⁻¹ Hᵀ is singular.
//!
//! The step is the box QP min ½pᵀ(W + D)p + cᵀp, lo ≤ p ≤ hi (docs/theory.md §9). With slacks s₁ = hi − p,
//! s₂ = p − lo and multipliers z₁, z₂ ≥ 0 (velocities, m/s) the optimality conditions are
//!
//! ```text
//! (W + D) p + c + z₁ − z₂ = 0,   s₁∘z₁ = 0,   s₂∘z₂ = 0,   s, z ≥ 0
//! ```
//!
//! so r = (W + D)p + c = z₂ − z₁: a friction section at p_j = hi_j moves backwards, one at lo_j forwards, one inside
//! is stuck. Where hi = +∞ the upper pair is absent (z₁ = 0 and 1/s₁ = 0 throughout); interactions with lo = hi
//! this step (a contact out of the index set) are fixed at p = lo and left out.
//! Mehrotra predictor–corrector steps keep p strictly inside the box (the slacks s₁, s₂ are carried as variables:
//! near a bound, hi − p would lose all precision). Each Newton system (W + D + Σ)Δp = r, Σ = z₁/s₁ + z₂/s₂ > 0, is
//! solved without ever forming W, by the Woodbury identity (Σ' = Σ + D)
//!
//! ```text
//! B = M̂ + Hᵀ Σ'⁻¹ H  (banded, half-bandwidth 3: each row H_j touches one element),
//! y = B⁻¹ Hᵀ Σ'⁻¹ r,   Δp = Σ'⁻¹ (r − H y),   M̂⁻¹ Hᵀ Δp = y,
//! ```
//!
//! so one banded factorisation and two banded solves per iteration, O(n + m). The velocity correction
//! M̂⁻¹Hᵀp is carried along, so W p is never needed either. Redundant stuck sections (more sections than DOFs)
//! only make Σ⁻¹ large on them, which B absorbs. Iterates stop when the law residual meets the tolerance.
//! Sections with a zero capacity are fixed at p = 0 and left out.
//!
//! # The moving window
//! Far from the load nothing changes from one step to the next: stuck sections keep their impulses, and the
//! coupling through M̂⁻¹ decays like e^{−x/(√2ℓ)} with the coupling length ℓ = (EI h²θ²/ρA)^¼. So each step first
//! tries the previous impulses; the sections where they violate the law, widened by a reach of free DOFs beyond
//! which M̂⁻¹ couples less than 1e-9 (measured once per run on columns of M̂⁻¹: `window::coupling_reach`; about
//! 30ℓ on a beam), form the window. Only the window's impulses are re-solved, on the window's DOFs, with the rest of
//! the beam condensed exactly into the window matrix by Schur complements taken from the LDLᵀ factors of M̂ and of
//! M̂ reversed (S_W = M̂_WW − M̂_WO M̂_OO⁻¹ M̂_OW, whose inverse is the W block of M̂⁻¹). The law residual is then
//! checked on *every* section; should a section outside the window fail, the window is widened (2×, 4×) and at
//! last the whole problem is solved instead.
//! The answer is therefore exact to the same tolerance; only the cost depends on the window.

mod active_set;
mod extra_rows;
mod iteration;
mod sections;
mod terms;
mod window;

use super::{InteractionProblem, InteractionSolver, SolverKind, StepReport, StepStatus, StepWork};
use active_set::ActiveSet;
use banded::{BandedLdlt, SymmetricBanded};
use iteration::{Subproblem, Work};
use sections::Sections;

/// How the steps of a run were solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WindowStatistics {
    /// Steps where the previous impulses already satisfied the law.
    pub unchanged: usize,
    /// Steps of compliant supports and Coulomb sections solved from the previous step's active set (`active_set`).
    pub predicted: usize,
    /// Steps solved on a window.
    pub windowed: usize,
    /// Steps solved on the whole beam.
    pub full: usize,
    /// Sections re-solved, summed over the steps.
    pub sections_solved: usize,
}

/// Banded primal–dual interior-point solver with a moving window; scratch allocated once per run.
#[derive(Debug)]
pub struct BandedInteriorPoint {
    tolerance: f64,
    max_iterations: usize,
    /// The window's reach beyond the violating sections (free DOFs); None solves the whole problem every step.
    reach: Option<usize>,
    all_active: Vec<usize>,
    /// The first free DOF of each section's row before the tail (moving rows' refreshed every step): where the
    /// window places the section; None for a row wholly in the tail (a wheel off the beam).
    places: Vec<Option<usize>>,
    /// The first DOF of the block the moving rows' far DOFs sit in (the vehicles'), not coupled to the DOFs before it
    /// in M̂: a window takes it whole beside its beam range.
    tail: Option<usize>,
    backward: Option<BandedLdlt>,
    /// The active-set predictor, where every row lies in the band.
    active: Option<ActiveSet>,
    /// Whether it applies, once known for a law that does not vary between steps.
    active_applies: Option<bool>,
    window_matrix: SymmetricBanded,
    work: Work,
    v: Vec<f64>,
    correction: Vec<f64>,
    check: Vec<f64>,
    started: bool,
    /// Whether `v` is v_free + M̂⁻¹Hᵀp of the impulses as they now are (formed by the last full residual).
    v_current: bool,
    /// How the steps were solved.
    pub statistics: WindowStatistics,
}

impl BandedInteriorPoint {
    /// Scratch for `problem`. With `moving_window` each step re-solves only a window around the sections that
    /// change; without, always the whole problem.
    pub fn new(
        problem: &InteractionProblem,
        tolerance: f64,
        max_iterations: usize,
        moving_window: bool,
    ) -> crate::Result<Self> {
        let (n, m) = (problem.matrix.m_hat.order(), problem.len());
        let bandwidth = problem.matrix.m_hat.bandwidth();
        if !problem.interactions.rows()[..problem.fixed_len()].iter().all(|r| r.lies_in_band(bandwidth)) {
            return Err(crate::NscdError::Unsupported {
                solver: SolverKind::InteriorPoint,
                reason: "its banded Newton matrices take fixed rows of at most four DOFs within the band; \
                         longer fixed rows need projection or clarabel",
            });
        }
        // Moving rows that reach outside the band (a wheel's DOF) need that DOF's block decoupled from the beam for a
        // window to hold it; otherwise the whole problem every step.
        let tail = window::decoupled_tail(problem);
        let long_moving = problem.interactions.rows()[problem.fixed_len()..].iter().any(|r| !r.lies_in_band(bandwidth));
        let moving_window = moving_window && (tail.is_some() || !long_moving);
        let backward = match moving_window {
            true => Some(problem.matrix.m_hat.reversed().factor()?),
            false => None,
        };
        Ok(Self {
            tolerance,
            max_iterations,
            reach: moving_window.then(|| window::coupling_reach(&problem.matrix.factor)),
            all_active: (0..m).filter(|&j| problem.law.is_free(j)).collect(),
            places: problem.interactions.rows().iter().map(|r| window::place(r, tail)).collect(),
            tail,
            backward,
            active: ActiveSet::new(problem),
            active_applies: None,
            window_matrix: problem.matrix.m_hat.clone(),
            work: Work {
                sections: Sections::with_capacity(m),
                y: vec![0.0; n],
                dy: vec![0.0; n],
                b: problem.matrix.m_hat.clone(),
                b_factor: problem.matrix.factor.clone(),
                full: vec![0.0; n],
                counts: StepWork::default(),
            },
            v: vec![0.0; n],
            correction: vec![0.0; n],
            check: vec![0.0; m],
            started: false,
            v_current: false,
            statistics: WindowStatistics::default(),
        })
    }

    /// v = v_free + M̂⁻¹Hᵀp and the law residual of every section, into `self.check` (u) — one banded solve.
    fn full_residual(&mut self, problem: &InteractionProblem, v_free: &[f64], p: &[f64]) -> f64 {
        self.v_current = true;
        if problem.responses.is_none() {
            self.work.counts.solves += 1;
        }
        problem.outcome(v_free, p, &mut self.v, &mut self.check)
    }

    /// The step from the previous step's active set ([`active_set`]) when every free interaction is a compliant
    /// one-sided support or a Coulomb section: the active-set rounds it took and its law residual, if that meets the
    /// tolerance (`p` then holds the prediction), else None with `p` as it was.
    fn predict_active(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
        tolerance: f64,
    ) -> crate::Result<Option<(usize, f64)>> {
        // Whether the predictor applies is decided once for a law that does not vary between steps, or whose every
        // interaction's step bounds are the run's (a soil's sections, Coulomb sections).
        let applies = match self.active_applies {
            Some(applies) => applies,
            None => {
                let applies = ActiveSet::applies(problem);
                let settled = !problem.is_varying() || ActiveSet::applies_every_step(problem);
                self.active_applies = settled.then_some(applies);
                applies
            }
        };
        let Some(active) = self.active.as_mut().filter(|a| applies && a.worth_trying()) else {
            return Ok(None);
        };
        active.start(problem, p);
        for round in 1..=active_set::MAX_ROUNDS {
            let refactored = active.predict(problem, u_free, p, &mut self.check)?;
            self.work.counts.factorisations += usize::from(refactored);
            self.work.counts.solves += 1;
            // A set that moves is not the solution yet (a held section would slip or pull, one at a bound move the
            // wrong way): the next round, without the residual. A set that stays is, to round-off (held rigid
            // sections to their holding spring, which the next round on the same set shrinks): checked on every
            // section.
            if active.update(problem, &self.check, p) {
                continue;
            }
            let residual = problem.law_residual(&self.check, p);
            if residual <= tolerance {
                // A held rigid section's impulse is (H y − c)/ε_j + p̄_j: a difference of nearly equal velocities
                // times 1/ε_j ≈ 10⁶/W_jj, good to ~1e-9 of the impulse, not to round-off. v = v_free − y is that close
                // to v_free + M̂⁻¹Hᵀp only, which the energy identity shows (2.7e-6 J over the 5 kN/m reference run
                // at one section a node, against 5e-10 J); the stepper forms v from p instead (one solve).
                if !active.holds_rigid() {
                    for ((v, &free), &y) in self.v.iter_mut().zip(v_free).zip(active.y()) {
                        *v = free - y;
                    }
                    self.v_current = true;
                }
                active.record(true);
                self.statistics.predicted += 1;
                self.statistics.sections_solved += self.all_active.len();
                return Ok(Some((round, residual)));
            }
            if !active.holds_rigid() {
                break;
            }
        }
        // Back to the previous impulses, from which the interior point starts.
        active.record(false);
        active.restore(p);
        Ok(None)
    }

    fn solve_whole(
        &mut self,
        problem: &InteractionProblem,
        u_free: &[f64],
        p: &mut [f64],
        tolerance: f64,
        budget: usize,
    ) -> crate::Result<(usize, f64)> {
        self.v_current = false;
        self.statistics.full += 1;
        self.statistics.sections_solved += self.all_active.len();
        let q = &mut self.work.sections;
        q.index.clear();
        q.index.extend_from_slice(&self.all_active);
        q.fit();
        for (u, &j) in q.u_free.iter_mut().zip(&q.index) {
            *u = u_free[j];
        }
        let subproblem = Subproblem {
            problem,
            base: &problem.matrix.m_hat,
            offset: 0,
            tail: None,
            tolerance,
            max_iterations: budget,
        };
        self.work.iterate(&subproblem, p)
    }
}

impl InteractionSolver for BandedInteriorPoint {
    fn kind(&self) -> SolverKind {
        SolverKind::InteriorPoint
    }

    /// v of the final impulses when the last check formed it (every step but those solved on the whole beam).
    fn velocity(&self) -> Option<&[f64]> {
        self.v_current.then_some(self.v.as_slice())
    }

    /// The moving rows' places for the window.
    fn refresh(&mut self, problem: &InteractionProblem) -> crate::Result<()> {
        let rows = problem.interactions.rows();
        for j in problem.fixed_len()..rows.len() {
            self.places[j] = window::place(&rows[j], self.tail);
        }
        Ok(())
    }

    fn solve(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        self.v_current = false;
        self.work.counts = StepWork::default();
        if problem.is_varying() {
            // Interactions with lo = hi this step hold p = lo (the stepper clamped the warm start) and sit out.
            self.all_active.clear();
            self.all_active.extend((0..problem.len()).filter(|&j| problem.law.is_free(j)));
        }
        let solved_before = self.statistics.sections_solved;
        let first = !self.started;
        self.started = true;
        // A step of compliant supports and Coulomb sections tries the previous step's active set first; the interior
        // point takes the steps it cannot (and the first).
        let predicted = match first {
            true => None,
            false => self.predict_active(problem, v_free, u_free, p, tolerance)?,
        };
        let (iterations, residual) = match (predicted, self.reach) {
            (Some(solved), _) => solved,
            (None, Some(reach)) if !first => {
                let unchanged = self.full_residual(problem, v_free, p);
                if unchanged <= tolerance {
                    self.statistics.unchanged += 1;
                    (0, unchanged)
                } else {
                    self.solve_windows(problem, v_free, u_free, p, tolerance, reach)?
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
            fallback: None,
            work: self.work.counts,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::IterationMatrix;
    use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

    /// A beam-like step without a beam: M̂ assembled from diagonally dominant 4 × 4 blocks over (w, θ) pairs of
    /// `elements` elements (so SPD with half-bandwidth 3), and sections at the nodes and at ξ = ¼, ½, ¾ of every
    /// element with rows (1 − ξ, ξ(1 − ξ)/10, ξ, −ξ(1 − ξ)/10) over the element's four DOFs — about twice as many
    /// sections as DOFs, so W is singular as with distributed friction. Every seventh section is a compliant stop
    /// pressed in by 1 mm (one-sided, with compliance and drift), the others Coulomb of `capacity`.
    fn beam_like_problem(elements: usize, capacity: f64) -> InteractionProblem {
        let m_hat = beam_like_m_hat(elements);
        let mut interactions = InteractionSet::new();
        for e in 0..elements {
            let xis: &[f64] = if e + 1 == elements { &[0.0, 0.25, 0.5, 0.75, 1.0] } else { &[0.0, 0.25, 0.5, 0.75] };
            for &xi in xis {
                let bubble = 0.1 * xi * (1.0 - xi);
                let row = InteractionRow::from_entries(
                    [1.0 - xi, bubble, xi, -bubble].into_iter().enumerate().map(|(k, v)| (2 * e + k, v)),
                );
                let law = if interactions.len() % 7 == 3 {
                    Law::Compliant { gap: -1e-3, stiffness: 50.0 }
                } else {
                    Law::Coulomb { capacity }
                };
                let kind = if law.depends_on_state() { InteractionKind::Support } else { InteractionKind::Friction };
                interactions.push(row, law, kind);
            }
        }
        let integration = crate::Integration::theta(0.5, 1.0);
        InteractionProblem::with_matrix(interactions, IterationMatrix::of(m_hat, integration).expect("M̂ is SPD"))
            .expect("M̂ is SPD")
    }

    /// M̂ of a beam without a beam: diagonally dominant 4 × 4 blocks over the (w, θ) pairs of `elements` elements,
    /// SPD with half-bandwidth 3.
    pub(super) fn beam_like_m_hat(elements: usize) -> SymmetricBanded {
        let mut m_hat = SymmetricBanded::zeros(2 * (elements + 1), 3);
        let block = [[4.0, 0.5, 1.0, -0.3], [0.5, 4.0, 0.3, -0.1], [1.0, 0.3, 4.0, -0.5], [-0.3, -0.1, -0.5, 4.0]];
        for e in 0..elements {
            for i in 0..4 {
                for j in 0..=i {
                    m_hat.add(2 * e + i, 2 * e + j, block[i][j]);
                }
            }
        }
        m_hat
    }

    /// The window's reach is where M̂⁻¹ stops coupling: every column of M̂⁻¹ (not only the three it is measured on)
    /// is below 1e-9 of its largest entry beyond the reach, and the reach is short of the whole beam (the window
    /// saves work) yet longer than the band (it couples at all).
    #[test]
    fn the_window_reach_bounds_the_coupling_of_every_column() {
        let problem = beam_like_problem(100, 0.05);
        let factor = &problem.matrix.factor;
        let n = factor.order();
        let reach = window::coupling_reach(factor);
        assert!(reach > problem.matrix.m_hat.bandwidth() && reach < n / 2, "reach {reach} of {n} DOFs");
        let mut column = vec![0.0; n];
        let mut longest = 0;
        for j in 0..n {
            column.iter_mut().for_each(|c| *c = 0.0);
            column[j] = 1.0;
            factor.solve_in_place(&mut column);
            let largest = column.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            let beyond = column.iter().enumerate().filter(|&(i, _)| i.abs_diff(j) > reach);
            let (i, worst) = beyond.fold((j, 0.0f64), |w, (i, c)| if c.abs() > w.1 { (i, c.abs()) } else { w });
            assert!(worst <= window::COUPLING_FLOOR * largest, "column {j}: {worst:e} at DOF {i}");
            let inside = column.iter().enumerate().filter(|&(_, c)| c.abs() > window::COUPLING_FLOOR * largest);
            longest = longest.max(inside.map(|(i, _)| i.abs_diff(j)).max().unwrap_or(0));
        }
        // Measured on three columns, the reach is the longest of all to within a few DOFs (the end columns decay
        // on one side only).
        assert!(longest <= reach && reach <= longest + 4, "reach {reach}, longest coupling {longest}");
    }

    /// The AVX2 build of the iteration must give the same bits as the baseline build: same operations, same order,
    /// no fused multiply–add. A whole step of the beam-like problem with a wavy free velocity (stick and slip of both
    /// signs, and one-sided stops), solved by both. (Without AVX2 there is only the baseline build and nothing to
    /// compare.)
    #[test]
    fn avx2_and_baseline_iterations_agree_to_the_bit() {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            let problem = beam_like_problem(100, 0.05);
            let interactions = &problem.interactions;
            let m_hat = &problem.matrix.m_hat;
            let v_free: Vec<f64> = (0..m_hat.order()).map(|i| 0.3 * (0.05 * i as f64).sin() - 0.05).collect();
            let mut u_free = vec![0.0; interactions.len()];
            interactions.velocities(&v_free, &mut u_free);
            let tolerance = problem.absolute_tolerance(1e-8, &u_free);
            let subproblem =
                Subproblem { problem: &problem, base: m_hat, offset: 0, tail: None, tolerance, max_iterations: 200 };
            let solve = |avx2: bool| {
                let mut solver = BandedInteriorPoint::new(&problem, 1e-8, 200, false).expect("solver");
                let work = &mut solver.work;
                work.sections.index.extend(0..interactions.len());
                work.sections.fit();
                work.sections.u_free.copy_from_slice(&u_free);
                let mut p = vec![0.0; interactions.len()];
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
            let law = &problem.law;
            let slipping = (0..interactions.len())
                .filter(|&j| law.upper[j].is_finite() && baseline.1[j].abs() > 0.999 * law.upper[j])
                .count();
            let pressed =
                (0..interactions.len()).filter(|&j| law.upper[j].is_infinite() && baseline.1[j] > 0.0).count();
            assert!(slipping > 10 && slipping < interactions.len() - 10, "stick and slip: {slipping} slipping");
            assert!(pressed > 5, "one-sided stops in contact: {pressed}");
            assert_eq!(baseline.0, avx2.0);
            assert!(baseline.1.iter().zip(&avx2.1).all(|(a, b)| a.to_bits() == b.to_bits()));
        }
    }
}
