//! `run --check-resolution`: each outcome at three resolutions and the run's estimated error, in text and JSON;
//! twins that cannot be built refused before any work; an interruption during the twins keeps the run's report.

use crate::{frictrack, json};
use std::process::{Command, Stdio};
use std::time::Duration;

#[test]
fn the_check_reports_each_outcome_at_three_resolutions_with_the_runs_error() {
    let args = ["run", "--elements", "60", "--load-advance", "0.4", "--speed", "150", "--check-resolution"];
    let v = json(&frictrack(&[&args[..], &["--format", "json"]].concat()));
    let check = &v["resolution_check"];
    let elements: Vec<u64> =
        check["resolutions"].as_array().unwrap().iter().map(|r| r["elements"].as_u64().unwrap()).collect();
    assert_eq!(elements, [30, 60, 120], "a coarser and a finer twin");
    assert_eq!(check["run"], 1);
    let outcomes = check["outcomes"].as_array().unwrap();
    let window = outcomes.iter().find(|o| o["name"] == "window_max_downward_deflection").unwrap();
    assert_eq!(window["values"][1], v["window_max_downward_deflection"]["value"], "the run's own value in the middle");
    assert_eq!(window["unit"], "m");
    for o in outcomes {
        let undefined = o["convergence"]["kind"] == "not_contracting";
        assert_eq!(o["error"].is_null(), undefined, "{o}");
        assert_eq!(o["relative"].is_null(), undefined || o["values"][1] == 0.0, "{o}");
    }
    let text = frictrack(&args);
    assert!(text.status.success());
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("resolution check: each outcome at three resolutions"), "{stdout}");
    assert!(stdout.contains("elements × load advance: 30 × 0.8 m"), "{stdout}");
    assert!(stdout.contains("window_max_downward_deflection"), "{stdout}");
    let plain = json(&frictrack(&["run", "--elements", "60", "--load-advance", "0.4", "--format", "json"]));
    assert!(plain.get("resolution_check").is_none(), "no check unless asked");
}

#[test]
fn an_odd_mesh_is_checked_against_two_finer_twins() {
    let v = json(&frictrack(&[
        "run",
        "--elements",
        "51",
        "--load-advance",
        "0.4",
        "--check-resolution",
        "--format",
        "json",
    ]));
    let check = &v["resolution_check"];
    let elements: Vec<u64> =
        check["resolutions"].as_array().unwrap().iter().map(|r| r["elements"].as_u64().unwrap()).collect();
    assert_eq!(elements, [51, 102, 204]);
    assert_eq!(check["run"], 0);
}

