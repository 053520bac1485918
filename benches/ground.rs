//! The ground under the track (docs/theory.md §19): one speed point of the linear moving-frame solution on a soft
//! layered site — the spectrum of a composite beam on the strip's k_eq(k_x, k_x v) and its wave's extremes — at a
//! subcritical, the critical and a supercritical speed, as `frictrack ground` computes each point of its speed curve
//! (the target: ≤ 0.5 s a speed on 2 cores), and the same on Ledsgård's profile; the X2000 at Ledsgård without and with ballast friction (≤ 5×
//! the linear wave); the two-beam track there, bonded, with the sleepers lifting off a tensionless ballast and with
//! friction between the sleepers and the embankment; and one strip integral k_eq alone.
//!
//! Run with `cargo bench -p frictrack-benches --bench ground`.

use analytic::ground::{GroundProfile, GroundedBeam, SoilLayer, SoilMaterial, StripGround};
use criterion::{Criterion, criterion_group, criterion_main};
use fem_beam::properties::Beam;
use std::hint::black_box;
use std::time::Duration;

/// The soft trial site of the CLI's tests: a crust over soft clay on a stiffer half-space.
fn site() -> StripGround {
    let soil = |shear_wave_speed: f64, density: f64, damping_ratio: f64| SoilMaterial {
        shear_wave_speed,
        compression_wave_speed: shear_wave_speed * (2.0 * 0.55 / 0.1f64).sqrt(),
        density,
        damping_ratio,
    };
    let layers = vec![
        SoilLayer { thickness: 1.5, material: soil(70.0, 1500.0, 0.04) },
        SoilLayer { thickness: 4.0, material: soil(45.0, 1300.0, 0.03) },
    ];
    StripGround { width: 3.0, profile: GroundProfile { layers, half_space: soil(110.0, 1700.0, 0.05) } }
}

fn ground(c: &mut Criterion) {
    let strip = site();
    let beam =
        Beam { youngs_modulus: 2e8, second_moment: 1.0, area: 1.0, density: 1e4, loss_factor: 0.1, ..Beam::default() };
    let grounded = GroundedBeam::new(&beam, &strip).unwrap();
    rayon::ThreadPoolBuilder::new().num_threads(2).build_global().ok();
    let mut group = c.benchmark_group("ground");
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(10));
    for speed in [40.0, 65.0, 100.0] {
        group.bench_function(format!("speed_point_{speed:.0}_m_per_s_2_threads"), |b| {
            b.iter(|| {
                let spectrum = grounded.spectrum(speed).unwrap();
                black_box(study::ground::speeds::extremes(&spectrum, speed, 1e5))
            })
        });
    }
    // The X2000 (20 axles) at 185 km/h at Ledsgård: its spectrum and its wave at the 1 105 points of the default
    // window, as `frictrack stationary` computes a speed on a [ground].
    let ledsgard = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/ledsgard/ledsgard.toml");
    let ledsgard = scenario::Scenario::from_path(&ledsgard).unwrap();
    // One speed point on the Ledsgård profile (the target, ≤ 0.5 s): the composite beam under one load at
    // 70 km/h, at its critical speed for one load (56.5 m/s) and at 280 km/h, as `frictrack ground` computes them.
    let (composite, ledsgard_strip, _) = ledsgard.ground_track().unwrap();
    let on_ledsgard = GroundedBeam::new(&composite, &ledsgard_strip).unwrap();
    for speed in [70.0 / 3.6, 56.5, 280.0 / 3.6] {
        group.bench_function(format!("ledsgard_speed_point_{:.0}_km_per_h_2_threads", speed * 3.6), |b| {
            b.iter(|| {
                let spectrum = on_ledsgard.spectrum(speed).unwrap();
                black_box(study::ground::speeds::extremes(&spectrum, speed, 1e5))
            })
        });
    }
    let window = study::ground::WaveWindow::default();
    group.bench_function("x2000_wave_at_ledsgard_185_km_per_h_2_threads", |b| {
        b.iter(|| {
            black_box(study::ground::GroundWaveStudy::of(&ledsgard, &[185.0 / 3.6], window, None, &|_| {}).unwrap())
        })
    });
    // The same with ballast friction of 1, 2 and 5 kN/m under the composite beam: the nonlinear wave on the ground
    // (the target: ≤ 5× the linear one), each from cold (no previous speed's wave).
    for friction in [1000.0, 2000.0, 5000.0] {
        let mut with_friction = ledsgard.clone();
        with_friction.friction.distributed =
            Some(scenario::DistributedSection { force_per_length: friction, ..Default::default() });
        group.bench_function(format!("x2000_wave_with_{friction:.0}_n_per_m_friction_185_km_per_h_2_threads"), |b| {
            b.iter(|| {
                let study = study::ground::GroundWaveStudy::of(&with_friction, &[185.0 / 3.6], window, None, &|_| {});
                black_box(study.unwrap())
            })
        });
    }
    // The two-beam track there (the rail on pads, sleepers and ballast over the embankment beam), bonded, with a
    // tensionless ballast and with 2 kN/m of friction between the sleepers and the embankment (from cold): the
    // interface's four spectra and the lift-off's or the friction's Newton iteration against the rail's wave.
    let two_beam = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/ledsgard/ledsgard-two-beam.toml");
    let bonded = scenario::Scenario::from_path(&two_beam).unwrap();
    let mut tensionless = bonded.clone();
    tensionless.embankment.as_mut().unwrap().interface = scenario::embankment::InterfaceKind::Tensionless;
    let mut friction = bonded.clone();
    friction.friction.distributed =
        Some(scenario::DistributedSection { force_per_length: 2000.0, ..Default::default() });
    for (name, case) in [("bonded", &bonded), ("tensionless", &tensionless), ("2000_n_per_m_friction", &friction)] {
        group.bench_function(format!("x2000_two_beam_{name}_185_km_per_h_2_threads"), |b| {
            b.iter(|| {
                black_box(study::ground::GroundWaveStudy::of(case, &[185.0 / 3.6], window, None, &|_| {}).unwrap())
            })
        });
    }
    group.bench_function("strip_integral_kx_0.5_at_65_m_per_s", |b| {
        b.iter(|| black_box(strip.equivalent_stiffness(0.5, 0.5 * 65.0).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, ground);
criterion_main!(benches);
