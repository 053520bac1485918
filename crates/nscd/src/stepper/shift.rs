//! Shifting the state along a uniform chain of identical blocks: the co-moving window of a load on an endless
//! uniform track (docs/theory.md §15). When the load has advanced one element, the window drops its rear element
//! and gains one at rest ahead — with M, C, K and the fixed interactions' layout translation-invariant, that is
//! the same system with its state moved by one node: q_i ← q_{i+d}, v_i ← v_{i+d}, the last d DOFs at rest, and in
//! each block of fixed interactions p_j ← p_{j+r}. The energy the dropped element carried leaves the window and the
//! new one brings none: E after − E before is booked as [`crate::EnergyLedger::transported`], so the identity
//! closes with it.

use super::MoreauJean;
use super::terms::{energies, spring_energy};
use crate::error::{NscdError, Result};
use crate::solver::SolverKind;

/// A block of fixed interactions that shifts with the state: its first index, its length, and how many
/// interactions one shift moves it by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShiftedBlock {
    /// First interaction of the block.
    pub start: usize,
    /// Interactions in the block.
    pub len: usize,
    /// Interactions per shift (per element).
    pub per_shift: usize,
}

/// Move `values[start..start + len]` down by `by`, the freed tail set to zero.
fn shift_down(values: &mut [f64], start: usize, len: usize, by: usize) {
    let block = &mut values[start..start + len];
    let by = by.min(len);
    block.copy_within(by.., 0);
    block[len - by..].iter_mut().for_each(|x| *x = 0.0);
}

/// One shift of a co-moving window: the chain's DOFs move down by `dofs` (one node's), the first `chain` DOFs of
/// the system being the chain (a coupled vehicle's DOFs after them do not move), each block of fixed interactions by
/// its `per_shift`, and the moving interactions (wheels) back by `distance` (m, one element) in the window.
#[derive(Debug, Clone, PartialEq)]
pub struct WindowShift<'a> {
    /// DOFs per shift (a node's).
    pub dofs: usize,
    /// The chain's DOFs, first in the system.
    pub chain: usize,
    /// The blocks of fixed interactions.
    pub blocks: &'a [ShiftedBlock],
    /// The element length (m): how far the moving interactions move back.
    pub distance: f64,
}

impl MoreauJean {
    /// Shift the state by `shift` between steps: the chain's rear node dropped, its new front node at rest, the
    /// fixed interactions' blocks with it, the moving interactions back by an element in the window (a vehicle's
    /// DOFs and its wheels' contact impulses stay: the vehicle rides on, the window moved under it). Refused with
    /// moving interactions that cannot follow a window and with the homotopy solver (it keeps a path that the shift
    /// would break).
    pub fn shift(&mut self, shift: &WindowShift<'_>) -> Result<()> {
        let moving_stay = self.problem.moving_follow_shifts();
        if !moving_stay || self.solver.kind() == SolverKind::Homotopy {
            return Err(NscdError::Unsupported {
                solver: self.solver.kind(),
                reason: "a co-moving window shifts fixed interactions and wheels that follow it, solved by \
                         projection, the interior point or clarabel",
            });
        }
        let chain = shift.chain.min(self.q.len());
        let before = self.energy.current;
        for x in [&mut self.q, &mut self.v, &mut self.v_prev] {
            shift_down(x, 0, chain, shift.dofs);
        }
        if let Some(rates) = self.rates.as_mut() {
            shift_down(&mut rates.q_rate, 0, chain, shift.dofs);
            shift_down(&mut rates.acceleration, 0, chain, shift.dofs);
            self.stiffness.mul_vec(&rates.q_rate, &mut rates.kq_rate);
            self.mass.mul_vec(&rates.acceleration, &mut rates.m_acceleration);
        }
        for block in shift.blocks {
            shift_down(&mut self.p, block.start, block.len, block.per_shift);
            shift_down(&mut self.u, block.start, block.len, block.per_shift);
        }
        self.problem.shift_moving_back(shift.distance);
        self.stiffness.mul_vec(&self.q, &mut self.kq);
        self.stiffness.mul_vec(&self.v, &mut self.kv);
        self.mass.mul_vec(&self.v, &mut self.mv);
        if self.damped {
            self.damping.mul_vec(&self.v, &mut self.cv);
        }
        let (kinetic, strain) = energies(&self.v, &self.mv, &self.q, &self.kq);
        let e = &mut self.energy;
        (e.kinetic, e.strain, e.current) = (kinetic, strain, kinetic + strain);
        e.transported += e.current - before;
        e.spring_energy = spring_energy(&self.problem, &self.q, None, &mut self.row_products);
        if self.problem.is_varying() {
            self.problem.update(self.time, &self.q, &self.v);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::shift_down;

    #[test]
    fn a_block_moves_down_and_its_tail_comes_to_rest() {
        let mut x = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
        shift_down(&mut x, 2, 4, 1);
        assert_eq!(x, [1.0, 2.0, 4.0, 5.0, 6.0, 0.0, 7.0]);
        shift_down(&mut x, 0, 7, 9);
        assert_eq!(x, [0.0; 7]);
    }
}
