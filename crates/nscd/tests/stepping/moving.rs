//! Moving interactions (docs/theory.md §9): rows, gaps and rheonomic velocities set by the update phase every step.
//! A moving interaction that stays put is the fixed one to round-off; a mass riding on a rigid wavy ground (the contact
//! point moving at speed v, a rheonomic constraint) presses with m(g + r̈) and leaves the ground exactly where that
//! force would turn tensile.

use banded::SymmetricBanded;
use friction::{InteractionKind, InteractionRow, InteractionSet, Law};
use nscd::forcing::DofForce;
use nscd::solver::{SolverKind, SolverSettings};
use nscd::stepper::Integration;
use nscd::{Forcing, Interactions, LinearSystem, MoreauJean, MovingInteraction, MovingState};
use std::f64::consts::PI;

const GRAVITY: f64 = 9.81;

/// A stop on one DOF, written as a moving interaction that never moves: row e_dof, gap g₀ + q_dof.
#[derive(Debug)]
struct StillStop {
    dof: usize,
    law: Law,
    gap: f64,
}

impl MovingInteraction for StillStop {
    fn law(&self) -> Law {
        self.law
    }
    fn kind(&self) -> InteractionKind {
        InteractionKind::Contact
    }
    fn update(&mut self, _: f64, _: f64, q: &[f64], v: &[f64], row: &mut InteractionRow) -> MovingState {
        row.set_entries([(self.dof, 1.0)]);
        MovingState { gap: self.gap + q[self.dof], velocity: v[self.dof], rheonomic: 0.0 }
    }
    fn gap(&self, _: f64, q: &[f64], row: &mut InteractionRow) -> f64 {
        row.set_entries([(self.dof, 1.0)]);
        self.gap + q[self.dof]
    }
}

/// A three-mass chain (springs ground–0–1–2), driven on mass 0, a friction device on mass 1 and a unilateral stop
/// under mass 2 — the stop given as a fixed row or as a moving interaction that stays put.
fn chain(law: Law, moving: bool, kind: SolverKind) -> (Vec<f64>, usize, f64, f64) {
    let mut mass = SymmetricBanded::zeros(3, 1);
    let mut stiffness = SymmetricBanded::zeros(3, 1);
    for (i, m) in [1.0, 2.0, 1.5].into_iter().enumerate() {
        mass.add(i, i, m);
    }
    for (i, j, k) in [(0, 0, 100.0), (0, 1, 200.0), (1, 2, 150.0)] {
        stiffness.add(i, i, if i == j { k } else { 0.0 });
        if i != j {
            stiffness.add(i, i, k);
            stiffness.add(j, j, k);
            stiffness.add(j, i, -k);
        }
    }
    let system = LinearSystem::new(mass, SymmetricBanded::zeros(3, 0), stiffness);
    let mut fixed = InteractionSet::new();
    fixed.push(InteractionRow::from_entries([(1, 1.0)]), Law::Coulomb { capacity: 5.0 }, InteractionKind::Friction);
    let gap = 2e-3;
    let interactions = if moving {
        Interactions { fixed, moving: vec![Box::new(StillStop { dof: 2, law, gap })] }
    } else {
        let fixed_law = match law {
            Law::Signorini { restitution, .. } => Law::Signorini { gap, restitution },
            Law::Compliant { stiffness, .. } => Law::Compliant { gap, stiffness },
            other => other,
        };
        fixed.push(InteractionRow::from_entries([(2, 1.0)]), fixed_law, InteractionKind::Contact);
        Interactions::from(fixed)
    };
    let integration = Integration::theta(0.5, 1e-3);
    // Clarabel is held to 1e-5 of the velocity scale: its own stopping criteria leave law residuals up to ~1e-6 of
    // it (seen: 1.04e-6 on an impact step), just past its 1e-6 acceptance.
    let tolerance = if kind == SolverKind::Clarabel { 1e-5 } else { 1e-10 };
    let settings = SolverSettings { kind, tolerance, ..SolverSettings::default() };
    let mut stepper =
        MoreauJean::build(&system, interactions, integration, &settings, vec![0.0; 3], vec![0.0; 3]).unwrap();
    let drive = DofForce { dof: 0, force: |t: f64| 8.0 * (9.0 * t).sin() };
    let (mut pressed, mut lowest) = (0, f64::INFINITY);
    for _ in 0..4000 {
        stepper.step(&drive).unwrap();
        pressed += usize::from(stepper.p[1] > 0.0);
        lowest = lowest.min(gap + stepper.q()[2]);
        let e = &stepper.energy;
        assert!(e.residual().abs() <= 1e-12 * e.load_work.abs().max(1e-3) * stepper.steps as f64);
    }
    (stepper.q().to_vec(), pressed, stepper.energy.contact_work, lowest)
}

