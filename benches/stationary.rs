//! The stationary wave on the infinite track (docs/theory.md §14): a 100-speed sweep by continuation, per soil and
//! with ballast friction, and
//! a nonlinear soil's run on the finite track beside the linear one (the cost of its sections in the engine).
//!
//! Run with `cargo bench -p frictrack-benches --bench stationary` (`-- co_moving_window/quarter_car` for the vehicle).

use analytic::reference::uic60_on_soft_soil;
use criterion::{Criterion, criterion_group, criterion_main};
use fem_beam::{BeamModel, Foundation, FoundationLaw};
use stationary::{ContactGuess, Domain, StationaryProblem, solve_from};
use std::hint::black_box;
use std::time::Duration;
use track::{FoundationSections, PlacedInteractions, RunSettings, Simulation};

fn problem(law: FoundationLaw) -> StationaryProblem {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { law, ..case.foundation.with_damping_ratio(0.05, &case.beam).unwrap() };
    StationaryProblem {
        beam: case.beam,
        foundation,
        load: 83.4e3,
        speed: 0.0,
        self_weight: true,
        friction: fem_beam::DistributedFriction::default(),
        domain: Domain::default(),
    }
}

/// 100 speeds, 3–300 m/s (linear, bilinear α = ½, ballast friction of 2 and 10 kN/m on the linear soil) or
/// 1–100 m/s (tensionless, whose wave is found up to ~105 m/s).
fn sweeps(c: &mut Criterion) {
    let mut group = c.benchmark_group("stationary_sweep_100_speeds");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    let friction = |f_u: f64| StationaryProblem {
        friction: fem_beam::DistributedFriction::new(f_u),
        ..problem(FoundationLaw::Linear)
    };
    for (name, base, step) in [
        ("linear", problem(FoundationLaw::Linear), 3.0),
        ("bilinear_half", problem(FoundationLaw::Bilinear { tension_ratio: 0.5 }), 3.0),
        ("tensionless", problem(FoundationLaw::Tensionless), 1.0),
        ("friction_2kN_per_m", friction(2e3), 3.0),
        ("friction_10kN_per_m", friction(10e3), 3.0),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut guess = ContactGuess::default();
                for i in 1..=100 {
                    let p = StationaryProblem { speed: step * i as f64, ..base };
                    black_box(solve_from(&p, &mut guess).unwrap());
                }
            })
        });
    }
    // What `frictrack stationary` adds to each wave: the same problem on halved elements, started from the wave, for
    // the peaks' discretisation error (stationary::refine).
    for (name, base) in [
        ("bilinear_half_with_error_estimate", problem(FoundationLaw::Bilinear { tension_ratio: 0.5 })),
        ("friction_2kN_per_m_with_error_estimate", friction(2e3)),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut guess = ContactGuess::default();
                for i in 1..=100 {
                    let p = StationaryProblem { speed: 3.0 * i as f64, ..base };
                    let wave = solve_from(&p, &mut guess).unwrap();
                    black_box(stationary::solve_halved(&p, &wave, &stationary::Control::new(None)).unwrap());
                }
            })
        });
    }
    group.finish();
}

/// The reference run (200 m, 2000 steps, 200 m/s... here 100 m/s, where the tensionless rail stays near its soil)
/// on a linear soil, and on a tensionless one through its 800 soil sections.
fn soil_runs(c: &mut Criterion) {
    let case = uic60_on_soft_soil();
    let model_of = |law| {
        let foundation = Foundation { law, ..case.foundation.with_damping_ratio(0.05, &case.beam).unwrap() };
        BeamModel::new(case.beam, foundation, case.mesh, case.supports).unwrap()
    };
    let (linear, tensionless) = (model_of(FoundationLaw::Linear), model_of(FoundationLaw::Tensionless));
    let sections = FoundationSections::default().interactions(&tensionless).unwrap();
    let mut settings = RunSettings::default();
    settings.moving.speed = 100.0;
    let mut group = c.benchmark_group("soil_run");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    group.bench_function("linear", |b| {
        b.iter(|| Simulation::new(&linear, &PlacedInteractions::new(), &settings).unwrap().run().unwrap())
    });
    group.bench_function("tensionless_800_sections", |b| {
        b.iter(|| Simulation::new(&tensionless, black_box(&sections), &settings).unwrap().run().unwrap())
    });
    group.finish();
}

/// A co-moving window of 120 m (0.25 m elements, 30 m zones) carrying the load at 100 m/s over 250 m and over
/// 1000 m of track (5 000 and 20 000 steps): the cost per step is the window's, whatever the track's length.
fn co_moving(c: &mut Criterion) {
    use fem_beam::{AbsorbingZones, Mesh, Support, Supports};
    use track::co_moving::{CoMovingSettings, run_co_moving};
    let case = uic60_on_soft_soil();
    let foundation = case.foundation.with_damping_ratio(0.05, &case.beam).unwrap();
    let mesh = Mesh::new(120.0, 480).unwrap();
    let zones = AbsorbingZones { length: 30.0, peak_damping: foundation.critical_damping(&case.beam) };
    let damping = zones.element_damping(&mesh, foundation.damping).unwrap();
    let supports = Supports { left: Support::Free, right: Support::Clamped };
    let model = BeamModel::with_element_damping(case.beam, foundation, mesh, supports, damping).unwrap();
    let ballast = track::BallastOnBeam::interactions(&track::DistributedFriction::new(2e3), &model).unwrap();
    let mut settings = RunSettings::default();
    settings.moving.speed = 100.0;
    settings.integration.load_advance = 0.05;
    let mut group = c.benchmark_group("co_moving_window");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    for (name, placed) in [("linear", PlacedInteractions::new()), ("ballast_2kN_per_m", ballast)] {
        for track in [250.0, 1000.0] {
            let window = CoMovingSettings { load_at: 60.0, track_length: track, middle: (30.0, 90.0) };
            group.bench_function(format!("{name}_{track}m"), |b| {
                b.iter(|| run_co_moving(&model, black_box(&placed), &settings, &window).unwrap())
            });
        }
    }
    group.finish();
}

/// A quarter car riding a 120 m window (0.25 m elements, 30 m zones) at 60 m/s over a 3 mm dipped joint, over 250 m
/// and 1000 m of track: the coupled system's cost per step is the window's too.
fn co_moving_vehicle(c: &mut Criterion) {
    let scenario = |track: f64| {
        let toml = format!(
            "[mesh]\nelements = 800\n[foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 60.0\n[vehicle]\n\
             kind = \"quarter-car\"\n[[rail.irregularities]]\nkind = \"dipped-joint\"\nposition = 140.0\n\
             depth = 3e-3\nlength = 1.0\n[integration]\nload_advance = 0.05\n[co_moving]\ntrack_length = {track}\n\
             zones = 30.0\n"
        );
        scenario::Scenario::from_toml(&toml, "bench.toml").unwrap()
    };
    let mut group = c.benchmark_group("co_moving_window");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    for track in [250.0, 1000.0] {
        let s = scenario(track);
        let section = s.co_moving.clone().unwrap();
        group.bench_function(format!("quarter_car_{track}m"), |b| {
            b.iter(|| study::co_moving::output::run(black_box(&s), &section).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, sweeps, soil_runs, co_moving, co_moving_vehicle);
criterion_main!(benches);
