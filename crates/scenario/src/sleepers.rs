//! The `[sleepers]` section (docs/theory.md §18): discrete supports under the rail — `spacing`, `first`, `mass` per
//! rail seat, `[sleepers.pad]` and `[sleepers.ballast]` each with `stiffness` (N/m), `damping` (N·s/m) and
//! `loss_factor`. What is left out takes a typical ballasted track's value (`fem_beam::Sleepers::default`).

use fem_beam::{Layer, Sleepers};
use serde::{Deserialize, Serialize};

/// `[sleepers]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SleepersSection {
    /// a (m).
    pub spacing: f64,
    /// The first sleeper's place (m); default half a spacing.
    pub first: Option<f64>,
    /// m_s (kg per rail seat).
    pub mass: f64,
    /// The rail pad: what is left out takes the typical pad's value.
    pub pad: LayerSection,
    /// The ballast: what is left out takes the typical ballast's value.
    pub ballast: LayerSection,
}

/// `[sleepers.pad]` or `[sleepers.ballast]`: each key left out takes the layer's typical value.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LayerSection {
    /// k (N/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// c (N·s/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping: Option<f64>,
    /// η (frequency domain only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss_factor: Option<f64>,
}

impl LayerSection {
    /// The layer, what is left out taken from `typical`.
    fn layer(&self, typical: Layer) -> Layer {
        Layer {
            stiffness: self.stiffness.unwrap_or(typical.stiffness),
            damping: self.damping.unwrap_or(typical.damping),
            loss_factor: self.loss_factor.unwrap_or(typical.loss_factor),
        }
    }
}

impl Default for SleepersSection {
    fn default() -> Self {
        let s = Sleepers::default();
        Self {
            spacing: s.spacing,
            first: None,
            mass: s.mass,
            pad: LayerSection::default(),
            ballast: LayerSection::default(),
        }
    }
}

impl SleepersSection {
    /// The sleepers (checked when the model places them).
    pub fn sleepers(&self) -> Sleepers {
        let typical = Sleepers::default();
        Sleepers {
            spacing: self.spacing,
            first: self.first.unwrap_or(0.5 * self.spacing),
            mass: self.mass,
            pad: self.pad.layer(typical.pad),
            ballast: self.ballast.layer(typical.ballast),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A key left out of `[sleepers.ballast]` takes the ballast's typical value, not the pad's.
    #[test]
    fn each_layer_takes_its_own_defaults() {
        let section: SleepersSection =
            toml::from_str("[ballast]\nloss_factor = 1.0\n[pad]\nstiffness = 5e8\n").unwrap();
        let (s, typical) = (section.sleepers(), Sleepers::default());
        assert_eq!(s.ballast, Layer { loss_factor: 1.0, ..typical.ballast });
        assert_eq!(s.pad, Layer { stiffness: 5e8, ..typical.pad });
        assert_eq!(s.first, 0.3);
    }
}
