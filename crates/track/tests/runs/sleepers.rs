//! Runs on sleepers (docs/theory.md §18): the energy identity with voided, tensionless and frictional sleepers and a
//! vehicle; the limits — a tensionless sleeper that keeps pressing is the bonded one, a void that never closes is no
//! ballast, sleepers ever closer with k per metre held are the Winkler track —; the interior point against Clarabel.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{BallastContact, BeamModel, Foundation, Layer, Mesh, SleeperException, Sleepers};
use nscd::solver::{SolverKind, SolverSettings};
use track::sleeper_layout::sleeper_interactions;
use track::vehicle::builtin::QuarterCar;
use track::vehicle::consist::VehicleSettings;
use track::{InitialState, Load, RunResult, RunSettings, Simulation};

/// The UIC60 rail on `sleepers` (no soil), `elements` over `length` m, pinned ends.
pub(super) fn on_sleepers(length: f64, elements: usize, sleepers: Sleepers) -> BeamModel {
    let case = uic60_on_soft_soil();
    let mesh = Mesh::new(length, elements).unwrap();
    BeamModel::new(case.beam, Foundation::linear(0.0, 0.0), mesh, case.supports)
        .unwrap()
        .with_sleepers(sleepers)
        .unwrap()
}

pub(super) fn settings(speed: f64, theta: f64, advance: f64) -> RunSettings {
    let mut s = RunSettings::default();
    s.integration.theta = theta;
    s.moving.speed = speed;
    s.integration.load_advance = advance;
    s
}

pub(super) fn run(model: &BeamModel, s: &RunSettings) -> RunResult {
    Simulation::new(model, &sleeper_interactions(model), s).unwrap().run().unwrap()
}

pub(super) fn exception(first: usize, last: usize) -> SleeperException {
    SleeperException { first, last, ..SleeperException::default() }
}

pub(super) fn voided(first: usize, last: usize, gap: f64) -> SleeperException {
    SleeperException { contact: BallastContact::Unilateral { gap }, ..exception(first, last) }
}

/// Voids, tensionless ballast everywhere, friction at twenty sleepers, all at once, θ = ½ and 0.6: the identity
/// closes to 1e-9 of the load's work (the interior point's tolerance on the laws' residuals, as for devices).
#[test]
fn energy_closes_with_voided_tensionless_and_frictional_sleepers() {
    let sets = [
        ("voided", vec![voided(49, 50, 1e-3)]),
        ("tensionless", vec![voided(0, 99, 0.0)]),
        ("friction", vec![SleeperException { friction: 2e3, ..exception(40, 60) }]),
        (
            "all",
            vec![voided(0, 99, 0.0), voided(49, 50, 1e-3), SleeperException { friction: 2e3, ..exception(40, 60) }],
        ),
    ];
    for theta in [0.5, 0.6] {
        for (name, exceptions) in &sets {
            let model = on_sleepers(60.0, 400, Sleepers { exceptions: exceptions.clone(), ..Sleepers::default() });
            let r = run(&model, &settings(50.0, theta, 0.0375));
            let e = r.energy;
            assert!(e.load_work > 0.0, "{name}: {e:?}");
            assert!(e.residual().abs() <= 1e-9 * e.load_work, "{name}, θ = {theta}: {:e}", e.residual());
            let sleepers = r.sleepers.unwrap();
            assert_eq!(sleepers.sleepers.len(), 100);
            if name == &"friction" {
                assert!(e.friction_work < 0.0, "{e:?}");
            } else {
                assert!(e.support_work != 0.0, "{name}: {e:?}");
            }
        }
    }
}

/// A quarter car over two voided sleepers: the identity to 1e-12 of its largest term (projection solver at 1e-12,
/// as on a continuous track), and the voided sleepers reach the ballast once the wheel is over them.
#[test]
fn energy_closes_with_a_vehicle_over_voided_sleepers() {
    let model = on_sleepers(60.0, 400, Sleepers { exceptions: vec![voided(49, 50, 0.5e-3)], ..Sleepers::default() });
    let mut s = settings(40.0, 0.5, 0.0375);
    let car = QuarterCar::default().vehicle().unwrap();
    s.moving.load = Load::Vehicles { vehicles: VehicleSettings::single(car), train: None };
    s.integration.solver =
        SolverSettings { kind: SolverKind::Projection, tolerance: 1e-12, ..SolverSettings::default() };
    let r = run(&model, &s);
    let e = &r.energy;
    let terms = [e.load_work, e.support_work, e.contact_work, e.viscous_dissipation, e.projection_work, e.initial];
    let scale = terms.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(scale > 0.0 && e.residual().abs() < 1e-12 * scale, "residual {} of {scale} J", e.residual());
    let sleepers = r.sleepers.unwrap();
    for p in &sleepers.sleepers[49..=50] {
        let when = p.first_contact.expect("the wheel presses the voided sleeper onto the ballast");
        // The wheel is within two bays of the sleeper when it closes the void (1.5 mm under a 50 kN wheel).
        assert!((40.0 * when - p.x).abs() < 1.2, "closed at t = {when} s, x = {} m", p.x);
        assert!(p.lowest > 0.5e-3 && p.ballast_force.0 > 0.0, "{p:?}");
    }
}