/// The same compliant stop, fixed or moving-but-still, gives the same run to round-off (projection: the same
/// arithmetic but for the truncation of stored responses), and within the solver tolerance with Clarabel (which
/// rebuilds its set-up every step for moving rows).
#[test]
fn a_moving_interaction_that_stays_put_is_the_fixed_one() {
    for law in [Law::Compliant { gap: 0.0, stiffness: 5e4 }] {
        let (fixed, pressed, work, _) = chain(law, false, SolverKind::Projection);
        let (moving, pressed_moving, work_moving, _) = chain(law, true, SolverKind::Projection);
        // Rigid impacts press for a step each (5 seen), the compliant stop for many.
        assert!(pressed >= 3, "{law:?}: the stop is reached ({pressed} steps pressed)");
        assert!(work < 0.0, "{law:?}: the stop takes energy ({work} J)");
        // The same arithmetic but for round-off: the fixed row's response is truncated below 1e-17 of its largest
        // entry and its W entries symmetrised, the moving row's are dense and recomputed each step.
        assert_eq!(pressed, pressed_moving);
        let scale = fixed.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!((work - work_moving).abs() <= 1e-9 * work.abs(), "{law:?}: contact work {work} vs {work_moving}");
        for (a, b) in fixed.iter().zip(&moving) {
            assert!((a - b).abs() <= 1e-9 * scale, "{law:?}: {fixed:?} vs {moving:?}");
        }
        if cfg!(feature = "clarabel") {
            let (clarabel, _, _, _) = chain(law, true, SolverKind::Clarabel);
            let scale = fixed.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            // Each step to 1e-5 of its velocity scale; 4000 steps of a chain with friction and impacts keep the
            // states within 1e-3 of their scale (a stick–slip transition a step apart moves a state by ~h·v).
            for (a, b) in clarabel.iter().zip(&fixed) {
                assert!((a - b).abs() <= 1e-3 * scale, "{law:?}: Clarabel {a} vs {b}");
            }
        }
    }
}

/// A rigid stop as a moving interaction has its positions projected ([`nscd::position`]): it never ends a step
/// penetrating, where the fixed stop sinks in by O(h·U) at each impact; otherwise the runs agree.
#[test]
fn a_moving_rigid_stop_is_the_fixed_one_without_penetration() {
    let law = Law::Signorini { gap: 0.0, restitution: 0.5 };
    let (fixed, pressed, work, fixed_lowest) = chain(law, false, SolverKind::Projection);
    let (moving, pressed_moving, work_moving, lowest) = chain(law, true, SolverKind::Projection);
    let scale = fixed.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let apart = fixed.iter().zip(&moving).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    // Five impacts each; the fixed stop sank in by up to 1.5e-4 m (5 % of its 2e-3 m gap), the projected one by 0.
    assert_eq!(pressed, pressed_moving);
    assert!(lowest >= -1e-12, "the projected stop ends {lowest:e} m in");
    assert!(fixed_lowest < -1e-5, "the fixed stop sinks in ({fixed_lowest:e} m)");
    // The runs differ by about what the projection removed: measured 8.8e-4 of the state scale for sinkings of
    // 1.5e-4 m (0.4 of it).
    let sunk = -fixed_lowest / scale;
    assert!(apart <= 5.0 * sunk, "states {apart:e} apart (of the scale), sinkings {sunk:e}");
    assert!((work - work_moving).abs() <= 1e-2 * work.abs(), "contact work {work} vs {work_moving}");
}

