//! The built-in vehicles (docs/theory.md §12): the moving mass m (one wheel DOF, m z̈ = −m g + λ) and the quarter car
//! (a body M_s on a suspension k_s, c_s over an unsprung wheel m_u; DOFs body, wheel). Parameter structs with defaults
//! and one `validate`; each builds its [`Vehicle`].

use super::{GRAVITY, Vehicle, Wheel};
use crate::error::Result;
use crate::error::{Setting, invalid};

/// A moving mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovingMass {
    /// m (kg) > 0; default 8 500 kg, the 83.4 kN of the reference load.
    pub mass: f64,
}

impl Default for MovingMass {
    fn default() -> Self {
        Self { mass: 83.4e3 / GRAVITY }
    }
}

impl MovingMass {
    /// Check m.
    pub fn validate(&self) -> Result<()> {
        if !(self.mass.is_finite() && self.mass > 0.0) {
            return Err(invalid(Setting::Vehicle("vehicle.mass"), self.mass, "must be finite and > 0 (kg)"));
        }
        Ok(())
    }

    /// The vehicle: one DOF, the wheel.
    pub fn vehicle(&self) -> Result<Vehicle> {
        self.validate()?;
        Ok(Vehicle {
            name: "moving mass".into(),
            mass: vec![self.mass],
            damping: vec![0.0],
            stiffness: vec![0.0],
            weight: vec![-self.mass * GRAVITY],
            wheels: vec![Wheel { dof: 0, offset: 0.0 }],
            body: 0,
        })
    }
}

/// A quarter car. Defaults: a quarter of a passenger coach over one wheel — M_s = 7 500 kg on k_s = 1.2 MN/m,
/// c_s = 30 kN·s/m (f = 2.0 Hz, ζ = 0.16), m_u = 1 000 kg (half a wheelset), 83.4 kN in all.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuarterCar {
    /// M_s (kg) > 0.
    pub body_mass: f64,
    /// k_s (N/m) > 0.
    pub suspension_stiffness: f64,
    /// c_s (N·s/m) ≥ 0.
    pub suspension_damping: f64,
    /// m_u (kg) ≥ 0 (0: a massless contact point under the suspension, the sprung mass of textbooks).
    pub wheel_mass: f64,
}

impl Default for QuarterCar {
    fn default() -> Self {
        Self { body_mass: 7_500.0, suspension_stiffness: 1.2e6, suspension_damping: 30e3, wheel_mass: 1_000.0 }
    }
}

impl QuarterCar {
    /// Check the parameters.
    pub fn validate(&self) -> Result<()> {
        let positive = |field: &'static str, v: f64, unit: &str| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(invalid(Setting::Vehicle(field), v, format!("must be finite and > 0 ({unit})")))
            }
        };
        positive("vehicle.body_mass", self.body_mass, "kg")?;
        positive("vehicle.suspension_stiffness", self.suspension_stiffness, "N/m")?;
        for (field, v, unit) in [
            ("vehicle.suspension_damping", self.suspension_damping, "N·s/m"),
            ("vehicle.wheel_mass", self.wheel_mass, "kg"),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(invalid(Setting::Vehicle(field), v, format!("must be finite and ≥ 0 ({unit})")));
            }
        }
        Ok(())
    }

    /// The natural frequency of the body on its suspension, ω_n = √(k_s/M_s) (rad/s).
    pub fn body_frequency(&self) -> f64 {
        (self.suspension_stiffness / self.body_mass).sqrt()
    }

    /// The suspension's damping ratio ζ = c_s/(2√(k_s M_s)).
    pub fn damping_ratio(&self) -> f64 {
        self.suspension_damping / (2.0 * (self.suspension_stiffness * self.body_mass).sqrt())
    }

    /// The vehicle: DOF 0 the body, DOF 1 the wheel.
    pub fn vehicle(&self) -> Result<Vehicle> {
        self.validate()?;
        let (k, c) = (self.suspension_stiffness, self.suspension_damping);
        Ok(Vehicle {
            name: "quarter car".into(),
            mass: vec![self.body_mass, 0.0, 0.0, self.wheel_mass],
            damping: vec![c, -c, -c, c],
            stiffness: vec![k, -k, -k, k],
            weight: vec![-self.body_mass * GRAVITY, -self.wheel_mass * GRAVITY],
            wheels: vec![Wheel { dof: 1, offset: 0.0 }],
            body: 0,
        })
    }
}
