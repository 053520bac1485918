//! A warning about the input: a legitimate but suspicious value, named by its path in the scenario, with what it means
//! and the limit it crosses (the diagnostics' and the plausibility checks' one shape).

use std::fmt;

/// A suspicious input: the field, its value, and what is wrong with it against which limit.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// Dotted path in the scenario.
    pub field: String,
    /// The value, as text.
    pub value: String,
    /// What it means and the limit it crosses.
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}: {}", self.field, self.value, self.message)
    }
}
