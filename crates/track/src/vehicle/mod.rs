//! Vehicles (docs/theory.md §12): small linear systems M ẍ + C ẋ + K x = f_g + Σ_w λ_w e_w whose wheel DOFs touch
//! the rail through wheel–rail interactions and fly between contacts. x holds upward displacements (m, or rad for
//! pitch) from the configuration where every spring is unstretched and every wheel at height 0; f_g the weights
//! (N, upward positive, so −m g); λ_w ≥ 0 the contact force on wheel w, never tensile.
//!
//! Built-in forms ([`builtin`]): the moving mass and the quarter car; the 2-D rail car ([`rail_car`]); a user
//! vehicle is given by its matrices. [`consist`] puts vehicles in a row for a run, [`wheel_rail`] names their contact with the rail.
//! [`ground`] rolls wheels over rigid ground with a rail profile r(x), [`rail`] along the beam (compliant contact).

pub mod builtin;
pub mod consist;
pub mod ground;
pub mod rail;
pub mod rail_car;
pub mod wheel_rail;

use crate::error::{Result, Setting, invalid, invalid_choice, invalid_count};
use banded::SymmetricBanded;
use nscd::LinearSystem;

/// Standard gravity g (m/s²): the one constant of the workspace, for the vehicles' weights.
pub use fem_beam::GRAVITY;
/// Largest number of DOFs of one vehicle (its matrices are dense).
pub const MAX_VEHICLE_DOFS: usize = 64;

/// A wheel: which DOF of its vehicle, and where it runs (m behind the vehicle's front).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wheel {
    /// DOF index within the vehicle.
    pub dof: usize,
    /// Offset behind the vehicle's reference point (m), ≥ 0.
    pub offset: f64,
}

/// A vehicle: dense symmetric matrices (row-major, n × n), weights and wheels.
#[derive(Debug, Clone, PartialEq)]
pub struct Vehicle {
    /// Name, for reports.
    pub name: String,
    /// M (kg, kg·m²).
    pub mass: Vec<f64>,
    /// C (N·s/m).
    pub damping: Vec<f64>,
    /// K (N/m).
    pub stiffness: Vec<f64>,
    /// f_g (N, upward positive).
    pub weight: Vec<f64>,
    /// The wheels.
    pub wheels: Vec<Wheel>,
    /// The DOF whose acceleration is reported as the body's (comfort): the car body's bounce.
    pub body: usize,
}

impl Vehicle {
    /// This vehicle `factor` times heavier: M, C, K and f_g scaled alike, which keeps every natural frequency and
    /// damping ratio (the way a template is fitted to an axle's load).
    pub fn scaled(&self, factor: f64) -> Self {
        let scale = |m: &[f64]| m.iter().map(|x| x * factor).collect::<Vec<_>>();
        Self {
            name: self.name.clone(),
            mass: scale(&self.mass),
            damping: scale(&self.damping),
            stiffness: scale(&self.stiffness),
            weight: scale(&self.weight),
            wheels: self.wheels.clone(),
            body: self.body,
        }
    }

    /// Number of DOFs.
    pub fn dofs(&self) -> usize {
        self.weight.len()
    }

