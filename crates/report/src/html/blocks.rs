//! The pieces a report page is made of: escaped text, numbers, tables, warnings, an inline SVG figure, the scenario
//! as TOML, a JSON summary's records as tables.

use scenario::error::{Result, StudyError};
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;

/// `text` with `& < > " '` escaped for HTML text and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A number as a reader wants it in a table: five significant digits, in scientific notation outside 1e-3…1e6
/// (integers as they are).
pub fn number(value: f64) -> String {
    if !value.is_finite() {
        return value.to_string();
    }
    if value.fract() == 0.0 && value.abs() < 1e9 {
        return format!("{value:.0}");
    }
    let magnitude = value.abs();
    if (1e-3..1e6).contains(&magnitude) {
        let decimals = (4 - magnitude.log10().floor() as i32).max(0) as usize;
        format!("{value:.decimals$}")
    } else {
        format!("{value:.4e}")
    }
}

/// A JSON scalar as table text (numbers by [`number`]); arrays and objects as compact JSON; null as "—".
pub fn scalar(value: &Value) -> String {
    match value {
        Value::Null => "—".into(),
        Value::Bool(b) => b.to_string(),
        Value::Number(n) => n.as_f64().map_or_else(|| n.to_string(), number),
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// A table with `header` cells and `rows` (already HTML); a cell that parses as a number is right-aligned.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    // Field names wrap at their underscores and dots (a wide table of snake_case names would not wrap at all).
    let mut out = String::from("<div class=\"table\"><table>\n<thead><tr>");
    for cell in header {
        let _ = write!(out, "<th>{}</th>", escape(cell).replace('_', "_<wbr>").replace('.', ".<wbr>"));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    for row in rows {
        out.push_str("<tr>");
        for cell in row {
            let class = if cell.parse::<f64>().is_ok() { " class=\"num\"" } else { "" };
            let _ = write!(out, "<td{class}>{cell}</td>");
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody>\n</table></div>\n");
    out
}

/// A file's columns — a JSON list of `{name, unit}`, as every result JSON lists them — as a (column, unit) table.
pub fn columns_table(columns: &Value) -> String {
    let text = |v: &Value| escape(v.as_str().unwrap_or(""));
    let rows: Vec<Vec<String>> = columns
        .as_array()
        .into_iter()
        .flatten()
        .map(|c| vec![format!("<code>{}</code>", text(&c["name"])), text(&c["unit"])])
        .collect();
    table(&["column", "unit"], &rows)
}

/// The warnings of a result as a highlighted list, or a line saying there were none.
pub fn warnings(list: &[String]) -> String {
    if list.is_empty() {
        return "<p class=\"none\">No warnings.</p>\n".into();
    }
    let items: String = list.iter().map(|w| format!("<li>{}</li>\n", escape(w))).collect();
    format!("<div class=\"warnings\" role=\"note\"><ul>\n{items}</ul></div>\n")
}

/// Preformatted text (a text report, a scenario).
pub fn pre(text: &str) -> String {
    format!("<pre>{}</pre>\n", escape(text.trim_end()))
}

/// The figure `folder/stem.svg` inline, captioned "Figure `number`: its title" (the title is the SVG's first text, as
/// drawn); an error names the file when it is missing or is not an SVG.
pub fn figure(folder: &Path, stem: &str, number: usize) -> Result<String> {
    let path = folder.join(format!("{stem}.svg"));
    let text = crate::files::read_text(&path)?;
    let start =
        text.find("<svg").filter(|_| text.trim_end().ends_with("</svg>")).ok_or_else(|| StudyError::InvalidField {
            path: path.display().to_string(),
            value: format!("{} bytes", text.len()),
            allowed: "an SVG figure as frictrack writes it (<svg …>…</svg>)".into(),
        })?;
    let title = first_text(&text[start..]).unwrap_or_else(|| stem.to_string());
    let svg = text[start..].replacen("<svg ", &format!("<svg role=\"img\" aria-label=\"{}\" ", escape(&title)), 1);
    Ok(format!(
        "<figure id=\"figure-{number}\">\n{svg}\n<figcaption>Figure {number}: {} (<code>{stem}.svg</code>)</figcaption>\n</figure>\n",
        escape(&title)
    ))
}

/// The content of the first `<text>` element of an SVG (a figure's title), unescaped of its entities.
fn first_text(svg: &str) -> Option<String> {
    let open = svg.find("<text")?;
    let body = &svg[open + svg[open..].find('>')? + 1..];
    let content = body[..body.find("</text>")?].trim();
    let content = [("&lt;", "<"), ("&gt;", ">"), ("&quot;", "\""), ("&apos;", "'"), ("&#39;", "'"), ("&amp;", "&")]
        .iter()
        .fold(content.to_string(), |text, (entity, c)| text.replace(entity, c));
    Some(content)
}

/// A scenario (the JSON of a result folder) as TOML, the format it is written in; keys without a value (null) are
/// left out, as a scenario file leaves them out.
pub fn scenario_toml(scenario: &Value) -> String {
    let table = match to_toml(scenario) {
        Some(toml::Value::Table(table)) => table,
        _ => return scenario.to_string(),
    };
    toml::to_string(&table).unwrap_or_else(|_| scenario.to_string())
}

/// A JSON value as TOML (nulls dropped; TOML has none).
fn to_toml(value: &Value) -> Option<toml::Value> {
    Some(match value {
        Value::Null => return None,
        Value::Bool(b) => toml::Value::Boolean(*b),
        Value::Number(n) => match n.as_i64() {
            Some(i) => toml::Value::Integer(i),
            None => toml::Value::Float(n.as_f64()?),
        },
        Value::String(s) => toml::Value::String(s.clone()),
        Value::Array(items) => toml::Value::Array(items.iter().filter_map(to_toml).collect()),
        Value::Object(map) => {
            toml::Value::Table(map.iter().filter_map(|(k, v)| Some((k.clone(), to_toml(v)?))).collect())
        }
    })
}

/// Each list of records in a JSON summary (an array of objects, at the top or one level down) as a table of its
/// scalar fields, headed by its name; the summary's own scalars as one (name, value) table. A field named as one of
/// `units`' columns (the study's CSV columns) is headed with its unit.
pub fn summary_tables(summary: &Value, units: &[(String, String)]) -> String {
    let Some(map) = summary.as_object() else { return pre(&summary.to_string()) };
    let mut out = String::new();
    let scalars: Vec<Vec<String>> = map
        .iter()
        .filter(|(_, v)| !v.is_array() && !v.is_object())
        .map(|(k, v)| {
            let unit = if v.is_number() { unit_of_field(k, units).unwrap_or_default() } else { String::new() };
            vec![format!("<code>{}</code>", escape(k)), escape(&scalar(v)), escape(&unit)]
        })
        .collect();
    if !scalars.is_empty() {
        out.push_str(&table(&["quantity", "value", "unit"], &scalars));
    }
    for (name, value) in map {
        match value {
            Value::Array(records) if records.iter().all(Value::is_object) && !records.is_empty() => {
                out.push_str(&records_table(name, records, units));
            }
            Value::Object(inner) => {
                for (sub, value) in inner {
                    if let Value::Array(records) = value
                        && !records.is_empty()
                        && records.iter().all(Value::is_object)
                    {
                        out.push_str(&records_table(&format!("{name}.{sub}"), records, units));
                    }
                }
            }
            _ => {}
        }
    }
    out
}

/// One list of records as a table: a column per field (in the first record's order, then any others'), lists
/// inside a record shown by their length — and each list of records inside them as a table of its own, its rows
/// led by the text fields of the record they belong to (a curve's rail, support and place before its resonances).
fn records_table(name: &str, records: &[Value], units: &[(String, String)]) -> String {
    let mut out = flat_table(name, records, units);
    let mut nested: Vec<&str> = Vec::new();
    for record in records.iter().filter_map(Value::as_object) {
        for (key, value) in record {
            if value.as_array().is_some_and(|a| !a.is_empty() && a.iter().all(Value::is_object))
                && !nested.contains(&key.as_str())
            {
                nested.push(key);
            }
        }
    }
    for key in nested {
        let rows: Vec<Value> = records
            .iter()
            .filter_map(Value::as_object)
            .flat_map(|parent| {
                let labels: serde_json::Map<String, Value> =
                    parent.iter().filter(|(_, v)| v.is_string()).map(|(k, v)| (k.clone(), v.clone())).collect();
                parent.get(key).and_then(Value::as_array).into_iter().flatten().filter_map(Value::as_object).map(
                    move |child| {
                        let mut row = labels.clone();
                        row.extend(
                            child.iter().filter(|(_, v)| !v.is_array()).map(|(k, v)| (format!("{key}.{k}"), v.clone())),
                        );
                        Value::Object(row)
                    },
                )
            })
            .collect();
        out.push_str(&flat_table(&format!("{name} → {key}"), &rows, units));
    }
    out
}

/// The unit of a summary's numeric field: the study's CSV column of that name, else the longest listed quantity
/// (`scenario::quantities`) its name ends with, read past a trailing `_sampled` or `_refined` (how it was found, not
/// what it is): `neighbour_ballast_force_speed` is a speed, `min_wheel_force` a force,
/// `peak_max_upward_deflection_sampled` a deflection. None for a count, a ratio (`acceleration_over_limit`), or a
/// name that ends in no listed quantity: a unit left out is better than a wrong one.
fn unit_of_field(field: &str, units: &[(String, String)]) -> Option<String> {
    let listed = units.iter().find(|(name, _)| name == field).map(|(_, unit)| unit.clone());
    let by_quantity = || {
        let name = field.strip_suffix("_sampled").or_else(|| field.strip_suffix("_refined")).unwrap_or(field);
        let words: Vec<&str> = name.split('_').collect();
        (0..words.len()).find_map(|i| scenario::quantities::unit_of(&words[i..].join("_")).map(String::from))
    };
    listed.or_else(by_quantity).filter(|unit| unit != "1" && unit != "text")
}

/// One list of records as a table of their fields (lists inside shown by their length).
fn flat_table(name: &str, records: &[Value], units: &[(String, String)]) -> String {
    // A field that is itself a record of scalars (an extreme's value, position and time) becomes a column each,
    // `field.part`, rather than its JSON in one cell.
    let flattened: Vec<Value> = records.iter().map(flattened).collect();
    let records = flattened.as_slice();
    let mut columns: Vec<&str> = Vec::new();
    for record in records.iter().filter_map(Value::as_object) {
        for key in record.keys() {
            if !columns.contains(&key.as_str()) {
                columns.push(key);
            }
        }
    }
    let rows: Vec<Vec<String>> = records
        .iter()
        .map(|r| {
            columns
                .iter()
                .map(|c| match r.get(*c) {
                    Some(Value::Array(items)) => format!("{} item(s)", items.len()),
                    Some(v) => escape(&scalar(v)),
                    None => "—".into(),
                })
                .collect()
        })
        .collect();
    // A unit heads a column of numbers only (`critical_speed_location` holds words).
    let numeric =
        |column: &str| records.iter().filter_map(|r| r.get(column)).filter(|v| !v.is_null()).all(Value::is_number);
    let unit = |column: &str| {
        // `x.value` carries x's unit; `x.position` a position's.
        let mut parts = column.rsplit('.');
        let field = match (parts.next(), parts.next()) {
            (Some("value"), Some(parent)) => parent,
            (Some(last), _) => last,
            (None, _) => column,
        };
        let unit = unit_of_field(field, units).filter(|_| numeric(column));
        unit.map_or_else(|| column.to_string(), |unit| format!("{column} ({unit})"))
    };
    let header: Vec<String> = columns.iter().map(|c| unit(c)).collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    format!("<h4><code>{}</code></h4>\n{}", escape(name), table(&header, &rows))
}

/// `record` with each field that is an object of scalars spread into fields `field.part` (nulls left out).
fn flattened(record: &Value) -> Value {
    let Some(map) = record.as_object() else { return record.clone() };
    let mut out = serde_json::Map::new();
    for (key, value) in map {
        match value {
            Value::Object(inner) if inner.values().all(|v| !v.is_array() && !v.is_object()) => {
                for (part, v) in inner.iter().filter(|(_, v)| !v.is_null()) {
                    out.insert(format!("{key}.{part}"), v.clone());
                }
            }
            _ => {
                out.insert(key.clone(), value.clone());
            }
        }
    }
    Value::Object(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_five_significant_digits() {
        assert_eq!(number(200.0), "200");
        assert_eq!(number(0.505_744_928), "0.50574");
        assert_eq!(number(205.573_271), "205.57");
        assert_eq!(number(-4.307e-9), "-4.3070e-9");
        assert_eq!(number(548_424.538), "548425");
        assert_eq!(number(f64::NAN), "NaN");
    }

    #[test]
    fn a_figure_title_is_read_back_unescaped_and_escaped_again() {
        let svg = "<svg x=\"1\"><rect/><text x=\"2\">\nThe track&apos;s &lt;receptance&gt; &amp; phase\n</text></svg>";
        assert_eq!(first_text(svg).as_deref(), Some("The track's <receptance> & phase"));
        assert_eq!(escape("a<b & 'c'"), "a&lt;b &amp; &#39;c&#39;");
    }

    #[test]
    fn the_scenario_reads_as_toml_without_its_empty_keys() {
        let json = serde_json::json!({"title": "", "load": {"speed": 150.0, "train": null}, "mesh": {"elements": 200}});
        let toml = scenario_toml(&json);
        assert!(toml.contains("[load]\nspeed = 150.0") && toml.contains("[mesh]\nelements = 200"), "{toml}");
        assert!(!toml.contains("train"));
    }

    #[test]
    fn nested_records_get_a_table_led_by_their_parent() {
        let summary =
            serde_json::json!({"curves": [{"rail": "EB", "resonances": [{"frequency": 110.1}, {"frequency": 411.4}]}]});
        let html = summary_tables(&summary, &[("frequency".into(), "Hz".into())]);
        assert!(html.contains("curves → resonances"), "{html}");
        assert!(
            html.contains("resonances.<wbr>frequency (Hz)") && html.contains("<td class=\"num\">411.40</td>"),
            "{html}"
        );
        assert_eq!(html.matches("<td>EB</td>").count(), 3, "the parent's row and one led row per resonance");
    }

    #[test]
    fn a_field_takes_the_unit_of_the_quantity_it_ends_with() {
        let csv = [("gap".to_string(), "m".to_string())];
        assert_eq!(unit_of_field("gap", &csv).as_deref(), Some("m"));
        assert_eq!(unit_of_field("neighbour_ballast_force_speed", &csv).as_deref(), Some("m/s"));
        assert_eq!(unit_of_field("min_wheel_force", &csv).as_deref(), Some("N"));
        assert_eq!(unit_of_field("peak_deflection", &csv).as_deref(), Some("m"));
        assert_eq!(unit_of_field("peak_max_upward_deflection_sampled", &csv).as_deref(), Some("m"));
        assert_eq!(unit_of_field("dynamic_amplification", &csv), None, "a ratio has none");
        assert_eq!(unit_of_field("acceleration_over_limit", &csv), None, "a utilisation, not an acceleration");
        assert_eq!(unit_of_field("voided", &csv), None);
    }
}
