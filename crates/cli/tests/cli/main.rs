//! Runs the `frictrack` binary and checks its output and exit codes.

mod absurd_inputs;
mod accuracy_key;
mod bad_inputs;
mod bridges;
mod check_resolution;
mod co_moving;
mod examples;
mod failures;
mod figures;
mod friction_acceleration;
mod ground;
mod ground_friction;
mod ground_lift_off;
mod ground_two_beam_friction;
mod ground_two_beam_run;
mod ground_wave;
mod no_silent_substitutions;
mod receptance;
mod report;
mod run_out;
mod sleeper_convergence;
mod soil;
mod stationary;
mod sweeps;
mod timoshenko;
mod track_profile;
mod trains;
mod trust;
mod validate_first;
mod variable_speed;
mod vehicles;

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
    // docs/theory.md §8: 176.17 mm at v = 200 m/s, ζ = 0.05.
    let w = v["max_downward_deflection"]["value"].as_f64().unwrap();
    assert!((w - 0.17617).abs() < 0.5e-5, "{w}");
    let curve = json(&frictrack(&["analytic", "--speeds", "10:300:10", "--damping-ratio", "0.1", "--format", "json"]));
    let points = curve.as_array().unwrap();
    assert_eq!(points.len(), 30);
    let peak = points
        .iter()
        .max_by(|a, b| {
            a["max_downward_deflection"]["value"]
                .as_f64()
                .partial_cmp(&b["max_downward_deflection"]["value"].as_f64())
                .unwrap()
        })
        .unwrap();
    let v_peak = peak["speed"].as_f64().unwrap();
    assert!((190.0..=210.0).contains(&v_peak), "peak at {v_peak}");
}

