//! A single-DOF Coulomb oscillator driven through the same stepper and solvers.

use banded::SymmetricBanded;
use friction::{InteractionKind, InteractionRow, InteractionSet, Law};
use nscd::forcing::{DofForce, Unloaded};
use nscd::solver::{SolverKind, SolverSettings};
use nscd::stepper::Integration;
use nscd::{Forcing, LinearSystem, MoreauJean};

fn scalar(value: f64) -> SymmetricBanded {
    let mut m = SymmetricBanded::zeros(1, 0);
    m.add(0, 0, value);
    m
}

/// Integrate m ẍ + k x ∈ f(t) − F_u Sign(ẋ) from (x₀, 0) and return the x history.
fn oscillator(
    mass: f64,
    stiffness: f64,
    force: f64,
    x0: f64,
    h: f64,
    steps: usize,
    kind: SolverKind,
    forcing: &dyn Forcing,
) -> Vec<(f64, f64)> {
    let system = LinearSystem { mass: scalar(mass), damping: scalar(0.0), stiffness: scalar(stiffness) };
    let mut interactions = InteractionSet::new();
    interactions.push(
        InteractionRow::from_entries([(0, 1.0)]),
        Law::Coulomb { capacity: force },
        InteractionKind::Friction,
    );
    let integration = Integration::theta(0.5, h);
    let settings = SolverSettings { kind, tolerance: 1e-12, ..SolverSettings::default() };
    let mut stepper = MoreauJean::build(&system, interactions, integration, &settings, vec![x0], vec![0.0]).unwrap();
    let mut out = vec![(0.0, x0)];
    for _ in 0..steps {
        stepper.step(forcing).unwrap();
        out.push((stepper.time, stepper.q()[0]));
        // The energy identity holds in the nonsmooth case too, up to the round-off accumulated over the steps.
        let scale = stepper.energy.initial.max(stepper.energy.load_work.abs());
        assert!(stepper.energy.residual().abs() <= 1e-10 * scale);
    }
    out
}

/// Free vibration loses 2F_u/k of amplitude per half cycle (4F_u/k per cycle) at the undamped period, and stops at
/// the first turning point with |k x| ≤ F_u.
#[test]
fn free_vibration_decays_linearly_and_sticks() {
    let (m, k, fu, x0) = (1.0, 100.0, 2.0, 1.01);
    let h = 1e-4;
    // Clarabel is left out: its interior-point "stuck" leaves ~1e-7 m of creep, which reads as extra turning points;
    // it is cross-checked on the beam instead.
    for kind in [SolverKind::Projection, SolverKind::InteriorPoint] {
        let history = oscillator(m, k, fu, x0, h, 100_000, kind, &Unloaded);
        // Turning points: local extrema of |x| where the motion reverses.
        let turns: Vec<(f64, f64)> = history
            .windows(3)
            .filter(|w| {
                let (d0, d1) = (w[1].1 - w[0].1, w[2].1 - w[1].1);
                d0 * d1 < 0.0
            })
            .map(|w| w[1])
            .collect();
        let decrement = 2.0 * fu / k;
        let period = 2.0 * std::f64::consts::PI * (m / k).sqrt();
        // 25 half cycles: |x| = 1.01 − 0.04 n until 0.01 ≤ F_u/k = 0.02, then stuck; the 24 reversals are turning
        // points, the 25th is where it stops.
        assert_eq!(turns.len(), 24, "{kind:?}: {} turning points, last {:?}", turns.len(), &turns[20..]);
        for (n, &(t, x)) in turns.iter().enumerate() {
            let expected = (x0 - decrement * (n + 1) as f64) * if n % 2 == 0 { -1.0 } else { 1.0 };
            // Turning points are sampled every h: |x| error O(h²ω²x) ≈ 1e-6; period error O((hω)²) ≈ 1e-6.
            assert!((x - expected).abs() < 2e-5, "{kind:?} turn {n}: {x} vs {expected}");
            assert!((t - (n + 1) as f64 * period / 2.0).abs() < 2.0 * h, "{kind:?} turn {n} at {t}");
        }
        let stuck = history.last().unwrap().1;
        assert!((stuck + 0.01).abs() < 2e-5, "{kind:?}: stuck at {stuck}");
        let stop = history.iter().rposition(|&(_, x)| (x - stuck).abs() > 1e-12).map(|i| history[i + 1].0).unwrap();
        // Near the stop the motion is O(h²) per step; the stop is resolved to a few steps.
        assert!((stop - 25.0 * period / 2.0).abs() < 4.0 * h, "{kind:?}: stops at {stop}");
        // Once stuck it stays (to the solver tolerance).
        let tail = &history[history.len() - 10_000..];
        assert!(tail.iter().all(|&(_, x)| (x - stuck).abs() < 1e-12), "{kind:?}: it moves after sticking");
    }
}

