//! What a stationary wave is asked of: the track (beam and soil), the load and its speed, and the moving domain.

use crate::error::{Result, StationaryError, invalid};
use analytic::MovingBeam;
use fem_beam::distributed::Quadrature;
use fem_beam::{Beam, DistributedFriction, Foundation};

/// The domain in moving coordinates s = x − vt (m): from `behind` m behind the load to `ahead` m ahead, in
/// elements of `element_length` m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    /// Length behind the load (m) > 0.
    pub behind: f64,
    /// Length ahead of the load (m) > 0.
    pub ahead: f64,
    /// Element length (m) > 0; rounded down so that the load sits on a node.
    pub element_length: f64,
}

impl Default for Domain {
    /// ±60 m in 0.25 m elements: the reference track's wave (length 2π/β = 20 m) resolved to 1e-6 of its peak, and
    /// room for lift-off zones; the transparent ends make the linear wave exact on any length.
    fn default() -> Self {
        Self { behind: 60.0, ahead: 60.0, element_length: 0.25 }
    }
}

/// The longest element accepted, in units of the shortest length 1/|r|ₘₐₓ of the track's waves
/// ([`StationaryProblem::check_resolution`]).
pub const RESOLUTION: f64 = 1.0;

/// The most elements of a domain (checked before anything is allocated).
pub const MAX_ELEMENTS: usize = 2_000_000;

impl Domain {
    /// Elements behind and ahead of the load, and the element length.
    pub fn elements(&self) -> (usize, usize, f64) {
        let l = self.element_length;
        let behind = (self.behind / l).ceil().max(1.0) as usize;
        let ahead = (self.ahead / l).ceil().max(1.0) as usize;
        (behind, ahead, l)
    }

    /// Check the lengths and the size.
    pub fn validate(&self) -> Result<()> {
        for (field, value) in [
            ("domain.behind", self.behind),
            ("domain.ahead", self.ahead),
            ("domain.element_length", self.element_length),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(invalid(field, value, "must be finite and > 0 (m)"));
            }
        }
        let (behind, ahead, _) = self.elements();
        if behind + ahead > MAX_ELEMENTS {
            return Err(invalid(
                "domain.element_length",
                self.element_length,
                format!("gives {} elements, more than {MAX_ELEMENTS}", behind + ahead),
            ));
        }
        Ok(())
    }
}

/// A point load moving at constant speed on an infinite beam on its foundation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StationaryProblem {
    /// The rail.
    pub beam: Beam,
    /// The soil: stiffness (in compression), damping and law.
    pub foundation: Foundation,
    /// The load F (N, downward) ≥ 0.
    pub load: f64,
    /// Its speed v (m/s) ≥ 0.
    pub speed: f64,
    /// Whether the rail's weight rests on a nonlinear soil (ignored on a linear one, where it only settles the
    /// rail uniformly).
    pub self_weight: bool,
    /// Friction in the ballast (none by default).
    pub friction: DistributedFriction,
    /// The moving domain.
    pub domain: Domain,
}

impl StationaryProblem {
    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<()> {
        self.beam.validate()?;
        self.foundation.validate()?;
        if self.foundation.stiffness <= 0.0 {
            return Err(invalid(
                "foundation.stiffness",
                self.foundation.stiffness,
                "must be > 0: without a foundation no stationary wave exists on an infinite beam",
            ));
        }
        if !(self.load.is_finite() && self.load >= 0.0) {
            return Err(invalid("load", self.load, "must be finite and ≥ 0 (N, downward)"));
        }
        // The moving-frame equations change type at the bar wave (Euler–Bernoulli) or the shear wave (Timoshenko).
        let limit = self.beam.wave_speed_limit();
        if !(self.speed.is_finite() && self.speed >= 0.0 && self.speed < limit) {
            return Err(invalid("speed", self.speed, format!("must lie in [0, {limit:.0}) m/s")));
        }
        self.friction.validate()?;
        if self.friction.quadrature != Quadrature::Trapezoid {
            return Err(StationaryError::InvalidChoice {
                field: "distributed.quadrature",
                value: self.friction.quadrature.name(),
                allowed: "must be the trapezoid sections (the default) of a time-domain run",
            });
        }
        self.domain.validate()
    }

