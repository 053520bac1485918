//! The moving-frame beam (docs/theory.md §8, §14, §16): an infinite rail — Euler–Bernoulli or Timoshenko, as the
//! scenario gives it — on a linear viscoelastic foundation, seen from a load moving along it at speed v. The one
//! entry every caller asks what depends on the rail theory: the roots r of the characteristic polynomial of
//! s = x − vt (the modes e^{rs} of the unloaded track), the rotation each mode carries (Ψ/W), the roots that decay
//! ahead of and behind the load, the steady wave of a moving force with its decay rates, its static limit, the
//! critical speed, critical damping and the speed beyond which the moving-frame equations change type.
//!
//! With W(s) the deflection and Ψ(s) the cross-section's rotation (upward / anticlockwise positive), G = κGA,
//! a = ρAv² − G and D = ρIv² − EI, the Timoshenko beam's two equations in s are
//!
//! ```text
//! a W″ + G Ψ′ − c v W′ + k W = f(s),        −G W′ + D Ψ″ + G Ψ = 0.
//! ```
//!
//! For W = e^{rs}: Ψ = β(r) W with β = r/(1 + q D r²), q = 1/G the shear compliance, and r is a root of the quartic
//! (the characteristic polynomial divided by G)
//!
//! ```text
//! P(r) = (ρAv² q − 1) D r⁴ − c v D q r³ + (ρAv² + k D q) r² − c v r + k.
//! ```
//!
//! **Euler–Bernoulli is its q = 0, ρI = 0 case**, evaluated by the same lines: P = EI r⁴ + ρAv² r² − cv r + k and
//! β = r (the rotation DOF is the slope W′). Frýba's closed form in ξ = βs ([`crate::reference::InfiniteBeam`]) is
//! kept as the independent reference the tests hold this type to, not as a second way in. A point force −F
//! (downward) at s = 0 gives, by the residues of W(s) = (1/2πi) ∫ f̂ (1 + q D r²)/P(r) e^{rs} dr,
//!
//! ```text
//! W(s) = −F Σ_{Re r<0} (1 + q D r²)/P′(r) e^{rs}  (s ≥ 0),     W(s) = F Σ_{Re r>0} (1 + q D r²)/P′(r) e^{rs}  (s ≤ 0),
//! ```
//!
//! a wave that decays both ways where two roots lie each side of the imaginary axis (below the critical speed, or
//! damped); a root on the axis (undamped at or above it) leaves no bounded steady state. Speeds must stay below the
//! [`Beam::wave_speed_limit`] (the shear wave √(G/ρA) ≈ 2 km/s of a Timoshenko rail, the bar wave of an
//! Euler–Bernoulli one), where a and D keep their sign.

use crate::dispersion::critical_speed;
use crate::reference::monic_quartic_roots;
use crate::steady_wave::SteadyWave;
use fem_beam::error::{FemError, Result, non_negative};
use fem_beam::properties::{Beam, Foundation};
use fem_beam::sleepers::Sleepers;
use num_complex::Complex64;

/// The infinite beam on its viscoelastic foundation in the frame of a moving load, either rail theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovingBeam {
    /// EI (N·m²).
    bending_stiffness: f64,
    /// ρA (kg/m).
    mass_per_length: f64,
    /// ρI (kg·m): 0 for Euler–Bernoulli.
    rotary_inertia: f64,
    /// q = 1/κGA (1/N): 0 for Euler–Bernoulli.
    shear_compliance: f64,
    /// k_f (N/m²) and c_f (N·s/m²).
    foundation: Foundation,
    /// v_cr (m/s).
    critical_speed: f64,
    /// c_cr = 2√(k_f ρA) (N·s/m²).
    critical_damping: f64,
    /// The speed (m/s) at which the moving-frame equations change type ([`Beam::wave_speed_limit`]).
    wave_speed_limit: f64,
}

