//! Unilateral laws through the same stepper and solvers (docs/theory.md §9): a ball bouncing on rigid ground
//! (Signorini + Newton impact), a mass oscillating against a compliant stop, and the stiff stop tending to the rigid
//! one. Each run also closes the energy identity with the contact work booked on its own.

use banded::SymmetricBanded;
use friction::{InteractionKind, InteractionRow, InteractionSet, Law};
use nscd::forcing::{DofForce, Unloaded};
use nscd::solver::{SolverKind, SolverSettings};
use nscd::stepper::Integration;
use nscd::{Forcing, LinearSystem, MoreauJean};

const GRAVITY: f64 = 9.81;

fn scalar(value: f64) -> SymmetricBanded {
    let mut m = SymmetricBanded::zeros(1, 0);
    m.add(0, 0, value);
    m
}

/// One DOF x (m) of mass `mass` on a spring `stiffness`, with a unilateral `law` on the gap g = gap₀ + x.
fn stepper(mass: f64, stiffness: f64, law: Law, x0: f64, h: f64, kind: SolverKind) -> MoreauJean {
    let system = LinearSystem { mass: scalar(mass), damping: scalar(0.0), stiffness: scalar(stiffness) };
    let mut interactions = InteractionSet::new();
    interactions.push(InteractionRow::from_entries([(0, 1.0)]), law, InteractionKind::Contact);
    let integration = Integration::theta(0.5, h);
    let settings = SolverSettings { kind, tolerance: 1e-10, ..SolverSettings::default() };
    MoreauJean::build(&system, interactions, integration, &settings, vec![x0], vec![0.0]).unwrap()
}

/// Step and check the ledger: the identity closes at round-off of the largest energy term, no friction work is
/// booked, and the contact impulses never pull.
fn advance(stepper: &mut MoreauJean, forcing: &dyn Forcing) {
    stepper.step(forcing).unwrap();
    let e = &stepper.energy;
    let scale = e.initial.abs().max(e.load_work.abs()).max(e.contact_work.abs()).max(1e-300);
    assert!(e.residual().abs() <= 1e-12 * scale * stepper.steps as f64, "energy residual {:e}", e.residual());
    assert_eq!(e.friction_work, 0.0);
    assert!(stepper.p[0] >= 0.0, "tensile contact impulse {}", stepper.p[0]);
}

/// Apex heights of a ball of 1 kg dropped from `h0` onto rigid ground with restitution e, for `bounces` bounces.
fn apexes(restitution: f64, h0: f64, h: f64, bounces: usize, kind: SolverKind) -> Vec<f64> {
    let gravity = DofForce { dof: 0, force: |_| -GRAVITY };
    let law = Law::Signorini { gap: 0.0, restitution };
    let mut ball = stepper(1.0, 0.0, law, h0, h, kind);
    let mut found = Vec::new();
    let mut rising = false;
    while found.len() < bounces {
        let before = ball.q()[0];
        advance(&mut ball, &gravity);
        let (x, v) = (ball.q()[0], ball.v()[0]);
        // Never below the ground by more than the step's travel at impact speed (the index set is set from the
        // gap predicted half a step ahead).
        assert!(x >= -h * (2.0 * GRAVITY * h0).sqrt(), "penetration {x:e}");
        if v > 0.0 {
            rising = true;
        } else if rising {
            // The apex: the largest height sampled (below the true top by at most g h²/8, 1.2e-6 m at h = 1e-3).
            found.push(before.max(x));
            rising = false;
        }
        assert!(ball.time < 10.0, "no apex found");
    }
    found
}

