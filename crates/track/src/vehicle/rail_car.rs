//! The 2-D rail car (docs/theory.md §12): a car body (bounce z_c, pitch φ_c) on two bogies (z_b, φ_b) through
//! secondary suspensions at ±l_c from the body's centre, each bogie on two wheelsets through primary suspensions at
//! ±l_b from the bogie's centre — 10 DOFs. Pitch is nose-up positive, so a point a ahead of a centre moves z + a·φ.
//!
//! Each suspension is a spring and a dashpot on the relative displacement d = gᵀx of its two ends, adding k·g gᵀ to
//! K and c·g gᵀ to C; the masses and inertias are diagonal; the weights act on the translations.
//!
//! The DOFs are ordered along the car — wheel 1, wheel 2, front bogie (z, φ), body (z, φ), rear bogie (z, φ), wheel
//! 3, wheel 4 — so that every spring couples DOFs at most 3 apart: the car's band is the Hermite beam's, and stacking
//! it beside the beam costs the beam nothing.
//!
//! Defaults: one rail's half of the passenger car of Huo & Dai's linearised vehicle–track model (Shock and
//! Vibration 2019, 2015465, Table 1): car body 34 500 kg and 1.5604e6 kg·m² in pitch, bogies 3 500 kg and
//! 1 722 kg·m², wheelsets 2 200 kg; per side a primary suspension of 1.173 MN/m and 19.6 kN·s/m at each axle box, a
//! secondary of 0.61 MN/m and 9.8 kN·s/m at each bogie; l_c = 8.75 m, l_b = 1.25 m. Half of every mass and inertia,
//! one side's suspensions: 61.7 kN on each wheel; the body bounces at about 1.2 Hz on the secondaries in series
//! with the primaries (√(2k/M_c), k = k_s·2k_p/(k_s + 2k_p)).

use super::{GRAVITY, Vehicle, Wheel};
use crate::error::Result;
use crate::error::{Setting, invalid};
use fem_beam::Axle;

/// A 2-D rail car's parameters, for one rail.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(default, deny_unknown_fields))]
pub struct RailCar {
    /// Car body mass M_c (kg) > 0.
    pub body_mass: f64,
    /// Car body pitch inertia J_c (kg·m²) > 0.
    pub body_pitch_inertia: f64,
    /// Bogie mass M_b (kg) > 0.
    pub bogie_mass: f64,
    /// Bogie pitch inertia J_b (kg·m²) > 0.
    pub bogie_pitch_inertia: f64,
    /// Wheelset mass M_w (kg) ≥ 0.
    pub wheelset_mass: f64,
    /// Primary suspension stiffness k_p (N/m) > 0, per wheel.
    pub primary_stiffness: f64,
    /// Primary suspension damping c_p (N·s/m) ≥ 0.
    pub primary_damping: f64,
    /// Secondary suspension stiffness k_s (N/m) > 0, per bogie.
    pub secondary_stiffness: f64,
    /// Secondary suspension damping c_s (N·s/m) ≥ 0.
    pub secondary_damping: f64,
    /// Half the distance between the bogie centres l_c (m) > l_b.
    pub bogie_half_distance: f64,
    /// Half the bogie's wheelbase l_b (m) > 0.
    pub axle_half_distance: f64,
}

impl Default for RailCar {
    fn default() -> Self {
        Self {
            body_mass: 34_500.0 / 2.0,
            body_pitch_inertia: 1_560_400.0 / 2.0,
            bogie_mass: 3_500.0 / 2.0,
            bogie_pitch_inertia: 1_722.0 / 2.0,
            wheelset_mass: 2_200.0 / 2.0,
            primary_stiffness: 1.173e6,
            primary_damping: 19.6e3,
            secondary_stiffness: 0.61e6,
            secondary_damping: 9.8e3,
            bogie_half_distance: 8.75,
            axle_half_distance: 1.25,
        }
    }
}

/// DOF indices, in the banded order of the module note.
const WHEELS: [usize; 4] = [0, 1, 8, 9];
const BOGIE_Z: [usize; 2] = [2, 6];
const BOGIE_PITCH: [usize; 2] = [3, 7];
const BODY_Z: usize = 4;
const BODY_PITCH: usize = 5;

