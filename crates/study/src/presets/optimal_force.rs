//! Study 3: the optimal device force at the critical speed for N ∈ {3, 7, 15, 31}: a log scan of F_u over
//! 1 kN–10 MN, then golden section around the best (docs/theory.md §7).

use super::resolution::Resolution;
use super::setups::{blank, mean_iterations, with_devices};
use super::study_data::{StudyData, StudyFailure, StudySummary, nothing_finished};
use report::figures::{DeflectionCurve, deflection_figure, device_color};
use runner::{OptimalForce, Runner, SweepPoint, log_spaced, refine_from_scan};
use scenario::Scenario;
use scenario::axis::{Axis, Shown};
use scenario::error::{Result, invalid};
use scenario::number::row_with_gaps;
use scenario::speeds::SpeedScale;
use serde::Serialize;
use std::fmt::Write as _;

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speed = SpeedScale::of(base)?.near_critical(206.0);
    let forces = log_spaced(1e3, 1e7, resolution.forces());
    let counts = [3usize, 7, 15, 31];
    let scenarios: Vec<Scenario> = counts
        .iter()
        .flat_map(|&n| forces.iter().map(move |&f| (n, f)))
        .map(|(n, f)| with_devices(base, n, f))
        .collect();
    // A failed run leaves a gap in its curve and is recorded; each curve's optimum comes from its finished runs.
    // Built before any run: bad input is refused (exit 2), not recorded as a failed run.
    let cases = scenarios.iter().map(Scenario::build).collect::<Result<Vec<_>>>()?;
    runner.announce_points(&cases, &(0..cases.len()).map(|c| (c, speed)).collect::<Vec<_>>());
    let points = runner.map_each(&cases, |case| runner.point(case, speed))?;
    let mut csv =
        String::from("devices,device_force,speed,max_downward_deflection,max_upward_deflection,dissipated_energy\n");
    let mut items = Vec::new();
    // (N, the refined optimum (F_u, max downward deflection) if any) per curve, for the headline.
    let mut optima = Vec::new();
    let mut lines = Vec::new();
    let mut failures = Vec::new();
    let mut finished_points = Vec::new();
    let mut figure_curves = Vec::new();
    let mut refinement_runs = 0;
    for (i, &n) in counts.iter().enumerate() {
        let scanned = &points[i * forces.len()..(i + 1) * forces.len()];
        let curve = scan(n, (&forces, scanned), speed, &mut csv, &mut failures);
        let optimum = optimum(&with_devices(base, n, 1.0), speed, &curve, runner);
        let optimum = match optimum {
            Ok(refined) => Some(refined),
            Err(e) => {
                let case = format!("devices = {n}");
                failures.push(StudyFailure { case, speed: None, error: format!("no optimal force: {e}") });
                None
            }
        };
        lines.push(describe(n, optimum.as_ref(), speed, (curve.len(), forces.len())));
        optima.push((n, optimum.as_ref().map(|o| (o.force, o.max_downward_deflection))));
        items.push(Optimum {
            devices: n,
            optimal_device_force: optimum.as_ref().map(|o| o.force),
            max_downward_deflection: optimum.as_ref().map(|o| o.max_downward_deflection),
        });
        let kn = |f: f64| f / 1e3;
        figure_curves.push(DeflectionCurve {
            label: format!("N = {n}"),
            color: device_color(n),
            downward: curve.iter().map(|(f, p)| (kn(*f), p.deflection.max_downward.value)).collect(),
            upward: curve.iter().map(|(f, p)| (kn(*f), p.deflection.max_upward.value)).collect(),
            optimum: optimum.as_ref().map(|o| (kn(o.force), o.max_downward_deflection)),
        });
        refinement_runs += optimum.map_or(0, |o| o.explored.len());
        finished_points.extend(curve.into_iter().map(|(_, p)| p));
    }
    if finished_points.is_empty() {
        return Err(nothing_finished(format!("the optimal-force scan at {speed} m/s"), &failures));
    }
    let mut plot = deflection_figure(
        "optimal-force",
        &format!("Max deflection vs device force at {speed} m/s"),
        &Axis::noted("device force F_u", "device_force", Shown::Kilo, "log scale"),
        figure_curves,
        "refined optimal force",
    );
    plot.log_x = true;
    Ok(StudyData {
        csv,
        summary: StudySummary::of(OptimaSummary { speed, optima: items }),
        headline: headline(speed, &optima),
        lines,
        plots: vec![plot],
        mean_iterations: mean_iterations(finished_points.iter()),
        failures,
        ..blank(refinement_runs + finished_points.len())
    })
}

