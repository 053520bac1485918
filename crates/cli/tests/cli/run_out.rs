//! `run --out DIR`: the files hold what the library computes, with their units documented beside them.

use super::{frictrack, json, temporary_folder};

fn read_csv(path: &std::path::Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines.map(|l| l.split(',').map(|c| c.parse::<f64>().unwrap()).collect()).collect();
    (header, rows)
}

#[test]
fn run_out_writes_histories_and_snapshots_that_match_the_library() {
    let dir = temporary_folder("run-out");
    let args = ["run", "--speed", "150", "--devices", "7", "--device-force", "20e3", "--record", "100,25"];
    let out = frictrack(&[&args[..], &["--snapshot-at-load", "200,50", "--out", dir.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));

    // The same run through the library.
    let mut scenario = scenario::Scenario::default();
    scenario.load.speed = 150.0;
    scenario.friction.devices = Some(scenario::DevicesSection { count: Some(7), positions: None, force: Some(20e3) });
    scenario.output.sections = vec![100.0, 25.0];
    let case = scenario.build().unwrap();
    let result = track::Simulation::new(&case.model, &case.interactions, &case.settings).unwrap().run().unwrap();

    let (header, rows) = read_csv(&dir.join("histories.csv"));
    assert_eq!(
        header,
        ["section", "time", "load_position", "deflection", "velocity", "acceleration", "moment", "friction_force"]
    );
    let mid: Vec<&Vec<f64>> = rows.iter().filter(|r| r[0] == 100.0).collect();
    let h = &result.histories[0];
    assert_eq!(mid.len(), h.time.len());
    for (k, r) in mid.iter().enumerate() {
        // Shortest round-trip text: the very bits of the library's values.
        assert_eq!((r[1], r[3], r[6]), (h.time[k], h.deflection[k], h.moment[k]), "step {k}");
        assert_eq!(r[7], h.impulse.as_ref().unwrap()[k] / result.step, "step {k}");
    }
    assert_eq!(rows.len(), 2 * h.time.len());

    // The snapshot with the load at x = L is the final state; snapshots come in time order.
    let (header, rows) = read_csv(&dir.join("snapshots.csv"));
    assert_eq!(header, ["time", "load_position", "x", "deflection", "moment"]);
    let nodes = case.model.mesh().nodes();
    assert_eq!(rows.len(), 2 * nodes);
    // Taken at the first step reaching the load position: within one load advance (0.1 m) after it.
    assert!((50.0 - 1e-9..50.1).contains(&rows[0][1]), "load at {}", rows[0][1]);
    // Its moment at x = 25 m equals the 25 m history's at that step: both are end-force moments of the same state
    // (summed in another order, hence 1e-9 of the largest moment rather than bit equality).
    let h25 = &result.histories[1];
    let k = h25.time.iter().position(|&t| t == rows[0][0]).expect("the snapshot's step");
    let scale = h25.moment.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let snapshot_moment = rows[..nodes].iter().find(|r| r[2] == 25.0).unwrap()[4];
    assert!((snapshot_moment - h25.moment[k]).abs() < 1e-9 * scale, "{snapshot_moment} vs {}", h25.moment[k]);
    let last = &rows[nodes..];
    let final_w = case.model.nodal_deflections(&case.model.dofs().expand(&result.final_displacement)).unwrap();
    for (r, w) in last.iter().zip(&final_w) {
        assert_eq!(r[3], *w);
    }
    assert!((last[0][1] - 200.0).abs() < 1e-9, "load at {}", last[0][1]);
    let summary: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap();
    let units: Vec<(&str, &str)> = summary["files"]["histories.csv"]["columns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| (c["name"].as_str().unwrap(), c["unit"].as_str().unwrap()))
        .collect();
    assert_eq!(units[3], ("deflection", "m"));
    assert_eq!(units[6], ("moment", "N·m"));
    assert_eq!(summary["scenario"]["load"]["speed"], 150.0);
    assert_eq!(summary["report"]["devices"], 7);
    for figure in ["histories-deflection", "histories-moment", "snapshots-deflection", "snapshots-moment"] {
        assert!(super::is_png(&dir.join(format!("{figure}.png"))), "{figure}");
        assert!(super::is_svg(&dir.join(format!("{figure}.svg"))), "{figure}");
    }
}

/// A sweep's CSV and a run's JSON use the same names for the same numbers: every metric a sweep row shares with
/// `run --format json` (the extremes with their node and time, the energy terms, W̄, the iterations, the
/// acceleration) has the run's key, and at the same speed the same value to the bit.
#[test]
fn a_sweep_row_and_a_run_name_the_same_numbers_alike() {
    let run =
        json(&frictrack(&["run", "--speed", "150", "--devices", "7", "--device-force", "50000", "--format", "json"]));
    let sweep = frictrack(&["sweep", "--speeds", "150:150:10", "--devices", "7", "--device-force", "50000", "--quiet"]);
    assert!(sweep.status.success(), "{}", String::from_utf8_lossy(&sweep.stderr));
    let text = String::from_utf8_lossy(&sweep.stdout);
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    // The sweep's flat columns and where the run's JSON holds each (an extreme's value, place and time; the energy
    // balance's terms).
    let shared = [
        ("max_downward_deflection", "/max_downward_deflection/value"),
        ("max_downward_deflection_position", "/max_downward_deflection/position"),
        ("max_downward_deflection_time", "/max_downward_deflection/time"),
        ("max_upward_deflection", "/max_upward_deflection/value"),
        ("window_max_downward_deflection_time", "/window_max_downward_deflection/time"),
        ("dissipated_energy", "/energy/dissipated"),
        ("global_norm", "/global_norm"),
        ("load_work", "/energy/load_work"),
        ("energy_residual", "/energy/residual"),
        ("mean_iterations", "/mean_iterations"),
        ("max_acceleration", "/max_acceleration/value"),
    ];
    for (name, key) in shared {
        let column = header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no sweep column {name}"));
        let in_sweep: f64 = row[column].parse().unwrap();
        let in_run = run.pointer(key).and_then(|x| x.as_f64()).unwrap_or_else(|| panic!("no run key {key}: {run}"));
        assert_eq!(in_sweep.to_bits(), in_run.to_bits(), "{name}: sweep {in_sweep}, run {in_run}");
    }
}
