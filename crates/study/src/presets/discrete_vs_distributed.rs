//! Study 6: 199 devices of 1 kN against f_u = 0.995 kN/m, equal capacity, at ¾ v_cr: mid-span deflection and
//! the friction mobilised (force over capacity) side by side (docs/theory.md §7).

use super::{StudyData, blank, with_devices, with_distributed};
use crate::error::Result;
use crate::figures::quantity_figure;
use crate::number::row;
use crate::scenario::Scenario;
use crate::speeds::SpeedScale;
use crate::sweep::Runner;
use serde_json::json;
use std::fmt::Write as _;

pub(super) fn study(base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speed = SpeedScale::of(base)?.fraction(0.75, 150.0);
    let mut devices = with_devices(base, 199, 1e3);
    let mut distributed = with_distributed(base, 995.0);
    for s in [&mut devices, &mut distributed] {
        s.load.speed = speed;
        s.output.sections = vec![s.mesh.length / 2.0];
    }
    // Each run with the capacity F_j (N) of its friction section at mid-span, to compare what each mobilises.
    let runs = runner.map(&[&devices, &distributed], |s| {
        let case = s.build()?;
        let middle = case.interactions.positions().iter().position(|&x| (x - s.mesh.length / 2.0).abs() < 1e-9);
        let capacity = middle.map_or(f64::NAN, |j| case.interactions.capacity(j));
        Ok((runner.simulate(&case, &case.settings)?, capacity))
    })?;
    let (capacities, runs): (Vec<f64>, Vec<_>) = runs.into_iter().map(|(r, c)| (c, r)).unzip();
    let mut csv = String::from("model,time,load_position,deflection,impulse\n");
    for (name, r) in ["devices", "distributed"].iter().zip(&runs) {
        let h = &r.histories[0];
        let impulse = h.impulse.as_deref().unwrap_or(&[]);
        for k in 0..h.time.len() {
            let values = [h.time[k], h.load_position[k], h.deflection[k], impulse.get(k).copied().unwrap_or(0.0)];
            let _ = writeln!(csv, "{name},{}", row(&values));
        }
    }
    let (a, b) = (&runs[0].histories[0], &runs[1].histories[0]);
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
            runs[0].energy.dissipated(),
            runs[1].energy.dissipated()
        ),
    ];
    let summary = json!({
        "speed": speed,
        "max_history_gap": gap,
        "peak_midspan_deflection": peak,
        "dissipated_devices": runs[0].energy.dissipated(),
        "dissipated_distributed": runs[1].energy.dissipated(),
    });
    let history = |i: usize, value: &dyn Fn(&track::simulation::SectionHistory, usize) -> f64| -> Vec<(f64, f64)> {
        let h = &runs[i].histories[0];
        (0..h.time.len()).map(|k| (h.time[k], value(h, k))).collect()
    };
    let labels = ["199 devices × 1 kN", "f_u = 0.995 kN/m"];
    let colors = [4, 5];
    let h = runs[0].step;
    let deflection = (0..2).map(|i| (labels[i].to_string(), colors[i], history(i, &|s, k| s.deflection[k] * 1e3)));
    let mobilised = (0..2).map(|i| {
        let fraction = &|s: &track::simulation::SectionHistory, k: usize| {
            s.impulse.as_ref().map_or(0.0, |p| p[k] / (h * capacities[i]))
        };
        (labels[i].to_string(), colors[i], history(i, fraction))
    });
    let plots = vec![
        {
            let mut plot = quantity_figure(
                "discrete-vs-distributed-deflection",
                &format!("Mid-span deflection at {speed} m/s, equal friction capacity"),
                "time t (s)",
                "mid-span deflection w (mm, upward > 0)",
                deflection.collect(),
                false,
            );
            // The two histories lie on each other (0.44 % apart): the second dashed, so that both show.
            if let Some(second) = plot.series.get_mut(1) {
                second.stroke = crate::plot::Stroke::Dashed;
            }
            plot.subtitle = "the distributed friction dashed over the devices: the two curves coincide".into();
            plot
        },
        {
            let mut plot = quantity_figure(
                "discrete-vs-distributed-mobilised",
                &format!("Friction mobilised at mid-span, {speed} m/s"),
                "time t (s)",
                "friction force / capacity of the section (-1 … 1)",
                mobilised.collect(),
                false,
            );
            plot.subtitle = format!(
                "capacity at mid-span: a device of {:.0} N against a section of {:.0} N (0.995 kN/m × 0.25 m)",
                capacities[0], capacities[1]
            );
            plot
        },
    ];
    Ok(StudyData { csv, summary, lines, plots, ..blank(2) })
}
