//! Whole runs of the reference case (200 elements, v = 200 m/s, 2000 steps) and single steps, per friction set-up.
//!
//! Run with `cargo bench -p frictrack-benches --bench runs`. Set-up (assembly, contact sets) is outside the timed part;
//! a whole run includes factoring M̂ and building the friction solver, as every run does.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fem_beam::BeamModel;
use fem_beam::reference::uic60_on_soft_soil;
use friction::{ContactSet, Devices, DistributedFriction};
use nscd::{RunSettings, Simulation};
use std::hint::black_box;
use std::time::Duration;

fn cases(model: &BeamModel) -> Vec<(&'static str, ContactSet)> {
    vec![
        ("no_friction", ContactSet::new()),
        ("devices_7_100kN", Devices::uniform(7, 100e3).contact_set(model).unwrap()),
        ("devices_31_100kN", Devices::uniform(31, 100e3).contact_set(model).unwrap()),
        ("distributed_1kN_per_m", DistributedFriction::new(1e3).contact_set(model).unwrap()),
        ("distributed_5kN_per_m", DistributedFriction::new(5e3).contact_set(model).unwrap()),
        ("distributed_10kN_per_m", DistributedFriction::new(10e3).contact_set(model).unwrap()),
    ]
}

fn whole_runs(c: &mut Criterion) {
    let model = uic60_on_soft_soil().model().unwrap();
    let settings = RunSettings::default();
    let mut group = c.benchmark_group("whole_run");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    for (name, contacts) in cases(&model) {
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| Simulation::new(&model, black_box(&contacts), &settings).unwrap().run().unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, whole_runs);
criterion_main!(benches);
