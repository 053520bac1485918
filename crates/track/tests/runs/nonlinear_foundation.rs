//! Nonlinear foundations (docs/theory.md §13): tensionless and bilinear soils as compliant unilateral sections beside
//! the linear part in K, with the rail's self-weight; the static tensionless closed form, the glued and linear
//! limits, lift-off and the energy identity.

use analytic::reference::{InfiniteBeam, uic60_on_soft_soil};
use analytic::tensionless::TensionlessPointLoad;
use fem_beam::{BeamModel, Foundation, FoundationLaw, LoadVector, Mesh, Support, Supports};
use track::unilateral_statics::{StaticSolver, static_deflection};
use track::{FoundationSections, PlacedInteractions, RunResult, RunSettings, Simulation};

fn model(law: FoundationLaw, length: f64, elements: usize, supports: Supports) -> BeamModel {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { law, ..case.foundation };
    BeamModel::new(case.beam, foundation, Mesh::new(length, elements).unwrap(), supports).unwrap()
}

fn run(model: &BeamModel, interactions: &PlacedInteractions, force: f64, speed: f64) -> RunResult {
    let mut settings = RunSettings::default();
    settings.moving.load = track::Load::Force(force);
    settings.moving.speed = speed;
    Simulation::new(model, interactions, &settings).unwrap().run().unwrap()
}

/// The self-weight settlement q/k_c of the reference rail (m): the rail lifts off where the dynamic wave rises above it.
fn settlement() -> f64 {
    let case = uic60_on_soft_soil();
    case.beam.mass_per_length() * fem_beam::GRAVITY / case.foundation.stiffness
}

/// A rail that never rises above its settlement never leaves the soil: tensionless and bilinear soils are then the
/// linear one. At rest to round-off (the Gauss sections' springs sum to the consistent foundation matrix); in a run
/// to the interior point's tolerance, which it meets on the law residual, not on the deflection itself.
#[test]
fn a_soil_the_rail_never_leaves_is_the_linear_foundation() {
    let laws = [FoundationLaw::Tensionless, FoundationLaw::Bilinear { tension_ratio: 0.5 }];
    let linear = model(FoundationLaw::Linear, 200.0, 200, Supports::default());
    // At rest: a 5 kN load standing at 70 m, deflections relative to the settled rail.
    let load =
        LoadVector::point_force(&linear.discretisation(), 70.0, -5e3).unwrap().to_free(linear.mesh(), linear.dofs());
    let mut reference = load.clone();
    linear.stiffness().factor().unwrap().solve_in_place(&mut reference);
    let light = run(&linear, &PlacedInteractions::new(), 5e3, 100.0);
    assert!(light.deflection.max_upward.value < 0.5 * settlement(), "{} m", light.deflection.max_upward.value);
    for law in laws {
        let m = model(law, 200.0, 200, Supports::default());
        let sections = FoundationSections::default().interactions(&m).unwrap();
        let q = static_deflection(&m, &sections, &load).unwrap();
        let at_rest = super::common::relative_difference(&q, &reference);
        // Round-off of a banded solve of order 400 with condition ~1e6: ≤ 1e-12 relative.
        assert!(at_rest <= 1e-12, "{law:?}: {at_rest:e}");
        let r = run(&m, &sections, 5e3, 100.0);
        let lift = r.lift_off.as_ref().unwrap();
        assert!(lift.zones.is_empty(), "{law:?}: {:?}", lift.zones);
        assert_eq!(lift.sections, 800);
        let moving =
            r.final_displacement.iter().zip(&light.final_displacement).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
                / light.deflection.max_downward.value;
        let peak = (r.deflection.max_downward.value - light.deflection.max_downward.value).abs()
            / light.deflection.max_downward.value;
        // The interior point stops at a law residual of 1e-8 of the velocity scale per step: the deflections carry
        // that error, measured 3e-8 on the peak; 1e-6 of the peak leaves a margin and catches any modelling
        // difference (the compliant stop's end-of-step force differed by 1.6 %).
        assert!(moving <= 1e-6 && peak <= 1e-6, "{law:?}: final state {moving:e}, peak {peak:e}");
    }
}

/// A 20 kN load entering the reference track at 100 m/s lifts the linear rail 3.7 mm, above its 2.35 mm settlement:
/// the tensionless rail leaves the soil there, rises further (nothing pulls it back) and, softer, deflects further
/// down too; the bilinear one (k_t = k_c/2) lies between. Every run closes the energy identity with the soil's work in the ledger.
#[test]
fn the_rail_lifts_off_where_the_linear_wave_rises_above_the_settlement() {
    let linear =
        run(&model(FoundationLaw::Linear, 200.0, 200, Supports::default()), &PlacedInteractions::new(), 20e3, 100.0);
    assert!(linear.deflection.max_upward.value > settlement());
    let mut upward = vec![linear.deflection.max_upward.value];
    let mut downward = vec![linear.deflection.max_downward.value];
    for law in [FoundationLaw::Bilinear { tension_ratio: 0.5 }, FoundationLaw::Tensionless] {
        let m = model(law, 200.0, 200, Supports::default());
        let sections = FoundationSections::default().interactions(&m).unwrap();
        let r = run(&m, &sections, 20e3, 100.0);
        let e = r.energy;
        // Round-off of 2000 steps of O(100 J) sums.
        assert!(e.residual().abs() <= 1e-12 * e.load_work, "{law:?}: {:e} of {:e}", e.residual(), e.load_work);
        assert!(e.support_work != 0.0 && e.spring_energy > 0.0, "{law:?}: {e:?}");
        let lift = r.lift_off.as_ref().unwrap();
        let zone = lift.largest().expect("the rail lifts off");
        let (at, when) = (zone.largest_gap.position.unwrap(), zone.largest_gap.time.unwrap());
        assert!(zone.largest_gap.value > 0.0 && zone.from <= at && at <= zone.to);
        assert!(zone.first_time.unwrap() <= when && when <= zone.last_time.unwrap());
        // The gap is the rail's rise above its settled state less the local settlement (≥ 0; less than q/k_c near a
        // pinned end): at most the largest rise, which between nodes exceeds the nodal one by far less than 1 %.
        assert!(zone.largest_gap.value <= 1.01 * r.deflection.max_upward.value, "{law:?}: {zone:?}");
        upward.push(r.deflection.max_upward.value);
        downward.push(r.deflection.max_downward.value);
    }
    assert!(upward.windows(2).all(|w| w[0] < w[1]), "upward {upward:?}");
    // Less soil in tension is a softer rail: it also deflects further down (as at rest, by coth(π/2) without weight).
    assert!(downward.windows(2).all(|w| w[0] < w[1]), "downward {downward:?}");
}

