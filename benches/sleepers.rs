//! Runs on sleepers (docs/theory.md §18), each against its twin without what the sleepers add:
//! - a moving load over 199.8 m of track on 333 sleepers (four elements a bay, 1332 elements, a sleeper DOF each)
//!   against the continuous track on the same rail mesh — the target is 2× per step;
//! - a quarter car over three voided sleepers (the `voided-sleeper` example: three unilateral laws beside the wheel's
//!   contact) against the same run without voids — the target is 1.5×.
//!
//! Run with `cargo bench -p frictrack-benches --bench sleepers`.

use criterion::{Criterion, criterion_group, criterion_main};
use scenario::Scenario;
use std::hint::black_box;
use std::time::Duration;
use track::Simulation;

fn example(name: &str) -> Scenario {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples").join(name);
    Scenario::from_path(&path).unwrap()
}

/// One run of `scenario` as `frictrack run` steps it (no files, no report).
fn run(scenario: &Scenario) -> track::RunResult {
    let case = scenario.build().unwrap();
    Simulation::new(&case.model, &case.interactions, &case.settings).unwrap().run().unwrap()
}

fn discrete_track(c: &mut Criterion) {
    // The discrete-track example with an Euler–Bernoulli rail and the element as the load advance (1332 steps),
    // and its rail on the continuous support k_eq with the same damping per metre.
    let mut discrete = example("discrete-track.toml");
    discrete.beam = Scenario::default().beam;
    discrete.integration.load_advance = 0.15;
    let mut continuous = discrete.clone();
    let sleepers = continuous.sleepers.take().unwrap().sleepers().unwrap();
    continuous.foundation.stiffness = sleepers.equivalent_stiffness();
    let mut group = c.benchmark_group("sleepers");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    group.bench_function("discrete_track_199.8m_333_sleepers", |b| b.iter(|| black_box(run(&discrete))));
    group.bench_function("continuous_track_199.8m_same_mesh", |b| b.iter(|| black_box(run(&continuous))));
    let voided = example("voided-sleeper.toml");
    let mut intact = voided.clone();
    intact.sleepers.as_mut().unwrap().exceptions.clear();
    group.bench_function("quarter_car_over_3_voided_sleepers", |b| b.iter(|| black_box(run(&voided))));
    group.bench_function("quarter_car_over_intact_sleepers", |b| b.iter(|| black_box(run(&intact))));
    group.finish();
}

criterion_group!(benches, discrete_track);
criterion_main!(benches);
