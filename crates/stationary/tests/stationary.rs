//! The stationary solver against the closed forms and its own limits (docs/theory.md §14).

use analytic::reference::{InfiniteBeam, uic60_on_soft_soil};
use analytic::tensionless::TensionlessPointLoad;
use fem_beam::DistributedFriction;
use fem_beam::{Foundation, FoundationLaw};
use stationary::{ContactGuess, Convergence, Domain, StationaryProblem, solve, solve_from};

fn problem(law: FoundationLaw, damping_ratio: f64, speed: f64, load: f64) -> StationaryProblem {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { law, ..case.foundation.with_damping_ratio(damping_ratio, &case.beam).unwrap() };
    StationaryProblem {
        beam: case.beam,
        foundation,
        load,
        speed,
        self_weight: true,
        friction: DistributedFriction::default(),
        domain: Domain::default(),
    }
}

/// Undamped and without friction no power flows: the wave is symmetric, the load's power F v W′(0) is round-off
/// (5e-8 W at 100 m/s against F v max|W′| ≈ 1e5 W), and the balance says no imbalance — not the 100 % that a ratio
/// of round-offs gives.
#[test]
fn an_undamped_wave_without_friction_has_no_power_imbalance() {
    let wave = solve(&problem(FoundationLaw::Linear, 0.0, 100.0, 83.4e3)).unwrap();
    assert!(wave.convergence.is_converged());
    let scale = 83.4e3 * 100.0 * wave.slope.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    assert!(wave.load_power.abs() < 1e-9 * scale && scale > 1e4, "{} W of {scale} W", wave.load_power);
    assert_eq!(wave.power_imbalance(), 0.0);
}

/// Linear soil: the wave equals the closed form of the infinite beam (`frictrack analytic`) to 1e-4 of its peak at
/// sub- and supercritical speeds with damping — on any domain, the transparent ends being exact.
#[test]
fn the_linear_wave_is_the_closed_form() {
    let case = uic60_on_soft_soil();
    for (zeta, v) in [(0.05, 100.0), (0.05, 200.0), (0.1, 300.0), (0.02, 150.0)] {
        for domain in [Domain::default(), Domain { behind: 15.0, ahead: 10.0, element_length: 0.25 }] {
            let p = StationaryProblem { domain, ..problem(FoundationLaw::Linear, zeta, v, 83.4e3) };
            let wave = solve(&p).unwrap();
            assert!(matches!(wave.convergence, Convergence::Converged { iterations: 1, .. }), "{:?}", wave.convergence);
            let closed = InfiniteBeam::new(&case.beam, &p.foundation).unwrap().steady_state(v, 83.4e3).unwrap();
            let peak = wave.max_downward().value;
            let error =
                wave.s.iter().zip(&wave.deflection).map(|(s, w)| (w - closed.deflection(*s)).abs()).fold(0.0, f64::max);
            // Hermite elements of 0.25 m on waves of 10–20 m: measured 1e-7–1e-6 of the peak.
            assert!(error <= 1e-4 * peak, "ζ {zeta} v {v} domain {domain:?}: {error:e} of {peak:e}");
            // The steady state's power balance: the load's power goes into the dashpots, on the domain and beyond its
            // ends (measured ≤ 3e-7 on a 25 m domain, 1e-10 on 120 m).
            assert!(wave.power_imbalance().abs() <= 1e-6, "ζ {zeta} v {v}: {:e}", wave.power_imbalance());
        }
    }
}

/// A tensionless or bilinear soil the rail never leaves (a light load on the settled rail) is the linear soil: the
/// same wave to round-off, the Gauss sections' springs summing to the consistent foundation matrix.
#[test]
fn a_soil_the_rail_never_leaves_is_the_linear_soil() {
    for v in [0.0, 120.0, 250.0] {
        let linear = solve(&problem(FoundationLaw::Linear, 0.05, v, 1e3)).unwrap();
        for law in [FoundationLaw::Tensionless, FoundationLaw::Bilinear { tension_ratio: 0.3 }] {
            let wave = solve(&problem(law, 0.05, v, 1e3)).unwrap();
            assert!(wave.convergence.is_converged() && wave.lift_off.is_empty(), "{law:?} v {v}: {:?}", wave.lift_off);
            let peak = linear.max_downward().value;
            let error = wave.deflection.iter().zip(&linear.deflection).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            // Round-off of an LU of order ~1000 with condition ~1e8.
            assert!(error <= 1e-9 * peak, "{law:?} v {v}: {error:e}");
        }
    }
}

