//! Runs on a tensionless soil from a scenario file: the soil's report in JSON and text, and none on a linear soil.

use super::{frictrack, json, temporary_folder};

#[test]
fn a_tensionless_soil_reports_where_the_rail_lifted_off() {
    let folder = temporary_folder("soil");
    let file = folder.join("tensionless.toml");
    std::fs::write(
        &file,
        "[foundation]\ndamping_ratio = 0.05\nlaw = \"tensionless\"\n[load]\nspeed = 100.0\n\
         [integration]\nstatic_start = 50.0\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    let v = json(&frictrack(&["run", path, "--format", "json"]));
    let soil = &v["soil"];
    assert_eq!(soil["law"], "tensionless");
    assert_eq!(soil["sections"], 800);
    // ρA·g/k_c = 7800 kg/m³ · 7.684e-3 m² · 9.81 m/s² / 250 kN/m² = 2.352 mm (JSON keeps 17 digits).
    let settlement = soil["settlement"].as_f64().unwrap();
    assert!((settlement - 7800.0 * 7.684e-3 * 9.81 / 250e3).abs() <= 1e-15, "{settlement}");
    // At 100 m/s the wave ahead of the load rises above the settlement: the rail leaves the soil, by less than it
    // rises above its settled state.
    let gap = soil["largest_gap"].as_f64().unwrap();
    let rise = v["max_upward_deflection"].as_f64().unwrap();
    assert!(gap > 0.0 && gap <= rise, "gap {gap} rise {rise}");
    let zones = soil["lift_off_zones"].as_array().unwrap();
    assert!(!zones.is_empty());
    let x = soil["largest_gap_position"].as_f64().unwrap();
    assert!(zones.iter().any(|z| z["from"].as_f64().unwrap() <= x && x <= z["to"].as_f64().unwrap()));
    // The energy identity holds with the soil's work.
    let residual = v["energy_residual"].as_f64().unwrap();
    assert!(residual.abs() <= 1e-9 * v["load_work"].as_f64().unwrap(), "{residual}");
    let text = frictrack(&["run", path]);
    let out = String::from_utf8_lossy(&text.stdout);
    assert!(out.contains("soil: tensionless") && out.contains("the rail lifted off the soil"), "{out}");
    assert!(out.contains("800 sections (0 friction, 800 soil)"), "{out}");
    // A linear soil has no soil report.
    let linear = json(&frictrack(&["run", "--format", "json"]));
    assert!(linear.get("soil").is_none());
}
