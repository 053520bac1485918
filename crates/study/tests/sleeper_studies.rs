//! The discrete track's studies (docs/theory.md §18) on short tracks: voided sleepers under a quarter car, and
//! friction at the sleepers against friction in the ballast.

use runner::Runner;
use scenario::{Scenario, SweepSection};
use study::presets::{Preset, Resolution, run_preset};

fn number(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// 36 m of the typical ballasted track: every curve and column; tensionless ballast without a void is the intact
/// track to 2 % (it lets go only where the rail lifts); the deflection grows with the void for three sleepers and
/// stops growing for one once the void is larger than what the rail, bridging it, sags (2 and 3 mm alike to 1 %);
/// three sleepers hanging 3 mm load their neighbours' ballast well beyond the intact track's largest.
#[test]
fn voided_sleepers_load_their_neighbours() {
    let base = Scenario::from_toml(
        "[mesh]\nlength = 36.0\nelements = 240\n[foundation]\nstiffness = 0.0\n[foundation.absorbing_zones]\n\
         length = 6.0\n[sleepers]\n",
        "short.toml",
    )
    .unwrap();
    let data = run_preset(Preset::VoidedSleepers, Resolution::Coarse, &base, &Runner::new(0).unwrap()).unwrap();
    assert!(data.failures.is_empty(), "{:?}", data.failures);
    assert_eq!(data.plots.len(), 4);
    let lines: Vec<&str> = data.csv.lines().collect();
    assert_eq!(lines.len(), 1 + 13 * 5);
    assert!(lines.iter().all(|l| l.split(',').count() == 12), "ragged CSV");
    let summary = data.summary_json();
    let curves = summary["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 13);
    let find = |voided: u64, gap: f64| {
        curves.iter().find(|c| c["voided"] == voided && (number(&c["gap"]) - gap).abs() < 1e-12).unwrap()
    };
    let peak = |voided, gap| number(&find(voided, gap)["peak_deflection"]);
    let intact = peak(0, 0.0);
    for voided in 1..=3 {
        assert!((peak(voided, 0.0) / intact - 1.0).abs() < 0.02, "{voided}: {} vs {intact}", peak(voided, 0.0));
    }
    assert!(peak(3, 1e-3) > 1.5 * intact && peak(3, 2e-3) > peak(3, 1e-3) && peak(3, 3e-3) > peak(3, 2e-3));
    assert!((peak(1, 3e-3) / peak(1, 2e-3) - 1.0).abs() < 0.01, "{} vs {}", peak(1, 3e-3), peak(1, 2e-3));
    let force = |voided, gap| number(&find(voided, gap)["neighbour_ballast_force"]);
    assert!(force(3, 3e-3) > 1.5 * force(0, 0.0), "{} vs {}", force(3, 3e-3), force(0, 0.0));
    assert!(data.headline[0].contains("Three sleepers hanging 3 mm"), "{:?}", data.headline);
}

/// The reference soil held by light sleepers on 60 m, at 180, 205 and 230 m/s with each curve's peak refined: the
/// discrete track's critical speed within 1 % of its continuous twin's (measured on 199.8 m: 203.5 and 203.7 m/s);
/// friction lowers both peaks, and friction at the sleepers, which slide by about half the rail's motion, less
/// than the same force per metre in the ballast under the rail.
#[test]
fn friction_at_the_sleepers_against_friction_in_the_ballast() {
    let base = Scenario {
        sweep: Some(SweepSection { from: 180.0, to: 230.0, step: 25.0 }),
        ..Scenario::from_toml("[mesh]\nlength = 60.0\nelements = 400\n", "short.toml").unwrap()
    };
    let data = run_preset(Preset::SleeperFriction, Resolution::Coarse, &base, &Runner::new(0).unwrap()).unwrap();
    assert!(data.failures.is_empty(), "{:?}", data.failures);
    let summary = data.summary_json();
    let curves = summary["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 6);
    let find = |sleepers: f64, f: f64| {
        curves
            .iter()
            .find(|c| number(&c["sleepers"]) == sleepers && number(&c["force_per_length"]) == f)
            .unwrap_or_else(|| panic!("no curve {sleepers}, {f}: {curves:?}"))
    };
    let (continuous, discrete) = (number(&find(0.0, 0.0)["critical_speed"]), number(&find(1.0, 0.0)["critical_speed"]));
    assert!((discrete / continuous - 1.0).abs() < 0.01, "{discrete} vs {continuous}");
    let peak = |s, f| number(&find(s, f)["peak_max_downward_deflection"]);
    for s in [0.0, 1.0] {
        assert!(peak(s, 5e3) < peak(s, 2e3) && peak(s, 2e3) < peak(s, 0.0), "{s}");
    }
    assert!(peak(1.0, 5e3) > peak(0.0, 5e3));
}

/// The receptance study on 60 m of the typical ballasted track: six curves of 200 frequencies; on sleepers the
/// three resonances of the literature at mid-span, named — pinned–pinned within 1 % of the span's frequency
/// (Euler–Bernoulli π/(2a²)·√(EI/ρA) = 1428 Hz, Timoshenko's frequency equation 1072 Hz) —, above a sleeper no
/// pinned–pinned peak (a dip there), and on the continuous twin the one resonance of a rail on its foundation.
#[test]
fn the_receptance_study_names_the_resonances_of_the_literature() {
    let base = Scenario::from_toml("[mesh]\nlength = 60.0\nelements = 100\n", "short.toml").unwrap();
    let data = run_preset(Preset::Receptance, Resolution::Coarse, &base, &Runner::new(0).unwrap()).unwrap();
    assert_eq!(data.plots.len(), 2);
    assert_eq!(data.csv.lines().count(), 1 + 6 * 200);
    let summary = data.summary_json();
    let curves = summary["curves"].as_array().unwrap();
    let find = |rail: &str, support: &str, place: &str| {
        curves.iter().find(|c| c["rail"] == rail && c["support"] == support && c["place"] == place).unwrap()
    };
    let named = |c: &serde_json::Value, name: &str| {
        c["resonances"].as_array().unwrap().iter().find(|r| r["name"] == name).map(|r| number(&r["frequency"]))
    };
    for (rail, pinned) in [("Euler–Bernoulli", 1428.0), ("Timoshenko", 1072.0)] {
        let mid = find(rail, "sleepers", "mid-span");
        let f = named(mid, "pinned–pinned").unwrap_or_else(|| panic!("{rail}: {mid}"));
        assert!((f / pinned - 1.0).abs() < 1e-2, "{rail}: {f} Hz");
        assert!(named(mid, "track on the ballast").is_some() && named(mid, "rail on its pads").is_some(), "{mid}");
        assert!(named(find(rail, "sleepers", "above a sleeper"), "pinned–pinned").is_none());
        let twin = find(rail, "continuous", "mid-span")["resonances"].as_array().unwrap().clone();
        assert_eq!(twin.len(), 1, "{twin:?}");
        assert_eq!(twin[0]["name"], "rail on its foundation");
    }
}

/// A bad sleeper spacing is named as written (`sleepers.spacing = -0.6`) by every preset — the Python entry reached
/// the preset unchecked and named the mesh the preset derives from it (`mesh.elements = 0`).
#[test]
fn a_bad_spacing_is_named_as_written() {
    let base = Scenario::from_toml("[sleepers]\nspacing = -0.6\n", "bad.toml").unwrap();
    for preset in [Preset::VoidedSleepers, Preset::SleeperFriction] {
        let error = run_preset(preset, Resolution::Coarse, &base, &Runner::new(1).unwrap()).unwrap_err().to_string();
        assert!(error.contains("sleepers.spacing = -0.6"), "{preset:?}: {error}");
    }
}
