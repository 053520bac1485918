//! A simply supported span (a railway bridge) from a scenario: no foundation, pinned ends, Rayleigh damping.

use super::{frictrack, json, temporary_folder};

#[test]
fn a_damped_span_runs_and_bad_damping_is_refused() {
    let folder = temporary_folder("bridges");
    let write = |name: &str, damping: &str| {
        let path = folder.join(name);
        let text = format!(
            "[mesh]\nlength = 20.0\nelements = 40\n[foundation]\nstiffness = 0.0\n{damping}\n[load]\nspeed = 30.0\n\
             [integration]\nload_advance = 0.05\nend_time = 2.0\n"
        );
        std::fs::write(&path, text).unwrap();
        path
    };
    let bare = write("bare.toml", "");
    let damped = write("damped.toml", "[damping]\nrayleigh = { ratio = 0.05, frequencies = [1.285, 11.57] }");
    let by_coefficients =
        write("coefficients.toml", "[damping]\nrayleigh = { alpha = 0.7266818, beta = 1.2380781e-3 }");
    let run = |path: &std::path::Path| json(&frictrack(&["run", path.to_str().unwrap(), "--format", "json"]));
    let (b, d, c) = (run(&bare), run(&damped), run(&by_coefficients));
    // Damping dissipates energy and lowers the free vibration after the load has left (end_time 2 s).
    assert_eq!(b["energy"]["viscous_dissipation"].as_f64().unwrap(), 0.0);
    assert!(d["energy"]["viscous_dissipation"].as_f64().unwrap() > 0.0);
    assert!(
        d["max_upward_deflection"]["value"].as_f64().unwrap() < b["max_upward_deflection"]["value"].as_f64().unwrap()
    );
    // ζ = 5 % at 1.285 and 11.57 Hz is α = 0.7266818 1/s, β = 1.2380781e-3 s (7 digits): the same run to 1e-6.
    let (dd, cd) = (
        d["max_downward_deflection"]["value"].as_f64().unwrap(),
        c["max_downward_deflection"]["value"].as_f64().unwrap(),
    );
    assert!((dd - cd).abs() <= 1e-6 * dd, "{dd} vs {cd}");
    let mixed = write("mixed.toml", "[damping]\nrayleigh = { ratio = 0.05, alpha = 0.1 }");
    let reversed = write("reversed.toml", "[damping]\nrayleigh = { ratio = 0.05, frequencies = [10.0, 1.0] }");
    for (path, needle) in [(mixed, "damping.rayleigh"), (reversed, "frequencies[1]")] {
        let out = frictrack(&["run", path.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(needle), "{stderr}");
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

/// A concrete deck (f₁ ≈ 10.4 Hz, f₃ ≈ 93.5 Hz): run reports the static envelope, the dynamic amplification and the
/// deck acceleration; a mesh or step too coarse for max(30 Hz, 1.5 f₁, f₃) is warned with the value to use.
#[test]
fn a_deck_reports_amplification_and_acceleration_and_warns_when_unresolved() {
    let folder = temporary_folder("deck");
    let write = |name: &str, elements: usize, advance: f64| {
        let path = folder.join(name);
        let text = format!(
            "[beam]\nyoungs_modulus = 35e9\nsecond_moment = 3.0\narea = 6.0\ndensity = 2500.0\n[mesh]\nlength = 20.0\n\
             elements = {elements}\n[foundation]\nstiffness = 0.0\n[damping]\n\
             rayleigh = {{ ratio = 0.01, frequencies = [10.0, 90.0] }}\n[load]\nspeed = 100.0\ntrain = \"hslm-a1\"\n\
             [integration]\nload_advance = {advance}\n"
        );
        std::fs::write(&path, text).unwrap();
        path
    };
    let fine = write("fine.toml", 40, 0.05);
    let out = frictrack(&["run", fine.to_str().unwrap(), "--format", "json"]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains("warning"), "{}", String::from_utf8_lossy(&out.stderr));
    let v = json(&out);
    let (dynamic, statics) = (
        v["max_downward_deflection"]["value"].as_f64().unwrap(),
        v["static_max_downward_deflection"].as_f64().unwrap(),
    );
    assert!((v["dynamic_amplification"].as_f64().unwrap() - dynamic / statics).abs() < 1e-12);
    assert!(statics > 5e-4 && statics < 2e-3, "static {statics} m");
    assert!(v["max_acceleration"]["value"].as_f64().unwrap() > 0.0);
    // A span reports the EN 1990 band-limited acceleration by default: its band is max(30 Hz, 1.5 f₁, f₃) of the
    // mesh's own modes — f₃ here, so the third mode is in it (the closed-form f₃ fell just below the mesh's).
    let band = &v["band_acceleration"];
    let modes: Vec<f64> = band["mode_frequencies"].as_array().unwrap().iter().map(|f| f.as_f64().unwrap()).collect();
    assert_eq!(modes.len(), 3, "{band}");
    assert_eq!(band["band"].as_f64().unwrap(), modes[2], "{band}");
    assert!(band["value"].as_f64().unwrap() > 0.0, "{band}");
    let coarse = write("coarse.toml", 10, 0.1);
    let stderr = String::from_utf8_lossy(&frictrack(&["run", coarse.to_str().unwrap()]).stderr).into_owned();
    // f₃ = 93.5 Hz is the highest needed: mode 3, 4 elements per half-wave, 12 elements.
    assert!(stderr.contains("warning: mesh.elements = 10") && stderr.contains("use at least 12 elements"), "{stderr}");
    assert!(stderr.contains("warning: integration.load_advance = 0.1"), "{stderr}");
    // The warning names the longest step that resolves f_max at every speed, 1/(20 f_max); capped there, the step
    // is no longer warned about.
    let hint = stderr.split("integration.max_step = ").nth(1).and_then(|t| t.split(' ').next()).unwrap();
    let h_max: f64 = hint.parse().unwrap();
    let capped = folder.join("capped.toml");
    let text = std::fs::read_to_string(&coarse).unwrap() + &format!("max_step = {h_max}\n");
    std::fs::write(&capped, text).unwrap();
    let stderr = String::from_utf8_lossy(&frictrack(&["run", capped.to_str().unwrap()]).stderr).into_owned();
    assert!(stderr.contains("mesh.elements") && !stderr.contains("integration.load_advance"), "{stderr}");
    std::fs::remove_dir_all(&folder).unwrap();
}

/// The example deck under HSLM-A1: while the first axle is in the middle third of the span the deck never deflects
/// upward, so that extreme is absent — value 0 without place or time in JSON, "none" in the text — not "0.000 mm at x = 0.0 m, t = 0"; the
/// window is named for what it is (the first axle, the middle third of the span, over every node).
#[test]
fn absent_extremes_are_absent_and_the_window_is_named_for_the_run() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/hslm-bridge.toml");
    let v = json(&frictrack(&["run", example, "--format", "json"]));
    let never = serde_json::json!({ "value": 0.0, "position": null, "time": null, "load_position": null });
    assert_eq!(v["window_max_upward_deflection"], never);
    assert!(v["window_max_downward_deflection"]["value"].as_f64().unwrap() > 0.0);
    assert!(v["max_upward_deflection"]["position"].as_f64().is_some(), "the whole run does deflect upward");
    let text = frictrack(&["run", example]);
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(
        stdout.contains("while the first axle is at 6.7–13.3 m (the middle third of the span), over every node:"),
        "{stdout}"
    );
    assert!(stdout.contains("max upward   deflection      none"), "{stdout}");
    assert!(!stdout.contains("at x = 0.0 m, t = 0.0000 s"), "{stdout}");
}

/// `--train hslm-a3 --speed 80` on a scenario titled "…, HSLM-A1": the header and every figure say what ran — the
/// title carries the flags, the figures' subtitle the train, speed and friction — never the file's HSLM-A1 alone.
#[test]
fn titles_name_the_train_and_speed_that_ran() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/hslm-bridge.toml");
    let dir = super::temporary_folder("titles");
    let args = ["run", example, "--train", "hslm-a3", "--speed", "80", "--out", dir.to_str().unwrap()];
    let out = frictrack(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let header = String::from_utf8_lossy(&out.stdout).lines().next().unwrap_or_default().to_string();
    assert!(header.contains("HSLM-A1 (run with --speed 80 m/s (288 km/h) --train hslm-a3): train hslm-a3"), "{header}");
    for figure in ["histories-deflection", "histories-moment", "snapshots-deflection", "snapshots-moment"] {
        let svg = std::fs::read_to_string(dir.join(format!("{figure}.svg"))).unwrap();
        assert!(svg.contains("(run with --speed 80 m/s (288 km/h) --train hslm-a3)"), "{figure}: title");
        assert!(svg.contains("train hslm-a3 (46 axles"), "{figure}: subtitle");
        assert!(svg.contains("at 80.00 m/s (288 km/h); friction: none"), "{figure}: subtitle");
    }
}

/// A sweep warns what a run at its speeds warns: the example deck's 0.05 m load advance resolves its 93.5 Hz only
/// above ~94 m/s; `run --speed 20` said so, a sweep from 20 m/s did not (it checked the scenario's own 100 m/s).
#[test]
fn a_sweep_warns_what_a_run_at_its_slowest_speed_warns() {
    let deck = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/hslm-bridge.toml");
    let run = frictrack(&["run", deck, "--speed", "20"]);
    let warned = String::from_utf8_lossy(&run.stderr).lines().find(|l| l.contains("load_advance")).unwrap().to_string();
    let sweep = frictrack(&["sweep", deck, "--speeds", "20:100:40", "--quiet"]);
    assert!(sweep.status.success());
    assert!(String::from_utf8_lossy(&sweep.stderr).contains(&warned), "{}", String::from_utf8_lossy(&sweep.stderr));
    // The study's deck-track option is checked before anything runs.
    let bad = frictrack(&["study", "hslm", "--scenario", deck, "--deck-track", "slab", "--out", "/nonexistent/x"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("direct-fastening"));
}
