//! Refusals come before the work (issue 71): a record beside several speeds is refused before any speed is computed
//! (it came after every one), a sweep of a speed-profile scenario is refused once before any run (each of its runs
//! failed alone), a bad key of the two-beam track on a ground is refused before the ground is fitted (after 14 s).

use super::{frictrack, temporary_folder, write_file};
use std::time::{Duration, Instant};

fn ledsgard(name: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/ledsgard").join(name);
    path.to_str().unwrap().to_string()
}

/// Exit code 2 naming `key`; the work's estimate (printed before long work starts) never printed.
fn refused_before_the_work(args: &[&str], key: &str) {
    let out = frictrack(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(stderr.contains(key), "{args:?}: {stderr}");
    assert!(!stderr.contains("estimated"), "{args:?}: the work was announced before the refusal: {stderr}");
}

#[test]
fn a_record_beside_several_speeds_is_refused_before_them() {
    let folder = temporary_folder("validate-first-record");
    let record = write_file(&folder, "record.csv", "x_m,displacement_mm\n0,-1\n1,-2\n");
    let site = ledsgard("ledsgard.toml");
    refused_before_the_work(&["stationary", &site, "--speeds", "10:80:1", "--measured", &record], "give one speed");
}

#[test]
fn a_sweep_of_a_speed_profile_is_refused_once() {
    let folder = temporary_folder("validate-first-profile");
    let profile = write_file(&folder, "profile.toml", "[load]\nspeed_profile = [[0.0, 120.0], [200.0, 150.0]]\n");
    let out = folder.join("sweep.csv");
    refused_before_the_work(
        &["sweep", &profile, "--speeds", "100:300:1", "--out", out.to_str().unwrap()],
        "speed_profile",
    );
}

/// The ground's fit takes seconds on the Ledsgård site (~3 s in release, 14 s were measured on a loaded machine): a
/// key it does not need is refused well within one.
#[test]
fn the_two_beam_tracks_keys_are_refused_before_the_fit() {
    let folder = temporary_folder("validate-first-two-beam");
    let text = std::fs::read_to_string(ledsgard("ledsgard-two-beam.toml")).unwrap();
    let bad = write_file(&folder, "bad.toml", &format!("{text}\n[output]\nsections = [1e9]\n"));
    let train = ledsgard("x2000.csv");
    let bad_text = std::fs::read_to_string(&bad).unwrap().replace("x2000.csv", &train.replace('\\', "/"));
    let bad = write_file(&folder, "bad.toml", &bad_text);
    let started = Instant::now();
    refused_before_the_work(&["run", &bad], "output.sections = 1000000000");
    assert!(started.elapsed() < Duration::from_secs(1), "refused after {:?}", started.elapsed());
}
