//! The report of a study folder (`frictrack study NAME --out DIR`) or a `reproduce` folder: for each study its
//! headline, its results as tables (with the verdicts its summary holds, e.g. the HSLM deck verdicts), its figures,
//! its per-curve lines, warnings and failed runs, its data files, and the scenario it ran on.

use super::blocks::{columns_table, escape, figure, number, pre, scenario_toml, summary_tables, warnings};
use super::page::{Page, Section};
use super::sources::{provenance_facts, string_list};
use scenario::error::Result;
use serde_json::Value;
use std::path::Path;

/// The page of `studies` (each a `<study>.json`) in `folder`, with `reproduce`'s `report.md` when there is one.
pub fn studies_page(folder: &Path, studies: &[Value], markdown: Option<&str>) -> Result<Page> {
    let mut sections = Vec::with_capacity(studies.len() + 1);
    let mut figures = 0;
    for study in studies {
        sections.push(study_section(folder, study, &mut figures)?);
    }
    // One scenario for all when they share it (reproduce), else each study shows its own.
    let first = scenarios_text(&studies[0]);
    if studies.iter().all(|s| scenarios_text(s) == first) {
        let heading = if studies.len() == 1 { "The scenario it ran on" } else { "The scenario the studies ran on" };
        sections.push(Section::new("scenario", heading, pre(&first)));
    } else {
        for (section, study) in sections.iter_mut().zip(studies) {
            let id = format!("{}-scenario", section.id);
            section.children.push(Section::new(id, "Scenario", pre(&scenarios_text(study))));
        }
    }
    let (title, lead) = match (studies, markdown) {
        ([study], None) => (format!("frictrack study: {}", text(&study["title"])), String::new()),
        (_, Some(markdown)) => ("frictrack reproduce: the thesis's studies".to_string(), preamble(markdown)),
        _ => ("frictrack studies".to_string(), String::new()),
    };
    Ok(Page { title, lead, facts: provenance_facts(&studies[0], folder), sections })
}

/// The TOML of the scenario a study ran on, and of each further one of its own (a built-in site on two tracks).
fn scenarios_text(study: &Value) -> String {
    let more = study["more_scenarios"].as_array().map_or(&[][..], Vec::as_slice);
    std::iter::once(&study["scenario"])
        .chain(more)
        .map(scenario_toml)
        .collect::<Vec<_>>()
        .join("\n# ——— and the study's next scenario ———\n\n")
}

/// One study: its headline and results, figures, lines, warnings and failures, data.
fn study_section(folder: &Path, study: &Value, figures: &mut usize) -> Result<Section> {
    let name = text(&study["study"]);
    let mut headline: String =
        string_list(&study["headline"]).iter().map(|l| format!("<p>{}</p>\n", escape(l))).collect();
    let units: Vec<(String, String)> =
        study["columns"].as_array().into_iter().flatten().map(|c| (text(&c["name"]), text(&c["unit"]))).collect();
    headline.push_str(&summary_tables(&study["summary"], &units));
    let mut drawn = String::new();
    for stem in string_list(&study["plots"]) {
        *figures += 1;
        drawn.push_str(&figure(folder, &stem, *figures)?);
    }
    let lines: String = string_list(&study["lines"]).iter().map(|l| format!("<li>{}</li>\n", escape(l))).collect();
    let mut notes = string_list(&study["warnings"]);
    notes.extend(string_list(&study["scenario_parts_not_used"]).into_iter().map(|n| format!("not used: {n}")));
    notes.extend(study["failures"].as_array().into_iter().flatten().map(|f| format!("failed run: {}", compact(f))));
    let children = vec![
        Section::new(format!("{name}-results"), "Results", headline),
        Section::new(format!("{name}-figures"), "Figures", drawn),
        Section::new(format!("{name}-curves"), "Per curve", format!("<ul>\n{lines}</ul>\n")),
        Section::new(format!("{name}-warnings"), format!("Warnings and notes ({})", notes.len()), warnings(&notes)),
        Section::new(format!("{name}-data"), "Data", data(study)),
    ];
    Ok(Section { id: name.clone(), heading: text(&study["title"]), body: String::new(), children })
}

/// The study's data: its files, the columns of its CSV with units, how many runs and how long, at which resolution,
/// and the command that ran it.
fn data(study: &Value) -> String {
    let name = text(&study["study"]);
    let mut out = format!(
        "<p><code>{name}.csv</code> (the curves, SI units) and <code>{name}.json</code> (this page's source); {} \
         simulations at the {} resolution in {} s, by <code>{}</code> on {}.</p>\n",
        study["runs"].as_f64().map_or("—".into(), number),
        escape(&text(&study["resolution"])),
        study["wall_time"].as_f64().map_or("—".into(), number),
        escape(&text(&study["command"])),
        escape(&text(&study["date"])),
    );
    out.push_str(&columns_table(&study["columns"]));
    out
}

/// A JSON string's text ("—" when absent).
fn text(value: &Value) -> String {
    value.as_str().map_or_else(|| "—".to_string(), String::from)
}

/// A record in one line (a failed run).
fn compact(value: &Value) -> String {
    value.as_object().map_or_else(
        || value.to_string(),
        |m| {
            m.iter()
                .map(|(k, v)| format!("{k} {}", v.as_str().map_or_else(|| v.to_string(), String::from)))
                .collect::<Vec<_>>()
                .join(", ")
        },
    )
}

/// The paragraphs of `reproduce`'s report.md before its first study (its heading left out): the base case in
/// numbers and how to read the figures, as HTML paragraphs (`code` kept as code).
fn preamble(markdown: &str) -> String {
    let before = markdown.split("\n## ").next().unwrap_or("");
    before
        .split("\n\n")
        .map(str::trim)
        .filter(|p| !p.is_empty() && !p.starts_with('#'))
        .map(|p| format!("<p>{}</p>", code_spans(&escape(p))))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Markdown's `code` spans as `<code>` (on escaped text).
fn code_spans(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for (i, part) in text.split('`').enumerate() {
        if i % 2 == 1 {
            out.push_str(&format!("<code>{part}</code>"));
        } else {
            out.push_str(part);
        }
    }
    out
}
