//! A labelled family of speed sweeps with the refined critical speed of each curve: the data, figures and summary
//! of the three speed studies (devices, equal cost, distributed friction).

use super::setups::{blank, mean_iterations};
use super::study_data::{StudyData, StudyFailure, StudySummary, failed_runs};
use report::figures::{DeflectionCurve, deflection_figure, load_speed_axis, quantity_figure};
use report::plot::PlotSpec;
use runner::{CriticalSpeed, PeakLocation, Runner, SweepPoint, SweepRow, critical_speed, finished};
use scenario::Scenario;
use scenario::axis::Axis;
use scenario::error::{Result, invalid};
use scenario::number::{row, row_with_gaps};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// A labelled family of speed sweeps with the critical speed of each curve.
pub(super) struct Curves {
    labels: Vec<Vec<(String, f64)>>,
    /// Each curve's sweep, one row per speed in the order of the speeds: a finished point or why the run failed.
    rows: Vec<Vec<SweepRow>>,
    /// Each curve's finished points, in the order of the speeds.
    pub(super) points: Vec<Vec<SweepPoint>>,
    /// Each curve's refined critical speed; None when the curve's runs failed too often to refine it (see
    /// `failures`).
    pub(super) critical: Vec<Option<CriticalSpeed>>,
    /// The runs that failed, each with its curve; every other run is kept.
    pub(super) failures: Vec<StudyFailure>,
    /// Simulations run (sweeps and refinements).
    pub(super) runs: usize,
}

/// Sweep every scenario over `speeds` on one pool, then refine each curve's critical speed to 2 % of the speed step.
/// A failed run leaves a gap in its curve and is recorded; a curve whose refinement fails (or with fewer than three
/// finished runs) has no critical speed, and that is recorded too.
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
    let labels: Vec<Vec<(String, f64)>> = scenarios.into_iter().map(|(l, _)| l).collect();
    let step = speeds[1] - speeds[0];
    // The refinement of each curve's critical speed follows the sweep: counted in its estimate.
    let refinements = runner::refinement_runs(step, 0.02 * step, 0);
    let rows = runner.clone().with_refinement(refinements).sweep_many_keeping(&cases, speeds)?;
    let points: Vec<Vec<SweepPoint>> = rows.iter().map(|r| finished(r)).collect();
    let curves: Vec<usize> = (0..cases.len()).collect();
    let refined = runner.silent().map_each(&curves, |&c| critical_speed(&cases[c], &points[c], 0.02 * step, runner))?;
    let mut failures = failed_runs(&rows, |c| describe(&labels[c]));
    let mut critical = Vec::with_capacity(cases.len());
    for (c, result) in refined.into_iter().enumerate() {
        match result {
            Ok(k) => critical.push(Some(k)),
            Err(e) => {
                failures.push(StudyFailure {
                    case: describe(&labels[c]),
                    speed: None,
                    error: format!("no critical speed: {e}"),
                });
                critical.push(None);
            }
        }
    }
    let runs = points.iter().map(Vec::len).sum::<usize>()
        + critical.iter().flatten().map(|c| c.evaluations.len()).sum::<usize>();
    Ok(Curves { labels, rows, points, critical, failures, runs })
}

/// A curve's labels as text: "devices = 31, device_force = 50000".
fn describe(labels: &[(String, f64)]) -> String {
    labels.iter().map(|(n, v)| format!("{n} = {v}")).collect::<Vec<_>>().join(", ")
}

impl Curves {
    /// Curve `c`'s sweep, one row per speed: a finished point or why the run failed.
    pub(super) fn speed_rows(&self, c: usize) -> &[SweepRow] {
        &self.rows[c]
    }

    /// Number of curves.
    pub(super) fn len(&self) -> usize {
        self.labels.len()
    }

    /// The first curve whose label `name` is `value`.
    pub(super) fn find(&self, name: &str, value: f64) -> Option<usize> {
        (0..self.labels.len()).find(|&c| self.label(Some(c), name) == value)
    }

    /// The value of label `name` of curve `c` (NaN for no curve, or a curve without that label).
    pub(super) fn label(&self, c: Option<usize>, name: &str) -> f64 {
        let labels = c.and_then(|c| self.labels.get(c));
        labels.and_then(|l| l.iter().find(|(n, _)| n == name)).map_or(f64::NAN, |(_, v)| *v)
    }

    /// The refined peak max downward deflection of curve `c` (m); NaN for no curve or no critical speed.
    pub(super) fn peak(&self, c: Option<usize>) -> f64 {
        c.and_then(|c| self.critical[c].as_ref()).map_or(f64::NAN, |k| k.max_downward_deflection)
    }

    /// The curve of the lowest refined peak among `members`, the first of equals.
    pub(super) fn lowest_peak(&self, members: impl Iterator<Item = usize>) -> Option<usize> {
        members.min_by(|&a, &b| self.peak(Some(a)).total_cmp(&self.peak(Some(b))))
    }

