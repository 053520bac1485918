//! The wheel–rail contact of a `[vehicle]` group (docs/theory.md §9, §12): the choice of law and its parameters,
//! each refused under the law it does not belong to.

use super::VehicleSection;
use crate::error::{Result, invalid};
use serde::{Deserialize, Serialize};
use track::vehicle::consist::WheelRail;

/// The wheel–rail contact law of `[vehicle]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum ContactKind {
    /// Hertz (`hertz_coefficient`, or `wheel_radius` for Zhai's fit; default 0.46 m).
    #[default]
    Hertz,
    /// A linear unilateral spring (`contact_stiffness`).
    Linear,
    /// A linear spring glued to the rail, pulling as well as pressing (`contact_stiffness`).
    Glued,
    /// Rigid unilateral contact with Newton's impact law (`restitution`, default 0).
    Rigid,
}

impl ContactKind {
    /// The name in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Self::Hertz => "hertz",
            Self::Linear => "linear",
            Self::Glued => "glued",
            Self::Rigid => "rigid",
        }
    }
}

impl VehicleSection {
    /// The contact law of this group of vehicles, its fields named under `path` (`vehicle`, `vehicle.behind[0]`).
    pub(crate) fn contact(&self, path: &str) -> Result<WheelRail> {
        let stiffness = self.contact_stiffness.unwrap_or(1.5e9);
        let given = [
            ("hertz_coefficient", self.hertz_coefficient.is_some(), self.contact == ContactKind::Hertz),
            ("wheel_radius", self.wheel_radius.is_some(), self.contact == ContactKind::Hertz),
            (
                "contact_stiffness",
                self.contact_stiffness.is_some(),
                matches!(self.contact, ContactKind::Linear | ContactKind::Glued),
            ),
            ("restitution", self.restitution.is_some(), self.contact == ContactKind::Rigid),
        ];
        if let Some((field, _, _)) = given.iter().find(|(_, given, taken)| *given && !taken) {
            return Err(invalid(
                &format!("{path}.{field}"),
                "given",
                format!("is not a parameter of contact = \"{}\"", self.contact.name()),
            ));
        }
        let contact = match self.contact {
            ContactKind::Hertz => match (self.hertz_coefficient, self.wheel_radius) {
                (Some(_), Some(r)) => {
                    return Err(invalid(
                        &format!("{path}.wheel_radius"),
                        r,
                        "give hertz_coefficient or wheel_radius, not both",
                    ));
                }
                (Some(coefficient), None) => WheelRail::Hertz { coefficient },
                (None, Some(radius)) => {
                    if !(radius.is_finite() && radius > 0.0) {
                        return Err(invalid(&format!("{path}.wheel_radius"), radius, "must be finite and > 0 (m)"));
                    }
                    WheelRail::hertz_for_radius(radius)
                }
                (None, None) => WheelRail::default(),
            },
            ContactKind::Linear => WheelRail::Linear { stiffness },
            ContactKind::Glued => WheelRail::Glued { stiffness },
            ContactKind::Rigid => WheelRail::Rigid { restitution: self.restitution.unwrap_or(0.0) },
        };
        contact.validate().map_err(|e| super::vehicle::in_group(path, e.into()))?;
        Ok(contact)
    }
}
