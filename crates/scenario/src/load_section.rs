//! `[load]`: what crosses (a single force, a train, axles, patches), at which speed — constant, changing at a constant
//! `acceleration`, or through a `speed_profile` over position — and what the beam carries of it.

use super::sections::{AxleSection, PatchSection};
use crate::error::{Result, invalid};
use analytic::reference::uic60_on_soft_soil;
use serde::{Deserialize, Serialize};
use track::simulation::MovingLoadSettings;

/// `[load]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LoadSection {
    /// Magnitude F (N), acting downward, of the single load (when no train is given).
    pub force: f64,
    /// Speed v (m/s) of a single run.
    pub speed: f64,
    /// A train instead of the single load: a catalogue name (`single`, `hslm-a1` … `hslm-a10`) or a CSV file of
    /// `offset,force` lines.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub train: Option<String>,
    /// `[[load.axles]]`: a train given axle by axle.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub axles: Vec<AxleSection>,
    /// `[[load.patches]]`: uniform load patches of the train.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub patches: Vec<PatchSection>,
    /// What the beam carries of a train's axle loads (and patches), by default [`LoadSection::share_on`]; the single
    /// load `force` is the beam's own and never scaled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub carries: Option<AxleShare>,
    /// a (m/s², negative brakes): the speed changes at this constant rate, `speed` being the speed at x = 0
    /// (v² = speed² + 2a·x, x the first axle's position).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub acceleration: Option<f64>,
    /// `[[x, v], …]` (m, m/s): the first axle's speed over its position, changing at constant acceleration between
    /// knots (v² linear in x) and held outside them — for trains that change speed more than once; replaces `speed`.
    #[serde(skip_serializing_if = "Option::is_none", deserialize_with = "knots")]
    pub speed_profile: Option<Vec<[f64; 2]>>,
}

/// A `speed_profile`'s knots, each exactly two numbers `[x, v]`: a knot of another length is refused (an array
/// would take the first two and drop the rest in silence).
fn knots<'de, D: serde::Deserializer<'de>>(deserializer: D) -> std::result::Result<Option<Vec<[f64; 2]>>, D::Error> {
    let rows = Vec::<Vec<f64>>::deserialize(deserializer)?;
    let pair = |(i, row): (usize, Vec<f64>)| match row[..] {
        [x, v] => Ok([x, v]),
        _ => Err(serde::de::Error::custom(format!(
            "knot {} has {} numbers: each knot is [x, v], a position (m) and the speed there (m/s)",
            i + 1,
            row.len()
        ))),
    };
    rows.into_iter().enumerate().map(pair).collect::<std::result::Result<Vec<_>, _>>().map(Some)
}

impl Default for LoadSection {
    fn default() -> Self {
        let (axles, patches) = (Vec::new(), Vec::new());
        Self {
            force: uic60_on_soft_soil().load,
            speed: 200.0,
            train: None,
            axles,
            patches,
            carries: None,
            acceleration: None,
            speed_profile: None,
        }
    }
}

/// What the modelled beam carries of a train's axle loads (docs/theory.md §10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum AxleShare {
    /// The beam is one rail of the track: half of each axle (the reference case's 83.4 kN is half of a 166.8 kN
    /// axle).
    OneRail,
    /// The beam carries whole axles: a bridge deck, or a track modelled as one beam for both rails.
    WholeAxle,
}

impl AxleShare {
    /// The factor on the axle loads: ½ or 1.
    pub fn factor(self) -> f64 {
        match self {
            AxleShare::OneRail => 0.5,
            AxleShare::WholeAxle => 1.0,
        }
    }

    /// The name in scenario files and reports: `one-rail` or `whole-axle`.
    pub fn name(self) -> &'static str {
        match self {
            AxleShare::OneRail => "one-rail",
            AxleShare::WholeAxle => "whole-axle",
        }
    }

    /// What it means, for reports.
    pub fn describe(self) -> &'static str {
        match self {
            AxleShare::OneRail => "one rail carries half of each axle",
            AxleShare::WholeAxle => "the beam carries whole axles",
        }
    }
}

impl LoadSection {
    /// What the beam carries of the axles: `carries` if given, else a rail's half on a soil of stiffness
    /// `foundation_stiffness` > 0 or on sleepers, whole axles on neither (a deck).
    pub fn share_on(&self, foundation_stiffness: f64, on_sleepers: bool) -> AxleShare {
        let track = foundation_stiffness > 0.0 || on_sleepers;
        self.carries.unwrap_or(if track { AxleShare::OneRail } else { AxleShare::WholeAxle })
    }
}

/// The refusal, by key, of a speed `v` (m/s) asked of a load whose `speed_profile` sets its speeds.
fn profile_sets_the_speeds(v: f64) -> crate::StudyError {
    invalid(
        "load.speed_profile",
        "given",
        format!(
            "sets the load's speeds itself, so the speed asked for ({} m/s) would not run: leave the speed out, or \
             the profile (a sweep over speeds takes a constant acceleration)",
            crate::number::number(v)
        ),
    )
}

impl LoadSection {
    /// Set the speed (m/s) to `v` (an override's), refused by key where the `speed_profile` sets the speeds.
    pub fn take_speed(&mut self, v: f64) -> Result<()> {
        if self.speed_profile.is_some() {
            return Err(profile_sets_the_speeds(v));
        }
        self.speed = v;
        Ok(())
    }

    /// Refuse, by key, a changing speed where `what` (a steady state in the moving frame) holds at one speed only.
    pub fn refuse_changing_speed(&self, what: &str) -> Result<()> {
        let allowed = |key: &str| {
            format!("{what} is the steady state at one constant speed: leave {key} out, or run the track in time")
        };
        match (self.acceleration, &self.speed_profile) {
            (Some(a), _) if a != 0.0 => Err(invalid("load.acceleration", a, allowed("the acceleration"))),
            (_, Some(_)) => Err(invalid("load.speed_profile", "given", allowed("the speed profile"))),
            _ => Ok(()),
        }
    }

    /// `moving` (at the run's speed, `moving.speed`) with this section's change of speed over the first axle's
    /// travel `(start, end)` (m): none at constant speed; the `speed_profile` as given; a constant `acceleration`
    /// ([`MovingLoadSettings::with_acceleration`]). Refused by key: both given, a bad profile (its knots checked by
    /// [`MovingLoadSettings::with_profile`]), a profile beside another speed (a sweep's or `--speed`), a load that would stop on the way.
    pub fn speed_change(&self, moving: MovingLoadSettings, travel: (f64, f64)) -> Result<MovingLoadSettings> {
        if let (Some(a), Some(_)) = (self.acceleration, &self.speed_profile) {
            return Err(invalid("load.acceleration", a, "give acceleration or speed_profile, not both"));
        }
        if let Some(knots) = &self.speed_profile {
            if moving.speed != self.speed {
                return Err(profile_sets_the_speeds(moving.speed));
            }
            return Ok(moving.with_profile(knots.iter().map(|&[x, v]| (x, v)).collect())?);
        }
        match self.acceleration {
            Some(a) => Ok(moving.with_acceleration(a, travel)?),
            None => Ok(moving),
        }
    }
}