impl RailCar {
    /// Check the parameters, each named by its field.
    pub fn validate(&self) -> Result<()> {
        for (field, value, unit) in [
            ("vehicle.body_mass", self.body_mass, "kg"),
            ("vehicle.body_pitch_inertia", self.body_pitch_inertia, "kg·m²"),
            ("vehicle.bogie_mass", self.bogie_mass, "kg"),
            ("vehicle.bogie_pitch_inertia", self.bogie_pitch_inertia, "kg·m²"),
            ("vehicle.primary_stiffness", self.primary_stiffness, "N/m"),
            ("vehicle.secondary_stiffness", self.secondary_stiffness, "N/m"),
            ("vehicle.axle_half_distance", self.axle_half_distance, "m"),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(invalid(Setting::Vehicle(field), value, format!("must be finite and > 0 ({unit})")));
            }
        }
        for (field, value, unit) in [
            ("vehicle.wheelset_mass", self.wheelset_mass, "kg"),
            ("vehicle.primary_damping", self.primary_damping, "N·s/m"),
            ("vehicle.secondary_damping", self.secondary_damping, "N·s/m"),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(invalid(Setting::Vehicle(field), value, format!("must be finite and ≥ 0 ({unit})")));
            }
        }
        let (lc, lb) = (self.bogie_half_distance, self.axle_half_distance);
        if !(lc.is_finite() && lc > lb) {
            let allowed = format!("must be finite and > axle_half_distance = {lb} m (the bogies must not overlap)");
            return Err(invalid(Setting::Vehicle("vehicle.bogie_half_distance"), lc, allowed));
        }
        Ok(())
    }

    /// The total weight (N).
    pub fn weight(&self) -> f64 {
        (self.body_mass + 2.0 * self.bogie_mass + 4.0 * self.wheelset_mass) * GRAVITY
    }

    /// This car's geometry fitted to four consecutive axles of a train (offsets a₀ < a₁ < a₂ < a₃ in m, forces in
    /// N): l_b = (a₁ − a₀)/2, l_c = (a₂ − a₀)/2, masses and suspension as they are (the caller scales the vehicle to
    /// the axles' load, [`crate::vehicle::Vehicle::scaled`]). The two bogies' wheelbases must agree (a₃ − a₂ = a₁ − a₀
    /// within 1 mm) and the four forces within 0.1 % of their mean: a symmetric car carries equal wheel loads. `car`
    /// names the car in errors (0-based).
    pub fn on_axles(&self, axles: &[Axle], car: usize) -> Result<Self> {
        let [a0, a1, a2, a3] = [0, 1, 2, 3].map(|i| axles[i].offset);
        let (front, rear) = (a1 - a0, a3 - a2);
        if (front - rear).abs() > 1e-3 {
            let allowed = format!(
                "car {car} (axles {}…{}): its bogies' wheelbases differ ({front} m, {rear} m); a rail car has two \
                 equal two-axle bogies — populate articulated or irregular layouts with one-wheel vehicles",
                4 * car,
                4 * car + 3
            );
            return Err(invalid(Setting::Vehicle("vehicle.train"), rear, allowed));
        }
        let total: f64 = axles[..4].iter().map(|a| a.force).sum();
        let mean = total / 4.0;
        if let Some(a) = axles[..4].iter().find(|a| (a.force - mean).abs() > 1e-3 * mean.abs()) {
            let allowed = format!(
                "car {car} (axles {}…{}): axle forces must agree within 0.1 % of their mean {mean} N (a symmetric car \
                 carries equal wheel loads)",
                4 * car,
                4 * car + 3
            );
            return Err(invalid(Setting::Vehicle("vehicle.train"), a.force, allowed));
        }
        let fitted = Self { bogie_half_distance: (a2 - a0) / 2.0, axle_half_distance: front / 2.0, ..*self };
        fitted.validate()?;
        Ok(fitted)
    }

    /// The vehicle: DOFs in the banded order of the module note, the body's bounce reported; wheels at offsets 0,
    /// 2l_b, 2l_c and 2(l_c + l_b) behind the front wheel.
    pub fn vehicle(&self) -> Result<Vehicle> {
        self.validate()?;
        const N: usize = 10;
        let (lc, lb) = (self.bogie_half_distance, self.axle_half_distance);
        let mut mass = vec![0.0; N * N];
        let (mut damping, mut stiffness) = (mass.clone(), mass.clone());
        let mut weight = vec![0.0; N];
        let mut diagonal = |dof: usize, m: f64, translation: bool| {
            mass[dof * N + dof] = m;
            if translation {
                weight[dof] = -m * GRAVITY;
            }
        };
        diagonal(BODY_Z, self.body_mass, true);
        diagonal(BODY_PITCH, self.body_pitch_inertia, false);
        for b in 0..2 {
            diagonal(BOGIE_Z[b], self.bogie_mass, true);
            diagonal(BOGIE_PITCH[b], self.bogie_pitch_inertia, false);
        }
        for w in WHEELS {
            diagonal(w, self.wheelset_mass, true);
        }
        // A suspension on d = Σ g_i x_i between two ends: k g gᵀ into K, c g gᵀ into C.
        let mut suspension = |g: &[(usize, f64)], k: f64, c: f64| {
            for &(i, gi) in g {
                for &(j, gj) in g {
                    stiffness[i * N + j] += k * gi * gj;
                    damping[i * N + j] += c * gi * gj;
                }
            }
        };
        for (b, arm) in [lc, -lc].into_iter().enumerate() {
            // Secondary: the bogie centre against the body's point above it.
            suspension(
                &[(BOGIE_Z[b], 1.0), (BODY_Z, -1.0), (BODY_PITCH, -arm)],
                self.secondary_stiffness,
                self.secondary_damping,
            );
            // Primaries: each wheel against the bogie's point above it (front wheel at +l_b).
            for (w, axle) in [lb, -lb].into_iter().enumerate() {
                suspension(
                    &[(WHEELS[2 * b + w], 1.0), (BOGIE_Z[b], -1.0), (BOGIE_PITCH[b], -axle)],
                    self.primary_stiffness,
                    self.primary_damping,
                );
            }
        }
        let offsets = [0.0, 2.0 * lb, 2.0 * lc, 2.0 * (lc + lb)];
        let wheels = WHEELS.iter().zip(offsets).map(|(&dof, offset)| Wheel { dof, offset }).collect();
        Ok(Vehicle { name: "rail car".into(), mass, damping, stiffness, weight, wheels, body: BODY_Z })
    }
}

