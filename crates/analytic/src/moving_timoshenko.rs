//! The infinite Timoshenko beam on a viscoelastic foundation under a moving load (docs/theory.md §16): the closed
//! form the stationary wave of a Timoshenko rail is checked against, and the far field that closes its domain.
//!
//! With s = x − vt, W(s) the deflection and Ψ(s) the cross-section's rotation (both upward / anticlockwise positive)
//! the two equations of the Timoshenko beam become, with G = κGA, a = ρAv² − G, D = ρIv² − EI,
//!
//! ```text
//! a W″ + G Ψ′ − c v W′ + k W = f(s),        −G W′ + D Ψ″ + G Ψ = 0.
//! ```
//!
//! For W = e^{rs}: Ψ = β(r) W with β = G r/(G + D r²), and r is a root of the characteristic quartic
//!
//! ```text
//! P(r) = (a r² − c v r + k)(D r² + G) + G² r² = aD r⁴ − cvD r³ + (ρAv²G + kD) r² − cvG r + kG,
//! ```
//!
//! whose limit G → ∞ (with ρI = 0) is Euler–Bernoulli's EI r⁴ + ρAv² r² − cv r + k. A point force −F (downward) at
//! s = 0 gives, by the residues of W(s) = (1/2πi) ∫ f̂ (D r² + G)/P(r) e^{rs} dr over the imaginary axis,
//!
//! ```text
//! W(s) = −F Σ_{Re r<0} (D r² + G)/P′(r) e^{rs}  (s ≥ 0),     W(s) = F Σ_{Re r>0} (D r² + G)/P′(r) e^{rs}  (s ≤ 0),
//! ```
//!
//! a wave that decays both ways where two roots lie each side of the imaginary axis (below the critical speed, or
//! damped); a root on the axis (undamped at or above it) leaves no bounded steady state. Speeds must stay below the
//! shear wave's, √(G/ρA) (≈ 2 km/s for a rail), where a and D keep their sign.

use crate::dispersion::critical_speed;
use crate::reference::{monic_quartic_roots, scan_extremes};
use fem_beam::DeflectionExtremes;
use fem_beam::error::{FemError, Result};
use fem_beam::extreme::Extreme;
use fem_beam::properties::{Beam, Foundation};
use num_complex::Complex64;

/// A Timoshenko beam on a linear viscoelastic foundation, seen from a load moving along it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovingTimoshenko {
    beam: Beam,
    foundation: Foundation,
    /// G = κGA (N).
    shear: f64,
}

impl MovingTimoshenko {
    /// The moving frame of `beam` (a Timoshenko beam) on `foundation` (its linear stiffness k ≥ 0 and damping c).
    pub fn new(beam: &Beam, foundation: &Foundation) -> Result<Self> {
        let shear = beam.shear_stiffness().ok_or(FemError::InvalidField {
            field: "beam.theory",
            value: 0.0,
            allowed: "must be Timoshenko for the Timoshenko beam's moving frame",
        })?;
        Ok(Self { beam: *beam, foundation: *foundation, shear })
    }

    /// The shear wave's speed √(κGA/ρA) (m/s): moving loads must stay below it ([`Beam::wave_speed_limit`]).
    pub fn shear_wave_speed(&self) -> f64 {
        self.beam.wave_speed_limit()
    }

    /// D = ρIv² − EI (N·m²) at `speed`.
    fn d(&self, speed: f64) -> f64 {
        self.beam.rotary_inertia() * speed * speed - self.beam.bending_stiffness()
    }

    /// P's coefficients [p₄, p₃, p₂, p₁, p₀] at `speed` (m/s).
    pub fn characteristic(&self, speed: f64) -> [f64; 5] {
        let (g, d, v) = (self.shear, self.d(speed), speed);
        let (k, c, rho_a) = (self.foundation.stiffness, self.foundation.damping, self.beam.mass_per_length());
        let a = rho_a * v * v - g;
        [a * d, -c * v * d, rho_a * v * v * g + k * d, -c * v * g, k * g]
    }

    /// The four roots r (1/m) of P at `speed`, unordered.
    pub fn wavenumbers(&self, speed: f64) -> [Complex64; 4] {
        let [p4, p3, p2, p1, p0] = self.characteristic(speed);
        monic_quartic_roots([p3 / p4, p2 / p4, p1 / p4, p0 / p4])
    }

    /// Ψ/W of the mode e^{rs} at `speed`: β(r) = G r/(G + D r²).
    pub fn rotation_per_deflection(&self, r: Complex64, speed: f64) -> Complex64 {
        r * self.shear / (r * r * self.d(speed) + self.shear)
    }

    /// dβ/dr at `speed`: G(G − D r²)/(G + D r²)² (the far field's traction needs it).
    pub fn rotation_slope(&self, r: Complex64, speed: f64) -> Complex64 {
        let (g, d) = (self.shear, self.d(speed));
        let denominator = r * r * d + g;
        (-(r * r * d) + g) * g / (denominator * denominator)
    }

