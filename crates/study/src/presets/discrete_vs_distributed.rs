//! Study 6: 199 devices of 1 kN against f_u = 0.995 kN/m, equal capacity, at ¾ v_cr: mid-span deflection and
//! the friction mobilised (force over capacity) side by side (docs/theory.md §7).

use super::setups::{blank, with_devices, with_distributed};
use super::study_data::{StudyData, StudyFailure, StudySummary, keep_finished, nothing_finished};
use report::figures::quantity_figure;
use report::plot::PlotSpec;
use runner::Runner;
use scenario::Scenario;
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row;
use scenario::speeds::SpeedScale;
use serde::Serialize;
use std::fmt::Write as _;
use track::simulation::SectionHistory;

/// The two models, in the files' order.
const MODELS: [&str; 2] = ["devices", "distributed"];

pub(super) fn study(base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speed = SpeedScale::of(base)?.fraction(0.75, 150.0);
    let mut devices = with_devices(base, 199, 1e3);
    let mut distributed = with_distributed(base, 995.0);
    for s in [&mut devices, &mut distributed] {
        s.load.speed = speed;
        s.output.sections = vec![s.mesh.length / 2.0];
    }
    let (runs, failures) = run_both(devices, distributed, speed, runner)?;
    if runs.is_empty() {
        return Err(nothing_finished("both models".into(), &failures));
    }
    let csv = csv(&runs);
    let dissipated = |i: usize| runs.iter().find(|r| r.0 == i).map(|r| r.1.energy.dissipated());
    // (largest gap between the two histories, peak of the first) (m), when both ran.
    let (lines, comparison) = match runs.as_slice() {
        [(_, a, _), (_, b, _)] => {
            let (a, b) = (&a.histories[0], &b.histories[0]);
            let peak = a.deflection.iter().fold(0.0f64, |m, w| m.max(w.abs()));
            let gap = a.deflection.iter().zip(&b.deflection).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            let lines = vec![
                format!(
                    "mid-span deflection histories differ by at most {:.2} mm on a {:.1} mm peak ({:.2} %)",
                    gap * 1e3,
                    peak * 1e3,
                    100.0 * gap / peak
                ),
                format!(
                    "dissipated energy {:.0} J (199 devices) vs {:.0} J (distributed)",
                    dissipated(0).unwrap_or(f64::NAN),
                    dissipated(1).unwrap_or(f64::NAN)
                ),
            ];
            (lines, Some((gap, peak)))
        }
        _ => (vec![format!("no comparison: the {} run failed (see the failures)", failures[0].case)], None),
    };
    let nan = f64::NAN;
    let (gap, peak) = comparison.unwrap_or((nan, nan));
    let headline = vec![
        format!(
            "With equal capacity, 199 devices of 1 kN and f_u = 0.995 kN/m give mid-span histories within {:.2} mm of each other on a {:.1} mm peak.",
            1e3 * gap,
            1e3 * peak
        ),
        format!("They dissipate {:.0} J and {:.0} J.", dissipated(0).unwrap_or(nan), dissipated(1).unwrap_or(nan)),
    ];
    let summary = StudySummary::of(ComparisonSummary {
        speed,
        max_history_gap: comparison.map(|c| c.0),
        peak_midspan_deflection: comparison.map(|c| c.1),
        dissipated_devices: dissipated(0),
        dissipated_distributed: dissipated(1),
    });
    let plots = figures(&runs, speed);
    Ok(StudyData { csv, summary, lines, headline, plots, failures, ..blank(runs.len()) })
}

/// Devices against distributed friction of the same capacity at one speed; None where a run failed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ComparisonSummary {
    /// v (m/s).
    pub speed: f64,
    /// The largest gap between the two mid-span deflection histories (m).
    pub max_history_gap: Option<f64>,
    /// The peak mid-span deflection (m).
    pub peak_midspan_deflection: Option<f64>,
    /// Energy the devices dissipated (J).
    pub dissipated_devices: Option<f64>,
    /// Energy the distributed friction dissipated (J).
    pub dissipated_distributed: Option<f64>,
}

/// A finished run of one model: its index in [`MODELS`], its result and the capacity F_j (N) of its friction
/// section at mid-span.
type ModelRun = (usize, track::RunResult, f64);

