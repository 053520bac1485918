//! How close a run is to its converged answer (`run --check-resolution`, docs/theory.md §6.1): every outcome the run
//! reports, beside the same outcome on the run's twins at other resolutions — one twin with elements and load advance
//! twice as long and one with them half as long (or, where the coarser twin cannot be built, two finer ones) — and its
//! error estimated from the three with the order they show ([`estimate`]).
//!
//! - [`accuracy`]: `run --accuracy TOL`, the run refined until every outcome's estimated error is within TOL;
//! - [`estimate`]: one outcome's error from three resolutions (observed order, Roache's safety factor, undefined where
//!   the values do not converge);
//! - [`outcomes`]: the outcomes of a run that are checked;
//! - [`point`]: the check at one point of a sweep (the speed of the peak it reports);
//! - [`twins`]: the twins built (before any work) and run;
//! - `text`: the check's lines in a run's text report.

pub mod accuracy;
pub mod estimate;
pub mod outcomes;
pub mod point;
mod text;
pub mod twins;

pub(crate) use text::{write_accuracy, write_check};

use crate::run_summary::RunSummary;
use estimate::{Convergence, Sequence};
use serde::Serialize;

impl Resolution {
    /// The resolution of `scenario`, whose run took `summary.wall_time`.
    pub fn of(scenario: &scenario::Scenario, summary: &RunSummary) -> Self {
        Self {
            elements: scenario.mesh.elements,
            load_advance: scenario.integration.load_advance,
            wall_time: summary.wall_time,
        }
    }
}

/// One resolution of the check.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Resolution {
    /// Number of elements.
    pub elements: usize,
    /// Load advance per step (m).
    pub load_advance: f64,
    /// Wall time of this resolution's run (s).
    pub wall_time: f64,
}

/// One outcome at the three resolutions.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutcomeCheck {
    /// What it is, in the JSON's own name (`max_downward_deflection`, `window_max_upward_deflection`,
    /// `friction_dissipation`, …).
    pub name: String,
    /// Its SI unit.
    pub unit: &'static str,
    /// Its values at the three resolutions, coarsest first (the run's among them).
    pub values: [f64; 3],
    /// How they converge.
    pub convergence: Convergence,
    /// The run's estimated error (the outcome's unit); None where the values do not converge.
    pub error: Option<f64>,
    /// `error` relative to the run's |value|; None where either is undefined or the value is 0.
    pub relative: Option<f64>,
}

/// A run's outcomes against its twins.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResolutionCheck {
    /// The three resolutions, coarsest first.
    pub resolutions: [Resolution; 3],
    /// Which of them is the run (1 with a coarser twin, 0 with two finer ones).
    pub run: usize,
    /// Every outcome the run and its twins report, in the report's order.
    pub outcomes: Vec<OutcomeCheck>,
}

impl ResolutionCheck {
    /// The run's summaries at three resolutions, coarsest first, the run's at index `run`: every outcome all three
    /// report, with the run's error estimated.
    pub fn of(summaries: [&RunSummary; 3], resolutions: [Resolution; 3], run: usize) -> Self {
        let lists = summaries.map(outcomes::outcomes);
        let outcomes = lists[run]
            .iter()
            .filter_map(|(name, unit, _)| {
                let value_in = |list: &Vec<outcomes::Outcome>| list.iter().find(|o| o.0 == *name).map(|o| o.2);
                let values = [value_in(&lists[0])?, value_in(&lists[1])?, value_in(&lists[2])?];
                let sequence = Sequence(values);
                let error = sequence.error_of(run);
                let value = values[run];
                let relative = relative(error, value);
                Some(OutcomeCheck {
                    name: name.clone(),
                    unit,
                    values,
                    convergence: sequence.convergence(),
                    error,
                    relative,
                })
            })
            .collect();
        Self { resolutions, run, outcomes }
    }

    /// The check with `earlier`, the run's summary one halving coarser than the three: an outcome whose three values do
    /// not contract but spread over no more than the change from its earlier value is [`Convergence::Scattered`] about a floor,
    /// its error three times their spread ([`Sequence::scattered_error`]).
    pub fn with_earlier(mut self, earlier: &RunSummary) -> Self {
        let list = outcomes::outcomes(earlier);
        for o in &mut self.outcomes {
            let Some(value) = list.iter().find(|e| e.0 == o.name).map(|e| e.2) else { continue };
            if let Some(error) = Sequence(o.values).scattered_error(value) {
                o.convergence = Convergence::Scattered { earlier: value };
                o.error = Some(error);
                o.relative = relative(o.error, o.values[self.run]);
            }
        }
        self
    }

    /// The largest relative error estimated, and its outcome.
    pub fn worst(&self) -> Option<&OutcomeCheck> {
        self.outcomes
            .iter()
            .filter(|o| o.relative.is_some())
            .max_by(|a, b| a.relative.unwrap_or(0.0).total_cmp(&b.relative.unwrap_or(0.0)))
    }

    /// The outcomes whose error is undefined (they do not converge at these resolutions).
    pub fn undefined(&self) -> impl Iterator<Item = &OutcomeCheck> {
        self.outcomes.iter().filter(|o| o.error.is_none())
    }
}

/// `error` relative to |`value`|; None where the error is undefined or the value is 0.
fn relative(error: Option<f64>, value: f64) -> Option<f64> {
    error.filter(|_| value != 0.0).map(|e| e / value.abs())
}
