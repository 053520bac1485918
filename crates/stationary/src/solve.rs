//! The stationary wave by a semismooth Newton iteration on the soil's contact (docs/theory.md §14): with the set P
//! of sections pressed into the soil, solve (A + Σ_P k_s H_sᵀH_s) W = f, then P = {s : H_s W < 0}, until P repeats —
//! each iterate exact for its set, so the wave is exact when the set is (the soil's force is piecewise linear). A
//! linear soil is one solve. The domain grows where the rail leaves the soil at an end (the far field must be
//! pressed and linear for the transparent ends to hold), and a set that cycles or a domain that cannot hold the
//! lift-off says so — never a silent wrong wave.

use crate::continuation;
use crate::control::Control;
use crate::error::Result;
use crate::newton::{MAX_ITERATIONS, frictionless, iterate};
use crate::operator::MovingFrame;
use crate::problem::{MAX_ELEMENTS, StationaryProblem};
pub use crate::status::{ContactGuess, Convergence};
use crate::wave::StationaryWave;

/// Most doublings of the domain to hold the lift-off zones.
pub const MAX_EXTENSIONS: usize = 6;

/// The stationary wave of `problem`, its domain grown where the rail lifts off at an end. Elements that cannot
/// resolve the wave are refused ([`StationaryProblem::check_resolution`]).
pub fn solve(problem: &StationaryProblem) -> Result<StationaryWave> {
    solve_from(problem, &mut ContactGuess::default())
}

/// As [`solve`], starting from `guess` (the previous speed's pressed set, if it fits) and leaving this one there.
pub fn solve_from(problem: &StationaryProblem, guess: &mut ContactGuess) -> Result<StationaryWave> {
    solve_within(problem, guess, &Control::new(None))
}

/// As [`solve_from`], within `control`: [`crate::StationaryError::Interrupted`] at the first Newton iteration after
/// its stop flag is raised; a wave that did not converge (said so) once its budget of Newton iterations is spent.
pub fn solve_within(
    problem: &StationaryProblem,
    guess: &mut ContactGuess,
    control: &Control<'_>,
) -> Result<StationaryWave> {
    problem.validate()?;
    problem.check_resolution()?;
    let mut problem = *problem;
    let mut extensions = 0;
    loop {
        let frame = MovingFrame::new(&problem)?;
        let (mut w, mut convergence) = nonlinear_solve(&problem, &frame, (guess, control))?;
        if !convergence.is_converged() && !guess.is_empty() && frame.friction.is_none() && !control.exhausted() {
            // The last speed's set led astray: start again from the soil pressed everywhere (with friction the
            // continuation has started cold itself).
            guess.forget();
            let (cold, status) = nonlinear_solve(&problem, &frame, (guess, control))?;
            let taken = match (convergence, status) {
                (
                    Convergence::NotConverged { iterations, .. },
                    Convergence::Converged { iterations: more, residual },
                ) => Convergence::Converged { iterations: iterations + more, residual },
                (_, other) => other,
            };
            (w, convergence) = (cold, taken);
        }
        // With friction the wave starts the grown domain's solve, continued at its ends.
        let kept = frame.friction.is_some().then(|| w.clone());
        let mut wave = StationaryWave::new(&problem, &frame, w, convergence);
        // Free ends (a nonlinear soil without weight) may lift: the rail there carries nothing. With friction the
        // wave must have settled near both ends (the free rear and the transparent front are exact only there).
        let lifted = if problem.is_weightless_nonlinear() { (false, false) } else { wave.lifted_at_ends() };
        let unsettled = wave.unsettled_at_ends();
        let (mut behind, mut ahead) = (lifted.0 || unsettled.0, lifted.1 || unsettled.1);
        if !convergence.is_converged() {
            // With friction and free ends a domain too short for the wave may hold no consistent one: try a longer.
            if frame.friction.is_none() || control.exhausted() {
                return Ok(wave);
            }
            (behind, ahead) = (true, true);
        } else if !(behind || ahead) {
            return Ok(wave);
        }
        let before = problem.domain.elements();
        let domain = &mut problem.domain;
        let grown = (domain.behind * if behind { 2.0 } else { 1.0 }, domain.ahead * if ahead { 2.0 } else { 1.0 });
        if extensions == MAX_EXTENSIONS || (grown.0 + grown.1) / domain.element_length > MAX_ELEMENTS as f64 {
            // The wave of the largest domain tried, said to be what it is (or that it was not found).
            if convergence.is_converged() {
                wave.convergence = Convergence::DomainTooShort { behind: domain.behind, ahead: domain.ahead };
            }
            return Ok(wave);
        }
        (domain.behind, domain.ahead) = grown;
        extensions += 1;
        guess.forget();
        if let Some(w) = kept.filter(|_| convergence.is_converged()) {
            let after = problem.domain.elements();
            guess.set_wave(continued(&w, after.0 - before.0, after.1 - before.1));
        }
    }
}

/// The DOFs `w` continued by `behind` nodes at the rear and `ahead` at the front, each at its end's deflection
/// with zero slope (where a wave with friction has settled).
fn continued(w: &[f64], behind: usize, ahead: usize) -> Vec<f64> {
    let n = w.len();
    let mut out = Vec::with_capacity(n + 2 * (behind + ahead));
    (0..behind).for_each(|_| out.extend([w[0], 0.0]));
    out.extend_from_slice(w);
    (0..ahead).for_each(|_| out.extend([w[n - 2], 0.0]));
    out
}

/// The nonlinear solve on one domain: the semismooth Newton iteration on the soil's contact without friction, the
/// continuation in the friction's stiffness with it ([`continuation`]).
fn nonlinear_solve(
    problem: &StationaryProblem,
    frame: &MovingFrame,
    (guess, control): (&mut ContactGuess, &Control<'_>),
) -> Result<(Vec<f64>, Convergence)> {
    match frame.friction {
        None => {
            let start = frictionless(frame, problem.speed, guess)?;
            iterate(frame, problem.speed, start, (guess, control), MAX_ITERATIONS)
        }
        Some(_) => continuation::friction_wave(problem, frame, guess, control),
    }
}
