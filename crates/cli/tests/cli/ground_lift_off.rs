//! `frictrack stationary` on the two-beam track whose ballast cannot pull (`[embankment] interface = "tensionless"`,
//! docs/theory.md §19): the X2000 at Ledsgård lifts the sleepers between the locomotive and the first car, the
//! weightless track lifts wherever the ballast would pull, and a wrong interface is refused by key.

use super::{frictrack, json, temporary_folder, write_file};

/// The Ledsgård two-beam scenario with `extra` lines after `[embankment]`'s and `[sleepers]`'s, written beside its
/// train.
pub(super) fn two_beam(folder: &std::path::Path, embankment: &str, sleepers: &str) -> String {
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/ledsgard");
    std::fs::copy(examples.join("x2000.csv"), folder.join("x2000.csv")).unwrap();
    let text = std::fs::read_to_string(examples.join("ledsgard-two-beam.toml")).unwrap();
    let text = text.replacen("[embankment]", &format!("[embankment]\n{embankment}"), 1);
    let text = text.replacen("[sleepers]", &format!("[sleepers]\n{sleepers}"), 1);
    write_file(folder, "site.toml", &text)
}

/// At 185 km/h the rail bends up between the locomotive's rear axle (12.4 m behind the first) and the first car's
/// front axle (16.5 m): the sleepers there leave the ballast by 3.6 µm (its weight's compression is 11.5 µm), over
/// one point of the window — and the rail's deepest point is the bonded track's to 1e-8 (the lift is that local).
/// Without weight the ballast lets go wherever the linear track would pull it: longer stretches, wider gaps.
#[test]
fn the_x2000_lifts_the_sleepers_between_the_locomotive_and_the_car() {
    let folder = temporary_folder("ground-lift-off");
    let point = |embankment: &str, sleepers: &str| {
        let site = two_beam(&folder, embankment, sleepers);
        let v = json(&frictrack(&["stationary", &site, "--speed", "185km/h", "--format", "json"]));
        v["points"][0].clone()
    };
    let bonded = point("", "");
    assert!(bonded.get("lift_off").is_none(), "{bonded}");
    let lifting = point("interface = \"tensionless\"", "");
    let lift = &lifting["lift_off"];
    let gap = lift["largest_gap"]["value"].as_f64().unwrap();
    let at = lift["largest_gap"]["position"].as_f64().unwrap();
    assert!((gap - 3.58e-6).abs() < 0.01e-6 && (-16.5..-12.4).contains(&at), "{lift}");
    assert!((lift["preload"].as_f64().unwrap() + 11.49e-6).abs() < 0.01e-6, "{lift}");
    assert_eq!(lift["lift_off_zones"], 1, "{lift}");
    assert!(lift["lifted_length"].as_f64().unwrap() <= 0.5, "{lift}");
    // The wave's CSV carries the opening and the ballast's push at each point: open where it pushes nothing, the
    // widest opening at the points no wider than the refined one.
    let site = two_beam(&folder, "interface = \"tensionless\"", "");
    let out = frictrack(&["stationary", &site, "--speed", "185km/h", "--format", "csv"]);
    let csv = String::from_utf8(out.stdout).unwrap();
    assert!(csv.starts_with("s,deflection,gap,ballast_force\n"), "{}", &csv[..80.min(csv.len())]);
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let widest = rows.iter().fold(0.0f64, |m, r| m.max(r[2]));
    assert!(widest > 0.0 && widest <= gap, "{widest} at the points, {gap} refined");
    assert!(rows.iter().all(|r| r[3] >= 0.0 && (r[2] == 0.0 || r[3] == 0.0)));
    let deepest = |p: &serde_json::Value| p["max_downward_deflection"]["value"].as_f64().unwrap();
    assert!((deepest(&lifting) - deepest(&bonded)).abs() <= 1e-8 * deepest(&bonded));
    let weightless = point("interface = \"tensionless\"", "self_weight = false");
    let free = &weightless["lift_off"];
    assert_eq!(free["preload"], 0.0, "{free}");
    assert!(free["lifted_length"].as_f64().unwrap() > 10.0, "{free}");
    assert!(free["largest_gap"]["value"].as_f64().unwrap() > gap, "{free}");
    let _ = std::fs::remove_dir_all(&folder);
}

/// An interface the model does not know is refused by key, exit code 2.
#[test]
fn an_unknown_interface_is_refused_by_key() {
    let folder = temporary_folder("ground-lift-off-bad");
    let site = two_beam(&folder, "interface = \"glued\"", "");
    let out = frictrack(&["stationary", &site, "--speed", "185km/h"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("interface") && stderr.contains("tensionless"), "{stderr}");
    let _ = std::fs::remove_dir_all(&folder);
}
