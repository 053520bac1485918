//! A vehicle on the beam (docs/theory.md §12): the wheel–rail contact as a moving compliant interaction between the
//! beam block and the vehicle block of one system.

use super::common::beam;
use fem_beam::BeamModel;
use irregularity::{Profile, WheelTrack};
use nscd::solver::{SolverKind, SolverSettings};
use track::Load;
use track::PlacedInteractions;
use track::vehicle::rail::WheelOnBeam;
use track::vehicle::{Vehicle, Wheel};
use track::vehicle::{consist::VehicleSettings, wheel_rail::WheelRail};
use track::{RunSettings, Simulation};

const FORCE: f64 = 83.4e3;
/// A stiff contact, of the order of a linearised Hertz contact (~1.5e9 N/m at 83 kN): 1e9 N/m.
const CONTACT: f64 = 1e9;

/// A point mass m pressed by a force F (its "weight", kept at F while m varies): the moving mass.
fn pressed_mass(mass: f64) -> Vehicle {
    Vehicle {
        name: "pressed mass".into(),
        mass: vec![mass],
        damping: vec![0.0],
        stiffness: vec![0.0],
        weight: vec![-FORCE],
        wheels: vec![Wheel { dof: 0, offset: 0.0 }],
        body: 0,
    }
}

/// What a vehicle run gives: the beam's deflection at the recorded section after every step, the contact impulse of
/// every step, and the energy identity's residual over the load work.
struct VehicleRun {
    deflection: Vec<f64>,
    impulses: Vec<f64>,
    residual: f64,
}

/// `vehicle` entering the beam at x = 0, t = 0 at `speed` from static equilibrium, through [`Simulation`] with the
/// step h = `advance`/v and θ = ½, until it leaves at x = L; the deflection recorded at `section`.
fn vehicle_run(
    model: &BeamModel,
    (vehicle, contact): (&Vehicle, WheelRail),
    (speed, advance): (f64, f64),
    section: f64,
) -> VehicleRun {
    let mut settings = RunSettings::default();
    settings.moving.speed = speed;
    settings.integration.load_advance = advance;
    settings.moving.load = Load::Vehicles {
        vehicles: VehicleSettings { contact, ..VehicleSettings::single(vehicle.clone()) },
        train: None,
    };
    settings.integration.solver =
        SolverSettings { kind: SolverKind::Projection, tolerance: 1e-12, ..Default::default() };
    settings.record.sections = vec![section];
    let run = Simulation::new(model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    let wheel = &run.vehicles.as_ref().unwrap().wheels[0];
    let e = &run.energy;
    VehicleRun {
        deflection: run.histories[0].deflection[1..].to_vec(),
        impulses: wheel.history.force.iter().map(|f| f * run.step).collect(),
        residual: e.residual() / e.load_work.abs().max(1.0),
    }
}

/// m → 0 with F fixed: the moving mass tends to the moving force. Against the moving-force run of the same beam and
/// step, the mid-span deflection history differs by 3.3e-2, 3.4e-3, 3.4e-4 of its peak at m = 20, 2, 0.2 kg — O(m),
/// each tenfold step of the mass cutting it 9.8 and 10.0 times (8–12 allowed: the next terms are O(m²)) — with the
/// linear contact and with the rigid one alike (3.34e-2, 3.41e-3, 3.42e-4). The step
/// resolves the lightest mass's contact mode; at Δx = 0.1 m the difference levelled off at 2.5e-4 of the peak below
/// 0.2 kg (the two discretisations' load positions, Ψ(x_{k+½}) against the θ-weighted (Ψ(x_k) + Ψ(x_{k+1}))/2). The
/// contact impulses tend to F·h (within 1.1e-3 at 0.2 kg) and never vanish; the energy identity closes to 1e-9 of
/// the load work with the contact spring's energy booked.
#[test]
fn a_vanishing_moving_mass_is_the_moving_force() {
    // Δx = 2.5 mm, h = 25 µs: the lightest mass's contact mode √(k_c/m) = 7.1e4 rad/s at ω_c·h = 1.8 ≤ 2
    // (track::vehicle::consist::MAX_CONTACT_STEP).
    const ADVANCE: f64 = 0.0025;
    let model = beam(60.0, 60);
    let speed = 100.0;
    let mut settings = RunSettings::default();
    settings.moving.speed = speed;
    settings.moving.load = Load::Force(FORCE);
    settings.integration.load_advance = ADVANCE;
    settings.record.sections = vec![30.0];
    let force_run = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    let reference = &force_run.histories[0].deflection[1..];
    let scale = reference.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let nominal = FORCE * ADVANCE / speed;
    for contact in [WheelRail::Linear { stiffness: CONTACT }, WheelRail::Rigid { restitution: 0.0 }] {
        let mut differences = Vec::new();
        for mass in [20.0, 2.0, 0.2] {
            let run = vehicle_run(&model, (&pressed_mass(mass), contact), (speed, ADVANCE), 30.0);
            let difference =
                run.deflection.iter().zip(reference).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
            let impulse = run.impulses.iter().map(|p| (p / nominal - 1.0).abs()).fold(0.0, f64::max);
            eprintln!(
                "{} m = {mass} kg: deflection {difference:.3e} of the peak, impulses within {impulse:.3e} of F·h",
                contact.name()
            );
            assert!(run.impulses.iter().all(|&p| p > 0.0), "the wheel stays on the rail");
            assert!(run.residual.abs() < 1e-9, "energy residual {}", run.residual);
            differences.push(difference);
        }
        for pair in differences.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!((8.0..12.0).contains(&ratio), "difference ratio {ratio} for a tenth of the mass");
        }
        assert!(differences[2] < 1e-3);
    }
}

