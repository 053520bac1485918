//! What a page reads of a result folder besides its tables: the figures in the order a reader meets them, where the
//! results came from, a JSON list of strings.

use super::blocks::escape;
use scenario::error::{Result, StudyError};
use serde_json::Value;
use std::path::Path;

/// The strings of a JSON list (none if it is not one).
pub fn string_list(value: &Value) -> Vec<String> {
    value.as_array().map(|a| a.iter().filter_map(|s| s.as_str().map(String::from)).collect()).unwrap_or_default()
}

/// Every SVG figure of `folder`, those named in `order` first (in that order), then the others by name.
pub fn figure_stems(folder: &Path, order: &[&str]) -> Result<Vec<String>> {
    let mut stems: Vec<String> = std::fs::read_dir(folder)
        .map_err(|e| StudyError::Io { path: folder.display().to_string(), message: e.to_string() })?
        .flatten()
        .filter_map(|e| e.file_name().to_str()?.strip_suffix(".svg").map(String::from))
        .collect();
    let rank = |s: &String| order.iter().position(|o| o == s).unwrap_or(order.len());
    stems.sort_by(|a, b| rank(a).cmp(&rank(b)).then(a.cmp(b)));
    Ok(stems)
}

/// The facts a page opens with: the command, frictrack's version and commit, the date, the folder — from a result
/// JSON's provenance fields (absent in folders written before they were kept).
pub fn provenance_facts(json: &Value, folder: &Path) -> Vec<(String, String)> {
    let command = json["command"].as_str();
    let unknown = || "<span class=\"none\">not recorded</span>".to_string();
    vec![
        (
            "command".into(),
            command.filter(|c| !c.is_empty()).map_or_else(unknown, |c| format!("<code>{}</code>", escape(c))),
        ),
        ("frictrack".into(), json["frictrack_version"].as_str().map_or_else(unknown, escape)),
        (
            "commit".into(),
            json["git_revision"].as_str().map_or_else(unknown, |c| format!("<code>{}</code>", escape(c))),
        ),
        ("date (UTC)".into(), json["date"].as_str().map_or_else(unknown, escape)),
        ("folder".into(), format!("<code>{}</code>", escape(&folder.display().to_string()))),
    ]
}
