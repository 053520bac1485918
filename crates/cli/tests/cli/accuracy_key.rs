//! `[integration] accuracy` (a run's `--accuracy` kept in the scenario) and the ballast friction's law a refinement
//! runs: taken by `run` and `check`, refused by name by every command that runs at the resolution given.

use crate::{frictrack, json, temporary_folder, write_file};

const REFINED: &str = "[mesh]\nelements = 50\n[integration]\nload_advance = 0.8\naccuracy = 0.05\n";

#[test]
fn a_scenario_s_accuracy_refines_its_run_and_the_flag_overrides_it() {
    let dir = temporary_folder("accuracy-key");
    let path = write_file(&dir, "refined.toml", REFINED);
    let v = json(&frictrack(&["run", &path, "--format", "json"]));
    assert_eq!(v["accuracy"]["tolerance"], 0.05);
    assert_eq!(v["accuracy"]["status"]["kind"], "reached");
    let v = json(&frictrack(&["run", &path, "--accuracy", "0.1", "--format", "json"]));
    assert_eq!(v["accuracy"]["tolerance"], 0.1);
    assert!(frictrack(&["check", &path]).status.success(), "check takes a run's accuracy");
}

#[test]
fn commands_that_keep_their_resolution_refuse_the_key_by_name() {
    let dir = temporary_folder("accuracy-key-refused");
    let path = write_file(&dir, "refined.toml", REFINED);
    let out = dir.join("study").to_str().unwrap().to_string();
    let refusals = [
        vec!["sweep", &path, "--speeds", "100:120:10"],
        vec!["stationary", &path, "--speed", "150"],
        vec!["receptance", &path, "--frequencies", "10:100:10"],
        vec!["study", "distributed-speed", "--scenario", &path, "--out", &out],
        vec!["run", &path, "--check-resolution"],
    ];
    for args in refusals {
        let out = frictrack(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("integration.accuracy = 0.05"), "{args:?}: {stderr}");
    }
    for bad in ["0", "1.5", "-0.1", "nan", "\"1%\""] {
        let path = write_file(&dir, "bad.toml", &format!("[integration]\naccuracy = {bad}\n"));
        for command in ["run", "check"] {
            let out = frictrack(&[command, &path]);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{command} {bad}: {stderr}");
            assert!(stderr.contains("integration.accuracy"), "{command} {bad}: {stderr}");
        }
    }
}

#[test]
fn light_ballast_friction_refines_on_one_section_a_node_and_heavy_keeps_four() {
    // A 40 m track from 20 elements: the law is chosen from the track and its load, whatever the size.
    let dir = temporary_folder("accuracy-law");
    let path =
        write_file(&dir, "short.toml", "[mesh]\nlength = 40\nelements = 20\n[integration]\nload_advance = 1.0\n");
    let run = |force: &str| {
        let args = ["--distributed-friction", force, "--accuracy", "0.3", "--format", "json"];
        json(&frictrack(&[&["run", &path][..], &args[..]].concat()))
    };
    let light = run("5000");
    let law = &light["accuracy"]["law"];
    assert_eq!((law["subdivisions"].as_u64(), law["chosen"].as_bool()), (Some(1), Some(true)), "{law}");
    // ρ_f = 2f_u/(βF) with β = 0.31417 1/m and F = 83.4 kN (docs/theory.md §2).
    assert!((law["friction_share"].as_f64().unwrap() - 0.3816).abs() < 1e-3, "{law}");
    let heavy = run("20000");
    let law = &heavy["accuracy"]["law"];
    assert_eq!((law["subdivisions"].as_u64(), law["chosen"].as_bool()), (Some(4), Some(false)), "{law}");
    let text =
        String::from_utf8(frictrack(&["run", &path, "--distributed-friction", "5000", "--accuracy", "0.3"]).stdout);
    assert!(text.unwrap().contains("ballast friction's law: one section a node (J = 1), chosen for the accuracy"));
}