/// Both models' runs at `speed`, built before any run (bad input is refused, exit 2, not recorded as a failed run);
/// a failed run is recorded and the other kept: the comparison needs both.
fn run_both(
    devices: Scenario,
    distributed: Scenario,
    speed: f64,
    runner: &Runner,
) -> Result<(Vec<ModelRun>, Vec<StudyFailure>)> {
    let cases = [devices.build()?, distributed.build()?];
    runner.announce_runs(&cases);
    let results = runner.map_each(&cases, |case| {
        let middle =
            case.interactions.positions().iter().position(|&x| (x - case.model.mesh().length / 2.0).abs() < 1e-9);
        let capacity = middle.map_or(f64::NAN, |j| case.interactions.interactions().capacity(j));
        Ok((runner.simulate(case, &case.settings)?, capacity))
    })?;
    let mut failures = Vec::new();
    let name = |i: usize| (format!("model = {}", MODELS[i]), Some(speed));
    let kept = keep_finished(results, name, &mut failures);
    let runs = kept.into_iter().map(|(i, (run, capacity))| (i, run, capacity)).collect();
    Ok((runs, failures))
}

/// `model,time,load_position,deflection,impulse` (text, s, m, m, N·s): the mid-span history of each finished run.
fn csv(runs: &[ModelRun]) -> String {
    let mut csv = String::from("model,time,load_position,deflection,impulse\n");
    for (i, r, _) in runs {
        let (name, h) = (MODELS[*i], &r.histories[0]);
        let impulse = h.impulse.as_deref().unwrap_or(&[]);
        for k in 0..h.time.len() {
            let values = [h.time[k], h.load_position[k], h.deflection[k], impulse.get(k).copied().unwrap_or(0.0)];
            let _ = writeln!(csv, "{name},{}", row(&values));
        }
    }
    csv
}

/// The mid-span deflection and the friction mobilised there, both models on common axes.
fn figures(runs: &[ModelRun], speed: f64) -> Vec<PlotSpec> {
    let history = |h: &SectionHistory, value: &dyn Fn(&SectionHistory, usize) -> f64| -> Vec<(f64, f64)> {
        (0..h.time.len()).map(|k| (h.time[k], value(h, k))).collect()
    };
    let labels = ["199 devices × 1 kN", "f_u = 0.995 kN/m"];
    let colors = [4, 5];
    let deflection = runs
        .iter()
        .map(|(i, r, _)| (labels[*i].into(), colors[*i], history(&r.histories[0], &|s, k| s.deflection[k] * 1e3)));
    let mobilised = runs.iter().map(|(i, r, capacity)| {
        let fraction = &|s: &SectionHistory, k: usize| s.impulse.as_ref().map_or(0.0, |p| p[k] / (r.step * capacity));
        (labels[*i].into(), colors[*i], history(&r.histories[0], fraction))
    });
    let capacity = |i: usize| runs.iter().find(|r| r.0 == i).map_or("–".into(), |r| format!("{:.0}", r.2));
    vec![
        {
            let mut plot = quantity_figure(
                "discrete-vs-distributed-deflection",
                &format!("Mid-span deflection at {speed} m/s, equal friction capacity"),
                &Axis::new("time t", "time", Shown::Si),
                &Axis::noted("mid-span deflection w", "deflection", Shown::Milli, "upward > 0"),
                deflection.collect(),
                false,
            );
            // The two histories lie on each other (0.44 % apart): the second dashed, so that both show.
            if let Some(second) = plot.series.get_mut(1) {
                second.stroke = report::plot::Stroke::Dashed;
                plot.subtitle = "the distributed friction dashed over the devices: the two curves coincide".into();
            }
            plot
        },
        {
            let mut plot = quantity_figure(
                "discrete-vs-distributed-mobilised",
                &format!("Friction mobilised at mid-span, {speed} m/s"),
                &Axis::new("time t", "time", Shown::Si),
                &Axis::noted("friction force / capacity of the section", "mobilised_friction", Shown::Si, "−1 … 1"),
                mobilised.collect(),
                false,
            );
            plot.subtitle = format!(
                "capacity at mid-span: a device of {} N against a section of {} N (0.995 kN/m × 0.25 m)",
                capacity(0),
                capacity(1)
            );
            plot
        },
    ]
}
