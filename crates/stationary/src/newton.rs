//! The Newton iteration of the stationary wave on one domain (docs/theory.md §14): the soil's force and the
//! ballast's friction are piecewise affine in W, so for the sets of W (the sections pressed into the soil; each
//! friction section slipping or stuck, and to which anchor) the equations are linear and their solution — the Newton
//! point of every W with these sets — is one banded solve plus a small dense one. The iteration takes that point,
//! damped by backtracking on ‖r‖₂, until the residual vanishes or the sets reproduce themselves (then the point
//! *is* the solution, to the round-off of its solve).
//!
//! With friction the start matters (the stationary problem is not a convex minimisation, docs/theory.md §14.4): at
//! the full Jenkins stiffness a Newton point from a wrong set is wild (a stiff spring anchored where the rail does
//! not stay). So the stiffness is raised from the soil's by factors of ten, each stage starting from the last
//! stage's wave, the factor shrinking to its square root where a stage fails; a warm start (the previous speed's
//! wave) enters the stages at [`WARM_STAGE`].

use crate::error::Result;
use crate::friction::{AnchorCoupling, FrictionState};
use crate::operator::{MovingFrame, factor};
use crate::solve::{ContactGuess, Convergence};
use banded::general::GeneralBanded;

/// Most Newton iterations of one stage (each changes the sets; measured 2–6 from the previous speed's soil set, up
/// to 60 for a friction stage).
pub const MAX_ITERATIONS: usize = 100;

/// A relative residual at which the wave counts as solved when the pressed set has not repeated exactly (round-off
/// of the LU is ~1e-15 of the load).
pub const TOLERANCE: f64 = 1e-10;

/// A relative residual below which the sets' Newton point counts as the solution when its sets reproduce
/// themselves: the round-off of the Woodbury solve with stiff stuck springs (measured up to 3.5e-10).
pub const ROUND_OFF: f64 = 1e-8;

/// From a warm start (the previous speed's wave) the stages start at this fraction of the final stiffness:
/// measured over 30 speeds 10–300 m/s at 2 kN/m, 2524 iterations against 3115 from cold (1e-6: 2961; 1e-2:
/// 3275; at the full stiffness a neighbouring speed's wave fails above 170 m/s).
const WARM_STAGE: f64 = 1e-4;

/// The Jenkins stiffness starts at this fraction of its final value (κ/10⁶ = k_c: the soil's own stiffness).
const FIRST_STAGE: f64 = 1e-6;

/// The smallest factor between stages before a friction solve gives up.
const SMALLEST_FACTOR: f64 = 1.05;

/// The sets that make the soil's and the ballast's forces affine near W: the soil sections pressed into it, and
/// each friction section slipping or stuck (and to which anchor).
struct Sets {
    pressed: Vec<bool>,
    friction: Option<FrictionState>,
}

impl Sets {
    /// Whether `other` has the same pressed sections and the same friction states.
    fn same_as(&self, other: &Sets) -> bool {
        let states = |s: &Sets| s.friction.as_ref().map(|f| f.states.clone());
        self.pressed == other.pressed && states(self) == states(other)
    }

    fn of(frame: &MovingFrame, w: &[f64]) -> Self {
        Self {
            pressed: frame.sections.iter().map(|s| s.deflection(w) < 0.0).collect(),
            friction: frame.friction.as_ref().map(|f| f.march(w)),
        }
    }
}

/// The solution of the equations made affine by `sets` (the Newton point of every W with these sets): the banded
/// matrix with the pressed springs and stuck Jenkins springs, less each stick segment's rank-one coupling to its
/// anchor, by Sherman–Morrison–Woodbury: W = y + Z (I − VᵀZ)⁻¹ Vᵀy with y = B⁻¹g, Z = B⁻¹U, V the anchors' rows.
fn newton_point(frame: &MovingFrame, sets: &Sets, speed: f64) -> Result<Vec<f64>> {
    let mut matrix = frame.with_pressed(&sets.pressed);
    let mut y = frame.rhs.clone();
    let (couplings, sections) = match (&frame.friction, &sets.friction) {
        (Some(friction), Some(state)) => (friction.linearise(state, &mut matrix, &mut y), &friction.sections[..]),
        _ => (Vec::new(), &[][..]),
    };
    let lu = factor(matrix, speed)?;
    lu.solve_in_place(&mut y);
    if couplings.is_empty() {
        return Ok(y);
    }
    let k = couplings.len();
    let mut z = Vec::with_capacity(k);
    let mut anchors = Vec::with_capacity(k);
    for AnchorCoupling { mut column, anchor } in couplings {
        lu.solve_in_place(&mut column);
        z.push(column);
        anchors.push(sections[anchor]);
    }
    let mut small = GeneralBanded::zeros(k, k - 1, k - 1);
    for (j, anchor) in anchors.iter().enumerate() {
        for (m, column) in z.iter().enumerate() {
            small.add(j, m, if j == m { 1.0 } else { 0.0 } - anchor.deflection(column));
        }
    }
    let mut c: Vec<f64> = anchors.iter().map(|a| a.deflection(&y)).collect();
    factor(small, speed)?.solve_in_place(&mut c);
    for (column, c) in z.iter().zip(&c) {
        y.iter_mut().zip(column).for_each(|(y, z)| *y += c * z);
    }
    Ok(y)
}