/// Newton's law: each bounce multiplies the apex height by e², so apex n = e^{2n}·h₀; the discrete impact happens
/// within one step of the true contact, so the error is O(h) per bounce and falls with h.
#[test]
fn ball_apex_heights_follow_the_restitution() {
    let h0 = 1.0;
    for restitution in [0.5, 0.9] {
        let mut errors = Vec::new();
        for h in [1e-3, 1e-4] {
            let found = apexes(restitution, h0, h, 3, SolverKind::Projection);
            let mut worst: f64 = 0.0;
            for (n, apex) in found.iter().enumerate() {
                let expected = restitution.powi(2 * (n as i32 + 1)) * h0;
                // Per bounce the impact is off by at most one step's travel at impact speed √(2g h₀) (4.4 mm at
                // h = 1e-3), and the apexes inherit the earlier bounces' errors: n + 1 such terms.
                let allowed = (n + 1) as f64 * h * (2.0 * GRAVITY * h0).sqrt();
                let error = (apex - expected).abs();
                assert!(error <= allowed, "e = {restitution}, h = {h}, bounce {}: {apex} vs {expected}", n + 1);
                worst = worst.max(error / expected);
            }
            errors.push(worst);
        }
        // First order in h: ten times smaller steps, at least five times smaller errors.
        assert!(errors[1] <= errors[0] / 5.0, "e = {restitution}: errors {errors:?} do not fall with h");
    }
}

/// The interior point and Clarabel solve the same contact steps: the same apexes to the solver tolerance.
#[test]
fn solvers_agree_on_the_bouncing_ball() {
    let reference = apexes(0.7, 1.0, 1e-3, 3, SolverKind::Projection);
    let mut kinds = vec![SolverKind::InteriorPoint];
    if cfg!(feature = "clarabel") {
        kinds.push(SolverKind::Clarabel);
    }
    for kind in kinds {
        let found = apexes(0.7, 1.0, 1e-3, 3, kind);
        for (a, b) in found.iter().zip(&reference) {
            // Tolerances 1e-10 relative to the impact speed (Clarabel accepted to 1e-6): apexes to 1e-6 m.
            assert!((a - b).abs() <= 1e-6, "{kind:?}: {a} vs {b}");
        }
    }
}

/// e = 0: the ball lands and stays, at rest, with the whole drop's energy booked as contact work.
#[test]
fn plastic_impact_stays_on_the_ground() {
    let (h0, h) = (1.0, 1e-3);
    let gravity = DofForce { dof: 0, force: |_| -GRAVITY };
    let mut ball = stepper(1.0, 0.0, Law::Signorini { gap: 0.0, restitution: 0.0 }, h0, h, SolverKind::Projection);
    // The fall from 1 m takes √(2h₀/g) = 0.45 s.
    while ball.time < 0.6 {
        advance(&mut ball, &gravity);
    }
    let landed = ball.q()[0];
    for _ in 0..2000 {
        advance(&mut ball, &gravity);
        assert_eq!(ball.v()[0], 0.0, "at rest after landing");
        assert_eq!(ball.q()[0], landed);
        // The ground carries the weight: impulse m g h per step.
        assert!((ball.p[0] - GRAVITY * h).abs() <= 1e-12);
    }
    assert!(landed.abs() <= h * (2.0 * GRAVITY * h0).sqrt(), "rests {landed:e} from the ground");
    // All the potential energy m g h₀ went into the impact: gravity's work m g (h₀ − x) is lost as contact work.
    let e = &ball.energy;
    assert!((e.load_work - GRAVITY * (h0 - landed)).abs() <= 1e-9);
    assert!((e.contact_work + e.load_work).abs() <= 1e-9, "contact work {} load work {}", e.contact_work, e.load_work);
}

/// Zero up-crossings of x (linear interpolation between samples) and the largest contact force p/h.
fn stop_oscillation(stiffness_stop: f64, h: f64, periods: f64, kind: SolverKind) -> (Vec<f64>, f64, MoreauJean) {
    let (m, k, x0): (f64, f64, f64) = (1.0, 100.0, 0.01);
    let law = Law::Compliant { gap: 0.0, stiffness: stiffness_stop };
    let mut oscillator = stepper(m, k, law, x0, h, kind);
    let period = std::f64::consts::PI * ((m / k).sqrt() + (m / (k + stiffness_stop)).sqrt());
    let (mut crossings, mut force) = (Vec::new(), 0.0f64);
    while oscillator.time < periods * period {
        let before = oscillator.q()[0];
        advance(&mut oscillator, &Unloaded);
        let x = oscillator.q()[0];
        if before < 0.0 && x >= 0.0 {
            crossings.push(oscillator.time - h * x / (x - before));
        }
        force = force.max(oscillator.p[0] / h);
    }
    (crossings, force, oscillator)
}