/// The interior point (default) and Clarabel on `sleepers`, both asked for law residuals of 1e-10 m/s (they reach
/// 2e-10 and 1e-9): the same peak, final state and friction work to 1e-8 — a hundred times what is measured.
pub(super) fn clarabel_agrees_on(sleepers: Sleepers) {
    let model = on_sleepers(60.0, 400, sleepers);
    let mut s = settings(50.0, 0.5, 0.0375);
    s.integration.solver.tolerance = 1e-10;
    let ip = run(&model, &s);
    s.integration.solver.kind = SolverKind::Clarabel;
    let clarabel = run(&model, &s);
    let peak = ip.deflection.max_downward.value;
    // The final state (the track settling, stuck by friction) against the peak, not against its own small size.
    let difference =
        ip.final_displacement.iter().zip(&clarabel.final_displacement).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / peak;
    let (f_ip, f_c) = (ip.energy.friction_work, clarabel.energy.friction_work);
    assert!(ip.energy.support_work != 0.0, "the voids must close: {:?}", ip.energy);
    assert!(
        (clarabel.deflection.max_downward.value - peak).abs() <= 1e-8 * peak,
        "{} vs {peak}",
        clarabel.deflection.max_downward.value
    );
    assert!(difference <= 1e-8, "{difference:e}");
    assert!((f_c / f_ip - 1.0).abs() <= 1e-8, "friction work {f_ip} vs {f_c} J");
}

/// Voided and frictional sleepers, the later exception deciding (the voided sleepers have no friction): measured
/// 4e-11 on the peak, 5e-10 on the final state, 2e-10 on the friction work.
pub(super) fn voided_and_frictional() -> Vec<SleeperException> {
    vec![SleeperException { friction: 3e3, ..exception(30, 70) }, voided(49, 51, 0.1e-3)]
}

#[test]
fn clarabel_agrees_on_voided_and_frictional_sleepers() {
    clarabel_agrees_on(Sleepers { exceptions: voided_and_frictional(), ..Sleepers::default() });
}

/// A tensionless sleeper (gap 0) that keeps pressing on the ballast is the bonded sleeper step for step (the soil
/// law at the θ-point is the linear spring while it presses): from a static start with the load 0.3 m before the
/// sleeper, over the 1.2 m the load takes to pass it, to 1e-6 (the solver's tolerance, as for a soil). A void that
/// never closes (1 m) is a sleeper without ballast (ballast_scale = 0), to the solver's tolerance.
#[test]
fn a_pressed_tensionless_sleeper_is_bonded_and_a_void_never_closed_is_no_ballast() {
    let s = |exceptions| Sleepers { exceptions, ..Sleepers::default() };
    let mut set = settings(30.0, 0.5, 0.0375);
    set.moving.initial = InitialState::Static { position: 29.4 };
    let stop = |r: &track::simulation::StepView<'_>| r.load_position < 30.9;
    let partial = |model: &BeamModel| {
        Simulation::new(model, &sleeper_interactions(model), &set).unwrap().run_observed(&mut |v| stop(v)).unwrap()
    };
    let bonded = partial(&on_sleepers(60.0, 400, s(vec![])));
    let tensionless = partial(&on_sleepers(60.0, 400, s(vec![voided(49, 49, 0.0)])));
    let p = tensionless.sleepers.as_ref().unwrap().sleepers[49];
    assert_eq!(p.largest_gap, Some(0.0), "the sleeper must keep pressing for the comparison: {p:?}");
    assert!(p.first_contact.is_some());
    let difference = super::common::relative_difference(&tensionless.final_displacement, &bonded.final_displacement);
    assert!(difference <= 1e-6, "{difference:e}");

    let huge = run(&on_sleepers(60.0, 400, s(vec![voided(49, 50, 1.0)])), &settings(50.0, 0.5, 0.075));
    let bare = SleeperException { ballast_scale: 0.0, ..exception(49, 50) };
    let none = run(&on_sleepers(60.0, 400, s(vec![bare])), &settings(50.0, 0.5, 0.075));
    let difference = super::common::relative_difference(&huge.final_displacement, &none.final_displacement);
    // Not to round-off: the interior point keeps a barrier force ~μ/g on a law far from contact, 3e-7 measured.
    assert!(difference <= 1e-6, "{difference:e}");
    assert!((huge.deflection.max_downward.value / none.deflection.max_downward.value - 1.0).abs() <= 1e-6);
    // And the void shows: the rail sags more over the hanging sleepers than over bonded ones.
    let normal = run(&on_sleepers(60.0, 400, s(vec![])), &settings(50.0, 0.5, 0.075));
    assert!(none.deflection.max_downward.value > 1.1 * normal.deflection.max_downward.value);
}

