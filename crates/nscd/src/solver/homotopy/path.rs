//! One step of the homotopy: the start at τ = 0 from the anchor, the path to τ = 1 through its events, and the
//! polish of the final partition (see the module documentation above).

use super::corrections::Added;
use super::{Anchor, MAX_REPAIRS, ParametricActiveSet, Pending, Side};
use crate::solver::InteractionProblem;

/// A section found at τ = 1 past the side its status says by more than this fraction of its interval's width is
/// moved and the partition solved again; less is round-off, which the final clip absorbs.
const WRONG_SIDE: f64 = 1e-12;

impl ParametricActiveSet {
    /// The path's start: the previous step's solution if the impulses passed in are its own, else p_in with
    /// v⁰ = v_free + M̂⁻¹Hᵀp_in formed here (the first step, or one after a fallback solved the last).
    pub(super) fn take_anchor(&mut self, problem: &InteractionProblem, v_free: &[f64], p_in: &[f64]) -> Anchor {
        match self.anchor.take() {
            Some(anchor) if anchor.p.as_slice() == p_in => anchor,
            _ => {
                let (n, m) = (v_free.len(), p_in.len());
                let mut anchor = Anchor { v_free: v_free.to_vec(), v: vec![0.0; n], u: vec![0.0; m], p: p_in.to_vec() };
                problem.clamp_to_bounds(&mut anchor.p);
                problem.outcome(v_free, &anchor.p, &mut anchor.v, &mut anchor.u);
                self.work.solves += 1;
                anchor
            }
        }
    }

    /// Set the path's start from `anchor`: each section's side, q⁰ = p̄⁰ − γu⁰ and p̄¹ − p̄⁰ with p̄¹ = p⁰, and
    /// M̂(v_free − v_free⁰).
    pub(super) fn start(&mut self, problem: &InteractionProblem, v_free: &[f64], anchor: &Anchor) {
        let law = &problem.law;
        for j in 0..problem.len() {
            let (lo, hi, p, u) = (law.lower[j], law.upper[j], anchor.p[j], anchor.u[j]);
            let side = if lo == hi {
                Side::Fixed
            } else if p <= lo && u >= 0.0 {
                Side::Lower
            } else if p >= hi && u <= 0.0 {
                Side::Upper
            } else {
                Side::Band
            };
            if side != self.side[j] {
                self.side[j] = side;
                self.stale = true;
            }
            // In the band q⁰ = p̄⁰ − γu⁰ = p⁰; at a bound the shift stays p⁰ and q⁰ lies past the bound.
            let band = side == Side::Band;
            let shift = if band { p + self.gamma[j] * u } else { p };
            self.dshift[j] = if band { -self.gamma[j] * u } else { 0.0 };
            self.q[j] = shift - self.gamma[j] * u;
            self.tau_ref[j] = 0.0;
            self.dq[j] = 0.0;
            self.changed_at[j] = f64::NAN;
        }
        // Δ = v_free − v_free⁰ into the scratch `dv` (the segment overwrites it).
        for ((d, a), b) in self.dv.iter_mut().zip(v_free).zip(&anchor.v_free) {
            *d = a - b;
        }
        problem.matrix.m_hat.mul_vec(&self.dv, &mut self.base_rate);
    }

    /// Rebuild B = M̂ + Σ_band γ_j h_j h_jᵀ and factor it, if the partition or γ changed since the last time.
    fn refresh_b(&mut self, problem: &InteractionProblem) -> crate::Result<()> {
        if !self.stale {
            return Ok(());
        }
        self.b.copy_from(&problem.matrix.m_hat);
        for (j, row) in problem.interactions.rows().iter().enumerate() {
            if self.side[j] == Side::Band {
                self.b.add_outer(row.dofs(), row.values(), self.gamma[j]);
            }
        }
        self.b.factor_into(&mut self.b_factor)?;
        self.work.factorisations += 1;
        self.stale = false;
        Ok(())
    }

