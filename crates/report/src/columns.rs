//! The one units convention of frictrack's tables: every number in SI units (m, s, N, N·m, J, W, m/s, m/s², rad);
//! column names are snake_case quantities without units (the JSON keys of the same quantities); and every column's
//! unit is written with the table — in the JSON written beside the CSV (`columns`: name and unit, a run folder's
//! `summary.json` under `files.<csv>.columns`), in Python's tables (`units`, pandas `attrs["units"]`), and, for a CSV
//! printed on standard output, in a comment line after the data (`# units (SI): …`, [`units_line`]; pandas reads
//! past it with `comment="#"`).

use serde::{Deserialize, Serialize};

/// A column of a table: its name and its SI unit ("1" for counts and ratios, "text" for words).
pub type Column = (&'static str, &'static str);

/// The CSV header of `columns`: their names, comma-separated.
pub fn header(columns: &[Column]) -> String {
    columns.iter().map(|(name, _)| *name).collect::<Vec<_>>().join(",")
}

/// A column as the JSON beside its CSV lists it: `{"name": …, "unit": …}`, with what it means where the file says.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ColumnMeta {
    /// The column's name in the CSV header.
    pub name: String,
    /// Its SI unit.
    pub unit: String,
    /// What it is, in words (a sweep's columns).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub meaning: Option<String>,
}

/// `columns` as the JSON beside their CSV lists them.
pub fn listed<'a>(columns: impl IntoIterator<Item = (&'a str, &'a str)>) -> Vec<ColumnMeta> {
    columns.into_iter().map(|(name, unit)| ColumnMeta { name: name.into(), unit: unit.into(), meaning: None }).collect()
}

/// `columns` as [`listed`], each name once (the first of its kind kept): the units list of a JSON whose tables
/// share columns.
pub fn listed_once<'a>(columns: impl IntoIterator<Item = (&'a str, &'a str)>) -> Vec<ColumnMeta> {
    let mut seen: Vec<&str> = Vec::new();
    listed(columns.into_iter().filter(|(name, _)| {
        let new = !seen.contains(name);
        seen.push(name);
        new
    }))
}

/// The units of `columns` in one line, for a CSV printed on standard output (after a `#`): "units (SI): speed m/s,
/// status text, …".
pub fn units_line<'a>(columns: impl IntoIterator<Item = (&'a str, &'a str)>) -> String {
    let list: Vec<String> = columns.into_iter().map(|(name, unit)| format!("{name} {unit}")).collect();
    format!("units (SI): {}", list.join(", "))
}

#[cfg(test)]
mod tests {
    use super::{header, listed, units_line};

    #[test]
    fn header_json_and_units_line_say_the_same_columns() {
        let columns = [("speed", "m/s"), ("max_moment", "N·m")];
        assert_eq!(header(&columns), "speed,max_moment");
        let json = serde_json::to_value(listed(columns)).unwrap();
        assert_eq!(json[1], serde_json::json!({ "name": "max_moment", "unit": "N·m" }));
        assert_eq!(units_line(columns), "units (SI): speed m/s, max_moment N·m");
    }
}
