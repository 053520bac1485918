//! `frictrack.sweep`: one run per speed on all cores (or `jobs` threads), as `frictrack sweep` — the CSV text it
//! writes, a failed run's row empty (its error in the returned failures).

use crate::errors::to_python;
use crate::interruptible;
use crate::scenario_input::{Source, overrides};
use pyo3::prelude::*;
use report::resolution_check::point::PointCheck;
use report::resolution_check::twins::Twin;
use runner::{Runner, failures, finished, write_csv_rows};

/// The sweep's CSV (`frictrack sweep`'s), the failed runs as (speed m/s, error) pairs, the warnings the command
/// line prints for the swept speeds, and with `check_resolution` the check at the sweep's peak (JSON).
type SweepTexts = (String, Vec<(f64, String)>, Vec<String>, Option<String>);

/// Sweep the scenario (`kind` and `text` as for `run`) with the keyword `overrides` over `speeds` (m/s) on `jobs`
/// worker threads (0: all cores), telling `progress` (a callable of the fraction of runs done), if given.
#[pyfunction]
#[pyo3(signature = (kind, text, speeds, jobs, keywords, progress=None, check_resolution=false))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn sweep(
    py: Python<'_>,
    kind: &str,
    text: Option<String>,
    speeds: Vec<f64>,
    jobs: usize,
    keywords: Vec<(String, Bound<'_, PyAny>)>,
    progress: Option<Bound<'_, PyAny>>,
    check_resolution: bool,
) -> PyResult<SweepTexts> {
    let scenario = overrides(&keywords)?.apply(Source::of(kind, text)?.read()?).map_err(to_python)?;
    scenario::speeds::check_count("speeds", speeds.len()).map_err(to_python)?;
    if speeds.is_empty() {
        return Err(to_python(scenario::error::invalid("speeds", "[]", "give at least one speed (m/s)")));
    }
    scenario.refuse_sweep_on_the_ground().map_err(to_python)?;
    let case = scenario.build().map_err(to_python)?;
    if check_resolution {
        // The twins at the first speed, built before any work: a twin beyond the limits is refused now.
        PointCheck::refuse_early(&scenario, speeds[0]).map_err(to_python)?;
    }
    let warnings = scenario::diagnostics::sweep_warnings(&scenario, &speeds).map_err(to_python)?;
    let warnings = warnings.iter().map(ToString::to_string).collect();
    let runner = Runner::new(jobs).map_err(to_python)?;
    let total = speeds.len() as f64;
    let (rows, checked) = interruptible::run_reporting(py, progress, move |stop, told| {
        let done = |runs: usize| told.set(runs as f64 / total);
        let announce = |estimate: &runner::cost::Estimate| told.announce("frictrack.sweep", estimate);
        let runner = runner.with_stop(stop).with_progress(&done).with_estimate(&announce);
        let rows = runner.speed_sweep_keeping(&case, &speeds)?;
        let peak =
            PointCheck::peak_of(&finished(&rows), None).filter(|_| check_resolution && failures(&rows).is_empty());
        let checked = match peak {
            Some((speed, point)) => {
                let mut started = |twin: &Twin| {
                    told.announce(&twin.label(), &runner::cost::Estimate::run(runner::cost::RunCost::of(&twin.case)));
                };
                Some(PointCheck::at(&scenario, speed, point, Some(stop), &mut started, &|f| told.set(f))?)
            }
            None => None,
        };
        Ok::<_, scenario::error::StudyError>((rows, checked))
    })?
    .map_err(to_python)?;
    let mut csv = Vec::new();
    write_csv_rows(&rows, &mut csv).map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    let failed = failures(&rows).into_iter().map(|f| (f.speed, f.error)).collect();
    let checked = checked
        .map(|c| serde_json::to_string(&c))
        .transpose()
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    Ok((String::from_utf8_lossy(&csv).into_owned(), failed, warnings, checked))
}

/// The sweep CSV's columns with their units: every column a sweep may write ([`runner::every_csv_column`]).
#[pyfunction]
pub(crate) fn sweep_columns() -> Vec<(&'static str, &'static str)> {
    runner::every_csv_column().map(|(n, u, _)| (*n, *u)).collect()
}
