//! Trains populated with vehicles (docs/theory.md §12): quarter cars and rail cars on a train's axles carry their
//! axle loads and take their geometry from them, and each vehicle may have its own contact law.

use fem_beam::{Axle, BeamModel, Train};
use track::Load;
use track::PlacedInteractions;
use track::vehicle::builtin::QuarterCar;
use track::vehicle::{consist::VehicleSettings, wheel_rail::WheelRail};
use track::{RunSettings, Simulation};

/// The reference rail on firm ballast (k = 100 MN/m², 400 × the soft soil's 250 kN/m²), damping ratio 10 %, 120 m
/// in 0.5 m elements.
fn firm_track() -> BeamModel {
    let case = analytic::reference::uic60_on_soft_soil();
    let foundation = fem_beam::Foundation::linear(1e8, 0.0).with_damping_ratio(0.1, &case.beam).unwrap();
    let mesh = fem_beam::Mesh::new(120.0, 240).unwrap();
    BeamModel::new(case.beam, foundation, mesh, case.supports).unwrap()
}

/// A train's axle layout populated with quarter cars, each scaled to its axle's load (frequencies and damping
/// ratios kept): every wheel carries its axle's force statically (to 1e-12), and at 10 m/s on a firm track
/// (quasi-static) the wheel forces stay within 1 % of static (measured 0.3 %) and the largest deflection is the moving
/// forces' within 0.2 % (measured 0.03 %), over the nodes in [70, 110] m, away from the entry. Not on the soft-soil
/// reference track: its trough under the train is 0.13 m deep, the track under a wheel (~1e6 N/m) is as soft as
/// the suspension, and the bodies set swinging by the drop into the trough at entry still move the wheel loads by
/// ±10 % 90 m later (deflection +6 %).
#[test]
fn a_train_populated_with_quarter_cars_carries_its_axle_loads() {
    let model = firm_track();
    let axles = [(0.0, 80e3), (2.5, 80e3), (15.0, 120e3), (17.5, 120e3)];
    let train = Train {
        name: "test".into(),
        axles: axles.iter().map(|&(offset, force)| Axle { offset, force }).collect(),
        patches: Vec::new(),
    };
    let car = QuarterCar::default();
    let vehicles = VehicleSettings::populate(&car.vehicle().unwrap(), &train).unwrap();
    let mut settings = RunSettings::default();
    settings.moving.speed = 10.0;
    // h = 1 ms: the wheels' contact mode (195 Hz) needs ω_c·h ≤ 2 (track::vehicle::consist::MAX_CONTACT_STEP).
    settings.integration.load_advance = 0.01;
    settings.moving.load = Load::Train(train);
    settings.record.extremes_nodes = Some((70.0, 110.0));
    let forces = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    settings.moving.load = Load::Vehicles { vehicles, train: None };
    let cars = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    let wheels = &cars.vehicles.as_ref().unwrap().wheels;
    for (wheel, (offset, force)) in wheels.iter().zip(axles) {
        assert!((wheel.static_force / force - 1.0).abs() < 1e-12 && wheel.offset == offset);
    }
    for w in wheels {
        assert!(w.min_force > 0.99 * w.static_force && w.max_force < 1.01 * w.static_force, "{w:?}");
    }
    let ratio = cars.deflection.max_downward.value / forces.deflection.max_downward.value;
    eprintln!("max deflection: cars / forces = {ratio:.5}");
    assert!((ratio - 1.0).abs() < 2e-3);
}

/// Two 2-D rail cars (10 DOFs each, four wheels) 25 m apart at 20 m/s on the firm track: every wheel stands on a
/// quarter of its car (61.7 kN, to 1e-12), its load stays within 2 % of it over [70, 110] m (measured 0.8 %) and the
/// largest deflection is that of the cars' static wheel loads moving as forces within 1.5 % (measured 0.7 %): what
/// is left of the bodies' bounce (1.2 Hz, ζ ≈ 0.08 on the secondaries) set off by the entry 3.5 s before. The
/// energy closes at round-off.
#[test]
fn rail_cars_carry_their_weight_on_four_wheels() {
    use track::vehicle::consist::PlacedVehicle;
    use track::vehicle::rail_car::RailCar;
    let model = firm_track();
    let car = RailCar::default().vehicle().unwrap();
    let vehicles = VehicleSettings {
        vehicles: vec![PlacedVehicle::new(car.clone(), 0.0), PlacedVehicle::new(car, 25.0)],
        ..VehicleSettings::default()
    };
    let mut settings = RunSettings::default();
    settings.moving.speed = 20.0;
    settings.integration.load_advance = 0.02;
    settings.record.extremes_nodes = Some((70.0, 110.0));
    settings.moving.load = Load::Train(vehicles.static_train().unwrap());
    let forces = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    settings.moving.load = Load::Vehicles { vehicles, train: None };
    let cars = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    let quarter = RailCar::default().weight() / 4.0;
    let wheels = &cars.vehicles.as_ref().unwrap().wheels;
    assert_eq!(wheels.len(), 8);
    let worst = wheels.iter().map(|w| w.dynamic_increment()).fold(0.0, f64::max);
    let ratio = cars.deflection.max_downward.value / forces.deflection.max_downward.value;
    eprintln!("largest ΔQ/Q₀ {worst:.4}, deflection cars/forces {ratio:.5}");
    assert!(wheels.iter().all(|w| (w.static_force / quarter - 1.0).abs() < 1e-12));
    assert!(worst < 0.02 && (ratio - 1.0).abs() < 1.5e-2);
    let e = &cars.energy;
    assert!(e.residual().abs() < 1e-9 * e.load_work.abs().max(e.contact_work.abs()), "{}", e.residual());
}

