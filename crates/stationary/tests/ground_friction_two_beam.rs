//! Ballast friction on the two-beam track on the ground ([`stationary::solve_on_ground`] with
//! [`FrictionTrack::RailOnEmbankment`], docs/theory.md §19) checked where its answer is known: over a rigid
//! embankment with rigid pads and massless sleepers the friction between the sleepers and the embankment is the
//! rail's ballast friction on a Winkler soil of k_f = k_b/a, c_f = c_b/a, whose wave the finite-element stationary
//! solver gives independently (a Hermite mesh, its sections at the nodes, a banded Newton iteration).

mod common;

use analytic::ground::{GroundedBeam, TrackOnEmbankment};
use fem_beam::{Axle, Foundation};
use stationary::{ContactGuess, Control, FrictionTrack, GroundFrictionProblem, GroundWindow, solve_on_ground};

/// Below and above the critical speed (~170 m/s on this track), 2 and 5 kN/m, on 0.1 m points and elements: the
/// rail's deflections agree with the finite elements' to 2e-4 of the peak (observed 1.5e-5 and 1.1e-4; the
/// tolerance of the composite beam's check: the window's Jenkins sections give 1e-6 of the linear peak where the mesh's give 1e-12, which shifts each
/// slip zone's start; here the pairs are also hats over a spacing where the mesh's sections are points, an O(h²)
/// difference) everywhere but the last 10 m behind, where the windows differ by design (the mesh ends free there);
/// the friction acts on d, which over a rigid embankment and rigid pads is the rail's W (to 1e-6 of the peak,
/// observed 6e-8: the pads' give and the spectra's tolerance);
/// the rail's wave is the axles' and the pairs' to the Newton iteration's round-off (1e-8 of the peak); and both
/// slip over the same stretch of track to 2 m.
#[test]
fn over_a_rigid_embankment_it_is_the_finite_element_friction_wave() {
    let (beam, foundation, sleepers, embankment, rigid) = common::rail_on_rigid_embankment(Foundation::default());
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &rigid };
    let (force, step) = (80e3, 0.1);
    let axles = [Axle { offset: 0.0, force }];
    for (speed, friction) in [(50.0, 2000.0), (200.0, 5000.0)] {
        let spectra = GroundedBeam::new(&beam, &track).unwrap().interface_spectra(speed, step).unwrap();
        let count = (120.0 / step).round() as usize + 1;
        let problem = GroundFrictionProblem {
            track: FrictionTrack::RailOnEmbankment(&spectra),
            axles: &axles,
            speed,
            window: GroundWindow { first: -60.0, step, count },
            friction_force: friction,
            local: track.local_across_ballast(&beam, step),
        };
        let ground = solve_on_ground(&problem, &mut ContactGuess::default(), &Control::new(None)).unwrap();
        assert!(ground.convergence.is_converged(), "{:?}", ground.convergence);
        let fe = common::fe_friction_wave((beam, foundation), (force, speed, friction), step);
        let peak = fe.deflection.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        let relative = ground.relative.as_ref().expect("the two-beam track's d");
        let (mut worst, mut worst_d) = (0.0f64, 0.0f64);
        for ((s, w), d) in ground.s.iter().zip(&ground.deflection).zip(relative).filter(|((s, _), _)| **s >= -50.0) {
            let i = fe.s.iter().position(|x| (x - s).abs() < 1e-9).expect("the same nodes");
            worst = worst.max((fe.deflection[i] - w).abs());
            worst_d = worst_d.max((w - d).abs());
        }
        assert!(worst <= 2e-4 * peak, "{speed} m/s: {worst:e} of {peak:e}");
        assert!(worst_d <= 1e-6 * peak, "{speed} m/s: d apart from W by {worst_d:e}");
        for (s, w) in ground.s.iter().zip(&ground.deflection) {
            let sum = spectra.rail.deflection_under(&axles, *s) + ground.carried(*s);
            assert!((sum - w).abs() <= 1e-8 * peak, "{speed} m/s at s = {s}: {sum} vs {w}");
        }
        let fe_slip: f64 = fe.slip_zones.iter().map(|z| (z.to - z.from.max(-50.0)).max(0.0)).sum();
        let ground_slip =
            ground.slipping.iter().zip(&ground.s).filter(|(slip, s)| **slip && **s >= -50.0).count() as f64 * step;
        assert!(fe_slip > 1.0 && (fe_slip - ground_slip).abs() <= 2.0, "{speed} m/s: {fe_slip} m vs {ground_slip} m");
        eprintln!(
            "{speed} m/s: {:e} of the peak, d−W {:e}, slip {fe_slip} vs {ground_slip}",
            worst / peak,
            worst_d / peak
        );
    }
}