/// A mass riding at speed v on rigid ground of height r(x) = a sin(2πx/λ): the contact point moves, so the gap
/// g = z − r(vt) is rheonomic, U = ż − v r′(vt).
#[derive(Debug)]
struct WavyGround {
    dof: usize,
    amplitude: f64,
    wavelength: f64,
    speed: f64,
}

impl WavyGround {
    fn height(&self, x: f64) -> f64 {
        self.amplitude * (2.0 * PI * x / self.wavelength).sin()
    }
    fn slope(&self, x: f64) -> f64 {
        self.amplitude * 2.0 * PI / self.wavelength * (2.0 * PI * x / self.wavelength).cos()
    }
}

impl MovingInteraction for WavyGround {
    fn law(&self) -> Law {
        Law::Signorini { gap: 0.0, restitution: 0.0 }
    }
    fn kind(&self) -> InteractionKind {
        InteractionKind::Contact
    }
    fn update(&mut self, time: f64, step: f64, q: &[f64], v: &[f64], row: &mut InteractionRow) -> MovingState {
        let (x, x_next) = (self.speed * time, self.speed * (time + step));
        row.set_entries([(self.dof, 1.0)]);
        MovingState {
            gap: q[self.dof] - self.height(x),
            velocity: v[self.dof] - self.speed * self.slope(x),
            rheonomic: -self.speed * self.slope(x_next),
        }
    }
    fn gap(&self, time: f64, q: &[f64], row: &mut InteractionRow) -> f64 {
        row.set_entries([(self.dof, 1.0)]);
        q[self.dof] - self.height(self.speed * time)
    }
}

/// (t, z, r, impulse) per step of a 1 kg mass under gravity on the wavy ground with aω² = `ratio`·g, ω = 2πv/λ,
/// started on the ground with its velocity.
fn ride(ratio: f64, h: f64, end: f64) -> Vec<(f64, f64, f64, f64)> {
    let (speed, wavelength) = (10.0, 2.0);
    let omega = 2.0 * PI * speed / wavelength;
    let ground = WavyGround { dof: 0, amplitude: ratio * GRAVITY / (omega * omega), wavelength, speed };
    let profile = WavyGround { ..ground };
    let mut one = SymmetricBanded::zeros(1, 0);
    one.add(0, 0, 1.0);
    let system = LinearSystem::new(one, SymmetricBanded::zeros(1, 0), SymmetricBanded::zeros(1, 0));
    let interactions = Interactions { fixed: InteractionSet::new(), moving: vec![Box::new(ground)] };
    let integration = Integration::theta(0.5, h);
    let settings = SolverSettings { kind: SolverKind::Projection, tolerance: 1e-12, ..SolverSettings::default() };
    let v0 = speed * profile.slope(0.0);
    let mut stepper = MoreauJean::build(&system, interactions, integration, &settings, vec![0.0], vec![v0]).unwrap();
    let gravity = DofForce { dof: 0, force: |_| -GRAVITY };
    let mut out = Vec::new();
    while stepper.time < end {
        stepper.step(&gravity as &dyn Forcing).unwrap();
        let e = &stepper.energy;
        assert!(e.residual().abs() <= 1e-12 * e.load_work.abs().max(1.0) * stepper.steps as f64);
        out.push((stepper.time, stepper.q()[0], profile.height(speed * stepper.time), stepper.p[0]));
    }
    out
}

