//! # scenario: the scenario file and everything checked before a run (docs/theory.md §2–§14)
//!
//! Every key of the TOML scenario format is optional (defaults = the reference case of docs/theory.md §2); unknown
//! keys are errors. [`Scenario::build`] turns a scenario into the beam model, the contact set and the run settings;
//! [`Scenario::validate`] names the offending key by its dotted path.
//!
//! - [`sections`]: the schema, one struct per `[section]` with the reference case as default.
//! - `build`: from the sections to the beam model, friction sections and run settings, each value checked and named
//!   by its dotted path ([`Scenario::build`], [`Scenario::model`], [`Scenario::run_settings`]).
//! - `parse`: TOML errors with file, line, column, the key's path and a "did you mean".
//! - [`overrides`]: the one table of the command-line flags and Python keywords that override a scenario's values;
//!   [`units`]: speeds in m/s or km/h; [`quantities`]: every output quantity with its SI unit, the one list every
//!   table's columns take their units from, and every figure's axis its label ([`axis`]).
//! - [`diagnostics`] and [`plausibility`]: refusals and warnings about a scenario before any run.
//! - [`ground`]: `[ground]`, the layered ground under the track and its checks ([`ground_plausibility`]: the values
//!   no site has, warned of); [`AsRan`]: a scenario as its
//!   reports show it (without the `[foundation]` a ground replaces).
//! - [`speeds`] and [`trains`]: the speed scale of a case (v_cr, default sweeps) and the train catalogue.
//! - [`accuracy_key`]: `[integration] accuracy`, taken by a single run, refused by every other use;
//!   [`accuracy_law`]: the ballast friction's law a refinement (`run --accuracy`) runs, the cheapest for an accuracy.
//! - [`error`]: the error type of the crates above this one, every message naming the field, its value and what is
//!   allowed; [`number`]: numbers as result files and messages print them.

mod acceleration_bands;
pub mod accuracy_key;
pub mod accuracy_law;
mod as_ran;
pub mod axis;
mod build;
pub mod contact;
mod deck;
mod devices_layout;
pub mod diagnostics;
pub mod embankment;
pub mod error;
pub mod ground;
pub mod ground_plausibility;
pub mod load_section;
mod long_wave_twin;
pub mod number;
mod override_values;
pub mod overrides;
mod parse;
pub mod plausibility;
pub mod quantities;
pub mod rail;
mod refined_twin;
pub mod sections;
pub mod sleepers;
pub mod speeds;
mod stationary_problem;
pub mod trains;
mod two_beam;
pub mod units;
pub mod vehicle;
mod warning;

pub use acceleration_bands::DEFAULT_ACCELERATION_FILTER;
pub use as_ran::AsRan;
pub use build::RESULT_FORMAT;
pub use error::{Result, StudyError};
pub use rail::RailSection;
pub use sections::*;
pub use vehicle::VehicleSection;

use crate::error::invalid;
use fem_beam::{Beam, BeamModel, Mesh, Supports};
use parse::{did_you_mean, key_path, line_column};
use serde::{Deserialize, Serialize};
use track::PlacedInteractions;
use track::RunSettings;

/// A whole case: beam, mesh, supports, foundation, load, friction, integration, sweep, output.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct Scenario {
    /// A title for reports.
    pub title: String,
    /// The rail section.
    pub beam: Beam,
    /// Length and elements.
    pub mesh: Mesh,
    /// End supports.
    pub supports: Supports,
    /// The soil.
    pub foundation: FoundationSection,
    /// A layered visco-elastic ground under the track, in place of the Winkler `[foundation]`
    /// (docs/theory.md §19).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ground: Option<ground::GroundSection>,
    /// The embankment beam under the whole track, on a `[ground]`, carrying the rail on `[sleepers]` (the two-beam
    /// track, docs/theory.md §19).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub embankment: Option<embankment::EmbankmentSection>,
    /// Discrete supports — rail pads on sleepers on ballast — beside (or instead of) the soil.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sleepers: Option<sleepers::SleepersSection>,
    /// Damping of the structure itself (Rayleigh), beside the foundation's.
    #[serde(skip_serializing_if = "DampingSection::is_empty")]
    pub damping: DampingSection,
    /// The moving load.
    pub load: LoadSection,
    /// Vehicles instead of moving forces: `[load]` then gives only the speed and, if any, the train whose axles
    /// carry them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vehicle: Option<VehicleSection>,
    /// The rail's irregularities, under the vehicles' wheels.
    #[serde(skip_serializing_if = "RailSection::is_empty")]
    pub rail: RailSection,
    /// Friction devices and/or distributed friction.
    pub friction: FrictionSection,
    /// Time integration and the friction solver.
    pub integration: IntegrationSection,
    /// Speed range of sweeps and studies; without it, a range around the case's critical speed
    /// ([`crate::speeds::SpeedScale`]).
    pub sweep: Option<SweepSection>,
    /// Run through a co-moving window instead of across the finite beam (`frictrack run`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub co_moving: Option<CoMovingSection>,
    /// What is recorded.
    pub output: OutputSection,
    /// Set on the scenario a run in time takes for a composite beam on a `[ground]` ([`Scenario::on_fitted_foundation`]):
    /// the ground's fastest wave (m/s), the speed limit in place of the composite beam's bar wave √(E/ρ), which is a
    /// section convention. Not a key of the file.
    #[serde(skip)]
    pub fastest_ground_wave: Option<f64>,
}

