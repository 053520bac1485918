//! Runs on a Timoshenko rail (docs/theory.md §15): the energy identity at round-off with friction and with a vehicle
//! (its wheel's contact row is the element's own N_w), and the limit G → ∞.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{Beam, BeamModel, BeamTheory, Mesh};
use nscd::solver::{SolverKind, SolverSettings};
use track::vehicle::builtin::QuarterCar;
use track::vehicle::consist::VehicleSettings;
use track::{BallastOnBeam, Devices, DistributedFriction, Load, PlacedInteractions, RunSettings, Simulation};

/// The reference track with a Timoshenko UIC60 rail of shear modulus `g` (κ = 0.4), `elements` over `length` m.
fn timoshenko_track(g: f64, length: f64, elements: usize) -> BeamModel {
    let case = uic60_on_soft_soil();
    let beam = Beam { theory: BeamTheory::Timoshenko { shear_modulus: g, shear_coefficient: 0.4 }, ..case.beam };
    BeamModel::new(beam, case.foundation, Mesh::new(length, elements).unwrap(), case.supports).unwrap()
}

fn settings(speed: f64, theta: f64) -> RunSettings {
    let mut s = RunSettings::default();
    s.integration.theta = theta;
    s.moving.speed = speed;
    s.integration.load_advance = 0.1;
    s
}

/// Short elements (0.25 m: φ ≈ 5, shear dominates the element's interpolation) with devices, with ballast friction
/// between nodes, for θ = 0.5 and 0.6: the residual at round-off (1e-9 of the load's work, as for Euler–Bernoulli).
#[test]
fn energy_closes_on_a_timoshenko_rail_with_friction() {
    let model = timoshenko_track(81e9, 60.0, 240);
    let sets = [
        ("devices", Devices::uniform(31, 50e3).interactions(&model).unwrap()),
        ("distributed", DistributedFriction::new(2e3).interactions(&model).unwrap()),
    ];
    for theta in [0.5, 0.6] {
        for (name, interactions) in &sets {
            let r = Simulation::new(&model, interactions, &settings(180.0, theta)).unwrap().run().unwrap();
            let e = r.energy;
            assert!(e.load_work > 0.0 && e.friction_work < 0.0, "{name}: {e:?}");
            assert!(e.residual().abs() <= 1e-9 * e.load_work, "{name}, θ = {theta}: {:e}", e.residual());
        }
    }
}

/// A quarter car on the Timoshenko rail, glued (linear contact) and unilateral: the identity closes to 1e-12 of
/// its largest term, as on an Euler–Bernoulli rail.
#[test]
fn energy_closes_with_a_vehicle_on_a_timoshenko_rail() {
    let model = timoshenko_track(81e9, 60.0, 240);
    let mut s = settings(60.0, 0.5);
    let car = QuarterCar::default().vehicle().unwrap();
    s.moving.load = Load::Vehicles { vehicles: VehicleSettings::single(car), train: None };
    s.integration.solver =
        SolverSettings { kind: SolverKind::Projection, tolerance: 1e-12, ..SolverSettings::default() };
    let interactions = Devices::uniform(5, 20e3).interactions(&model).unwrap();
    let r = Simulation::new(&model, &interactions, &s).unwrap().run().unwrap();
    let e = &r.energy;
    let terms = [e.load_work, e.friction_work, e.contact_work, e.viscous_dissipation, e.projection_work, e.initial];
    let scale = terms.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(scale > 0.0 && e.residual().abs() < 1e-12 * scale, "residual {} of {scale} J", e.residual());
}

/// G → ∞ converges (G = 1e16 and 1e20 Pa agree to 1e-6) to a Rayleigh beam — rotary inertia kept — whose largest
/// deflection at 150 m/s lies within 0.2 % of the Euler–Bernoulli run's (measured 0.12 %: ρI k²/ρA = (I/A)k² is
/// 2e-3 at k = 0.7 rad/m, waves of 9 m, shorter than those that carry the deflection); a real rail's shear
/// (G = 81 GPa) adds about as much again (0.28 % in all), still below 1 %.
#[test]
fn infinite_shear_modulus_runs_like_a_rayleigh_beam() {
    let case = uic60_on_soft_soil();
    let euler = BeamModel::new(case.beam, case.foundation, Mesh::new(60.0, 240).unwrap(), case.supports).unwrap();
    let none = PlacedInteractions::new();
    let peak = |model: &BeamModel| {
        Simulation::new(model, &none, &settings(150.0, 0.5)).unwrap().run().unwrap().deflection.max_downward.value
    };
    let e = peak(&euler);
    let (stiff, stiffer) = (peak(&timoshenko_track(1e16, 60.0, 240)), peak(&timoshenko_track(1e20, 60.0, 240)));
    assert!((stiff - stiffer).abs() < 1e-6 * stiffer, "{stiff} vs {stiffer}");
    assert!((stiffer - e).abs() < 2e-3 * e, "{stiffer} vs {e}");
    let rail = peak(&timoshenko_track(81e9, 60.0, 240));
    assert!(rail > stiffer && (rail - e) / e < 1e-2, "{rail} vs {e}");
}