/// aω² = g/2: the mass stays on the ground; it follows r and the ground pushes with N = m(g − aω² sin ωt). The
/// projection puts the mass back on the ground at every step's end and keeps the closed contact in the index set, so
/// it presses at every step (before the projection, a contact a few nanometres open rested for a step now and
/// then). Each step's impulse is compared with ∫N dt over its step, and over windows of 20 steps.
#[test]
fn a_mass_rides_a_gentle_wave_pressing_with_m_g_plus_r_dot_dot() {
    let omega = 2.0 * PI * 10.0 / 2.0;
    let amplitude = 0.5 * GRAVITY / (omega * omega);
    let expected =
        |t0: f64, t1: f64| GRAVITY * (t1 - t0) + amplitude * omega * ((omega * t1).cos() - (omega * t0).cos());
    for h in [2e-4, 1e-4] {
        let history = ride(0.5, h, 0.5);
        let track = history.iter().fold(0.0f64, |m, s| m.max((s.1 - s.2).abs())) / amplitude;
        let resting = history.iter().filter(|s| s.3 == 0.0).count();
        let step = history.iter().fold(0.0f64, |m, s| m.max((s.3 - expected(s.0 - h, s.0)).abs())) / (GRAVITY * h);
        let window = 20;
        let mut force: f64 = 0.0;
        for chunk in history.chunks_exact(window) {
            let (t0, t1) = (chunk[0].0 - h, chunk[window - 1].0);
            let impulse: f64 = chunk.iter().map(|s| s.3).sum();
            force = force.max((impulse - expected(t0, t1)).abs() / (GRAVITY * (t1 - t0)));
        }
        assert_eq!(resting, 0, "h = {h}: {resting} steps without contact");
        // On the ground at every step's end to round-off (measured 1e-24 of the amplitude).
        assert!(track <= 1e-12, "h = {h}: {track:e} of the amplitude off the ground");
        // The velocity follows the ground's exactly, so each step's impulse is gravity's and the change of momentum:
        // ∫N dt over the step to round-off (measured 4e-13 and 7e-13 of m g h), and over windows (1.4e-13).
        assert!(step <= 1e-10, "h = {h}: a step's impulse off by {step:e} of m g h");
        assert!(force <= 1e-10, "h = {h}: windowed impulse off by {force:e} of m g T");
    }
}

/// aω² = 2g: the ground would have to pull once sin ωt > g/(aω²) = ½, i.e. from ωt = π/6; the mass leaves there
/// (the first step without impulse lies within a step of t = π/(6ω)), flies above the ground and lands again.
#[test]
fn a_mass_leaves_a_steep_wave_where_the_force_would_turn_tensile() {
    let h = 1e-4;
    let omega = 2.0 * PI * 10.0 / 2.0;
    let history = ride(2.0, h, 0.2);
    let lift = history.iter().find(|s| s.3 == 0.0).expect("the mass lifts off").0;
    let expected = PI / 6.0 / omega;
    assert!((lift - expected).abs() <= 2.0 * h, "lift-off at {lift} s, expected {expected} s");
    let flying = history.iter().filter(|s| s.3 == 0.0 && s.1 - s.2 > 1e-6).count();
    assert!(flying > 10, "it flies ({flying} steps above the ground)");
    let landed = history.iter().skip_while(|s| s.0 <= lift).find(|s| s.3 != 0.0);
    assert!(landed.is_some(), "it lands again");
    // Never below the ground by more than a step's travel at the landing speed.
    let worst = history.iter().map(|s| s.2 - s.1).fold(f64::NEG_INFINITY, f64::max);
    assert!(worst <= 1e-3, "penetration {worst}");
}

