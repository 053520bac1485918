//! The twins of a resolution check: built (and their sizes checked) before the run starts, then run after it.
//!
//! The twins are the scenario one halving coarser and one halving finer ([`Scenario::twin`]), so that the check costs
//! about 4¼ times the run (the finer twin has twice the elements and twice the steps); where the coarser twin cannot
//! be built (an odd number of elements, sleepers or devices its nodes cannot hold, a mesh below the model's limits),
//! the twins are one and two halvings finer, about 20 times the run.

use super::{Resolution, ResolutionCheck};
use crate::run_summary::RunSummary;
use scenario::error::{Result, StudyError};
use scenario::{Case, Scenario};
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// One twin: how many halvings finer than the run (−1: one coarser), its scenario and its built case.
pub struct Twin {
    /// Halvings finer than the run.
    pub level: i32,
    /// Its scenario.
    pub scenario: Scenario,
    /// Its case, built.
    pub case: Case,
}

impl Twin {
    /// The twin of `scenario` `level` halvings finer, built.
    pub(crate) fn built(scenario: &Scenario, level: i32) -> Result<Self> {
        let twin = scenario.twin(level)?;
        let case = twin.build()?;
        Ok(Self { level, scenario: twin, case })
    }

    /// How the twin is named in progress lines: "the coarser twin (40 elements, load advance 0.2 m)".
    pub fn label(&self) -> String {
        let which = match self.level {
            -1 => "the coarser twin".to_string(),
            0 => "the resolution given".to_string(),
            1 => "the finer twin".to_string(),
            n => format!("the twin {n} halvings finer"),
        };
        format!(
            "{which} ({} elements, load advance {} m)",
            self.scenario.mesh.elements, self.scenario.integration.load_advance
        )
    }
}

/// The two twins of a run's resolution check.
pub struct Twins(pub [Twin; 2]);

impl Twins {
    /// The twins of `scenario`, built: one coarser and one finer where the coarser can be built, else two finer.
    /// The error is the finer twin's (its size beyond the limits, say); a coarser twin's is no error.
    pub fn of(scenario: &Scenario) -> Result<Self> {
        let finer = |level: i32| Twin::built(scenario, level);
        let pair = match Twin::built(scenario, -1) {
            Ok(coarser) => [coarser, finer(1)?],
            Err(StudyError::Interrupted) => return Err(StudyError::Interrupted),
            Err(_) => [finer(1)?, finer(2)?],
        };
        Ok(Self(pair))
    }

    /// Which of the three resolutions is the run's: 1 beside a coarser twin, 0 below two finer ones.
    pub fn run_index(&self) -> usize {
        usize::from(self.0[0].level < 0)
    }

    /// Run both twins (each `started` first, its progress to `progress`, stoppable by `stop`), and the check of the
    /// run `run` (of `scenario`) against them.
    pub fn check(
        &self,
        scenario: &Scenario,
        run: &RunSummary,
        stop: Option<&AtomicBool>,
        started: &mut dyn FnMut(&Twin),
        progress: &dyn Fn(f64),
    ) -> Result<ResolutionCheck> {
        let mut summaries = Vec::with_capacity(2);
        for twin in &self.0 {
            started(twin);
            let start = Instant::now();
            let (result, _) = crate::run_output::run_with_snapshots(&twin.case, &[], stop, progress)?;
            summaries.push(RunSummary::of(&twin.scenario, &twin.case, &result, start)?);
        }
        let resolution = Resolution::of;
        let ([a, b], [ta, tb]) = ([&summaries[0], &summaries[1]], [&self.0[0], &self.0[1]]);
        let (all, resolutions) = match self.run_index() {
            1 => ([a, run, b], [resolution(&ta.scenario, a), resolution(scenario, run), resolution(&tb.scenario, b)]),
            _ => ([run, a, b], [resolution(scenario, run), resolution(&ta.scenario, a), resolution(&tb.scenario, b)]),
        };
        Ok(ResolutionCheck::of(all, resolutions, self.run_index()))
    }
}
