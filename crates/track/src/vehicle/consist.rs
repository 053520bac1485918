//! Vehicles on the rail together (docs/theory.md §12): a row of vehicles at offsets behind the first, their
//! wheel–rail contact, the rail's profile and the wheels' flats — what a run needs to couple them to the beam. A
//! train's axle layout can be populated with copies of one vehicle scaled to each axle's load.

use super::Vehicle;
use super::rail_car::RailCar;
use super::wheel_rail::WheelRail;
use crate::error::Result;
use crate::error::{Setting, invalid};
use fem_beam::Train;
use irregularity::{Profile, WheelFlat, WheelTrack};

/// Largest number of vehicles in one run (each adds a dense block and a moving interaction per wheel).
pub const MAX_VEHICLES: usize = 1_000;

/// Check a number of vehicles against 1 … [`MAX_VEHICLES`] (before any is built from it).
pub fn check_count(count: usize) -> Result<()> {
    if count == 0 || count > MAX_VEHICLES {
        return Err(invalid(
            Setting::Vehicle("vehicle.count"),
            count as f64,
            format!("must lie in 1 … {MAX_VEHICLES}"),
        ));
    }
    Ok(())
}

/// Largest ω_c·h a run with vehicles may take, ω_c = √(k_t/m_w) the stiffest wheel's contact mode (its tangent
/// contact stiffness at its static load over its own mass): at least π steps per period. The θ-method keeps an
/// unresolved mode bounded but not still — a wheel re-excited by its moving row every step rings at the step's
/// rate: measured on the reference track at 10 m/s, two quarter cars 2.5 m apart kept their wheel forces within
/// ±4 % of static at ω_c·h = 1.2 and 2.4, and swung ±80 % at 6.1 and ±30 % at 12.
pub const MAX_CONTACT_STEP: f64 = 2.0;

/// A vehicle and where it runs: `offset` (m) behind the first vehicle's reference point.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedVehicle {
    /// The vehicle.
    pub vehicle: Vehicle,
    /// Offset of its reference point behind the first vehicle's (m), ≥ 0.
    pub offset: f64,
    /// Its wheels' contact law, when not the run's ([`VehicleSettings::contact`]).
    pub contact: Option<WheelRail>,
}

impl PlacedVehicle {
    /// `vehicle` at `offset` (m) with the run's contact law.
    pub fn new(vehicle: Vehicle, offset: f64) -> Self {
        Self { vehicle, offset, contact: None }
    }
}

/// A wheel flat on one wheel of the run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatWheel {
    /// Which wheel, counted over the vehicles in order and each vehicle's wheels in order (0-based).
    pub wheel: usize,
    /// The flat.
    pub flat: WheelFlat,
}

/// The vehicles of a run, their contact with the rail and the rail's irregularity. Default: one quarter car
/// ([`super::builtin::QuarterCar`]) on a smooth rail, Hertz contact ([`WheelRail::default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleSettings {
    /// The vehicles, the first at offset 0.
    pub vehicles: Vec<PlacedVehicle>,
    /// The wheel–rail contact law of every vehicle that does not give its own ([`PlacedVehicle::contact`]).
    pub contact: WheelRail,
    /// The rail's profile r(x) (m, upward), the same under every wheel.
    pub profile: Profile,
    /// Wheel flats.
    pub flats: Vec<FlatWheel>,
}

impl Default for VehicleSettings {
    fn default() -> Self {
        let car = super::builtin::QuarterCar::default().vehicle().expect("the default quarter car is valid");
        Self {
            vehicles: vec![PlacedVehicle::new(car, 0.0)],
            contact: WheelRail::default(),
            profile: Profile::Smooth,
            flats: Vec::new(),
        }
    }
}

/// A wheel of the run: its vehicle, its index in the vehicle, its DOF there, and its offset behind the first
/// vehicle's reference point (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunWheel {
    /// Vehicle index.
    pub vehicle: usize,
    /// Wheel index within the vehicle.
    pub index: usize,
    /// DOF within the vehicle.
    pub dof: usize,
    /// Offset behind the first vehicle's reference point (m).
    pub offset: f64,
}

