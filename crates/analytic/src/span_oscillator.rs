//! A sprung mass crossing a simply supported span, its wheel glued to the beam: the modal Galerkin solution with the
//! moving-mass convective terms (Frýba 1999, ch. 8; docs/theory.md §12) — the independent reference for vehicles on
//! a bridge, sharing nothing with the finite elements, the nonsmooth step or the contact laws.
//!
//! With w = Σ_n q_n(t) φ_n(x), φ_n = sin(nπx/L), the wheel (mass m_u) at x_c = vt follows the beam,
//! w_c = φᵀq, ẇ_c = φᵀq̇ + vφ′ᵀq, ẅ_c = φᵀq̈ + 2vφ′ᵀq̇ + v²φ″ᵀq (φ = φ(x_c)), and carries a body M_s on a spring k_s
//! and dashpot c_s. The contact force (upward on the wheel) is λ = m_u(g + ẅ_c) + k_s(w_c − z_b) + c_s(ẇ_c − ż_b)
//! and loads the beam with −λφ; the body obeys M_s z̈_b + c_s(ż_b − ẇ_c) + k_s(z_b − w_c) = −M_s g. In (q, z_b):
//!
//! ```text
//! M = [ρAL/2·I + m_u φφᵀ, 0; 0, M_s]
//! C = [2m_u v φφ′ᵀ + c_s φφᵀ, −c_s φ; −c_s φᵀ, c_s]
//! K = [K_n + m_u v² φφ″ᵀ + k_s φφᵀ + c_s v φφ′ᵀ, −k_s φ; −k_s φᵀ − c_s v φ′ᵀ, k_s]
//! F = [−m_u g φ; −M_s g],        K_n = diag(ρAL/2·ω_n²)
//! ```
//!
//! time-varying through x_c, integrated by the classical Runge–Kutta method (fourth order) with a dense solve of
//! M(t) at every stage. Without a body (M_s = 0, k_s = c_s = 0) it is the moving mass. The wheel enters at x = 0
//! (φ = 0: the beam at rest, the body at its static sag M_s g/k_s below the wheel) and the solution runs until it
//! leaves at x = L.

use crate::span::SimplySupportedSpan;
use fem_beam::GRAVITY;
use fem_beam::error::{FemError, Result, non_negative, positive};
use std::f64::consts::PI;

/// The oscillator: a wheel m_u glued to the beam, and optionally a body M_s on k_s, c_s above it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oscillator {
    /// m_u (kg) > 0.
    pub wheel_mass: f64,
    /// M_s (kg) ≥ 0 (0: a moving mass).
    pub body_mass: f64,
    /// k_s (N/m) > 0 with a body.
    pub stiffness: f64,
    /// c_s (N·s/m) ≥ 0.
    pub damping: f64,
}

/// The crossing, sampled every step: time (s), mid-span deflection (m, upward) and contact force λ (N, upward on
/// the wheel; compressive > 0).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Crossing {
    /// t (s), from 0 to L/v.
    pub time: Vec<f64>,
    /// w(L/2, t) (m).
    pub midspan: Vec<f64>,
    /// λ(t) (N).
    pub contact_force: Vec<f64>,
}

/// Largest number of modes × steps (each step four dense solves of (modes + 1)²·(modes + 1)/3).
const MAX_WORK: f64 = 1e11;

impl Oscillator {
    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<()> {
        positive("wheel_mass", self.wheel_mass)?;
        non_negative("body_mass", self.body_mass)?;
        non_negative("damping", self.damping)?;
        if self.body_mass > 0.0 {
            positive("stiffness", self.stiffness)?;
        }
        Ok(())
    }

    /// Whether there is a body above the wheel (else a moving mass).
    fn has_body(&self) -> bool {
        self.body_mass > 0.0
    }
}

