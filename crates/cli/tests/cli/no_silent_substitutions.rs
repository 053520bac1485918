//! Issue 71's silent substitutions, each refused by key or said: no closed form answers for a layered ground with a
//! fitted spring, no `[foundation]` beside a `[ground]` taken and ignored (nor shown as "the scenario as it ran"), the
//! two-beam track's default soil said, every speed an accelerating load reaches judged, a `--speed` a speed profile
//! would ignore refused, a profile knot of three numbers refused; and the composite beam on a ground judged by the
//! ground's fastest wave, not by a bar wave of its section convention.

use super::{frictrack, json, temporary_folder, write_file};

fn soft_ground() -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/soft-ground.toml");
    std::fs::read_to_string(path).unwrap()
}

/// Exit code 2, and the standard error names `key`.
fn refused(args: &[&str], key: &str) -> String {
    let out = frictrack(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(stderr.contains(key), "{args:?}: {stderr}");
    stderr
}

/// `analytic` and `reference` on a `[ground]` answered with a Winkler spring fitted at the scenario's speed (+15 % at
/// 40 m/s on the soft site): refused, pointing to the commands that solve the ground.
#[test]
fn the_closed_forms_refuse_a_layered_ground() {
    let folder = temporary_folder("closed-forms-on-ground");
    let site = write_file(&folder, "site.toml", &soft_ground());
    let error = refused(&["analytic", &site, "--speed", "40"], "ground = given");
    assert!(error.contains("frictrack stationary") && error.contains("frictrack ground"), "{error}");
    refused(&["reference", &site], "ground = given");
}

/// A `[foundation]` table beside a `[ground]` — even an empty one, or one repeating the defaults — is refused by key;
/// a run on the ground reports the scenario as it ran, without the default `[foundation]` it did not use.
#[test]
fn a_foundation_beside_a_ground_is_refused_and_not_reported() {
    let folder = temporary_folder("foundation-beside-ground");
    for table in ["[foundation]\n", "[foundation]\nstiffness = 250000.0\n"] {
        let both = write_file(&folder, "both.toml", &format!("{}{table}", soft_ground()));
        refused(&["check", &both], "foundation = given");
    }
    let site = write_file(&folder, "site.toml", &soft_ground());
    let out = folder.join("run");
    let ran = frictrack(&["run", &site, "--speed", "40", "--quiet", "--out", out.to_str().unwrap()]);
    assert!(ran.status.success(), "{}", String::from_utf8_lossy(&ran.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(summary["scenario"].get("ground").is_some(), "{}", summary["scenario"]);
    assert!(summary["scenario"].get("foundation").is_none(), "{}", summary["scenario"]);
    // Its figures say they are of a fitted foundation, and how far its wave is from the exact (they said nothing).
    let subtitle = summary["figures"]["subtitle"].as_str().unwrap();
    assert!(
        subtitle.ends_with("on a foundation fitted to the ground (its wave within 2.7 % of the exact)"),
        "{subtitle}"
    );
}

/// An untitled braking run's figures were titled "v = 200 m/s" while the load slowed to 179 m/s.
#[test]
fn a_braking_runs_figures_name_both_speeds() {
    let folder = temporary_folder("braking-title");
    let out = folder.join("run");
    let ran = frictrack(&["run", "--acceleration", "-20", "--quiet", "--out", out.to_str().unwrap()]);
    assert!(ran.status.success(), "{}", String::from_utf8_lossy(&ran.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["figures"]["title"], "v = 200.00 → 178.89 m/s");
}

/// The two-beam track with neither a `[ground]` nor a `[foundation]` stands on the reference soil: said.
#[test]
fn the_two_beam_tracks_default_soil_is_said() {
    let folder = temporary_folder("two-beam-default-soil");
    let track = "[mesh]\nlength = 60.0\nelements = 200\n[sleepers]\nspacing = 0.6\n[embankment]\nbending_stiffness = \
                 2.0e8\nmass_per_length = 7560.0\n[load]\nspeed = 40.0\n";
    let file = write_file(&folder, "track.toml", track);
    let out = frictrack(&["run", &file, "--quiet"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning: foundation = not given") && stderr.contains("250000 N/m²"), "{stderr}");
    let given = write_file(&folder, "given.toml", &format!("{track}[foundation]\nstiffness = 8.6e6\n"));
    let out = frictrack(&["run", &given, "--quiet"]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains("foundation = not given"));
}

/// An accelerating load reaching 900 m/s (4.4 v_cr) gets the warning a constant 900 m/s gets, naming the key that
/// sets the speed; a bar-wave refusal of an acceleration prints the acceleration, not the speed it reaches, as the
/// key's value; an acceleration may carry its unit and a minus sign.
#[test]
fn every_speed_a_changing_load_reaches_is_judged() {
    let out = frictrack(&["run", "--speed", "100", "--acceleration", "2000", "--quiet", "--elements", "100"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("warning: load.acceleration = 2000 m/s²: brings the load to 900 m/s, 4.4 × the critical"),
        "{stderr}"
    );
    let error = refused(&["run", "--acceleration", "1e6"], "load.acceleration = 1000000:");
    assert!(error.contains("brings the load to 20001 m/s, which must be below the beam's bar wave speed"), "{error}");
    let braking = json(&frictrack(&["run", "--acceleration", "-60m/s2", "--elements", "100", "--format", "json"]));
    assert_eq!(braking["speed_change"]["acceleration"], -60.0);
    refused(&["run", "--acceleration", "-60km/h"], "is not a number in m/s²");
}

/// A `--speed` beside a speed profile was ignored while the title said it ran; a knot of three numbers lost its third.
#[test]
fn a_speed_profile_takes_no_other_speed_and_knots_of_two_numbers() {
    let folder = temporary_folder("profile-refusals");
    let profile = write_file(&folder, "profile.toml", "[load]\nspeed_profile = [[0.0, 120.0], [200.0, 150.0]]\n");
    let error = refused(&["run", &profile, "--speed", "100"], "load.speed_profile = given");
    assert!(error.contains("(100 m/s) would not run"), "{error}");
    let three = write_file(&folder, "three.toml", "[load]\nspeed_profile = [[0.0, 120.0, 5.0], [200.0, 150.0]]\n");
    refused(&["check", &three], "knot 1 has 3 numbers");
}

/// The composite beam's E and ρ are a section convention: a run at 150 m/s on the soft site was refused as above
/// "the beam's bar wave speed" (its √(E/ρ) with the ground's co-vibrating mass); it runs, and a speed beyond the
/// ground's fastest wave (C_p = 365 m/s here) is refused before any spectrum, in `run` and in `stationary`.
#[test]
fn the_composite_beam_is_judged_by_the_grounds_fastest_wave() {
    let folder = temporary_folder("composite-speed-limit");
    let site = write_file(&folder, "site.toml", &soft_ground());
    let fast = json(&frictrack(&["run", &site, "--speed", "150", "--format", "json"]));
    assert!(fast["max_downward_deflection"]["value"].as_f64().unwrap() > 0.0);
    let error = refused(&["stationary", &site, "--speed", "1e5"], "--speed = 100000");
    assert!(error.contains("fastest wave") && error.contains("C_p = 365 m/s"), "{error}");
    refused(&["run", &site, "--speed", "400"], "load.speed = 400");
}

/// `stationary` on the ground gave its extremes at the window's end (s = −60 m, the upward wake at 300 m/s on the soft
/// site) without a word: warned of, naming the side to widen; the wider window finds the wake's peak inside and says
/// nothing.
#[test]
fn an_extreme_at_the_windows_end_is_said() {
    let folder = temporary_folder("window-edge");
    let site = write_file(&folder, "site.toml", &soft_ground());
    let at_edge = frictrack(&["stationary", &site, "--speed", "300"]);
    let stderr = String::from_utf8_lossy(&at_edge.stderr);
    assert!(at_edge.status.success(), "{stderr}");
    assert!(
        stderr.contains("the largest upward deflection") && stderr.contains("lies at the window's end s = -60.00 m"),
        "{stderr}"
    );
    assert!(stderr.contains("widen the window behind the train"), "{stderr}");
    let wider = json(&frictrack(&["stationary", &site, "--speed", "300", "--domain", "120:60", "--format", "json"]));
    assert_eq!(wider["warnings"].as_array().unwrap().len(), 0, "{}", wider["warnings"]);
    let up = wider["points"][0]["max_upward_deflection"]["position"].as_f64().unwrap();
    assert!(up < -60.0 && up > -120.0, "{up}");
}

/// A ground no site has (ρ in g/cm³) is warned of by key before any spectrum; a strip no track loads is refused.
#[test]
fn a_ground_no_site_has_is_warned_of() {
    let folder = temporary_folder("absurd-ground");
    let grams = write_file(&folder, "grams.toml", &soft_ground().replace("density = 1500.0", "density = 1.5"));
    let out = frictrack(&["stationary", &grams, "--speed", "40"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && stderr.contains("warning: ground.layers[0].density = 1.5 kg/m³"), "{stderr}");
    // A strip a kilometre wide is no track's (and kept a spectrum busy for minutes): refused by key.
    let wide = write_file(&folder, "wide.toml", &soft_ground().replace("width = 3.0", "width = 1e6"));
    refused(&["check", &wide], "ground.width = 1000000: must be at most 100 m");
}