#[cfg(test)]
mod tests {
    use super::RailCar;

    /// The default car on level wheels: a quarter of its weight on each wheel (61.7 kN) to 1e-12, band 3, no pitch,
    /// and the body's sag the closed form of the springs in series: each bogie's two primaries (2k_p) carry half the
    /// body and the bogie, the secondary (k_s) half the body. Overlapping bogies are refused by name.
    #[test]
    fn the_default_car_stands_on_its_wheels() {
        let car = RailCar::default();
        let vehicle = car.vehicle().unwrap();
        vehicle.validate().unwrap();
        assert_eq!(vehicle.bandwidth(), 3);
        let (x, forces) = vehicle.static_state(&[0.0; 4]).unwrap();
        for f in &forces {
            assert!((f / (car.weight() / 4.0) - 1.0).abs() < 1e-12, "{f}");
        }
        assert!((car.weight() / 4.0 - 61.68e3).abs() < 10.0);
        // Sag of the body: primaries carry (M_c/2 + M_b) g each pair (2k_p), the secondary M_c g/2.
        let g = super::GRAVITY;
        let bogie_sag = (car.body_mass / 2.0 + car.bogie_mass) * g / (2.0 * car.primary_stiffness);
        let body_sag = bogie_sag + car.body_mass * g / 2.0 / car.secondary_stiffness;
        assert!((x[super::BODY_Z] + body_sag).abs() < 1e-12, "{} vs {}", x[super::BODY_Z], -body_sag);
        assert!(x[super::BODY_PITCH].abs() < 1e-15);
        let short = RailCar { bogie_half_distance: 1.0, ..car };
        assert!(short.vehicle().unwrap_err().to_string().contains("vehicle.bogie_half_distance"));
    }
}
