//! Study 4: the critical speed with distributed friction f_u ∈ {0, 1, 2, 5, 10} kN/m: max deflections, W̄ and
//! dissipated energy vs speed (docs/theory.md §7).

use super::curves::{Curves, curves_study};
use super::resolution::Resolution;
use super::setups::with_distributed;
use super::study_data::StudyData;
use report::figures::dissipated_energy_axis;
use runner::Runner;
use scenario::Scenario;
use scenario::axis::{Axis, Shown};
use scenario::error::Result;

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let scenarios = [0.0, 1e3, 2e3, 5e3, 10e3]
        .into_iter()
        .map(|f| (vec![("force_per_length".into(), f)], with_distributed(base, f)))
        .collect();
    curves_study(
        scenarios,
        &resolution.speeds(base)?,
        runner,
        &|curves| {
            let legend = |c: usize| match c {
                0 => "no friction".to_string(),
                _ => format!("f_u = {} kN/m", [0, 1, 2, 5, 10][c]),
            };
            // f_u = 0 is "no friction", black as in every study; 1–10 kN/m take the next colours in order.
            let color = |c: usize| c;
            let all: Vec<usize> = (0..curves.len()).collect();
            vec![
                curves.deflection_plot(
                    "distributed-speed-deflection",
                    "Distributed friction: max deflection vs speed",
                    &all,
                    &legend,
                    &color,
                ),
                curves.quantity_plot(
                    "distributed-speed-global-norm",
                    "Distributed friction: global norm vs speed",
                    &Axis::new("global norm (1/t_on)∫∫|w| dx dt", "global_norm", Shown::Si),
                    |q| q.global_norm,
                    &all,
                    &legend,
                    &color,
                ),
                curves.quantity_plot(
                    "distributed-speed-dissipated",
                    "Distributed friction: dissipated energy vs speed",
                    &dissipated_energy_axis(),
                    |q| q.energy.dissipated / 1e3,
                    &all,
                    &legend,
                    &color,
                ),
            ]
        },
        headline,
    )
}

/// The critical speed without ballast friction and with the most of it.
fn headline(curves: &Curves) -> Vec<String> {
    let (none, strong) = (curves.find("force_per_length", 0.0), curves.find("force_per_length", 10e3));
    vec![
        format!("Without ballast friction the critical speed is {}.", curves.critical_text(none)),
        format!("With f_u = 10 kN/m it is {}.", curves.critical_text(strong)),
    ]
}
