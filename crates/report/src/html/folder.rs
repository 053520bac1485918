//! Which result folder a report is asked of — a run's (`summary.json`), a study's or `reproduce`'s (`<study>.json`
//! files, `report.md`), or another command's (`ground.json`, `stationary.json`, `receptance.json`, `co-moving.json`,
//! a sweep's JSON beside its CSV) — and which page shows it.

use super::command_page::Command;
use super::page::Page;
use crate::files::read_text;
use scenario::error::{Result, StudyError};
use serde_json::Value;
use std::path::Path;

/// What a folder holds.
#[derive(Debug, Clone, PartialEq)]
pub enum ResultFolder {
    /// A run folder: its `summary.json`.
    Run(Value),
    /// A study folder or a `reproduce` folder: each study's JSON in the order written (reproduce's report order),
    /// and reproduce's `report.md` when there is one.
    Studies(Vec<Value>, Option<String>),
    /// A folder of a command without a run folder (`ground`, `stationary`, `receptance`, `run --co-moving`, a
    /// sweep's CSV and JSON): which, and its JSON.
    Command(Command, Value),
}

impl ResultFolder {
    /// Read `folder`: an error names it and says what a report is made from when it is neither kind.
    pub fn read(folder: &Path) -> Result<Self> {
        if !folder.is_dir() {
            return Err(invalid(folder, "not a folder"));
        }
        let summary = folder.join("summary.json");
        if summary.is_file() {
            let value = read_json(&summary)?;
            if value.get("report").is_some() && value.get("scenario").is_some() {
                return Ok(Self::Run(value));
            }
        }
        let mut studies = Vec::new();
        // Other JSON in the folder (unreadable, or not a study's) is not part of the report.
        for path in json_files(folder)? {
            let Ok(value) = read_json(&path) else { continue };
            if value.get("study").and_then(Value::as_str).is_some() && value.get("summary").is_some() {
                studies.push(value);
            }
        }
        if studies.is_empty() {
            return Self::of_a_command(folder);
        }
        let markdown = Some(folder.join("report.md")).filter(|p| p.is_file()).map(|p| read_text(&p)).transpose()?;
        if let Some(text) = &markdown {
            // reproduce's order: the order its report names the studies in.
            let place =
                |s: &Value| text.find(&format!("{}.json", s["study"].as_str().unwrap_or(""))).unwrap_or(usize::MAX);
            studies.sort_by_key(place);
        }
        Ok(Self::Studies(studies, markdown))
    }

    /// The report page of this folder's results (its figures read from `folder`).
    pub fn page(&self, folder: &Path) -> Result<Page> {
        match self {
            Self::Run(summary) => super::run_page::run_page(folder, summary),
            Self::Studies(studies, markdown) => super::study_page::studies_page(folder, studies, markdown.as_deref()),
            Self::Command(command, value) => super::command_page::command_page(folder, *command, value),
        }
    }

    /// A folder a command other than `run`, `study` and `reproduce` wrote: its JSON by name, or a sweep's (a JSON
    /// naming the CSV beside it); the error says what a report is made of when there is none.
    fn of_a_command(folder: &Path) -> Result<Self> {
        for (name, command) in Command::FILES {
            let path = folder.join(name);
            if path.is_file() {
                return Ok(Self::Command(command, read_json(&path)?));
            }
        }
        for path in json_files(folder)? {
            let Ok(value) = read_json(&path) else { continue };
            let beside = value["csv"].as_str().map(|csv| folder.join(csv));
            if beside.is_some_and(|csv| csv.is_file()) && value.get("extremes_window").is_some() {
                return Ok(Self::Command(Command::Sweep, value));
            }
        }
        Err(invalid(folder, "has no summary.json of a run, no <study>.json of a study and no command's JSON"))
    }
}

/// The JSON files of `folder`, by name.
fn json_files(folder: &Path) -> Result<Vec<std::path::PathBuf>> {
    let mut files: Vec<_> = std::fs::read_dir(folder)
        .map_err(|e| StudyError::Io { path: folder.display().to_string(), message: e.to_string() })?
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json") && p.is_file())
        .collect();
    files.sort();
    Ok(files)
}

/// The error for a folder a report cannot be made of.
fn invalid(folder: &Path, why: &str) -> StudyError {
    StudyError::InvalidField {
        path: "DIR".into(),
        value: folder.display().to_string(),
        allowed: format!(
            "{why}: a report is made of a folder written by `frictrack run --out`, `study --out`, `reproduce --out`, \
             `ground --out`, `stationary --out`, `receptance --out`, `run --co-moving --out` or a sweep's `--out \
             DIR/FILE.csv`"
        ),
    }
}

/// A JSON file of the folder, or an error naming it.
fn read_json(path: &Path) -> Result<Value> {
    let text = read_text(path)?;
    serde_json::from_str(&text).map_err(|e| StudyError::InvalidField {
        path: path.display().to_string(),
        value: format!("line {}, column {}", e.line(), e.column()),
        allowed: format!("JSON as frictrack writes it ({e})"),
    })
}
