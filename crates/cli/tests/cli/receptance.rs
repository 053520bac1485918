//! `frictrack receptance`: the files it writes, its JSON and CSV, its warnings, bad flags named with exit code 2.

use super::{frictrack, json, temporary_folder};

#[test]
fn receptance_writes_its_table_json_and_figure() {
    let folder = temporary_folder("receptance");
    let file = folder.join("track.toml");
    std::fs::write(
        &file,
        "[mesh]\nelements = 1600\n[foundation]\ndamping_ratio = 0.1\nloss_factor = 0.2\n\
         [foundation.absorbing_zones]\nlength = 40.0\n[beam]\nloss_factor = 0.02\n",
    )
    .unwrap();
    let (path, out) = (file.to_str().unwrap(), folder.join("out"));
    let v = json(&frictrack(&[
        "receptance",
        path,
        "--frequencies",
        "1:100:1",
        "--format",
        "json",
        "--out",
        out.to_str().unwrap(),
    ]));
    assert_eq!(v["kind"], "point");
    assert_eq!(v["points"].as_array().unwrap().len(), 100);
    let resonance = v["resonances"][0]["frequency"].as_f64().unwrap();
    assert!((9.5..10.5).contains(&resonance), "{resonance}");
    for name in ["receptance.csv", "receptance.json", "receptance.png", "receptance.svg"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let csv = frictrack(&[
        "receptance",
        path,
        "--frequencies",
        "10:12:1",
        "--at",
        "90",
        "--excite",
        "100",
        "--format",
        "csv",
    ]);
    let text = String::from_utf8_lossy(&csv.stdout);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "frequency,real,imaginary,magnitude,phase,mobility");
    assert_eq!(lines.len(), 5, "{text}");
    assert!(lines[4].starts_with("# units (SI): frequency Hz"), "{text}");
    // The reference track, undamped on pinned ends: the warnings say why its peaks are the finite beam's modes.
    let undamped = frictrack(&["receptance", "--frequencies", "1:50:1"]);
    let stderr = String::from_utf8_lossy(&undamped.stderr);
    assert!(undamped.status.success() && stderr.contains("come back at up to"), "{stderr}");
}

/// Sleepers: the receptance takes them (the pinned–pinned peak of the rail between them is listed); a run refuses
/// them by key, exit code 2, rather than run a track without them.
#[test]
fn sleepers_are_taken_by_the_receptance_and_by_runs() {
    let folder = temporary_folder("receptance-sleepers");
    let file = folder.join("discrete.toml");
    std::fs::write(
        &file,
        "[mesh]\nlength = 60.0\nelements = 800\n[foundation]\nstiffness = 0.0\n[supports]\nleft = \"free\"\n\
         right = \"free\"\n[sleepers]\n[sleepers.pad]\nloss_factor = 0.25\n[sleepers.ballast]\nloss_factor = 0.5\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    let v = json(&frictrack(&["receptance", path, "--frequencies", "1200:1600:10", "--at", "30", "--format", "json"]));
    let peak = v["resonances"][0]["frequency"].as_f64().unwrap();
    // Euler–Bernoulli's pinned–pinned span: π/(2a²)·√(EI/ρA) = 1428 Hz, to 2 % (the pads give a little).
    assert!((peak / 1428.0 - 1.0).abs() < 2e-2, "{peak}");
    // A run takes them (reporting what the discrete track adds); a co-moving window, which needs a uniform support,
    // refuses them by key, and the receptance refuses a voided sleeper (it is the linear track's).
    let run = frictrack(&["run", path, "--elements", "400"]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(stdout.contains("sleeper passing v/a") && stdout.contains("pinned–pinned 1428 Hz"), "{stdout}");
    let window = frictrack(&["run", path, "--co-moving"]);
    let stderr = String::from_utf8_lossy(&window.stderr);
    assert_eq!(window.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("sleepers") && stderr.contains("uniform"), "{stderr}");
    let voided = folder.join("voided.toml");
    let text = std::fs::read_to_string(&file).unwrap() + "[[sleepers.exceptions]]\nindex = 40\ngap = 0.001\n";
    std::fs::write(&voided, text).unwrap();
    let refused = frictrack(&["receptance", voided.to_str().unwrap(), "--frequencies", "100:200:10"]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("sleepers.exceptions") && stderr.contains("linear track"), "{stderr}");
}

#[test]
fn bad_receptance_flags_are_named() {
    for (args, named) in [
        (vec!["--frequencies", "0:100:1"], "--frequencies = 0"),
        (vec!["--frequencies", "10:100"], "--frequencies = 10:100"),
        (vec!["--frequencies", "10:100:1", "--at", "500"], "--at = 500"),
        (vec!["--frequencies", "10:100:1", "--excite", "-1"], "--excite = -1"),
    ] {
        let out = frictrack(&[&["receptance"], args.as_slice()].concat());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(named), "{args:?}: {stderr}");
    }
}

/// Frequencies far beyond what the mesh resolves (examples/receptance.toml: 0.0625 m elements, good to 2720 Hz with
/// ten a wavelength) gave a "resonance" of the mesh at 17.8 kHz: peaks above the resolved band are not listed, and a
/// warning says how many were left out.
#[test]
fn only_resonances_the_mesh_resolves_are_listed() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/receptance.toml");
    let out = frictrack(&["receptance", example, "--frequencies", "100:20000:20", "--format", "json"]);
    let v = json(&out);
    let listed: Vec<f64> =
        v["resonances"].as_array().unwrap().iter().map(|r| r["frequency"].as_f64().unwrap()).collect();
    assert!(listed.iter().all(|&f| f < 2720.0), "{listed:?}");
    let warnings = v["warnings"].to_string();
    assert!(warnings.contains("up to 2720 Hz") && warnings.contains("1 peak(s)"), "{warnings}");
}

/// A negative range is the user's number, refused by key (clap took `-10:100:1` for a flag); a point on a pinned
/// end is warned about (|α| = 0 there by the support, not by the track).
#[test]
fn a_negative_range_is_named_and_a_held_point_is_warned_about() {
    let out = super::frictrack(&["receptance", "--frequencies", "-10:100:1"]);
    assert_eq!(out.status.code(), Some(2));
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(error.contains("invalid --frequencies = -10"), "{error}");
    let out = super::frictrack(&["sweep", "--speeds", "-10:100:10"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--speeds"));
    let out = super::frictrack(&["receptance", "--frequencies", "10:20:5", "--at", "0", "--excite", "50"]);
    assert!(out.status.success());
    let warnings = String::from_utf8_lossy(&out.stderr);
    assert!(warnings.contains("the response is read at x = 0 m, where a support holds the rail"), "{warnings}");
    assert!(!warnings.contains("the force acts at x = 50"), "{warnings}");
}
