//! `run --accuracy TOL` (docs/theory.md §6.2): the run refined — elements and load advance halved together — until
//! the estimated error of every outcome it reports is within TOL of its value, each error estimated from the last
//! three resolutions as [`super::estimate`] does; the answer is the finest run's, with its check. Where the next
//! resolution is beyond the model's limits or [`LEVEL_SECONDS`], it stops and says which outcomes did not reach TOL.
//!
//! It starts one halving *below* the scenario's resolution where that twin can be built (a quarter of a run's cost),
//! so that the scenario's own resolution and one finer already give the first estimate.

use super::twins::Twin;
use super::{Resolution, ResolutionCheck};
use crate::run_summary::RunSummary;
use scenario::error::{Result, StudyError, invalid};
use scenario::{Case, Scenario};
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;
use track::{RunResult, Snapshot, SnapshotAt};

/// The longest estimated run of one resolution `run --accuracy` starts (s): beyond it, it stops and says so.
pub const LEVEL_SECONDS: f64 = 1200.0;

/// Whether `tolerance` (given as `name`) is a relative error the refinement can aim at: finite, in (0, 1).
pub fn validate_tolerance(name: &str, tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0 {
        Ok(())
    } else {
        Err(invalid(name, tolerance, "a relative error in (0, 1): 0.01 asks for every outcome within 1 %"))
    }
}

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

/// One resolution run: its twin (level, scenario, case) and its summary, result and snapshots.
struct Level {
    twin: Twin,
    summary: RunSummary,
    result: RunResult,
    snapshots: Vec<Snapshot>,
}

/// The outcomes of `check` (the finest at index 2) not within `tolerance`.
fn outside(check: &ResolutionCheck, tolerance: f64) -> Vec<String> {
    let within = |o: &super::OutcomeCheck| o.error.is_some_and(|e| e <= tolerance * o.values[2].abs());
    check.outcomes.iter().filter(|o| !within(o)).map(|o| o.name.clone()).collect()
}

/// What is not within the tolerance before three resolutions have run: every outcome.
fn too_few() -> Vec<String> {
    vec!["every outcome (fewer than three resolutions ran)".to_string()]
}

/// The twin of `scenario` `level` halvings finer, built, if it is within the limits and `level_seconds`; else why
/// not.
fn next(scenario: &Scenario, level: i32, level_seconds: f64) -> std::result::Result<Twin, String> {
    let twin = Twin::built(scenario, level).map_err(|e| match e {
        StudyError::Interrupted => "interrupted".to_string(),
        e => format!("the next resolution cannot be built: {e}"),
    })?;
    let seconds = runner::cost::RunCost::of(&twin.case).seconds;
    match seconds <= level_seconds {
        true => Ok(twin),
        false => Err(format!(
            "the next resolution ({} elements, load advance {} m) would take ~{seconds:.1} s, beyond {level_seconds} s",
            twin.scenario.mesh.elements, twin.scenario.integration.load_advance
        )),
    }
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
    let first = if Twin::built(scenario, -1).is_ok() { -1 } else { 0 };
    let mut levels: Vec<Level> = Vec::new();
    let mut twin = Twin::built(scenario, first)?;
    loop {
        started(&twin);
        let start = Instant::now();
        let asked = requests(&twin.scenario, &twin.case);
        let (result, snapshots) = match crate::run_output::run_with_snapshots(&twin.case, &asked, stop, progress) {
            Err(StudyError::Interrupted) if !levels.is_empty() => {
                let check = (levels.len() >= 3).then(|| check_of(&levels[levels.len() - 3..]));
                let outcomes = check.as_ref().map_or_else(too_few, |c| outside(c, tolerance));
                return Ok(finish(levels, check, tolerance, AccuracyStatus::Interrupted { outcomes }, begun));
            }
            ran => ran?,
        };
        let summary = RunSummary::of(&twin.scenario, &twin.case, &result, start)?;
        levels.push(Level { twin, summary, result, snapshots });
        let check = (levels.len() >= 3).then(|| check_of(&levels[levels.len() - 3..]));
        let not_within = check.as_ref().map_or_else(too_few, |c| outside(c, tolerance));
        if not_within.is_empty() {
            return Ok(finish(levels, check, tolerance, AccuracyStatus::Reached, begun));
        }
        twin = match next(scenario, levels.last().map_or(0, |l| l.twin.level + 1), level_seconds) {
            Ok(twin) => twin,
            Err(why) if why == "interrupted" => return Err(StudyError::Interrupted),
            Err(why) => {
                let status = AccuracyStatus::NotReached { why, outcomes: not_within };
                return Ok(finish(levels, check, tolerance, status, begun));
            }
        };
    }
}

/// The check of three successive levels, the finest the run.
fn check_of(three: &[Level]) -> ResolutionCheck {
    let resolution = |l: &Level| Resolution::of(&l.twin.scenario, &l.summary);
    ResolutionCheck::of(
        [&three[0].summary, &three[1].summary, &three[2].summary],
        [resolution(&three[0]), resolution(&three[1]), resolution(&three[2])],
        2,
    )
}

/// The finest level as the answer, with its check and the accuracy.
fn finish(
    mut levels: Vec<Level>,
    check: Option<ResolutionCheck>,
    tolerance: f64,
    status: AccuracyStatus,
    begun: Instant,
) -> Refined {
    let resolutions = levels.iter().map(|l| Resolution::of(&l.twin.scenario, &l.summary)).collect();
    let finest = levels.pop().expect("at least one level ran");
    let mut summary = finest.summary;
    summary.resolution_check = check;
    summary.accuracy = Some(Accuracy { tolerance, status, resolutions, wall_time: begun.elapsed().as_secs_f64() });
    Refined {
        scenario: finest.twin.scenario,
        case: finest.twin.case,
        result: finest.result,
        snapshots: finest.snapshots,
        summary,
    }
}
