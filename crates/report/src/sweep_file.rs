//! The JSON beside a sweep's CSV (`frictrack sweep --out FILE.csv` writes `FILE.json`): the CSV's name, its columns
//! with units and meanings, the extremes window of load positions (m), the refined critical speed with its
//! description, the runs that failed, the version and the scenario — written once here, and read back by
//! `frictrack plot FILE.csv` for the scenario and the critical speed it draws.

use crate::columns::ColumnMeta;
use runner::{CriticalSpeed, FailedRun};
use scenario::Scenario;
use serde::{Deserialize, Serialize};

/// What a sweep's JSON holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepFile {
    /// The CSV's file name.
    pub csv: Option<String>,
    /// Name, unit and meaning of each column.
    pub columns: Vec<ColumnMeta>,
    /// The window of load positions [A, B] (m) of the window extremes.
    pub extremes_window: (f64, f64),
    /// The refined critical speed, if the sweep asked for it.
    pub critical_speed: Option<CriticalSpeedNote>,
    /// The runs that failed (their CSV rows have the speed and empty values).
    pub failures: Vec<FailedRun>,
    /// The version that wrote it.
    pub frictrack_version: String,
    /// The scenario swept.
    pub scenario: Scenario,
    /// With `sweep --check-resolution`: the check at the speed of the sweep's peak
    /// ([`crate::resolution_check::point::PointCheck`], as JSON).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resolution_check: Option<serde_json::Value>,
}

/// A refined critical speed and what it is, in words.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CriticalSpeedNote {
    /// In words, with its bounds where it lies at an end.
    pub description: String,
    /// The refined speed, its peak and the runs it took.
    pub result: CriticalSpeed,
}

impl SweepFile {
    /// The JSON beside `csv` (its file name) of a sweep of `scenario` with its refined `critical` speed and `failed`
    /// runs; a scenario with vehicles has the vehicles' columns too.
    pub fn of(
        csv: Option<String>,
        scenario: &Scenario,
        critical: Option<&CriticalSpeed>,
        failed: &[FailedRun],
    ) -> Self {
        let columns = runner::csv_columns_of(scenario)
            .map(|(name, unit, meaning)| ColumnMeta {
                name: name.to_string(),
                unit: unit.to_string(),
                meaning: Some(meaning.to_string()),
            })
            .collect();
        Self {
            csv,
            columns,
            extremes_window: scenario.output.extremes_window(scenario.mesh.length),
            critical_speed: critical.map(|c| CriticalSpeedNote { description: c.describe(), result: c.clone() }),
            failures: failed.to_vec(),
            frictrack_version: env!("CARGO_PKG_VERSION").to_string(),
            scenario: scenario.clone(),
            resolution_check: None,
        }
    }

    /// The sweep's JSON read back from its text; None where it is not one (a file of another version or none).
    pub fn read(text: &str) -> Option<Self> {
        serde_json::from_str(text).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::SweepFile;

    /// What a sweep writes beside its CSV reads back as it was.
    #[test]
    fn a_sweep_file_reads_back() {
        let scenario = scenario::Scenario::default();
        let file = SweepFile::of(Some("sweep.csv".into()), &scenario, None, &[]);
        let text = serde_json::to_string_pretty(&file).unwrap();
        assert_eq!(SweepFile::read(&text), Some(file));
        assert_eq!(SweepFile::read("{}"), None);
    }
}
