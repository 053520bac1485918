//! The Newton iteration of the stationary wave on one domain (docs/theory.md §14): the soil's force and the
//! ballast's friction are piecewise affine in W, so for the sets of W (the sections pressed into the soil; each
//! friction section slipping or stuck, and to which anchor) the equations are linear and their solution — the Newton
//! point of every W with these sets — is one banded solve plus a small dense one. The iteration takes that point,
//! damped by backtracking on ‖r‖₂, until the residual vanishes or the sets reproduce themselves (then the point
//! *is* the solution, to the round-off of its solve).
//! With friction the start matters: [`crate::continuation`] leads the iteration there.

use crate::control::Control;
use crate::error::Result;
use crate::friction::FrictionSections;
use crate::operator::MovingFrame;
use crate::path_search::{PATH_FLIPS, path_search};
use crate::sets::residual;
pub(crate) use crate::sets::{SetSystem, Sets};
use crate::status::{ContactGuess, Convergence};

/// Most Newton iterations of one stage (each changes the sets; measured 2–6 from the previous speed's soil set, up
/// to 60 for a friction stage).
pub const MAX_ITERATIONS: usize = 100;

/// The factor between the κ continuation's stages a problem starts with unless it asks for its own (the friction
/// across the two-beam track's ballast, [`crate::ground::BALLAST_STAGE_FACTOR`]).
pub const STAGE_FACTOR: f64 = 10.0;

/// A relative residual at which the wave counts as solved when the pressed set has not repeated exactly (round-off
/// of the LU is ~1e-15 of the load).
pub const TOLERANCE: f64 = 1e-10;

/// The relative residual at which a wave with friction counts as solved, and below which the sets' Newton point
/// counts as the solution when its sets reproduce themselves: the round-off of the Woodbury solve with stiff stuck
/// springs (κ·weight ~25× the beam's largest entry; measured floors 1e-12–1e-8, sets flipping at sections whose
/// trial force is ±f_u to round-off). 1e-8 of the load is 0.8 mN on any DOF.
pub const ROUND_OFF: f64 = 1e-8;

/// What the Newton iteration needs of a problem whose forces are piecewise affine in W: the track on a Winkler soil
/// ([`MovingFrame`]) or on the ground (`crate::ground`).
pub(crate) trait SetProblem: Clone {
    /// The residual of `w` and the sets it lies in.
    fn evaluate(&self, w: &[f64]) -> Evaluation;
    /// The solution of the equations made affine by `sets`.
    fn newton_point(&self, sets: &Sets, speed: f64) -> Result<Vec<f64>>;
    /// The ballast's sections, if it has friction (their Jenkins stiffness is what the continuation raises).
    fn friction_mut(&mut self) -> Option<&mut FrictionSections>;
    /// Whether the ballast has friction.
    fn has_friction(&self) -> bool;
    /// The factor between the κ continuation's first stages.
    fn stage_factor(&self) -> f64 {
        STAGE_FACTOR
    }
    /// Whether [`Self::path`] can lead to this problem's wave (a track with friction on a linear soil).
    fn takes_path(&self) -> bool {
        false
    }
    /// Ralph's path from `w` ([`crate::path_search`]): where it reached the wave, that point (to the round-off of
    /// its flips) and the flips it passed; None where it gave up or the problem has no path.
    fn path(&self, _w: Vec<f64>, _speed: f64, _control: &Control<'_>) -> Result<(Option<Vec<f64>>, usize)> {
        Ok((None, 0))
    }
}

impl SetProblem for MovingFrame {
    fn evaluate(&self, w: &[f64]) -> Evaluation {
        evaluate(self, w)
    }

    fn newton_point(&self, sets: &Sets, speed: f64) -> Result<Vec<f64>> {
        let mut system = SetSystem::new(self, sets, speed)?;
        let mut w = std::mem::take(&mut system.rhs);
        system.solve_in_place(&mut w);
        Ok(w)
    }

    fn friction_mut(&mut self) -> Option<&mut FrictionSections> {
        self.friction.as_mut()
    }

    fn has_friction(&self) -> bool {
        self.friction.is_some()
    }

    fn takes_path(&self) -> bool {
        self.friction.is_some() && self.sections.is_empty()
    }

