//! `frictrack trains` and trains in `run` (docs/theory.md §10): the catalogue, one train's axles, `--train` with a
//! catalogue name, a CSV file and scenario axles, and bad trains refused with the value named.

use super::{frictrack, json, temporary_folder, write_file};

#[test]
fn the_catalogue_lists_the_single_load_and_ten_hslm_trains() {
    let list = json(&frictrack(&["trains", "--format", "json"]));
    let names: Vec<&str> = list.as_array().unwrap().iter().map(|t| t["name"].as_str().unwrap()).collect();
    assert_eq!(names.len(), 11);
    assert_eq!(names[0], "single");
    assert_eq!(names[10], "hslm-a10");
    let a1 = json(&frictrack(&["trains", "hslm-a1", "--format", "json"]));
    assert_eq!(a1["name"], "hslm-a1");
    assert_eq!(a1["axles"].as_array().unwrap().len(), 50);
    assert!((a1["length"].as_f64().unwrap() - 397.525).abs() < 1e-9);
    assert_eq!(a1["axles"][4]["offset"].as_f64().unwrap(), 20.525);
    assert_eq!(a1["axles"][0]["force"].as_f64().unwrap(), 170e3);
    let text = frictrack(&["trains"]);
    assert!(String::from_utf8_lossy(&text.stdout).contains("hslm-a7        40     397.525"));
}

