//! `[vehicle]`: vehicles instead of moving forces and their wheel–rail contact (docs/theory.md §12) — the schema
//! and its translation into [`track::vehicle`] settings, every error named by its path in the scenario file. The
//! rail under them: [`super::rail`].

use crate::error::StudyError;
use crate::error::{Result, invalid};
use fem_beam::Train;
use irregularity::{Profile, WheelFlat};
use serde::{Deserialize, Serialize};
use track::vehicle::Vehicle;
use track::vehicle::builtin::{MovingMass, QuarterCar};
use track::vehicle::consist::{FlatWheel, PlacedVehicle, VehicleSettings};
use track::vehicle::rail_car::RailCar;
use track::vehicle::wheel_rail::WheelRailKind;

/// The kind of vehicle of `[vehicle]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum VehicleKind {
    /// A moving mass m (`mass`).
    MovingMass,
    /// A quarter car (`body_mass`, `suspension_stiffness`, `suspension_damping`, `wheel_mass`).
    #[default]
    QuarterCar,
    /// The 2-D rail car (`[vehicle.rail_car]`).
    RailCar,
    /// A vehicle given by its matrices (`[vehicle.matrices]`).
    Matrices,
}

impl VehicleKind {
    /// The name in the scenario file.
    pub fn name(self) -> &'static str {
        match self {
            Self::MovingMass => "moving-mass",
            Self::QuarterCar => "quarter-car",
            Self::RailCar => "rail-car",
            Self::Matrices => "matrices",
        }
    }
}

/// `[vehicle]`: vehicles instead of moving forces. Without a train in `[load]`, `count` vehicles `spacing` m apart,
/// each with its own weight (`[load] force` is not used); with a train, one vehicle per axle, scaled to the axle's
/// force (frequencies and damping ratios kept).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct VehicleSection {
    /// What vehicle.
    pub kind: VehicleKind,
    /// Moving mass m (kg); default 8 501 kg (83.4 kN).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// Quarter car: body mass M_s (kg), default 7 500.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub body_mass: Option<f64>,
    /// Quarter car: k_s (N/m), default 1.2e6.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub suspension_stiffness: Option<f64>,
    /// Quarter car: c_s (N·s/m), default 3e4.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub suspension_damping: Option<f64>,
    /// Quarter car: m_u (kg), default 1 000.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wheel_mass: Option<f64>,
    /// The 2-D rail car's parameters (defaults: [`RailCar::default`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rail_car: Option<RailCar>,
    /// A vehicle by its matrices.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub matrices: Option<MatricesSection>,
    /// Number of vehicles in a row (without a train). Default 1.
    pub count: usize,
    /// Distance between consecutive vehicles (m), needed when count > 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spacing: Option<f64>,
    /// The wheel–rail contact law.
    pub contact: WheelRailKind,
    /// Hertz coefficient C_H (N/m^1.5); default from `wheel_radius`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hertz_coefficient: Option<f64>,
    /// Wheel radius (m) for Zhai's fit of C_H; default 0.46.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wheel_radius: Option<f64>,
    /// k_c (N/m) of a linear or glued contact; default 1.5e9 (Hertz's tangent at 83.4 kN).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_stiffness: Option<f64>,
    /// Newton's coefficient of restitution e ∈ [0, 1] of a rigid contact; default 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// `[[vehicle.flats]]`: wheel flats.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub flats: Vec<FlatSection>,
    /// Of a `[[vehicle.behind]]` group: how far its first vehicle runs behind the first vehicle of `[vehicle]` (m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub offset: Option<f64>,
    /// `[[vehicle.behind]]`: further groups of vehicles behind the first, each a `[vehicle]` table of its own (kind,
    /// parameters, count, spacing, contact, flats) with its `offset`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub behind: Vec<VehicleSection>,
}

impl Default for VehicleSection {
    fn default() -> Self {
        Self {
            kind: VehicleKind::QuarterCar,
            mass: None,
            body_mass: None,
            suspension_stiffness: None,
            suspension_damping: None,
            wheel_mass: None,
            rail_car: None,
            matrices: None,
            count: 1,
            spacing: None,
            contact: WheelRailKind::Hertz,
            hertz_coefficient: None,
            wheel_radius: None,
            contact_stiffness: None,
            restitution: None,
            flats: Vec::new(),
            offset: None,
            behind: Vec::new(),
        }
    }
}

impl VehicleSection {
    /// Whether this group or one behind it meets the rail through a rigid (Signorini + impact) contact.
    pub fn has_rigid_contact(&self) -> bool {
        self.contact == WheelRailKind::Rigid || self.behind.iter().any(Self::has_rigid_contact)
    }
}

/// `[vehicle.matrices]`: M, C, K (rows of n numbers each), the weights and the wheels.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct MatricesSection {
    /// A name for reports.
    pub name: String,
    /// M (kg, kg·m²), n rows of n.
    pub mass: Vec<Vec<f64>>,
    /// C (N·s/m).
    pub damping: Vec<Vec<f64>>,
    /// K (N/m).
    pub stiffness: Vec<Vec<f64>>,
    /// Gravity loads f_g per DOF (N, upward positive: −m g on a translation).
    pub weight: Vec<f64>,
    /// `[[vehicle.matrices.wheels]]`.
    pub wheels: Vec<WheelSection>,
    /// The DOF whose acceleration is reported as the body's (0-based). Default 0.
    pub body: usize,
}

