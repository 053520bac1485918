//! A resolution check at one point of a sweep or study: the scenario run at the speed of the peak it reports (the
//! refined critical speed, or the speed of the largest deflection), and that run checked against its twins — what
//! `sweep --check-resolution` adds (docs/theory.md §6.1).

use super::ResolutionCheck;
use super::twins::{Twin, Twins};
use crate::run_summary::RunSummary;
use scenario::Scenario;
use scenario::error::Result;
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// The check at one point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointCheck {
    /// The speed checked (m/s).
    pub speed: f64,
    /// Which point it is, in words ("the refined critical speed", "the largest max downward deflection").
    pub point: String,
    /// The run at that speed against its twins.
    pub check: ResolutionCheck,
}

impl PointCheck {
    /// The point of a sweep to check: the refined critical speed where there is one, else the speed of the largest
    /// max downward deflection of the finished `points` (m/s, and the point in words); None without any.
    pub fn peak_of(
        points: &[runner::SweepPoint],
        critical: Option<&runner::CriticalSpeed>,
    ) -> Option<(f64, &'static str)> {
        if let Some(c) = critical {
            return Some((c.speed, "the refined critical speed"));
        }
        let largest = |a: &&runner::SweepPoint, b: &&runner::SweepPoint| {
            a.deflection.max_downward.value.total_cmp(&b.deflection.max_downward.value)
        };
        points.iter().max_by(largest).map(|p| (p.speed, "the speed of the largest max downward deflection"))
    }

    /// Refuse, before a sweep starts, a check whose twins cannot be built: they are built at its first speed `speed`
    /// (m/s) and dropped.
    pub fn refuse_early(scenario: &Scenario, speed: f64) -> Result<()> {
        Twins::of(&at_speed(scenario, speed)).map(|_| ())
    }

    /// `scenario` at `speed` (m/s; the point named `point`), its twins built before the run, then run — each run
    /// `started` first, its progress to `progress`, stoppable by `stop`.
    pub fn at(
        scenario: &Scenario,
        speed: f64,
        point: &str,
        stop: Option<&AtomicBool>,
        started: &mut dyn FnMut(&Twin),
        progress: &dyn Fn(f64),
    ) -> Result<Self> {
        let at_speed = at_speed(scenario, speed);
        let twins = Twins::of(&at_speed)?;
        let run = Twin::built(&at_speed, 0)?;
        started(&run);
        let start = Instant::now();
        let (result, _) = crate::run_output::run_with_snapshots(&run.case, &[], stop, progress)?;
        let summary = RunSummary::of(&at_speed, &run.case, &result, start)?;
        let check = twins.check(&at_speed, &summary, stop, started, progress)?;
        Ok(Self { speed, point: point.to_string(), check })
    }
}

/// `scenario` with its load at `speed` (m/s).
fn at_speed(scenario: &Scenario, speed: f64) -> Scenario {
    let mut at = scenario.clone();
    at.load.speed = speed;
    at
}
