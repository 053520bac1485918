//! `run --accuracy TOL` (docs/theory.md §6.2): the run refined — elements and load advance halved together — until
//! the estimated error of every outcome it reports is within TOL of its value, each error estimated from the last
//! three resolutions as [`super::estimate`] does; the answer is the finest run's, with its check. Where the next
//! resolution is beyond the model's limits or [`LEVEL_SECONDS`], it stops and says which outcomes did not reach TOL.
//!
//! It starts one halving *below* the scenario's resolution where that twin can be built (a quarter of a run's cost),
//! so that the scenario's own resolution and one finer already give the first estimate; light ballast friction on
//! the default law runs one section a node ([`scenario::accuracy_law`]: as accurate, and cheaper).

use super::twins::Twin;
use super::{Resolution, ResolutionCheck};
use crate::run_summary::RunSummary;
use scenario::accuracy_law::AccuracyLaw;
use scenario::error::{Result, StudyError};
use scenario::{Case, Scenario};
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;
use track::{RunResult, Snapshot, SnapshotAt};

/// The longest estimated run of one resolution `run --accuracy` starts (s): beyond it, it stops and says so.
pub const LEVEL_SECONDS: f64 = 1200.0;

pub use scenario::accuracy_key::validate_tolerance;

/// Whether the refinement reached its tolerance.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum AccuracyStatus {
    /// Every outcome's estimated error is within the tolerance.
    Reached,
    /// It stopped before: `why`, and the outcomes whose error is above the tolerance or undefined.
    NotReached {
        /// Why it stopped (the next resolution's size or cost).
        why: String,
        /// The outcomes not within the tolerance.
        outcomes: Vec<String>,
    },
    /// Stopped by Ctrl-C or SIGTERM: the finest resolution finished is the answer; `outcomes` are not within the
    /// tolerance there.
    Interrupted {
        /// The outcomes not within the tolerance.
        outcomes: Vec<String>,
    },
}

impl AccuracyStatus {
    /// Whether the refinement was interrupted.
    pub fn interrupted(&self) -> bool {
        matches!(self, Self::Interrupted { .. })
    }
}

/// What `--accuracy` came to: the tolerance asked, whether it was reached, the resolutions run and their cost.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Accuracy {
    /// The relative error asked for.
    pub tolerance: f64,
    /// Reached or not, and why.
    pub status: AccuracyStatus,
    /// The outcomes that diverge under refinement (over the last four resolutions their differences keep one sign
    /// and do not shrink, [`DIVERGING_GROWTH`]): undefined, left out of the tolerance.
    pub diverging: Vec<String>,
    /// The law of the ballast friction it ran (chosen for the accuracy or the scenario's own); None without ballast
    /// friction.
    pub law: Option<AccuracyLaw>,
    /// Every resolution run, coarsest first (the answer is the last's).
    pub resolutions: Vec<Resolution>,
    /// Wall time of all of them (s).
    pub wall_time: f64,
}

/// The finest run of a refinement: what a run folder is written from, its summary holding the check and the
/// accuracy.
pub struct Refined {
    /// Its scenario (the given one at the finest resolution).
    pub scenario: Scenario,
    /// Its case.
    pub case: Case,
    /// Its results.
    pub result: RunResult,
    /// Its snapshots.
    pub snapshots: Vec<Snapshot>,
    /// Its summary, with `resolution_check` and `accuracy`.
    pub summary: RunSummary,
}

/// The finest resolution run so far, whole: its twin, results and snapshots (the coarser ones keep their summaries
/// only).
struct Finest {
    twin: Twin,
    result: RunResult,
    snapshots: Vec<Snapshot>,
}

/// A difference of one sign that does not shrink — grows by this factor or more — twice in a row diverges: a sequence
/// converging at any order p > 0 has differences that shrink by 2⁻ᵖ each halving.
pub const DIVERGING_GROWTH: f64 = 1.0;

/// Whether four values, each at a resolution a halving finer than the last, diverge: their differences keep one
/// sign and do not shrink ([`DIVERGING_GROWTH`]) from one halving to the next.
pub fn diverges(q: [f64; 4]) -> bool {
    let d = [q[1] - q[0], q[2] - q[1], q[3] - q[2]];
    d[0] * d[1] > 0.0
        && d[1] * d[2] > 0.0
        && d[1].abs() >= DIVERGING_GROWTH * d[0].abs()
        && d[2].abs() >= DIVERGING_GROWTH * d[1].abs()
}

