//! What a study produces — its CSV, typed summary, lines, headline, figures — and the runs that failed.

use report::plot::PlotSpec;
use runner::SweepRow;
use scenario::error::{Result, StudyError};
use serde::Serialize;
use std::sync::Arc;

/// What a study produces.
#[derive(Debug, Clone, Serialize)]
pub struct StudyData {
    /// Preset name.
    pub name: &'static str,
    /// Title.
    pub title: &'static str,
    /// Resolution name.
    pub resolution: &'static str,
    /// The data, CSV with a header line.
    #[serde(skip)]
    pub csv: String,
    /// Machine-readable summary (critical speeds, peaks, optimal forces…), typed per study.
    pub summary: StudySummary,
    /// Human-readable summary lines, one per curve or case.
    pub lines: Vec<String>,
    /// Two sentences saying what the study shows, for reports.
    pub headline: Vec<String>,
    /// The figures.
    pub plots: Vec<PlotSpec>,
    /// Number of simulations run.
    pub runs: usize,
    /// Mean friction-solver iterations per step over the study's sweep runs (solver statistics).
    pub mean_iterations: f64,
    /// The CSV's columns with their units, in order.
    pub columns: Vec<(String, &'static str)>,
    /// The scenarios the study ran on where they are its own (a built-in site), not the base scenario; empty for
    /// a study on the base scenario.
    #[serde(skip)]
    pub ran_on: Vec<scenario::Scenario>,
    /// The runs that failed; every other run is in the data (a failed run's CSV row, where the study writes one,
    /// has its case and speed with the values empty).
    pub failures: Vec<StudyFailure>,
}

/// What a study found, typed by the study that found it: each preset's own summary (its curves' critical speeds,
/// optima, verdicts), written with its names (`study --format json`, `<study>.json`); null for a study that has
/// none. The registry names no study's type: any serialisable summary is one ([`StudySummary::of`]).
#[derive(Clone, Default)]
pub struct StudySummary(Option<Arc<dyn Summary>>);

/// A study's typed summary, as [`StudySummary`] holds it.
pub trait Summary: erased_serde::Serialize + std::fmt::Debug + Send + Sync {}

impl<T: Serialize + std::fmt::Debug + Send + Sync> Summary for T {}

erased_serde::serialize_trait_object!(Summary);

impl StudySummary {
    /// The summary `summary` of a study.
    pub fn of(summary: impl Summary + 'static) -> Self {
        Self(Some(Arc::new(summary)))
    }

    /// No summary (null).
    pub fn none() -> Self {
        Self(None)
    }
}

impl Serialize for StudySummary {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        match &self.0 {
            Some(summary) => summary.as_ref().serialize(serializer),
            None => serializer.serialize_none(),
        }
    }
}

impl std::fmt::Debug for StudySummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.0 {
            Some(summary) => summary.fmt(f),
            None => f.write_str("None"),
        }
    }
}

impl StudyData {
    /// These results, run on the study's own `scenarios` (a built-in site) rather than the base scenario: the
    /// scenarios its file reports as the ones it ran on.
    pub fn ran_on(self, scenarios: Vec<scenario::Scenario>) -> Self {
        Self { ran_on: scenarios, ..self }
    }

    /// The summary as a JSON reader sees it (`study --format json`, `<study>.json`).
    pub fn summary_json(&self) -> serde_json::Value {
        serde_json::to_value(&self.summary).unwrap_or(serde_json::Value::Null)
    }
}

/// The failed runs of a family of sweeps (`rows[c]` the sweep of the case called `name(c)`), in order.
pub(super) fn failed_runs(rows: &[Vec<SweepRow>], name: impl Fn(usize) -> String) -> Vec<StudyFailure> {
    let failed = |(c, curve): (usize, &Vec<SweepRow>)| {
        let name = name(c);
        runner::failures(curve).into_iter().map(move |f| StudyFailure {
            case: name.clone(),
            speed: Some(f.speed),
            error: f.error,
        })
    };
    rows.iter().enumerate().flat_map(failed).collect()
}

/// The finished results of a study's runs, each with its index, in order; each failed run is recorded in
/// `failures` under the case and speed `name(i)` gives it.
pub(super) fn keep_finished<R>(
    results: Vec<Result<R>>,
    name: impl Fn(usize) -> (String, Option<f64>),
    failures: &mut Vec<StudyFailure>,
) -> Vec<(usize, R)> {
    let mut kept = Vec::with_capacity(results.len());
    for (i, result) in results.into_iter().enumerate() {
        match result {
            Ok(r) => kept.push((i, r)),
            Err(e) => {
                let (case, speed) = name(i);
                failures.push(StudyFailure { case, speed, error: e.to_string() });
            }
        }
    }
    kept
}

/// The error of a study (or a curve) `case` of which every run failed, naming the first failure of that case.
pub(super) fn nothing_finished(case: String, failures: &[StudyFailure]) -> StudyError {
    let first = failures.iter().find(|f| f.case == case).or(failures.first());
    StudyError::CurveFailed { case, first: first.map_or(String::new(), |f| f.error.clone()) }
}

/// A run of a study that failed: which case, at which speed, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyFailure {
    /// The case, by the values that set it apart ("devices = 31, device_force = 50000").
    pub case: String,
    /// Load speed (m/s) of the failed run; None for a failed refinement of a critical speed.
    pub speed: Option<f64>,
    /// The error, as text.
    pub error: String,
}
