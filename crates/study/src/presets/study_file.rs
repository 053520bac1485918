//! The JSON a study writes beside its CSV (`study NAME --out DIR` writes `DIR/NAME.json`).

use super::preset::Preset;
use super::resolution::Resolution;
use super::study_data::{StudyData, StudyFailure, StudySummary};
use report::provenance::Provenance;
use scenario::Scenario;
use scenario::error::Result;
use serde::Serialize;

/// The JSON a study writes beside its CSV (`study NAME --out DIR` writes `DIR/NAME.json`): what ran, how long, its
/// typed summary and lines, its figures, the scenario with the speeds and sets the study used and the parts of it
/// the study does not use, its columns with units and its failed runs.
#[derive(Debug, Clone, Serialize)]
pub struct StudyFile<'a> {
    /// The preset's name.
    pub study: &'static str,
    /// Its title.
    pub title: &'static str,
    /// "coarse" or "paper".
    pub resolution: &'static str,
    /// Simulations run.
    pub runs: usize,
    /// The solvers' work.
    pub solver_statistics: SolverStatisticsNote,
    /// Wall time of the study (s).
    pub wall_time: f64,
    /// The command, version, commit and date (flattened: `command`, `frictrack_version`, `git_revision`, `date`).
    #[serde(flatten)]
    pub provenance: &'a Provenance,
    /// What the scenario gave warning of, as the command line printed it.
    pub warnings: &'a [String],
    /// The two sentences of the study's report section.
    pub headline: &'a [String],
    /// The typed summary.
    pub summary: &'a StudySummary,
    /// The summary in lines.
    pub lines: &'a [String],
    /// The figures' file stems.
    pub plots: Vec<&'a str>,
    /// The figures' titles, in the order of `plots`.
    pub plot_titles: Vec<&'a str>,
    /// The scenario it ran on (without the `[foundation]` a `[ground]` replaces): the base scenario, or the first of
    /// the study's own where it brings them ([`StudyData::ran_on`]).
    pub scenario: scenario::AsRan<'a>,
    /// The study's other scenarios of its own, after [`Self::scenario`]; empty for a study on the base scenario.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub more_scenarios: Vec<scenario::AsRan<'a>>,
    /// The speeds it swept (m/s), where one list serves every curve.
    pub speeds: Option<Vec<f64>>,
    /// What the study sets itself.
    pub study_sets: &'static [&'static str],
    /// The parts of the scenario it does not use.
    pub scenario_parts_not_used: Vec<String>,
    /// Name and unit of each CSV column.
    pub columns: Vec<report::columns::ColumnMeta>,
    /// The runs that failed.
    pub failures: &'a [StudyFailure],
}

/// The mean work of the step solver over a study.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SolverStatisticsNote {
    /// Mean friction-solver iterations per step over the study's sweep runs.
    pub mean_iterations_per_step: f64,
}

impl StudyData {
    /// The JSON beside this study's CSV: these results of `preset` at `resolution` on `base`, with the parts of
    /// `base` it does not use (`Preset::overrides`, which the caller has already told the user) and its `warnings`,
    /// run in `wall_time` s by the command of `provenance`.
    pub fn file<'a>(
        &'a self,
        (preset, resolution, base): (Preset, Resolution, &'a Scenario),
        (scenario_parts_not_used, warnings): (Vec<String>, &'a [String]),
        (wall_time, provenance): (f64, &'a Provenance),
    ) -> Result<StudyFile<'a>> {
        Ok(StudyFile {
            study: self.name,
            title: self.title,
            resolution: self.resolution,
            runs: self.runs,
            solver_statistics: SolverStatisticsNote { mean_iterations_per_step: self.mean_iterations },
            wall_time,
            provenance,
            warnings,
            headline: &self.headline,
            summary: &self.summary,
            lines: &self.lines,
            plots: self.plots.iter().map(|p| p.stem.as_str()).collect(),
            plot_titles: self.plots.iter().map(|p| p.title.as_str()).collect(),
            scenario: scenario::AsRan(self.ran_on.first().unwrap_or(base)),
            more_scenarios: self.ran_on.iter().skip(1).map(scenario::AsRan).collect(),
            speeds: preset.speeds(resolution, base)?,
            study_sets: preset.sets(),
            scenario_parts_not_used,
            columns: report::columns::listed(self.columns.iter().map(|(name, unit)| (name.as_str(), *unit))),
            failures: &self.failures,
        })
    }
}