    /// The wavenumbers split into the two that decay ahead of the load (Re r < 0) and the two behind (Re r > 0),
    /// ahead first; [`FemError::NoSteadyState`] when a root lies on the imaginary axis (to 1e-9 of the largest) or
    /// the speed reaches the shear wave's.
    pub fn decaying_wavenumbers(&self, speed: f64) -> Result<[Complex64; 4]> {
        let no_state = || {
            let (k, rho_a) = (self.foundation.stiffness, self.beam.mass_per_length());
            let damping_ratio = self.foundation.damping / (2.0 * (k * rho_a).sqrt());
            let critical = critical_speed(&self.beam, &self.foundation).unwrap_or(f64::NAN);
            FemError::NoSteadyState { speed, damping_ratio, critical_speed: critical }
        };
        if !(speed.is_finite() && speed >= 0.0) || speed >= self.shear_wave_speed() {
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

    /// The steady-state wave of a force `force` (N, downward) moving at `speed` (m/s), by the residues above.
    pub fn steady_state(&self, speed: f64, force: f64) -> Result<TimoshenkoSteadyState> {
        let roots = self.decaying_wavenumbers(speed)?;
        let [p4, p3, p2, p1, _] = self.characteristic(speed);
        let (g, d) = (self.shear, self.d(speed));
        let residue = |r: Complex64| {
            let derivative = ((r * (4.0 * p4) + 3.0 * p3) * r + 2.0 * p2) * r + p1;
            (r * r * d + g) / derivative
        };
        let term = |r: Complex64, sign: f64| (r, residue(r) * (sign * force), self.rotation_per_deflection(r, speed));
        Ok(TimoshenkoSteadyState {
            ahead: [term(roots[0], -1.0), term(roots[1], -1.0)],
            behind: [term(roots[2], 1.0), term(roots[3], 1.0)],
            bending_stiffness: self.beam.bending_stiffness(),
            speed,
        })
    }
}

/// The steady wave of a Timoshenko beam under a moving force: W(s) = Re Σ C e^{rs} over each side's two roots.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimoshenkoSteadyState {
    /// (r, C, β) ahead of the load (s ≥ 0).
    ahead: [(Complex64, Complex64, Complex64); 2],
    /// (r, C, β) behind it (s ≤ 0).
    behind: [(Complex64, Complex64, Complex64); 2],
    bending_stiffness: f64,
    speed: f64,
}

impl TimoshenkoSteadyState {
    /// The slowest decay rates of the wave ahead of and behind the load (1/m): min |Re r| over each pair of roots.
    pub fn decay_rates(&self) -> (f64, f64) {
        let slowest = |pair: &[(Complex64, Complex64, Complex64); 2]| pair[0].0.re.abs().min(pair[1].0.re.abs());
        (slowest(&self.ahead), slowest(&self.behind))
    }

    fn sum(&self, s: f64, factor: impl Fn(Complex64, Complex64) -> Complex64) -> f64 {
        let terms = if s >= 0.0 { &self.ahead } else { &self.behind };
        terms.iter().map(|&(r, c, beta)| (c * factor(r, beta) * (r * s).exp()).re).sum()
    }

    /// W (m, upward) at s = x − vt (m).
    pub fn deflection(&self, s: f64) -> f64 {
        self.sum(s, |_, _| Complex64::new(1.0, 0.0))
    }

    /// W′ (rad) at s; it jumps at the load by the shear force's jump F/κGA.
    pub fn slope(&self, s: f64) -> f64 {
        self.sum(s, |r, _| r)
    }

    /// The cross-section's rotation Ψ (rad) at s.
    pub fn rotation(&self, s: f64) -> f64 {
        self.sum(s, |_, beta| beta)
    }

    /// The bending moment EI Ψ′ (N·m, sagging positive) at s.
    pub fn moment(&self, s: f64) -> f64 {
        self.bending_stiffness * self.sum(s, |r, beta| r * beta)
    }

    /// ∂w/∂t = −v W′ (m/s) at s.
    pub fn velocity(&self, s: f64) -> f64 {
        -self.speed * self.slope(s)
    }

    /// ∂ψ/∂t = −v Ψ′ (rad/s) at s.
    pub fn rotation_rate(&self, s: f64) -> f64 {
        -self.speed * self.sum(s, |r, beta| r * beta)
    }

    /// The roots, ahead pair first (1/m).
    pub fn roots(&self) -> [Complex64; 4] {
        [self.ahead[0].0, self.ahead[1].0, self.behind[0].0, self.behind[1].0]
    }

    /// How to sample the wave (m): a step of a 64th of its shortest wave (2π/|r|ₘₐₓ, at most 0.05/|r|ₘₐₓ) and the
    /// reach 40/min|Re r| beyond which it is below e⁻⁴⁰ of its size (at most 4000/|r|ₘₐₓ).
    pub fn sampling(&self) -> (f64, f64) {
        let roots = self.roots();
        let decay = roots.iter().map(|r| r.re.abs()).fold(f64::INFINITY, f64::min);
        let wave = roots.iter().map(|r| r.norm()).fold(0.0, f64::max);
        ((std::f64::consts::TAU / wave / 64.0).min(0.05 / wave), (40.0 / decay).min(4000.0 / wave))
    }