/// Two masses joined by a stiff spring (k = 1e5 N/m), each riding its own wavy ground half a wave apart: with
/// h = 1 ms, M̂'s coupling h²θ²k is 2.5 % of the masses, so the projection's W is full and Gauss–Seidel iterates.
/// Pressed by 5 kN and 10 kN (the spring pulls with at most 400 N), both stay on, every step ends with both gaps
/// closed to the projection's tolerance, and the energy closes with the projection booked.
#[test]
fn coupled_rigid_contacts_are_projected_together() {
    let (speed, wavelength) = (10.0, 2.0);
    let omega = 2.0 * PI * speed / wavelength;
    let amplitude = 0.2 * GRAVITY / (omega * omega);
    let grounds = [0, 1].map(|dof| WavyGround { dof, amplitude, wavelength, speed });
    let mut mass = SymmetricBanded::zeros(2, 1);
    mass.add(0, 0, 1.0);
    mass.add(1, 1, 2.0);
    let mut stiffness = SymmetricBanded::zeros(2, 1);
    let k = 1e5;
    stiffness.add(0, 0, k);
    stiffness.add(1, 1, k);
    stiffness.add(1, 0, -k);
    let system = LinearSystem::new(mass, SymmetricBanded::zeros(2, 1), stiffness);
    // The second ground in opposite phase to the first; both masses start on their grounds with their velocities.
    let v0 = speed * grounds[0].slope(0.0);
    let shifted = |g: WavyGround| WavyGround { amplitude: -g.amplitude, ..g };
    let [first, second] = grounds;
    let moving: Vec<Box<dyn MovingInteraction>> = vec![Box::new(first), Box::new(shifted(second))];
    let interactions = Interactions { fixed: InteractionSet::new(), moving };
    let settings = SolverSettings { kind: SolverKind::Projection, tolerance: 1e-12, ..SolverSettings::default() };
    let integration = Integration::theta(0.5, 1e-3);
    let mut stepper =
        MoreauJean::build(&system, interactions, integration, &settings, vec![0.0; 2], vec![v0, -v0]).unwrap();
    let gravity = PressingBoth;
    let (mut worst, mut resting, mut peak, mut sweeps) = (0.0f64, 0, 0.0f64, 0);
    let check = WavyGround { dof: 0, amplitude, wavelength, speed };
    for _ in 0..600 {
        stepper.step(&gravity).unwrap();
        let x = speed * stepper.time;
        let gaps = [stepper.q()[0] - check.height(x), stepper.q()[1] + check.height(x)];
        worst = worst.max(gaps[0].abs()).max(gaps[1].abs());
        resting += stepper.p.iter().filter(|&&p| p <= 0.0).count();
        peak = peak.max(stepper.energy.kinetic + stepper.energy.strain);
        sweeps = sweeps.max(stepper.last_projection.sweeps);
    }
    let e = &stepper.energy;
    assert_eq!(resting, 0, "{resting} contact-steps without force");
    assert!(worst <= 1e-12, "gap left {worst:e} m");
    // One contact is solved in one sweep and confirmed by a second; the coupled pair takes three (measured).
    assert!(sweeps > 2 && e.projection_work != 0.0, "the coupled pair was projected ({sweeps} sweeps)");
    assert!(e.residual().abs() <= 1e-12 * peak, "residual {:e} of {peak} J: {e:?}", e.residual());
}

/// The loads pressing the two masses of [`coupled_rigid_contacts_are_projected_together`] (N).
struct PressingBoth;

impl Forcing for PressingBoth {
    fn add_to(&self, _: f64, scale: f64, out: &mut [f64]) {
        out[0] -= scale * 5e3;
        out[1] -= scale * 1e4;
    }
    fn power(&self, _: f64, v: &[f64]) -> f64 {
        -5e3 * v[0] - 1e4 * v[1]
    }
}

/// The interior point takes a moving row (by its bordered Newton solve): the chain with the compliant stop given as
/// a moving interaction runs on it and ends where projection ends. Both are held to 1e-10 per step; over 4000 steps
/// of friction and impacts the two trajectories drift apart through the stick–slip history (measured 6.9e-7 of the
/// state scale, 3.5e-7 of the contact work), bounded at 1e-5. (The steps pressed are not compared: an open stop holds
/// p = 0 exactly under projection and p ≈ 1e-20 inside the interior point's bound.)
#[test]
fn the_interior_point_takes_moving_interactions() {
    let law = Law::Compliant { gap: 0.0, stiffness: 5e4 };
    let (projection, pressed, work, _) = chain(law, true, SolverKind::Projection);
    let (interior, _, work_interior, _) = chain(law, true, SolverKind::InteriorPoint);
    assert!(pressed >= 3 && work < 0.0, "the stop is reached ({pressed} steps) and takes energy ({work} J)");
    let scale = projection.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let apart = projection.iter().zip(&interior).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    assert!(apart <= 1e-5, "states {apart:e} of their scale apart");
    assert!((work - work_interior).abs() <= 1e-5 * work.abs(), "contact work {work} vs {work_interior}");
}
