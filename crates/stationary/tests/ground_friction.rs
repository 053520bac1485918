//! Ballast friction under a load on the ground ([`stationary::solve_on_ground`], docs/theory.md §19.9) checked where
//! its answer is known: on a Winkler line support it is the finite-element stationary solver's wave (a second,
//! independent method: a banded Hermite mesh with free ends, against the exact Fourier-integral kernel applied by FFT
//! with GMRES), and its limits — friction too weak to matter, friction too strong to let the rail move.

mod common;

use analytic::ground::GroundedBeam;
use fem_beam::{Axle, Beam, Foundation};
use stationary::{
    ContactGuess, Control, FrictionTrack, GroundFrictionProblem, GroundFrictionWave, GroundWindow, solve_on_ground,
};

/// The reference rail on its Winkler soil with 5 % of critical damping.
fn winkler_track() -> (Beam, Foundation) {
    let beam = Beam::default();
    let mut foundation = Foundation::default();
    foundation.damping = 0.05 * foundation.critical_damping(&beam);
    (beam, foundation)
}

/// One load `force` (N) at `speed` on the line support `foundation` with friction `friction` (N/m), on 481 points
/// 0.25 m apart from 60 m behind the load to 60 m ahead, preconditioned by the same Winkler operator.
fn on_line_support(beam: &Beam, foundation: &Foundation, speed: f64, force: f64, friction: f64) -> GroundFrictionWave {
    let grounded = GroundedBeam::new(beam, foundation).unwrap();
    let spectrum = grounded.spectrum(speed).unwrap();
    let axles = [Axle { offset: 0.0, force }];
    let problem = GroundFrictionProblem {
        track: FrictionTrack::Composite(&spectrum),
        axles: &axles,
        speed,
        window: GroundWindow { first: -60.0, step: 0.25, count: 481 },
        friction_force: friction,
        local: (*beam, *foundation),
    };
    solve_on_ground(&problem, &mut ContactGuess::default(), &Control::new(None)).unwrap()
}

fn largest(values: &[f64]) -> f64 {
    values.iter().fold(0.0f64, |m, w| m.max(w.abs()))
}

/// Below and above the critical speed (~170 m/s on this track), 2 and 5 kN/m: the two methods' deflections at the
/// shared nodes agree to 2e-4 of the peak (observed 2.0e-5 and 7.2e-5: the window's Jenkins sections give 1e-6 of
/// the linear peak where the mesh's give 1e-12, a difference that shifts each slip zone's start and the level the
/// rail is held at behind; with equal κ the two agreed to 1.4e-6, the spectrum's tolerance and the Hermite mesh's
/// nodal error at 0.25 m) everywhere but the last 10 m behind, where the windows differ by design —
/// the mesh ends free there, the window's track goes on without friction (on a Winkler soil the rail behind is held
/// at its residual deflection by a force the window leaves out; on the ground that force dies out instead).
#[test]
fn on_a_winkler_line_support_it_is_the_finite_element_wave() {
    let (beam, foundation) = winkler_track();
    for (speed, friction) in [(50.0, 2000.0), (200.0, 5000.0)] {
        let force = 80e3;
        let ground = on_line_support(&beam, &foundation, speed, force, friction);
        assert!(ground.convergence.is_converged(), "{:?}", ground.convergence);
        let fe = common::fe_friction_wave((beam, foundation), (force, speed, friction), 0.25);
        let peak = largest(&fe.deflection);
        let mut compared = 0;
        for (s, w) in ground.s.iter().zip(&ground.deflection).filter(|(s, _)| **s >= -50.0) {
            let i = fe.s.iter().position(|x| (x - s).abs() < 1e-9).expect("the same nodes");
            assert!((fe.deflection[i] - w).abs() <= 2e-4 * peak, "{speed} m/s at s = {s}: {w} vs {}", fe.deflection[i]);
            compared += 1;
        }
        assert_eq!(compared, 441);
        // The wave is the axles' linear wave and what the friction forces carry, at the points to the Newton
        // iteration's round-off (1e-8 of the peak): the reading the peaks are refined on between them.
        let grounded = GroundedBeam::new(&beam, &foundation).unwrap();
        let spectrum = grounded.spectrum(speed).unwrap();
        for (s, w) in ground.s.iter().zip(&ground.deflection) {
            let sum = force * spectrum.deflection(*s) + ground.carried(*s);
            assert!((sum - w).abs() <= 1e-8 * peak, "{speed} m/s at s = {s}: {sum} vs {w}");
        }
        // Both slip over the same stretch of track (a point's state may differ where its trial force is ±f_u).
        let fe_slip: f64 = fe.slip_zones.iter().map(|z| (z.to - z.from.max(-50.0)).max(0.0)).sum();
        let ground_slip: f64 =
            ground.slipping.iter().zip(&ground.s).filter(|(slip, s)| **slip && **s >= -50.0).count() as f64 * 0.25;
        assert!((fe_slip - ground_slip).abs() <= 2.0, "{speed} m/s: slip {fe_slip} m vs {ground_slip} m");
    }
}

