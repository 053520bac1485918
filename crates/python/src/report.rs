//! `frictrack.report(dir)` and `Run.report_html()`: a result folder as one self-contained HTML file, as `frictrack
//! report DIR [--out FILE]` writes it ([`report::html`]).

use crate::errors::to_python;
use pyo3::prelude::*;
use std::path::PathBuf;

/// The report of the result folder `folder` as HTML text.
#[pyfunction]
pub(crate) fn report_html(py: Python<'_>, folder: PathBuf) -> PyResult<String> {
    py.detach(|| report::html::report_html(&folder)).map_err(to_python)
}

/// Write the report of `folder` to `out` (default `folder/report.html`); the path written.
#[pyfunction]
#[pyo3(signature = (folder, out=None))]
pub(crate) fn write_report(py: Python<'_>, folder: PathBuf, out: Option<PathBuf>) -> PyResult<PathBuf> {
    py.detach(|| report::html::write_report(&folder, out.as_deref(), "out")).map_err(to_python)
}
