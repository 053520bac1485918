//! Under ballast friction the step's acceleration does not converge (stick and slip starting within a step kick the
//! mesh's highest modes), so a run reports the acceleration filtered to 1 kHz by default (docs/theory.md §10.4),
//! which does.

use crate::{frictrack, json, temporary_folder, write_file};

#[test]
fn ballast_friction_filters_the_acceleration_to_1_khz_by_default_and_it_converges() {
    let dir = temporary_folder("friction-acceleration");
    let text = "[mesh]\nlength = 40\n[friction.distributed]\nforce_per_length = 5000\nsubdivisions = 1\n";
    let path = write_file(&dir, "friction.toml", text);
    let filtered: Vec<f64> = [(160, 0.025), (320, 0.0125), (640, 0.00625), (1280, 0.003125)]
        .iter()
        .map(|(elements, advance)| {
            let (elements, advance) = (elements.to_string(), advance.to_string());
            let args = ["run", &path, "--elements", &elements, "--load-advance", &advance, "--format", "json"];
            let v = json(&frictrack(&args));
            assert_eq!(v["filtered_acceleration"]["band_asked"], 1000.0, "{}", v["filtered_acceleration"]);
            v["filtered_acceleration"]["value"].as_f64().unwrap()
        })
        .collect();
    // Measured 1710.3, 1693.4, 1682.4, 1681.4 m/s²: differences 17, 11, 1 shrinking; the last within 0.1 %.
    let d: Vec<f64> = filtered.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    assert!(d[1] < d[0] && d[2] < d[1], "{filtered:?}");
    assert!(d[2] < 1e-3 * filtered[3], "{filtered:?}");
    // Without friction a Euler–Bernoulli rail keeps the step's acceleration alone (it converges there).
    let v = json(&frictrack(&["run", "--elements", "100", "--format", "json"]));
    assert!(v["filtered_acceleration"].is_null(), "{}", v["filtered_acceleration"]);
}
