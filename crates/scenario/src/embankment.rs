//! `[embankment]`: the embankment beam under the whole track, between the sleepers' ballast and the `[ground]` — the
//! two-beam track on the ground (docs/theory.md §19): `[beam]` is one rail, `[sleepers]` its pads, sleepers and
//! ballast per rail seat, and each rail rests on half the embankment on half the strip. `interface = "tensionless"`
//! lets the sleepers lift off the ballast where it would pull them down (default `"bonded"`).

use crate::error::{Result, invalid};
use serde::{Deserialize, Serialize};

/// The embankment as a beam (whole track).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EmbankmentSection {
    /// EI_e (N·m²), > 0.
    pub bending_stiffness: f64,
    /// ρA_e (kg/m), ≥ 0.
    pub mass_per_length: f64,
    /// η_e ≥ 0, the fill's hysteretic damping (2ξ). Default 0.
    #[serde(default)]
    pub loss_factor: f64,
    /// How the ballast holds the sleepers on the embankment. Default bonded.
    #[serde(default)]
    pub interface: InterfaceKind,
}

/// `[embankment] interface`: the ballast between the sleepers and the embankment pulls as it pushes (`"bonded"`), or
/// only pushes (`"tensionless"`: the sleepers lift off where the track's weight no longer holds them down).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum InterfaceKind {
    /// Pushes and pulls: the linear track.
    #[default]
    Bonded,
    /// Pushes only.
    Tensionless,
}

impl EmbankmentSection {
    /// The embankment, its values checked by key.
    pub fn embankment(&self) -> Result<analytic::ground::Embankment> {
        let check = |key: &str, value: f64, positive: bool, unit: &str| {
            let fine = value.is_finite() && if positive { value > 0.0 } else { value >= 0.0 };
            let allowed = format!("must be finite and {} 0 ({unit})", if positive { ">" } else { "≥" });
            if fine { Ok(()) } else { Err(invalid(&format!("embankment.{key}"), value, allowed)) }
        };
        check("bending_stiffness", self.bending_stiffness, true, "N·m²")?;
        check("mass_per_length", self.mass_per_length, false, "kg/m")?;
        check("loss_factor", self.loss_factor, false, "1")?;
        Ok(analytic::ground::Embankment {
            bending_stiffness: self.bending_stiffness,
            mass_per_length: self.mass_per_length,
            loss_factor: self.loss_factor,
        })
    }
}