/// A block on a device (no spring) pushed by f(t) = c·t: stuck until c·t* = F_u, then
/// v = c(t − t*)²/(2m), x = x₀ + c(t − t*)³/(6m).
#[test]
fn ramp_forced_block_breaks_away_on_time() {
    let (m, fu, c) = (2.0, 3.0, 10.0);
    let h = 1e-4;
    let forcing = DofForce { dof: 0, force: move |t: f64| c * t };
    for kind in [SolverKind::Projection, SolverKind::InteriorPoint] {
        let history = oscillator(m, 0.0, fu, 0.5, h, 10_000, kind, &forcing);
        let t_star = fu / c;
        for &(t, x) in &history {
            let exact = 0.5 + if t > t_star { c * (t - t_star).powi(3) / (6.0 * m) } else { 0.0 };
            // Break-away time is resolved to one step: |Δx| ≤ ẋ·h plus O(h²) — well under 1e-4 m here.
            assert!((x - exact).abs() < 1e-4, "{kind:?} t = {t}: {x} vs {exact}");
        }
        assert!(history.iter().filter(|&&(t, _)| t < t_star - h).all(|&(_, x)| x == 0.5));
    }
}

/// A force that overflows or turns NaN stops the run with a NonFinite error at that step, before the energy ledger
/// takes the step in: the step finds it through ½vᵀMv + ½qᵀKq, which any ∞ or NaN in v or q reaches.
#[test]
fn non_finite_state_stops_the_run_at_its_step() {
    for (bad, label) in [(f64::NAN, "NaN"), (f64::MAX, "overflow"), (f64::INFINITY, "∞")] {
        let system = LinearSystem { mass: scalar(2.0), damping: scalar(0.0), stiffness: scalar(50.0) };
        let interactions = InteractionSet::new();
        let integration = Integration::theta(0.5, 1e-3);
        let settings = SolverSettings { kind: SolverKind::Projection, ..SolverSettings::default() };
        let mut stepper =
            MoreauJean::build(&system, interactions, integration, &settings, vec![0.1], vec![0.0]).unwrap();
        // Finite until t = 5 ms, then the bad value (f64::MAX·h² overflows the energy although q stays finite).
        let forcing = DofForce { dof: 0, force: move |t: f64| if t < 5e-3 - 1e-12 { 1.0 } else { bad } };
        let mut failure = None;
        for _ in 0..10 {
            if let Err(error) = stepper.step(&forcing) {
                failure = Some(error);
                break;
            }
        }
        match failure {
            Some(nscd::NscdError::NonFinite { step, .. }) => assert_eq!(step, 5, "{label}"),
            other => panic!("{label}: expected a NonFinite error, got {other:?}"),
        }
        let ledger = stepper.energy;
        assert!(ledger.current.is_finite() && ledger.load_work.is_finite(), "{label}: the ledger took the bad step");
        assert_eq!(stepper.steps, 4, "{label}");
    }
}
