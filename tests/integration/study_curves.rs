//! Snapshots of the response curves of every study at coarse resolution (insta). Values are rounded to four
//! significant digits — far coarser than the solver tolerance (1e-6) and the spread of stick–slip peaks under the
//! load (~1e-4) — so only a change in the physics or the numerics shows as a reviewable diff. Residual deflections,
//! stuck impulses and W̄ or energy of slow, strongly damped runs are ill-determined to a few digits (README: how far
//! to trust the numbers) and move whenever the numerics do: review such diffs against those spreads.
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

/// The CSV as rows of rounded numbers (non-numeric cells kept as text), thinned to about 40 rows. Each number is
/// rounded to four significant digits, and set to 0 below 1e-6 of its column's largest magnitude, so that values
/// that are zero up to round-off (e.g. 1e-11 m against a 0.1 m peak) print as 0 instead of as noise.
fn thinned_table(csv: &str) -> serde_json::Value {
    let mut lines = csv.lines();
    let header = lines.next().unwrap_or_default().to_string();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let columns = rows.first().map_or(0, Vec::len);
    let scale: Vec<f64> = (0..columns)
        .map(|c| rows.iter().filter_map(|r| r.get(c)?.parse::<f64>().ok()).fold(0.0, |m: f64, x| m.max(x.abs())))
        .collect();
    let stride = rows.len().div_ceil(40).max(1);
    let picked: Vec<serde_json::Value> = rows
        .iter()
        .enumerate()
        .filter(|(i, _)| i % stride == 0 || *i + 1 == rows.len())
        .map(|(_, row)| {
            serde_json::Value::Array(
                row.iter()
                    .zip(&scale)
                    .map(|(cell, &scale)| {
                        cell.parse::<f64>().map_or_else(
                            |_| serde_json::json!(cell),
                            |x| {
                                let x = if x.abs() < 1e-6 * scale { 0.0 } else { x };
                                serde_json::json!(round4(x))
                            },
                        )
                    })
                    .collect(),
            )
        })
        .collect();
    serde_json::json!({ "columns": header, "rows_total": rows.len(), "rows": picked })
}

fn snapshot(preset: Preset) {
    let data = run_preset(preset, Resolution::Coarse, &Scenario::default(), &Runner::new(0).unwrap()).unwrap();
    let value = serde_json::json!({
        "headline": data.headline,
        "summary": rounded_json(&data.summary),
        "table": thinned_table(&data.csv),
    });
    insta::assert_yaml_snapshot!(preset.name(), value);
    crate::figures::assert_drawn_inside(&data.plots, preset.name());
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

#[test]
fn hslm() {
    snapshot(Preset::Hslm);
}
