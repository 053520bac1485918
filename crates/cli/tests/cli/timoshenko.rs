//! A Timoshenko rail from a scenario file: named in `check` and the run's report, its critical speed from the
//! dispersion relation, the commands built on Euler–Bernoulli closed forms refusing it by key, bad keys named.

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
    for command in [vec!["stationary", path, "--speed", "100"], vec!["analytic", path, "--speed", "100"]] {
        let out = frictrack(&command);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{command:?}: {stderr}");
        assert!(stderr.contains("beam.theory = timoshenko") && stderr.contains("Euler–Bernoulli"), "{stderr}");
    }
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
