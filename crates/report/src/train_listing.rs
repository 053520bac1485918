//! The catalogue of trains and one train's axles, as reported (`frictrack trains`'s text and JSON): name, axles,
//! length (m) and weight (kN in the text, N in the JSON); a train's axles by offset behind its head (m) and force.

use crate::output::{Output, pretty};
use fem_beam::Train;
use scenario::trains::TrainSummary;
use serde::Serialize;
use std::fmt::{self, Formatter};

/// The trains of the catalogue, a line each.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(transparent)]
pub struct TrainCatalogue {
    /// Each train's summary.
    pub trains: Vec<TrainSummary>,
}

/// One train in full.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainListing {
    /// The train's name.
    pub name: String,
    /// Its axles, head first.
    pub axles: Vec<AxleListing>,
    /// First to last axle (m).
    pub length: f64,
}

/// One axle of a train.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxleListing {
    /// Behind the head (m).
    pub offset: f64,
    /// Its force (N).
    pub force: f64,
}

impl TrainListing {
    /// The listing of `train`.
    pub fn of(train: &Train) -> Self {
        Self {
            name: train.name.clone(),
            axles: train.axles.iter().map(|a| AxleListing { offset: a.offset, force: a.force }).collect(),
            length: train.length(),
        }
    }
}

impl Output for TrainCatalogue {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        writeln!(f, "{:<10} {:>6} {:>11} {:>12}", "name", "axles", "length (m)", "weight (kN)")?;
        for t in &self.trains {
            writeln!(f, "{:<10} {:>6} {:>11.3} {:>12.1}", t.name, t.axles, t.length, t.total_force / 1e3)?;
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(self)
    }
}

impl Output for TrainListing {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}: {} axles over {:.3} m", self.name, self.axles.len(), self.length)?;
        writeln!(f, "{:>10} {:>10}", "offset (m)", "force (kN)")?;
        for a in &self.axles {
            writeln!(f, "{:>10.3} {:>10.1}", a.offset, a.force / 1e3)?;
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(self)
    }
}