impl MovingBeam {
    /// The moving frame of `beam` on `foundation` (its linear stiffness k_f ≥ 0 and damping c_f ≥ 0); on k_f = 0
    /// (the free rail) the critical speed is 0.
    pub fn new(beam: &Beam, foundation: &Foundation) -> Result<Self> {
        beam.validate()?;
        non_negative("foundation.stiffness", foundation.stiffness)?;
        non_negative("foundation.damping", foundation.damping)?;
        let critical_speed = match foundation.stiffness > 0.0 {
            true => critical_speed(beam, foundation)?,
            false => 0.0,
        };
        Ok(Self {
            bending_stiffness: beam.bending_stiffness(),
            mass_per_length: beam.mass_per_length(),
            rotary_inertia: beam.rotary_inertia(),
            shear_compliance: beam.shear_stiffness().map_or(0.0, |g| 1.0 / g),
            foundation: *foundation,
            critical_speed,
            critical_damping: foundation.critical_damping(beam),
            wave_speed_limit: beam.wave_speed_limit(),
        })
    }

    /// The moving frame of the track a scenario describes: `beam` on a foundation `foundation`, or — on `sleepers` —
    /// its long-wave twin, the equivalent continuous track ([`Sleepers::equivalent_track`]: the sleepers' mass on
    /// the rail, pads and ballast in series spread over a spacing, beside the soil), whose critical speed is the
    /// discrete track's to the accuracy of the smeared support.
    pub fn of_track(beam: &Beam, foundation: &Foundation, sleepers: Option<&Sleepers>) -> Result<Self> {
        match sleepers {
            None => Self::new(beam, foundation),
            Some(s) => {
                let (twin, stiffness) = s.equivalent_track(beam, foundation.stiffness);
                Self::new(&twin, &Foundation { stiffness, ..*foundation })
            }
        }
    }

    /// v_cr (m/s): the least phase velocity of the track's bending waves (Euler–Bernoulli's (4k_f EI/(ρA)²)^¼).
    pub fn critical_speed(&self) -> f64 {
        self.critical_speed
    }

    /// c_cr = 2√(k_f ρA) (N·s/m²).
    pub fn critical_damping(&self) -> f64 {
        self.critical_damping
    }

    /// The speed (m/s) the moving frame holds below: the bar wave √(E/ρ) for Euler–Bernoulli, the shear wave
    /// √(κGA/ρA) for Timoshenko, where the equations change type.
    pub fn wave_speed_limit(&self) -> f64 {
        self.wave_speed_limit
    }

    /// β = (k_f/4EI)^¼ (1/m), the reciprocal of the track's bending length: the static deflection under a force F is
    /// Fβ/(2k_f) and the foundation's peak reaction Fβ/2 per metre (Hetényi 1946); 0 on k_f = 0.
    pub fn bending_wavenumber(&self) -> f64 {
        (self.foundation.stiffness / (4.0 * self.bending_stiffness)).powf(0.25)
    }

    /// q D = q(ρIv² − EI) (m²) at `speed`: 0 for Euler–Bernoulli.
    fn shear_term(&self, speed: f64) -> f64 {
        self.shear_compliance * (self.rotary_inertia * speed * speed - self.bending_stiffness)
    }

    /// P's coefficients [p₄, p₃, p₂, p₁, p₀] at `speed` (m/s) (N/m², per the module's scaling).
    pub fn characteristic(&self, speed: f64) -> [f64; 5] {
        let v = speed;
        let d = self.rotary_inertia * v * v - self.bending_stiffness;
        let (q, qd) = (self.shear_compliance, self.shear_term(speed));
        let (k, c, rho_a) = (self.foundation.stiffness, self.foundation.damping, self.mass_per_length);
        [(rho_a * v * v * q - 1.0) * d, -c * v * qd, rho_a * v * v + k * qd, -c * v, k]
    }

    /// The four roots r (1/m) of the characteristic polynomial at `speed` (m/s), unordered: every solution of the
    /// unloaded track in s = x − vt is a sum of e^{rs}. They exist at every speed; undamped above v_cr some lie on
    /// the imaginary axis. Their largest modulus sets the shortest length a mesh must resolve.
    pub fn wavenumbers(&self, speed: f64) -> [Complex64; 4] {
        let [p4, p3, p2, p1, p0] = self.characteristic(speed);
        monic_quartic_roots([p3 / p4, p2 / p4, p1 / p4, p0 / p4])
    }

