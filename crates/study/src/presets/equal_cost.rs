//! Study 2: equal-cost device solutions, N·F_u ∈ {3100, 1550, 310} kN shared by N ∈ {31, 15, 7, 3}
//! (docs/theory.md §7).

use super::curves::{Curves, curves_study};
use super::resolution::Resolution;
use super::setups::with_devices;
use super::study_data::StudyData;
use report::figures::device_color;
use runner::Runner;
use scenario::Scenario;
use scenario::error::Result;

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let mut scenarios = Vec::new();
    for cost in [3100e3, 1550e3, 310e3] {
        for count in [31usize, 15, 7, 3] {
            let force = cost / count as f64;
            let labels = vec![("cost".into(), cost), ("devices".into(), count as f64), ("device_force".into(), force)];
            scenarios.push((labels, with_devices(base, count, force)));
        }
    }
    curves_study(
        scenarios,
        &resolution.speeds(base)?,
        runner,
        &|curves| {
            [3100, 1550, 310]
                .iter()
                .enumerate()
                .map(|(i, cost)| {
                    let legend = |c: usize| {
                        let n = [31, 15, 7, 3][c % 4];
                        format!("N = {n}, F_u = {:.1} kN", f64::from(*cost) / f64::from(n))
                    };
                    curves.deflection_plot(
                        &format!("equal-cost-{cost}kN"),
                        &format!("Equal cost N·F_u = {cost} kN: max deflection vs speed"),
                        &((4 * i)..(4 * i + 4)).collect::<Vec<_>>(),
                        &legend,
                        &|c| device_color([31, 15, 7, 3][c % 4]),
                    )
                })
                .collect()
        },
        headline,
    )
}

/// For each total capacity, the device count with the lowest peak.
fn headline(curves: &Curves) -> Vec<String> {
    let mut text = Vec::new();
    for cost in [3100e3, 1550e3, 310e3] {
        let group = (0..curves.len()).filter(|&c| curves.label(Some(c), "cost") == cost);
        if let Some(b) = curves.lowest_peak(group).map(Some) {
            text.push(format!(
                "{:.0} kN: {} × {:.0} kN (peak {:.0} mm)",
                cost / 1e3,
                curves.label(b, "devices"),
                curves.label(b, "device_force") / 1e3,
                1e3 * curves.peak(b)
            ));
        }
    }
    vec![
        "For a given total friction capacity N·F_u, the lowest resonance peak comes from:".into(),
        format!("{}.", text.join("; ")),
    ]
}
