//! Runs the `frictrack` binary and checks its output and exit codes.

use std::process::{Command, Output};

fn frictrack(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_frictrack")).args(args).output().expect("run frictrack")
}

fn json(output: &Output) -> serde_json::Value {
    assert!(output.status.success(), "stderr: {}", String::from_utf8_lossy(&output.stderr));
    serde_json::from_slice(&output.stdout).expect("stdout is one JSON value")
}

#[test]
fn reference_reports_static_case_against_closed_form() {
    let out = frictrack(&["reference", "--format", "json"]);
    let v = json(&out);
    let w = v["midspan_deflection"].as_f64().unwrap();
    let w0 = v["midspan_deflection_closed_form"].as_f64().unwrap();
    assert!((w - w0).abs() / w0.abs() < 1e-4, "{w} vs {w0}");
    assert!((w0 + 52.40e-3).abs() < 0.005e-3);
    assert_eq!(v["modes"].as_array().unwrap().len(), 5);
    let text = frictrack(&["reference"]);
    assert!(text.status.success());
    assert!(String::from_utf8_lossy(&text.stdout).contains("critical speed v_cr = 205.57 m/s"));
}

#[test]
fn analytic_matches_model_md_value() {
    let v = json(&frictrack(&["analytic", "--speed", "200", "--damping-ratio", "0.05", "--format", "json"]));
    // MODEL.md §8: 176.17 mm at v = 200 m/s, ζ = 0.05.
    let w = v["max_downward_deflection"].as_f64().unwrap();
    assert!((w - 0.17617).abs() < 0.5e-5, "{w}");
    let curve = json(&frictrack(&["analytic", "--speeds", "10:300:10", "--damping-ratio", "0.1", "--format", "json"]));
    let points = curve.as_array().unwrap();
    assert_eq!(points.len(), 30);
    let peak = points
        .iter()
        .max_by(|a, b| {
            a["max_downward_deflection"].as_f64().partial_cmp(&b["max_downward_deflection"].as_f64()).unwrap()
        })
        .unwrap();
    let v_peak = peak["speed"].as_f64().unwrap();
    assert!((190.0..=210.0).contains(&v_peak), "peak at {v_peak}");
}