    /// Check sizes, symmetry, signs and wheels (sizes first, before anything is allocated from them).
    pub fn validate(&self) -> Result<()> {
        let n = self.dofs();
        if n == 0 || n > MAX_VEHICLE_DOFS {
            return Err(invalid(
                Setting::Vehicle("vehicle.dofs"),
                n as f64,
                format!("must lie in 1 … {MAX_VEHICLE_DOFS}"),
            ));
        }
        for (field, matrix) in
            [("vehicle.mass", &self.mass), ("vehicle.damping", &self.damping), ("vehicle.stiffness", &self.stiffness)]
        {
            if matrix.len() != n * n {
                return Err(invalid(
                    Setting::Vehicle(field),
                    matrix.len() as f64,
                    format!("needs {n} × {n} = {} entries", n * n),
                ));
            }
            for i in 0..n {
                for j in 0..n {
                    let (a, b) = (matrix[i * n + j], matrix[j * n + i]);
                    if !a.is_finite() || (a - b).abs() > 1e-12 * a.abs().max(b.abs()) {
                        return Err(invalid(
                            Setting::Vehicle(field),
                            a,
                            format!("must be finite and symmetric (entry {i}, {j})"),
                        ));
                    }
                }
                if matrix[i * n + i] < 0.0 {
                    return Err(invalid(
                        Setting::Vehicle(field),
                        matrix[i * n + i],
                        format!("diagonal entry {i} must be ≥ 0"),
                    ));
                }
            }
        }
        if let Some(w) = self.weight.iter().find(|w| !w.is_finite()) {
            return Err(invalid(Setting::Vehicle("vehicle.weight"), *w, "must be finite (N)"));
        }
        if self.body >= n {
            return Err(invalid(
                Setting::Vehicle("vehicle.body"),
                self.body as f64,
                format!("must be a DOF index < {n}"),
            ));
        }
        if self.wheels.is_empty() {
            return Err(invalid_count(Setting::Vehicle("vehicle.wheels"), 0, "needs at least one wheel"));
        }
        for w in &self.wheels {
            if w.dof >= n {
                return Err(invalid(
                    Setting::Vehicle("vehicle.wheels.dof"),
                    w.dof as f64,
                    format!("must be a DOF index < {n}"),
                ));
            }
            if !(w.offset.is_finite() && w.offset >= 0.0) {
                return Err(invalid(Setting::Vehicle("vehicle.wheels.offset"), w.offset, "must be finite and ≥ 0 (m)"));
            }
        }
        // On a level rail every wheel must press with a share of the weight: a wheel the weight lifts would start
        // in tension, which a unilateral contact cannot hold (an upward weight, or a wheel on the wrong side).
        let (_, forces) = self.static_state(&vec![0.0; self.wheels.len()])?;
        if let Some((i, &q)) = forces.iter().enumerate().find(|(_, q)| q.is_nan() || **q <= 0.0) {
            return Err(invalid(
                Setting::Vehicle("vehicle.weight"),
                q,
                format!(
                    "gives wheel {} a static load of {q:.6e} N on a level rail: every wheel must press on the rail \
                     (weights are gravity loads, upward positive: −m·g on a translation, N)",
                    i + 1
                ),
            ));
        }
        Ok(())
    }

    /// The largest |i − j| of a nonzero entry of M, C or K: order the DOFs so that it is small (the beam's is 3),
    /// for a system stacked from blocks takes the largest bandwidth of its blocks.
    pub fn bandwidth(&self) -> usize {
        let n = self.dofs();
        let mut width = 0;
        for matrix in [&self.mass, &self.damping, &self.stiffness] {
            for i in 0..n {
                for j in 0..i {
                    if matrix[i * n + j] != 0.0 {
                        width = width.max(i - j);
                    }
                }
            }
        }
        width
    }

    /// The vehicle as a system block, banded with [`Vehicle::bandwidth`].
    pub fn system(&self) -> LinearSystem {
        let n = self.dofs();
        let width = self.bandwidth();
        let banded = |dense: &[f64]| {
            let mut m = SymmetricBanded::zeros(n, width);
            for i in 0..n {
                for j in i.saturating_sub(width)..=i {
                    m.add(i, j, dense[i * n + j]);
                }
            }
            m
        };
        LinearSystem::new(banded(&self.mass), banded(&self.damping), banded(&self.stiffness))
    }

    /// The static state with each wheel held at the height in `heights` (m): x with K_ff x_f = f_f − K_fw x_w, and the
    /// contact forces λ_w = (K x)_w − f_w (N, upward on the wheel). Errors when the free DOFs are not held by springs.
    pub fn static_state(&self, heights: &[f64]) -> Result<(Vec<f64>, Vec<f64>)> {
        let n = self.dofs();
        let wheel_of = |i: usize| self.wheels.iter().position(|w| w.dof == i);
        let mut x = vec![0.0; n];
        for (w, &h) in self.wheels.iter().zip(heights) {
            x[w.dof] = h;
        }
        let free: Vec<usize> = (0..n).filter(|&i| wheel_of(i).is_none()).collect();
        let k = &self.stiffness;
        let mut a: Vec<f64> = free.iter().flat_map(|&i| free.iter().map(move |&j| k[i * n + j])).collect();
        let mut b: Vec<f64> = free
            .iter()
            .map(|&i| self.weight[i] - self.wheels.iter().map(|w| k[i * n + w.dof] * x[w.dof]).sum::<f64>())
            .collect();
        let solution = solve_dense(&mut a, &mut b).ok_or_else(|| {
            invalid_choice(
                Setting::Vehicle("vehicle.stiffness"),
                "singular",
                "leaves a DOF without a spring to a wheel: no static state",
            )
        })?;
        for (&i, s) in free.iter().zip(solution) {
            x[i] = s;
        }
        let forces = self
            .wheels
            .iter()
            .map(|w| (0..n).map(|j| k[w.dof * n + j] * x[j]).sum::<f64>() - self.weight[w.dof])
            .collect();
        Ok((x, forces))
    }
}