    /// Follow the path from τ = 0 to 1; returns the number of events (sections changing side), stopping early at
    /// the event budget. B₀ is factored at the start's partition (kept from the last step when it has not changed);
    /// each event adds its rank-one change to the Sherman–Morrison–Woodbury correction (`Corrections`) and
    /// updates the rates and event times of the sections its column touches; after [`super::MAX_CORRECTIONS`]
    /// events, or where the capacitance turns ill-conditioned, B₀ is factored afresh at the current partition.
    pub(super) fn follow_path(&mut self, problem: &InteractionProblem) -> crate::Result<usize> {
        let rows = problem.interactions.rows();
        let law = &problem.law;
        let (mut tau, mut events) = (0.0, 0);
        self.begin_segment(problem, tau)?;
        while events < self.max_events {
            let Some((t, j, queued)) = self.next_event() else { break };
            if t > 1.0 {
                break;
            }
            if queued {
                self.pending.pop();
            }
            tau = f64::max(tau, t);
            let (lo, hi) = (law.lower[j], law.upper[j]);
            let (side, edge, sign) = match self.side[j] {
                Side::Band if self.dq[j] < 0.0 => (Side::Lower, lo, -1.0),
                Side::Band => (Side::Upper, hi, -1.0),
                Side::Lower => (Side::Band, lo, 1.0),
                Side::Upper | Side::Fixed => (Side::Band, hi, 1.0),
            };
            self.side[j] = side;
            self.q[j] = edge;
            self.tau_ref[j] = tau;
            self.changed_at[j] = tau;
            self.stale = true;
            events += 1;
            let (order, first_dofs) = (&self.order, &self.first_dofs);
            let touching = |start: usize, end: usize| {
                first_dofs.partition_point(|&d| d + 3 < start)..first_dofs.partition_point(|&d| d < end)
            };
            let gamma = self.gamma[j];
            match self.corrections.push(j, &rows[j], (sign, gamma), &self.b_factor, rows, touching, order) {
                Added::Bordered => self.update_rates(j, tau, law),
                Added::Refactor => self.begin_segment(problem, tau)?,
            }
        }
        Ok(events)
    }

    /// The earliest event, if any: (τ, section, whether it is the queue's top). The sections the events' columns
    /// touch are recomputed at every event and kept out of the queue (their earliest is `union_next`); the queue
    /// holds the others, whose rates have not changed since the segment began (an entry is stale once its
    /// section's version moved on).
    fn next_event(&mut self) -> Option<(f64, usize, bool)> {
        let queued = loop {
            match self.pending.peek() {
                Some(top) if top.version != self.version[top.section] => {
                    self.pending.pop();
                }
                top => break top.map(|p| (p.time, p.section)),
            }
        };
        match (queued, self.union_next) {
            (Some((t, j)), Some((u, _))) if t < u => Some((t, j, true)),
            (_, Some((u, s))) => Some((u, s, false)),
            (Some((t, j)), None) => Some((t, j, true)),
            (None, None) => None,
        }
    }

    /// Start a segment at `tau`: B₀ factored at the current partition (if it changed), no correction, every q
    /// brought to `tau`, dv₀ = B₀⁻¹(M̂Δ + Σ_band h_j dp̄_j), du₀ = H dv₀, every rate and event time afresh.
    fn begin_segment(&mut self, problem: &InteractionProblem, tau: f64) -> crate::Result<()> {
        self.refresh_b(problem)?;
        self.corrections.clear();
        let rows = problem.interactions.rows();
        self.dv.copy_from_slice(&self.base_rate);
        for (j, row) in rows.iter().enumerate() {
            if self.side[j] == Side::Band {
                row.add_transpose(self.dshift[j], &mut self.dv);
            }
        }
        self.b_factor.solve_in_place(&mut self.dv);
        self.work.solves += 1;
        problem.interactions.velocities(&self.dv, &mut self.du);
        for &s in &self.union {
            self.in_union[s] = false;
        }
        self.union.clear();
        self.union_next = None;
        // The queue afresh, built in one O(m) heapify rather than m pushes.
        let mut pending = std::mem::take(&mut self.pending).into_vec();
        pending.clear();
        let law = &problem.law;
        for j in 0..problem.len() {
            self.q[j] += (tau - self.tau_ref[j]) * self.dq[j];
            self.tau_ref[j] = tau;
            self.du_extra[j] = 0.0;
            self.dq[j] = self.dshift[j] - self.gamma[j] * self.du[j];
            self.version[j] = self.version[j].wrapping_add(1);
            if let Some(time) = self.event_time(j, tau, law.lower[j], law.upper[j]) {
                pending.push(Pending { time, section: j, version: self.version[j] });
            }
        }
        self.pending = std::collections::BinaryHeap::from(pending);
        Ok(())
    }