#[test]
fn runs_take_a_train_by_name_file_or_scenario_axles() {
    let folder = temporary_folder("trains");
    let csv = folder.join("pair.csv");
    std::fs::write(&csv, "offset,force\n0,100e3\n2.5,100e3 # a bogie\n").unwrap();
    let scenario = folder.join("pair.toml");
    std::fs::write(&scenario, "[load]\nspeed = 100.0\n[[load.axles]]\noffset = 0.0\nforce = 100e3\n[[load.axles]]\noffset = 2.5\nforce = 100e3\n").unwrap();
    let by_file = json(&frictrack(&["run", "--train", csv.to_str().unwrap(), "--speed", "100", "--format", "json"]));
    let by_scenario = json(&frictrack(&["run", scenario.to_str().unwrap(), "--format", "json"]));
    assert_eq!(by_file["train"]["axles"], 2);
    assert_eq!(by_scenario["train"]["name"], "scenario");
    // The same two axles, however given: the same run.
    assert_eq!(by_file["max_downward_deflection"], by_scenario["max_downward_deflection"]);
    assert_eq!(by_file["steps"], by_scenario["steps"]);
    // The run lasts until the last axle leaves: (200 + 2.5) m at 0.1 m per step.
    assert_eq!(by_file["steps"].as_u64().unwrap(), 2025);
    let hslm = json(&frictrack(&["run", "--train", "hslm-a1", "--speed", "80", "--format", "json"]));
    assert_eq!(hslm["train"]["name"], "hslm-a1");
    assert_eq!(hslm["steps"].as_u64().unwrap(), 5975);
    assert!(hslm["energy"]["residual"].as_f64().unwrap().abs() < 1e-9 * hslm["energy"]["load_work"].as_f64().unwrap());
    let single = json(&frictrack(&["run", "--speed", "80", "--format", "json"]));
    assert!(single.get("train").is_none(), "the single load names no train");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn bad_trains_exit_2_naming_the_value() {
    let folder = temporary_folder("bad-trains");
    let both = folder.join("both.toml");
    std::fs::write(&both, "[load]\ntrain = \"hslm-a1\"\n[[load.axles]]\noffset = 0.0\nforce = 1e5\n").unwrap();
    let negative = folder.join("negative.toml");
    std::fs::write(
        &negative,
        "[[load.axles]]\noffset = 0.0\nforce = 1e5\n[[load.axles]]\noffset = -3.0\nforce = 1e5\n",
    )
    .unwrap();
    let garbled = folder.join("garbled.csv");
    std::fs::write(&garbled, "0,1e5\n2.5;1e5\n").unwrap();
    let cases: [(Vec<&str>, &str); 6] = [
        (vec!["run", "--train", "/nonexistent/train.csv"], "cannot read the train file"),
        (vec!["run", "--train", "hslm-a11"], "hslm-a11"),
        (vec!["trains", "hslm-a0"], "hslm-a0"),
        (vec!["run", both.to_str().unwrap()], "load.train"),
        (vec!["run", negative.to_str().unwrap()], "load.axles[1].offset"),
        (vec!["run", "--train", garbled.to_str().unwrap()], "line 2"),
    ];
    for (args, needle) in cases {
        let out = frictrack(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(needle), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

/// `analytic --train`: the single train equals the plain single load; HSLM-A1 at a crawl is its static response
/// (DAF → 1) and its largest deflection sits among the axles.
#[test]
fn analytic_superposes_a_train() {
    let args = |extra: &[&'static str]| {
        let mut a = vec!["analytic", "--speed", "120", "--damping-ratio", "0.05", "--format", "json"];
        a.extend_from_slice(extra);
        a
    };
    let plain = json(&frictrack(&args(&[])));
    let single = json(&frictrack(&args(&["--train", "single"])));
    for key in ["/max_downward_deflection/value", "/max_upward_deflection/value", "/amplification_downward"] {
        let (a, b) = (plain.pointer(key).unwrap().as_f64().unwrap(), single.pointer(key).unwrap().as_f64().unwrap());
        assert!((a - b).abs() <= 1e-9 * a.abs(), "{key}: {a} vs {b}");
    }
    let crawl = json(&frictrack(&["analytic", "--speed", "1", "--train", "hslm-a1", "--format", "json"]));
    let daf = crawl["amplification_downward"].as_f64().unwrap();
    assert!((daf - 1.0).abs() < 1e-3, "DAF at 1 m/s: {daf}");
    let at = crawl["max_downward_deflection"]["position"].as_f64().unwrap();
    assert!((-397.525..=0.0).contains(&at), "under the train: s = {at}");
}

/// Output piped into a reader that stops early (`frictrack … | head -1`): no panic report, the exit code of a Unix
/// tool stopped by SIGPIPE (141). 10 000 axles of JSON (~0.5 MB) overflow any pipe buffer.
#[test]
fn a_closed_pipe_ends_the_command_quietly() {
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    let folder = temporary_folder("pipe");
    let csv = folder.join("long.csv");
    let lines: String = (0..10_000).map(|i| format!("{},1e5\n", i as f64 * 0.5)).collect();
    std::fs::write(&csv, lines).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_frictrack"))
        .args(["trains", csv.to_str().unwrap(), "--format", "json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut first).unwrap();
    assert_eq!(first.trim(), "{");
    // The reader is dropped here: the pipe closes with most of the output unwritten.
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(141), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    std::fs::remove_dir_all(&folder).unwrap();
}

/// `analytic SCENARIO` takes the scenario's train as the beam carries it (one rail's half of each HSLM-A1 axle on
/// the reference track): the same as `--train hslm-a1`, and half the deflection of whole axles (the steady state is
/// linear in the loads); `reference` refuses a train (it checks one load at mid-span), naming the key; catalogue
/// names are taken in any case.
#[test]
fn analytic_takes_the_scenarios_train_and_reference_refuses_it() {
    let folder = temporary_folder("scenario-train");
    let write = |name: &str, text: &str| write_file(&folder, name, text);
    let rail = write("rail.toml", "[load]\ntrain = \"HSLM-A1\"\n[foundation]\ndamping_ratio = 0.05\n");
    let whole = write(
        "whole.toml",
        "[load]\ntrain = \"hslm-a1\"\ncarries = \"whole-axle\"\n[foundation]\ndamping_ratio = 0.05\n",
    );
    let deflection = |args: &[&str]| {
        let v = json(&frictrack(&[&["analytic"], args, &["--speed", "100", "--format", "json"]].concat()));
        v["max_downward_deflection"]["value"].as_f64().unwrap()
    };
    let from_file = deflection(&[&rail]);
    let by_flag = deflection(&["--train", "HSLM-A1", "--damping-ratio", "0.05"]);
    let whole_axles = deflection(&[&whole]);
    assert_eq!(from_file, by_flag);
    assert!((whole_axles / from_file - 2.0).abs() < 1e-12, "{whole_axles} vs {from_file}");
    // Not the single 83.4 kN load the scenario's train replaces.
    let single = deflection(&["--damping-ratio", "0.05"]);
    assert!(from_file > 1.5 * single, "{from_file} vs {single}");
    let out = frictrack(&["reference", &rail]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("load.train = HSLM-A1") && stderr.contains("frictrack analytic"), "{stderr}");
    std::fs::remove_dir_all(&folder).unwrap();
}