/// A contact law out of range is refused with its field named.
#[test]
fn a_bad_contact_is_refused_naming_its_field() {
    let model = beam(60.0, 60);
    for (contact, field) in [
        (WheelRail::Linear { stiffness: 0.0 }, "vehicle.contact_stiffness"),
        (WheelRail::Hertz { coefficient: f64::NAN }, "vehicle.hertz_coefficient"),
        (WheelRail::Rigid { restitution: 1.5 }, "vehicle.restitution"),
    ] {
        let track = WheelTrack::rail(Profile::Smooth);
        let error = WheelOnBeam::new(&model, (0, 122), fem_beam::Motion::constant(0.0, 100.0), track, contact, 0.5)
            .unwrap_err();
        assert!(error.to_string().contains(field), "{error}");
    }
}

/// A quarter car whose suspension stiffens tends to the moving mass of its whole mass (M_s + m_u), as O(1/k_s) once
/// the suspension is much stiffer than the contact spring it is in series with (k_c = 1e9 N/m): the mid-span
/// histories differ by 0.35, 9.3e-3, 2.3e-3, 2.5e-4 and 2.6e-5 of the peak at k_s = 1.2e6 (the default car), 1e8,
/// 1e9, 1e10 and 1e11 N/m — between 1e8 and 1e9 the series stiffness k_s k_c/(k_s + k_c) still moves (0.09 → 0.5
/// k_c), from 1e10 each tenfold k_s cuts the difference 9.7 times (8–12 allowed: the next term is O(1/k_s²)). The
/// vehicles start in static equilibrium (body and wheel pressed together), so the stiff body–wheel mode (1.7 kHz at
/// 1e11 N/m, far above what h = 1 ms resolves) is not set off. Energy at round-off in every run.
#[test]
fn a_stiff_quarter_car_is_the_moving_mass() {
    use track::vehicle::builtin::{MovingMass, QuarterCar};
    let model = beam(60.0, 60);
    let speed = 100.0;
    let car = QuarterCar { suspension_damping: 0.0, ..QuarterCar::default() };
    let linear = WheelRail::Linear { stiffness: CONTACT };
    let mass = vehicle_run(
        &model,
        (&MovingMass { mass: car.body_mass + car.wheel_mass }.vehicle().unwrap(), linear),
        (speed, 0.1),
        30.0,
    );
    let scale = mass.deflection.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let mut differences = Vec::new();
    for stiffness in [1.2e6, 1e10, 1e11] {
        let quarter = QuarterCar { suspension_stiffness: stiffness, ..car };
        let run = vehicle_run(&model, (&quarter.vehicle().unwrap(), linear), (speed, 0.1), 30.0);
        let difference =
            run.deflection.iter().zip(&mass.deflection).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
        eprintln!("k_s = {stiffness:e} N/m: deflection differs by {difference:.3e} of the peak");
        assert!(run.residual.abs() < 1e-9);
        differences.push(difference);
    }
    assert!(differences[0] > 0.1, "a soft suspension is no moving mass: {}", differences[0]);
    let ratio = differences[1] / differences[2];
    assert!(differences[1] < 5e-4 && (8.0..12.0).contains(&ratio), "{differences:?}");
}
