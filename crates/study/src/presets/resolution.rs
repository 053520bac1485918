//! How finely the studies sample speeds and forces: coarse for tests and previews, the paper's resolution for its
//! curves.

use scenario::error::{Result, invalid};
use scenario::speeds::SpeedScale;
use scenario::{Scenario, SweepSection};

/// How finely the studies sample speeds and forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// 10–290 m/s by 20 m/s, 9 forces per decade-scan: quick, for tests and previews.
    Coarse,
    /// 10–300 m/s by 1 m/s, 41 forces: the paper's curves.
    Paper,
}

impl Resolution {
    /// The speeds of a study on `base`: its `[sweep]` as given, whatever the resolution; otherwise the default
    /// range around the case's critical speed ([`SpeedScale::default_range`], 10–300 m/s by 10 for the reference
    /// case) sampled every second step (coarse: 10–290 m/s by 20) or every tenth of a step (paper: 1 m/s).
    pub fn speeds(self, base: &Scenario) -> Result<Vec<f64>> {
        if let Some(sweep) = &base.sweep {
            return Ok(sweep.speeds());
        }
        let range = SpeedScale::of(base)?.default_range();
        let step = match self {
            Resolution::Coarse => 2.0 * range.step,
            Resolution::Paper => 0.1 * range.step,
        };
        let count = ((range.to - range.from) / step + 1e-9).floor() as usize + 1;
        Ok((0..count).map(|i| range.from + i as f64 * step).collect())
    }

    /// The speeds of the train study on `base` (m/s): its `[sweep]` as given; otherwise 140–420 km/h (Eurocode sweeps
    /// run from 40 m/s to 1.2 × the line speed, 420 km/h for a 350 km/h line) every 20 km/h (coarse) or 2 km/h
    /// (paper).
    pub fn train_speeds(self, base: &Scenario) -> Vec<f64> {
        if let Some(sweep) = &base.sweep {
            return sweep.speeds();
        }
        let step = match self {
            Resolution::Coarse => 20.0,
            Resolution::Paper => 2.0,
        };
        let kmh = SweepSection { from: 140.0, to: 420.0, step };
        kmh.speeds().into_iter().map(|v| v / scenario::units::KMH).collect()
    }

    pub(super) fn forces(self) -> usize {
        match self {
            Resolution::Coarse => 9,
            Resolution::Paper => 41,
        }
    }

    /// Both, coarse first.
    pub const ALL: [Resolution; 2] = [Resolution::Coarse, Resolution::Paper];

    /// Name on the command line and in Python.
    pub fn name(self) -> &'static str {
        match self {
            Resolution::Coarse => "coarse",
            Resolution::Paper => "paper",
        }
    }

    /// What it samples, in words (for the reference case).
    pub fn description(self) -> &'static str {
        match self {
            Resolution::Coarse => "20 m/s speed steps, 9 forces: quick",
            Resolution::Paper => "1 m/s speed steps, 41 forces: the paper's curves",
        }
    }

    /// The resolution called `name`, or an error naming both.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|r| r.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.map(Resolution::name).to_vec();
            invalid("resolution", name, format!("must be one of {}", names.join(", ")))
        })
    }
}
