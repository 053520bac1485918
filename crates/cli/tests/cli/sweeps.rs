//! Sweeps from the command line: independent of the thread count, sharded and merged exactly, resumed after an
//! interruption to the same result.

use super::{frictrack, temporary_folder, write_file};
use std::process::Command;

fn sweep_args<'a>(scenario: &'a str, speeds: &'a str, out: &'a str, jobs: &'a str) -> Vec<&'a str> {
    vec!["sweep", scenario, "--speeds", speeds, "--out", out, "--jobs", jobs, "--quiet"]
}

fn small_case(dir: &std::path::Path) -> String {
    write_file(dir, "case.toml", "[mesh]\nlength = 60.0\nelements = 60\n[friction.devices]\ncount = 7\nforce = 20e3\n")
}

/// Results do not depend on the thread count, and three shards merged are the unsharded file byte for byte.
#[test]
fn sweep_is_thread_independent_and_shards_merge_exactly() {
    let dir = temporary_folder("shards");
    let case = small_case(&dir);
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let speeds = "100:290:10";
    for jobs in ["1", "2"] {
        let out = frictrack(&sweep_args(&case, speeds, &path(&format!("jobs{jobs}.csv")), jobs));
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let whole = std::fs::read(path("jobs1.csv")).unwrap();
    assert_eq!(whole, std::fs::read(path("jobs2.csv")).unwrap(), "1 thread vs 2 threads");
    assert_eq!(whole.iter().filter(|&&b| b == b'\n').count(), 21);
    for k in 1..=3 {
        let shard = format!("{k}/3");
        let part = path(&format!("part{k}.csv"));
        let mut args = sweep_args(&case, speeds, &part, "1");
        args.extend(["--shard", &shard]);
        let out = frictrack(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    // Shards in any order.
    let out =
        frictrack(&["merge", "--out", &path("merged.csv"), &path("part2.csv"), &path("part3.csv"), &path("part1.csv")]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read(path("merged.csv")).unwrap(), whole, "3 shards merged = one run");
    // A missing shard, or a shard of another sweep, is refused and writes nothing.
    let out = frictrack(&["merge", "--out", &path("bad.csv"), &path("part1.csv"), &path("part3.csv")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("exactly once"));
    let other = frictrack(&[
        "sweep",
        &case,
        "--speeds",
        "100:290:5",
        "--out",
        &path("other2.csv"),
        "--shard",
        "2/3",
        "--quiet",
    ]);
    assert!(other.status.success());
    let out =
        frictrack(&["merge", "--out", &path("bad.csv"), &path("part1.csv"), &path("other2.csv"), &path("part3.csv")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("different sweeps"));
    assert!(!dir.join("bad.csv").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Interrupt a sweep (SIGINT, then a hard SIGKILL) while it runs: it leaves no CSV but a journal of finished
/// points, and `--resume` finishes it to the same bytes as an uninterrupted run.
#[test]
fn interrupted_sweep_resumes_to_the_same_result() {
    let dir = temporary_folder("resume");
    // The reference beam (runs of ~40 ms), so that the sweep is still running when the signal arrives.
    let case = dir.join("case.toml").to_str().unwrap().to_string();
    std::fs::write(&case, "[friction.devices]\ncount = 7\nforce = 20e3\n").unwrap();
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let speeds = "60:295:5";
    let out = frictrack(&sweep_args(&case, speeds, &path("whole.csv"), "2"));
    assert!(out.status.success());
    let whole = std::fs::read(path("whole.csv")).unwrap();

    for signal in ["-INT", "-KILL"] {
        let target = path(&format!("cut{signal}.csv"));
        let journal = format!("{target}.journal");
        let mut child = Command::new(env!("CARGO_BIN_EXE_frictrack"))
            .args(sweep_args(&case, speeds, &target, "1"))
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        // Wait for a few finished points, then interrupt.
        let started = std::time::Instant::now();
        while std::fs::read_to_string(&journal).map_or(0, |t| t.lines().count()) < 4 {
            assert!(started.elapsed().as_secs() < 120, "no progress");
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        Command::new("kill").args([signal, &child.id().to_string()]).status().unwrap();
        let status = child.wait().unwrap();
        assert!(!status.success());
        if signal == "-INT" {
            assert_eq!(status.code(), Some(130));
            let mut err = String::new();
            std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
            assert!(err.contains("--resume"), "{err}");
        }
        assert!(!std::path::Path::new(&target).exists(), "no half-written CSV");
        let finished = std::fs::read_to_string(&journal).unwrap().lines().count() - 1;
        assert!((3..48).contains(&finished), "{finished} points journaled");
        // Without --resume the journal is protected.
        let out = frictrack(&sweep_args(&case, speeds, &target, "2"));
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("--resume"));
        let mut resume = sweep_args(&case, speeds, &target, "2");
        resume.retain(|a| *a != "--quiet");
        resume.push("--resume");
        let out = frictrack(&resume);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert!(String::from_utf8_lossy(&out.stderr).contains(&format!("resuming: {finished} finished runs")));
        assert_eq!(std::fs::read(&target).unwrap(), whole, "resumed after {signal}");
        assert!(!std::path::Path::new(&journal).exists(), "journal removed once the CSV is written");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
