//! The `ledsgard` study (docs/theory.md §19): the built-in site's curves with and without ballast friction, the
//! critical speeds, the measured records beside the computed waves, its files' columns and figures.

use runner::Runner;
use scenario::Scenario;
use study::presets::{Preset, Resolution, run_preset};

/// Coarse: four curves (f_u = 0, 1, 2, 5 kN/m) of eleven speeds, 100–280 km/h by 20 and 185 km/h, on each track.
/// Under the composite beam friction lowers the deepest deflection
/// at every speed (its force only resists the track's motion), the more the stronger; the curves at 185 km/h are the
/// command line's (8.78, 8.67, 8.54, 8.10 mm: `cli/tests/cli/ground_friction.rs`) to 1e-6 of the peak (the same
/// solve); the comparisons are `--measured`'s (RMS misfit 0.62 and 2.23 mm); the ground's critical speed for one
/// load is `frictrack ground`'s 56.5 m/s and the Winkler control lies far above it; every CSV column has a unit.
/// Between the sleepers and the embankment of the two-beam track the same friction moves the rail's deepest
/// deflection by 0.2 % at most (measured 0.02–0.10 % down, and 0.04 % up at 280 km/h: the ballast's compression
/// is a small part of the deflection on this soft site), its curves peaking at 12.12 mm at 240 km/h (12.11 with
/// 5 kN/m) and 9.23 mm at 185 km/h (9.22) (docs/theory.md §19).
#[test]
fn ledsgard_with_and_without_ballast_friction() {
    let data =
        run_preset(Preset::Ledsgard, Resolution::Coarse, &Scenario::default(), &Runner::new(0).unwrap()).unwrap();
    assert!(data.columns.iter().all(|(_, unit)| *unit != "unknown"), "{:?}", data.columns);
    let summary = serde_json::to_value(&data.summary).unwrap();
    let curves = summary["curves"].as_array().unwrap();
    let at_185: Vec<f64> = curves.iter().map(|c| 1e3 * c["deflection_at_185_km_per_h"].as_f64().unwrap()).collect();
    for (got, quoted) in at_185.iter().zip([8.78, 8.67, 8.54, 8.10]) {
        assert!((got - quoted).abs() < 0.005, "{at_185:?}");
    }
    let rows: Vec<Vec<f64>> =
        data.csv.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 44);
    assert!(rows.iter().all(|r| r.len() == 8), "{:?}", data.columns);
    for speed in 0..11 {
        let down: Vec<f64> = (0..4).map(|curve| rows[curve * 11 + speed][2]).collect();
        assert!(down.windows(2).all(|w| w[1] < w[0]), "at {} m/s: {down:?}", rows[speed][1]);
        let (bare, strongest) = (rows[speed][5], rows[33 + speed][5]);
        let change = strongest / bare - 1.0;
        assert!(change.abs() <= 2e-3 && change != 0.0, "two-beam at {} m/s: {change:e}", rows[speed][1]);
    }
    let two_beam = summary["two_beam_curves"].as_array().unwrap();
    for (curve, (quoted_peak, quoted_185)) in
        two_beam.iter().zip([(12.12, 9.23), (12.12, 9.23), (12.12, 9.23), (12.11, 9.22)])
    {
        let peak = 1e3 * curve["max_downward_deflection"].as_f64().unwrap();
        let at_185 = 1e3 * curve["deflection_at_185_km_per_h"].as_f64().unwrap();
        assert!((peak - quoted_peak).abs() < 0.005 && (at_185 - quoted_185).abs() < 0.005, "{curve}");
        assert!((curve["speed"].as_f64().unwrap() * 3.6 - 240.0).abs() < 1e-9, "{curve}");
    }
    // The curves' sampled peaks, at 240 km/h: 11.75, 11.32, 10.87 and 9.51 mm (docs/theory.md §19 quotes them).
    for (curve, quoted) in curves.iter().zip([11.75, 11.32, 10.87, 9.51]) {
        let peak = 1e3 * curve["max_downward_deflection"].as_f64().unwrap();
        assert!((peak - quoted).abs() < 0.005, "{curve}");
        assert!((curve["speed"].as_f64().unwrap() * 3.6 - 240.0).abs() < 1e-9, "{curve}");
    }
    let critical = summary["critical_speed"].as_f64().unwrap();
    assert!((critical - 56.5).abs() < 0.05, "{critical}");
    // The Winkler control, 378 km/h (quoted in docs/theory.md §19), far above it.
    let winkler = summary["winkler_critical_speed"].as_f64().unwrap() * 3.6;
    assert!((winkler - 378.0).abs() < 0.5, "{winkler} km/h");
    let misfits: Vec<f64> = summary["measured"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| 1e3 * m["comparison"]["rms_misfit"].as_f64().unwrap())
        .collect();
    assert!((misfits[0] - 0.62).abs() < 0.005 && (misfits[1] - 2.23).abs() < 0.005, "{misfits:?}");
    let stems: Vec<&str> = data.plots.iter().map(|p| p.stem.as_str()).collect();
    assert_eq!(stems, ["ledsgard-speeds", "ledsgard-speeds-two-beam", "ledsgard-70-kmh", "ledsgard-185-kmh"]);
    assert_eq!(data.headline.len(), 3);
    figures_say_what_they_show(&data.plots);
    // Every number of a curve has a unit, found as the HTML report finds it (a suffix of its name a listed quantity):
    // the deflection at 185 km/h was `at_185_km_per_h`, a column without unit.
    for key in curves[0].as_object().unwrap().keys().filter(|k| curves[0][k.as_str()].is_number()) {
        let words: Vec<&str> = key.split('_').collect();
        let unit = (0..words.len()).find_map(|i| scenario::quantities::unit_of(&words[i..].join("_")));
        assert!(unit.is_some(), "{key} has no unit");
    }
}

/// The figures pasted alone: the two-beam track's four curves, within 0.10 % of each other, are drawn as one that
/// says so (three hid under the fourth), with none of the composite beam's critical speeds; the Winkler control at
/// 378 km/h, beyond the speeds computed (280 km/h), is named in the subtitle rather than stretching the axis; the
/// computed wave's legend says it is computed and the record's gives the RMS misfit.
fn figures_say_what_they_show(plots: &[report::plot::PlotSpec]) {
    let labels = |i: usize| -> Vec<String> { plots[i].series.iter().filter_map(|s| s.label.clone()).collect() };
    let two_beam = labels(1);
    assert_eq!(two_beam.len(), 1, "{two_beam:?}");
    assert!(two_beam[0].contains("f_u = 0, 1, 2, 5 kN/m: one curve (within 0.10 % of each other)"), "{two_beam:?}");
    let composite = labels(0);
    assert_eq!(composite.len(), 5, "four curves and the critical speed: {composite:?}");
    assert!(!composite.iter().any(|l| l.contains("Winkler")) && plots[0].subtitle.contains("Winkler control"));
    assert!(plots[0].subtitle.contains("378 km/h (beyond the speeds computed)"), "{}", plots[0].subtitle);
    let wave = labels(3);
    assert!(wave[0].starts_with("computed, v = 51.4 m/s") && wave[1].contains("RMS misfit 2.23 mm"), "{wave:?}");
}