    /// Largest downward and upward deflections and where (s, m): sampled over the region where the wave is above
    /// ~e⁻⁴⁰ of its size, refined by golden section.
    pub fn extremes(&self) -> DeflectionExtremes {
        let (step, reach) = self.sampling();
        let count = (reach / step).ceil() as i64;
        let (down, up) = scan_extremes(|s| -self.deflection(s), (-count..=count).map(|i| i as f64 * step), step);
        DeflectionExtremes {
            max_downward: Extreme::in_frame(down.1.max(0.0), down.0),
            max_upward: Extreme::in_frame(up.1.max(0.0), up.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispersion::static_deflection;
    use crate::reference::InfiniteBeam;
    use fem_beam::properties::BeamTheory;

    fn rail(shear_modulus: f64) -> Beam {
        Beam { theory: BeamTheory::Timoshenko { shear_modulus, shear_coefficient: 0.4 }, ..Beam::default() }
    }

    /// At rest the residues give the Fourier integral's static deflection under the load (an independent
    /// quadrature, ~1e-14) to 1e-10, for a stiff soil where shear adds ~1 % to the deflection.
    #[test]
    fn at_rest_the_wave_is_the_static_deflection() {
        let (beam, k) = (rail(81e9), 100e6);
        let wave =
            MovingTimoshenko::new(&beam, &Foundation::linear(k, 0.0)).unwrap().steady_state(0.0, 83.4e3).unwrap();
        let exact = static_deflection(&beam, k, 83.4e3);
        assert!((-wave.deflection(0.0) / exact - 1.0).abs() < 1e-10, "{} vs {exact}", wave.deflection(0.0));
        let euler = static_deflection(&Beam::default(), k, 83.4e3);
        assert!(exact > 1.005 * euler, "shear must show: {exact} vs {euler}");
    }

    /// The wave solves the equations across the load: W, Ψ and the moment continuous, W′ jumping by
    /// F/(κGA − ρAv²) (Eq. 1 integrated across s = 0), to 1e-9 of their scales; and it decays both ways.
    #[test]
    fn across_the_load_the_shear_force_jumps_by_the_force() {
        let beam = rail(81e9);
        let foundation = Foundation::linear(250e3, 774.0 * 10.0);
        let moving = MovingTimoshenko::new(&beam, &foundation).unwrap();
        for v in [0.0, 100.0, 250.0] {
            let wave = moving.steady_state(v, 83.4e3).unwrap();
            let (before, after) = (-1e-13, 0.0);
            let w = wave.deflection(0.0).abs();
            assert!((wave.deflection(after) - wave.deflection(before)).abs() < 1e-9 * w, "v {v}");
            let psi = wave.rotation(1.0).abs();
            assert!((wave.rotation(after) - wave.rotation(before)).abs() < 1e-9 * psi, "v {v}");
            let m = wave.moment(0.0).abs();
            assert!((wave.moment(after) - wave.moment(before)).abs() < 1e-9 * m, "v {v}");
            let jump = wave.slope(after) - wave.slope(before);
            let expected = 83.4e3 / (beam.shear_stiffness().unwrap() - beam.mass_per_length() * v * v);
            assert!((jump / expected - 1.0).abs() < 1e-6, "v {v}: {jump} vs {expected}");
            assert!(wave.deflection(300.0).abs() < 1e-6 * w && wave.deflection(-300.0).abs() < 1e-6 * w);
        }
    }

    /// A shear modulus 10⁶ times steel's leaves the Rayleigh beam (Euler–Bernoulli with rotary inertia ρI): at rest
    /// Euler–Bernoulli's closed form to 1e-6; at 100 m/s within ρIv²/EI = v²ρ/E = 3.7e-4 of it.
    #[test]
    fn without_shear_flexibility_it_is_the_euler_bernoulli_beam() {
        let foundation = Foundation::linear(250e3, 774.0);
        let stiff = MovingTimoshenko::new(&rail(81e15), &foundation).unwrap();
        let euler = InfiniteBeam::new(&Beam::default(), &foundation).unwrap();
        for (v, tolerance) in [(0.0, 1e-6), (100.0, 1e-3)] {
            let (t, e) = (stiff.steady_state(v, 83.4e3).unwrap(), euler.steady_state(v, 83.4e3).unwrap());
            let (td, ed) = (t.extremes().max_downward.value, e.extremes().max_downward.value);
            assert!((td / ed - 1.0).abs() < tolerance, "v {v}: {td} vs {ed}");
            assert!((t.deflection(0.0) / e.deflection(0.0) - 1.0).abs() < tolerance);
        }
        // Undamped at or above the critical speed there is no steady state.
        let undamped = MovingTimoshenko::new(&rail(81e9), &Foundation::linear(250e3, 0.0)).unwrap();
        let v_cr = critical_speed(&rail(81e9), &Foundation::linear(250e3, 0.0)).unwrap();
        assert!(undamped.steady_state(0.9 * v_cr, 1.0).is_ok());
        assert!(matches!(undamped.steady_state(1.1 * v_cr, 1.0), Err(FemError::NoSteadyState { .. })));
    }
}
