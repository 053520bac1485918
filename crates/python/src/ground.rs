//! `frictrack.ground`: the scenario's composite beam on its `[ground]`, as `frictrack ground` computes it — its JSON
//! (dispersion, critical speeds, speeds, k_eq), its CSV (the fundamental mode) and its text report, with the tables
//! and figures written where asked.

use crate::errors::to_python;
use crate::interruptible;
use crate::scenario_input::Source;
use pyo3::prelude::*;
use report::output::Output;
use runner::Runner;
use study::ground::{GroundRequest, GroundStudy};

/// The ground's JSON, CSV, text report and warnings.
type GroundTexts = (String, String, String, Vec<String>);

/// The ground of the scenario (`kind`, `text`) at `frequencies` (Hz; by default 1 to 50 by 1), on `jobs` threads;
/// with `out`, its files are written into that folder as the command line writes them.
#[pyfunction]
#[pyo3(signature = (kind, text, frequencies, jobs, out=None))]
pub(crate) fn ground(
    py: Python<'_>,
    kind: &str,
    text: Option<String>,
    frequencies: Option<Vec<f64>>,
    jobs: usize,
    out: Option<std::path::PathBuf>,
) -> PyResult<GroundTexts> {
    let scenario = Source::of(kind, text)?.read()?;
    let request = frequencies.map_or_else(GroundRequest::default, |frequencies| GroundRequest { frequencies });
    if let Some(folder) = &out {
        study::ground::text::check_folder(folder, "out").map_err(to_python)?;
    }
    let runner = Runner::new(jobs).map_err(to_python)?;
    let work = move |stop: &_, told: &interruptible::Progress| {
        let announce = |estimate: &runner::cost::Estimate| told.announce("frictrack.ground", estimate);
        let study = GroundStudy::of(&scenario, &request, &runner.with_stop(stop).with_estimate(&announce))?;
        if let Some(folder) = &out {
            study.write_folder(folder, "out")?;
        }
        Ok::<_, scenario::error::StudyError>(study)
    };
    let study = interruptible::run_reporting(py, None, work)?.map_err(to_python)?;
    let json = study.json().map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    let csv = study.csv().unwrap_or_default();
    Ok((json, csv, study.text(), study.warnings.clone()))
}