/// A wheel of a vehicle given by its matrices.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WheelSection {
    /// Its DOF (0-based).
    pub dof: usize,
    /// Offset behind the vehicle's reference point (m).
    pub offset: f64,
}

/// The default wheel of a flat: the first, numbered from 1.
fn first_wheel() -> usize {
    1
}

/// `[[vehicle.flats]]`: a wheel flat.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FlatSection {
    /// Which wheel of its group (`[vehicle]` or a `[[vehicle.behind]]`), counted from 1 over the group's vehicles in
    /// order — for `[vehicle]` the wheel's number in the run, as every report numbers it. Default 1.
    #[serde(default = "first_wheel")]
    pub wheel: usize,
    /// Flat length ℓ (m).
    pub length: f64,
    /// Wheel diameter D (m). Default 0.92.
    #[serde(default = "default_diameter")]
    pub diameter: f64,
    /// The wheel's travel when the flat first meets the rail (m). Default 0.
    #[serde(default)]
    pub first_contact: f64,
}

fn default_diameter() -> f64 {
    0.92
}

impl VehicleSection {
    /// One vehicle of this group, its parameters checked and named under `path` (`vehicle`,
    /// `vehicle.behind[0]`).
    pub fn vehicle(&self, path: &str) -> Result<Vehicle> {
        self.build_vehicle(path).map_err(|e| in_group(path, e))
    }

    fn build_vehicle(&self, path: &str) -> Result<Vehicle> {
        let unused = |field: &str, given: bool| {
            if given {
                Err(invalid(
                    &format!("{path}.{field}"),
                    "given",
                    format!("is not a parameter of kind = \"{}\"", self.kind.name()),
                ))
            } else {
                Ok(())
            }
        };
        let quarter = [self.body_mass, self.suspension_stiffness, self.suspension_damping, self.wheel_mass];
        match self.kind {
            VehicleKind::MovingMass => {
                unused("body_mass … wheel_mass", quarter.iter().any(Option::is_some))?;
                unused("rail_car", self.rail_car.is_some())?;
                unused("matrices", self.matrices.is_some())?;
                let mass = self.mass.unwrap_or(MovingMass::default().mass);
                Ok(MovingMass { mass }.vehicle()?)
            }
            VehicleKind::QuarterCar => {
                unused("mass", self.mass.is_some())?;
                unused("rail_car", self.rail_car.is_some())?;
                unused("matrices", self.matrices.is_some())?;
                let d = QuarterCar::default();
                Ok(QuarterCar {
                    body_mass: self.body_mass.unwrap_or(d.body_mass),
                    suspension_stiffness: self.suspension_stiffness.unwrap_or(d.suspension_stiffness),
                    suspension_damping: self.suspension_damping.unwrap_or(d.suspension_damping),
                    wheel_mass: self.wheel_mass.unwrap_or(d.wheel_mass),
                }
                .vehicle()?)
            }
            VehicleKind::RailCar => {
                unused("mass", self.mass.is_some())?;
                unused("body_mass … wheel_mass", quarter.iter().any(Option::is_some))?;
                unused("matrices", self.matrices.is_some())?;
                // The car's fields live under [vehicle.rail_car]: errors name them there.
                let car = self.rail_car.unwrap_or_default().vehicle();
                car.map_err(|e| in_group(&format!("{path}.rail_car"), e.into()))
            }
            VehicleKind::Matrices => {
                unused("mass", self.mass.is_some())?;
                unused("body_mass … wheel_mass", quarter.iter().any(Option::is_some))?;
                unused("rail_car", self.rail_car.is_some())?;
                let m = self.matrices.as_ref().ok_or_else(|| {
                    invalid(&format!("{path}.matrices"), "missing", "kind = \"matrices\" needs a matrices table")
                })?;
                let n = m.weight.len();
                let flat = |field: &str, rows: &[Vec<f64>]| -> Result<Vec<f64>> {
                    if rows.len() != n || rows.iter().any(|r| r.len() != n) {
                        return Err(invalid(
                            &format!("{path}.matrices.{field}"),
                            rows.len(),
                            format!("needs {n} rows of {n} numbers (one per entry of weight)"),
                        ));
                    }
                    Ok(rows.concat())
                };
                let vehicle = Vehicle {
                    name: if m.name.is_empty() { "vehicle".into() } else { m.name.clone() },
                    mass: flat("mass", &m.mass)?,
                    damping: flat("damping", &m.damping)?,
                    stiffness: flat("stiffness", &m.stiffness)?,
                    weight: m.weight.clone(),
                    wheels: m.wheels.iter().map(|w| track::vehicle::Wheel { dof: w.dof, offset: w.offset }).collect(),
                    body: m.body,
                };
                vehicle.validate().map_err(|e| in_group(&format!("{path}.matrices"), e.into()))?;
                Ok(vehicle)
            }
        }
    }

