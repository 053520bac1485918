//! Snapshots of the response curves of every study at coarse resolution (insta). Values are rounded to four
//! significant digits — far coarser than the solver tolerance (1e-10) and the run-to-run spread of stick–slip
//! trajectories (~3e-6) — so only a change in the physics or the numerics shows as a reviewable diff.
//! Long tables are thinned to about 40 rows, keeping the first and last.

use study::Scenario;
use study::presets::{Preset, Resolution, run_preset};
use study::sweep::Runner;

/// `value` rounded to four significant digits.
fn round4(value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    let scale = 10f64.powi(3 - value.abs().log10().floor() as i32);
    (value * scale).round() / scale
}

fn rounded_json(value: &serde_json::Value) -> serde_json::Value {
    match value {
        serde_json::Value::Number(n) => serde_json::json!(round4(n.as_f64().unwrap_or(f64::NAN))),
        serde_json::Value::Array(a) => serde_json::Value::Array(a.iter().map(rounded_json).collect()),
        serde_json::Value::Object(o) => o.iter().map(|(k, v)| (k.clone(), rounded_json(v))).collect(),
        other => other.clone(),
    }
}

/// The CSV as rows of rounded numbers (non-numeric cells kept as text), thinned to about 40 rows.
fn thinned_table(csv: &str) -> serde_json::Value {
    let mut lines = csv.lines();
    let header = lines.next().unwrap_or_default().to_string();
    let rows: Vec<&str> = lines.collect();
    let stride = rows.len().div_ceil(40).max(1);
    let picked: Vec<serde_json::Value> = rows
        .iter()
        .enumerate()
        .filter(|(i, _)| i % stride == 0 || *i + 1 == rows.len())
        .map(|(_, row)| {
            serde_json::Value::Array(
                row.split(',')
                    .map(|cell| {
                        cell.parse::<f64>().map_or_else(|_| serde_json::json!(cell), |x| serde_json::json!(round4(x)))
                    })
                    .collect(),
            )
        })
        .collect();
    serde_json::json!({ "columns": header, "rows_total": rows.len(), "rows": picked })
}

fn snapshot(preset: Preset) {
    let data = run_preset(preset, Resolution::Coarse, &Scenario::default(), &Runner::new(0)).unwrap();
    let value = serde_json::json!({
        "headline": data.headline,
        "summary": rounded_json(&data.summary),
        "table": thinned_table(&data.csv),
    });
    insta::assert_yaml_snapshot!(preset.name(), value);
}

#[test]
fn discrete_speed() {
    snapshot(Preset::DiscreteSpeed);
}

#[test]
fn equal_cost() {
    snapshot(Preset::EqualCost);
}

#[test]
fn optimal_force() {
    snapshot(Preset::OptimalForce);
}

#[test]
fn distributed_speed() {
    snapshot(Preset::DistributedSpeed);
}

#[test]
fn amplification() {
    snapshot(Preset::Amplification);
}

#[test]
fn discrete_vs_distributed() {
    snapshot(Preset::DiscreteVsDistributed);
}
