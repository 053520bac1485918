//! A labelled family of speed sweeps with the refined critical speed of each curve: the data, figures and summary
//! of the three speed studies (devices, equal cost, distributed friction).

use super::{StudyData, blank, mean_iterations};
use crate::error::{Result, invalid};
use crate::figures::{DeflectionCurve, deflection_figure, quantity_figure};
use crate::number::row;
use crate::plot::PlotSpec;
use crate::scenario::Scenario;
use crate::sweep::{CriticalSpeed, Runner, SweepPoint, critical_speed};
use serde_json::{Value, json};
use std::fmt::Write as _;

/// A labelled family of speed sweeps with the critical speed of each curve.
pub(super) struct Curves {
    labels: Vec<Vec<(String, f64)>>,
    /// Each curve's sweep, in the order of the speeds.
    pub(super) points: Vec<Vec<SweepPoint>>,
    /// Each curve's refined critical speed.
    pub(super) critical: Vec<CriticalSpeed>,
    /// Simulations run (sweeps and refinements).
    pub(super) runs: usize,
}

/// Sweep every scenario over `speeds` on one pool, then refine each curve's critical speed to 2 % of the speed step.
pub(super) fn sweep_curves(
    scenarios: Vec<(Vec<(String, f64)>, Scenario)>,
    speeds: &[f64],
    runner: &Runner,
) -> Result<Curves> {
    // A critical speed needs an interior maximum: refused before any run rather than after the sweep.
    if speeds.len() < 3 {
        return Err(invalid("speeds", format!("{} speed(s)", speeds.len()), "a speed study needs at least 3 speeds"));
    }
    let cases = scenarios.iter().map(|(_, s)| s.build()).collect::<Result<Vec<_>>>()?;
    let points = runner.sweep_many(&cases, speeds)?;
    let step = speeds[1] - speeds[0];
    let curves: Vec<usize> = (0..cases.len()).collect();
    let refined = runner.silent().map(&curves, |&c| critical_speed(&cases[c], &points[c], 0.02 * step, runner))?;
    let runs = cases.len() * speeds.len() + refined.iter().map(|c| c.evaluations.len()).sum::<usize>();
    Ok(Curves { labels: scenarios.into_iter().map(|(l, _)| l).collect(), points, critical: refined, runs })
}

impl Curves {
    /// Max downward and upward deflection magnitudes vs speed for the curves `members`, coloured by `color`, with
    /// each interior critical speed marked.
    pub(super) fn deflection_plot(
        &self,
        stem: &str,
        title: &str,
        members: &[usize],
        legend: &dyn Fn(usize) -> String,
        color: &dyn Fn(usize) -> usize,
    ) -> PlotSpec {
        let curves = members
            .iter()
            .map(|&c| DeflectionCurve {
                label: legend(c),
                color: color(c),
                downward: self.points[c].iter().map(|q| (q.speed, q.max_downward_deflection)).collect(),
                upward: self.points[c].iter().map(|q| (q.speed, q.max_upward_deflection)).collect(),
                optimum: Some(&self.critical[c])
                    .filter(|k| k.is_interior())
                    .map(|k| (k.speed, k.max_downward_deflection)),
            })
            .collect();
        deflection_figure(stem, title, "load speed v (m/s)", curves, "refined critical speed")
    }

    /// One quantity vs speed for every curve.
    pub(super) fn quantity_plot(
        &self,
        stem: &str,
        title: &str,
        y_label: &str,
        value: fn(&SweepPoint) -> f64,
        legend: &dyn Fn(usize) -> String,
        color: &dyn Fn(usize) -> usize,
    ) -> PlotSpec {
        let curves = (0..self.points.len())
            .map(|c| (legend(c), color(c), self.points[c].iter().map(|q| (q.speed, value(q))).collect()))
            .collect();
        quantity_figure(stem, title, "load speed v (m/s)", y_label, curves, true)
    }

    fn csv(&self) -> String {
        let mut out = String::new();
        let label_names: Vec<&str> = self.labels[0].iter().map(|(n, _)| n.as_str()).collect();
        let _ = writeln!(
            out,
            "{},speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm,\
             window_max_downward_deflection,window_max_upward_deflection",
            label_names.join(",")
        );
        for (labels, points) in self.labels.iter().zip(&self.points) {
            let prefix: Vec<f64> = labels.iter().map(|(_, v)| *v).collect();
            for p in points {
                let values = [
                    p.speed,
                    p.max_downward_deflection,
                    p.max_upward_deflection,
                    p.dissipated_energy,
                    p.global_norm,
                    p.window_max_downward_deflection,
                    p.window_max_upward_deflection,
                ];
                let _ = writeln!(out, "{},{}", row(&prefix), row(&values));
            }
        }
        out
    }

    fn summary(&self) -> (Value, Vec<String>) {
        let mut items = Vec::new();
        let mut lines = Vec::new();
        for ((labels, points), critical) in self.labels.iter().zip(&self.points).zip(&self.critical) {
            let upward = points.iter().fold(0.0f64, |m, p| m.max(p.max_upward_deflection));
            let window = points.iter().fold(0.0f64, |m, p| m.max(p.window_max_downward_deflection));
            let mut item = serde_json::Map::new();
            for (name, value) in labels {
                item.insert(name.clone(), json!(value));
            }
            item.insert("critical_speed".into(), json!(critical.speed));
            item.insert("critical_speed_location".into(), json!(critical.location));
            item.insert("peak_max_downward_deflection".into(), json!(critical.max_downward_deflection));
            item.insert("peak_max_upward_deflection_sampled".into(), json!(upward));
            item.insert("peak_window_max_downward_deflection_sampled".into(), json!(window));
            items.push(Value::Object(item));
            let label: Vec<String> = labels.iter().map(|(n, v)| format!("{n} = {v}")).collect();
            let text = if critical.is_interior() {
                format!(
                    "critical speed {:.1} m/s ({:.0} km/h), peak max downward deflection {:.1} mm",
                    critical.speed,
                    critical.speed * 3.6,
                    critical.max_downward_deflection * 1e3
                )
            } else {
                critical.describe()
            };
            lines.push(format!("{}: {text}", label.join(", ")));
        }
        (json!({ "curves": items }), lines)
    }
}

pub(super) fn curves_study(
    scenarios: Vec<(Vec<(String, f64)>, Scenario)>,
    speeds: &[f64],
    runner: &Runner,
    plots: &dyn Fn(&Curves) -> Vec<PlotSpec>,
) -> Result<StudyData> {
    let curves = sweep_curves(scenarios, speeds, runner)?;
    let (summary, lines) = curves.summary();
    Ok(StudyData {
        csv: curves.csv(),
        summary,
        lines,
        plots: plots(&curves),
        mean_iterations: mean_iterations(curves.points.iter().flatten()),
        ..blank(curves.runs)
    })
}
