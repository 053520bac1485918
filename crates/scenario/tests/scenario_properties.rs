//! Property tests: no scenario, valid or not, makes frictrack panic. Random scenarios (mostly valid, some values
//! out of range) are built and run; random bytes, and the template with random bytes changed, are parsed and built.
//! Each must end in `Ok` or an `Err` that names what is wrong.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use scenario::Scenario;
use scenario::TEMPLATE;

/// A scenario of a small beam (≤ 30 elements, ≤ 60 m) so that each run stays below ~100 steps. Values are drawn
/// mostly inside their valid ranges (fractions of the mesh where a range depends on it), a few outside.
fn scenario_text() -> impl Strategy<Value = String> {
    let supports = prop_oneof![Just("pinned"), Just("clamped"), Just("free")];
    let solver = prop_oneof![Just("auto"), Just("projection"), Just("interior-point")];
    let damping = prop_oneof![
        Just(String::new()),
        (0.0f64..2e4).prop_map(|c| format!("damping = {c}\n")),
        (-0.01f64..1.5).prop_map(|z| format!("damping_ratio = {z}\n")),
    ];
    // (layout 0 none / 1 count / 2 positions, fraction of the interior nodes or positions along L, force).
    let devices = (0usize..3, proptest::collection::vec(-0.01f64..1.01, 1..5), 0.0f64..2e5);
    let distributed = (any::<bool>(), -1e2f64..2e4, 1usize..7, any::<bool>());
    let extras = (prop::option::of(0.0f64..1.0), prop::option::of(1.0f64..3.0), prop::option::of(0.01f64..0.55));
    (
        (10.0f64..60.0, 2usize..30, supports.clone(), supports, 0.0f64..1e6, damping),
        (0.0f64..2e5, -1.0f64..400.0, devices, distributed),
        (0.48f64..1.01, 0.3f64..1.02, solver, extras),
    )
        .prop_map(
            |(
                (length, elements, left, right, stiffness, damping),
                (force, speed, (layout, fractions, device_force), (with_distributed, f_u, j, simpson)),
                (theta, advance, solver, (steady, end, zone)),
            )| {
                let h = length / elements as f64;
                let mut text = format!(
                    "[mesh]\nlength = {length}\nelements = {elements}\n[supports]\nleft = \"{left}\"\nright = \"{right}\"\n\
                     [foundation]\nstiffness = {stiffness}\n{damping}"
                );
                if let Some(z) = zone {
                    text += &format!("[foundation.absorbing_zones]\nlength = {}\n", z * length);
                }
                text += &format!("[load]\nforce = {force}\nspeed = {speed}\n");
                match layout {
                    1 => {
                        let count = (fractions[0] * (elements - 1) as f64).round() as i64;
                        text += &format!("[friction.devices]\ncount = {}\nforce = {device_force}\n", count.max(0));
                    }
                    2 => {
                        let x: Vec<f64> = fractions.iter().map(|f| f * length).collect();
                        text += &format!("[friction.devices]\npositions = {x:?}\nforce = {device_force}\n");
                    }
                    _ => {}
                }
                if with_distributed {
                    let q = if simpson { "simpson" } else { "trapezoid" };
                    text += &format!(
                        "[friction.distributed]\nforce_per_length = {f_u}\nsubdivisions = {j}\nquadrature = \"{q}\"\n"
                    );
                }
                text += &format!(
                    "[integration]\ntheta = {theta}\nload_advance = {}\nsolver = \"{solver}\"\nmax_iterations = 2000\n",
                    advance * h
                );
                if let Some(x) = steady {
                    text += &format!("steady_start = {}\n", x * length);
                }
                if let Some(t) = end {
                    text += &format!("end_time = {}\n", t * length / speed.max(1e-3));
                }
                text
            },
        )
}

/// Parse, build and run; how far it got: 0 not parsed, 1 parsed, 2 built, 3 ran to the end.
fn build_and_run(text: &str) -> usize {
    let Ok(scenario) = Scenario::from_toml(text, "random.toml") else { return 0 };
    let Ok(case) = scenario.build() else { return 1 };
    // Runs are capped to keep the test quick; the cap itself is validated input.
    if case.settings.integration.load_advance > 0.0
        && scenario.mesh.length / case.settings.integration.load_advance > 400.0
    {
        return 2;
    }
    match track::Simulation::new(&case.model, &case.interactions, &case.settings).and_then(|s| s.run()) {
        Ok(_) => 3,
        Err(_) => 2,
    }
}

proptest! {
    // A fixed seed, so that CI runs the same cases every time (fresh cases: set PROPTEST_RNG_SEED).
    #![proptest_config(ProptestConfig {
        cases: 96,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(
            std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(20261121),
        ),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_scenarios_never_panic(text in scenario_text()) {
        build_and_run(&text);
    }

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        build_and_run(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn a_mangled_template_never_panics(edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..6)) {
        let mut bytes = TEMPLATE.as_bytes().to_vec();
        for (at, byte) in edits {
            let i = at.index(bytes.len());
            bytes[i] = byte;
        }
        // The template is the full 200-element reference case: parse and build only.
        if let Ok(s) = Scenario::from_toml(&String::from_utf8_lossy(&bytes), "template.toml") {
            let _ = s.build();
        }
    }
}

/// The generator must reach the stepper, or the property above says little: of 200 random scenarios (a fixed
/// seed), at least half run to the end. Measured: 200 parsed, 148 built, 121 ran to the end (the
/// others: no bounded steady state for `steady_start` above v_cr, or projection forced on dense distributed friction
/// not converging in the 2000 sweeps allowed — both reported as errors).
#[test]
fn random_scenarios_reach_the_stepper() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = scenario_text();
    let mut reached = [0usize; 4];
    for _ in 0..200 {
        let text = strategy.new_tree(&mut runner).unwrap().current();
        reached[build_and_run(&text)] += 1;
    }
    eprintln!("random scenarios: {reached:?} stopped at parse / build / run / ran to the end");
    assert!(reached[3] >= 100, "{reached:?}");
}
