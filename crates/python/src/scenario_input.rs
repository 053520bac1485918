//! A scenario as Python gives it — a TOML file's path, a TOML string, a dict (passed as JSON), or none (the
//! reference case) — read by the library's parser, with keyword overrides by the command line's names on top.

use crate::errors::to_python;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use scenario::Scenario;
use scenario::overrides::{OverrideSpec, OverrideValue, Overrides};

/// Where the scenario comes from.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Source {
    /// The reference case.
    Reference,
    /// A TOML file.
    Path(String),
    /// TOML text.
    Toml(String),
    /// A dict, as JSON.
    Json(String),
}

impl Source {
    /// From the Python side's (kind, text): kind "reference", "path", "toml" or "json".
    pub(crate) fn of(kind: &str, text: Option<String>) -> PyResult<Self> {
        let text = || text.clone().ok_or_else(|| PyTypeError::new_err(format!("a {kind} scenario needs its text")));
        Ok(match kind {
            "reference" => Source::Reference,
            "path" => Source::Path(text()?),
            "toml" => Source::Toml(text()?),
            "json" => Source::Json(text()?),
            other => return Err(PyTypeError::new_err(format!("unknown scenario kind {other}"))),
        })
    }

    /// The scenario, read and parsed.
    pub(crate) fn read(&self) -> PyResult<Scenario> {
        match self {
            Source::Reference => Ok(Scenario::default()),
            Source::Path(path) => Scenario::from_path(std::path::Path::new(path)).map_err(to_python),
            Source::Toml(text) => Scenario::from_toml(text, "scenario (TOML string)").map_err(to_python),
            Source::Json(text) => Scenario::from_json(text, "scenario (dict)").map_err(to_python),
        }
    }
}

/// The overrides `keywords` ((name, value) pairs, in order) as the library's; a keyword given as None leaves the
/// scenario's value, as an absent one does.
pub(crate) fn overrides(keywords: &[(String, Bound<'_, PyAny>)]) -> PyResult<Overrides> {
    let mut overrides = Overrides::default();
    for (name, value) in keywords {
        let spec = OverrideSpec::named(name).map_err(to_python)?;
        if value.is_none() {
            continue;
        }
        overrides.set(name, value_of(spec, value)?).map_err(to_python)?;
    }
    Ok(overrides)
}

/// A Python value as an override's: a number, text, or a pair of numbers. Booleans are refused (True is 1 in Python
/// and would pass for a count); anything else is refused with what `spec` takes.
fn value_of(spec: &OverrideSpec, value: &Bound<'_, PyAny>) -> PyResult<OverrideValue> {
    let refuse = |what: &str| to_python(scenario::error::invalid(spec.name, what, spec.takes()));
    if value.is_instance_of::<pyo3::types::PyBool>() {
        return Err(refuse("a boolean"));
    }
    if let Ok(text) = value.extract::<String>() {
        return Ok(OverrideValue::Text(text));
    }
    if let Ok(number) = value.extract::<f64>() {
        return Ok(OverrideValue::Number(number));
    }
    if let Ok([a, b]) = value.extract::<[f64; 2]>() {
        return Ok(OverrideValue::Pair([a, b]));
    }
    Err(refuse(&value.get_type().name().map_or_else(|_| "a value".into(), |n| n.to_string())))
}

/// A speed in m/s from a number's text with its unit (`"144km/h"`, `"40m/s"`), as the command line and `speed=`
/// take it; refused as `InputError` naming `name`.
#[pyfunction]
pub(crate) fn parse_speed(name: &str, text: &str) -> PyResult<f64> {
    let quoted = format!("\"{text}\"");
    scenario::units::parse_speed(text).map_err(|why| to_python(scenario::error::invalid(name, quoted, why)))
}