#[test]
fn run_prints_the_documented_json() {
    let v =
        json(&frictrack(&["run", "--speed", "180", "--devices", "31", "--device-force", "50e3", "--format", "json"]));
    // One shape for every extreme ({value, position, time}) and one object for the energy balance.
    for key in [
        "/max_downward_deflection/value",
        "/max_downward_deflection/position",
        "/max_downward_deflection/time",
        "/max_upward_deflection/value",
        "/max_upward_deflection/position",
        "/max_upward_deflection/time",
        "/max_acceleration/value",
        "/window_max_downward_deflection/load_position",
        "/energy/load_work",
        "/energy/friction_work",
        "/energy/friction_dissipation",
        "/energy/dissipated",
        "/energy/numerical_dissipation",
        "/energy/transported",
        "/energy/residual",
        "/steps",
        "/mean_iterations",
        "/max_iterations",
        "/solver",
        "/wall_time",
        "/time_loop",
    ] {
        assert!(v.pointer(key).is_some_and(|x| !x.is_null()), "missing {key}");
    }
    let f = |k: &str| v.pointer(k).and_then(serde_json::Value::as_f64).unwrap();
    assert_eq!(v["solver"], "projection");
    assert_eq!(v["steps"], 2000);
    assert!(f("/max_downward_deflection/value") > 0.0 && f("/max_upward_deflection/value") > 0.0);
    assert!(f("/energy/dissipated") > 0.0 && f("/energy/friction_work") < 0.0);
    // Dissipations are positive: friction's is the opposite of its work, and all of the dissipated energy here.
    assert_eq!(f("/energy/friction_dissipation"), -f("/energy/friction_work"));
    assert_eq!(f("/energy/friction_dissipation") + f("/energy/viscous_dissipation"), f("/energy/dissipated"));
    assert!(f("/energy/residual").abs() < 1e-9 * f("/energy/load_work"));
    assert_eq!(f("/energy/transported"), 0.0, "a fixed track carries nothing out");
    // The whole run's time holds its time loop's (and the set-up and statics around it).
    assert!(f("/wall_time") >= f("/time_loop") && f("/time_loop") > 0.0);
    assert_eq!(v["device_positions"].as_array().unwrap().len(), 31);
    // Friction cuts the peak of the friction-free run.
    let free = json(&frictrack(&["run", "--speed", "180", "--format", "json"]));
    assert!(f("/max_downward_deflection/value") < free["max_downward_deflection"]["value"].as_f64().unwrap());
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
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--speeds = 10:5:1"));
    // The homotopy: its tolerance floor, and vehicles it cannot take — named by the solver's name, not a number.
    let out = frictrack(&["run", "--solver", "homotopy", "--tolerance", "1e-10", "--distributed-friction", "1000"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("integration.tolerance = 1e-10"));
    let cars = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/quarter-cars-random-rail.toml");
    let out = frictrack(&["run", cars, "--solver", "homotopy"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("integration.solver = homotopy: "), "{err}");
}

pub(crate) fn temporary_folder(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("frictrack-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Write `text` to `folder/name`; its path as a string, for a command line.
pub(crate) fn write_file(folder: &std::path::Path, name: &str, text: &str) -> String {
    let path = folder.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
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
    // Refuses to overwrite (invalid input: exit 2).
    assert_eq!(frictrack(&["init", template.to_str().unwrap()]).status.code(), Some(2));

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
    // The same sweep with the range on the command line and one thread, on stdout: the same bytes, then the units
    // as a comment line.
    let out = frictrack(&["sweep", path, "--speeds", "100:220:40", "--jobs", "1"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let (data, units) = stdout.split_at(csv.len());
    assert_eq!(data, csv);
    assert!(units.starts_with("# units (SI): speed m/s, max_downward_deflection m,") && units.ends_with("m/s²\n"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every kind of bad input exits with 2 and a message naming the file position or field path, the value and what
/// is allowed (the table doubles as the documentation of these messages).
#[test]
fn bad_scenarios_exit_2_with_line_or_path() {
    let dir = temporary_folder("bad");
    let cases: &[(&str, &[&str])] = &[
        ("[foundation]\ndampng = 0.1\n", &[":2:1: foundation.dampng: unknown field", "did you mean `damping`?"]),
        ("[integraton]\ntheta = 0.6\n", &[":1:2: integraton: unknown field", "did you mean `integration`?"]),
        ("[mesh]\nlength = \"abc\"\n", &[":2:10: mesh.length: invalid type: string \"abc\", expected f64"]),
        ("[mesh]\nelements = 2.5\n", &[":2:12: mesh.elements: invalid type: floating point `2.5`"]),
        ("[mesh\nlength = 1\n", &[":1:6:", "unclosed table"]),
        (
            "[integration]\nsolver = \"projecton\"\n",
            &["integration.solver: unknown variant", "did you mean `projection`?"],
        ),
        ("[integration]\ntheta = 0.3\n", &["integration.theta = 0.3: must lie in [0.5, 1]"]),
        ("[integration]\ntheta = 2.0\n", &["integration.theta = 2"]),
        ("[load]\nspeed = -3.0\n", &["load.speed = -3: must be finite and > 0 (m/s)"]),
        ("[sweep]\nfrom = 100.0\nto = 50.0\n", &["sweep.to = 50: must be finite and ≥ from = 100 (m/s)"]),
        ("[sweep]\nstep = 0.0\n", &["sweep.step = 0"]),
        ("[friction.devices]\ncount = 500\nforce = 1e3\n", &["friction.devices.count = 500: at most 199"]),
        ("[friction.devices]\nforce = 1e3\n", &["friction.devices", "give count or positions"]),
        ("[friction.devices]\npositions = [10.0, 250.0]\nforce = 1e3\n", &["friction.devices.positions = 250"]),
        (
            "[friction.distributed]\nforce_per_length = 1e3\nsubdivisions = 3\nquadrature = \"simpson\"\n",
            &["friction.distributed.subdivisions = 3: must be even with Simpson weights"],
        ),
        ("[friction.distributed]\nforce_per_length = -1.0\n", &["friction.distributed.force_per_length = -1"]),
        (
            "[integration]\nload_advance = 5.0\n",
            &["integration.load_advance = 5: must be > 0 and ≤ the element length"],
        ),
        ("[integration]\nmax_step = 0.0\n", &["integration.max_step = 0: must be a time step > 0 (s)"]),
        ("[foundation]\ndamping = 1.0\ndamping_ratio = 0.1\n", &["not both"]),
        ("[beam]\nyoungs_modulus = 0.0\n", &["youngs_modulus = 0"]),
        ("[mesh]\nelements = 0\n", &["mesh.elements = 0"]),
        ("[integration]\ntolerance = nan\n", &["integration.tolerance = NaN"]),
    ];
    for (i, (text, expected)) in cases.iter().enumerate() {
        let file = dir.join(format!("bad{i}.toml"));
        std::fs::write(&file, text).unwrap();
        let out = frictrack(&["check", file.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{text:?}: {err}");
        for e in *expected {
            assert!(err.contains(e), "{text:?}: expected `{e}` in {err}");
        }
        assert!(!err.contains("panicked") && !err.contains("RUST_BACKTRACE"), "{err}");
    }
    let missing = dir.join("missing.toml");
    let out = frictrack(&["check", missing.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot be read"));
    for args in [
        &["sweep", "--speeds", "10:5:1"][..],
        &["sweep", "--speeds", "fast"],
        &["sweep", "--speeds", "0:10:1"],
        &["sweep", "--shard", "4/3", "--out", "x.csv"],
        &["sweep", "--shard", "0/3", "--out", "x.csv"],
        &["run", "--speed", "nan"],
        &["study", "no-such-study"],
    ] {
        let out = frictrack(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
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
    assert!(meta["speeds"].is_null(), "a fixed-speed study has no speed list");
    assert_eq!(meta["columns"][1], serde_json::json!({ "name": "device_force", "unit": "N" }));
    assert!(meta["study_sets"][1].as_str().unwrap().starts_with("load.speed"));
    assert!(meta["scenario_parts_not_used"].as_array().unwrap().is_empty());
    // A base scenario with its own friction and [sweep]: the study says what it does not use, on stderr and in the
    // JSON, which records the scenario as given.
    let base = dir.join("base.toml");
    std::fs::write(&base, "[friction.distributed]\nforce_per_length = 5e3\n[sweep]\nfrom = 100\nto = 120\nstep = 10\n")
        .unwrap();
    let out =
        frictrack(&["study", "optimal-force", "--scenario", base.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("the scenario's [friction] is not used") && err.contains("[sweep] is not used"), "{err}");
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("optimal-force.json")).unwrap()).unwrap();
    assert_eq!(meta["scenario_parts_not_used"].as_array().unwrap().len(), 2);
    assert_eq!(meta["scenario"]["friction"]["distributed"]["force_per_length"], 5e3);
    let bad = frictrack(&["study", "no-such-study", "--out", dir.to_str().unwrap()]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("discrete-speed"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// All nine studies at coarse resolution (about 2 minutes): every file exists and parses, every figure is a valid
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
        "hslm",
        "vehicle-speed",
        "stationary-wave",
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
    // 3 + 3 + 1 + 3 + 4 + 2 + 6 + 6 + 4 figures.
    assert_eq!(figures, 32);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `study --help` names every preset the library knows (the list an unknown preset's error gives), so that the help
/// cannot fall behind a new study.
#[test]
fn study_help_names_every_preset() {
    let unknown = frictrack(&["study", "no-such-study"]);
    let stderr = String::from_utf8_lossy(&unknown.stderr);
    assert_eq!(unknown.status.code(), Some(2), "{stderr}");
    let list = stderr.split("must be one of ").nth(1).unwrap_or_else(|| panic!("{stderr}"));
    let names: Vec<&str> = list.trim().split(", ").collect();
    assert_eq!(names.len(), 13, "{names:?}");
    let help = String::from_utf8_lossy(&frictrack(&["study", "--help"]).stdout).replace('\n', " ");
    for name in names {
        assert!(help.contains(name), "study --help does not name {name}: {help}");
    }
}

/// The README shows the main job's output on the reference case (`cargo run --release -- run`): every line of it but
/// the wall time (a clock) is what `frictrack run` prints today.
#[test]
fn the_readme_shows_what_the_reference_run_prints() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md")).unwrap();
    let shown: Vec<&str> = readme
        .split("$ cargo run --release -- run\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .unwrap()
        .lines()
        .filter(|l| !l.trim_start().starts_with("wall time"))
        .collect();
    let out = frictrack(&["run"]);
    assert!(out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    let printed: Vec<&str> = stdout.lines().filter(|l| !l.trim_start().starts_with("wall time")).collect();
    assert_eq!(shown, printed);
}