    /// After the event of section `flipped` at `tau`: the new weights w, the rates of every section the events'
    /// columns touch (their q brought to `tau` first, with the rates they had), and their event times.
    fn update_rates(&mut self, flipped: usize, tau: f64, law: &crate::problem::StepLaw) {
        let Self { corrections, union, in_union, du_extra, q, tau_ref, dq, dshift, du, .. } = self;
        for &s in union.iter() {
            q[s] += (tau - tau_ref[s]) * dq[s];
            tau_ref[s] = tau;
            du_extra[s] = 0.0;
        }
        // A section outside the union has no correction yet (du_extra = 0).
        let mut enter = |s: usize| {
            if !in_union[s] {
                in_union[s] = true;
                union.push(s);
                q[s] += (tau - tau_ref[s]) * dq[s];
                tau_ref[s] = tau;
            }
        };
        enter(flipped);
        corrections.rates(dshift, du, |s, value| {
            enter(s);
            du_extra[s] += value;
        });
        let mut next: Option<(f64, usize)> = None;
        for k in 0..self.union.len() {
            let s = self.union[k];
            self.dq[s] = self.dshift[s] - self.gamma[s] * (self.du[s] + self.du_extra[s]);
            // Its queued time (if any) is stale from now on.
            self.version[s] = self.version[s].wrapping_add(1);
            if let Some(time) = self.event_time(s, tau, law.lower[s], law.upper[s])
                && next.is_none_or(|(t, _)| time < t)
            {
                next = Some((time, s));
            }
        }
        self.union_next = next;
    }

    /// When (in τ, from `tau` on) section j reaches the bound it moves towards on its side, if it does: in the band
    /// q_j reaching lo or hi, at a bound q_j coming back to it. A section that changed side at this very τ does not
    /// change back at it (a tie of round-off, not an event).
    fn event_time(&self, j: usize, tau: f64, lo: f64, hi: f64) -> Option<f64> {
        let (q, dq) = (self.q[j], self.dq[j]);
        let target = match self.side[j] {
            Side::Band if dq < 0.0 => lo,
            Side::Band if dq > 0.0 => hi,
            Side::Lower if dq > 0.0 => lo,
            Side::Upper if dq < 0.0 => hi,
            _ => return None,
        };
        let t = tau + ((target - q) / dq).max(0.0);
        (t > tau || self.changed_at[j] != tau).then_some(t)
    }

    /// Solve the final partition at τ = 1 exactly, B v = M̂ v_free + Σ_band h_j p̄¹_j + Σ_bound h_j p_j, move the
    /// sections found on the wrong side and solve again (at most [`MAX_REPAIRS`] rounds), and write p = clip(q)
    /// into `p`. Returns the repair rounds taken.
    pub(super) fn polish(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        anchor: &Anchor,
        p: &mut [f64],
    ) -> crate::Result<usize> {
        let rows = problem.interactions.rows();
        let law = &problem.law;
        let target = &anchor.p;
        let mut repairs = 0;
        loop {
            self.refresh_b(problem)?;
            problem.matrix.m_hat.mul_vec(v_free, &mut self.v);
            for (j, row) in rows.iter().enumerate() {
                let term = match self.side[j] {
                    Side::Band => target[j],
                    Side::Lower | Side::Fixed => law.lower[j],
                    Side::Upper => law.upper[j],
                };
                row.add_transpose(term, &mut self.v);
            }
            self.b_factor.solve_in_place(&mut self.v);
            self.work.solves += 1;
            problem.interactions.velocities(&self.v, &mut self.u);
            let mut wrong = false;
            for j in 0..problem.len() {
                let (lo, hi) = (law.lower[j], law.upper[j]);
                let q = target[j] - self.gamma[j] * self.u[j];
                self.q[j] = q;
                let slack = WRONG_SIDE * (hi - lo);
                let side = if q < lo - slack {
                    Side::Lower
                } else if q > hi + slack {
                    Side::Upper
                } else {
                    Side::Band
                };
                let moved = match self.side[j] {
                    Side::Fixed => false,
                    Side::Band => side != Side::Band,
                    Side::Lower => q > lo + slack,
                    Side::Upper => q < hi - slack,
                };
                if moved && repairs < MAX_REPAIRS {
                    self.side[j] = side;
                    self.stale = true;
                    wrong = true;
                }
            }
            if !wrong {
                break;
            }
            repairs += 1;
        }
        for j in 0..problem.len() {
            p[j] = match self.side[j] {
                Side::Fixed => law.lower[j],
                _ => self.q[j].clamp(law.lower[j], law.upper[j]),
            };
        }
        Ok(repairs)
    }
}
