//! What a run or a sweep does when something fails on the way: a step its solver cannot solve is solved by a
//! fallback and reported; a sweep keeps every finished run past a failed one, records the failure, exits non-zero.

use super::{frictrack, json, temporary_folder, write_file};

/// An interior point held to 3 iterations a step (it needs ~20) cannot solve a step of distributed friction: every
/// step is solved by Clarabel instead, and the run says so in text and JSON.
#[test]
fn a_run_reports_the_steps_its_solver_could_not_solve() {
    let dir = temporary_folder("fallback");
    let scenario = write_file(
        &dir,
        "held.toml",
        "[mesh]\nlength = 30.0\nelements = 30\n[friction.distributed]\nforce_per_length = 5000.0\n\
         [integration]\nsolver = \"interior-point\"\nmax_iterations = 3\n",
    );
    let path = scenario.as_str();
    let v = json(&frictrack(&["run", path, "--speed", "100", "--format", "json"]));
    let steps = v["steps"].as_u64().unwrap();
    assert_eq!(v["solver"], "interior-point");
    assert_eq!(v["fallback_steps"].as_u64(), Some(steps), "{v}");
    assert_eq!(v["fallbacks"][0]["solver"], "clarabel");
    assert!(v["max_residual"].as_f64().unwrap() <= 1e-6, "{v}");
    let text = frictrack(&["run", path, "--speed", "100"]);
    assert!(text.status.success());
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains(&format!("fallback: interior-point failed on {steps} of {steps} steps")), "{stdout}");
    assert!(stdout.contains("solved instead by clarabel"), "{stdout}");
    let stderr = String::from_utf8_lossy(&text.stderr);
    assert!(stderr.contains("--solver interior-point could not solve most steps of this run; --solver clarabel"));
    // The default solver meets the tolerance alone: no fallback line.
    let alone = frictrack(&["run", "--speed", "20", "--distributed-friction", "1000"]);
    assert!(alone.status.success(), "{}", String::from_utf8_lossy(&alone.stderr));
    assert!(!String::from_utf8_lossy(&alone.stdout).contains("fallback"));
}

/// Undamped, a steady start has no steady state at or above v_cr = 205.57 m/s: those runs fail, the others are
/// kept — on stdout with `# failed_run` lines, with `--out` as empty rows beside a JSON that lists the failures —
/// and the sweep exits with 1, naming each failed speed, after writing everything else.
#[test]
fn a_sweep_keeps_every_finished_run_past_a_failed_one() {
    let args = ["sweep", "--speeds", "195:215:5", "--steady-start", "50", "--jobs", "2", "--quiet"];
    let out = frictrack(&args);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = stdout.lines().collect();
    // Header, five rows, the two failures and the units as comment lines.
    assert_eq!(lines.len(), 1 + 5 + 2 + 1, "{stdout}");
    for (line, speed) in lines[1..4].iter().zip(["195,", "200,", "205,"]) {
        assert!(line.starts_with(speed) && !line.contains(",,"), "{line}");
    }
    assert_eq!(lines[4], format!("210{}", ",".repeat(16)));
    assert!(lines[6].starts_with("# failed_run {\"speed\":210.0,\"error\":\"no bounded steady state"), "{stdout}");
    assert!(stderr.contains("2 of 5 runs failed") && stderr.contains("215 m/s: no bounded steady state"), "{stderr}");

    let dir = temporary_folder("sweep-failures");
    let csv = dir.join("sweep.csv");
    let out = frictrack(&[&args[..5], &["--out", csv.to_str().unwrap(), "--quiet"]].concat());
    assert_eq!(out.status.code(), Some(1));
    let written = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(written.lines().collect::<Vec<_>>(), lines[..6].to_vec(), "the same rows as on stdout");
    let meta: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("sweep.json")).unwrap()).unwrap();
    let failures = meta["failures"].as_array().unwrap();
    assert_eq!(failures.len(), 2);
    assert_eq!(failures[1]["speed"], 215.0);
    assert!(dir.join("sweep.csv.journal").exists(), "the journal is kept for --resume");
}

