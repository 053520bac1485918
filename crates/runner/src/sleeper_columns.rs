//! What a sweep point reports of the sleepers (docs/theory.md §18): the largest pad and ballast forces where the
//! results are read, and, where some sleepers differ (`[[sleepers.exceptions]]`), the largest ballast force under
//! them and under their neighbours — the sleepers beside a voided one carry what it does not — and how low they went.

use fem_beam::BeamModel;
use scenario::quantities::unit;
use serde::{Deserialize, Serialize};
use track::simulation::SleeperResults;

/// The sleepers' columns of a sweep point. Forces in N (compression positive), positions in m (downward positive).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SleeperColumns {
    /// Largest pad force over the sleepers where the results are read.
    pub max_pad_force: f64,
    /// Largest ballast force over the sleepers where the results are read.
    pub max_ballast_force: f64,
    /// Largest ballast force under a sleeper of an exception; None without exceptions.
    pub exception_ballast_force: Option<f64>,
    /// Largest ballast force under a sleeper next to an exception's range (not itself one); None without.
    pub neighbour_ballast_force: Option<f64>,
    /// The lowest a sleeper of an exception went; None without exceptions.
    pub exception_lowest: Option<f64>,
}

/// The sleepers' columns of sweep output, after the vehicles' (when a sweep runs on sleepers): name, unit, meaning.
pub const SLEEPER_CSV_COLUMNS: [(&str, &str, &str); 5] = [
    ("max_pad_force", unit("max_pad_force"), "largest rail-pad force where the results are read (compression)"),
    (
        "max_ballast_force",
        unit("max_ballast_force"),
        "largest ballast force under a sleeper where the results are read",
    ),
    (
        "exception_ballast_force",
        unit("exception_ballast_force"),
        "largest ballast force under a sleeper of [[sleepers.exceptions]]",
    ),
    (
        "neighbour_ballast_force",
        unit("neighbour_ballast_force"),
        "largest ballast force under a sleeper next to the exceptions",
    ),
    ("exception_lowest", unit("exception_lowest"), "the lowest a sleeper of the exceptions went (downward)"),
];

impl SleeperColumns {
    /// The columns of `results`, a run on `model`'s sleepers, read over the sleepers at `read` = (a, b) m (all
    /// without).
    pub fn of(model: &BeamModel, results: &SleeperResults, read: Option<(f64, f64)>) -> Self {
        let inside = |x: f64| read.is_none_or(|(a, b)| (a..=b).contains(&x));
        let sleepers = &results.sleepers;
        let largest = |values: &mut dyn Iterator<Item = f64>| values.fold(0.0, f64::max);
        let exceptional: Vec<bool> = match model.sleepers() {
            Some((s, _)) => (0..sleepers.len()).map(|i| s.differs(i)).collect(),
            None => vec![false; sleepers.len()],
        };
        let neighbour = |i: usize| {
            !exceptional[i] && ((i > 0 && exceptional[i - 1]) || exceptional.get(i + 1).copied().unwrap_or(false))
        };
        let over = |keep: &dyn Fn(usize) -> bool, value: fn(&track::simulation::SleeperPeaks) -> f64| {
            let mut values = sleepers.iter().enumerate().filter(|(i, _)| keep(*i)).map(|(_, p)| value(p)).peekable();
            values.peek().is_some().then(|| values.fold(0.0, f64::max))
        };
        Self {
            max_pad_force: largest(&mut sleepers.iter().filter(|p| inside(p.x)).map(|p| p.pad_force.0)),
            max_ballast_force: largest(&mut sleepers.iter().filter(|p| inside(p.x)).map(|p| p.ballast_force.0)),
            exception_ballast_force: over(&|i| exceptional[i], |p| p.ballast_force.0),
            neighbour_ballast_force: over(&neighbour, |p| p.ballast_force.0),
            exception_lowest: over(&|i| exceptional[i], |p| p.lowest),
        }
    }

    /// The values in the order of [`SLEEPER_CSV_COLUMNS`] (NaN, an empty field, where absent).
    pub fn values(&self) -> [f64; 5] {
        let or_gap = |v: Option<f64>| v.unwrap_or(f64::NAN);
        [
            self.max_pad_force,
            self.max_ballast_force,
            or_gap(self.exception_ballast_force),
            or_gap(self.neighbour_ballast_force),
            or_gap(self.exception_lowest),
        ]
    }
}
