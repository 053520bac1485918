//! Whole runs of the reference case (200 elements, v = 200 m/s, 2000 steps) and single steps, per friction set-up.
//!
//! Run with `cargo bench -p frictrack-benches --bench runs`. Set-up (assembly, contact sets) is outside the timed part;
//! a whole run includes factoring M̂ and building the friction solver, as every run does.

use analytic::reference::uic60_on_soft_soil;
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fem_beam::BeamModel;
use std::hint::black_box;
use std::time::Duration;
use track::Load;
use track::PlacedInteractions;
use track::{BallastOnBeam, Devices, DistributedFriction};
use track::{RunSettings, Simulation};

fn cases(model: &BeamModel) -> Vec<(&'static str, PlacedInteractions)> {
    vec![
        ("no_friction", PlacedInteractions::new()),
        ("devices_7_100kN", Devices::uniform(7, 100e3).interactions(model).unwrap()),
        ("devices_31_100kN", Devices::uniform(31, 100e3).interactions(model).unwrap()),
        ("distributed_1kN_per_m", DistributedFriction::new(1e3).interactions(model).unwrap()),
        ("distributed_5kN_per_m", DistributedFriction::new(5e3).interactions(model).unwrap()),
        ("distributed_10kN_per_m", DistributedFriction::new(10e3).interactions(model).unwrap()),
    ]
}

fn whole_runs(c: &mut Criterion) {
    let model = uic60_on_soft_soil().model().unwrap();
    let settings = RunSettings::default();
    let mut group = c.benchmark_group("whole_run");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    for (name, interactions) in cases(&model) {
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run().unwrap())
        });
    }
    group.finish();
}

/// The friction-free run beside the 2000 bare banded solves with the same M̂ (the yardstick: ≤ 1.3×).
fn friction_free_against_bare_solves(c: &mut Criterion) {
    let model = uic60_on_soft_soil().model().unwrap();
    let settings = RunSettings::default();
    let system = track::system::beam_system(&model);
    let h = settings.integration.load_advance / settings.moving.speed;
    let m_hat = nscd::stepper::iteration_matrix(
        &system,
        nscd::stepper::Integration { scheme: settings.integration.scheme(), step: h },
    );
    let factor = m_hat.factor().unwrap();
    let steps = (model.mesh().length / settings.integration.load_advance).round() as usize;
    let mut group = c.benchmark_group("friction_free_vs_bare_solves");
    group.sample_size(20).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(5));
    group.bench_function(BenchmarkId::new("bare_banded_solves", steps), |b| {
        let mut x = vec![1.0; system.dofs()];
        b.iter(|| {
            for _ in 0..steps {
                factor.solve_in_place(black_box(&mut x));
            }
        })
    });
    // The least any θ-method step must do, in plain loops: the right-hand side −h[Kq + hθKv + Cv] + F, the solve,
    // v and q updated, the two products K v and C v of the new velocity and K q carried forward — no energy ledger,
    // no observers. If this alone exceeds 1.3× the bare solves, so must a whole run.
    group.bench_function(BenchmarkId::new("least_step_loop", steps), |b| {
        let stiffness = banded::BandDiagonals::new(&system.stiffness);
        let damping = banded::BandDiagonals::new(&system.damping);
        let (h, theta, n) = (h, settings.integration.theta, system.dofs());
        b.iter(|| {
            let [mut q, mut v, mut kq, mut kv, mut kv_next, mut cv, mut w] = std::array::from_fn(|_| vec![0.0; n]);
            for step in 0..steps {
                for (((w, kq), kv), cv) in w.iter_mut().zip(&kq).zip(&kv).zip(&cv) {
                    *w = -h * (kq + h * theta * kv + cv);
                }
                w[(2 * step / 10) % n] += h * 83.4e3;
                factor.solve_in_place(&mut w);
                for ((w, v), q) in w.iter_mut().zip(v.iter_mut()).zip(q.iter_mut()) {
                    let next = *v + *w;
                    *w = theta * next + (1.0 - theta) * *v;
                    *v = next;
                    *q += h * *w;
                }
                stiffness.mul_vec(&v, &mut kv_next);
                damping.mul_vec(&v, &mut cv);
                for ((kq, kv_next), kv) in kq.iter_mut().zip(&kv_next).zip(&kv) {
                    *kq += h * (theta * kv_next + (1.0 - theta) * kv);
                }
                std::mem::swap(&mut kv, &mut kv_next);
            }
            black_box(q)
        })
    });
    let none = PlacedInteractions::new();
    group.bench_function(BenchmarkId::new("whole_run_no_friction", steps), |b| {
        b.iter(|| Simulation::new(&model, black_box(&none), &settings).unwrap().run().unwrap())
    });
    group.finish();
}

