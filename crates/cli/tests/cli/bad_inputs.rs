//! The bad and borderline inputs of issue 15, each with its exit code and the parameter its message names. None
//! panics (exit 101) or aborts (134); crashes, hangs and destroyed files found by a new user are regressions here.

use super::{frictrack, temporary_folder};
use std::path::Path;

/// (arguments, expected exit code, text the message must contain).
const CASES: &[(&[&str], i32, &str)] = &[
    (&["run", "--elements", "1"], 2, "mesh.elements"),
    (&["run", "--elements", "4000000000"], 2, "mesh.elements"),
    (&["run", "--elements", "18446744073709551615"], 2, "mesh.elements"),
    (&["reference", "--elements", "100000"], 2, "mesh.elements"),
    (&["reference", "--modes", "1000"], 2, "--modes"),
    (&["run", "--speed", "-5"], 2, "load.speed"),
    (&["run", "--devices", "3", "--device-force", "-10"], 2, "friction.devices.force"),
    (&["run", "--damping-ratio", "-0.1"], 2, "foundation.damping_ratio"),
    (&["run", "--devices", "15"], 2, "friction.devices.force"),
    (&["sweep", "--speed", "100"], 2, "--speed"),
    (&["sweep", "--speeds", "100:110:10", "--critical"], 2, "--speeds"),
    (&["run", "--extremes-window", "150:50"], 2, "output.extremes_window"),
    (&["analytic", "--speed", "-3"], 2, "speed"),
    (&["stationary", "--speed", "100", "--domain", "-5:10"], 2, "domain.behind"),
    (&["stationary", "--speed", "100", "--domain", "1e9:1e9"], 2, "more than 2000000"),
    (
        &["run", "--co-moving", "--speed", "100", "--damping-ratio", "0.05", "--devices", "7", "--device-force", "1e3"],
        2,
        "friction.devices",
    ),
    (&["run", "--co-moving", "--speed", "100", "--damping-ratio", "0.05", "--load-advance", "0.3"], 2, "load_advance"),
    // A tolerance at round-off: the interior point stalls (and stops long before its 20 000 iterations), its
    // fallbacks cannot meet it either, and the run stops naming all three.
    (&["run", "--distributed-friction", "5000", "--tolerance", "1e-15"], 1, "stalled before the iteration limit"),
    (&["run", "--distributed-friction", "5000", "--tolerance", "1e-15"], 1, "fallbacks clarabel and projection failed"),
    (&["run", "--distributed-friction", "5000", "--tolerance", "1e-15"], 1, "hint: every solver stalled"),
];

/// Scenario files: (TOML, expected exit code, text the message must contain).
const FILES: &[(&str, i32, &str)] = &[
    ("[mesh]\nelements = 18446744073709551615\n", 2, "mesh.elements"),
    ("[friction.distributed]\nforce_per_length = 1e3\nsubdivisions = 100000\n", 2, "subdivisions"),
    ("[integration]\nend_time = 1e9\n", 2, "integration.end_time"),
    ("[integration]\nmax_iterations = 0\n", 2, "invalid integration.max_iterations = 0: must be ≥ 1"),
    ("[foundation]\nstiffness = 0.0\n[supports]\nleft = \"free\"\nright = \"free\"\n", 2, "supports"),
    ("[foundation]\nstiffness = 0.0\n[supports]\nright = \"free\"\n", 2, "supports"),
    ("[friction.devices]\ncount = 15\n", 2, "friction.devices.force"),
    // Nonlinear soils: a tension stiffness above the compression stiffness, a bilinear soil without its ratio, a
    // ratio on another law, a nonlinear soil's key on a linear one, an unknown law, a steady start (linear only).
    ("[foundation]\nlaw = \"bilinear\"\ntension_ratio = 1.5\n", 2, "foundation.tension_ratio"),
    ("[foundation]\nlaw = \"bilinear\"\n", 2, "foundation.tension_ratio"),
    ("[foundation]\nlaw = \"tensionless\"\ntension_ratio = 0.5\n", 2, "foundation.tension_ratio"),
    ("[foundation]\nself_weight = false\n", 2, "foundation.self_weight"),
    ("[foundation]\nlaw = \"sticky\"\n", 2, "foundation.law"),
    ("[foundation]\nlaw = \"tensionless\"\n[integration]\nsteady_start = 60.0\n", 2, "linear foundation"),
    // A co-moving window: zones that leave no room, a load outside the window, a track of too many steps.
    ("[foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 100.0\n[co_moving]\nzones = -1.0\n", 2, "co_moving.zones"),
    ("[foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 100.0\n[co_moving]\nload_at = 5.0\n", 2, "co_moving.load_at"),
    (
        "[foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 100.0\n[co_moving]\ntrack_length = 1e12\n",
        2,
        "co_moving.track_length",
    ),
    // 2·10⁶ steps × 30 recorded sections: more history samples than the stated limit, refused before allocating.
    (
        "[integration]\nload_advance = 1e-4\n[output]\nsections = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, \
         11.0, 12.0, 13.0, 14.0, 15.0, 16.0, 17.0, 18.0, 19.0, 20.0, 21.0, 22.0, 23.0, 24.0, 25.0, 26.0, 27.0, 28.0, \
         29.0, 30.0]\n",
        2,
        "output.sections",
    ),
];

