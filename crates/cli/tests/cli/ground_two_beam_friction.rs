//! `frictrack stationary` on the two-beam track with ballast friction between the sleepers and the embankment
//! (`[friction.distributed]` with an `[embankment]`, docs/theory.md §19): one load at Ledsgård's 185 km/h.

use super::ground_lift_off::two_beam;
use super::{frictrack, json, temporary_folder};

/// The Ledsgård two-beam site with one 90 kN force in place of the X2000 (a shorter window: a test's time), `extra`
/// lines after `[embankment]`'s, and f_u = `friction` N/m (0: none).
fn one_load(folder: &std::path::Path, embankment: &str, friction: f64) -> String {
    let site = two_beam(folder, embankment, "");
    let text = std::fs::read_to_string(&site).unwrap();
    let text = text.replacen("train = \"x2000.csv\"", "force = 90000.0", 1);
    let text = match friction > 0.0 {
        true => format!("{text}\n[friction.distributed]\nforce_per_length = {friction}\n"),
        false => text,
    };
    std::fs::write(&site, text).unwrap();
    site
}

/// 2 kN/m between the sleepers and the embankment slips over ~4 m behind the load and takes ~56 W from it, yet moves
/// the rail's deepest point by 1e-4 of itself at most (measured +9e-5: on this soft site the ballast's compression,
/// which the friction acts on, is ~1/30 of the rail's deflection, the rest being the ground's) — against the
/// X2000's 2.7 % on the composite beam, whose friction acts on the whole deflection. The wave converges, in at most
/// 150 Newton steps of at most 40 GMRES steps each.
#[test]
fn friction_between_the_sleepers_and_the_embankment_barely_moves_the_rail() {
    let folder = temporary_folder("ground-two-beam-friction");
    let point = |friction: f64| {
        let site = one_load(&folder, "", friction);
        let v = json(&frictrack(&["stationary", &site, "--speed", "185km/h", "--format", "json"]));
        v["points"][0].clone()
    };
    let (bare, rubbing) = (point(0.0), point(2000.0));
    assert!(bare.get("friction").is_none(), "{bare}");
    let friction = &rubbing["friction"];
    assert_eq!(rubbing["status"], "converged", "{rubbing}");
    let slipping = friction["slipping_length"].as_f64().unwrap();
    let power = friction["friction_power"].as_f64().unwrap();
    assert!((2.0..8.0).contains(&slipping) && (30.0..100.0).contains(&power), "{friction}");
    // The iteration's cost (counts, not time): measured 66 Newton steps and 22 GMRES steps each with the pair's
    // twin across the ballast and κ stages by 2; the rail on k_b/a with stages by 10 took 303 and 127.
    let newton = friction["newton_iterations"].as_u64().unwrap();
    let krylov = friction["krylov_iterations"].as_u64().unwrap();
    assert!(newton > 0 && newton <= 150 && krylov <= 40 * newton, "{friction}");
    let deepest = |p: &serde_json::Value| p["max_downward_deflection"]["value"].as_f64().unwrap();
    let change = deepest(&rubbing) / deepest(&bare) - 1.0;
    assert!(change.abs() <= 1e-4 && change != 0.0, "{change:e}");
    let _ = std::fs::remove_dir_all(&folder);
}

/// Friction and lift-off at one interface are not built together: refused by key, exit code 2.
#[test]
fn friction_with_a_tensionless_ballast_is_refused_by_key() {
    let folder = temporary_folder("ground-two-beam-friction-bad");
    let site = one_load(&folder, "interface = \"tensionless\"", 2000.0);
    for args in [vec!["stationary", &site, "--speed", "185km/h"], vec!["check", &site]] {
        let out = frictrack(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("embankment.interface") && stderr.contains("friction"), "{stderr}");
    }
    // Without lift-off `check` names the friction and where it acts.
    let site = one_load(&folder, "", 2000.0);
    let out = frictrack(&["check", &site]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("ballast friction 2.0 kN/m between the sleepers and the embankment"), "{stdout}");
    let _ = std::fs::remove_dir_all(&folder);
}
