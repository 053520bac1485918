//! # frictrack from Python (`frictrack._native`)
//!
//! A thin layer over the study library (docs/architecture.md): every function here reads a scenario with the
//! library's parser, applies overrides by the command line's names ([`scenario::overrides::Overrides`]), runs the
//! library and returns what the command line prints or writes — the run summary as the JSON of `frictrack run
//! --format json`, the tables as the CSV text of `histories.csv`, `snapshots.csv` and `wheels.csv`. The package's
//! Python side (`python/frictrack`) turns these into dicts and NumPy structured arrays; neither side holds
//! numerics or a schema of its own.
//!
//! Runs release the GIL and stop within a step when Python raises KeyboardInterrupt (Ctrl-C): the run goes on a
//! worker thread, the caller waits without the GIL and checks Python's signals every 50 ms. Errors the user can fix
//! raise `frictrack.InputError` (a `ValueError`) with the field, its value and what is allowed; nothing panics
//! across the boundary.
//!
//! The wheel's `frictrack` console script runs the command line itself in the Python process (`command_line`), so
//! `pip install frictrack` gives the same command as the binary without a second executable in the wheel.

#![allow(unsafe_code)] // PyO3's macros expand to the FFI's unsafe calls.

mod command_line;
mod commands;
mod errors;
mod ground;
mod interruptible;
mod receptance;
mod report;
mod run;
mod scenario_input;
mod sweep;

use pyo3::prelude::*;

/// The compiled half of the `frictrack` package.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InputError", m.py().get_type::<errors::InputError>())?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(run::override_names, m)?)?;
    m.add_function(wrap_pyfunction!(run::override_table, m)?)?;
    m.add_function(wrap_pyfunction!(run::trains, m)?)?;
    m.add_function(wrap_pyfunction!(run::columns, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_columns, m)?)?;
    m.add_function(wrap_pyfunction!(commands::analytic, m)?)?;
    m.add_function(wrap_pyfunction!(commands::stationary_wave, m)?)?;
    m.add_function(wrap_pyfunction!(commands::preset, m)?)?;
    m.add_function(wrap_pyfunction!(commands::train, m)?)?;
    m.add_function(wrap_pyfunction!(commands::track_profile, m)?)?;
    m.add_function(wrap_pyfunction!(receptance::receptance, m)?)?;
    m.add_function(wrap_pyfunction!(ground::ground, m)?)?;
    m.add_function(wrap_pyfunction!(command_line::command_line, m)?)?;
    m.add_function(wrap_pyfunction!(report::report_html, m)?)?;
    m.add_function(wrap_pyfunction!(report::write_report, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_input::parse_speed, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