/// The wave on `frame`: from the guess's wave when friction makes the start matter and it fits, else from the
/// frictionless wave of the guess's pressed set; with friction, through the stages of the Jenkins stiffness.
pub(crate) fn newton(frame: &MovingFrame, speed: f64, guess: &mut ContactGuess) -> Result<(Vec<f64>, Convergence)> {
    let frictionless = |guess: &ContactGuess| -> Result<Vec<f64>> {
        let pressed =
            guess.pressed(frame.sections.len()).map_or_else(|| vec![true; frame.sections.len()], <[bool]>::to_vec);
        newton_point(frame, &Sets { pressed, friction: None }, speed)
    };
    let Some(friction) = &frame.friction else {
        return iterate(frame, speed, frictionless(guess)?, guess, MAX_ITERATIONS);
    };
    let mut spent = 0;
    let target = friction.stiffness;
    let (start, from) = match guess.wave(frame.rhs.len()) {
        Some(warm) => (warm.to_vec(), target * WARM_STAGE),
        None => (frictionless(guess)?, target * FIRST_STAGE),
    };
    let mut stage = frame.clone();
    let set_stiffness = |stage: &mut MovingFrame, k: f64| stage.friction.as_mut().expect("friction").stiffness = k;
    let (mut w, mut reached, mut factor) = (start, from, 10.0);
    set_stiffness(&mut stage, reached);
    loop {
        let stiffness = (reached * factor).min(target);
        let last = w.clone();
        set_stiffness(&mut stage, stiffness);
        let (next, status) = iterate(&stage, speed, w, guess, MAX_ITERATIONS)?;
        spent += status.iterations();
        match status {
            Convergence::Converged { residual, .. } if stiffness >= target => {
                return Ok((next, Convergence::Converged { iterations: spent, residual }));
            }
            Convergence::Converged { .. } => (w, reached) = (next, stiffness),
            _ if factor.sqrt() >= SMALLEST_FACTOR => (w, factor) = (last, factor.sqrt()),
            Convergence::NotConverged { residual, .. } => {
                return Ok((next, Convergence::NotConverged { iterations: spent, residual }));
            }
            other => return Ok((next, other)),
        }
    }
}

/// One stage: the iteration from `w`, globalised by backtracking on ‖r‖₂ (the plain iteration cycles between sets
/// that differ in a section at a zone's edge): the Newton point W_N of the sets of W, then W + t(W_N − W) with t
/// halved until the residual falls by 1e-4·t of itself.
fn iterate(
    frame: &MovingFrame,
    speed: f64,
    mut w: Vec<f64>,
    guess: &mut ContactGuess,
    limit: usize,
) -> Result<(Vec<f64>, Convergence)> {
    let (mut norm, mut relative) = residual(frame, &w);
    for iteration in 1..=limit {
        let sets = Sets::of(frame, &w);
        // The residual decides: after a damped step the iterate is not its sets' Newton point, so repeated sets
        // alone prove nothing (the next step takes that point).
        if relative <= TOLERANCE {
            guess.remember(sets.pressed, &w);
            return Ok((w, Convergence::Converged { iterations: iteration, residual: relative }));
        }
        let target = newton_point(frame, &sets, speed)?;
        let (target_norm, target_relative) = residual(frame, &target);
        let reproduced = Sets::of(frame, &target);
        if target_relative <= ROUND_OFF && reproduced.same_as(&sets) {
            guess.remember(reproduced.pressed, &target);
            return Ok((target, Convergence::Converged { iterations: iteration, residual: target_relative }));
        }
        let mut t = 1.0;
        let mut trial_point = (target, target_norm, target_relative);
        loop {
            if trial_point.1 <= (1.0 - 1e-4 * t) * norm || t < 1e-6 {
                (w, norm, relative) = trial_point;
                break;
            }
            t *= 0.5;
            let trial: Vec<f64> = w.iter().zip(&trial_point.0).map(|(a, b)| a + 0.5 * (b - a)).collect();
            let (n, r) = residual(frame, &trial);
            trial_point = (trial, n, r);
        }
    }
    Ok((w, Convergence::NotConverged { iterations: limit, residual: relative }))
}

/// (‖r‖₂, ‖r‖∞/‖f‖∞) of r = A W − Σ H_sᵀ k_s⟨−H_s W⟩₊ + Σ_i weight_i H_iᵀ r_i(W) − f.
fn residual(frame: &MovingFrame, w: &[f64]) -> (f64, f64) {
    let mut r = vec![0.0; w.len()];
    frame.matrix.mul_vec(w, &mut r);
    for s in &frame.sections {
        let force = s.stiffness * (-s.deflection(w)).max(0.0);
        let d = 2 * s.element;
        (0..4).for_each(|k| r[d + k] -= s.row[k] * force);
    }
    if let Some(friction) = &frame.friction {
        friction.add_forces(&friction.march(w).force, &mut r);
    }
    r.iter_mut().zip(&frame.rhs).for_each(|(r, f)| *r -= f);
    let scale = frame.rhs.iter().fold(0.0f64, |m, f| m.max(f.abs())).max(f64::MIN_POSITIVE);
    let two = r.iter().map(|x| x * x).sum::<f64>().sqrt();
    (two, r.iter().fold(0.0f64, |m, x| m.max(x.abs())) / scale)
}
