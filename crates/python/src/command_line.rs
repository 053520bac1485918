//! The `frictrack` console script of the wheel (`frictrack._cli:main`): the command line of the `frictrack` crate,
//! run in this process.

use pyo3::prelude::*;
use std::ffi::OsString;

/// Run the command line `args` (`args[0]` the program's name) as the `frictrack` binary does, without the GIL, and
/// return its exit code (0, 1, 2 or 130; see `frictrack_cli::run_command_line`). For a process that runs this one
/// command: it installs the command's panic hook and Ctrl-C handler.
#[pyfunction]
pub(crate) fn command_line(py: Python<'_>, args: Vec<OsString>) -> u8 {
    py.detach(|| frictrack_cli::run_command_line(args))
}