    /// The vehicles of a run: this group — over `train`, one vehicle per axle; without one, `count` of them `spacing`
    /// apart — then every `[[vehicle.behind]]` group at its offset, each vehicle with its group's contact law and
    /// flats (wheels counted within the group); over the rail's profile made by `profile` for the distance from the
    /// first vehicle's reference point to the last wheel (m).
    pub fn settings(
        &self,
        train: Option<&Train>,
        profile: impl FnOnce(f64) -> Result<Profile>,
    ) -> Result<VehicleSettings> {
        if let Some(offset) = self.offset {
            return Err(invalid(
                "vehicle.offset",
                offset,
                "the first group runs at 0: offset is for [[vehicle.behind]]",
            ));
        }
        let mut settings = self.group("vehicle", train)?;
        if train.is_some() && !self.behind.is_empty() {
            let allowed = "with a train in [load] there is one vehicle per axle: no groups behind";
            return Err(invalid("vehicle.behind", self.behind.len(), allowed));
        }
        for (i, group) in self.behind.iter().enumerate() {
            let path = format!("vehicle.behind[{i}]");
            if !group.behind.is_empty() {
                return Err(invalid(&format!("{path}.behind"), group.behind.len(), "groups do not nest"));
            }
            let offset = match group.offset {
                Some(x) if x.is_finite() && x >= 0.0 => x,
                x => {
                    let value = x.map_or("missing".into(), |x| x.to_string());
                    return Err(invalid(&format!("{path}.offset"), value, "must be finite and ≥ 0 (m)"));
                }
            };
            let more = group.group(&path, None)?;
            let wheels = settings.wheels().count();
            settings.flats.extend(more.flats.into_iter().map(|f| FlatWheel { wheel: wheels + f.wheel, ..f }));
            settings
                .vehicles
                .extend(more.vehicles.into_iter().map(|p| PlacedVehicle { offset: offset + p.offset, ..p }));
        }
        settings.profile = profile(settings.lead() + settings.length())?;
        settings.validate()?;
        Ok(settings)
    }

    /// This group alone, named under `path`: its vehicles from offset 0, each with the group's contact law, and its
    /// flats by wheel within the group.
    fn group(&self, path: &str, train: Option<&Train>) -> Result<VehicleSettings> {
        let vehicle = self.vehicle(path)?;
        let mut settings = match train {
            Some(train) => {
                if self.count != 1 || self.spacing.is_some() {
                    return Err(invalid(
                        &format!("{path}.count"),
                        self.count,
                        "with a train in [load] there is one vehicle per axle: leave count and spacing out",
                    ));
                }
                let populated = match self.kind {
                    VehicleKind::RailCar => VehicleSettings::populate_cars(&self.rail_car.unwrap_or_default(), train),
                    _ => VehicleSettings::populate(&vehicle, train),
                };
                populated.map_err(|e| in_group(path, e.into()))?
            }
            None => {
                let count = self.count;
                track::vehicle::consist::check_count(count).map_err(|e| in_group(path, e.into()))?;
                let spacing = match (count, self.spacing) {
                    (1, s) => s.unwrap_or(0.0),
                    (_, Some(s)) if s.is_finite() && s > 0.0 => s,
                    (_, s) => {
                        let allowed = "must be finite and > 0 (m) with more than one vehicle";
                        let value = s.map_or("missing".into(), |s| s.to_string());
                        return Err(invalid(&format!("{path}.spacing"), value, allowed));
                    }
                };
                let vehicles = (0..count).map(|i| PlacedVehicle::new(vehicle.clone(), i as f64 * spacing)).collect();
                VehicleSettings { vehicles, ..VehicleSettings::default() }
            }
        };
        let contact = self.contact(path)?;
        settings.contact = contact;
        settings.vehicles.iter_mut().for_each(|p| p.contact = Some(contact));
        let wheels = settings.wheels().count();
        for (i, f) in self.flats.iter().enumerate() {
            if !(1..=wheels).contains(&f.wheel) {
                let allowed = format!("must be a wheel of this group, numbered from 1: 1 … {wheels}");
                return Err(invalid(&format!("{path}.flats[{i}].wheel"), f.wheel, allowed));
            }
            let flat = WheelFlat { length: f.length, diameter: f.diameter, first_contact: f.first_contact };
            settings.flats.push(FlatWheel { wheel: f.wheel - 1, flat });
        }
        Ok(settings)
    }
}

/// An error of the library's vehicle checks, which name their fields `vehicle.…`, named under the group's `path`.
pub(crate) fn in_group(path: &str, error: StudyError) -> StudyError {
    let rename = |field: &str| match field.strip_prefix("vehicle.") {
        Some(rest) if path != "vehicle" => format!("{path}.{rest}"),
        _ => field.to_string(),
    };
    match error {
        StudyError::Stepping(nscd::NscdError::InvalidField { field, value, allowed }) => {
            StudyError::InvalidField { path: rename(field), value: crate::number::number(value), allowed }
        }
        StudyError::InvalidField { path: field, value, allowed } => {
            StudyError::InvalidField { path: rename(&field), value, allowed }
        }
        other => other,
    }
}
