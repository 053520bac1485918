//! The path search against Newton's waves, and the two measurements behind its place in the κ continuation
//! (`cargo test --release -p stationary --lib path_search -- --ignored --nocapture`, speeds in `PATH_SPEEDS`).

use super::*;
use crate::continuation::{WARM_STAGE, stages};
use crate::newton::{MAX_ITERATIONS, iterate};
use crate::problem::{Domain, StationaryProblem};
use crate::solve::solve_within;
use crate::status::ContactGuess;
use analytic::reference::uic60_on_soft_soil;
use fem_beam::{DistributedFriction, Foundation, FoundationLaw};

/// The undamped reference track with 1 kN/m of ballast friction, as the stationary-wave study's curve.
fn problem(speed: f64, domain: Domain) -> StationaryProblem {
    let case = uic60_on_soft_soil();
    StationaryProblem {
        beam: case.beam,
        foundation: Foundation { law: FoundationLaw::Linear, ..case.foundation },
        load: case.load,
        speed,
        self_weight: false,
        friction: DistributedFriction::new(1e3),
        domain,
    }
}

fn speeds(default: &[f64]) -> Vec<f64> {
    std::env::var("PATH_SPEEDS")
        .map(|s| s.split(',').map(|x| x.parse().expect("a speed")).collect())
        .unwrap_or_else(|_| default.to_vec())
}

/// max |ΔW| over the nodes (m).
fn largest_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).step_by(2).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
}

/// `frame` at `level`·κ.
fn at_level(frame: &MovingFrame, level: f64) -> MovingFrame {
    let mut stage = frame.clone();
    let friction = stage.friction.as_mut().expect("friction");
    friction.stiffness *= level;
    stage
}

/// At 196 m/s, from the wave at κ/10, Newton at κ takes 82 iterations (measured); the path reaches the same wave in
/// 14 flips and one Newton iteration. Both solve the equations to ROUND_OFF (1e-8 of the load); 1e-7 m is ~1e-6 of
/// the 0.2 m peak, 10× the largest gap measured between the two.
#[test]
fn from_the_last_stage_the_path_reaches_newtons_wave_in_fewer_factorisations() {
    let mut guess = ContactGuess::default();
    solve_within(&problem(195.0, Domain::default()), &mut guess, &Control::new(None)).unwrap();
    let frame = MovingFrame::new(&problem(196.0, Domain::default())).unwrap();
    let control = Control::new(None);
    let start = guess.wave(frame.rhs.len()).expect("the same domain").to_vec();
    let (lower, status) =
        stages(&at_level(&frame, 0.1), 196.0, start, WARM_STAGE * 10.0, (&mut guess, &control)).unwrap();
    assert!(status.is_converged(), "{status:?}");
    let (newton, by_newton) =
        iterate(&frame, 196.0, lower.clone(), (&mut guess.clone(), &control), MAX_ITERATIONS).unwrap();
    let out = path_search(&frame, 196.0, lower, PATH_FLIPS, &control).unwrap();
    assert_eq!(out.t, 1.0, "{out:?}");
    let (polished, status) = iterate(&frame, 196.0, out.w, (&mut guess.clone(), &control), MAX_ITERATIONS).unwrap();
    assert!(status.is_converged() && by_newton.is_converged(), "{status:?} {by_newton:?}");
    let difference = largest_difference(&polished, &newton);
    assert!(difference < 1e-7, "the path's wave is {difference:e} m from Newton's");
    let path_cost = out.events + status.iterations();
    assert!(path_cost * 2 < by_newton.iterations(), "path {path_cost}, Newton {}", by_newton.iterations());
}