    /// The rotation DOF each mode e^{rs} carries at `speed`, with its derivative in r: β = r/(1 + qD r²) and
    /// dβ/dr = (1 − qD r²)/(1 + qD r²)² — the cross-section's Ψ/W of a Timoshenko rail, Euler–Bernoulli's slope
    /// (β = r, dβ/dr = 1) at q = 0.
    pub fn rotation_per_deflection(&self, r: Complex64, speed: f64) -> (Complex64, Complex64) {
        let qd_r2 = r * r * self.shear_term(speed);
        let denominator = qd_r2 + 1.0;
        (r / denominator, (-qd_r2 + 1.0) / (denominator * denominator))
    }

    /// The roots that decay away from the load at `speed`: two ahead (Re r < 0), then two behind (Re r > 0);
    /// [`FemError::NoSteadyState`] where a root lies on the imaginary axis (to 1e-9 of the largest; undamped at or
    /// above v_cr) or the speed reaches the [wave speed limit](Self::wave_speed_limit).
    pub fn decaying_wavenumbers(&self, speed: f64) -> Result<[Complex64; 4]> {
        let no_state = || {
            let damping_ratio = self.foundation.damping / self.critical_damping;
            FemError::NoSteadyState { speed, damping_ratio, critical_speed: self.critical_speed }
        };
        if !(speed.is_finite() && speed >= 0.0) || speed >= self.wave_speed_limit {
            return Err(no_state());
        }
        let roots = self.wavenumbers(speed);
        let scale = roots.iter().map(|r| r.norm()).fold(0.0, f64::max);
        if roots.iter().any(|r| r.re.abs() <= 1e-9 * scale) {
            return Err(no_state());
        }
        let mut ahead = roots.iter().copied().filter(|r| r.re < 0.0);
        let mut behind = roots.iter().copied().filter(|r| r.re > 0.0);
        match (ahead.next(), ahead.next(), ahead.next(), behind.next(), behind.next()) {
            (Some(a0), Some(a1), None, Some(b0), Some(b1)) => Ok([a0, a1, b0, b1]),
            _ => Err(no_state()),
        }
    }

    /// The steady wave of a force `force` (N, downward) moving at `speed` (m/s, ≥ 0), by the residues above.
    pub fn steady_state(&self, speed: f64, force: f64) -> Result<SteadyWave> {
        non_negative("speed", speed)?;
        if !force.is_finite() {
            return Err(FemError::InvalidField { field: "force", value: force, allowed: "must be finite" });
        }
        let roots = self.decaying_wavenumbers(speed)?;
        let [p4, p3, p2, p1, _] = self.characteristic(speed);
        let qd = self.shear_term(speed);
        let residue = |r: Complex64| {
            let derivative = ((r * (4.0 * p4) + 3.0 * p3) * r + 2.0 * p2) * r + p1;
            (r * r * qd + 1.0) / derivative
        };
        let term = |r: Complex64, sign: f64| (r, residue(r) * (sign * force), self.rotation_per_deflection(r, speed).0);
        Ok(SteadyWave::new(
            [term(roots[0], -1.0), term(roots[1], -1.0)],
            [term(roots[2], 1.0), term(roots[3], 1.0)],
            self.bending_stiffness,
            speed,
        ))
    }

    /// The static deflection under `force` (m, magnitude): the wave at rest under the load (Euler–Bernoulli's
    /// Fβ/2k_f).
    pub fn static_deflection(&self, force: f64) -> Result<f64> {
        Ok(-self.steady_state(0.0, force)?.deflection(0.0))
    }

    /// The static bending moment under `force` (N·m, sagging): the wave's at rest (Euler–Bernoulli's F/4β).
    pub fn static_moment(&self, force: f64) -> Result<f64> {
        Ok(self.steady_state(0.0, force)?.moment(0.0))
    }
}