/// Whole-run time against the element count (200 m beam, Δx = 0.1 m ≤ the element length, so 2000 steps each):
/// it must grow linearly with DOFs × steps.
fn scaling(c: &mut Criterion) {
    let settings = RunSettings::default();
    let mut group = c.benchmark_group("scaling");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(5));
    for elements in [200usize, 400, 1000, 2000] {
        let mut case = uic60_on_soft_soil();
        case.mesh.elements = elements;
        let model = case.model().unwrap();
        let mut cases = vec![
            ("no_friction", PlacedInteractions::new()),
            ("devices_31_100kN", Devices::uniform(31, 100e3).interactions(&model).unwrap()),
        ];
        // Distributed friction on 2000 elements takes ~15 s a run: measured by the probe example instead.
        if elements <= 1000 {
            cases.push(("distributed_5kN_per_m", DistributedFriction::new(5e3).interactions(&model).unwrap()));
        }
        for (name, interactions) in cases {
            group.bench_function(BenchmarkId::new(name, elements), |b| {
                b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run().unwrap())
            });
        }
    }
    group.finish();
}

/// A train against the single load (docs/theory.md §10): the reference case at 200 m/s without friction and with 31
/// devices. The single load crosses in 2000 steps, HSLM-A1 (397.525 m) in 5975, with up to 26 of its 50 axles on
/// the 200 m beam at once: compare the time per step (BENCHMARKS.md), whose difference is the load assembly.
fn trains(c: &mut Criterion) {
    let model = uic60_on_soft_soil().model().unwrap();
    let mut group = c.benchmark_group("train");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(5));
    for (name, interactions) in [
        ("no_friction", PlacedInteractions::new()),
        ("devices_31_100kN", Devices::uniform(31, 100e3).interactions(&model).unwrap()),
    ] {
        for train in ["single", "hslm-a1"] {
            let mut settings = RunSettings::default();
            let force = settings.moving.load.train().axles[0].force;
            settings.moving.load = Load::Train(fem_beam::Train::named(train, force).unwrap());
            group.bench_function(BenchmarkId::new(name, train), |b| {
                b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run().unwrap())
            });
        }
    }
    group.finish();
}

/// A quarter car against the moving force on the reference track at 200 m/s (issue: ≤ 2× the moving-force run),
/// both whole runs through `Simulation` with their observers (the car's: every wheel's force, rail deflection and
/// moment, the body's acceleration): the car with Hertz contact (Newton iterations in every step), with a
/// linear contact spring, and rigid (position projection every step, θ = 0.51).
fn vehicles(c: &mut Criterion) {
    use track::vehicle::builtin::QuarterCar;
    use track::vehicle::{consist::VehicleSettings, wheel_rail::WheelRail};

    let model = uic60_on_soft_soil().model().unwrap();
    let settings = RunSettings::default();
    let steps = (model.mesh().length / settings.integration.load_advance).round() as usize;
    let car = QuarterCar::default().vehicle().unwrap();
    let with_contact = |contact: WheelRail| {
        let mut s = settings.clone();
        s.moving.load = Load::Vehicles {
            vehicles: VehicleSettings { contact, ..VehicleSettings::single(car.clone()) },
            train: None,
        };
        s
    };
    let hertz = with_contact(WheelRail::default());
    let linear = with_contact(WheelRail::Linear { stiffness: 1.5e9 });
    // Rigid contact as the README says to run it (θ = 0.51): one solve a step and the position projection.
    let mut rigid = with_contact(WheelRail::Rigid { restitution: 0.0 });
    rigid.integration.theta = 0.51;

    let mut group = c.benchmark_group("vehicle");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(5));
    let cases = [
        ("moving_force", &settings),
        ("quarter_car_hertz", &hertz),
        ("quarter_car_linear", &linear),
        ("quarter_car_rigid", &rigid),
    ];
    for (name, s) in cases {
        group.bench_function(BenchmarkId::new(name, steps), |b| {
            b.iter(|| Simulation::new(&model, black_box(&PlacedInteractions::new()), s).unwrap().run().unwrap())
        });
    }
    group.finish();
}

