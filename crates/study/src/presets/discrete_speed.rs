//! Study 1: the critical speed with discrete devices, N ∈ {3, 7, 15, 31} of F_u ∈ {10, 50, 100} kN, and without
//! friction (docs/theory.md §7).

use super::curves::{Curves, curves_study};
use super::resolution::Resolution;
use super::setups::with_devices;
use super::study_data::StudyData;
use report::figures::device_color;
use runner::Runner;
use scenario::Scenario;
use scenario::error::Result;

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let mut scenarios = vec![(vec![("device_force".into(), 0.0), ("devices".into(), 0.0)], with_devices(base, 0, 0.0))];
    for force in [10e3, 50e3, 100e3] {
        for count in [3usize, 7, 15, 31] {
            scenarios.push((
                vec![("device_force".into(), force), ("devices".into(), count as f64)],
                with_devices(base, count, force),
            ));
        }
    }
    let mut data = curves_study(
        scenarios,
        &resolution.speeds(base)?,
        runner,
        &|curves| {
            let legend = |c: usize| {
                if c == 0 { "no friction".to_string() } else { format!("N = {}", [3, 7, 15, 31][(c - 1) % 4]) }
            };
            [10, 50, 100]
                .iter()
                .enumerate()
                .map(|(i, kn)| {
                    let members: Vec<usize> = std::iter::once(0).chain((1 + 4 * i)..(5 + 4 * i)).collect();
                    curves.deflection_plot(
                        &format!("discrete-speed-{kn}kN"),
                        &format!("Discrete devices, F_u = {kn} kN: max deflection vs speed"),
                        &members,
                        &legend,
                        &|c| if c == 0 { 0 } else { device_color([3, 7, 15, 31][(c - 1) % 4]) },
                    )
                })
                .collect()
        },
        headline,
    )?;
    data.lines.insert(0, "Discrete devices: critical speed and peak of each curve (refined on fresh runs).".into());
    Ok(data)
}

/// The critical speed without friction, and how much the best set of devices cuts its peak.
fn headline(curves: &Curves) -> Vec<String> {
    let none = curves.find("devices", 0.0);
    let best = curves.lowest_peak(0..curves.len());
    let cut = 1.0 - curves.peak(best) / curves.peak(none);
    vec![
        format!("Without friction the track's critical speed is {}.", curves.critical_text(none)),
        format!(
            "The best set, {} devices of {:.0} kN, cuts that peak by {:.0} % (critical speed {}).",
            curves.label(best, "devices"),
            curves.label(best, "device_force") / 1e3,
            100.0 * cut,
            curves.critical_text(best)
        ),
    ]
}
