//! The train of a scenario (docs/theory.md §10): a catalogue name, a CSV file of `offset,force`, or axles and
//! patches given in the scenario file — resolved into a [`fem_beam::Train`] with errors that name the scenario path.

use crate::LoadSection;
use crate::error::{Result, invalid};
use fem_beam::{Axle, FemError, Patch, Train};
use serde::Serialize;

/// The train of `[load]`, or None for the single load `load.force`.
pub fn resolve(load: &LoadSection) -> Result<Option<Train>> {
    let given = !load.axles.is_empty() || !load.patches.is_empty();
    let train = match (&load.train, given) {
        (Some(name), true) => {
            return Err(invalid(
                "load.train",
                name,
                "give either a train (a catalogue name or a CSV file) or [[load.axles]]/[[load.patches]], not both",
            ));
        }
        (None, false) => return Ok(None),
        (None, true) => Train {
            name: "scenario".into(),
            axles: load.axles.iter().map(|a| Axle { offset: a.offset, force: a.force }).collect(),
            patches: load
                .patches
                .iter()
                .map(|p| Patch { offset: p.offset, length: p.length, intensity: p.intensity })
                .collect(),
        },
        (Some(name), false) => named_or_file(name, load.force, "load.train")?,
    };
    train.validate().map_err(|e| match e {
        FemError::InvalidTrain { path, value, allowed } => invalid(&format!("load.{path}"), value, allowed),
        other => other.into(),
    })?;
    Ok(Some(train))
}

/// A catalogue train (`single` takes `single_force`; names in any case, `HSLM-A1` is `hslm-a1`), else a CSV file of
/// axles; errors name `field`.
pub fn named_or_file(name: &str, single_force: f64, field: &str) -> Result<Train> {
    if let Some(known) = Train::catalogue().into_iter().find(|n| n.eq_ignore_ascii_case(name)) {
        return Ok(Train::named(&known, single_force)?);
    }
    let path = std::path::Path::new(name);
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("csv")) || path.exists() {
        return read_csv(path);
    }
    Err(invalid(
        field,
        name,
        format!("expected a catalogue name ({}) or a CSV file of offset,force", Train::catalogue().join(", ")),
    ))
}

/// Largest train file read (bytes): 10 000 axles of two numbers fit many times over.
const MAX_FILE_BYTES: u64 = 4 << 20;

/// Axles from a CSV file: one `offset,force` pair per line (m, N), an optional header line, `#` comments.
pub fn read_csv(path: &std::path::Path) -> Result<Train> {
    // A train file that cannot be read is the user's input (exit 2), like a bad value in it.
    let io = |e: std::io::Error| invalid("load.train", path.display(), format!("cannot read the train file: {e}"));
    let size = std::fs::metadata(path).map_err(io)?.len();
    if size > MAX_FILE_BYTES {
        return Err(invalid("load.train", path.display(), "train files are at most 4 MiB"));
    }
    let text = std::fs::read_to_string(path).map_err(io)?;
    let name = path.file_stem().map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
    parse_csv(&name, &text, &path.display().to_string())
}

/// The train `name` from the text of a train file (`offset,force` rows, `#` comments); `source` names it in errors.
pub fn parse_csv(name: &str, text: &str, source: &str) -> Result<Train> {
    // Spreadsheets write a UTF-8 byte-order mark first: it is no part of the header.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut axles = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() || (axles.is_empty() && line.eq_ignore_ascii_case("offset,force")) {
            continue;
        }
        let bad = || {
            invalid(
                &format!("{source} line {}", number + 1),
                line,
                "expected `offset,force` (m behind the first axle, N downward)",
            )
        };
        let (offset, force) = line.split_once(',').ok_or_else(bad)?;
        let offset = offset.trim().parse::<f64>().map_err(|_| bad())?;
        let force = force.trim().parse::<f64>().map_err(|_| bad())?;
        axles.push(Axle { offset, force });
    }
    Ok(Train { name: name.into(), axles, patches: Vec::new() })
}

/// What a report says of a train: name, counts, length (m) and whole weight (N).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainSummary {
    /// Name.
    pub name: String,
    /// Number of axles.
    pub axles: usize,
    /// Number of load patches.
    pub patches: usize,
    /// First to last axle or patch end (m).
    pub length: f64,
    /// Σ P + Σ q ℓ (N).
    pub total_force: f64,
}

impl TrainSummary {
    /// The summary of `train`.
    pub fn of(train: &Train) -> Self {
        Self {
            name: train.name.clone(),
            axles: train.axles.len(),
            patches: train.patches.len(),
            length: train.length(),
            total_force: train.total_force(),
        }
    }
}