/// Solve A y = b in place by Gaussian elimination with partial pivoting (A square, row-major); None if singular.
/// Written out rather than nalgebra's LU: its order of operations fixes the bits of every vehicle's static start,
/// which nalgebra's moves by ~1e-14 relative (measured on `examples/vehicle-groups.toml`).
fn solve_dense(a: &mut [f64], b: &mut [f64]) -> Option<Vec<f64>> {
    let n = b.len();
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))?;
        if a[pivot * n + col].abs() <= 1e-12 * scale {
            return None;
        }
        for j in 0..n {
            a.swap(col * n + j, pivot * n + j);
        }
        b.swap(col, pivot);
        for row in col + 1..n {
            let f = a[row * n + col] / a[col * n + col];
            for j in col..n {
                a[row * n + j] -= f * a[col * n + j];
            }
            b[row] -= f * b[col];
        }
    }
    let mut y = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|j| a[i * n + j] * y[j]).sum();
        y[i] = (b[i] - s) / a[i * n + i];
    }
    Some(y)
}

#[cfg(test)]
mod tests {
    use super::builtin::{MovingMass, QuarterCar};
    use super::{GRAVITY, Vehicle, Wheel};

    /// The quarter car at rest on a rail 2 mm up: the wheel there, the body M_s g/k_s below it, the rail carrying
    /// (M_s + m_u) g; the moving mass carries m g; a DOF without a spring to a wheel has no static state.
    #[test]
    fn static_states() {
        let car = QuarterCar::default();
        let (x, forces) = car.vehicle().unwrap().static_state(&[2e-3]).unwrap();
        let sag = car.body_mass * GRAVITY / car.suspension_stiffness;
        assert!((x[0] - (2e-3 - sag)).abs() < 1e-15 && x[1] == 2e-3);
        assert!((forces[0] / ((car.body_mass + car.wheel_mass) * GRAVITY) - 1.0).abs() < 1e-14);
        assert!((car.body_frequency() / std::f64::consts::TAU - 2.0).abs() < 0.02 && car.damping_ratio() > 0.15);
        let (_, forces) = MovingMass { mass: 100.0 }.vehicle().unwrap().static_state(&[0.0]).unwrap();
        assert!((forces[0] - 100.0 * GRAVITY).abs() < 1e-12);
        let loose = Vehicle {
            name: "loose".into(),
            mass: vec![1.0, 0.0, 0.0, 1.0],
            damping: vec![0.0; 4],
            stiffness: vec![0.0; 4],
            weight: vec![-1.0, -1.0],
            wheels: vec![Wheel { dof: 1, offset: 0.0 }],
            body: 0,
        };
        assert!(loose.static_state(&[0.0]).is_err());
    }

    /// Bad vehicles name the field: sizes, symmetry, negative diagonal entries, wheels.
    #[test]
    fn bad_vehicles_are_refused() {
        let good = QuarterCar::default().vehicle().unwrap();
        good.validate().unwrap();
        let mut v = good.clone();
        v.stiffness[1] = 0.0;
        assert!(v.validate().unwrap_err().to_string().contains("vehicle.stiffness"));
        let mut v = good.clone();
        v.mass.pop();
        assert!(v.validate().unwrap_err().to_string().contains("vehicle.mass"));
        let mut v = good.clone();
        v.wheels[0].dof = 2;
        assert!(v.validate().unwrap_err().to_string().contains("vehicle.wheels.dof"));
        let mut v = good;
        v.wheels.clear();
        assert!(v.validate().unwrap_err().to_string().contains("vehicle.wheels"));
        assert!(QuarterCar { wheel_mass: -1.0, ..QuarterCar::default() }.validate().is_err());
        assert!(MovingMass { mass: 0.0 }.validate().is_err());
    }
}