/// The outcomes of the last summaries (coarsest first) that diverge under refinement: over the last four
/// resolutions their differences keep one sign and do not shrink ([`DIVERGING_GROWTH`]).
fn diverging(summaries: &[RunSummary]) -> Vec<String> {
    let Some(four) = summaries.len().checked_sub(4).map(|from| &summaries[from..]) else { return Vec::new() };
    let lists: Vec<Vec<super::outcomes::Outcome>> = four.iter().map(super::outcomes::outcomes).collect();
    lists[3]
        .iter()
        .filter(|(name, _, _)| {
            let values: Option<Vec<f64>> = lists.iter().map(|l| l.iter().find(|o| o.0 == *name).map(|o| o.2)).collect();
            values.is_some_and(|q| diverges([q[0], q[1], q[2], q[3]]))
        })
        .map(|(name, _, _)| name.clone())
        .collect()
}

/// The outcomes of `check` (the finest at index 2) not within `tolerance`, leaving out those `diverging`.
fn outside(check: &ResolutionCheck, tolerance: f64, diverging: &[String]) -> Vec<String> {
    let within = |o: &super::OutcomeCheck| o.error.is_some_and(|e| e <= tolerance * o.values[2].abs());
    check.outcomes.iter().filter(|o| !within(o) && !diverging.contains(&o.name)).map(|o| o.name.clone()).collect()
}

/// What is not within the tolerance before three resolutions have run: every outcome.
fn too_few() -> Vec<String> {
    vec!["every outcome (fewer than three resolutions ran)".to_string()]
}

/// The twin of `scenario` `level` halvings finer, built, if it is within the limits and `level_seconds`; else why
/// not (`Ok(Err(why))`). An interruption while it is built (a ground fitted) is the error.
fn next(scenario: &Scenario, level: i32, level_seconds: f64) -> Result<std::result::Result<Twin, String>> {
    let twin = match Twin::built(scenario, level) {
        Ok(twin) => twin,
        Err(StudyError::Interrupted) => return Err(StudyError::Interrupted),
        Err(e) => return Ok(Err(format!("the next resolution cannot be built: {e}"))),
    };
    let seconds = runner::cost::RunCost::of(&twin.case).seconds;
    Ok(match seconds <= level_seconds {
        true => Ok(twin),
        false => Err(format!(
            "the next resolution ({} elements, load advance {} m) would take ~{seconds:.1} s, beyond {level_seconds} s",
            twin.scenario.mesh.elements, twin.scenario.integration.load_advance
        )),
    })
}

/// How far a refinement goes: the relative error asked for, and the longest estimated run of one resolution it
/// starts (s; [`LEVEL_SECONDS`] for `run --accuracy`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    /// The relative error asked for, in (0, 1).
    pub tolerance: f64,
    /// The longest estimated run of one resolution it starts (s).
    pub level_seconds: f64,
}

/// Refine `scenario` until every outcome is within `target.tolerance` (relative): each level `started`, its progress
/// to `progress`, stoppable by `stop`; `requests` gives a level's snapshot requests.
pub fn refine(
    scenario: &Scenario,
    target: Target,
    requests: &dyn Fn(&Scenario, &Case) -> Vec<SnapshotAt>,
    stop: Option<&AtomicBool>,
    started: &mut dyn FnMut(&Twin),
    progress: &dyn Fn(f64),
) -> Result<Refined> {
    let Target { tolerance, level_seconds } = target;
    validate_tolerance("accuracy", tolerance)?;
    let begun = Instant::now();
    let (cheaper, law) = scenario.with_accuracy_law().unzip();
    let scenario = match (&cheaper, law) {
        (Some(cheaper), Some(law)) if law.chosen => cheaper,
        _ => scenario,
    };
    let mut twin = first(scenario)?;
    let mut done = Done { resolutions: Vec::new(), summaries: Vec::new(), tolerance, law, begun };
    let mut last: Option<Finest> = None;
    loop {
        started(&twin);
        let start = Instant::now();
        let asked = requests(&twin.scenario, &twin.case);
        let (result, snapshots) = match crate::run_output::run_with_snapshots(&twin.case, &asked, stop, progress) {
            Err(StudyError::Interrupted) if last.is_some() => {
                let finest = last.take().expect("a finished resolution");
                return Ok(done.finish(finest, |outcomes| AccuracyStatus::Interrupted { outcomes }));
            }
            ran => ran?,
        };
        let summary = RunSummary::of(&twin.scenario, &twin.case, &result, start)?;
        done.resolutions.push(Resolution::of(&twin.scenario, &summary));
        done.summaries.push(summary);
        let finest = Finest { twin, result, snapshots };
        if done.reached() {
            return Ok(done.finish(finest, |_| AccuracyStatus::Reached));
        }
        twin = match next(scenario, finest.twin.level + 1, level_seconds)? {
            Ok(twin) => twin,
            Err(why) => return Ok(done.finish(finest, |outcomes| AccuracyStatus::NotReached { why, outcomes })),
        };
        last = Some(finest);
    }
}

