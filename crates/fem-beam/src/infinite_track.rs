//! The infinite track's closed forms for either rail (docs/theory.md §8, §16): Euler–Bernoulli's
//! ([`crate::reference::InfiniteBeam`], Frýba's roots in ξ = βs) or Timoshenko's
//! ([`crate::moving_timoshenko::MovingTimoshenko`], the residues of its own quartic) — one steady state of a moving
//! force, its static limit and the critical speed, so that `frictrack analytic`, `reference` and the train's steady
//! state take the scenario's rail as it is.

use crate::dispersion::critical_speed;
use crate::error::Result;
use crate::moving_timoshenko::{MovingTimoshenko, TimoshenkoSteadyState};
use crate::properties::{Beam, Foundation};
use crate::reference::{InfiniteBeam, SteadyExtremes, SteadyState};

/// The infinite beam on its viscoelastic foundation, by rail theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InfiniteTrack {
    /// Euler–Bernoulli's closed form.
    EulerBernoulli(InfiniteBeam),
    /// Timoshenko's, with its critical speed (the least phase velocity of its bending waves).
    Timoshenko {
        /// The moving frame.
        moving: MovingTimoshenko,
        /// v_cr (m/s).
        critical_speed: f64,
        /// c_cr = 2√(k_f ρA) (N·s/m²).
        critical_damping: f64,
    },
}

/// The steady wave of a moving force, by rail theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SteadyWave {
    /// Euler–Bernoulli's.
    EulerBernoulli(SteadyState),
    /// Timoshenko's.
    Timoshenko(TimoshenkoSteadyState),
}

impl InfiniteTrack {
    /// The closed form of `beam` on `foundation` (k_f > 0).
    pub fn new(beam: &Beam, foundation: &Foundation) -> Result<Self> {
        let euler = InfiniteBeam::new(beam, foundation)?;
        Ok(match beam.shear_stiffness() {
            None => Self::EulerBernoulli(euler),
            Some(_) => Self::Timoshenko {
                moving: MovingTimoshenko::new(beam, foundation)?,
                critical_speed: critical_speed(beam, foundation)?,
                critical_damping: euler.critical_damping(),
            },
        })
    }

    /// v_cr (m/s).
    pub fn critical_speed(&self) -> f64 {
        match self {
            Self::EulerBernoulli(b) => b.critical_speed(),
            Self::Timoshenko { critical_speed, .. } => *critical_speed,
        }
    }

    /// c_cr = 2√(k_f ρA) (N·s/m²).
    pub fn critical_damping(&self) -> f64 {
        match self {
            Self::EulerBernoulli(b) => b.critical_damping(),
            Self::Timoshenko { critical_damping, .. } => *critical_damping,
        }
    }

    /// The steady wave of a force `force` (N, downward) at `speed` (m/s).
    pub fn steady_state(&self, speed: f64, force: f64) -> Result<SteadyWave> {
        Ok(match self {
            Self::EulerBernoulli(b) => SteadyWave::EulerBernoulli(b.steady_state(speed, force)?),
            Self::Timoshenko { moving, .. } => SteadyWave::Timoshenko(moving.steady_state(speed, force)?),
        })
    }

    /// The static deflection under `force` (m, magnitude): Fβ/2k_f, or the Timoshenko wave at rest.
    pub fn static_deflection(&self, force: f64) -> Result<f64> {
        match self {
            Self::EulerBernoulli(b) => Ok(b.static_deflection(force)),
            Self::Timoshenko { moving, .. } => Ok(-moving.steady_state(0.0, force)?.deflection(0.0)),
        }
    }

    /// The static bending moment under `force` (N·m, sagging): F/4β, or the Timoshenko wave's at rest.
    pub fn static_moment(&self, force: f64) -> Result<f64> {
        match self {
            Self::EulerBernoulli(b) => Ok(b.static_moment(force)),
            Self::Timoshenko { moving, .. } => Ok(moving.steady_state(0.0, force)?.moment(0.0)),
        }
    }
}

impl SteadyWave {
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
    pub fn extremes(&self) -> SteadyExtremes {
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