    /// Curve `c`'s critical speed in words, for the report's headline: a bound at an end of the range says so.
    pub(super) fn critical_text(&self, c: Option<usize>) -> String {
        let Some(k) = c.and_then(|c| self.critical[c].as_ref()) else {
            return "unknown (runs of that curve failed: see the study's failures)".to_string();
        };
        let (speed, peak) = (k.speed, 1e3 * k.max_downward_deflection);
        match k.location {
            PeakLocation::UpperEnd => {
                format!("at or above {speed:.1} m/s, the top of the range (peak there {peak:.0} mm)")
            }
            PeakLocation::LowerEnd => {
                format!("at or below {speed:.1} m/s, the bottom of the range (peak there {peak:.0} mm)")
            }
            PeakLocation::Interior => format!("{speed:.1} m/s with a peak of {peak:.0} mm"),
        }
    }

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
                downward: self.points[c].iter().map(|q| (q.speed, q.deflection.max_downward.value)).collect(),
                upward: self.points[c].iter().map(|q| (q.speed, q.deflection.max_upward.value)).collect(),
                optimum: self.critical[c]
                    .as_ref()
                    .filter(|k| k.is_interior())
                    .map(|k| (k.speed, k.max_downward_deflection)),
            })
            .collect();
        deflection_figure(stem, title, &load_speed_axis(), curves, "refined critical speed")
    }

    /// One quantity vs speed for the curves `members`.
    #[allow(clippy::too_many_arguments)] // A figure's words, its curves and their look, one each.
    pub(super) fn quantity_plot(
        &self,
        stem: &str,
        title: &str,
        y: &Axis,
        value: fn(&SweepPoint) -> f64,
        members: &[usize],
        legend: &dyn Fn(usize) -> String,
        color: &dyn Fn(usize) -> usize,
    ) -> PlotSpec {
        let curves = members
            .iter()
            .map(|&c| (legend(c), color(c), self.points[c].iter().map(|q| (q.speed, value(q))).collect()))
            .collect();
        quantity_figure(stem, title, &load_speed_axis(), y, curves, true)
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
        for (labels, rows) in self.labels.iter().zip(&self.rows) {
            let prefix: Vec<f64> = labels.iter().map(|(_, v)| *v).collect();
            for r in rows {
                // A failed run's row keeps its labels and speed, every value empty (why: the JSON's failures).
                let values = match r {
                    Ok(p) => [
                        p.speed,
                        p.deflection.max_downward.value,
                        p.deflection.max_upward.value,
                        p.energy.dissipated,
                        p.global_norm,
                        p.window_deflection.max_downward.value,
                        p.window_deflection.max_upward.value,
                    ],
                    Err(f) => [f.speed, f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN],
                };
                let _ = writeln!(out, "{},{}", row(&prefix), row_with_gaps(&values));
            }
        }
        out
    }

    pub(super) fn summary(&self) -> (CurvesSummary, Vec<String>) {
        let mut curves = Vec::new();
        let mut lines = Vec::new();
        for ((labels, points), critical) in self.labels.iter().zip(&self.points).zip(&self.critical) {
            curves.push(CurveSummary {
                labels: labels.iter().cloned().collect(),
                critical_speed: critical.as_ref().map(|k| k.speed),
                critical_speed_location: critical.as_ref().map(|k| k.location),
                peak_max_downward_deflection: critical.as_ref().map(|k| k.max_downward_deflection),
                peak_max_upward_deflection_sampled: points
                    .iter()
                    .fold(0.0, |m, p| m.max(p.deflection.max_upward.value)),
                peak_window_max_downward_deflection_sampled: points
                    .iter()
                    .fold(0.0, |m, p| m.max(p.window_deflection.max_downward.value)),
            });
            let text = match critical {
                Some(k) if k.is_interior() => format!(
                    "critical speed {:.1} m/s ({:.0} km/h), peak max downward deflection {:.1} mm",
                    k.speed,
                    k.speed * scenario::units::KMH,
                    k.max_downward_deflection * 1e3
                ),
                Some(k) => k.describe(),
                None => format!("no critical speed ({} of the sweep's runs finished; see the failures)", points.len()),
            };
            lines.push(format!("{}: {text}", describe(labels)));
        }
        (CurvesSummary { curves }, lines)
    }
}

/// The curves of a study over speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurvesSummary {
    /// One per curve, in the order of the data.
    pub curves: Vec<CurveSummary>,
}

/// One curve: what sets it (its labels, e.g. `devices`, `device_force` N, `force_per_length` N/m) and its peak.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveSummary {
    /// The curve's parameters by name.
    #[serde(flatten)]
    pub labels: BTreeMap<String, f64>,
    /// The refined critical speed (m/s); None when too few runs finished.
    pub critical_speed: Option<f64>,
    /// Where in the speed range it lies.
    pub critical_speed_location: Option<runner::PeakLocation>,
    /// The refined peak of the max downward deflection (m).
    pub peak_max_downward_deflection: Option<f64>,
    /// The largest max upward deflection of the sampled speeds (m).
    pub peak_max_upward_deflection_sampled: f64,
    /// The largest window max downward deflection of the sampled speeds (m).
    pub peak_window_max_downward_deflection_sampled: f64,
}

/// A study of curves: sweep `scenarios` over `speeds`, draw them with `plots`, and say what they show with
/// `headline`.
pub(super) fn curves_study(
    scenarios: Vec<(Vec<(String, f64)>, Scenario)>,
    speeds: &[f64],
    runner: &Runner,
    plots: &dyn Fn(&Curves) -> Vec<PlotSpec>,
    headline: fn(&Curves) -> Vec<String>,
) -> Result<StudyData> {
    let curves = sweep_curves(scenarios, speeds, runner)?;
    let (summary, lines) = curves.summary();
    Ok(StudyData {
        csv: curves.csv(),
        summary: StudySummary::of(summary),
        lines,
        headline: headline(&curves),
        plots: plots(&curves),
        mean_iterations: mean_iterations(curves.points.iter().flatten()),
        failures: curves.failures,
        ..blank(curves.runs)
    })
}