    fn path(&self, w: Vec<f64>, speed: f64, control: &Control<'_>) -> Result<(Option<Vec<f64>>, usize)> {
        if !self.takes_path() {
            return Ok((None, 0));
        }
        let out = path_search(self, speed, w, PATH_FLIPS, control)?;
        Ok(((out.t == 1.0).then_some(out.w), out.events))
    }
}

/// The wave without friction for the guess's pressed set (all pressed if it does not fit): one solve.
pub(crate) fn frictionless(frame: &MovingFrame, speed: f64, guess: &ContactGuess) -> Result<Vec<f64>> {
    let sections = frame.sections.len();
    let pressed = guess.pressed(sections).map_or_else(|| vec![true; sections], <[bool]>::to_vec);
    frame.newton_point(&Sets { pressed, friction: None }, speed)
}

/// One stage: the iteration from `w`, globalised by backtracking on ‖r‖₂ (the plain iteration cycles between sets
/// that differ in a section at a zone's edge): the Newton point W_N of the sets of W, then W + t(W_N − W) with t
/// halved until the residual falls by 1e-4·t of itself.
pub(crate) fn iterate<P: SetProblem>(
    frame: &P,
    speed: f64,
    mut w: Vec<f64>,
    (guess, control): (&mut ContactGuess, &Control<'_>),
    limit: usize,
) -> Result<(Vec<f64>, Convergence)> {
    let Evaluation { mut norm, mut relative, mut sets } = frame.evaluate(&w);
    let tolerance = if frame.has_friction() { ROUND_OFF } else { TOLERANCE };
    for iteration in 1..=limit {
        if !control.next_iteration(w.len())? {
            return Ok((w, Convergence::NotConverged { iterations: iteration - 1, residual: relative }));
        }
        // The residual decides: after a damped step the iterate is not its sets' Newton point, so repeated sets
        // alone prove nothing (the next step takes that point).
        if relative <= tolerance {
            guess.remember(sets.pressed, &w);
            return Ok((w, Convergence::Converged { iterations: iteration, residual: relative }));
        }
        let target = frame.newton_point(&sets, speed)?;
        let at_target = frame.evaluate(&target);
        if at_target.relative <= ROUND_OFF && at_target.sets.same_as(&sets) {
            guess.remember(at_target.sets.pressed, &target);
            return Ok((target, Convergence::Converged { iterations: iteration, residual: at_target.relative }));
        }
        let mut t = 1.0;
        let mut trial_point = (target, at_target);
        loop {
            if trial_point.1.norm <= (1.0 - 1e-4 * t) * norm || t < 1e-6 {
                let (trial, at_trial) = trial_point;
                (w, norm, relative, sets) = (trial, at_trial.norm, at_trial.relative, at_trial.sets);
                break;
            }
            if !control.next_iteration(w.len())? {
                return Ok((w, Convergence::NotConverged { iterations: iteration, residual: relative }));
            }
            t *= 0.5;
            let trial: Vec<f64> = w.iter().zip(&trial_point.0).map(|(a, b)| a + 0.5 * (b - a)).collect();
            let at_trial = frame.evaluate(&trial);
            trial_point = (trial, at_trial);
        }
    }
    Ok((w, Convergence::NotConverged { iterations: limit, residual: relative }))
}

/// The residual of a W and the sets it lies in, from one pass over the soil's and the ballast's sections.
pub(crate) struct Evaluation {
    /// ‖r‖₂ of r = A W − Σ H_sᵀ k_s⟨−H_s W⟩₊ + Σ_i weight_i H_iᵀ r_i(W) − f (N), or the problem's own residual.
    pub(crate) norm: f64,
    /// ‖r‖∞/‖f‖∞.
    pub(crate) relative: f64,
    /// The sets of W (the friction march's forces with them).
    pub(crate) sets: Sets,
}

fn evaluate(frame: &MovingFrame, w: &[f64]) -> Evaluation {
    let sets = Sets::of(frame, w);
    let r = residual(frame, w, sets.friction.as_ref().map(|state| &state.force[..]));
    let scale = frame.rhs.iter().fold(0.0f64, |m, f| m.max(f.abs())).max(f64::MIN_POSITIVE);
    let norm = r.iter().map(|x| x * x).sum::<f64>().sqrt();
    Evaluation { norm, relative: r.iter().fold(0.0f64, |m, x| m.max(x.abs())) / scale, sets }
}
