//! A load that changes speed from the command line and a scenario file: the report says from which speed to which
//! and the speed at each window extreme, a braking load that would stop on the track and a changing speed where a
//! steady state is asked for are refused by key (exit 2), and a speed profile runs.

use super::{frictrack, json, temporary_folder};

/// Braking at 20 m/s² from 200 m/s on the reference track: 178.89 m/s where the load leaves (v² = 200² − 2·20·200
/// at x = 200 m); the extremes in the window carry the speed the load had then, between the two.
#[test]
fn a_braking_load_runs_and_reports_its_speeds() {
    let v = json(&frictrack(&["run", "--acceleration", "-20", "--format", "json"]));
    let change = &v["speed_change"];
    assert_eq!(change["acceleration"], -20.0);
    assert_eq!(change["start_speed"], 200.0);
    let end = change["end_speed"].as_f64().unwrap();
    assert!((end - (200.0f64.powi(2) - 2.0 * 20.0 * 200.0).sqrt()).abs() < 1e-9, "{end}");
    let extreme = &v["window_max_downward_deflection"];
    let (x, speed) = (extreme["load_position"].as_f64().unwrap(), extreme["load_speed"].as_f64().unwrap());
    assert!((speed - (200.0f64.powi(2) - 40.0 * x).sqrt()).abs() < 1e-6, "{x} {speed}");
    let energy = &v["energy"];
    assert!(energy["residual"].as_f64().unwrap().abs() < 1e-9 * energy["load_work"].as_f64().unwrap());
    let text = frictrack(&["run", "--acceleration", "-20"]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("from 200.00 to 178.89 m/s (braking at 20 m/s²)"), "{text}");
    // At constant speed the JSON has neither key.
    let constant = json(&frictrack(&["run", "--elements", "100", "--format", "json"]));
    assert!(constant.get("speed_change").is_none());
    assert!(constant["window_max_downward_deflection"].get("load_speed").is_none());
}

#[test]
fn a_load_that_would_stop_or_a_steady_state_at_changing_speed_is_refused_by_key() {
    let out = frictrack(&["run", "--acceleration", "-150"]);
    assert_eq!(out.status.code(), Some(2));
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(error.contains("load.acceleration = -150") && error.contains("to rest at x = 133.3 m"), "{error}");
    let folder = temporary_folder("variable-speed");
    let file = folder.join("profile.toml");
    std::fs::write(&file, "[load]\nspeed_profile = [[0.0, 120.0], [100.0, 80.0], [200.0, 150.0]]\n").unwrap();
    let path = file.to_str().unwrap();
    let out = frictrack(&["stationary", path, "--speed", "100"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("load.speed_profile"));
    let out = frictrack(&["analytic", path, "--speed", "100"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("load.speed_profile"));
    // The profile runs: 120 m/s at the start, 150 m/s where the load leaves, 80 m/s the slowest.
    let v = json(&frictrack(&["run", path, "--format", "json"]));
    let change = &v["speed_change"];
    assert_eq!((change["start_speed"].as_f64(), change["end_speed"].as_f64()), (Some(120.0), Some(150.0)));
    assert_eq!((change["slowest"].as_f64(), change["fastest"].as_f64()), (Some(80.0), Some(150.0)));
    for bad in ["[[0.0, 120.0], [0.0, 80.0]]", "[[0.0, -1.0]]", "[]"] {
        std::fs::write(&file, format!("[load]\nspeed_profile = {bad}\n")).unwrap();
        let out = frictrack(&["run", path]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("load.speed_profile"), "{bad}");
    }
    std::fs::write(&file, "[load]\nacceleration = 1.0\nspeed_profile = [[0.0, 50.0]]\n").unwrap();
    let out = frictrack(&["run", path]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not both"));
}

/// A sweep keeps the acceleration and varies the speed at x = 0: each point is the run at that speed (to the bit),
/// braking ends slower than it starts; a speed profile, which sets the speeds itself, fails every point by key.
#[test]
fn a_sweep_varies_the_speed_at_zero_and_keeps_the_acceleration() {
    let sweep = frictrack(&["sweep", "--speeds", "100:120:20", "--acceleration", "-10", "--elements", "200"]);
    assert!(sweep.status.success(), "{}", String::from_utf8_lossy(&sweep.stderr));
    let csv = String::from_utf8_lossy(&sweep.stdout);
    let row = csv.lines().find(|l| l.starts_with("120,")).unwrap();
    let swept: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
    let run =
        json(&frictrack(&["run", "--speed", "120", "--acceleration", "-10", "--elements", "200", "--format", "json"]));
    assert_eq!(swept, run["max_downward_deflection"]["value"].as_f64().unwrap());
    assert!(run["speed_change"]["end_speed"].as_f64().unwrap() < 120.0);
    let folder = temporary_folder("variable-speed-sweep");
    let file = folder.join("profile.toml");
    std::fs::write(&file, "[load]\nspeed_profile = [[0.0, 120.0], [200.0, 150.0]]\n[mesh]\nelements = 200\n").unwrap();
    let out = frictrack(&["sweep", file.to_str().unwrap(), "--speeds", "100:120:20"]);
    assert_ne!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stderr).contains("speed_profile"));
}
