//! The stationary wave by a semismooth Newton iteration on the soil's contact (docs/theory.md §14): with the set P
//! of sections pressed into the soil, solve (A + Σ_P k_s H_sᵀH_s) W = f, then P = {s : H_s W < 0}, until P repeats —
//! each iterate exact for its set, so the wave is exact when the set is (the soil's force is piecewise linear). A
//! linear soil is one solve. The domain grows where the rail leaves the soil at an end (the far field must be
//! pressed and linear for the transparent ends to hold), and a set that cycles or a domain that cannot hold the
//! lift-off says so — never a silent wrong wave.

use crate::error::Result;
use crate::operator::MovingFrame;
use crate::problem::{MAX_ELEMENTS, StationaryProblem};
use crate::wave::StationaryWave;

/// Most Newton iterations (each changes the pressed set; measured 2–6 from the previous speed's set).
pub const MAX_ITERATIONS: usize = 100;

/// Most doublings of the domain to hold the lift-off zones.
pub const MAX_EXTENSIONS: usize = 6;

/// How the iteration ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Convergence {
    /// The pressed set repeated: the wave solves the discrete equations to round-off.
    Converged {
        /// Newton iterations (solves).
        iterations: usize,
        /// ‖A W − p_soil(W) − f‖∞ / ‖f‖∞ of the wave.
        residual: f64,
    },
    /// The set kept changing (or cycled) for the iteration limit.
    NotConverged {
        /// Iterations taken.
        iterations: usize,
        /// Relative residual of the last iterate.
        residual: f64,
    },
    /// The rail still left the soil at an end of the largest domain tried.
    DomainTooShort {
        /// The domain's length behind and ahead of the load then (m).
        behind: f64,
        /// Ahead (m).
        ahead: f64,
    },
}

impl Convergence {
    /// Whether the wave is the solution.
    pub fn is_converged(&self) -> bool {
        matches!(self, Convergence::Converged { .. })
    }
}

/// The pressed set of one solve, to start the next speed's from (continuation in speed).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactGuess {
    pressed: Vec<bool>,
}

/// The stationary wave of `problem`, its domain grown where the rail lifts off at an end.
pub fn solve(problem: &StationaryProblem) -> Result<StationaryWave> {
    solve_from(problem, &mut ContactGuess::default())
}

/// As [`solve`], starting from `guess` (the previous speed's pressed set, if it fits) and leaving this one there.
pub fn solve_from(problem: &StationaryProblem, guess: &mut ContactGuess) -> Result<StationaryWave> {
    let mut problem = *problem;
    let mut extensions = 0;
    loop {
        let frame = MovingFrame::new(&problem)?;
        let (mut w, mut convergence) = newton(&frame, problem.speed, guess)?;
        if !convergence.is_converged() && !guess.pressed.is_empty() {
            // The last speed's set led astray: start again from the soil pressed everywhere.
            guess.pressed.clear();
            let (cold, status) = newton(&frame, problem.speed, guess)?;
            let taken = match (convergence, status) {
                (
                    Convergence::NotConverged { iterations, .. },
                    Convergence::Converged { iterations: more, residual },
                ) => Convergence::Converged { iterations: iterations + more, residual },
                (_, other) => other,
            };
            (w, convergence) = (cold, taken);
        }
        let mut wave = StationaryWave::new(&problem, &frame, w, convergence);
        // Free ends (a nonlinear soil without weight) may lift: the rail there carries nothing.
        let (behind, ahead) = if problem.has_free_ends() { (false, false) } else { wave.lifted_at_ends() };
        if !(behind || ahead) || !convergence.is_converged() {
            return Ok(wave);
        }
        let domain = &mut problem.domain;
        let grown = (domain.behind * if behind { 2.0 } else { 1.0 }, domain.ahead * if ahead { 2.0 } else { 1.0 });
        if extensions == MAX_EXTENSIONS || (grown.0 + grown.1) / domain.element_length > MAX_ELEMENTS as f64 {
            // The wave of the largest domain tried, said to be what it is.
            wave.convergence = Convergence::DomainTooShort { behind: domain.behind, ahead: domain.ahead };
            return Ok(wave);
        }
        (domain.behind, domain.ahead) = grown;
        extensions += 1;
        guess.pressed.clear();
    }
}

/// A relative residual at which the wave counts as solved when the pressed set has not repeated exactly (round-off
/// of the LU is ~1e-15 of the load).
pub const TOLERANCE: f64 = 1e-10;

/// The iteration on one domain, globalised by backtracking on ‖r‖₂ (the plain iteration cycles between sets that
/// differ in a section at the contact's edge): from W, the Newton point W_N of the set P(W), then W + t(W_N − W)
/// with t halved until the residual falls by 1e-4·t of itself. Returns (W, how it ended).
fn newton(frame: &MovingFrame, speed: f64, guess: &mut ContactGuess) -> Result<(Vec<f64>, Convergence)> {
    let m = frame.sections.len();
    let mut pressed = match guess.pressed.len() == m {
        true => guess.pressed.clone(),
        false => vec![true; m],
    };
    let newton_point = |pressed: &[bool]| -> Result<Vec<f64>> {
        let mut w = frame.rhs.clone();
        frame.factor_with(pressed, speed)?.solve_in_place(&mut w);
        Ok(w)
    };
    let mut w = newton_point(&pressed)?;
    let (mut norm, mut relative) = residual(frame, &w);
    for iteration in 1..=MAX_ITERATIONS {
        let next: Vec<bool> = frame.sections.iter().map(|s| s.deflection(&w) < 0.0).collect();
        // The residual decides: after a damped step the iterate is not its set's Newton point, so a repeated set
        // alone proves nothing (the next step takes that point).
        if relative <= TOLERANCE {
            guess.pressed = next;
            return Ok((w, Convergence::Converged { iterations: iteration, residual: relative }));
        }
        pressed = next;
        let target = newton_point(&pressed)?;
        let mut t = 1.0;
        loop {
            let trial: Vec<f64> = w.iter().zip(&target).map(|(a, b)| a + t * (b - a)).collect();
            let (trial_norm, trial_relative) = residual(frame, &trial);
            if trial_norm <= (1.0 - 1e-4 * t) * norm || t < 1e-6 {
                (w, norm, relative) = (trial, trial_norm, trial_relative);
                break;
            }
            t *= 0.5;
        }
    }
    Ok((w, Convergence::NotConverged { iterations: MAX_ITERATIONS, residual: relative }))
}

/// (‖r‖₂, ‖r‖∞/‖f‖∞) of r = A W − Σ H_sᵀ k_s⟨−H_s W⟩₊ − f.
fn residual(frame: &MovingFrame, w: &[f64]) -> (f64, f64) {
    let mut r = vec![0.0; w.len()];
    frame.matrix.mul_vec(w, &mut r);
    for s in &frame.sections {
        let force = s.stiffness * (-s.deflection(w)).max(0.0);
        let d = 2 * s.element;
        (0..4).for_each(|k| r[d + k] -= s.row[k] * force);
    }
    r.iter_mut().zip(&frame.rhs).for_each(|(r, f)| *r -= f);
    let scale = frame.rhs.iter().fold(0.0f64, |m, f| m.max(f.abs())).max(f64::MIN_POSITIVE);
    let two = r.iter().map(|x| x * x).sum::<f64>().sqrt();
    (two, r.iter().fold(0.0f64, |m, x| m.max(x.abs())) / scale)
}
