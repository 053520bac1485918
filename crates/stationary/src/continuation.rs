//! Leading the Newton iteration to a wave with ballast friction (docs/theory.md §14.4). The stationary problem with
//! friction is not a convex minimisation, and at the full Jenkins stiffness κ a Newton point from wrong section
//! states is wild (a stiff spring anchored where the rail does not stay). Two continuations lead there:
//!
//! - **in κ**: from the soil's own stiffness up by factors of ten (or the problem's own), each stage from the last
//!   stage's wave, the factor shrinking to its square root where a stage fails; a warm start (the previous speed's
//!   wave) enters at [`WARM_STAGE`]; a stage after a settled one that Newton does not settle within
//!   [`NEWTON_BUDGET`] iterations is taken by Ralph's path from the settled stage ([`crate::path_search`]);
//! - **in damping**, where that fails on a lightly damped track (undamped above the critical speed the frictionless
//!   start is a resonance of the free-ended domain, not a wave): the whole κ continuation on the track with
//!   ζ = [`DAMPED_START`], then the damping lowered step by step ([`DAMPING_STEPS`]) to the track's own, each from
//!   the last one's wave. Measured: undamped at 210 and 250 m/s with 2 and 10 kN/m, the peaks move smoothly with ζ
//!   (2 kN/m at 250 m/s: 90.1 mm at ζ = 5 %, 99.5 at 0.1 %, 99.7 undamped).

use crate::control::Control;
use crate::error::Result;
use crate::newton::{MAX_ITERATIONS, SetProblem, frictionless, iterate};
use crate::operator::MovingFrame;
use crate::problem::StationaryProblem;
use crate::status::{ContactGuess, Convergence};

/// From a warm start (the previous speed's wave) the κ stages start at this fraction of the final stiffness:
/// measured over 30 speeds 10–300 m/s at 2 kN/m, 2524 iterations against 3115 from cold (1e-6: 2961; 1e-2: 3275;
/// at the full stiffness a neighbouring speed's wave fails above 170 m/s).
pub const WARM_STAGE: f64 = 1e-4;

/// From cold the κ stages start at this fraction (κ/10⁶ = k_c, the soil's own stiffness).
pub const FIRST_STAGE: f64 = 1e-6;

/// Newton iterations a κ stage from a settled stage gets before the path search takes it (where the problem has
/// one, [`crate::path_search`]). Measured over 195–215 m/s undamped with 1 kN/m (factorisations, time): budgets of
/// 10, 20, 30, 40 gave 4468 (7.63 s), 4652 (7.13 s), 4835 (8.23 s), 4951 (8.16 s), against 10 162 (20.2 s) with
/// Newton alone.
pub const NEWTON_BUDGET: usize = 20;

/// The smallest factor between κ stages before a continuation gives up.
pub const SMALLEST_FACTOR: f64 = 1.05;

/// The damping ratio the damping continuation starts from (its κ continuation converges at every speed measured).
pub const DAMPED_START: f64 = 0.05;

/// The damping ratios it passes on the way down to the track's own (those above it).
pub const DAMPING_STEPS: [f64; 6] = [0.05, 0.02, 0.01, 0.005, 0.002, 0.001];

