//! The report of a run folder (`frictrack run --out DIR`): what ran and its key numbers, the warnings, every figure,
//! the text report as the command printed it, the scenario as it ran, and the files with their columns and units.

use super::blocks::{columns_table, escape, figure, number, pre, scalar, scenario_toml, table, warnings};
use super::page::{Page, Section};
use super::sources::{figure_stems, provenance_facts, string_list};
use crate::run_output::FIGURE_STEMS;
use scenario::error::Result;
use serde_json::Value;
use std::path::Path;

/// The page of the run folder `folder`, whose `summary.json` is `summary`.
pub fn run_page(folder: &Path, summary: &Value) -> Result<Page> {
    let report = &summary["report"];
    let title = summary["figures"]["title"].as_str().unwrap_or("frictrack run").to_string();
    let mut sections = vec![Section::new("results", "Key results", key_results(report))];
    if let Some(check) = super::resolution_table::resolution_section(report) {
        sections.push(Section::new("resolution", "How close it is", check));
    }
    let list: Vec<String> = string_list(&summary["warnings"]);
    sections.push(Section::new("warnings", format!("Warnings ({})", list.len()), warnings(&list)));
    let mut figures = String::new();
    let order: Vec<&str> = FIGURE_STEMS.iter().chain(&["wheel-forces", "bay"]).copied().collect();
    for (i, stem) in figure_stems(folder, &order)?.iter().enumerate() {
        figures.push_str(&figure(folder, stem, i + 1)?);
    }
    if figures.is_empty() {
        figures = "<p>This folder holds no figure (a folder written before runs drew them, or with its figures \
                   removed).</p>\n"
            .into();
    }
    sections.push(Section::new("figures", "Figures", figures));
    let text = summary["text"].as_str().unwrap_or("(this folder was written before runs kept their text report)");
    sections.push(Section::new("report", "The run's report", pre(text)));
    sections.push(Section::new("scenario", "The scenario as it ran", pre(&scenario_toml(&summary["scenario"]))));
    sections.push(Section::new("files", "Files", files(&summary["files"], &summary["conventions"])));
    Ok(Page {
        title: format!("frictrack run: {title}"),
        lead: escape(summary["figures"]["subtitle"].as_str().unwrap_or("")),
        facts: provenance_facts(summary, folder),
        sections,
    })
}

/// The run's key numbers with their units: what ran, the extremes (whole run and the results window), the static
/// envelope and amplification, the energy ledger and the stepping.
fn key_results(report: &Value) -> String {
    let mut rows: Vec<Vec<String>> = Vec::new();
    let mut row = |what: &str, value: Option<String>, unit: &str, note: String| {
        if let Some(value) = value {
            rows.push(vec![escape(what), value, escape(unit), note]);
        }
    };
    let f = |key: &str| report[key].as_f64();
    row(
        "speed",
        f("speed").map(number),
        "m/s",
        f("speed").map_or(String::new(), |v| format!("{} km/h", number(v * scenario::units::KMH))),
    );
    row("load", f("load").map(|v| number(v / 1e3)), "kN", String::new());
    row("critical speed of the infinite track", f("critical_speed").map(number), "m/s", String::new());
    let fitted = report["ground_fit"].is_object();
    let ratio =
        if fitted { "damping ratio ζ of the foundation fitted to the ground" } else { "foundation damping ratio ζ" };
    let of = if fitted { "the fitted dashpot c over 2√(k_f ρA)".to_string() } else { String::new() };
    row(ratio, f("damping_ratio").map(number), "", of);
    for fitted in ground_fit_rows(&report["ground_fit"]) {
        let [what, value, unit, note] = fitted;
        row(&what, Some(value), &unit, note);
    }
    for (key, what) in [
        ("max_downward_deflection", "max downward deflection, whole run"),
        ("max_upward_deflection", "max upward deflection, whole run"),
        ("window_max_downward_deflection", "max downward deflection, results window"),
        ("window_max_upward_deflection", "max upward deflection, results window"),
    ] {
        let extreme = &report[key];
        let at =
            |k: &str, words: &str, unit: &str| extreme[k].as_f64().map(|v| format!("{words} {} {unit}", number(v)));
        let note: Vec<String> =
            [at("position", "x =", "m"), at("time", "t =", "s"), at("load_position", "load at", "m")]
                .into_iter()
                .flatten()
                .collect();
        row(what, extreme["value"].as_f64().map(|v| number(v * 1e3)), "mm", escape(&note.join(", ")));
    }
    if let Some([a, b]) = report["extremes_window"].as_array().map(Vec::as_slice) {
        row("results window (load position)", Some(format!("{}–{}", scalar(a), scalar(b))), "m", String::new());
    }
    row(
        "static max downward deflection",
        f("static_max_downward_deflection").map(|v| number(v * 1e3)),
        "mm",
        String::new(),
    );
    row("dynamic amplification", f("dynamic_amplification").map(number), "", String::new());
    let acc = &report["max_acceleration"];
    row("max acceleration", acc["value"].as_f64().map(number), "m/s²", String::new());
    row("global norm W̄", f("global_norm").map(number), "m²", String::new());
    for (key, what) in [
        ("load_work", "energy: work of the load"),
        ("dissipated", "energy: dissipated"),
        ("friction_dissipation", "energy: by friction"),
        ("viscous_dissipation", "energy: by viscous damping"),
        ("numerical_dissipation", "energy: by the scheme"),
        ("residual", "energy: balance residual"),
    ] {
        row(what, report["energy"][key].as_f64().map(number), "J", String::new());
    }
    row(
        "time steps",
        f("steps").map(number),
        "",
        f("time_step").map_or(String::new(), |h| format!("of {} s", number(h))),
    );
    row("friction solver", report["solver"].as_str().map(escape), "", String::new());
    row("solver iterations a step (mean)", f("mean_iterations").map(number), "", String::new());
    row("wall time", f("wall_time").map(number), "s", String::new());
    table(&["quantity", "value", "unit", "where, when"], &rows)
}

/// On a `[ground]`, the foundation the run took in its place and how far its wave is from the exact one (rows of
/// quantity, value, unit, note); none for a run on a Winkler soil.
fn ground_fit_rows(fit: &Value) -> Vec<[String; 4]> {
    if !fit.is_object() {
        return Vec::new();
    }
    let f = |key: &str| fit[key].as_f64();
    let at = f("speed").map_or(String::new(), |v| format!("fitted at {} m/s", number(v)));
    let rows = [
        ("ground: fitted spring k_f", f("stiffness").map(number), "N/m²", at),
        ("ground: fitted dashpot c", f("damping").map(number), "N·s/m²", String::new()),
        ("ground: co-vibrating mass", f("co_vibrating_mass").map(number), "kg/m", "added to the beam's".into()),
        (
            "ground: fitted wave's error against the exact",
            f("wave_error").map(|e| number(100.0 * e)),
            "%",
            f("peak_error").map_or(String::new(), |e| format!("peak {} %", number(100.0 * e))),
        ),
    ];
    rows.into_iter()
        .filter_map(|(what, value, unit, note)| Some([what.to_string(), value?, unit.to_string(), escape(&note)]))
        .collect()
}

/// The folder's CSV files with their columns and units, and the sign conventions.
fn files(files: &Value, conventions: &Value) -> String {
    let mut out = format!("<p>Conventions: {}.</p>\n", escape(conventions.as_str().unwrap_or("")));
    let Some(map) = files.as_object() else { return out };
    for (name, meta) in map {
        out.push_str(&format!("<h4><code>{}</code></h4>\n{}", escape(name), columns_table(&meta["columns"])));
    }
    out
}