/// A study keeps every finished run past failed ones: undamped with a steady start, the runs above v_cr = 205.57
/// m/s fail on every curve of the distributed-friction study; its CSV keeps their rows (labels and speed, values
/// empty) beside the finished ones, its JSON lists each failure with its curve, its figures are drawn, the failures
/// are printed and it exits with 1, the journal kept for --resume.
#[test]
fn a_study_keeps_every_finished_run_past_failed_ones() {
    let dir = temporary_folder("study-failures");
    let scenario = write_file(
        &dir,
        "undamped.toml",
        "[mesh]\nlength = 100.0\nelements = 100\n[integration]\nsteady_start = 50.0\n\
         [sweep]\nfrom = 195.0\nto = 215.0\nstep = 5.0\n",
    );
    let out_dir = dir.join("out");
    let args = ["study", "distributed-speed", "--scenario", &scenario];
    let out = frictrack(&[&args[..], &["--out", out_dir.to_str().unwrap(), "--quiet"]].concat());
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("10 run(s) of distributed-speed failed"), "{stderr}");
    assert!(stderr.contains("force_per_length = 1000 at 215 m/s: no bounded steady state"), "{stderr}");
    let csv = std::fs::read_to_string(out_dir.join("distributed-speed.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 5 * 5, "every curve keeps a row per speed");
    let empty: Vec<&&str> = rows.iter().filter(|r| r.ends_with(",,,,,,")).collect();
    assert_eq!(empty.len(), 10, "{csv}");
    assert!(empty.iter().all(|r| r.contains(",210,") || r.contains(",215,")), "{csv}");
    let meta: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out_dir.join("distributed-speed.json")).unwrap()).unwrap();
    let failures = meta["failures"].as_array().unwrap();
    assert_eq!(failures.len(), 10);
    assert_eq!(failures[0]["case"], "force_per_length = 0");
    assert_eq!(failures[0]["speed"], 210.0);
    assert!(out_dir.join("distributed-speed-deflection.svg").exists());
    assert!(out_dir.join(".distributed-speed.journal").exists(), "the journal is kept for --resume");
}

/// The HSLM study keeps going past failed runs too: on the example deck (bar wave speed 3742 m/s) a sweep 50, 2050,
/// 4050 m/s has its 4050 m/s runs refused, each curve keeps the others, the failures are listed in the JSON with
/// their train, the figures are drawn and the study exits with 1.
#[test]
fn the_train_study_keeps_every_finished_run_past_failed_ones() {
    let dir = temporary_folder("hslm-failures");
    let deck =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/hslm-bridge.toml")).unwrap();
    let scenario =
        write_file(&dir, "fast.toml", &format!("{deck}\n[sweep]\nfrom = 50.0\nto = 4050.0\nstep = 2000.0\n"));
    let out_dir = dir.join("out");
    let out = frictrack(&["study", "hslm", "--scenario", &scenario, "--out", out_dir.to_str().unwrap(), "--quiet"]);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let meta: serde_json::Value = serde_json::from_slice(&std::fs::read(out_dir.join("hslm.json")).unwrap()).unwrap();
    let failures = meta["failures"].as_array().unwrap();
    let at_4050 = failures.iter().filter(|f| f["speed"] == 4050.0).count();
    assert_eq!(at_4050, 20, "ten trains, with and without friction: {failures:?}");
    assert!(failures.iter().any(|f| f["case"] == "HSLM-A7, friction"), "{failures:?}");
    let csv = std::fs::read_to_string(out_dir.join("hslm.csv")).unwrap();
    assert!(csv.lines().count() > 40, "the finished runs are kept: {csv}");
    assert!(out_dir.join("hslm-deflection.svg").exists() && out_dir.join("hslm-envelope-acceleration.svg").exists());
}

/// The vehicle study keeps going past failed runs: on a 30 m track at 50, 5050 and 10 050 m/s the last speed is
/// refused per run (the rail's bar wave speed is 5189 m/s), each of the twelve curves keeps its other two speeds,
/// the CSV keeps a row with empty values for each failed one, the JSON lists ten failures (the moving force's run
/// serves both rails), the figures are drawn and the study exits with 1.
#[test]
fn the_vehicle_study_keeps_every_finished_run_past_failed_ones() {
    let dir = temporary_folder("vehicle-failures");
    let scenario = write_file(
        &dir,
        "fast.toml",
        "[mesh]\nlength = 30.0\nelements = 30\n[sweep]\nfrom = 50.0\nto = 10050.0\nstep = 5000.0\n",
    );
    let out_dir = dir.join("out");
    let args = ["study", "vehicle-speed", "--scenario", &scenario, "--out", out_dir.to_str().unwrap(), "--quiet"];
    let out = frictrack(&args);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("10 run(s) of vehicle-speed failed"), "{stderr}");
    assert!(stderr.contains("model = quarter-car, friction = with, rail = irregular at 10050 m/s"), "{stderr}");
    let csv = std::fs::read_to_string(out_dir.join("vehicle-speed.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 12 * 3, "every curve keeps a row per speed: {csv}");
    let empty: Vec<&&str> = rows.iter().filter(|r| r.ends_with(",10050,,,,,,,")).collect();
    assert_eq!(empty.len(), 12, "{csv}");
    assert!(rows.iter().filter(|r| !r.contains(",10050,")).all(|r| !r.contains(",,,,")), "{csv}");
    let meta: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out_dir.join("vehicle-speed.json")).unwrap()).unwrap();
    let failures = meta["failures"].as_array().unwrap();
    assert_eq!(failures.len(), 10, "{failures:?}");
    assert_eq!(failures[0]["case"], "model = moving-force, friction = none");
    assert_eq!(meta["runs"], 20, "the finished runs");
    assert!(out_dir.join("vehicle-speed-deflection-irregular.svg").exists());
}