#[test]
fn run_prints_the_documented_json() {
    let v =
        json(&frictrack(&["run", "--speed", "180", "--devices", "31", "--device-force", "50e3", "--format", "json"]));
    for key in [
        "max_downward_deflection",
        "max_upward_deflection",
        "max_downward_deflection_position",
        "max_downward_deflection_time",
        "max_upward_deflection_position",
        "max_upward_deflection_time",
        "load_work",
        "friction_work",
        "dissipated_energy",
        "numerical_dissipation",
        "energy_residual",
        "steps",
        "mean_iterations",
        "max_iterations",
        "solver",
        "wall_time",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    let f = |k: &str| v[k].as_f64().unwrap();
    assert_eq!(v["solver"], "projection");
    assert_eq!(v["steps"], 2000);
    assert!(f("max_downward_deflection") > 0.0 && f("max_upward_deflection") > 0.0);
    assert!(f("dissipated_energy") > 0.0 && f("friction_work") < 0.0);
    assert!(f("energy_residual").abs() < 1e-9 * f("load_work"));
    assert_eq!(v["device_positions"].as_array().unwrap().len(), 31);
    // Friction cuts the peak of the friction-free run.
    let free = json(&frictrack(&["run", "--speed", "180", "--format", "json"]));
    assert!(f("max_downward_deflection") < free["max_downward_deflection"].as_f64().unwrap());
}

#[test]
fn invalid_input_exits_2_with_a_named_field() {
    let out = frictrack(&["run", "--theta", "0.4"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("integration.theta"));
    let out = frictrack(&["run", "--devices", "500"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("devices.count"));
    let out = frictrack(&["run", "--speed=-3"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("speed"));
    let out = frictrack(&["reference", "--elements", "0"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("mesh.elements"), "{err}");
    let out = frictrack(&["analytic", "--speed", "250"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("damping > 0"));
    let out = frictrack(&["analytic", "--speeds", "10:5:1"]);
    assert_ne!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stderr).contains("speed range"));
}

fn temporary_folder(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("frictrack-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn init_check_run_and_sweep_a_scenario_file() {
    let dir = temporary_folder("scenario");
    let template = dir.join("case.toml");
    let out = frictrack(&["init", template.to_str().unwrap()]);
    assert!(out.status.success());
    let out = frictrack(&["check", template.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains(": ok"));
    // Refuses to overwrite.
    assert!(!frictrack(&["init", template.to_str().unwrap()]).status.success());

    let small = dir.join("small.toml");
    std::fs::write(
        &small,
        "[mesh]\nlength = 60.0\nelements = 60\n[friction.devices]\ncount = 7\nforce = 20e3\n\
         [sweep]\nfrom = 100.0\nto = 220.0\nstep = 40.0\n",
    )
    .unwrap();
    let path = small.to_str().unwrap();
    let v = json(&frictrack(&["run", path, "--speed", "150", "--format", "json"]));
    assert_eq!(v["devices"], 7);
    assert_eq!(v["steps"], 600);
    assert!((v["speed"].as_f64().unwrap() - 150.0).abs() < 1e-12);

    let csv_path = dir.join("sweep.csv");
    let out = frictrack(&["sweep", path, "--out", csv_path.to_str().unwrap(), "--jobs", "2"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert!(lines[0].starts_with("speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm"));
    assert_eq!(lines.len(), 5);
    assert!(lines[1].starts_with("100,"));
    // The same sweep with the range on the command line and one thread, on stdout: the same bytes.
    let out = frictrack(&["sweep", path, "--speeds", "100:220:40", "--jobs", "1"]);
    assert_eq!(String::from_utf8_lossy(&out.stdout), csv);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_scenarios_exit_2_with_line_or_path() {
    let dir = temporary_folder("bad");
    let typo = dir.join("typo.toml");
    std::fs::write(&typo, "[foundation]\ndampng = 0.1\n").unwrap();
    let out = frictrack(&["check", typo.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("typo.toml:2:1") && err.contains("dampng"), "{err}");
    let range = dir.join("range.toml");
    std::fs::write(&range, "[integration]\ntheta = 2.0\n").unwrap();
    let out = frictrack(&["run", range.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("integration.theta"));
    let missing = dir.join("missing.toml");
    let out = frictrack(&["check", missing.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

fn is_png(path: &std::path::Path) -> bool {
    std::fs::read(path)
        .is_ok_and(|b| b.len() > 1000 && b.starts_with(&[0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a]))
}

fn is_svg(path: &std::path::Path) -> bool {
    std::fs::read_to_string(path).is_ok_and(|s| s.contains("<svg") && s.trim_end().ends_with("</svg>"))
}

#[test]
fn study_writes_data_metadata_and_figures() {
    let dir = temporary_folder("study");
    let out = frictrack(&["study", "optimal-force", "--out", dir.to_str().unwrap(), "--quiet"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("optimal-force.csv")).unwrap();
    assert!(csv.starts_with("devices,device_force,speed,max_downward_deflection"));
    assert_eq!(csv.lines().count(), 1 + 4 * 9);
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("optimal-force.json")).unwrap()).unwrap();
    assert_eq!(meta["study"], "optimal-force");
    assert_eq!(meta["summary"]["optima"].as_array().unwrap().len(), 4);
    assert!(meta["wall_time"].as_f64().unwrap() > 0.0);
    assert!(is_png(&dir.join("optimal-force.png")) && is_svg(&dir.join("optimal-force.svg")));
    let bad = frictrack(&["study", "no-such-study", "--out", dir.to_str().unwrap()]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("discrete-speed"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// All six studies at coarse resolution (about 1.5 minutes): every file exists and parses, every figure is a valid
/// PNG and SVG, and the report shows every figure.
#[test]
fn reproduce_coarse_writes_every_study_and_a_report() {
    let dir = temporary_folder("reproduce");
    let out = frictrack(&["reproduce", "--out", dir.to_str().unwrap(), "--resolution", "coarse", "--quiet"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    let mut figures = 0;
    for name in [
        "discrete-speed",
        "equal-cost",
        "optimal-force",
        "distributed-speed",
        "amplification",
        "discrete-vs-distributed",
    ] {
        let csv = std::fs::read_to_string(dir.join(format!("{name}.csv"))).unwrap();
        let columns = csv.lines().next().unwrap().split(',').count();
        assert!(csv.lines().skip(1).all(|l| l.split(',').count() == columns), "{name}.csv is ragged");
        let meta: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join(format!("{name}.json"))).unwrap()).unwrap();
        for stem in meta["plots"].as_array().unwrap() {
            let stem = stem.as_str().unwrap();
            assert!(is_png(&dir.join(format!("{stem}.png"))), "{stem}.png");
            assert!(is_svg(&dir.join(format!("{stem}.svg"))), "{stem}.svg");
            assert!(report.contains(&format!("({stem}.png)")), "report misses {stem}");
            figures += 1;
        }
        assert!(report.contains(&format!("({name}.csv)")));
    }
    // 3 + 3 + 1 + 3 + 4 + 2 figures.
    assert_eq!(figures, 16);
    let _ = std::fs::remove_dir_all(&dir);
}
