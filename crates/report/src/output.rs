//! One way every result reaches a reader: a result the command line prints and Python returns implements
//! [`Output`] once — its text report, its JSON and, where it has one, its table as CSV — and [`render`] gives the
//! form asked for. The CLI prints what [`render`] returns; Python's functions hand back the same JSON and text.

use serde::Serialize;
use std::fmt::{self, Display, Formatter};
use thiserror::Error;

/// The forms a result can be given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// The report a person reads.
    Text,
    /// The result's values, with the names of every JSON file (SI units).
    Json,
    /// The result's table, one row per point, with a closing `# units:` line.
    Csv,
}

/// Why a result cannot be given in a form.
#[derive(Debug, Error)]
pub enum OutputError {
    /// CSV asked of a result that has no table.
    #[error("this result has no table to give as CSV; allowed: text, json")]
    NoTable,
    /// The JSON could not be written (a map with keys that are not strings: a bug, not bad input).
    #[error("cannot write the result as JSON: {0}")]
    Json(#[from] serde_json::Error),
}

/// A result that can be reported.
pub trait Output {
    /// The text report, line by line, each ended by a newline.
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result;

    /// The result's values as JSON.
    fn json(&self) -> serde_json::Result<String>;

    /// The result's table as CSV with its units line, where it has one.
    fn csv(&self) -> Option<String> {
        None
    }

    /// The text report as a string.
    fn text(&self) -> String
    where
        Self: Sized,
    {
        Text(self).to_string()
    }
}

/// The pretty-printed JSON of a value: what [`Output::json`] is for a result that is its own JSON.
pub fn pretty<T: Serialize + ?Sized>(value: &T) -> serde_json::Result<String> {
    serde_json::to_string_pretty(value)
}

/// `output` in `format`, ending in a newline: what the command line prints.
pub fn render(output: &dyn Output, format: Format) -> Result<String, OutputError> {
    match format {
        Format::Text => Ok(Text(output).to_string()),
        Format::Json => Ok(output.json()? + "\n"),
        Format::Csv => output.csv().ok_or(OutputError::NoTable),
    }
}

/// The text report of a result, as a [`Display`].
pub struct Text<'a>(pub &'a dyn Output);

impl Display for Text<'_> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        self.0.write_text(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A result with two numbers and no table.
    #[derive(Serialize)]
    struct Pair {
        a: f64,
        b: f64,
    }

    impl Output for Pair {
        fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
            writeln!(f, "a = {}", self.a)?;
            writeln!(f, "b = {}", self.b)
        }
        fn json(&self) -> serde_json::Result<String> {
            pretty(self)
        }
    }

    #[test]
    fn each_form_ends_in_a_newline_and_a_missing_table_is_refused() {
        let pair = Pair { a: 1.5, b: -2.0 };
        assert_eq!(render(&pair, Format::Text).unwrap(), "a = 1.5\nb = -2\n");
        assert_eq!(pair.text(), "a = 1.5\nb = -2\n");
        let json = render(&pair, Format::Json).unwrap();
        assert!(json.ends_with("}\n"), "{json}");
        assert_eq!(serde_json::from_str::<serde_json::Value>(&json).unwrap()["b"], -2.0);
        let refused = render(&pair, Format::Csv).unwrap_err().to_string();
        assert!(refused.contains("no table") && refused.contains("text, json"), "{refused}");
    }
}
