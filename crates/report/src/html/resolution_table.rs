//! A run page's "How close it is" section: the resolution check of `run --check-resolution` or `--accuracy` as a
//! table — each outcome at the three resolutions, the run's estimated error and how the values converge — and, with
//! `--accuracy`, whether the tolerance was reached.

use super::blocks::{escape, number, table};
use serde_json::Value;

/// The section's HTML, or None where the run was not checked.
pub fn resolution_section(report: &Value) -> Option<String> {
    let check = report.get("resolution_check").filter(|c| c.is_object())?;
    let run = check["run"].as_u64().unwrap_or(0) as usize;
    let resolutions: Vec<String> = check["resolutions"]
        .as_array()
        .into_iter()
        .flatten()
        .enumerate()
        .map(|(i, r)| {
            let own = if i == run { " (the run)" } else { "" };
            // As the JSON writes them (0.05, not 0.050000).
            format!("{} × {} m{own}", r["elements"], r["load_advance"])
        })
        .collect();
    let mut html = format!(
        "<p>Each outcome at three resolutions (elements × load advance: {}) and the run's estimated discretisation \
         error, from the order of convergence the three show (Richardson × 1.25 in the asymptotic range, three times \
         their spread elsewhere; undefined where they do not converge).</p>\n",
        escape(&resolutions.join(", "))
    );
    if let Some(line) = accuracy_line(&report["accuracy"]) {
        html.push_str(&format!("<p>{}</p>\n", escape(&line)));
    }
    let rows: Vec<Vec<String>> = check["outcomes"].as_array().into_iter().flatten().map(outcome_row).collect();
    html.push_str(&table(&["outcome", "values, coarsest first", "unit", "error", "relative", "convergence"], &rows));
    Some(html)
}

fn scalar_of(v: &Value) -> String {
    v.as_f64().map_or_else(|| v.to_string(), number)
}

/// One outcome's row: name, values, unit, error, relative error (%), convergence.
fn outcome_row(o: &Value) -> Vec<String> {
    let values: Vec<String> = o["values"].as_array().into_iter().flatten().map(scalar_of).collect();
    let error = o["error"].as_f64().map_or_else(|| "undefined".to_string(), number);
    let relative = o["relative"].as_f64().map_or(String::new(), |r| format!("{} %", number(100.0 * r)));
    let convergence = match o["convergence"]["kind"].as_str() {
        Some("monotone") => {
            format!("monotone, order {}", o["convergence"]["order"].as_f64().map_or(String::new(), number))
        }
        Some("not_contracting") => "not converging".to_string(),
        Some("scattered") => "scattered about a floor (3 × the spread)".to_string(),
        Some(kind) => kind.to_string(),
        None => String::new(),
    };
    vec![
        format!("<code>{}</code>", escape(o["name"].as_str().unwrap_or(""))),
        escape(&values.join(" → ")),
        escape(o["unit"].as_str().unwrap_or("")),
        escape(&error),
        escape(&relative),
        escape(&convergence),
    ]
}

/// `--accuracy`'s outcome in words.
fn accuracy_line(accuracy: &Value) -> Option<String> {
    let tolerance = accuracy["tolerance"].as_f64()? * 100.0;
    let runs = accuracy["resolutions"].as_array().map_or(0, Vec::len);
    let status = &accuracy["status"];
    let diverging: Vec<&str> =
        accuracy["diverging"].as_array().into_iter().flatten().filter_map(Value::as_str).collect();
    let diverging = match diverging.is_empty() {
        true => String::new(),
        false => format!(
            " Diverging under refinement (undefined, their differences growing with each halving): {}.",
            diverging.join(", ")
        ),
    };
    let line = match status["kind"].as_str() {
        Some("reached") => format!("Asked for {} %: reached after {runs} resolutions.", number(tolerance)),
        _ => format!(
            "Asked for {} %: not reached after {runs} resolutions ({}); above it or undefined: {}.",
            number(tolerance),
            status["why"].as_str().unwrap_or("interrupted"),
            status["outcomes"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(Value::as_str)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    Some(line + &diverging)
}