/// The optimal device force for each number of devices at one speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OptimaSummary {
    /// v (m/s).
    pub speed: f64,
    /// One per device count.
    pub optima: Vec<Optimum>,
}

/// The refined device force that minimises the max downward deflection; None where too few runs finished.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Optimum {
    /// N.
    pub devices: usize,
    /// F_u (N).
    pub optimal_device_force: Option<f64>,
    /// The max downward deflection there (m).
    pub max_downward_deflection: Option<f64>,
}

/// The refined optimal device force of a curve from its finished scan `(F_u, point)`: refused with fewer than
/// three finished forces (no bracket around the best one).
fn optimum(scenario: &Scenario, speed: f64, curve: &[(f64, SweepPoint)], runner: &Runner) -> Result<OptimalForce> {
    if curve.len() < 3 {
        return Err(invalid("device forces", format!("{} finished", curve.len()), "at least 3 to bracket an optimum"));
    }
    let forces: Vec<f64> = curve.iter().map(|(f, _)| *f).collect();
    let values: Vec<f64> = curve.iter().map(|(_, p)| p.deflection.max_downward.value).collect();
    refine_from_scan(scenario, speed, &forces, &values, 0.02, runner)
}

/// The optimal device force of each device count at the study's speed.
fn headline(speed: f64, optima: &[(usize, Option<(f64, f64)>)]) -> Vec<String> {
    let text: Vec<String> = optima
        .iter()
        .map(|(n, optimum)| {
            let (force, deflection) = optimum.unwrap_or((f64::NAN, f64::NAN));
            format!("N = {n}: {:.0} kN ({:.0} mm)", force / 1e3, 1e3 * deflection)
        })
        .collect();
    vec![
        format!("At {speed} m/s the max downward deflection is smallest for an intermediate device force:"),
        format!("{}.", text.join("; ")),
    ]
}

/// The scan of `n` devices: a CSV row per force (`forces`, the runs `points` in their order; a failed run's row has
/// its values empty and its failure recorded) and the finished (F_u, point) pairs.
fn scan(
    n: usize,
    (forces, points): (&[f64], &[Result<SweepPoint>]),
    speed: f64,
    csv: &mut String,
    failures: &mut Vec<StudyFailure>,
) -> Vec<(f64, SweepPoint)> {
    let mut curve = Vec::new();
    for (&f, p) in forces.iter().zip(points) {
        let values = match p {
            Ok(p) => {
                curve.push((f, p.clone()));
                [
                    n as f64,
                    f,
                    speed,
                    p.deflection.max_downward.value,
                    p.deflection.max_upward.value,
                    p.energy.dissipated,
                ]
            }
            Err(e) => {
                let case = format!("devices = {n}, device_force = {f}");
                failures.push(StudyFailure { case, speed: Some(speed), error: e.to_string() });
                [n as f64, f, speed, f64::NAN, f64::NAN, f64::NAN]
            }
        };
        let _ = writeln!(csv, "{}", row_with_gaps(&values));
    }
    curve
}

/// The summary line of `n` devices: their optimum, or that there is none and how many of the scan's runs finished
/// (`finished`, `scanned`).
fn describe(n: usize, optimum: Option<&OptimalForce>, speed: f64, (finished, scanned): (usize, usize)) -> String {
    match optimum {
        Some(o) => format!(
            "N = {n}: optimal F_u {:.1} kN gives max downward deflection {:.1} mm at {speed} m/s",
            o.force / 1e3,
            o.max_downward_deflection * 1e3
        ),
        None => format!("N = {n}: no optimal force ({finished} of {scanned} runs finished)"),
    }
}
