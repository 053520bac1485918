//! # report: what a run or a sweep reports, as typed values, files and figures (docs/theory.md §7–§12)
//!
//! - [`output`]: one way every result reaches a reader — its text report, JSON and CSV ([`output::Output`]);
//!   [`run_text`] is a run's text report, [`window_wording`] how it names the extremes window.
//! - [`run_summary`]: one run's typed summary — what ran, extremes, static envelope and amplification, energy
//!   ledger, solver statistics, vehicles, soil — the names of `run --format json`; [`result_warnings`]: a result
//!   outside the model's validity.
//! - [`run_output`], [`vehicle_output`], [`soil_output`]: a run's histories, snapshots, wheels and lift-off as CSV
//!   and figures, written into its folder by [`run_folder`]; [`mesh_ripple`]: the element period in a wheel force.
//! - [`files`]: result files checked before any work starts and written atomically, never over a link or device.
//! - [`sweep_figures`]: the figures of a speed sweep, and its CSV read back; [`sweep_file`]: the JSON beside it; [`tables`]: reading CSV files back;
//!   [`columns`]: one convention for the units of every column.
//! - [`html`]: a run, study or `reproduce` folder as one self-contained HTML report; [`provenance`]: the command,
//!   version, commit and date a result folder records.
//! - [`track_profile`]: a sample of a random rail profile with its periodogram against the target spectrum.
//! - [`plot`] (with [`axis_grid`], [`typeset`] and the common figure shapes of [`figures`]): line plots as PNG and
//!   SVG, drawn with plotters and a bundled DejaVu font. Colours by configuration in [`palette`].

pub mod axis_grid;
pub mod columns;
pub mod figures;
pub mod files;
pub mod html;
pub mod mesh_ripple;
pub mod output;
pub mod palette;
pub mod plot;
mod plot_text;
pub mod provenance;
pub mod resolution_check;
pub mod result_warnings;
pub mod run_folder;
pub mod run_output;
pub mod run_summary;
pub mod run_text;
pub mod sleeper_output;
pub mod snapshot_zoom;
pub mod soil_output;
pub mod sweep_figures;
pub mod sweep_file;
pub mod tables;
pub mod track_profile;
pub mod train_listing;
pub mod typeset;
pub mod vehicle_output;
pub mod window_wording;
