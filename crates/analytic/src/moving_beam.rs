//! The moving-frame beam (docs/theory.md §8, §14, §16): an infinite rail — Euler–Bernoulli or Timoshenko, as the
//! scenario gives it — on a linear viscoelastic foundation, seen from a load moving along it at speed v. The one
//! entry every caller asks what depends on the rail theory: the roots r of the characteristic polynomial of
//! s = x − vt (the modes e^{rs} of the unloaded track), the rotation each mode carries (Ψ/W), the roots that decay
//! ahead of and behind the load, the steady wave of a moving force with its decay rates, its static limit, the
//! critical speed, critical damping and the speed beyond which the moving-frame equations change type.
//!
//! Euler–Bernoulli is the κGA → ∞, ρI → 0 limit of the Timoshenko quartic, evaluated in Frýba's scaled variable
//! ξ = βs ([`crate::reference::InfiniteBeam`]); a Timoshenko rail by the residues of its own quartic
//! ([`crate::moving_timoshenko::MovingTimoshenko`]). The tests check each against the other at large κGA.

use crate::dispersion::critical_speed;
use crate::moving_timoshenko::{MovingTimoshenko, TimoshenkoSteadyState};
use crate::reference::{InfiniteBeam, SteadyState};
use fem_beam::DeflectionExtremes;
use fem_beam::error::Result;
use fem_beam::properties::{Beam, Foundation};
use fem_beam::sleepers::Sleepers;
use num_complex::Complex64;

/// The infinite beam on its viscoelastic foundation in the frame of a moving load, by rail theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovingBeam {
    rail: Rail,
    /// v_cr (m/s).
    critical_speed: f64,
    /// c_cr = 2√(k_f ρA) (N·s/m²).
    critical_damping: f64,
    /// The speed (m/s) at which the moving-frame equations change type ([`Beam::wave_speed_limit`]).
    wave_speed_limit: f64,
}

/// The closed form behind a [`MovingBeam`].
#[derive(Debug, Clone, Copy, PartialEq)]
enum Rail {
    EulerBernoulli(InfiniteBeam),
    Timoshenko(MovingTimoshenko),
}

/// The steady wave of a moving force, by rail theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SteadyWave {
    /// Euler–Bernoulli's.
    EulerBernoulli(SteadyState),
    /// Timoshenko's.
    Timoshenko(TimoshenkoSteadyState),
}

