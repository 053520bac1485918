//! The simply supported span under a moving force, by its modal series (Frýba 1999, ch. 1; docs/theory.md §10): the
//! independent reference for bridges.
//!
//! For EI w'''' + ρA ẅ + k_f w = −F δ(x − vt) on 0 ≤ x ≤ L with pinned ends (w upward positive, the force pushing
//! down while 0 ≤ vt ≤ L), w = Σ_n q_n(t) sin(nπx/L) with ω_n² = (EI(nπ/L)⁴ + k_f)/ρA, Ω_n = nπv/L and
//!
//! ```text
//! q̈_n + ω_n² q_n = −(2F/ρAL) sin Ω_n t,   q_n(0) = q̇_n(0) = 0,
//! q_n(t) = −(2F/ρAL)·(sin Ω_n t − (Ω_n/ω_n) sin ω_n t)/(ω_n² − Ω_n²)        (0 ≤ t ≤ L/v, Ω_n ≠ ω_n),
//! q_n(t) = −(2F/ρAL)·(sin ω_n t − ω_n t cos ω_n t)/(2ω_n²)                 (Ω_n = ω_n, resonance),
//! ```
//!
//! and free vibration from (q_n, q̇_n)(L/v) once the force has left. Undamped: the reference for the FE run without
//! damping. The static mid-span deflection under F at mid-span is FL³/(48EI) without foundation.

use fem_beam::error::{FemError, Result, non_negative, positive};
use fem_beam::motion::Motion;
use fem_beam::properties::Beam;
use std::f64::consts::PI;

/// A pinned–pinned span of length L on an optional Winkler foundation k_f, for modal-series references.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimplySupportedSpan {
    bending_stiffness: f64,
    mass_per_length: f64,
    foundation_stiffness: f64,
    length: f64,
}

impl SimplySupportedSpan {
    /// The span of `beam` over `length` (m) on a foundation of stiffness `foundation_stiffness` (N/m², ≥ 0).
    pub fn new(beam: &Beam, foundation_stiffness: f64, length: f64) -> Result<Self> {
        beam.validate()?;
        non_negative("foundation.stiffness", foundation_stiffness)?;
        positive("mesh.length", length)?;
        Ok(Self {
            bending_stiffness: beam.bending_stiffness(),
            mass_per_length: beam.mass_per_length(),
            foundation_stiffness,
            length,
        })
    }

    /// L (m).
    pub fn length(&self) -> f64 {
        self.length
    }

    /// ρA (kg/m).
    pub fn mass_per_length(&self) -> f64 {
        self.mass_per_length
    }

    /// ω_n (rad/s).
    pub fn omega(&self, n: usize) -> f64 {
        let k = n as f64 * PI / self.length;
        ((self.bending_stiffness * k.powi(4) + self.foundation_stiffness) / self.mass_per_length).sqrt()
    }

    /// f_n = ω_n/2π (Hz).
    pub fn frequency(&self, n: usize) -> f64 {
        self.omega(n) / (2.0 * PI)
    }

    /// Deflection w(x, t) (m, upward positive) under a force `force` (N, downward) entering at x = 0 at t = 0 at
    /// `speed` (m/s), summed over the first `modes` modes (1 ≤ modes ≤ 10 000).
    pub fn moving_force_deflection(&self, x: f64, time: f64, force: f64, speed: f64, modes: usize) -> Result<f64> {
        positive("speed", speed)?;
        non_negative("time", time)?;
        if !(1..=10_000).contains(&modes) {
            return Err(FemError::InvalidCount { field: "modes", value: modes, allowed: "must lie in 1..=10000" });
        }
        let (l, rho_a) = (self.length, self.mass_per_length);
        let scale = -2.0 * force / (rho_a * l);
        let exit = l / speed;
        let mut w = 0.0;
        for n in 1..=modes {
            let (omega, big) = (self.omega(n), n as f64 * PI * speed / l);
            // Forced response and its rate at time t ≤ L/v.
            let forced = |t: f64| -> (f64, f64) {
                if (omega - big).abs() <= 1e-9 * omega {
                    let (s, c) = (omega * t).sin_cos();
                    let q = (s - omega * t * c) / (2.0 * omega * omega);
                    let dq = t * s / 2.0;
                    (scale * q, scale * dq)
                } else {
                    let d = omega * omega - big * big;
                    let q = ((big * t).sin() - big / omega * (omega * t).sin()) / d;
                    let dq = big * ((big * t).cos() - (omega * t).cos()) / d;
                    (scale * q, scale * dq)
                }
            };
            let q = if time <= exit {
                forced(time).0
            } else {
                let (q0, dq0) = forced(exit);
                let tau = time - exit;
                q0 * (omega * tau).cos() + dq0 / omega * (omega * tau).sin()
            };
            w += q * (n as f64 * PI * x / l).sin();
        }
        Ok(w)
    }