/// The fixed-speed studies keep going past failed runs too. Undamped with a steady start on a foundation of
/// 389 kN/m² (v_cr = 229.6 m/s): the amplification study's runs at 250 m/s (v_cr rounded up to five steps) have no
/// steady state and fail, its six others are kept, with their figures, and the study exits with 1; the optimal
/// force study runs at 230 m/s (v_cr to a tenth of a step), where every run fails: it exits with 1 naming the first
/// error, not with a figure of nothing.
#[test]
fn fixed_speed_studies_keep_every_finished_run_past_failed_ones() {
    let dir = temporary_folder("fixed-speed-failures");
    let scenario = write_file(
        &dir,
        "undamped.toml",
        "[mesh]\nlength = 100.0\nelements = 100\n[foundation]\nstiffness = 389e3\n[integration]\nsteady_start = 50.0\n",
    );
    let out_dir = dir.join("out");
    let study = |preset: &str| {
        frictrack(&["study", preset, "--scenario", &scenario, "--out", out_dir.to_str().unwrap(), "--quiet"])
    };
    let out = study("amplification");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("force_per_length = 2000 at 250 m/s: no bounded steady state"), "{stderr}");
    let meta: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out_dir.join("amplification.json")).unwrap()).unwrap();
    assert_eq!(meta["failures"].as_array().unwrap().len(), 2, "{meta}");
    assert_eq!(meta["summary"]["curves"].as_array().unwrap().len(), 6, "{meta}");
    let csv = std::fs::read_to_string(out_dir.join("amplification.csv")).unwrap();
    let speeds: std::collections::BTreeSet<&str> = csv.lines().skip(1).filter_map(|r| r.split(',').nth(1)).collect();
    assert_eq!(speeds.into_iter().collect::<Vec<_>>(), ["100", "150", "50"], "{csv}");
    assert!(out_dir.join("amplification-moment-2kN.svg").exists());

    let out = study("optimal-force");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("every run of the optimal-force scan at 230 m/s failed; the first: no bounded"),
        "{stderr}"
    );
    assert!(!out_dir.join("optimal-force.svg").exists(), "no figure of nothing");
}

/// `reproduce` on a scenario one study's own set-up does not fit (199 devices on a 40 m track of 39 interior nodes):
/// that study is recorded in the report as not run, with the reason, and the eight others are run and written; the
/// command exits with 1 naming it. Before, it stopped at the sixth study with exit 2 and no report.
#[test]
fn reproduce_records_a_study_that_cannot_run_on_the_scenario() {
    let dir = temporary_folder("reproduce-not-run");
    let scenario = write_file(&dir, "short.toml", "[mesh]\nlength = 40.0\nelements = 40\n");
    let out_dir = dir.join("out");
    let out = frictrack(&["reproduce", "--scenario", &scenario, "--out", out_dir.to_str().unwrap(), "--quiet"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("discrete-vs-distributed: not run on this scenario: invalid friction.devices.count = 199"));
    let report = std::fs::read_to_string(out_dir.join("report.md")).unwrap();
    assert!(report.contains("## 6. discrete-vs-distributed — not run on this scenario"), "{report}");
    let sections = report.lines().filter(|l| l.starts_with("## ")).count();
    assert_eq!(sections, 9, "{report}");
    assert!(out_dir.join("vehicle-speed.csv").exists() && !out_dir.join("discrete-vs-distributed.csv").exists());
}

/// A 20 m deck on a tensionless soil of zero stiffness (no soil under the span) stopped with "non-finite state at step
/// 2" whatever θ or solver: its soil sections were compliant stops of zero stiffness. It runs, says the law acts on
/// no soil, and gives the span on its supports alone — the linear deck's answer to the bit.
#[test]
fn a_tensionless_soil_of_zero_stiffness_is_no_soil() {
    let dir = temporary_folder("no-soil");
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/hslm-bridge.toml");
    let deck = std::fs::read_to_string(example).unwrap();
    let tensionless =
        write_file(&dir, "deck.toml", &deck.replace("stiffness = 0.0", "stiffness = 0.0\nlaw = \"tensionless\""));
    let out = frictrack(&["run", &tensionless, "--format", "json"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("warning: foundation.law = tensionless: acts on no soil"), "{stderr}");
    let on_nothing = json(&out);
    let linear = json(&frictrack(&["run", example, "--format", "json"]));
    assert_eq!(on_nothing["max_downward_deflection"], linear["max_downward_deflection"]);
}