impl VehicleSettings {
    /// One vehicle at offset 0, the other settings at their defaults.
    pub fn single(vehicle: Vehicle) -> Self {
        Self { vehicles: vec![PlacedVehicle::new(vehicle, 0.0)], ..Self::default() }
    }

    /// A copy of `template` on every axle of `train` (at the axle's offset), each scaled so that its weight is the
    /// axle's force: M, C, K and f_g times P_i/W, which keeps every natural frequency and damping ratio. The
    /// template has one wheel, which runs at the axle; patches have no vehicle and are refused.
    pub fn populate(template: &Vehicle, train: &Train) -> Result<Self> {
        template.validate()?;
        if template.wheels.len() != 1 {
            return Err(invalid(
                Setting::Vehicle("vehicle.train"),
                template.wheels.len() as f64,
                "a train's axles take one-wheel vehicles (moving mass, quarter car), or rail cars four axles each \
                 (populate_cars); run other vehicles with several wheels in a row instead",
            ));
        }
        if !train.patches.is_empty() {
            return Err(invalid(
                Setting::Vehicle("vehicle.train"),
                train.patches.len() as f64,
                "load patches cannot carry vehicles",
            ));
        }
        let weight = -template.weight.iter().sum::<f64>();
        if weight.is_nan() || weight <= 0.0 {
            return Err(invalid(
                Setting::Vehicle("vehicle.weight"),
                weight,
                "must press the rail (total weight > 0 N) to scale",
            ));
        }
        let vehicles = train
            .axles
            .iter()
            .map(|axle| {
                let mut vehicle = template.scaled(axle.force / weight);
                vehicle.wheels[0].offset = 0.0;
                PlacedVehicle::new(vehicle, axle.offset)
            })
            .collect();
        Ok(Self { vehicles, ..Self::default() })
    }

    /// A rail car on every four consecutive axles of `train` ([`RailCar::on_axles`]: its geometry from the axles),
    /// scaled to their loads as [`VehicleSettings::populate`] scales ([`Vehicle::scaled`] by ΣP/W), each at its first
    /// axle's offset. Every four
    /// consecutive axles are read as one car of two two-axle bogies, which an articulated train (HSLM: coaches
    /// share bogies) is not. Patches have no vehicle and are refused.
    pub fn populate_cars(template: &RailCar, train: &Train) -> Result<Self> {
        template.validate()?;
        if !train.patches.is_empty() {
            return Err(invalid(
                Setting::Vehicle("vehicle.train"),
                train.patches.len() as f64,
                "load patches cannot carry vehicles",
            ));
        }
        let n = train.axles.len();
        if n == 0 || !n.is_multiple_of(4) {
            let allowed = "rail cars take four axles each: the train's axles must be a whole number of cars";
            return Err(invalid(Setting::Vehicle("vehicle.train"), n as f64, allowed));
        }
        let first = train.axles[0].offset;
        let mut vehicles = Vec::with_capacity(n / 4);
        for (car, axles) in train.axles.chunks_exact(4).enumerate() {
            let fitted = template.on_axles(axles, car)?;
            let load: f64 = axles.iter().map(|a| a.force).sum();
            let vehicle = fitted.vehicle()?.scaled(load / fitted.weight());
            vehicles.push(PlacedVehicle::new(vehicle, axles[0].offset - first));
        }
        Ok(Self { vehicles, ..Self::default() })
    }

    /// Check counts first, then each vehicle, the contact, the profile and the flats.
    pub fn validate(&self) -> Result<()> {
        check_count(self.vehicles.len())?;
        for placed in &self.vehicles {
            placed.vehicle.validate()?;
            if !(placed.offset.is_finite() && placed.offset >= 0.0) {
                return Err(invalid(Setting::Vehicle("vehicle.offset"), placed.offset, "must be finite and ≥ 0 (m)"));
            }
        }
        self.contact.validate()?;
        for placed in &self.vehicles {
            if let Some(contact) = placed.contact {
                contact.validate()?;
            }
        }
        self.static_train()?;
        self.profile.validate("rail")?;
        let wheels = self.wheels().count();
        for f in &self.flats {
            if f.wheel >= wheels {
                return Err(invalid(
                    Setting::Vehicle("vehicle.flats.wheel"),
                    f.wheel as f64,
                    format!("must be a wheel index < {wheels}"),
                ));
            }
            f.flat.validate("vehicle.flats")?;
        }
        Ok(())
    }

