//! The wheel–rail contact of a `[vehicle]` group (docs/theory.md §9, §12): the choice of law and its parameters,
//! each refused under the law it does not belong to.

use super::VehicleSection;
use crate::error::{Result, invalid};
use track::vehicle::wheel_rail::{WheelRail, WheelRailKind};

impl VehicleSection {
    /// The contact law of this group of vehicles, its fields named under `path` (`vehicle`, `vehicle.behind[0]`).
    pub(crate) fn contact(&self, path: &str) -> Result<WheelRail> {
        let stiffness = self.contact_stiffness.unwrap_or(1.5e9);
        let given = [
            ("hertz_coefficient", self.hertz_coefficient.is_some(), self.contact == WheelRailKind::Hertz),
            ("wheel_radius", self.wheel_radius.is_some(), self.contact == WheelRailKind::Hertz),
            (
                "contact_stiffness",
                self.contact_stiffness.is_some(),
                matches!(self.contact, WheelRailKind::Linear | WheelRailKind::Glued),
            ),
            ("restitution", self.restitution.is_some(), self.contact == WheelRailKind::Rigid),
        ];
        if let Some((field, _, _)) = given.iter().find(|(_, given, taken)| *given && !taken) {
            return Err(invalid(
                &format!("{path}.{field}"),
                "given",
                format!("is not a parameter of contact = \"{}\"", self.contact.name()),
            ));
        }
        let contact = match self.contact {
            WheelRailKind::Hertz => match (self.hertz_coefficient, self.wheel_radius) {
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
            WheelRailKind::Linear => WheelRail::Linear { stiffness },
            WheelRailKind::Glued => WheelRail::Glued { stiffness },
            WheelRailKind::Rigid => WheelRail::Rigid { restitution: self.restitution.unwrap_or(0.0) },
        };
        contact.validate().map_err(|e| super::vehicle::in_group(path, e.into()))?;
        Ok(contact)
    }
}
