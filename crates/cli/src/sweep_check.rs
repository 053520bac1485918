//! `sweep --check-resolution`: the run at the speed of the sweep's peak (the refined critical speed with `--critical`,
//! else the speed of the largest max downward deflection) checked against its twins
//! ([`report::resolution_check::point`]); the twins are built at the first speed before the sweep starts, so that a
//! twin beyond the limits is refused before any work.

use anyhow::{Context, Result};
use report::resolution_check::point::PointCheck;
use runner::{CriticalSpeed, SweepPoint};

/// Refuse before the sweep a check whose twins cannot be built (at the sweep's first speed `speed`).
pub fn refuse_early(scenario: &scenario::Scenario, speed: f64) -> Result<()> {
    PointCheck::refuse_early(scenario, speed).context("--check-resolution: the twins at the sweep's speeds")
}

/// The check at the sweep's peak; None where no run finished. Progress and the check's lines on standard error
/// unless `quiet`.
pub fn at_peak(
    scenario: &scenario::Scenario,
    points: &[SweepPoint],
    critical: Option<&CriticalSpeed>,
    quiet: bool,
) -> Result<Option<PointCheck>> {
    let Some((speed, point)) = PointCheck::peak_of(points, critical) else { return Ok(None) };
    if !quiet {
        eprintln!("--check-resolution: checking the run at {point}, {speed:.2} m/s, against its twins");
    }
    let bars = crate::resolution_check::Bars::new(quiet);
    let stop = Some(crate::interrupt::stop_flag());
    let checked = PointCheck::at(scenario, speed, point, stop, &mut |t| bars.started(t), &|f| bars.progress(f));
    bars.close();
    let checked = crate::interrupt::explain(checked)?;
    if !quiet {
        eprint!("{}", checked.check);
    }
    Ok(Some(checked))
}
