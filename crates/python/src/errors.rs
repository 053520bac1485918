//! The library's errors as Python exceptions: the user's input as `InputError` (a `ValueError`), an interrupted run
//! as `KeyboardInterrupt`, anything else (a run that failed numerically, a file that could not be written) as
//! `RuntimeError` — each with the library's message.

use pyo3::create_exception;
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use scenario::error::StudyError;

create_exception!(
    frictrack,
    InputError,
    PyValueError,
    "Bad input: the message names the field (its dotted path in the scenario, or the keyword), its value and what is \
     allowed."
);

/// `error` as the Python exception that says what it is.
pub(crate) fn to_python(error: StudyError) -> PyErr {
    match error {
        StudyError::Interrupted => PyKeyboardInterrupt::new_err("the run was interrupted"),
        e if e.is_invalid_input() => InputError::new_err(e.to_string()),
        e => PyRuntimeError::new_err(e.to_string()),
    }
}