/// The wave with friction on `frame` (of `problem`): warm, cold, then through the damping (see the module doc).
pub(crate) fn friction_wave(
    problem: &StationaryProblem,
    frame: &MovingFrame,
    guess: &mut ContactGuess,
    control: &Control<'_>,
) -> Result<(Vec<f64>, Convergence)> {
    let speed = problem.speed;
    let mut spent = 0;
    if let Some(warm) = guess.wave(frame.rhs.len()).map(<[f64]>::to_vec) {
        // The same speed's wave on another mesh (an error estimate's halving) starts at the full stiffness.
        let from = if guess.is_same_speed() { 1.0 } else { WARM_STAGE };
        match stages(frame, speed, warm, from, (guess, control))? {
            (w, Convergence::Converged { iterations, residual }) => {
                return Ok((w, Convergence::Converged { iterations: spent + iterations, residual }));
            }
            (_, failed) => spent += failed.iterations(),
        }
    }
    let cold = frictionless(frame, speed, guess)?;
    let (w, status) = stages(frame, speed, cold, FIRST_STAGE, (guess, control))?;
    spent += status.iterations();
    let critical = problem.foundation.critical_damping(&problem.beam);
    let own = problem.foundation.damping / critical;
    if status.is_converged() || own >= DAMPED_START || control.exhausted() {
        return Ok((w, with_iterations(status, spent)));
    }
    // From ζ = DAMPED_START down to the track's own, each stage from the last one's wave.
    let (mut wave, mut last) = (None::<Vec<f64>>, status);
    for ratio in DAMPING_STEPS.iter().copied().filter(|&z| z > own).chain([own]) {
        let damped = StationaryProblem {
            foundation: fem_beam::Foundation { damping: ratio * critical, ..problem.foundation },
            ..*problem
        };
        let frame = MovingFrame::new(&damped)?;
        let (next, status) = match wave.take() {
            Some(w) => stages(&frame, speed, w, WARM_STAGE, (guess, control))?,
            None => {
                let start = frictionless(&frame, speed, guess)?;
                stages(&frame, speed, start, FIRST_STAGE, (guess, control))?
            }
        };
        spent += status.iterations();
        if !status.is_converged() {
            return Ok((next, with_iterations(status, spent)));
        }
        (wave, last) = (Some(next), status);
    }
    Ok((wave.unwrap_or(w), with_iterations(last, spent)))
}

pub(crate) fn with_iterations(status: Convergence, iterations: usize) -> Convergence {
    match status {
        Convergence::Converged { residual, .. } => Convergence::Converged { iterations, residual },
        Convergence::NotConverged { residual, .. } => Convergence::NotConverged { iterations, residual },
        other => other,
    }
}

/// The κ continuation from `w`, starting at `from`·κ.
pub(crate) fn stages<P: SetProblem>(
    frame: &P,
    speed: f64,
    mut w: Vec<f64>,
    from: f64,
    (guess, control): (&mut ContactGuess, &Control<'_>),
) -> Result<(Vec<f64>, Convergence)> {
    let mut stage = frame.clone();
    let target = stage.friction_mut().map_or(0.0, |f| f.stiffness);
    let set_stiffness = |stage: &mut P, k: f64| {
        if let Some(f) = stage.friction_mut() {
            f.stiffness = k;
        }
    };
    let (mut reached, mut factor, mut spent) = (from * target, frame.stage_factor(), 0);
    // Whether `w` is a settled stage of this speed: the path search starts only from one.
    let mut settled = false;
    loop {
        let stiffness = (reached * factor).min(target);
        let last = w.clone();
        set_stiffness(&mut stage, stiffness);
        let by_path = settled && stage.takes_path();
        let budget = if by_path { NEWTON_BUDGET } else { MAX_ITERATIONS };
        let (mut next, mut status) = iterate(&stage, speed, w, (&mut *guess, control), budget)?;
        spent += status.iterations();
        if !status.is_converged() && by_path && !control.exhausted() {
            // Ralph's path from the settled stage, then Newton from its end (one iteration where its flips' round-off
            // leaves the states right).
            let (end, flips) = stage.path(last.clone(), speed, control)?;
            spent += flips;
            if let Some(end) = end {
                (next, status) = iterate(&stage, speed, end, (&mut *guess, control), MAX_ITERATIONS)?;
                spent += status.iterations();
            }
        }
        settled |= status.is_converged();
        match status {
            Convergence::Converged { .. } if stiffness >= target => return Ok((next, with_iterations(status, spent))),
            Convergence::Converged { .. } => (w, reached) = (next, stiffness),
            _ if factor.sqrt() >= SMALLEST_FACTOR && !control.exhausted() => (w, factor) = (last, factor.sqrt()),
            other => return Ok((next, with_iterations(other, spent))),
        }
    }
}