    /// The shortest length (m) the track's waves vary on at this speed: 1/|r|ₘₐₓ over the wavenumbers r of the
    /// moving-frame equation EI r⁴ + ρA v² r² − c_f v r + k = 0 ([`MovingBeam::wavenumbers`]) of the soil pressed
    /// (k = k_c) and, on a nonlinear soil, where the rail lifts (k = k_t; on a tensionless soil the free rail's,
    /// whose fastest modes are r ≈ ±i v√(ρA/EI)). 2.25 m for the reference track at rest (√2 β = 0.444 m⁻¹).
    pub fn shortest_length(&self) -> Result<f64> {
        let f = &self.foundation;
        let largest = |stiffness: f64| -> Result<f64> {
            let soil = Foundation::linear(stiffness, f.damping);
            let r = MovingBeam::new(&self.beam, &soil)?.wavenumbers(self.speed);
            Ok(r.iter().map(|r| r.norm()).fold(0.0, f64::max))
        };
        let mut fastest = largest(f.stiffness)?;
        if self.is_nonlinear() {
            fastest = fastest.max(largest(f.tension_stiffness())?);
        }
        Ok(1.0 / fastest)
    }

    /// Refuse elements longer than [`RESOLUTION`] × [`Self::shortest_length`]: the wave is not resolved and its peaks
    /// are wrong by more than a few per cent (measured on the reference track at 100 m/s, 1/|r| = 2.25 m: 2 m
    /// elements leave the moment 4.3 % low, 5 m ones 26 % and the deflection 2 %, 100 m ones the deflection 10× low).
    pub fn check_resolution(&self) -> Result<()> {
        let shortest = self.shortest_length()?;
        let l = self.domain.element_length;
        if l > RESOLUTION * shortest {
            return Err(invalid(
                "domain.element_length",
                l,
                format!(
                    "is longer than the shortest length the wave varies on at {} m/s, 1/|r| = {shortest:.3} m \
                     (r the track's wavenumbers): the wave is not resolved and its peaks would be wrong; use \
                     elements of at most {:.3} m (0.25 m or less for peaks to ~0.1 %)",
                    self.speed,
                    RESOLUTION * shortest
                ),
            ));
        }
        Ok(())
    }

    /// Whether the ballast holds the rail by friction.
    pub fn has_friction(&self) -> bool {
        self.friction.force_per_length > 0.0
    }

    /// Whether the soil is nonlinear (sections carry its unilateral part).
    pub fn is_nonlinear(&self) -> bool {
        !self.foundation.law.is_linear()
    }

    /// Whether the soil is nonlinear and carries no weight: its far field rests on the soil without force, or lifts
    /// straight off it, and is not the linear one.
    pub fn is_weightless_nonlinear(&self) -> bool {
        self.is_nonlinear() && !self.self_weight
    }

    /// Whether the domain's ends are free (W″ = W‴ = 0) rather than transparent: on a weightless nonlinear soil, and
    /// with friction, which holds the rail at rest ahead of the wave and at its residual deflection behind it
    /// (W′ = 0 there, so W″ = W‴ = 0; a transparent rear would pull the rail back to W_far).
    pub fn has_free_ends(&self) -> bool {
        self.is_weightless_nonlinear() || self.has_friction()
    }

    /// The far field's level W_far (m): the self-weight settlement −ρA·g/k_c on a nonlinear soil with self-weight,
    /// else 0 (deflections from the settled state).
    pub fn far_level(&self) -> f64 {
        match self.is_nonlinear() && self.self_weight {
            true => -self.foundation.settlement(&self.beam),
            false => 0.0,
        }
    }
}
