//! Study 3: the optimal device force at the critical speed for N ∈ {3, 7, 15, 31}: a log scan of F_u over
//! 1 kN–10 MN, then golden section around the best (docs/theory.md §7).

use super::{Resolution, StudyData, blank, mean_iterations, with_devices};
use crate::error::Result;
use crate::figures::{DeflectionCurve, deflection_figure, device_color};
use crate::number::row;
use crate::scenario::Scenario;
use crate::speeds::SpeedScale;
use crate::sweep::{Runner, log_spaced, refine_from_scan};
use serde_json::json;
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
    let points = runner.map(&scenarios, |s| runner.point(&s.build()?, speed))?;
    let mut csv =
        String::from("devices,device_force,speed,max_downward_deflection,max_upward_deflection,dissipated_energy\n");
    let mut items = Vec::new();
    let mut lines = Vec::new();
    let mut runs = points.len();
    let mut figure_curves = Vec::new();
    for (i, &n) in counts.iter().enumerate() {
        let curve = &points[i * forces.len()..(i + 1) * forces.len()];
        let kn = |f: &f64| f / 1e3;
        for (f, p) in forces.iter().zip(curve) {
            let values = [n as f64, *f, speed, p.max_downward_deflection, p.max_upward_deflection, p.dissipated_energy];
            let _ = writeln!(csv, "{}", row(&values));
        }
        let values: Vec<f64> = curve.iter().map(|p| p.max_downward_deflection).collect();
        let refined = refine_from_scan(&with_devices(base, n, 1.0), speed, &forces, &values, 0.02, runner)?;
        runs += refined.explored.len();
        figure_curves.push(DeflectionCurve {
            label: format!("N = {n}"),
            color: device_color(n),
            downward: forces.iter().zip(curve).map(|(f, p)| (kn(f), p.max_downward_deflection)).collect(),
            upward: forces.iter().zip(curve).map(|(f, p)| (kn(f), p.max_upward_deflection)).collect(),
            optimum: Some((kn(&refined.force), refined.max_downward_deflection)),
        });
        items.push(json!({ "devices": n, "optimal_device_force": refined.force, "max_downward_deflection": refined.max_downward_deflection }));
        lines.push(format!(
            "N = {n}: optimal F_u {:.1} kN gives max downward deflection {:.1} mm at {speed} m/s",
            refined.force / 1e3,
            refined.max_downward_deflection * 1e3
        ));
    }
    let mut plot = deflection_figure(
        "optimal-force",
        &format!("Max deflection vs device force at {speed} m/s"),
        "device force F_u (kN, log scale)",
        figure_curves,
        "refined optimal force",
    );
    plot.log_x = true;
    Ok(StudyData {
        csv,
        summary: json!({ "speed": speed, "optima": items }),
        lines,
        plots: vec![plot],
        mean_iterations: mean_iterations(points.iter()),
        ..blank(runs)
    })
}