    /// The deflection history w(x, t_i) (m, upward positive) under a force `force` (N, downward) entering at x = 0 at
    /// t = 0 and moving as `motion` says — at a changing speed too (Frýba 1999, ch. 6; Michaltsos, Sophianopoulos &
    /// Kounadis 1996, J. Sound Vib. 191(3)) — by Duhamel's integral of each of the first `modes` modes:
    /// q_n(t) = (c/ω_n)∫₀ᵗ sin ω_n(t − τ) sin(nπs(τ)/L)·1[s(τ) ≤ L] dτ, c = −2F/(ρAL), i.e.
    /// q_n = (c/ω_n)(sin ω_n t·A_n − cos ω_n t·B_n) with A_n, B_n the integrals of cos ω_nτ and sin ω_nτ times the
    /// forcing, accumulated over the ascending `times` by four-point Gauss–Legendre on panels of at most an eighth
    /// of the shorter of the mode's period and the forcing's (relative error below 1e-10). Independent of the FE
    /// model and of the time stepping: the reference for runs at a changing speed.
    pub fn moving_force_history(
        &self,
        x: f64,
        times: &[f64],
        force: f64,
        motion: &Motion,
        modes: usize,
    ) -> Result<Vec<f64>> {
        if !(1..=10_000).contains(&modes) {
            return Err(FemError::InvalidCount { field: "modes", value: modes, allowed: "must lie in 1..=10000" });
        }
        if motion.position(0.0).abs() > 1e-12 || times.windows(2).any(|w| w[1] < w[0]) || times.first() < Some(&0.0) {
            return Err(FemError::InvalidField {
                field: "times",
                value: times.first().copied().unwrap_or(f64::NAN),
                allowed: "ascending from t ≥ 0, the force entering at x = 0 at t = 0",
            });
        }
        let l = self.length;
        let scale = -2.0 * force / (self.mass_per_length * l);
        let exit = motion.time_at(l);
        let fastest = motion.speed_range(l).0;
        let mut w = vec![0.0; times.len()];
        for n in 1..=modes {
            let (omega, k) = (self.omega(n), n as f64 * PI / l);
            let panel = 0.125 * 2.0 * PI / omega.max(k * fastest);
            let (mut a, mut b, mut reached) = (0.0, 0.0, 0.0);
            for (wi, &t) in w.iter_mut().zip(times) {
                let to = t.min(exit);
                if to > reached {
                    let count = ((to - reached) / panel).ceil().max(1.0) as usize;
                    let width = (to - reached) / count as f64;
                    for p in 0..count {
                        let start = reached + p as f64 * width;
                        for &(xi, weight) in &fem_beam::element::hermite::GAUSS_4 {
                            let tau = start + xi * width;
                            let f = weight * width * (k * motion.position(tau)).sin();
                            let (s, c) = (omega * tau).sin_cos();
                            a += c * f;
                            b += s * f;
                        }
                    }
                    reached = to;
                }
                let (s, c) = (omega * t).sin_cos();
                *wi += scale / omega * (s * a - c * b) * (k * x).sin();
            }
        }
        Ok(w)
    }

    /// The static mid-span deflection (m, magnitude) under `force` (N) at mid-span without foundation: FL³/(48EI).
    pub fn static_midspan_deflection(&self, force: f64) -> f64 {
        force * self.length.powi(3) / (48.0 * self.bending_stiffness)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A crawling force gives the static influence line: at mid-span, with the force at mid-span, FL³/48EI (the
    /// series converges like 1/n⁴); and the resonant term is the limit of the non-resonant one.
    #[test]
    fn slow_force_gives_the_static_deflection_and_resonance_is_a_limit() {
        let span = SimplySupportedSpan::new(&Beam::default(), 0.0, 20.0).unwrap();
        let speed = 1e-3 * span.frequency(1) * 20.0;
        let t_mid = 10.0 / speed;
        let w = span.moving_force_deflection(10.0, t_mid, 1e5, speed, 200).unwrap();
        let w_static = span.static_midspan_deflection(1e5);
        assert!((-w / w_static - 1.0).abs() < 1e-5, "{w} vs {w_static}");
        // Ω₁ = ω₁ exactly against Ω₁ a hair away: the same response.
        let resonant = span.omega(1) * 20.0 / PI;
        let at = |v: f64| span.moving_force_deflection(7.0, 0.8 * 20.0 / v, 1e5, v, 1).unwrap();
        assert!((at(resonant) - at(resonant * (1.0 + 1e-7))).abs() <= 1e-5 * at(resonant).abs());
    }

    /// Duhamel's quadrature at a constant speed is the closed form to 1e-9 of the response, during and after the
    /// crossing (α = 0.5: the force at about the first mode's resonance speed over two).
    #[test]
    fn duhamel_history_is_the_closed_form_at_constant_speed() {
        let span = SimplySupportedSpan::new(&Beam::default(), 0.0, 20.0).unwrap();
        let speed = 0.5 * 2.0 * span.frequency(1) * 20.0;
        let times: Vec<f64> = (0..=60).map(|i| i as f64 * 0.03 * 20.0 / speed).collect();
        let motion = Motion::constant(0.0, speed);
        let history = span.moving_force_history(10.0, &times, 1e5, &motion, 20).unwrap();
        let scale = span.static_midspan_deflection(1e5);
        for (&t, &w) in times.iter().zip(&history) {
            let exact = span.moving_force_deflection(10.0, t, 1e5, speed, 20).unwrap();
            assert!((w - exact).abs() <= 1e-9 * scale, "t = {t}: {w} vs {exact}");
        }
    }
}