/// A mass on a spring k against a compliant stop k_c at its equilibrium: half a free cycle on the open side, half a
/// stiffer one on the stop, period π√(m/k) + π√(m/(k + k_c)); the stop's largest force k_c·v₀/ω₂ with the speed
/// v₀ = ω₁x₀ at the stop. Period and force converge as h → 0, at the orders measured below.
#[test]
fn compliant_stop_period_and_force_converge() {
    let (m, k, kc, x0): (f64, f64, f64, f64) = (1.0, 100.0, 300.0, 0.01);
    let period = std::f64::consts::PI * ((m / k).sqrt() + (m / (k + kc)).sqrt());
    let peak = kc * (k / m).sqrt() * x0 / ((k + kc) / m).sqrt();
    let mut errors = Vec::new();
    for h in [1e-3, 5e-4, 2.5e-4] {
        let (crossings, force, oscillator) = stop_oscillation(kc, h, 3.2, SolverKind::Projection);
        assert!(crossings.len() >= 3, "{} up-crossings", crossings.len());
        let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        let (period_error, force_error) = ((measured / period - 1.0).abs(), (force / peak - 1.0).abs());
        // The stop stores ½k_c δ² and the implicit law loses a little per step: never more energy than it began with.
        let e = &oscillator.energy;
        assert!(e.current + e.spring_energy <= e.initial * (1.0 + 1e-12));
        errors.push((period_error, force_error));
    }
    let (coarse, fine) = (errors[0], errors[2]);
    // Measured at h = 1e-3, 5e-4, 2.5e-4: period 1.9e-5, 4.8e-6, 1.2e-6 (second order), peak force 5.9e-3, 2.9e-3,
    // 1.5e-3 (first order: the force is k_c δ_{k+1}, taken at the step's end). Bounds with margin on the finest step,
    // and the orders: a quarter of the step, at least 12× (of 16) and 3.5× (of 4) smaller errors.
    assert!(fine.0 <= 3e-6 && fine.1 <= 3e-3, "errors at the finest step: {fine:?}");
    assert!(fine.0 <= coarse.0 / 12.0 && fine.1 <= coarse.1 / 3.5, "errors {errors:?} do not converge at their order");
}