impl SimplySupportedSpan {
    /// `oscillator` crossing the span at `speed` (m/s), `modes` modes, RK4 steps of at most `step` (s) and at most
    /// 1/ω_modes (RK4 is stable to ω h < 2.8; at ω h = 1 its error on the highest mode is 1e-3 a period); the
    /// crossing is cut into whole steps.
    pub fn oscillator_crossing(
        &self,
        oscillator: &Oscillator,
        speed: f64,
        modes: usize,
        step: f64,
    ) -> Result<Crossing> {
        oscillator.validate()?;
        positive("speed", speed)?;
        positive("step", step)?;
        let l = self.length();
        let steps = (l / speed / step.min(1.0 / self.omega(modes.max(1)))).ceil();
        if !(1..=2_000).contains(&modes) || (modes as f64).powi(3) * steps > MAX_WORK {
            return Err(FemError::InvalidCount {
                field: "modes",
                value: modes,
                allowed: "must lie in 1..=2000, with modes³ × steps ≤ 1e11",
            });
        }
        let steps = steps as usize;
        let h = l / speed / steps as f64;
        let modal_mass = 0.5 * self.mass_per_length() * l;
        let motion = ModalMotion {
            oscillator: *oscillator,
            speed,
            length: l,
            modes,
            modal_mass,
            modal_stiffness: (1..=modes).map(|k| modal_mass * self.omega(k).powi(2)).collect(),
        };
        let n = modes + 1;
        let mut y = vec![0.0; n];
        let mut v = vec![0.0; n];
        if oscillator.has_body() {
            y[modes] = -oscillator.body_mass * GRAVITY / oscillator.stiffness;
        }
        let mut out = Crossing::default();
        let mut record = |t: f64, y: &[f64], v: &[f64]| {
            let a = motion.acceleration(t, y, v);
            out.time.push(t);
            out.midspan.push(motion.midspan(y));
            out.contact_force.push(motion.contact(t, y, v, &a));
        };
        record(0.0, &y, &v);
        for k in 0..steps {
            let t = k as f64 * h;
            motion.runge_kutta_step(t, h, &mut y, &mut v);
            record(t + h, &y, &v);
        }
        Ok(out)
    }
}

/// The modal equations of the oscillator on the span, in y = (q, z_b) (z_b absent without a body: its row is a
/// unit mass at rest).
struct ModalMotion {
    oscillator: Oscillator,
    speed: f64,
    length: f64,
    modes: usize,
    /// ρAL/2 (kg).
    modal_mass: f64,
    /// ρAL/2·ω_n² (N/m).
    modal_stiffness: Vec<f64>,
}

/// aᵀb.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>()
}

impl ModalMotion {
    /// φ, φ′, φ″ of every mode at the wheel at time t.
    fn shapes(&self, t: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let x = self.speed * t;
        let modes = self.modes;
        let mut s = (vec![0.0; modes], vec![0.0; modes], vec![0.0; modes]);
        for k in 0..modes {
            let a = (k + 1) as f64 * PI / self.length;
            let (sin, cos) = (a * x).sin_cos();
            (s.0[k], s.1[k], s.2[k]) = (sin, a * cos, -a * a * sin);
        }
        s
    }

    /// ÿ = M(t)⁻¹(F − C ẏ − K y) at time t for y, ẏ = v.
    fn acceleration(&self, t: f64, y: &[f64], v: &[f64]) -> Vec<f64> {
        let (o, speed, modes, n) = (self.oscillator, self.speed, self.modes, self.modes + 1);
        let body = o.has_body();
        let (phi, dphi, ddphi) = self.shapes(t);
        let mut m = vec![0.0; n * n];
        let mut rhs = vec![0.0; n];
        let (wc, dwc_q, dwc_x, curv) =
            (dot(&phi, &y[..modes]), dot(&phi, &v[..modes]), dot(&dphi, &y[..modes]), dot(&ddphi, &y[..modes]));
        let slope_rate = dot(&dphi, &v[..modes]);
        let (zb, dzb) = if body { (y[modes], v[modes]) } else { (0.0, 0.0) };
        // λ without its m_u φᵀq̈ part: m_u(g + 2vφ′ᵀq̇ + v²φ″ᵀq) + k_s(w_c − z_b) + c_s(ẇ_c − ż_b).
        let spring = if body { o.stiffness * (wc - zb) + o.damping * (dwc_q + speed * dwc_x - dzb) } else { 0.0 };
        let known = o.wheel_mass * (GRAVITY + 2.0 * speed * slope_rate + speed * speed * curv) + spring;
        for i in 0..modes {
            m[i * n + i] = self.modal_mass;
            for j in 0..modes {
                m[i * n + j] += o.wheel_mass * phi[i] * phi[j];
            }
            rhs[i] = -self.modal_stiffness[i] * y[i] - known * phi[i];
        }
        if body {
            m[modes * n + modes] = o.body_mass;
            rhs[modes] = -o.body_mass * GRAVITY - o.stiffness * (zb - wc) - o.damping * (dzb - dwc_q - speed * dwc_x);
        } else {
            m[modes * n + modes] = 1.0;
        }
        // M(t) is symmetric positive definite (a modal mass plus m_u φφᵀ, and M_s or 1).
        let m = nalgebra::DMatrix::from_row_slice(n, n, &m);
        let rhs = nalgebra::DVector::from_vec(rhs);
        m.cholesky().expect("M(t) is positive definite").solve(&rhs).data.into()
    }

