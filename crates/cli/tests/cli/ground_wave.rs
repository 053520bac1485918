//! `frictrack stationary` on a `[ground]`: the steady wave of one load is the one `frictrack ground` reports at its
//! critical speed; a train's wave at Ledsgård beside the measured records; what it refuses, by key, with exit code 2.

use super::{frictrack, json, temporary_folder, write_file};

fn example(path: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(path)
}

/// Two commands, one wave: `frictrack ground`'s largest deflection at its critical speed is the largest downward
/// deflection `frictrack stationary` finds at that speed for the same load — the same spectrum, searched over
/// different windows (60 m behind to 20 m ahead, and 60 m each way) and refined to 1 mm in s at a flat peak, so
/// equal to 1e-9 of it. The JSON's names and units.
#[test]
fn one_load_on_the_ground_is_the_ground_commands_wave() {
    let site = example("soft-ground.toml");
    let site = site.to_str().unwrap();
    let ground = json(&frictrack(&["ground", site, "--frequencies", "5:6:1", "--format", "json"]));
    let (critical, deepest) =
        (ground["critical_speed"].as_f64().unwrap(), ground["critical_deflection"].as_f64().unwrap());
    let folder = temporary_folder("ground-wave");
    let out = folder.join("out");
    let speed = critical.to_string();
    let args = ["stationary", site, "--speed", &speed, "--format", "json", "--out", out.to_str().unwrap()];
    let v = json(&frictrack(&args));
    let point = &v["points"][0];
    let down = point["max_downward_deflection"]["value"].as_f64().unwrap();
    assert!((down - deepest).abs() < 1e-9 * deepest, "{down} vs {deepest}");
    assert_eq!(point["status"], "converged");
    let units = v["units"].as_array().unwrap();
    let unit_of = |name: &str| units.iter().find(|u| u["name"] == name).map(|u| u["unit"].clone());
    for (name, unit) in [("s", "m"), ("deflection", "m"), ("max_downward_deflection", "m"), ("offset", "m")] {
        assert_eq!(unit_of(name), Some(serde_json::json!(unit)), "{name}");
    }
    for name in ["stationary.json", "wave.csv", "ground-wave.png", "ground-wave.svg"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let csv = std::fs::read_to_string(out.join("wave.csv")).unwrap();
    assert!(csv.starts_with("s,deflection\n"), "{}", &csv[..40]);
    let several = json(&frictrack(&["stationary", site, "--speeds", "20:60:20", "--format", "json"]));
    assert_eq!(several["csv"], "speeds.csv");
    assert_eq!(several["points"].as_array().unwrap().len(), 3);
}

/// The X2000 at Ledsgård (examples/ledsgard) against the measured records: at 70 km/h the computed wave follows the
/// record to an RMS misfit of 0.62 mm against the record's 3.27 mm, the deepest point 6.04 mm against 6.37 mm
/// measured; at 185 km/h, near the site's critical speed, it falls short — 8.77 mm down against 10.86, 1.91 mm up
/// against 6.50, misfit 2.23 mm against 4.83 — as an equivalent-linear model without the soil's softening at large
/// strain does (docs/theory.md §19). Pinned to the printed 0.01 mm: the numbers the docs quote.
#[test]
fn the_x2000_at_ledsgard_beside_the_measurements() {
    let site = example("ledsgard/ledsgard.toml");
    for (speed, quoted) in
        [("70km/h", [0.62, 3.27, 6.37, 6.04, 0.05, 0.00]), ("185km/h", [2.23, 4.83, 10.86, 8.77, 6.50, 1.91])]
    {
        let record = example(&format!("ledsgard/x2000_{}.csv", speed.replace("km/h", "kmh")));
        let args = [
            "stationary",
            site.to_str().unwrap(),
            "--speed",
            speed,
            "--measured",
            record.to_str().unwrap(),
            "--format",
            "json",
        ];
        let v = json(&frictrack(&args));
        let m = &v["measured"];
        assert_eq!(m["direction"], -1.0, "the record runs backward along the train");
        let mm = |name: &str| 1e3 * m[name].as_f64().unwrap();
        let got = [
            mm("rms_misfit"),
            mm("rms_measured"),
            mm("measured_max_downward"),
            mm("computed_max_downward"),
            mm("measured_max_upward"),
            mm("computed_max_upward"),
        ];
        for (value, quoted) in got.iter().zip(quoted) {
            assert!((value - quoted).abs() < 0.005 + 1e-9, "{speed}: {got:?} vs the quoted {quoted:?}");
        }
    }
}

/// The two-beam track at Ledsgård (examples/ledsgard/ledsgard-two-beam.toml: one UIC60 rail on pads, sleepers and
/// ballast over the embankment beam on the same site) beside the records: at 70 km/h the rail goes 6.63 mm down
/// against the measured 6.37 (the composite beam's 6.04: the pads and ballast add their compression), RMS misfit
/// 0.68 mm; at 185 km/h 9.21 mm, misfit 2.21 mm — the numbers examples/ledsgard/README.md quotes, to 0.01 mm. `check`
/// describes it; the receptance takes it (the rail's; a run in time too, ground_two_beam_run.rs, and `frictrack ground`,
/// ground.rs); sleepers and an embankment come together, without a ballast body.
#[test]
fn the_two_beam_track_at_ledsgard() {
    let site = example("ledsgard/ledsgard-two-beam.toml");
    let site = site.to_str().unwrap();
    for (speed, deepest, misfit) in [("70km/h", 6.63, 0.68), ("185km/h", 9.21, 2.21)] {
        let record = example(&format!("ledsgard/x2000_{}.csv", speed.replace("km/h", "kmh")));
        let args = ["stationary", site, "--speed", speed, "--measured", record.to_str().unwrap(), "--format", "json"];
        let m = json(&frictrack(&args))["measured"].clone();
        let mm = |name: &str| 1e3 * m[name].as_f64().unwrap();
        assert!((mm("computed_max_downward") - deepest).abs() < 0.005, "{speed}: {m}");
        assert!((mm("rms_misfit") - misfit).abs() < 0.005, "{speed}: {m}");
    }
    let checked = frictrack(&["check", site]);
    assert!(String::from_utf8_lossy(&checked.stdout).contains("ok — rail EI"), "{checked:?}");
    // The rail's point receptance on the two-beam track (analytic/tests/track_on_embankment.rs checks the integral).
    let receptance = frictrack(&["receptance", site, "--frequencies", "20:40:20"]);
    let text = String::from_utf8_lossy(&receptance.stdout);
    assert!(receptance.status.success(), "{receptance:?}");
    assert!(text.contains("Euler–Bernoulli rail") && text.contains("sleepers every 0.65 m"), "{text}");
    let folder = temporary_folder("two-beam-refusals");
    let refused = |args: &[&str], key: &str| {
        let out = frictrack(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(key), "{args:?}: {stderr}");
    };
    let text = std::fs::read_to_string(site).unwrap();
    let start = text.find("[embankment]").unwrap();
    let end = text.find("[load]").unwrap();
    let without = format!("{}{}", &text[..start], &text[end..]);
    refused(&["check", &write_file(&folder, "no-embankment.toml", &without)], "embankment = missing");
    let body = text.replace("stiffness = 1.4e8", "stiffness = 1.4e8\nmass = 500.0");
    refused(&["check", &write_file(&folder, "body.toml", &body)], "sleepers.ballast.mass = 500");
    // Without a ground the embankment stands on the Winkler [foundation] (a run in time takes it); without sleepers
    // there is nothing for it to carry.
    let no_ground = text[..text.find("[ground]").unwrap()].to_string();
    let (from, to) = (no_ground.find("[sleepers]").unwrap(), no_ground.find("[embankment]").unwrap());
    let no_sleepers = format!("{}{}", &no_ground[..from], &no_ground[to..]);
    refused(&["run", &write_file(&folder, "no-sleepers.toml", &no_sleepers)], "embankment = given");
}

/// Refused by key with exit code 2: a mesh (`--element-length`) or the Winkler soil's damping on the ground, a record
/// without a ground or over several speeds, a record without known columns, load patches and a vehicle on the ground.
#[test]
fn the_wave_on_the_ground_refuses_by_key() {
    let folder = temporary_folder("ground-wave-refusals");
    let site = example("soft-ground.toml");
    let site = site.to_str().unwrap();
    let refused = |args: &[&str], key: &str| {
        let out = frictrack(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(key), "{args:?}: {stderr}");
    };
    refused(&["stationary", site, "--speed", "40", "--element-length", "0.1"], "--element-length = 0.1");
    refused(&["stationary", site, "--speed", "40", "--damping-ratio", "0.1"], "--damping-ratio = 0.1");
    let record = write_file(&folder, "record.csv", "x_m,displacement_mm\n0,-1\n1,-2\n");
    refused(&["stationary", "--speed", "40", "--measured", &record], "--measured");
    refused(&["stationary", site, "--speeds", "20:40:20", "--measured", &record], "give one speed");
    let unknown = write_file(&folder, "unknown.csv", "time,w\n0,-1\n1,-2\n");
    refused(&["stationary", site, "--speed", "40", "--measured", &unknown], "names no known columns");
    let text = std::fs::read_to_string(site).unwrap();
    let patches = text.replace(
        "force = 100000.0             # one 100 kN load",
        "[[load.patches]]\noffset = 0.0\nlength = 10.0\nintensity = 1e4",
    );
    refused(&["stationary", &write_file(&folder, "patches.toml", &patches), "--speed", "40"], "load.patches");
    let vehicle = format!("{text}\n[vehicle]\nkind = \"quarter-car\"\n");
    refused(&["stationary", &write_file(&folder, "vehicle.toml", &vehicle), "--speed", "40"], "vehicle");
}
