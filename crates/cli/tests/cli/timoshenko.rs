//! A Timoshenko rail from a scenario file: named in `check` and the run's report, its critical speed from the
//! dispersion relation, the stationary wave and the closed forms (`analytic`, `reference`) taking it, bad keys named.

use super::{frictrack, json, temporary_folder};

const TIMOSHENKO: &str = "[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\nshear_coefficient = 0.4\n\
                          [mesh]\nelements = 400\n[load]\nspeed = 150.0\n";

#[test]
fn a_timoshenko_rail_runs_and_says_so() {
    let folder = temporary_folder("timoshenko");
    let file = folder.join("rail.toml");
    std::fs::write(&file, TIMOSHENKO).unwrap();
    let path = file.to_str().unwrap();
    let checked = frictrack(&["check", path]);
    assert!(checked.status.success());
    assert!(String::from_utf8_lossy(&checked.stdout).contains("Timoshenko (G = 81 GPa, κ = 0.4) beam"));
    let v = json(&frictrack(&["run", path, "--format", "json"]));
    assert_eq!(v["rail_theory"], "Timoshenko (G = 81 GPa, κ = 0.4)");
    // Shear lowers the critical speed a little below Euler–Bernoulli's 205.57 m/s (the least phase velocity).
    let v_cr = v["critical_speed"].as_f64().unwrap();
    assert!(v_cr < 205.57 && v_cr > 204.5, "{v_cr}");
    let energy = &v["energy"];
    assert!(energy["residual"].as_f64().unwrap().abs() < 1e-9 * energy["load_work"].as_f64().unwrap());
    // An Euler–Bernoulli run's JSON has no such key.
    assert!(json(&frictrack(&["run", "--elements", "100", "--format", "json"])).get("rail_theory").is_none());
}

/// The stationary wave (moving-frame Timoshenko elements, 0.25 m) and the closed form (the residues of the
/// Timoshenko beam's quartic) of the same rail at 150 m/s, ζ = 5 %: the same peak to 1e-4 (measured 2.8e-6), each
/// report naming the rail; `reference` checks the Timoshenko FE beam against its closed forms.
#[test]
fn the_stationary_wave_and_the_closed_form_take_a_timoshenko_rail() {
    let folder = temporary_folder("timoshenko-closed");
    let file = folder.join("rail.toml");
    std::fs::write(&file, TIMOSHENKO).unwrap();
    let path = file.to_str().unwrap();
    let args = ["--speed", "150", "--damping-ratio", "0.05", "--format", "json"];
    let peak = |command: &str| {
        let out = frictrack(&[&[command, path][..], &args[..]].concat());
        json(&out)["max_downward_deflection"]["value"].as_f64().unwrap()
    };
    let (stationary, closed) = (peak("stationary"), peak("analytic"));
    assert!((stationary / closed - 1.0).abs() < 1e-4, "{stationary} vs {closed}");
    for command in [vec!["stationary", path, "--speed", "150"], vec!["analytic", path, "--speed", "150"]] {
        let out = frictrack(&command);
        assert!(out.status.success(), "{command:?}");
        assert!(String::from_utf8_lossy(&out.stdout).contains("Timoshenko (G = 81 GPa, κ = 0.4)"), "{command:?}");
    }
    let reference = json(&frictrack(&["reference", path, "--format", "json"]));
    assert_eq!(reference["rail_theory"], "Timoshenko (G = 81 GPa, κ = 0.4)");
    let (fe, exact) = (
        reference["midspan_deflection"].as_f64().unwrap(),
        reference["midspan_deflection_closed_form"].as_f64().unwrap(),
    );
    assert!((fe / exact - 1.0).abs() < 1e-4, "{fe} vs {exact}");
}

#[test]
fn missing_or_stray_shear_keys_are_named() {
    let folder = temporary_folder("timoshenko-bad");
    for (text, named) in [
        ("[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\n", "needs shear_coefficient"),
        ("[beam]\ntheory = \"timoshenko\"\nshear_coefficient = 0.4\n", "needs shear_modulus"),
        ("[beam]\nshear_modulus = 81e9\n", "shear_modulus is used only by a Timoshenko beam"),
        (
            "[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\nshear_coefficient = 1.5\n",
            "beam.shear_coefficient = 1.5",
        ),
        ("[beam]\ntheory = \"timoshenko\"\nshear_modulus = -1.0\nshear_coefficient = 0.4\n", "beam.shear_modulus = -1"),
        ("[beam]\ntheory = \"rayleigh\"\n", "expected `euler-bernoulli` or `timoshenko`"),
    ] {
        let file = folder.join("bad.toml");
        std::fs::write(&file, text).unwrap();
        let out = frictrack(&["check", file.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{text}: {stderr}");
        assert!(stderr.contains(named), "{text}: {stderr}");
    }
}
