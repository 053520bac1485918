//! The time step h = min(Δx/v, h_max): the longest step caps the load advance's step where that one would not
//! resolve the run, and only there.

use super::common::beam;
use track::co_moving::{CoMovingSettings, run_co_moving};
use track::vehicle::builtin::QuarterCar;
use track::vehicle::consist::VehicleSettings;
use track::{Load, PlacedInteractions, RunResult, RunSettings, Simulation, TrackError};

/// A quarter car at `speed` with load advance `advance` and longest step `max_step`, recording x = 30 m.
fn settings(speed: f64, advance: f64, max_step: Option<f64>) -> RunSettings {
    let mut settings = RunSettings::default();
    settings.moving.speed = speed;
    let car = QuarterCar::default().vehicle().unwrap();
    settings.moving.load = Load::Vehicles { vehicles: VehicleSettings::single(car), train: None };
    settings.integration.load_advance = advance;
    settings.integration.max_step = max_step;
    settings.record.sections = vec![30.0];
    settings
}

fn run(settings: &RunSettings) -> Result<RunResult, TrackError> {
    Simulation::new(&beam(60.0, 120), &PlacedInteractions::new(), settings)?.run()
}

/// At 10 m/s a load advance of 0.1 m (h = 0.01 s) cannot resolve the ~180 Hz contact mode and is refused, naming
/// the longest step that would; capped at h_max = 0.016 m / 10 m/s the run is the one of a 0.016 m advance bit for
/// bit (the same h, every step). At 100 m/s the same cap is above Δx/v = 1 ms and changes nothing.
#[test]
fn the_longest_step_caps_only_where_the_advance_is_too_long() {
    let refused = run(&settings(10.0, 0.1, None)).unwrap_err().to_string();
    assert!(refused.contains("load_advance") && refused.contains("max_step"), "{refused}");
    let h_max = 0.016 / 10.0;
    let capped = settings(10.0, 0.1, Some(h_max));
    assert!(capped.step_is_capped() && capped.time_step() == h_max);
    let (a, b) = (run(&capped).unwrap(), run(&settings(10.0, 0.016, None)).unwrap());
    assert_eq!(a.histories[0].deflection, b.histories[0].deflection);
    assert_eq!((a.statistics.steps, a.step), (b.statistics.steps, b.step));
    let fast = settings(100.0, 0.1, Some(h_max));
    assert!(!fast.step_is_capped() && fast.time_step() == 0.1 / 100.0);
    let (a, b) = (run(&fast).unwrap(), run(&settings(100.0, 0.1, None)).unwrap());
    assert_eq!(
        (a.histories[0].deflection.clone(), a.statistics.steps),
        (b.histories[0].deflection.clone(), b.statistics.steps)
    );
}

/// A longest step that is not a positive time is refused by name; a co-moving window, which moves by whole load
/// advances, refuses a step capped below Δx/v.
#[test]
fn a_longest_step_must_be_a_positive_time_that_a_window_can_take() {
    for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        let message = run(&settings(100.0, 0.1, Some(bad))).unwrap_err().to_string();
        assert!(message.contains("max_step"), "{bad}: {message}");
    }
    let mut window = RunSettings::default();
    window.moving.speed = 100.0;
    window.integration.load_advance = 0.05;
    window.integration.max_step = Some(1e-4);
    let case = analytic::reference::uic60_on_soft_soil();
    let free_clamped = fem_beam::Supports { left: fem_beam::Support::Free, right: fem_beam::Support::Clamped };
    let mesh = fem_beam::Mesh::new(60.0, 240).unwrap();
    let model = fem_beam::BeamModel::new(case.beam, case.foundation, mesh, free_clamped).unwrap();
    let at = CoMovingSettings { load_at: 30.0, track_length: 100.0, middle: (15.0, 45.0) };
    let message = run_co_moving(&model, &PlacedInteractions::new(), &window, &at).unwrap_err().to_string();
    assert!(message.contains("max_step"), "{message}");
}
