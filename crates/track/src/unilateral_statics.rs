//! The static deflection of the beam with the springs of its placed interactions (docs/theory.md §13): the linear
//! part K (bending and the foundation's tension stiffness) plus, per section s with a spring law of stiffness k_s
//! and gap g_s = g₀ₛ + H_s q, the force k_s⟨−g_s⟩₊ of a unilateral stop (k_s(−g_s) of a glued spring) on the beam:
//!
//! ```text
//! K q = f + f₀ + Σ_s H_sᵀ k_s ⟨−g₀ₛ − H_s q⟩₊
//! ```
//!
//! with f₀ the interactions' preload. The energy ½qᵀKq − (f + f₀)ᵀq + Σ ½k_s⟨−g_s⟩₊² is convex, so the solution is
//! unique where it is bounded; it is found by the primal–dual active-set (semismooth Newton) iteration: with the set
//! A of stops pressed in, solve (K + Σ_{A} k_s H_sᵀH_s) q = f + f₀ − Σ_{A} k_s g₀ₛ H_sᵀ, then A = {s : g_s < 0}, until
//! A repeats. Friction (no spring) plays no part at rest.

use crate::error::{Result, TrackError};
use crate::placed::PlacedInteractions;

/// Largest number of active-set iterations; each changes the set, and the sets seen are never revisited in practice
/// (measured: 3–8 on the reference track with self-weight and a point load).
pub const MAX_ITERATIONS: usize = 200;

/// The static deflection q (free DOFs of the beam, m) under `load` (N, free DOFs) and the preload of `placed`, with
/// its spring laws (compliant stops and glued springs) at their gaps.
pub fn static_deflection(model: &fem_beam::BeamModel, placed: &PlacedInteractions, load: &[f64]) -> Result<Vec<f64>> {
    StaticSolver::new(model, placed).solve(load)
}

/// The active-set iteration of [`static_deflection`] for one model and set of springs under many loads (a train at
/// every position of its crossing): each load starts from the set the last one ended with, and the matrix
/// K + Σ_A k_s H_sᵀH_s is factored only when the set differs from the one last factored — a load that moves the
/// contact set little costs one or two banded solves instead of a factorisation per iteration.
pub struct StaticSolver<'a> {
    model: &'a fem_beam::BeamModel,
    placed: &'a PlacedInteractions,
    /// (section j, stiffness k_s, gap g₀ₛ, glued) of every spring law.
    springs: Vec<(usize, f64, f64, bool)>,
    /// The set A the next iteration takes (all pressed at first).
    pressed: Vec<bool>,
    /// The set last factored, and its factor.
    factored: Option<(Vec<bool>, banded::BandedLdlt)>,
    /// Factorisations so far.
    factorisations: usize,
}

impl<'a> StaticSolver<'a> {
    /// The solver of `model` with the springs of `placed`.
    pub fn new(model: &'a fem_beam::BeamModel, placed: &'a PlacedInteractions) -> Self {
        let springs: Vec<(usize, f64, f64, bool)> = placed
            .interactions()
            .laws()
            .iter()
            .enumerate()
            .filter_map(|(j, law)| {
                let (stiffness, glued) = law.linear_spring()?;
                Some((j, stiffness, law.gap()?, glued))
            })
            .collect();
        let pressed = vec![true; springs.len()];
        Self { model, placed, springs, pressed, factored: None, factorisations: 0 }
    }

    /// The static deflection under `load` (N, free DOFs), from the set the last load ended with.
    pub fn solve(&mut self, load: &[f64]) -> Result<Vec<f64>> {
        let rows = self.placed.interactions().rows();
        let mut q = vec![0.0; load.len()];
        for _ in 0..MAX_ITERATIONS {
            q.copy_from_slice(load);
            for (p, f) in q.iter_mut().zip(self.placed.preload()) {
                *p += f;
            }
            for (&(j, k, gap, _), _) in self.springs.iter().zip(&self.pressed).filter(|(_, on)| **on) {
                rows[j].add_transpose(-k * gap, &mut q);
            }
            self.factor()?.solve_in_place(&mut q);
            let mut changed = false;
            for (&(j, _, gap, glued), on) in self.springs.iter().zip(self.pressed.iter_mut()) {
                let now = glued || gap + rows[j].dot(&q) < 0.0;
                changed |= now != *on;
                *on = now;
            }
            if !changed {
                return Ok(q);
            }
        }
        Err(TrackError::NoStaticEquilibrium {
            reason: format!(
                "the set of sections pressed into the soil still changed after {MAX_ITERATIONS} iterations"
            ),
        })
    }

    /// The banded factorisations the loads so far took.
    pub fn factorisations(&self) -> usize {
        self.factorisations
    }

    /// The factor of K + Σ_A k_s H_sᵀH_s for the current set A, factored only when A is not the set last factored.
    fn factor(&mut self) -> Result<&banded::BandedLdlt> {
        if self.factored.as_ref().is_none_or(|(set, _)| *set != self.pressed) {
            let rows = self.placed.interactions().rows();
            let mut matrix = self.model.stiffness().clone();
            for (&(j, k, _, _), _) in self.springs.iter().zip(&self.pressed).filter(|(_, on)| **on) {
                matrix.add_outer(rows[j].dofs(), rows[j].values(), k);
            }
            let factor = matrix.factor().map_err(|_| unheld())?;
            self.factored = Some((self.pressed.clone(), factor));
            self.factorisations += 1;
        }
        Ok(&self.factored.as_ref().expect("factored just now").1)
    }
}

fn unheld() -> TrackError {
    TrackError::NoStaticEquilibrium {
        reason: "the sections in contact with the soil and the supports do not hold the beam (it would lift off \
                 as a whole)"
            .into(),
    }
}

/// `placed` settled under `weight` (N, free DOFs of the beam; docs/theory.md §13, §18): the static state q_s under it
/// ([`static_deflection`]) on the laws touching at rest — a void (a law with a positive gap: a voided sleeper) is a
/// gap measured in the settled state, open there and carrying nothing —, each touching law's gap moved to what its row
/// reads there, g + H q_s (negative: the weight presses it), and the preload f₀ = P − K q_s that, with the laws'
/// forces at those gaps, holds q = 0 in equilibrium — the settled state a run reports deflections from. Returns the
/// settled interactions and q_s.
pub fn settle(
    model: &fem_beam::BeamModel,
    mut placed: PlacedInteractions,
    weight: &[f64],
) -> Result<(PlacedInteractions, Vec<f64>)> {
    let settled = static_deflection(model, &placed.without_voids(), weight)?;
    placed.shift_gaps(&settled);
    let mut preload = vec![0.0; settled.len()];
    model.stiffness().mul_vec(&settled, &mut preload);
    for (f, p) in preload.iter_mut().zip(weight) {
        *f = p - *f;
    }
    placed.add_preload(&preload);
    Ok((placed, settled))
}