/// The static tensionless case without self-weight against its closed form (analytic::tensionless): a free beam of
/// 100 m with the 83.4 kN load in the middle rests on the soil over π/β and is straight beyond; the peak deflection
/// is coth(π/2) = 1.0903 times the linear beam's.
#[test]
fn static_tensionless_contact_against_the_closed_form() {
    let p = 83.4e3;
    let case = uic60_on_soft_soil();
    let closed = TensionlessPointLoad::new(&InfiniteBeam::new(&case.beam, &case.foundation).unwrap(), p).unwrap();
    let m = model(FoundationLaw::Tensionless, 100.0, 400, Supports::both(Support::Free));
    let sections = FoundationSections { self_weight: false, ..Default::default() }.interactions(&m).unwrap();
    assert!(sections.preload().is_empty());
    let load = LoadVector::point_force(&m.discretisation(), 50.0, -p).unwrap().to_free(m.mesh(), m.dofs());
    let q = static_deflection(&m, &sections, &load).unwrap();
    let full = m.dofs().expand(&q);
    let w0 = m.deflection_at(&full, 50.0).unwrap();
    // Hermite elements of 0.25 m: 1.6e-7 measured, 4.5e-9 at 0.125 m (fifth order).
    let error = (w0 - closed.deflection(0.0)).abs() / closed.deflection(0.0).abs();
    assert!(error <= 5e-7, "w(0) = {w0} m against {} m: {error:e}", closed.deflection(0.0));
    let linear = model(FoundationLaw::Linear, 100.0, 400, Supports::both(Support::Free));
    let mut w_linear = load.clone();
    linear.stiffness().factor().unwrap().solve_in_place(&mut w_linear);
    let amplification = w0 / linear.deflection_at(&linear.dofs().expand(&w_linear), 50.0).unwrap();
    assert!((amplification - TensionlessPointLoad::amplification()).abs() <= 1e-6, "{amplification}");
    // The contact zone: the sections pressed in, to within the largest gap between neighbouring Gauss sections
    // (0.53 of an element).
    let pressed: Vec<f64> = sections
        .positions()
        .iter()
        .zip(sections.interactions().rows())
        .filter(|(_, row)| row.dot(&q) < 0.0)
        .map(|(x, _)| *x)
        .collect();
    let half = 0.5 * (pressed.last().unwrap() - pressed.first().unwrap());
    let spacing = 0.53 * m.mesh().element_length();
    assert!(
        (half - closed.contact_half_length()).abs() <= spacing,
        "{half} m against {} m",
        closed.contact_half_length()
    );
    // Beyond it the beam is straight: no moment.
    let moment = |x: f64| m.interpolated_moment(&full, x).unwrap();
    assert!(moment(50.0 + 1.2 * closed.contact_half_length()).abs() <= 1e-6 * moment(50.0).abs());
}

/// The static envelope's solver ([`StaticSolver`]) keeps one contact set along the crossing: a load standing at
/// 161 positions (10–90 m by 0.5 m) on the free tensionless beam gives each position's cold solution (every section
/// pressed at first, a factorisation per iteration) to round-off — the solution is unique —, with a factorisation
/// only where the contact set moves: measured 351 factorisations against the cold solves' 3913 (2.2 a position
/// against 24); bounded at a quarter.
#[test]
fn the_static_envelope_keeps_its_contact_set_along_the_crossing() {
    let m = model(FoundationLaw::Tensionless, 100.0, 400, Supports::both(Support::Free));
    let sections = FoundationSections { self_weight: false, ..Default::default() }.interactions(&m).unwrap();
    let mut warm = StaticSolver::new(&m, &sections);
    let mut cold_factorisations = 0;
    for i in 0..=160 {
        let x = 10.0 + 0.5 * i as f64;
        let load = LoadVector::point_force(&m.discretisation(), x, -83.4e3).unwrap().to_free(m.mesh(), m.dofs());
        let mut cold = StaticSolver::new(&m, &sections);
        let (a, b) = (warm.solve(&load).unwrap(), cold.solve(&load).unwrap());
        cold_factorisations += cold.factorisations();
        let difference = super::common::relative_difference(&a, &b);
        assert!(difference <= 1e-12, "at {x} m: {difference:e}");
    }
    assert!(4 * warm.factorisations() <= cold_factorisations, "{} vs {cold_factorisations}", warm.factorisations());
}
