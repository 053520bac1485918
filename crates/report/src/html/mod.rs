//! # A result folder as one self-contained HTML file (`frictrack report DIR`, `frictrack.report(dir)`)
//!
//! - [`folder`]: which folder it is — a run's, a study's, `reproduce`'s, another command's — and which page shows it.
//! - [`run_page`], [`study_page`], [`command_page`]: what each page shows (tables, verdicts, warnings, figures,
//!   scenario, data).
//! - [`sources`]: what a page reads of the folder besides its tables (figures in order, where the results came
//!   from).
//! - [`blocks`]: the pieces (escaped text, numbers, tables, inline SVG, the scenario as TOML);
//!   [`page`]: the document, its table of contents and its screen and print styles.

pub mod blocks;
pub mod command_page;
pub mod folder;
pub mod page;
pub mod resolution_table;
pub mod run_page;
pub mod sources;
pub mod study_page;

use crate::files::{check_output_file, write_atomically};
use folder::ResultFolder;
use scenario::error::Result;
use std::path::{Path, PathBuf};

/// The report of the result folder `folder` as HTML text.
pub fn report_html(folder: &Path) -> Result<String> {
    Ok(ResultFolder::read(folder)?.page(folder)?.html())
}

/// Write the report of `folder` to `out` (default `folder/report.html`): the folder is read first (a folder of no
/// results is refused by name), then `out` checked (never written through a link or onto a device) and written
/// atomically; `option` names where `out` was given in an error. Returns the path written.
pub fn write_report(folder: &Path, out: Option<&Path>, option: &str) -> Result<PathBuf> {
    let html = report_html(folder)?;
    let out = out.map_or_else(|| folder.join("report.html"), Path::to_path_buf);
    check_output_file(option, &out)?;
    write_atomically(&out, html.as_bytes())?;
    Ok(out)
}
