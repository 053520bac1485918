//! `frictrack ground`: the composite beam on a layered ground — its JSON names and units, its table and files, its
//! refusals by key with exit code 2, and the Winkler control above the critical speed on soft ground.

use super::{frictrack, json, temporary_folder, write_file};

/// A crust over soft clay on a stiffer half-space, under a track-and-embankment beam.
const SITE: &str = r#"title = "soft site"
[beam]
youngs_modulus = 2.0e8
second_moment = 1.0
area = 1.0
density = 10000.0
loss_factor = 0.1
[load]
force = 100000.0
[ground]
width = 3.0
[[ground.layers]]
thickness = 1.5
shear_wave_speed = 70.0
poisson_ratio = 0.45
density = 1500.0
damping_ratio = 0.04
[[ground.layers]]
thickness = 4.0
shear_wave_speed = 45.0
poisson_ratio = 0.48
density = 1300.0
damping_ratio = 0.03
[ground.half_space]
shear_wave_speed = 110.0
poisson_ratio = 0.45
density = 1700.0
damping_ratio = 0.05
"#;

/// The numbers the issue names, each with its unit; the files; the table on standard output; on this soft site the
/// critical speed on the ground lies below both the Winkler control (a spring fitted to the site's static
/// deflection) and the half-space's shear wave, and the free beam's bending waves meet the soil's fundamental mode
/// within 15 % of it.
#[test]
fn ground_reports_the_critical_speeds_and_writes_its_files() {
    let folder = temporary_folder("ground");
    let site = write_file(&folder, "site.toml", SITE);
    let checked = frictrack(&["check", &site]);
    assert!(checked.status.success() && String::from_utf8_lossy(&checked.stdout).contains("ok — composite beam"));
    let out = folder.join("out");
    let v = json(&frictrack(&[
        "ground",
        &site,
        "--frequencies",
        "1:40:1",
        "--format",
        "json",
        "--out",
        out.to_str().unwrap(),
    ]));
    let dispersion = v["dispersion"].as_array().unwrap();
    assert!(dispersion.len() >= 30 && dispersion[0]["phase_velocity"].as_f64().unwrap() > 0.0, "{dispersion:?}");
    let units = v["units"].as_array().unwrap();
    let unit_of = |name: &str| units.iter().find(|u| u["name"] == name).map(|u| u["unit"].clone());
    for (name, unit) in [
        ("critical_speed", "m/s"),
        ("winkler_critical_speed", "m/s"),
        ("minimum_phase_velocity", "m/s"),
        ("phase_velocity", "m/s"),
        ("frequency", "Hz"),
        ("static_strip_stiffness", "N/m²"),
    ] {
        assert_eq!(unit_of(name), Some(serde_json::json!(unit)), "{name}");
    }
    let critical = v["critical_speed"].as_f64().unwrap();
    let winkler = v["winkler_critical_speed"].as_f64().unwrap();
    assert!(critical < winkler && critical < 110.0, "{critical} vs {winkler}");
    let free = v["free_beam_crossing_speed"].as_f64().unwrap();
    assert!((free / critical - 1.0).abs() < 0.15, "{free} vs {critical}");
    for name in ["ground.json", "dispersion.csv", "modes.csv", "speeds.csv", "equivalent_stiffness.csv"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    for stem in ["ground-dispersion", "ground-speeds", "ground-stiffness"] {
        assert!(out.join(format!("{stem}.png")).is_file() && out.join(format!("{stem}.svg")).is_file(), "{stem}");
    }
}

/// What the command and the runs refuse, by key, with exit code 2: frequencies at 0, no `[ground]`, a `[ground]`
/// beside a `[foundation]`, a Timoshenko composite beam, a run in time on the ground (its fitted foundation is not
/// built yet), a bad profile.
#[test]
fn ground_refuses_by_key() {
    let folder = temporary_folder("ground-refusals");
    let site = write_file(&folder, "site.toml", SITE);
    let refused = |args: &[&str], key: &str| {
        let out = frictrack(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(key), "{args:?}: {stderr}");
    };
    refused(&["ground", &site, "--frequencies", "0:10:1"], "--frequencies = 0");
    let winkler = write_file(&folder, "winkler.toml", "[foundation]\nstiffness = 1e7\n");
    refused(&["ground", &winkler], "ground = missing");
    let both = write_file(&folder, "both.toml", &format!("{SITE}[foundation]\nstiffness = 1e7\n"));
    refused(&["ground", &both], "foundation = given");
    let timoshenko = SITE.replace(
        "loss_factor = 0.1",
        "loss_factor = 0.1\ntheory = \"timoshenko\"\nshear_modulus = 8e7\nshear_coefficient = 0.8",
    );
    refused(&["ground", &write_file(&folder, "timoshenko.toml", &timoshenko)], "beam.theory = timoshenko");
    refused(&["run", &site], "ground = given");
    let flat = SITE.replace("thickness = 4.0", "thickness = 0.0");
    refused(&["ground", &write_file(&folder, "flat.toml", &flat)], "ground.layers[1].thickness = 0");
}