impl MovingBeam {
    /// The moving frame of `beam` on `foundation` (its linear stiffness k_f and damping c_f ≥ 0). An Euler–Bernoulli
    /// rail needs k_f > 0 (β = (k_f/4EI)^¼ scales its closed form); a Timoshenko rail takes k_f = 0 too (the free
    /// rail, critical speed 0).
    pub fn new(beam: &Beam, foundation: &Foundation) -> Result<Self> {
        let critical_damping = foundation.critical_damping(beam);
        let wave_speed_limit = beam.wave_speed_limit();
        let (rail, critical_speed) = match beam.shear_stiffness() {
            None => {
                let euler = InfiniteBeam::new(beam, foundation)?;
                (Rail::EulerBernoulli(euler), euler.critical_speed())
            }
            Some(_) => {
                beam.validate()?;
                fem_beam::error::non_negative("foundation.stiffness", foundation.stiffness)?;
                fem_beam::error::non_negative("foundation.damping", foundation.damping)?;
                let critical = match foundation.stiffness > 0.0 {
                    true => critical_speed(beam, foundation)?,
                    false => 0.0,
                };
                (Rail::Timoshenko(MovingTimoshenko::new(beam, foundation)?), critical)
            }
        };
        Ok(Self { rail, critical_speed, critical_damping, wave_speed_limit })
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

    /// The four roots r (1/m) of the characteristic polynomial at `speed` (m/s), unordered: every solution of the
    /// unloaded track in s = x − vt is a sum of e^{rs}. They exist at every speed; undamped above v_cr some lie on
    /// the imaginary axis. Their largest modulus sets the shortest length a mesh must resolve.
    pub fn wavenumbers(&self, speed: f64) -> [Complex64; 4] {
        match &self.rail {
            Rail::EulerBernoulli(b) => b.wavenumbers(speed),
            Rail::Timoshenko(t) => t.wavenumbers(speed),
        }
    }

    /// The roots that decay away from the load at `speed`: two ahead (Re r < 0), then two behind (Re r > 0);
    /// [`fem_beam::FemError::NoSteadyState`] where a root lies on the imaginary axis (undamped at or above v_cr).
    pub fn decaying_wavenumbers(&self, speed: f64) -> Result<[Complex64; 4]> {
        match &self.rail {
            Rail::EulerBernoulli(b) => Ok(b.steady_state(speed, 1.0)?.roots().map(|r| r * b.beta())),
            Rail::Timoshenko(t) => t.decaying_wavenumbers(speed),
        }
    }

    /// The rotation DOF each mode e^{rs} carries at `speed`, with its derivative in r: Euler–Bernoulli's θ = W′
    /// (β = r, dβ/dr = 1); Timoshenko's cross-section Ψ = β(r) W with β = G r/(G + D r²) and
    /// dβ/dr = G(G − D r²)/(G + D r²)², G = κGA, D = ρIv² − EI.
    pub fn rotation_per_deflection(&self, r: Complex64, speed: f64) -> (Complex64, Complex64) {
        match &self.rail {
            Rail::EulerBernoulli(_) => (r, Complex64::new(1.0, 0.0)),
            Rail::Timoshenko(t) => (t.rotation_per_deflection(r, speed), t.rotation_slope(r, speed)),
        }
    }

    /// The steady wave of a force `force` (N, downward) at `speed` (m/s).
    pub fn steady_state(&self, speed: f64, force: f64) -> Result<SteadyWave> {
        Ok(match &self.rail {
            Rail::EulerBernoulli(b) => SteadyWave::EulerBernoulli(b.steady_state(speed, force)?),
            Rail::Timoshenko(t) => SteadyWave::Timoshenko(t.steady_state(speed, force)?),
        })
    }

    /// The static deflection under `force` (m, magnitude): Fβ/2k_f, or the Timoshenko wave at rest.
    pub fn static_deflection(&self, force: f64) -> Result<f64> {
        match &self.rail {
            Rail::EulerBernoulli(b) => Ok(b.static_deflection(force)),
            Rail::Timoshenko(t) => Ok(-t.steady_state(0.0, force)?.deflection(0.0)),
        }
    }

    /// The static bending moment under `force` (N·m, sagging): F/4β, or the Timoshenko wave's at rest.
    pub fn static_moment(&self, force: f64) -> Result<f64> {
        match &self.rail {
            Rail::EulerBernoulli(b) => Ok(b.static_moment(force)),
            Rail::Timoshenko(t) => Ok(t.steady_state(0.0, force)?.moment(0.0)),
        }
    }
}

impl SteadyWave {
    /// The slowest decay rates of the wave ahead of and behind the load (1/m): it falls to a fraction ε of its size
    /// within ln(1/ε)/rate of the load.
    pub fn decay_rates(&self) -> (f64, f64) {
        match self {
            Self::EulerBernoulli(w) => w.decay_rates(),
            Self::Timoshenko(w) => w.decay_rates(),
        }
    }

    /// W (m, upward) at s = x − vt (m).
    pub fn deflection(&self, s: f64) -> f64 {
        match self {
            Self::EulerBernoulli(w) => w.deflection(s),
            Self::Timoshenko(w) => w.deflection(s),
        }
    }

    /// The rotation DOF θ at s (rad): W′ for Euler–Bernoulli, the cross-section's Ψ for Timoshenko.
    pub fn rotation(&self, s: f64) -> f64 {
        match self {
            Self::EulerBernoulli(w) => w.slope(s),
            Self::Timoshenko(w) => w.rotation(s),
        }
    }

    /// ∂w/∂t = −v W′ (m/s) at s.
    pub fn velocity(&self, s: f64) -> f64 {
        match self {
            Self::EulerBernoulli(w) => w.velocity(s),
            Self::Timoshenko(w) => w.velocity(s),
        }
    }

    /// ∂θ/∂t = −v θ′ (rad/s) at s.
    pub fn rotation_rate(&self, s: f64) -> f64 {
        match self {
            Self::EulerBernoulli(w) => w.rotation_rate(s),
            Self::Timoshenko(w) => w.rotation_rate(s),
        }
    }

    /// The largest downward and upward deflections and where.
    pub fn extremes(&self) -> DeflectionExtremes {
        match self {
            Self::EulerBernoulli(w) => w.extremes(),
            Self::Timoshenko(w) => w.extremes(),
        }
    }

    /// How to sample the wave for its extremes (m): a step that resolves its shortest wave, and the reach beyond
    /// which it is below e⁻⁴⁰ of its size.
    pub fn sampling(&self) -> (f64, f64) {
        match self {
            Self::EulerBernoulli(w) => w.sampling(),
            Self::Timoshenko(w) => w.sampling(),
        }
    }
}