/// As k_c grows the compliant stop becomes the rigid one. Against a rigid elastic stop at its equilibrium a mass on
/// a spring moves as x₀|cos ω₁t| exactly; the compliant stop lets it dip by x₀ω₁/ω₂ ≈ x₀√(k/k_c) for half its period
/// π/ω₂, so the largest deviation from x₀|cos ω₁t| is O(√(k/k_c)) (about (1 + π/2)√(k/k_c)·x₀). The implicit stop law
/// also loses ½k_c(Δδ)² per step in contact, about π²/(2N) of the energy per contact resolved by N steps: each run
/// takes N ∝ √(k_c) so that this loss falls as fast as √(k/k_c). The rigid run (Signorini, e = 1) is checked against
/// the same closed form.
#[test]
fn stiff_compliant_stop_tends_to_the_rigid_stop() {
    let (m, k, x0): (f64, f64, f64) = (1.0, 100.0, 0.01);
    let omega = (k / m).sqrt();
    // One bounce (at t = π/2ω₁ = 0.157 s) and the way back up.
    let deviation = |law: Law, h: f64| {
        let mut oscillator = stepper(m, k, law, x0, h, SolverKind::Projection);
        let mut worst: f64 = 0.0;
        while oscillator.time < 0.25 {
            advance(&mut oscillator, &Unloaded);
            let exact = x0 * (omega * oscillator.time).cos().abs();
            worst = worst.max((oscillator.q()[0] - exact).abs() / x0);
        }
        worst
    };
    let rigid = deviation(Law::Signorini { gap: 0.0, restitution: 1.0 }, 1e-5);
    // The rigid stop's impact lands within a step of the true one: O(ω₁h) of the amplitude (measured 1.1e-4).
    assert!(rigid <= 1e-3, "rigid stop {rigid}");
    let mut previous = f64::INFINITY;
    for (factor, steps_per_contact) in [(1e2, 30.0), (1e4, 300.0), (1e6, 3000.0)] {
        let kc: f64 = factor * k;
        let h = std::f64::consts::PI * (m / (k + kc)).sqrt() / steps_per_contact;
        let compliant = deviation(Law::Compliant { gap: 0.0, stiffness: kc }, h);
        let scale = (k / kc).sqrt();
        // Measured 3.09, 3.23 and 3.25·√(k/k_c) (the dip, the delay of the bounce and the way back up together).
        assert!(compliant <= 4.0 * scale, "k_c = {factor} k: deviation {compliant} > 4√(k/k_c) = {}", 4.0 * scale);
        // √(k/k_c) falls tenfold per step of the sequence: at least eightfold here.
        assert!(compliant <= previous / 8.0, "k_c = {factor} k: deviation {compliant} after {previous}");
        previous = compliant;
    }
}

/// The soil's spring (Law::Soil) takes its force at the θ-point as the structure's K does: a mass of weight 100 N
/// on a soil spring of 100 N/m pressed in by the 1 m it settles (it never lets go) moves as the mass on the same
/// spring in K without weight, step for step to round-off (one interaction: the projection is exact), and at θ = ½
/// conserves ½mv² + ½kδ² + mgx to round-off. The compliant stop, forced at the step's end, loses energy on the same
/// motion.
#[test]
fn the_soil_spring_is_the_structures_spring_while_it_presses() {
    let (m, k, x0, h) = (1.0, 100.0, 0.01, 2e-3);
    let weight = DofForce { dof: 0, force: |_| -100.0 };
    let mut soil = stepper(m, 0.0, Law::Soil { gap: -1.0, stiffness: k, damping: 0.0 }, x0, h, SolverKind::Projection);
    let mut compliant = stepper(m, 0.0, Law::Compliant { gap: -1.0, stiffness: k }, x0, h, SolverKind::Projection);
    let mut reference = stepper(m, k, Law::Coulomb { capacity: 0.0 }, x0, h, SolverKind::Projection);
    let energy = |s: &MoreauJean| {
        let x = s.q()[0];
        0.5 * m * s.v()[0].powi(2) + 0.5 * k * (1.0 - x).powi(2) + 100.0 * x
    };
    let start = energy(&soil);
    // Ten periods of 2π/10 s.
    for _ in 0..3142 {
        soil.step(&weight).unwrap();
        compliant.step(&weight).unwrap();
        reference.step(&Unloaded).unwrap();
        assert!((soil.q()[0] - reference.q()[0]).abs() <= 1e-12, "{} vs {}", soil.q()[0], reference.q()[0]);
        // Energies of 50 J around a motion of 5 mJ: round-off of 1e-14 relative.
        assert!((energy(&soil) - start).abs() <= 1e-11, "{} vs {start}", energy(&soil));
        // The ledger closes with the soil's work: its terms are of the spring's 50 J.
        assert!(soil.energy.residual().abs() <= 1e-11, "{:e}", soil.energy.residual());
    }
    // The stop's end-of-step force removes ½k(Δδ)² a step, ~ωh/2 of the motion a radian (ωh = 0.02): 0.47 of the
    // 5 mJ over ten periods, measured.
    let motion = |s: &MoreauJean| energy(s) - 0.5 * k;
    assert!(motion(&compliant) < 0.6 * motion(&soil), "{} vs {}", motion(&compliant), motion(&soil));
}