/// Friction far below what the wave needs leaves the linear wave (to 1e-6 of its peak, ~f_u over the largest soil
/// pressure); friction far above what any point needs holds the rail still (W ≤ 1e-4 of the linear peak: the
/// Jenkins springs' give, F/(κL) with κ = 1e6·k_f and L the few metres the rail's bending spreads the load over,
/// measured 2.4e-5).
#[test]
fn weak_friction_leaves_the_linear_wave_and_strong_friction_holds_the_rail() {
    let (beam, foundation) = winkler_track();
    let (speed, force) = (100.0, 80e3);
    let linear_peak = 80e3
        * largest(
            &(-200..=200)
                .map(|i| {
                    GroundedBeam::new(&beam, &foundation).unwrap().spectrum(speed).unwrap().deflection(i as f64 * 0.1)
                })
                .collect::<Vec<_>>(),
        );
    let weak = on_line_support(&beam, &foundation, speed, force, 1e-3);
    let grounded = GroundedBeam::new(&beam, &foundation).unwrap();
    let spectrum = grounded.spectrum(speed).unwrap();
    for (s, w) in weak.s.iter().zip(&weak.deflection) {
        assert!((w - force * spectrum.deflection(*s)).abs() <= 1e-6 * linear_peak, "s = {s}");
    }
    let strong = on_line_support(&beam, &foundation, speed, force, 1e9);
    assert!(strong.convergence.is_converged());
    assert!(largest(&strong.deflection) <= 1e-4 * linear_peak, "{}", largest(&strong.deflection));
    assert!(strong.slipping.iter().all(|s| !s));
}

/// The soft trial site of the CLI's tests (a crust over soft clay on a stiffer half-space) under a composite beam.
fn soft_site() -> (Beam, analytic::ground::StripGround) {
    let beam =
        Beam { youngs_modulus: 2e8, second_moment: 1.0, area: 1.0, density: 1e4, loss_factor: 0.1, ..Beam::default() };
    (beam, common::soft_strip())
}

/// On a layered ground (the soft site at 50 m/s, a 100 kN load, 2 kN/m) the wave converges as the friction's points
/// are refined, 1 → 0.5 → … → 0.0625 m, at first order (the play operator's march places each stick–slip change at a
/// point: measured changes 4.3e-5, 1.1e-5, 5.6e-6, 2.5e-6 m of the deepest point, orders 2.0, 0.93, 1.17): asked ≥ 0.8
/// over the last two halvings, and at 0.25 m — the spacing `frictrack stationary` uses — within 1 % of the
/// extrapolated value (measured 0.49 %: the discretisation error a quoted friction wave carries).
#[test]
fn on_the_ground_the_wave_converges_as_the_points_are_refined() {
    let (beam, strip) = soft_site();
    let grounded = GroundedBeam::new(&beam, &strip).unwrap();
    let speed = 50.0;
    let spectrum = grounded.spectrum(speed).unwrap();
    let local = grounded.local_fit(&beam, &spectrum, speed).unwrap();
    let axles = [Axle { offset: 0.0, force: 100e3 }];
    let deepest = |step: f64| {
        let count = (160.0 / step).round() as usize + 1;
        let problem = GroundFrictionProblem {
            track: FrictionTrack::Composite(&spectrum),
            axles: &axles,
            speed,
            window: GroundWindow { first: -100.0, step, count },
            friction_force: 2000.0,
            local,
        };
        let wave = solve_on_ground(&problem, &mut ContactGuess::default(), &Control::new(None)).unwrap();
        assert!(wave.convergence.is_converged(), "{step} m: {:?}", wave.convergence);
        let at_points = largest(&wave.deflection);
        // Refined between the points on the linear wave plus what friction carries.
        let mut at = |s: f64| Ok::<_, ()>(-(100e3 * spectrum.deflection(s) + wave.carried(s)));
        let i = wave.deflection.iter().position(|w| w.abs() == at_points).unwrap();
        let sample = (wave.s[i], at_points);
        analytic::golden::refine_peak(&mut at, (wave.s[i - 1], wave.s[i + 1]), sample, 1e-4).unwrap().1
    };
    let values: Vec<f64> = [1.0, 0.5, 0.25, 0.125, 0.0625].iter().map(|&h| deepest(h)).collect();
    let changes: Vec<f64> = values.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    let order = (changes[2] / changes[3]).log2();
    let extrapolated = values[4] + (values[4] - values[3]) / (2f64.powf(order) - 1.0);
    assert!(order >= 0.8, "{values:?}: order {order}");
    assert!((values[2] - extrapolated).abs() <= 1e-2 * extrapolated, "{values:?}: {extrapolated}");
}
