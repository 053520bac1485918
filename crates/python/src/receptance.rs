//! `frictrack.receptance`: the track's receptance over frequency, as `frictrack receptance` computes it — its JSON
//! (points, resonances, warnings), its CSV and its text report — with the figure written where asked.

use crate::errors::to_python;
use crate::interruptible;
use crate::scenario_input::{Source, overrides};
use pyo3::prelude::*;
use report::output::Output;
use runner::Runner;
use study::receptance::{ReceptanceRequest, ReceptanceStudy};

/// The receptance's JSON, CSV, text report and warnings.
type ReceptanceTexts = (String, String, String, Vec<String>);

/// The receptance of the scenario (`kind`, `text`) with the keyword overrides at `frequencies` (Hz) for a force at
/// `excite` read at `at` (m; by default mid-track, and the point receptance), on `jobs` threads; with `out`, the
/// CSV, JSON and figure are written into that folder as the command line writes them.
#[pyfunction]
#[pyo3(signature = (kind, text, frequencies, at, excite, jobs, keywords, out=None))]
#[allow(clippy::too_many_arguments)] // Python's keywords, one each.
pub(crate) fn receptance(
    py: Python<'_>,
    kind: &str,
    text: Option<String>,
    frequencies: Vec<f64>,
    at: Option<f64>,
    excite: Option<f64>,
    jobs: usize,
    keywords: Vec<(String, Bound<'_, PyAny>)>,
    out: Option<std::path::PathBuf>,
) -> PyResult<ReceptanceTexts> {
    let scenario = overrides(&keywords)?.apply(Source::of(kind, text)?.read()?).map_err(to_python)?;
    let at = at.unwrap_or(0.5 * scenario.mesh.length);
    let request = ReceptanceRequest { frequencies, excite: excite.unwrap_or(at), at };
    if let Some(folder) = &out {
        study::receptance::text::check_folder(folder, "out").map_err(to_python)?;
    }
    let runner = Runner::new(jobs).map_err(to_python)?;
    let work = move |stop: &_, told: &interruptible::Progress| {
        let announce = |estimate: &runner::cost::Estimate| told.announce("frictrack.receptance", estimate);
        let study = ReceptanceStudy::of(&scenario, &request, &runner.with_stop(stop).with_estimate(&announce))?;
        if let Some(folder) = &out {
            study.write_folder(folder, "out")?;
        }
        Ok::<_, scenario::error::StudyError>(study)
    };
    let study = interruptible::run_reporting(py, None, work)?.map_err(to_python)?;
    let json = study.json().map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    Ok((json, study.csv(), study.text(), study.warnings.clone()))
}
