//! The moving window: re-solve only the sections within a reach of free DOFs of those whose previous impulses
//! violate the law, on the window's DOFs, with the rest of the beam condensed exactly by Schur complements; widen it, and at
//! last solve the whole problem, while any section fails the law (see the module documentation above).

use super::BandedInteriorPoint;
use super::iteration::Subproblem;
use crate::problem::responses::significant_range;
use crate::solver::InteractionProblem;
use banded::BandedLdlt;

/// The coupling a window leaves out: entries of a column of M̂⁻¹ at most this fraction of its largest are beyond
/// the window's reach. An impulse re-solved inside the window moves the velocity there by less than this fraction of
/// its effect at its own section — below the law tolerances runs use (≥ 1e-10 relative), and a window that fails
/// the final check on every section is widened anyway.
pub(super) const COUPLING_FLOOR: f64 = 1e-9;

/// The window's reach (free DOFs) for the factor of M̂: the largest distance |i − j| at which column j of M̂⁻¹
/// still exceeds [`COUPLING_FLOOR`] of its largest entry, over the columns a quarter, half and three quarters
/// along the DOFs (three banded solves, once per run). On a uniform beam it is the DOFs of ≈ 30 coupling lengths
/// ℓ = (EI h²θ²/ρA)^¼: the coupling decays like e^{−x/(√2ℓ)}, and e^{−30/√2} ≈ 6e-10.
pub(super) fn coupling_reach(factor: &BandedLdlt) -> usize {
    let n = factor.order();
    let mut column = vec![0.0; n];
    let mut reach = 0;
    for j in [n / 4, n / 2, 3 * n / 4].into_iter().filter(|&j| j < n) {
        column.iter_mut().for_each(|c| *c = 0.0);
        column[j] = 1.0;
        factor.solve_in_place(&mut column);
        let (first, last) = significant_range(&column, COUPLING_FLOOR, j);
        reach = reach.max(j.saturating_sub(first)).max(last.saturating_sub(j + 1));
    }
    reach
}

/// The first DOF t of a trailing block that holds the far DOFs of the moving rows that are not local (the wheels'
/// DOFs of the vehicles, stacked after the beam) and that M̂ does not couple to the DOFs before it: the largest t at
/// most the smallest such far DOF with M̂_ij = 0 for every j < t ≤ i. None without such rows or such a block.
pub(super) fn decoupled_tail(problem: &InteractionProblem) -> Option<usize> {
    let moving = &problem.interactions.rows()[problem.fixed_len()..];
    let m_hat = &problem.matrix.m_hat;
    let (n, b) = (m_hat.order(), m_hat.bandwidth());
    let far = moving.iter().filter(|r| !r.lies_in_band(b)).filter_map(|r| r.dof_span()).map(|(_, last)| last).min()?;
    let decoupled = |t: usize| (t..(t + b).min(n)).all(|i| (i.saturating_sub(b)..t).all(|j| m_hat.get(i, j) == 0.0));
    (1..=far).rev().find(|&t| decoupled(t))
}

/// Where the window places `row`: its first DOF before the tail (None when it has none there).
pub(super) fn place(row: &friction::InteractionRow, tail: Option<usize>) -> Option<usize> {
    row.dofs().first().copied().filter(|&d| tail.is_none_or(|t| d < t))
}

impl BandedInteriorPoint {
    /// Re-solve the sections within `reach` free DOFs of the ones violating the law (residuals in `self.check`, v
    /// in `self.v`), on the window's DOFs. Returns None when the window would be the whole problem.
    pub(super) fn solve_window(
        &mut self,
        problem: &InteractionProblem,
        p: &mut [f64],
        tolerance: f64,
        reach: usize,
        budget: usize,
    ) -> crate::Result<Option<usize>> {
        let rows = problem.interactions.rows();
        let (places, fixed) = (&self.places, problem.fixed_len());
        let beam_end = self.tail.unwrap_or(usize::MAX);
        // The moving rows are re-solved every step: always in the window, with their reach.
        let (mut lo, mut hi) = (usize::MAX, 0);
        for &j in &self.all_active {
            if let Some(place) = places[j]
                && (j >= fixed || problem.section_residual(j, self.check[j], p[j]) > tolerance)
            {
                lo = lo.min(place);
                hi = hi.max(place);
            }
        }
        let (lo, hi) = (lo.saturating_sub(reach), hi.saturating_add(reach));
        self.work.sections.index.clear();
        let (mut start, mut end) = (usize::MAX, 0);
        for &j in &self.all_active {
            if j >= fixed || places[j].is_some_and(|place| (lo..=hi).contains(&place)) {
                self.work.sections.index.push(j);
                for &d in rows[j].dofs().iter().filter(|&&d| d < beam_end) {
                    start = start.min(d);
                    end = end.max(d + 1);
                }
            }
        }
        let n = problem.matrix.m_hat.order();
        let bandwidth = problem.matrix.m_hat.bandwidth();
        if self.work.sections.index.len() == self.all_active.len() || end <= start {
            return Ok(None);
        }
        // The condensation needs the window wider than the band (and, with a tail, within the beam before it).
        let beam_end = beam_end.min(n);
        if end - start <= bandwidth {
            end = (start + bandwidth + 1).min(beam_end);
            start = end.saturating_sub(bandwidth + 1);
        }
        // v' = v − M̂⁻¹H_Wᵀp_W: the motion with the window's impulses removed; u_free of the window from it.
        self.correction.iter_mut().for_each(|x| *x = 0.0);
        for &j in &self.work.sections.index {
            rows[j].add_transpose(p[j], &mut self.correction);
        }
        problem.matrix.factor.solve_in_place(&mut self.correction);
        self.work.counts.solves += 1;
        let q = &mut self.work.sections;
        q.fit();
        for (u, &j) in q.u_free.iter_mut().zip(&q.index) {
            *u = rows[j].dot(&self.v) - rows[j].dot(&self.correction);
        }
        problem.matrix.m_hat.principal_submatrix_into(start, end, &mut self.window_matrix);
        if start > 0 {
            problem.matrix.factor.subtract_leading_schur(start, &mut self.window_matrix);
        }
        if end < n {
            self.backward.as_ref().expect("window factors").subtract_trailing_schur(end, &mut self.window_matrix);
        }
        // The tail is not coupled to the beam in M̂: its block joins the window as it is.
        let tail = self.tail.map(|first| (first, end - start));
        if let Some(first) = self.tail {
            self.window_matrix.append_decoupled_block(&problem.matrix.m_hat, first);
        }
        self.statistics.sections_solved += self.work.sections.index.len();
        self.v_current = false;
        let subproblem =
            Subproblem { problem, base: &self.window_matrix, offset: start, tail, tolerance, max_iterations: budget };
        let (iterations, _) = self.work.iterate(&subproblem, p)?;
        Ok(Some(iterations))
    }

    /// Window solves with growing reach (the final check on every section decides), then the whole problem; all
    /// of them together within `max_iterations`.
    pub(super) fn solve_windows(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
        tolerance: f64,
        reach: usize,
    ) -> crate::Result<(usize, f64)> {
        let mut iterations = 0;
        for widen in [1, 2, 4] {
            let budget = self.max_iterations - iterations;
            match self.solve_window(problem, p, tolerance, widen * reach, budget)? {
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