#[test]
fn twins_that_cannot_be_built_or_run_are_refused_before_any_work() {
    // 600 000 elements: the finer twin's 1 200 000 exceed the mesh's limit — said at once, not after the run.
    let started = std::time::Instant::now();
    let out = frictrack(&["run", "--elements", "600000", "--load-advance", "0.0003", "--check-resolution"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--check-resolution") && stderr.contains("mesh.elements = 1200000"), "{stderr}");
    assert!(started.elapsed() < Duration::from_secs(20), "refused after {:?}", started.elapsed());
    let out = frictrack(&["run", "--co-moving", "--check-resolution"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--check-resolution"));
}

/// SIGTERM while the twins run (201 elements: two finer twins, ~20 times the run's 0.2 s) stops them; the run's own
/// report is printed without the check, and the exit code is 130.
#[test]
fn an_interruption_during_the_twins_keeps_the_runs_report() {
    let child = Command::new(env!("CARGO_BIN_EXE_frictrack"))
        .args(["run", "--elements", "201", "--load-advance", "0.2", "--distributed-friction", "5000"])
        .arg("--check-resolution")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    let (output, stopped) = crate::trust::terminate(child);
    assert!(stopped < Duration::from_secs(2), "took {stopped:?}");
    assert_eq!(output.status.code(), Some(130));
    let (stdout, stderr) = (String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    assert!(stdout.contains("max downward deflection") && !stdout.contains("resolution check"), "{stdout}");
    assert!(stderr.contains("the run's report stands without its resolution check"), "{stderr}");
}

#[test]
fn accuracy_refines_until_every_outcome_is_within_it_and_says_so() {
    let v = json(&frictrack(&[
        "run",
        "--elements",
        "50",
        "--load-advance",
        "0.8",
        "--accuracy",
        "0.05",
        "--format",
        "json",
    ]));
    let accuracy = &v["accuracy"];
    assert_eq!(accuracy["tolerance"], 0.05);
    assert_eq!(accuracy["status"]["kind"], "reached");
    let resolutions = accuracy["resolutions"].as_array().unwrap();
    assert!(resolutions.len() >= 3);
    assert_eq!(v["resolution_check"]["run"], 2);
    let finest = resolutions.last().unwrap();
    assert_eq!(v["resolution_check"]["resolutions"][2]["elements"], finest["elements"]);
    for o in v["resolution_check"]["outcomes"].as_array().unwrap() {
        let (error, value) = (o["error"].as_f64().unwrap(), o["values"][2].as_f64().unwrap());
        assert!(error <= 0.05 * value.abs(), "{o}");
    }
    let text = String::from_utf8(
        frictrack(&["run", "--elements", "50", "--load-advance", "0.8", "--accuracy", "0.05"]).stdout,
    )
    .unwrap();
    assert!(text.contains("accuracy 5 %: reached at"), "{text}");
}

#[test]
fn a_bad_accuracy_is_refused_by_key() {
    for bad in ["0", "-0.01", "NaN", "1", "1.5", "1%", "inf"] {
        let out = frictrack(&["run", "--accuracy", bad]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains("--accuracy"), "{bad}: {stderr}");
    }
    let out = frictrack(&["run", "--accuracy", "0.01", "--check-resolution"]);
    assert_eq!(out.status.code(), Some(2));
    let out = frictrack(&["run", "--co-moving", "--accuracy", "0.01"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("invalid --accuracy"));
}

#[test]
fn a_sweep_checks_the_run_at_its_peak() {
    let base = ["sweep", "--speeds", "150:250:25", "--elements", "100", "--load-advance", "0.2", "--check-resolution"];
    let out = frictrack(&base);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let line = stdout.lines().find_map(|l| l.strip_prefix("# resolution_check ")).expect("a check line after the CSV");
    let check: serde_json::Value = serde_json::from_str(line).unwrap();
    // The largest max downward deflection of 150–250 m/s is at 200 m/s (v_cr = 205.6 m/s).
    assert_eq!(check["speed"], 200.0);
    assert_eq!(check["point"], "the speed of the largest max downward deflection");
    assert_eq!(check["check"]["outcomes"][0]["name"], "max_downward_deflection");
    assert!(String::from_utf8_lossy(&out.stderr).contains("checking the run at the speed of the largest"));
    // With --critical, the refined critical speed is the point checked, recorded in OUT.json.
    let dir = crate::temporary_folder("sweep-check");
    let csv = dir.join("sweep.csv");
    let out = frictrack(&[&base[..], &["--critical", "--quiet", "--out", csv.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    assert_eq!(meta["resolution_check"]["point"], "the refined critical speed");
    assert_eq!(meta["resolution_check"]["speed"], meta["critical_speed"]["result"]["speed"]);
    let refused = frictrack(&[&base[..], &["--shard", "1/2", "--out", csv.to_str().unwrap()]].concat());
    assert_eq!(refused.status.code(), Some(2));
    std::fs::remove_dir_all(dir).unwrap();
}

/// The HTML report of a refined run shows how close it is, and its folder records the warnings of the scenario as it
/// ran — not the coarse mesh it started from.
#[test]
fn a_refined_run_folder_reports_how_close_it_is() {
    let dir = crate::temporary_folder("accuracy-report");
    let out = dir.join("run");
    let args = ["run", "--elements", "60", "--load-advance", "0.4", "--accuracy", "0.1", "--quiet"];
    let ran = frictrack(&[&args[..], &["--out", out.to_str().unwrap()]].concat());
    assert!(ran.status.success(), "{}", String::from_utf8_lossy(&ran.stderr));
    assert!(String::from_utf8_lossy(&ran.stderr).contains("use at least 81 elements"), "warned of the mesh given");
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(!summary.contains("use at least 81 elements"), "the record warns of the mesh that ran");
    assert!(frictrack(&["report", out.to_str().unwrap()]).status.success());
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("How close it is") && html.contains("Asked for 10 %: reached"), "no check section");
    assert!(html.contains("<code>window_max_downward_deflection</code>") && html.contains("(the run)"));
    std::fs::remove_dir_all(dir).unwrap();
}
