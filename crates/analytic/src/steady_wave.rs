//! The steady wave of a moving force on the infinite beam ([`crate::MovingBeam`]): a sum of two decaying modes each
//! side of the load, W(s) = Re Σ C e^{rs}, with the rotation DOF each mode carries (Ψ = βW; β = r, the slope, for an
//! Euler–Bernoulli rail), read at any s = x − vt with its rates −vW′ and −vΨ′ and its extremes.

use crate::reference::scan_extremes;
use fem_beam::DeflectionExtremes;
use fem_beam::extreme::Extreme;
use num_complex::Complex64;

/// The steady wave of a moving force on either rail: W(s) = Re Σ C e^{rs} over each side's two roots, the rotation
/// DOF Re Σ C β e^{rs} ([`crate::MovingBeam::steady_state`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyWave {
    /// (r, C, β) ahead of the load (s ≥ 0).
    ahead: [(Complex64, Complex64, Complex64); 2],
    /// (r, C, β) behind it (s ≤ 0).
    behind: [(Complex64, Complex64, Complex64); 2],
    bending_stiffness: f64,
    speed: f64,
}

impl SteadyWave {
    /// The wave of the (r, C, β) terms `ahead` of the load (s ≥ 0) and `behind` it, on a rail of bending stiffness
    /// `bending_stiffness` (N·m²) moving at `speed` (m/s).
    pub(crate) fn new(
        ahead: [(Complex64, Complex64, Complex64); 2],
        behind: [(Complex64, Complex64, Complex64); 2],
        bending_stiffness: f64,
        speed: f64,
    ) -> Self {
        Self { ahead, behind, bending_stiffness, speed }
    }

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

    /// W′ (rad) at s; on a Timoshenko rail it jumps at the load by the shear force's jump F/(κGA − ρAv²).
    pub fn slope(&self, s: f64) -> f64 {
        self.sum(s, |r, _| r)
    }

    /// The rotation DOF θ (rad) at s: the cross-section's Ψ of a Timoshenko rail, the slope W′ of an
    /// Euler–Bernoulli one.
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

    /// ∂θ/∂t = −v θ′ (rad/s) at s.
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
