//! The track's receptance (docs/theory.md §17): 1500 frequencies, 2 Hz to 2 kHz, of the receptance example's track
//! (a Timoshenko rail on 3200 elements, 6402 DOFs) on 2 threads, as `frictrack receptance` computes them — the target is 1 s.
//!
//! Run with `cargo bench -p frictrack-benches --bench receptance`.

use criterion::{Criterion, criterion_group, criterion_main};
use runner::Runner;
use scenario::Scenario;
use std::hint::black_box;
use std::time::Duration;
use study::receptance::{ReceptanceRequest, ReceptanceStudy};

fn receptance(c: &mut Criterion) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/receptance.toml");
    let scenario = Scenario::from_path(&path).unwrap();
    let frequencies = (0..1500).map(|i| 2.0 + 1998.0 * i as f64 / 1499.0).collect();
    let request = ReceptanceRequest { frequencies, excite: 100.0, at: 100.0 };
    let runner = Runner::new(2).unwrap();
    let mut group = c.benchmark_group("receptance");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    group.bench_function("1500_frequencies_2_threads", |b| {
        b.iter(|| black_box(ReceptanceStudy::of(&scenario, &request, &runner).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, receptance);
criterion_main!(benches);