fn check(args: &[&str], code: i32, needle: &str) {
    let out = frictrack(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: expected `{needle}` in: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
}

#[test]
fn bad_inputs_exit_with_a_message_naming_the_parameter() {
    for (args, code, needle) in CASES {
        check(args, *code, needle);
    }
    let dir = temporary_folder("bad-files");
    for (i, (toml, code, needle)) in FILES.iter().enumerate() {
        let path = dir.join(format!("case{i}.toml"));
        std::fs::write(&path, toml).unwrap();
        check(&["run", path.to_str().unwrap()], *code, needle);
    }
}

#[test]
fn suspicious_inputs_run_with_a_warning_naming_the_value_and_limit() {
    let out = frictrack(&["run", "--elements", "3", "--speed", "100"]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("warning: mesh.elements = 3") && err.contains("π/β = 10.000 m"), "{err}");
    let dir = temporary_folder("merged");
    let path = dir.join("merged.toml");
    std::fs::write(&path, "[friction.devices]\npositions = [50.0, 50.2, 50.3]\nforce = 1e4\n").unwrap();
    let out = frictrack(&["run", path.to_str().unwrap(), "--speed", "100"]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("warning: friction.devices = 3 devices") && err.contains("only 1 distinct"), "{err}");
}

/// Whatever `--out` names, a target that is not a regular file is refused before any run (exit 2), and left as it
/// was; an unusable folder gives the same exit code from sweep, study and reproduce.
#[test]
fn output_targets_that_are_not_regular_files_are_refused_and_kept() {
    let dir = temporary_folder("targets");
    let target = dir.join("kept.csv");
    std::fs::write(&target, "precious").unwrap();
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let fifo = dir.join("fifo.csv");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    for bad in [link.as_path(), fifo.as_path(), Path::new("/dev/null"), dir.as_path()] {
        check(&["sweep", "--speeds", "100:120:10", "--out", bad.to_str().unwrap()], 2, "--out");
    }
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "precious");
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    // A figure's name taken by a link in a study's output folder: refused before the first run, link and target kept.
    let study_dir = dir.join("study");
    std::fs::create_dir_all(&study_dir).unwrap();
    std::os::unix::fs::symlink(&target, study_dir.join("optimal-force.png")).unwrap();
    check(&["study", "optimal-force", "--out", study_dir.to_str().unwrap(), "--quiet"], 2, "symbolic link");
    assert!(!study_dir.join("optimal-force.csv").exists(), "refused before any run");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "precious");
    // The same for run --out: a link where histories.csv goes is refused before the run.
    let run_dir = dir.join("run");
    std::fs::create_dir_all(&run_dir).unwrap();
    std::os::unix::fs::symlink(&target, run_dir.join("histories.csv")).unwrap();
    check(&["run", "--out", run_dir.to_str().unwrap()], 2, "symbolic link");
    assert!(!run_dir.join("summary.json").exists());
    let unusable = dir.join("kept.csv/inside");
    let unusable = unusable.to_str().unwrap();
    check(&["sweep", "--speeds", "100:120:10", "--out", &format!("{unusable}/x.csv")], 2, "--out");
    check(&["study", "amplification", "--out", unusable], 2, "--out");
    check(&["reproduce", "--out", unusable], 2, "--out");
}

/// `frictrack check examples/*.toml` (the README's command) checks every file; one bad file among good ones is
/// reported by name and makes the command exit 2.
#[test]
fn check_takes_several_files() {
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut files: Vec<String> = std::fs::read_dir(&examples)
        .unwrap()
        .map(|e| e.unwrap().path().to_string_lossy().into_owned())
        .filter(|p| p.ends_with(".toml"))
        .collect();
    files.sort();
    let args: Vec<&str> = std::iter::once("check").chain(files.iter().map(String::as_str)).collect();
    let out = frictrack(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout).lines().filter(|l| l.contains(": ok")).count(), files.len());
    let dir = temporary_folder("check-several");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[integration]\nsolver = \"interor-point\"\n").unwrap();
    check(&["check", &files[0], bad.to_str().unwrap()], 2, "did you mean `interior-point`?");
    check(&["check", &files[0], bad.to_str().unwrap()], 2, "scenario files = 1 of 2");
}

/// Ballast friction on the rail and a tensionless soil beside sleepers stopped with exit 1 under the default solver
/// ("solver interior-point cannot solve this problem", a solver the user never chose): the interior point now takes
/// their rows, so `auto` runs them (and says it used the interior point); the homotopy, which does not, is refused by
/// key before the run.
#[test]
fn rail_sections_on_sleepers_run_under_the_default_solver() {
    let folder = temporary_folder("rail-rows-on-sleepers");
    let track =
        "[mesh]\nlength = 30.0\nelements = 200\n[foundation]\nstiffness = 250e3\n[sleepers]\n[load]\nspeed = 50.0\n";
    for (extra, key, args) in [
        ("", "friction.distributed.force_per_length", vec!["--distributed-friction", "2000"]),
        ("law = \"tensionless\"\n", "foundation.law", vec![]),
    ] {
        let file = folder.join("track.toml");
        std::fs::write(&file, track.replace("stiffness = 250e3\n", &format!("stiffness = 250e3\n{extra}"))).unwrap();
        let path = file.to_str().unwrap();
        let out = frictrack(&[&["run", path, "--load-advance", "0.15", "--format", "json"][..], &args[..]].concat());
        assert!(out.status.success(), "{key}: {}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(json["solver"], "interior-point", "{key}");
        let homotopy = frictrack(&[&["run", path, "--solver", "homotopy"][..], &args[..]].concat());
        let stderr = String::from_utf8_lossy(&homotopy.stderr);
        assert_eq!(homotopy.status.code(), Some(2), "{key}: {stderr}");
        assert!(stderr.contains(key) && stderr.contains("homotopy"), "{stderr}");
    }
}
