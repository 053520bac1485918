//! The page of a folder written by one of the commands that answer without a run folder — `frictrack ground --out`,
//! `stationary --out`, `receptance --out`, `run --co-moving --out`, and a sweep's `--out FILE.csv` (its `FILE.json`
//! beside it): the command's numbers with their units and its tables of points (from its JSON), every warning it
//! gave, its figures (each SVG in the folder), the scenario where it recorded one, and its files.

use super::blocks::{columns_table, figure, pre, scenario_toml, summary_tables, warnings};
use super::page::{Page, Section};
use super::sources::provenance_facts;
use scenario::error::{Result, StudyError};
use serde_json::Value;
use std::path::Path;

/// Which command wrote a folder's JSON, by the JSON's file name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Command {
    /// `ground.json`.
    Ground,
    /// `stationary.json`.
    Stationary,
    /// `receptance.json`.
    Receptance,
    /// `co-moving.json`.
    CoMoving,
    /// A sweep's `FILE.json` beside its `FILE.csv`.
    Sweep,
}

impl Command {
    /// The command's JSON files, in the order a folder is searched (a sweep's is any JSON naming its `csv`).
    pub const FILES: [(&'static str, Command); 4] = [
        ("ground.json", Command::Ground),
        ("stationary.json", Command::Stationary),
        ("receptance.json", Command::Receptance),
        ("co-moving.json", Command::CoMoving),
    ];

    /// The command, as typed.
    pub fn name(self) -> &'static str {
        match self {
            Command::Ground => "ground",
            Command::Stationary => "stationary",
            Command::Receptance => "receptance",
            Command::CoMoving => "run --co-moving",
            Command::Sweep => "sweep",
        }
    }
}

/// The page of `value`, the JSON `command` wrote into `folder`.
pub fn command_page(folder: &Path, command: Command, value: &Value) -> Result<Page> {
    let title = value["title"].as_str().filter(|t| !t.is_empty()).or_else(|| value["scenario"]["title"].as_str());
    let title = match title.filter(|t| !t.is_empty()) {
        Some(t) => format!("frictrack {}: {t}", command.name()),
        None => format!("frictrack {}", command.name()),
    };
    let units: Vec<(String, String)> = value["units"]
        .as_array()
        .or_else(|| value["columns"].as_array())
        .into_iter()
        .flatten()
        .map(|u| (text(&u["name"]), text(&u["unit"])))
        .collect();
    let numbers = without(value, &["units", "columns", "scenario", "warnings", "csv", "frictrack_version"]);
    let mut sections = vec![Section::new("results", "Results", summary_tables(&numbers, &units))];
    let said: Vec<String> =
        value["warnings"].as_array().into_iter().flatten().filter_map(|w| w.as_str()).map(String::from).collect();
    if !said.is_empty() {
        sections.push(Section::new("warnings", "Warnings", warnings(&said)));
    }
    sections.push(Section::new("figures", "Figures", figures(folder)?));
    if value["scenario"].is_object() {
        sections.push(Section::new("scenario", "The scenario as it ran", pre(&scenario_toml(&value["scenario"]))));
    }
    if value["columns"].is_array() {
        sections.push(Section::new("files", "Data file and its columns", columns_table(&value["columns"])));
    }
    Ok(Page { title, lead: String::new(), facts: provenance_facts(value, folder), sections })
}

/// Every SVG figure in `folder`, by name, numbered; a note where there is none.
fn figures(folder: &Path) -> Result<String> {
    let mut stems: Vec<String> = std::fs::read_dir(folder)
        .map_err(|e| StudyError::Io { path: folder.display().to_string(), message: e.to_string() })?
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .collect();
    stems.sort();
    if stems.is_empty() {
        return Ok("<p>This folder holds no figure (the command draws its figures with <code>--out</code>; \
                   <code>frictrack plot</code> draws a sweep's).</p>\n"
            .into());
    }
    let drawn: Result<Vec<String>> = stems.iter().enumerate().map(|(i, stem)| figure(folder, stem, i + 1)).collect();
    Ok(drawn?.concat())
}

/// `value` without the keys `left_out` (what other sections show).
fn without(value: &Value, left_out: &[&str]) -> Value {
    let mut value = value.clone();
    if let Some(map) = value.as_object_mut() {
        map.retain(|key, _| !left_out.contains(&key.as_str()));
    }
    value
}

fn text(value: &Value) -> String {
    value.as_str().unwrap_or_default().to_string()
}