/// The first resolution of a refinement of `scenario`, built: one halving coarser where that twin can be built (a
/// quarter of a run), else the resolution given.
fn first(scenario: &Scenario) -> Result<Twin> {
    match Twin::built(scenario, -1) {
        Ok(coarser) => Ok(coarser),
        Err(StudyError::Interrupted) => Err(StudyError::Interrupted),
        Err(_) => Twin::built(scenario, 0),
    }
}

/// The resolutions a refinement has run, coarsest first, and what it aims at.
struct Done {
    resolutions: Vec<Resolution>,
    summaries: Vec<RunSummary>,
    tolerance: f64,
    law: Option<AccuracyLaw>,
    begun: Instant,
}

impl Done {
    /// The check of the last three resolutions, the finest the run, with the one before them where it ran (a floor
    /// of scatter told from values that do not converge); None before three have run.
    fn check(&self) -> Option<ResolutionCheck> {
        let from = self.summaries.len().checked_sub(3)?;
        let (s, r) = (&self.summaries[from..], &self.resolutions[from..]);
        let check = ResolutionCheck::of([&s[0], &s[1], &s[2]], [r[0].clone(), r[1].clone(), r[2].clone()], 2);
        Some(match from.checked_sub(1) {
            Some(earlier) => check.with_earlier(&self.summaries[earlier]),
            None => check,
        })
    }

    /// The outcomes not yet within the tolerance of `check` (the last three resolutions'), those `diverging` left out:
    /// no refinement brings them in.
    fn not_within(&self, check: Option<&ResolutionCheck>, diverging: &[String]) -> Vec<String> {
        check.map_or_else(too_few, |c| outside(c, self.tolerance, diverging))
    }

    /// Whether every outcome is within the tolerance (or diverging).
    fn reached(&self) -> bool {
        self.not_within(self.check().as_ref(), &diverging(&self.summaries)).is_empty()
    }

    /// The finest run `finest` as the answer, with its check and the accuracy, whose status `status` makes of the
    /// outcomes not within the tolerance.
    fn finish(mut self, finest: Finest, status: impl FnOnce(Vec<String>) -> AccuracyStatus) -> Refined {
        let (check, diverging) = (self.check(), diverging(&self.summaries));
        let status = status(self.not_within(check.as_ref(), &diverging));
        let mut summary = self.summaries.pop().expect("at least one resolution ran");
        summary.resolution_check = check;
        summary.accuracy = Some(Accuracy {
            tolerance: self.tolerance,
            status,
            diverging,
            law: self.law,
            resolutions: self.resolutions,
            wall_time: self.begun.elapsed().as_secs_f64(),
        });
        let Finest { twin, result, snapshots } = finest;
        Refined { scenario: twin.scenario, case: twin.case, result, snapshots, summary }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_whose_differences_double_diverge_and_shrinking_or_turning_ones_do_not() {
        // The step acceleration under ballast friction: 1954, 3983, 7935 m/s² at 1600, 3200, 6400 elements.
        assert!(diverges([1000.0, 1954.0, 3983.0, 7935.0]));
        // With one section a node: 1983, 4279, 7587, 11 092 m/s² at 1600 to 12 800 elements (growing by ~3300 each).
        assert!(diverges([1983.0, 4279.0, 7587.0, 11_092.0]));
        assert!(!diverges([1.0, 1.5, 1.75, 1.875]), "converging at first order");
        assert!(!diverges([1.0, 1.1, 1.3, 1.2]), "turning back");
        assert!(!diverges([1.0, 1.3, 1.5, 1.65]), "shrinking slowly");
        assert!(!diverges([1.0, 1.0, 1.0, 1.0]));
    }
}
