//! The wheel–rail contact (docs/theory.md §9, §12): the law a wheel meets the rail with — [`WheelRail`], with its
//! parameter — and the choice of law alone, [`WheelRailKind`] (what a scenario file's `contact` key names).

use crate::error::Result;
use crate::error::{Setting, invalid};

/// The choice of wheel–rail law, without its parameter; named in scenario files and reports in kebab case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum WheelRailKind {
    /// Hertz's law (the default).
    #[default]
    Hertz,
    /// A linear unilateral spring.
    Linear,
    /// A linear spring glued to the rail, pulling as well as pressing.
    Glued,
    /// Rigid unilateral contact with Newton's impact law.
    Rigid,
}

impl WheelRailKind {
    /// The name in scenario files and reports.
    pub fn name(self) -> &'static str {
        match self {
            Self::Hertz => "hertz",
            Self::Linear => "linear",
            Self::Glued => "glued",
            Self::Rigid => "rigid",
        }
    }
}

/// The wheel–rail contact law (docs/theory.md §9, §12), of a run or of one vehicle. Default: Hertz with
/// C_H = 8.6e10 N/m^1.5 ([`WheelRail::hertz_for_radius`] of a 0.46 m wheel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WheelRail {
    /// Hertz's law λ = C_H⟨δ⟩₊^{3/2} (unilateral), solved by Newton iterations within each step.
    Hertz {
        /// C_H (N/m^1.5) > 0.
        coefficient: f64,
    },
    /// A linear spring k_c in series with a unilateral stop: λ = k_c⟨δ⟩₊.
    Linear {
        /// k_c (N/m) > 0.
        stiffness: f64,
    },
    /// The wheel glued to the rail by a linear spring that also pulls (λ = k_c δ of either sign): the bilateral
    /// reference a unilateral contact equals while it presses.
    Glued {
        /// k_c (N/m) > 0.
        stiffness: f64,
    },
    /// Rigid contact: Signorini's condition with Newton's impact law U⁺ = −eU⁻, held at velocity level in the step
    /// and at position level by the projection after it ([`nscd::position`]): the limit of the compliant laws as
    /// their stiffness grows.
    Rigid {
        /// Newton's coefficient of restitution e ∈ [0, 1] (0: plastic landings).
        restitution: f64,
    },
}

impl Default for WheelRail {
    fn default() -> Self {
        Self::hertz_for_radius(0.46)
    }
}

impl WheelRail {
    /// Hertz's coefficient of a wheel of `radius` (m) on a rail by Zhai's fit G = 4.57·R^−0.149·10⁻⁸ m/N^{2/3}
    /// (Zhai, Vehicle–Track Coupled Dynamics, 2020), C_H = G^{−3/2}: 8.6e10 N/m^1.5 at R = 0.46 m.
    pub fn hertz_for_radius(radius: f64) -> Self {
        let g = 4.57 * radius.powf(-0.149) * 1e-8;
        Self::Hertz { coefficient: g.powf(-1.5) }
    }

    /// Check the parameter, named by its field.
    pub fn validate(&self) -> Result<()> {
        let (field, value) = match *self {
            Self::Hertz { coefficient } => ("vehicle.hertz_coefficient", coefficient),
            Self::Linear { stiffness } | Self::Glued { stiffness } => ("vehicle.contact_stiffness", stiffness),
            Self::Rigid { restitution } => {
                if !(restitution.is_finite() && (0.0..=1.0).contains(&restitution)) {
                    return Err(invalid(Setting::Vehicle("vehicle.restitution"), restitution, "must lie in [0, 1]"));
                }
                return Ok(());
            }
        };
        if !(value.is_finite() && value > 0.0) {
            let unit = if matches!(self, Self::Hertz { .. }) { "N/m^1.5" } else { "N/m" };
            return Err(invalid(Setting::Vehicle(field), value, format!("must be finite and > 0 ({unit})")));
        }
        Ok(())
    }

    /// The engine's law of this contact (gap field 0: a wheel's gap is set every step).
    pub fn law(&self) -> friction::Law {
        match *self {
            Self::Hertz { coefficient } => friction::Law::Hertz { gap: 0.0, coefficient },
            Self::Linear { stiffness } => friction::Law::Compliant { gap: 0.0, stiffness },
            Self::Glued { stiffness } => friction::Law::Spring { gap: 0.0, stiffness },
            Self::Rigid { restitution } => friction::Law::Signorini { gap: 0.0, restitution },
        }
    }

    /// The penetration δ (m) that carries a static wheel load `force` (N): (Q/C_H)^{2/3}, Q/k_c, or 0 when rigid.
    pub fn static_penetration(&self, force: f64) -> f64 {
        match *self {
            Self::Hertz { coefficient } => (force.max(0.0) / coefficient).powf(2.0 / 3.0),
            Self::Linear { stiffness } | Self::Glued { stiffness } => force / stiffness,
            Self::Rigid { .. } => 0.0,
        }
    }

    /// The tangent stiffness dλ/dδ (N/m) at a wheel load `force` (N): (3/2)C_H^{2/3}Q^{1/3}, or k_c; None when
    /// rigid (no contact mode: the wheel moves with the rail).
    pub fn tangent_stiffness(&self, force: f64) -> Option<f64> {
        match *self {
            Self::Hertz { coefficient } => Some(1.5 * coefficient.powf(2.0 / 3.0) * force.max(0.0).cbrt()),
            Self::Linear { stiffness } | Self::Glued { stiffness } => Some(stiffness),
            Self::Rigid { .. } => None,
        }
    }

    /// Whether the wheel can leave the rail under this law: every law but the glued spring, which pulls instead
    /// (a tensile force is then tension, not a loss of contact).
    pub fn separates(&self) -> bool {
        !matches!(self, Self::Glued { .. })
    }

    /// Which law this is, without its parameter.
    pub fn kind(&self) -> WheelRailKind {
        match self {
            Self::Hertz { .. } => WheelRailKind::Hertz,
            Self::Linear { .. } => WheelRailKind::Linear,
            Self::Glued { .. } => WheelRailKind::Glued,
            Self::Rigid { .. } => WheelRailKind::Rigid,
        }
    }

    /// The law's name for reports: `hertz`, `linear`, `glued` or `rigid`.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }
}