/// Sleepers under every node whose pads and ballast in series are the Winkler soil's spring and dashpot per metre
/// (k_p = k_b = 2 k_f a, c_p = c_b = 2 c_f a: two Kelvin–Voigt layers of one time constant in series are one, of half
/// the stiffness and damping), nearly massless (m_s = 1e-9 ρA a): a moving load's peak deflection and the final
/// state tend to the continuous track's (its rail carrying the sleepers' spread mass,
/// [`Sleepers::equivalent_track`]) as a shrinks — the springs lumped at nodes against the consistent foundation
/// matrix: fourth order, measured 3.1e-7, 1.9e-8, 1.3e-9 on the peak for a = 0.3, 0.15, 0.075 m (the sleepers' own
/// mass would set a floor near 1e-7 at m_s = 1e-6 ρA a).
#[test]
fn sleepers_ever_closer_are_the_winkler_track() {
    let case = uic60_on_soft_soil();
    let k_f = case.foundation.stiffness;
    let c_f = 0.1 * case.foundation.critical_damping(&case.beam);
    let mut errors = Vec::new();
    for elements in [200usize, 400, 800] {
        let a = 60.0 / elements as f64;
        let layer = Layer { stiffness: 2.0 * k_f * a, damping: 2.0 * c_f * a, loss_factor: 0.0 };
        let mass = 1e-9 * case.beam.mass_per_length() * a;
        let sleepers = Sleepers {
            spacing: a,
            first: 0.0,
            mass,
            pad: layer,
            ballast: layer,
            ballast_body: None,
            exceptions: vec![],
        };
        let (beam, soil) = sleepers.equivalent_track(&case.beam, 0.0);
        assert!((soil / k_f - 1.0).abs() < 1e-12);
        let discrete = on_sleepers(60.0, elements, sleepers);
        let mesh = Mesh::new(60.0, elements).unwrap();
        let winkler = BeamModel::new(beam, Foundation::linear(k_f, c_f), mesh, case.supports).unwrap();
        let s = settings(60.0, 0.5, 0.075);
        let (d, w) = (run(&discrete, &s), run(&winkler, &s));
        // The rail's DOFs: the sleepers' follow them in the full vector.
        let rail = 2 * (elements + 1);
        let discrete_rail = &discrete.dofs().expand(&d.final_displacement)[..rail];
        let state = super::common::relative_difference(discrete_rail, &winkler.dofs().expand(&w.final_displacement));
        let peak = (d.deflection.max_downward.value / w.deflection.max_downward.value - 1.0).abs();
        errors.push((peak, state));
    }
    // Each halving gains at least 10× (16× is fourth order).
    assert!(errors.windows(2).all(|e| e[1].0 <= 0.1 * e[0].0 && e[1].1 <= 0.1 * e[0].1), "{errors:?}");
    assert!(errors[2].0 <= 1e-8 && errors[2].1 <= 1e-7, "{errors:?}");
}

/// A sleeper hanging over a void its rail never closes (2 and 10 mm under a 50 m/s load that bends the rail ~1 mm)
/// carries no ballast force at all — the ballast's dashpot acts in contact only, as its spring does (it reported
/// 3.1 kN before, the dashpot pulling across the open gap) — and never touches; a void that does close (0.1 mm)
/// carries a force from its first contact on. The hanging sleepers move the same for either void (to the
/// solver's tolerance: nothing under them acts).
#[test]
fn a_void_that_never_closes_carries_no_ballast_force() {
    let voids = |gap| Sleepers { exceptions: vec![voided(49, 50, gap)], ..Sleepers::default() };
    let set = settings(50.0, 0.5, 0.075);
    let mut finals = Vec::new();
    for gap in [2e-3, 10e-3] {
        let r = run(&on_sleepers(60.0, 400, voids(gap)), &set);
        let sleepers = &r.sleepers.as_ref().unwrap().sleepers;
        for s in &sleepers[49..=50] {
            assert_eq!(s.first_contact, None, "gap {gap}: {s:?}");
            assert_eq!(s.ballast_force.0, 0.0, "gap {gap}: {s:?}");
            assert!(s.largest_gap.unwrap() > 0.5 * gap, "gap {gap}: {s:?}");
        }
        assert!(sleepers[48].ballast_force.0 > 1e3, "{:?}", sleepers[48]);
        finals.push(r.final_displacement);
    }
    assert!(super::common::relative_difference(&finals[0], &finals[1]) <= 1e-6);
    let closing = run(&on_sleepers(60.0, 400, voids(0.1e-3)), &set);
    let s = closing.sleepers.as_ref().unwrap().sleepers[49];
    assert!(s.first_contact.is_some() && s.ballast_force.0 > 1e3, "{s:?}");
}