    /// Every wheel of the run, vehicle by vehicle.
    pub fn wheels(&self) -> impl Iterator<Item = RunWheel> + '_ {
        self.vehicles.iter().enumerate().flat_map(|(vehicle, placed)| {
            placed.vehicle.wheels.iter().enumerate().map(move |(index, w)| RunWheel {
                vehicle,
                index,
                dof: w.dof,
                offset: placed.offset + w.offset,
            })
        })
    }

    /// The distance from the first wheel to the last (m): what must cross the beam after the first wheel.
    pub fn length(&self) -> f64 {
        let offsets = self.wheels().map(|w| w.offset);
        let (lo, hi) = offsets.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
        if hi >= lo { hi - lo } else { 0.0 }
    }

    /// The offset of the foremost wheel behind the first vehicle's reference point (m).
    pub fn lead(&self) -> f64 {
        self.wheels().map(|w| w.offset).fold(f64::INFINITY, f64::min)
    }

    /// The contact law of `placed`'s wheels: its own, else the run's.
    pub fn contact_of(&self, placed: &PlacedVehicle) -> WheelRail {
        placed.contact.unwrap_or(self.contact)
    }

    /// The name of the run's contact laws for reports: the one law's, or `mixed`.
    pub fn contact_name(&self) -> &'static str {
        let first = self.contact_of(&self.vehicles[0]).name();
        if self.vehicles.iter().all(|p| self.contact_of(p).name() == first) { first } else { "mixed" }
    }

    /// What wheel `wheel` (run index) follows: the rail's profile and its flat, if any.
    pub fn track(&self, wheel: usize) -> WheelTrack {
        let flat = self.flats.iter().find(|f| f.wheel == wheel).map(|f| f.flat);
        WheelTrack { rail: self.profile.clone(), flat }
    }

    /// The moving forces of the vehicles standing on a level rail: an axle at each wheel (offset behind the first
    /// wheel) carrying its static load (N) — the static envelope a dynamic run is measured against. Errors when a
    /// vehicle has a DOF without a spring to a wheel (no static state).
    pub fn static_train(&self) -> Result<Train> {
        let lead = self.lead();
        let mut axles = Vec::new();
        for placed in &self.vehicles {
            let v = &placed.vehicle;
            let (_, forces) = v.static_state(&vec![0.0; v.wheels.len()])?;
            for (w, force) in v.wheels.iter().zip(forces) {
                axles.push(fem_beam::Axle { offset: placed.offset + w.offset - lead, force });
            }
        }
        Ok(Train { name: "vehicles".into(), axles, patches: Vec::new() })
    }

    /// ω_c (rad/s) of the stiffest wheel–rail contact mode: max over the wheels with mass of √(k_t/m_w), k_t the
    /// contact's tangent stiffness at the wheel's static load on a level rail, m_w the wheel DOF's mass (a massless
    /// wheel's contact mode is the rail's, and a rigid contact has none: not checked here). 0 if no wheel has one.
    pub fn contact_frequency(&self) -> Result<f64> {
        let mut largest = 0.0f64;
        // The static train's axles are the wheels, in order, with their static loads.
        for (wheel, axle) in self.wheels().zip(self.static_train()?.axles) {
            let placed = &self.vehicles[wheel.vehicle];
            let v = &placed.vehicle;
            let mass = v.mass[wheel.dof * v.dofs() + wheel.dof];
            if let (true, Some(stiffness)) = (mass > 0.0, self.contact_of(placed).tangent_stiffness(axle.force)) {
                largest = largest.max((stiffness / mass).sqrt());
            }
        }
        Ok(largest)
    }
}