    /// The contact force λ (N, upward on the wheel) at time t from y, ẏ = v and ÿ = a.
    fn contact(&self, t: f64, y: &[f64], v: &[f64], a: &[f64]) -> f64 {
        let (o, speed, modes) = (self.oscillator, self.speed, self.modes);
        let (phi, dphi, ddphi) = self.shapes(t);
        let ddwc =
            dot(&phi, &a[..modes]) + 2.0 * speed * dot(&dphi, &v[..modes]) + speed * speed * dot(&ddphi, &y[..modes]);
        let wc = dot(&phi, &y[..modes]);
        let dwc = dot(&phi, &v[..modes]) + speed * dot(&dphi, &y[..modes]);
        let spring = if o.has_body() { o.stiffness * (wc - y[modes]) + o.damping * (dwc - v[modes]) } else { 0.0 };
        o.wheel_mass * (GRAVITY + ddwc) + spring
    }

    /// w(L/2) (m) of the modal coordinates in y.
    fn midspan(&self, y: &[f64]) -> f64 {
        (0..self.modes).map(|k| y[k] * ((k + 1) as f64 * PI / 2.0).sin()).sum::<f64>()
    }

    /// One classical Runge–Kutta step of length h from t on (y, v)′ = (v, ÿ(t, y, v)).
    fn runge_kutta_step(&self, t: f64, h: f64, y: &mut [f64], v: &mut [f64]) {
        let axpy = |a: &[f64], s: f64, b: &[f64]| a.iter().zip(b).map(|(x, d)| x + s * d).collect::<Vec<f64>>();
        let (k1y, k1v) = (v.to_vec(), self.acceleration(t, y, v));
        let (y2, v2) = (axpy(y, 0.5 * h, &k1y), axpy(v, 0.5 * h, &k1v));
        let (k2y, k2v) = (v2.clone(), self.acceleration(t + 0.5 * h, &y2, &v2));
        let (y3, v3) = (axpy(y, 0.5 * h, &k2y), axpy(v, 0.5 * h, &k2v));
        let (k3y, k3v) = (v3.clone(), self.acceleration(t + 0.5 * h, &y3, &v3));
        let (y4, v4) = (axpy(y, h, &k3y), axpy(v, h, &k3v));
        let (k4y, k4v) = (v4.clone(), self.acceleration(t + h, &y4, &v4));
        for i in 0..y.len() {
            y[i] += h / 6.0 * (k1y[i] + 2.0 * k2y[i] + 2.0 * k3y[i] + k4y[i]);
            v[i] += h / 6.0 * (k1v[i] + 2.0 * k2v[i] + 2.0 * k3v[i] + k4v[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Oscillator, SimplySupportedSpan};
    use fem_beam::properties::Beam;

    /// A light mass is the moving force of its weight, as O(m): masses of 1 and 0.1 kg crossing the reference rail as
    /// a 10 m span (600 kg) at 5 m/s deflect the mid-span like the force m g of Frýba's series (the same 10 modes) up
    /// to a difference that shrinks tenfold with the mass (8–12 allowed) and is below 1e-3 of the peak at 0.1 kg; the
    /// mass presses with m g as it enters.
    #[test]
    fn a_light_mass_is_the_moving_force() {
        let span = SimplySupportedSpan::new(&Beam::default(), 0.0, 10.0).unwrap();
        let difference = |mass: f64| {
            let oscillator = Oscillator { wheel_mass: mass, body_mass: 0.0, stiffness: 0.0, damping: 0.0 };
            let crossing = span.oscillator_crossing(&oscillator, 5.0, 10, 1e-3).unwrap();
            assert!((crossing.contact_force[0] / (mass * fem_beam::GRAVITY) - 1.0).abs() < 1e-12);
            let peak = crossing.midspan.iter().fold(0.0f64, |m, w| m.max(w.abs()));
            let mut worst = 0.0f64;
            for (t, w) in crossing.time.iter().zip(&crossing.midspan) {
                let force = span.moving_force_deflection(5.0, *t, mass * fem_beam::GRAVITY, 5.0, 10).unwrap();
                worst = worst.max((w - force).abs());
            }
            worst / peak
        };
        let (heavy, light) = (difference(1.0), difference(0.1));
        assert!(light < 1e-3 && (8.0..12.0).contains(&(heavy / light)), "{heavy} then {light}");
    }
}