/// A scenario turned into what the stepper runs.
#[derive(Debug, Clone)]
pub struct Case {
    /// The assembled beam.
    pub model: BeamModel,
    /// All friction sections.
    pub interactions: PlacedInteractions,
    /// Run settings (speed from `[load]`).
    pub settings: RunSettings,
    /// v_cr of this track (m/s; [`speeds::SpeedScale::of`]: the rail as it is, on sleepers their long-wave twin);
    /// `None` for a beam without any support.
    pub critical_speed: Option<f64>,
    /// Identifies what a run of this case at a given speed computes: a hash (64-bit FNV-1a) of the frictrack version
    /// and the scenario without its title, load speed, recorded sections and sweep range. Keys journal entries.
    pub fingerprint: u64,
    /// On a `[ground]`: the foundation the model takes for it, fitted at one speed, and its wave's error against the
    /// exact moving-frame solution ([`Scenario::on_fitted_foundation`]); a run at another speed is refused.
    pub ground_fit: Option<analytic::ground::FittedFoundation>,
}

impl Scenario {
    /// Parse TOML; `source_name` (a file name) prefixes syntax errors with line and column.
    pub fn from_toml(text: &str, source_name: &str) -> Result<Self> {
        let scenario: Self = toml::from_str(text).map_err(|e| {
            let offset = e.span().map_or(0, |span| span.start);
            let (line, column) = line_column(text, offset);
            let message = e.message().trim();
            let message = match key_path(text, offset) {
                Some(path) => format!("{path}: {message}{}", did_you_mean(message)),
                None => format!("{message}{}", did_you_mean(message)),
            };
            StudyError::Syntax { source_name: source_name.into(), line, column, message }
        })?;
        if scenario.ground.is_some() {
            ground::refuse_tables_beside_ground(text)?;
        }
        Ok(scenario)
    }

    /// Parse a scenario given as JSON (a Python dict, a web form): the same keys as the TOML file, checked by the
    /// same parser, errors named by their dotted path.
    pub fn from_json(text: &str, source_name: &str) -> Result<Self> {
        let value: toml::Value = serde_json::from_str(text)
            .map_err(|e| invalid(source_name, "JSON", format!("is not a scenario table: {e}")))?;
        let toml = toml::to_string(&value)
            .map_err(|e| invalid(source_name, "JSON", format!("is not a scenario table: {e}")))?;
        Self::from_toml(&toml, source_name)
    }

    /// Read and parse a file.
    pub fn from_path(path: &std::path::Path) -> Result<Self> {
        // A scenario that cannot be read is the user's input error (exit code 2), not a failure of the run.
        let text = std::fs::read_to_string(path)
            .map_err(|e| invalid("scenario file", path.display(), format!("cannot be read: {e}")))?;
        let mut scenario = Self::from_toml(&text, &path.display().to_string())?;
        scenario.resolve_files(path.parent().unwrap_or(std::path::Path::new("")));
        Ok(scenario)
    }

    /// Make the files a scenario names (a train CSV, profile tables) relative to `folder`, the scenario file's own,
    /// where they are relative: a scenario reads the same from any working directory. Catalogue train names stay.
    fn resolve_files(&mut self, folder: &std::path::Path) {
        let beside = |file: &mut String| {
            let path = std::path::Path::new(file.as_str());
            if path.is_relative() && !folder.as_os_str().is_empty() {
                *file = folder.join(path).to_string_lossy().into_owned();
            }
        };
        if let Some(train) = self.load.train.as_mut()
            && !fem_beam::Train::catalogue().iter().any(|n| n.eq_ignore_ascii_case(train))
        {
            beside(train);
        }
        for irregularity in &mut self.rail.irregularities {
            if let rail::IrregularitySection::Table { file } = irregularity {
                beside(file);
            }
        }
    }

    /// The scenario as TOML (all keys, defaults included).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a scenario always serialises")
    }
}

/// 64-bit FNV-1a hash: stable across platforms, Rust versions and runs (unlike `std`'s `DefaultHasher`).
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// A documented scenario template: every key with its default, unit and meaning (`frictrack init`).
pub const TEMPLATE: &str = include_str!("template.toml");