/// The static tensionless case without self-weight (v = 0): contact over π/β, the peak deflection and moment
/// coth(π/2) times the linear beam's — the closed form of analytic::tensionless.
#[test]
fn at_rest_without_weight_the_tensionless_wave_is_the_closed_form() {
    let case = uic60_on_soft_soil();
    let p = StationaryProblem { self_weight: false, ..problem(FoundationLaw::Tensionless, 0.0, 0.0, 83.4e3) };
    let wave = solve(&p).unwrap();
    assert!(wave.convergence.is_converged(), "{:?}", wave.convergence);
    let closed = TensionlessPointLoad::new(&InfiniteBeam::new(&case.beam, &case.foundation).unwrap(), 83.4e3).unwrap();
    let w0 = wave.under_load();
    assert!((w0 - closed.deflection(0.0)).abs() <= 1e-6 * w0.abs(), "{w0} vs {}", closed.deflection(0.0));
    let linear = solve(&problem(FoundationLaw::Linear, 0.0, 0.0, 83.4e3)).unwrap();
    let amplification = w0 / linear.under_load();
    assert!((amplification - TensionlessPointLoad::amplification()).abs() <= 1e-5, "{amplification}");
    let moment = wave.max_moment().value / linear.max_moment().value;
    // The moment at the load from the cubic's curvature: second order in the element, 1e-3 at 0.25 m.
    assert!((moment - TensionlessPointLoad::amplification()).abs() <= 2e-3, "{moment}");
    // Lifted on both sides beyond a = π/(2β): the two zones start within a Gauss spacing of ±a.
    let a = closed.contact_half_length();
    let (rear, front) = (wave.lift_off.first().unwrap(), wave.lift_off.last().unwrap());
    assert!((rear.to + a).abs() <= 0.15 && (front.from - a).abs() <= 0.15, "{rear:?} {front:?} a = {a}");
}

/// Continuation in speed: each speed starts from the last one's contact set and takes a few solves (measured 4.5 on
/// average for the bilinear soil over 10–300 m/s, 3 for the tensionless one up to 100 m/s); the soil is elastic,
/// so the load's power still goes into the dashpots alone.
#[test]
fn a_speed_sweep_costs_a_few_solves_per_speed() {
    let sweeps = [
        (FoundationLaw::Tensionless, (1..=20).map(|i| 5.0 * i as f64).collect::<Vec<_>>()),
        (FoundationLaw::Bilinear { tension_ratio: 0.5 }, (1..=30).map(|i| 10.0 * i as f64).collect()),
    ];
    for (law, speeds) in sweeps {
        let mut guess = ContactGuess::default();
        let mut solves = 0;
        for &v in &speeds {
            let wave = solve_from(&problem(law, 0.05, v, 83.4e3), &mut guess).unwrap();
            match wave.convergence {
                Convergence::Converged { iterations, residual } => {
                    solves += iterations;
                    assert!(residual <= stationary::newton::TOLERANCE, "{law:?} v {v}: {residual:e}");
                }
                other => panic!("{law:?} v {v}: {other:?}"),
            }
            // Quadrature at the soil's kinks (where the rail leaves the soil the spring force has a corner between
            // Gauss sections): worst measured 9.4e-5 over 5–100 m/s on 0.25 m elements, 3.5e-5 on 0.125 m, 3.9e-6
            // on 0.0625 m.
            assert!(wave.power_imbalance().abs() <= 2e-4, "{law:?} v {v}: {:e}", wave.power_imbalance());
        }
        assert!(solves <= 6 * speeds.len(), "{law:?}: {solves} solves for {} speeds", speeds.len());
    }
}

/// Past ~105 m/s the reference rail's lift-off zones (~10 m) on a tensionless soil are longer than the span a
/// compression ρAv² buckles, π√(EI/ρA)/v: no settled stationary wave is found, and the solver says so with its
/// residual — never a wave taken for the answer (the time-domain run shows the rail thrown off the soil).
#[test]
fn a_tensionless_wave_that_is_not_found_is_reported_as_such() {
    let wave = solve(&problem(FoundationLaw::Tensionless, 0.05, 150.0, 83.4e3)).unwrap();
    match wave.convergence {
        Convergence::NotConverged { iterations, residual } => {
            assert_eq!(iterations, stationary::newton::MAX_ITERATIONS);
            assert!(residual > 1e-4, "{residual:e}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn undamped_above_the_critical_speed_it_says_there_is_no_wave() {
    let err = solve(&problem(FoundationLaw::Linear, 0.0, 250.0, 83.4e3)).unwrap_err();
    assert!(err.to_string().contains("no stationary wave at v = 250 m/s"), "{err}");
    assert!(err.is_invalid_input());
}

/// The tensionless wave need not be unique: at 100 m/s (ζ = 5 %, with weight) the iteration started from the contact
/// set of a 300 kN load at 60 m/s ends on a second exact wave, 68.6 mm deep, besides the 61.5 mm one continuation in
/// speed from rest follows (and the co-moving window's time stepping reaches: 61.49 mm). Both solve the discrete
/// equations to round-off; which one a report gives is the branch its continuation follows (docs/theory.md §14).
#[test]
fn the_tensionless_wave_at_100_m_per_s_has_two_solutions() {
    let at = |load: f64, speed: f64| problem(FoundationLaw::Tensionless, 0.05, speed, load);
    let mut from_rest = ContactGuess::default();
    let mut followed = None;
    for v in (0..=10).map(|i| 10.0 * i as f64) {
        followed = Some(solve_from(&at(83.4e3, v), &mut from_rest).unwrap());
    }
    let followed = followed.unwrap();
    let mut heavy = ContactGuess::default();
    solve_from(&at(300e3, 60.0), &mut heavy).unwrap();
    let other = solve_from(&at(83.4e3, 100.0), &mut heavy).unwrap();
    for wave in [&followed, &other] {
        assert!(matches!(wave.convergence, Convergence::Converged { residual, .. } if residual <= 1e-10));
    }
    let (a, b) = (followed.max_downward().value, other.max_downward().value);
    assert!((a - 0.061521).abs() <= 1e-6 && (b - 0.068611).abs() <= 1e-6, "{a} {b}");
}