/// A quarter car on ballast friction against the moving force on the same track (issue 27: ≤ 3×): the example
/// `examples/quarter-car-on-ballast-friction.toml` (2 kN/m, 100 m/s, rigid contact on a German high-irregularity
/// rail, ζ = 5 %, θ = 0.51, static start at 40 m), and the same case with the car's weight (83.4 kN, the default
/// load) as a moving force from the same start — both on the interior point, whose window takes the car's DOFs
/// beside the beam's.
fn vehicle_on_ballast_friction(c: &mut Criterion) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/quarter-car-on-ballast-friction.toml");
    let car = scenario::Scenario::from_path(&path).unwrap().build().unwrap();
    let mut force = car.settings.clone();
    force.moving.load = RunSettings::default().moving.load;
    let mut group = c.benchmark_group("vehicle_on_ballast_friction");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    for (name, settings) in [("moving_force", &force), ("quarter_car_rigid", &car.settings)] {
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| Simulation::new(&car.model, black_box(&car.interactions), settings).unwrap().run().unwrap())
        });
    }
    group.finish();
}

/// Projection chosen for the reference track's 800 ballast sections (10 kN/m, 10 m/s, 2000 steps), where
/// Gauss–Seidel stalls: handed over to the interior point after 3 failures (nscd::fallback; ~45 min a run before,
/// every step ground through 20 000 sweeps), beside the interior point chosen.
fn projection_handed_over(c: &mut Criterion) {
    let model = uic60_on_soft_soil().model().unwrap();
    let interactions = DistributedFriction::new(10e3).interactions(&model).unwrap();
    let mut group = c.benchmark_group("projection_on_distributed_friction");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    for kind in [nscd::SolverKind::Projection, nscd::SolverKind::InteriorPoint] {
        let mut settings = RunSettings::default();
        settings.moving.speed = 10.0;
        settings.integration.solver.kind = kind;
        group.bench_function(BenchmarkId::from_parameter(kind.name()), |b| {
            b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run().unwrap())
        });
    }
    group.finish();
}

/// 5 kN/m of ballast friction at one section a node (J = 1, 199 sections 1 m apart on the reference track), by the
/// interior point — whose active-set predictor takes the steps, ~1.2 factorisations each — and by projection, which
/// `auto` picks for sections this far apart; and by the interior point on 400 elements (0.5 m: the law as accurate as
/// the default five sections an element on 200, BENCHMARKS.md).
fn one_section_a_node(c: &mut Criterion) {
    let mut group = c.benchmark_group("one_section_a_node_5kN_per_m");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    let friction = DistributedFriction { subdivisions: 1, ..DistributedFriction::new(5e3) };
    for (elements, kind) in [
        (200, nscd::SolverKind::InteriorPoint),
        (200, nscd::SolverKind::Projection),
        (400, nscd::SolverKind::InteriorPoint),
    ] {
        let mut case = uic60_on_soft_soil();
        case.mesh.elements = elements;
        let model = case.model().unwrap();
        let interactions = friction.interactions(&model).unwrap();
        let mut settings = RunSettings::default();
        settings.integration.solver.kind = kind;
        group.bench_function(BenchmarkId::new(kind.name(), elements), |b| {
            b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run().unwrap())
        });
    }
    group.finish();
}

/// The set-up of a run before its first step (factoring M̂, the friction solver, the Delassus diagonal) with
/// distributed friction on 20 000 elements of 0.01 m (80 000 sections over 40 000 DOFs): a banded solve per section
/// made it 13 s, uninterruptible; the band of M̂⁻¹ (banded::selected_inverse) makes it one O(n·b²) pass.
fn setup_with_many_sections(c: &mut Criterion) {
    let mut case = uic60_on_soft_soil();
    case.mesh.elements = 20_000;
    let model = case.model().unwrap();
    let interactions = DistributedFriction::new(5e3).interactions(&model).unwrap();
    let mut settings = RunSettings::default();
    settings.integration.load_advance = 0.01;
    let mut group = c.benchmark_group("setup");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(5));
    group.bench_function("distributed_5kN_per_m_20000_elements", |b| {
        // Stopped at its first step: what is timed is what comes before it.
        b.iter(|| Simulation::new(&model, black_box(&interactions), &settings).unwrap().run_observed(&mut |_| false))
    });
    group.finish();
}

criterion_group!(
    benches,
    setup_with_many_sections,
    projection_handed_over,
    whole_runs,
    one_section_a_node,
    friction_free_against_bare_solves,
    scaling,
    trains,
    vehicles,
    vehicle_on_ballast_friction
);
criterion_main!(benches);