/// From the last speed's wave straight at the full κ: flips, reversals and time against the κ continuation.
#[test]
#[ignore = "a measurement"]
fn from_the_last_speed() {
    let speeds = speeds(&[180.0, 181.0, 182.0]);
    let limit = std::env::var("PATH_LIMIT").map_or(50_000, |s| s.parse().expect("a count"));
    let (mut guess, mut domain) = (ContactGuess::default(), Domain::default());
    let first = solve_within(&problem(speeds[0], domain), &mut guess, &Control::new(None)).unwrap();
    (domain.behind, domain.ahead) = (-first.s[0], *first.s.last().unwrap());
    for pair in speeds.windows(2) {
        let next = problem(pair[1], domain);
        let frame = MovingFrame::new(&next).unwrap();
        let w0 = guess.wave(frame.rhs.len()).expect("same domain").to_vec();
        let clock = std::time::Instant::now();
        let control = Control::new(None);
        let out = path_search(&frame, pair[1], w0, limit, &control).unwrap();
        let (polished, status) =
            iterate(&frame, pair[1], out.w.clone(), (&mut guess.clone(), &control), MAX_ITERATIONS).unwrap();
        let spent = clock.elapsed();
        let clock = std::time::Instant::now();
        let wave = solve_within(&next, &mut guess, &Control::new(None)).unwrap();
        let newton = clock.elapsed();
        let difference = guess.wave(polished.len()).map(|n| largest_difference(n, &polished));
        println!(
            "{:5.1} m/s: path {} flips over {} sections ({} of no length), {} reversals, t = {:.4}, then {} Newton \
             iterations ({}), {:.1} ms | κ continuation {} iterations, {:.1} ms | max |ΔW| {difference:?} m",
            pair[1],
            out.events,
            out.flipped,
            out.degenerate,
            out.reversals,
            out.t,
            status.iterations(),
            if status.is_converged() { "converged" } else { "not converged" },
            spent.as_secs_f64() * 1e3,
            wave.convergence.iterations(),
            newton.as_secs_f64() * 1e3,
        );
        (domain.behind, domain.ahead) = (-wave.s[0], *wave.s.last().unwrap());
    }
}

/// Stage by stage of the κ continuation from the last speed's wave: Newton's iterations (a budget of 100) and the
/// path's flips from the last stage's wave.
#[test]
#[ignore = "a measurement"]
fn through_the_stages() {
    let speeds = speeds(&[210.0, 211.0]);
    let (mut guess, mut domain) = (ContactGuess::default(), Domain::default());
    let first = solve_within(&problem(speeds[0], domain), &mut guess, &Control::new(None)).unwrap();
    (domain.behind, domain.ahead) = (-first.s[0], *first.s.last().unwrap());
    let control = Control::new(None);
    for pair in speeds.windows(2) {
        let frame = MovingFrame::new(&problem(pair[1], domain)).unwrap();
        let w0 = guess.wave(frame.rhs.len()).expect("same domain").to_vec();
        let (mut by_path, mut by_newton) = (w0.clone(), w0);
        let (mut flips, mut iterations) = (Vec::new(), Vec::new());
        let mut level = WARM_STAGE;
        loop {
            let stage = at_level(&frame, level);
            let out = path_search(&stage, pair[1], by_path, 100_000, &control).unwrap();
            let (next, status) =
                iterate(&stage, pair[1], out.w, (&mut guess.clone(), &control), MAX_ITERATIONS).unwrap();
            flips.push((out.events, out.t, status.iterations()));
            by_path = next;
            let (next, status) =
                iterate(&stage, pair[1], by_newton, (&mut guess.clone(), &control), MAX_ITERATIONS).unwrap();
            iterations.push((status.iterations(), status.is_converged()));
            by_newton = next;
            if level >= 1.0 {
                break;
            }
            level = (level * 10.0).min(1.0);
        }
        println!(
            "{} m/s: path (flips, t, then Newton) {flips:?}; Newton (iterations, converged) {iterations:?}",
            pair[1]
        );
        let wave = solve_within(&problem(pair[1], domain), &mut guess, &Control::new(None)).unwrap();
        (domain.behind, domain.ahead) = (-wave.s[0], *wave.s.last().unwrap());
    }
}
