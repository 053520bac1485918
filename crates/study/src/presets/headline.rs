//! The two sentences on what each study shows, for `reproduce`'s report, from its summary.

use super::Preset;
use super::hslm::{KMH, millimetres};
use serde_json::Value;

fn number(v: &Value, key: &str) -> f64 {
    v.get(key).and_then(Value::as_f64).unwrap_or(f64::NAN)
}

/// A train name in upper case as the standard writes it (`hslm-a4` → `HSLM-A4`).
fn name(v: &Value, key: &str) -> String {
    v.get(key).and_then(Value::as_str).unwrap_or("?").to_uppercase()
}

/// Two sentences on what a study shows, from its summary.
pub(super) fn headline(preset: Preset, summary: &Value) -> Vec<String> {
    let empty = Vec::new();
    let items = summary.get("curves").or_else(|| summary.get("optima")).and_then(Value::as_array).unwrap_or(&empty);
    let find = |pred: &dyn Fn(&Value) -> bool| items.iter().find(|v| pred(v)).cloned().unwrap_or(Value::Null);
    let curve_text = |v: &Value| {
        let (speed, peak) = (number(v, "critical_speed"), 1e3 * number(v, "peak_max_downward_deflection"));
        if speed.is_nan() {
            return "unknown (runs of that curve failed: see the study's failures)".to_string();
        }
        match v.get("critical_speed_location").and_then(Value::as_str) {
            Some("upper-end") => format!("at or above {speed:.1} m/s, the top of the range (peak there {peak:.0} mm)"),
            Some("lower-end") => {
                format!("at or below {speed:.1} m/s, the bottom of the range (peak there {peak:.0} mm)")
            }
            _ => format!("{speed:.1} m/s with a peak of {peak:.0} mm"),
        }
    };
    match preset {
        Preset::DiscreteSpeed => {
            let none = find(&|v| number(v, "devices") == 0.0);
            let best = items
                .iter()
                .min_by(|a, b| {
                    number(a, "peak_max_downward_deflection").total_cmp(&number(b, "peak_max_downward_deflection"))
                })
                .cloned()
                .unwrap_or(Value::Null);
            let cut =
                1.0 - number(&best, "peak_max_downward_deflection") / number(&none, "peak_max_downward_deflection");
            vec![
                format!("Without friction the track's critical speed is {}.", curve_text(&none)),
                format!(
                    "The best set, {} devices of {:.0} kN, cuts that peak by {:.0} % (critical speed {}).",
                    number(&best, "devices"),
                    number(&best, "device_force") / 1e3,
                    100.0 * cut,
                    curve_text(&best)
                ),
            ]
        }
        Preset::EqualCost => {
            let mut text = Vec::new();
            for cost in [3100e3, 1550e3, 310e3] {
                let group: Vec<&Value> = items.iter().filter(|v| number(v, "cost") == cost).collect();
                let best = group.iter().min_by(|a, b| {
                    number(a, "peak_max_downward_deflection").total_cmp(&number(b, "peak_max_downward_deflection"))
                });
                if let Some(b) = best {
                    text.push(format!(
                        "{:.0} kN: {} × {:.0} kN (peak {:.0} mm)",
                        cost / 1e3,
                        number(b, "devices"),
                        number(b, "device_force") / 1e3,
                        1e3 * number(b, "peak_max_downward_deflection")
                    ));
                }
            }
            vec![
                "For a given total friction capacity N·F_u, the lowest resonance peak comes from:".into(),
                format!("{}.", text.join("; ")),
            ]
        }
        Preset::OptimalForce => {
            let text: Vec<String> = items
                .iter()
                .map(|v| {
                    format!(
                        "N = {}: {:.0} kN ({:.0} mm)",
                        number(v, "devices"),
                        number(v, "optimal_device_force") / 1e3,
                        1e3 * number(v, "max_downward_deflection")
                    )
                })
                .collect();
            vec![
                format!(
                    "At {} m/s the max downward deflection is smallest for an intermediate device force:",
                    number(summary, "speed")
                ),
                format!("{}.", text.join("; ")),
            ]
        }
        Preset::DistributedSpeed => {
            let none = find(&|v| number(v, "force_per_length") == 0.0);
            let strong = find(&|v| number(v, "force_per_length") == 10e3);
            vec![
                format!("Without ballast friction the critical speed is {}.", curve_text(&none)),
                format!("With f_u = 10 kN/m it is {}.", curve_text(&strong)),
            ]
        }
        Preset::Amplification => {
            let top = items.iter().map(|v| number(v, "speed")).fold(0.0, f64::max);
            let at = |f: f64| find(&|v| number(v, "force_per_length") == f && number(v, "speed") == top);
            vec![
                "Mid-span amplification grows with speed towards the critical speed.".into(),
                format!(
                    "At {top} m/s: max φ_w {:.2} and φ_M {:.2} with f_u = 1 kN/m, {:.2} and {:.2} with 2 kN/m.",
                    number(&at(1e3), "max_phi_w"),
                    number(&at(1e3), "max_phi_m"),
                    number(&at(2e3), "max_phi_w"),
                    number(&at(2e3), "max_phi_m")
                ),
            ]
        }
        Preset::Hslm => {
            let envelopes = summary.get("envelopes").and_then(Value::as_array).unwrap_or(&empty);
            // On a span the beam is the deck and EN 1990 limits its acceleration; on a track it is the rail.
            let limit = summary.get("acceleration_limit").and_then(Value::as_f64);
            let text = |v: &Value| {
                let (speed, peak) = (number(v, "critical_speed"), number(v, "peak_max_downward_deflection"));
                let at = match v.get("critical_speed_location").and_then(Value::as_str) {
                    Some("upper-end") => "at or above",
                    Some("lower-end") => "at or below",
                    _ => "at",
                };
                let acceleration = number(v, "peak_max_acceleration");
                let acceleration = match limit {
                    Some(l) => format!(
                        "deck acceleration, {acceleration:.2} m/s² ({:.2} × the EN 1990 limit of {l} m/s²)",
                        acceleration / l
                    ),
                    None => format!("rail acceleration, {acceleration:.0} m/s²"),
                };
                format!(
                    "{} {at} {:.0} km/h ({speed:.1} m/s): max downward deflection {}, dynamic amplification {:.2}; \
                     the largest {acceleration}, comes from {} at {:.0} km/h",
                    name(v, "critical_train"),
                    KMH * speed,
                    millimetres(peak),
                    number(v, "dynamic_amplification"),
                    name(v, "acceleration_train"),
                    KMH * number(v, "acceleration_speed")
                )
            };
            let (none, with) = (envelopes.first().unwrap_or(&Value::Null), envelopes.get(1).unwrap_or(&Value::Null));
            let cut = 1.0 - number(with, "peak_max_downward_deflection") / number(none, "peak_max_downward_deflection");
            vec![
                format!("Without friction the critical train is {}.", text(none)),
                format!(
                    "With {} the peak deflection is {:.0} % {}: {}.",
                    summary.get("friction_setup").and_then(Value::as_str).unwrap_or("friction"),
                    100.0 * cut.abs(),
                    if cut >= 0.0 { "lower" } else { "higher" },
                    text(with)
                ),
            ]
        }
        Preset::VehicleSpeed => {
            let pick = |model: &str, friction: &str, rail: &str| {
                find(&|v: &Value| v["model"] == model && v["friction"] == friction && v["rail"] == rail)
            };
            let (force, mass, car) = (
                pick("moving-force", "none", "smooth"),
                pick("moving-mass", "none", "smooth"),
                pick("quarter-car", "none", "smooth"),
            );
            let peak = |v: &Value| {
                format!(
                    "{:.1} mm at {:.0} m/s",
                    1e3 * number(v, "peak_max_downward_deflection"),
                    number(v, "peak_speed")
                )
            };
            let rough = pick("quarter-car", "none", "irregular");
            let lift = |v: &Value| match v.get("first_loss_of_contact_speed").and_then(Value::as_f64) {
                Some(speed) => format!("leaves the rail from {speed:.0} m/s on"),
                None => format!("keeps at least {:.1} kN on the rail", number(v, "min_wheel_force") / 1e3),
            };
            vec![
                format!(
                    "On the smooth rail without friction the peak rail deflection is {} under the moving force, {} \
                     under the moving mass and {} under the quarter car.",
                    peak(&force),
                    peak(&mass),
                    peak(&car)
                ),
                format!(
                    "On the irregular rail the quarter car's wheel {}, its body reaching {:.2} m/s².",
                    lift(&rough),
                    number(&rough, "max_body_acceleration")
                ),
            ]
        }
        Preset::DiscreteVsDistributed => vec![
            format!(
                "With equal capacity, 199 devices of 1 kN and f_u = 0.995 kN/m give mid-span histories within {:.2} mm of each other on a {:.1} mm peak.",
                1e3 * number(summary, "max_history_gap"),
                1e3 * number(summary, "peak_midspan_deflection")
            ),
            format!(
                "They dissipate {:.0} J and {:.0} J.",
                number(summary, "dissipated_devices"),
                number(summary, "dissipated_distributed")
            ),
        ],
    }
}