/// A train's axle layout populated with rail cars, four axles each: two cars of different geometry and load
/// (wheelbases 2.5 m and 3 m, bogie centres 15 m and 18 m apart, 100 kN and 150 kN axles) built from the axles —
/// every wheel at its axle and on its axle's force statically (1e-12). At 20 m/s on the firm track, standing on the
/// loaded track at the start, the wheel loads ring by ±2.4 % (100 kN car) and ±2.0 % (150 kN car) at the 40 Hz of
/// the 0.5 m elements' node crossings (w″ of the Hermite rail jumps at nodes; the same axles laid out as the default
/// car give the default car's 0.66 %, so the layout is read right), and the largest deflection is the axles' as
/// moving forces within 1.4 %: allowed 3 % and 2 %. Layouts that are no cars are refused naming the car: unequal
/// wheelbases, unequal loads, an axle count that is not a multiple of four.
#[test]
fn a_train_populated_with_rail_cars_takes_its_geometry_from_the_axles() {
    use track::vehicle::rail_car::RailCar;
    let model = firm_track();
    let train = |axles: &[(f64, f64)]| Train {
        name: "test".into(),
        axles: axles.iter().map(|&(offset, force)| Axle { offset, force }).collect(),
        patches: Vec::new(),
    };
    let axles = [
        (0.0, 100e3),
        (2.5, 100e3),
        (15.0, 100e3),
        (17.5, 100e3),
        (22.0, 150e3),
        (25.0, 150e3),
        (40.0, 150e3),
        (43.0, 150e3),
    ];
    let vehicles = VehicleSettings::populate_cars(&RailCar::default(), &train(&axles)).unwrap();
    let mut settings = RunSettings::default();
    // Standing on the loaded track at the start (the last wheel on the beam at 7 m): no bounce from entering.
    settings.moving.initial = track::InitialState::Static { position: 50.0 };
    settings.moving.speed = 20.0;
    settings.integration.load_advance = 0.02;
    settings.record.extremes_nodes = Some((70.0, 110.0));
    settings.moving.load = Load::Train(train(&axles));
    let forces = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    settings.moving.load = Load::Vehicles { vehicles, train: None };
    let cars = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    let wheels = &cars.vehicles.as_ref().unwrap().wheels;
    assert_eq!(wheels.len(), 8);
    for (wheel, (offset, force)) in wheels.iter().zip(axles) {
        assert!((wheel.static_force / force - 1.0).abs() < 1e-12 && (wheel.offset - offset).abs() < 1e-12, "{wheel:?}");
    }
    let worst = wheels.iter().map(|w| w.dynamic_increment()).fold(0.0, f64::max);
    let ratio = cars.deflection.max_downward.value / forces.deflection.max_downward.value;
    eprintln!("largest ΔQ/Q₀ {worst:.4}, deflection cars/forces {ratio:.5}");
    assert!(worst < 0.03 && (ratio - 1.0).abs() < 2e-2);
    for (bad, field) in [
        (vec![(0.0, 1e5), (2.5, 1e5), (15.0, 1e5), (18.0, 1e5)], "wheelbases differ"),
        (vec![(0.0, 1e5), (2.5, 1e5), (15.0, 1e5), (17.5, 2e5)], "axle forces must agree"),
        (vec![(0.0, 1e5), (2.5, 1e5), (15.0, 1e5)], "four axles each"),
    ] {
        let error = VehicleSettings::populate_cars(&RailCar::default(), &train(&bad)).unwrap_err();
        assert!(error.to_string().contains("vehicle.train") && error.to_string().contains(field), "{error}");
    }
}

/// A contact law per vehicle: a quarter car on Hertz contact (the run's) and one on a 5e8 N/m linear spring (its
/// own) start pressed into their own laws — (Q₀/C_H)^{2/3} = 98 µm and Q₀/k_c = 167 µm — so each first step's
/// force is its static load within 1e-3 (measured 1.3e-5: the first step's motion; either law's penetration in the
/// other's spring would be 41 % and 122 % off); the run's contact reads "mixed".
#[test]
fn each_vehicle_may_have_its_own_contact_law() {
    use track::vehicle::consist::PlacedVehicle;
    let model = firm_track();
    let car = QuarterCar::default().vehicle().unwrap();
    let linear =
        PlacedVehicle { contact: Some(WheelRail::Linear { stiffness: 5e8 }), ..PlacedVehicle::new(car.clone(), 20.0) };
    let vehicles =
        VehicleSettings { vehicles: vec![PlacedVehicle::new(car, 0.0), linear], ..VehicleSettings::default() };
    assert_eq!(vehicles.contact_name(), "mixed");
    let mut settings = RunSettings::default();
    settings.moving.speed = 10.0;
    settings.integration.load_advance = 0.01;
    settings.moving.initial = track::InitialState::Static { position: 40.0 };
    settings.moving.load = Load::Vehicles { vehicles, train: None };
    let run = Simulation::new(&model, &PlacedInteractions::new(), &settings).unwrap().run().unwrap();
    for wheel in &run.vehicles.as_ref().unwrap().wheels {
        let first = wheel.history.force[0] / wheel.static_force - 1.0;
        eprintln!("wheel {}: first step {first:.2e} of Q₀", wheel.vehicle);
        assert!(first.abs() < 1e-3);
    }
}
