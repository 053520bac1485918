//! Sleepers that differ from the rest (docs/theory.md §18): a soft spot (pad or ballast stiffness scaled), ballast
//! that pushes but cannot pull (tensionless), a voided (hanging) sleeper that meets the ballast only once a gap has
//! closed, and Coulomb friction at the sleeper–ballast interface in parallel with the ballast spring.
//!
//! This crate holds what they are and puts their linear part in M, C, K: the pad scaled; the ballast's spring in K
//! only where it is bonded (a tensionless or voided sleeper's spring is the engine's unilateral law on its DOF, force
//! k_b⟨−(z + g)⟩₊ with g the void); the ballast's dashpot c_b stays in C for every sleeper (a simplification: it damps a
//! hanging sleeper too). The friction slider and the unilateral spring are interactions placed by the `track` crate.

use crate::error::{FemError, Result};

/// The largest friction force a sleeper's exception takes (N): a hundred times any wheel load, where a slider is
/// locked whatever the track does; above it a value is a slip of units (1e12 N ran silently).
pub const MAX_SLEEPER_FRICTION: f64 = 1e7;

/// How the ballast holds a sleeper.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum BallastContact {
    /// A linear spring that pushes and pulls (the ballast's stiffness in K).
    #[default]
    Bonded,
    /// Pushes only, once the sleeper has come down by `gap` (m, ≥ 0; 0 for tensionless ballast in contact at rest).
    Unilateral {
        /// The void under the sleeper at rest (m).
        gap: f64,
    },
}

/// One or more consecutive sleepers that differ from the rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeperException {
    /// The first and last sleeper it applies to (0-based: sleeper i sits at first + i·a), inclusive.
    pub first: usize,
    /// See `first`.
    pub last: usize,
    /// The pad's stiffness times this (> 0). Default 1.
    pub pad_scale: f64,
    /// The ballast's stiffness and dashpot times this (≥ 0; 0: no ballast, the sleeper hangs from the rail). Default 1.
    pub ballast_scale: f64,
    /// How the ballast holds these sleepers. Default bonded.
    pub contact: BallastContact,
    /// The Coulomb friction force between sleeper and ballast, F (N, ≥ 0; 0 for none).
    pub friction: f64,
}

impl Default for SleeperException {
    fn default() -> Self {
        Self { first: 0, last: 0, pad_scale: 1.0, ballast_scale: 1.0, contact: BallastContact::Bonded, friction: 0.0 }
    }
}

fn invalid(exception: usize, key: &'static str, value: f64, allowed: String) -> FemError {
    FemError::InvalidSleeper { exception, key, value, allowed }
}

impl SleeperException {
    /// Check the values of the `index`-th exception; `count` sleepers lie on the beam.
    pub fn validate(&self, index: usize, count: usize) -> Result<()> {
        if self.first > self.last || self.last >= count {
            let allowed = format!(
                "sleepers are numbered 0 to {} on this track (sleeper i at first + i·spacing); give first ≤ last",
                count.saturating_sub(1)
            );
            return Err(invalid(index, "index", self.last.max(self.first) as f64, allowed));
        }
        let checks = [
            ("pad_scale", self.pad_scale, self.pad_scale > 0.0, "must be finite and > 0 (the pad's stiffness × it)"),
            ("ballast_scale", self.ballast_scale, self.ballast_scale >= 0.0, "must be finite and ≥ 0 (0: no ballast)"),
            (
                "friction",
                self.friction,
                (0.0..=MAX_SLEEPER_FRICTION).contains(&self.friction),
                "must lie in [0, 1e7] N: a sleeper's ballast friction is a few kN, and 10 MN already locks it",
            ),
        ];
        for (key, value, ok, allowed) in checks {
            if !(value.is_finite() && ok) {
                return Err(invalid(index, key, value, allowed.into()));
            }
        }
        if let BallastContact::Unilateral { gap } = self.contact
            && !(gap.is_finite() && gap >= 0.0)
        {
            return Err(invalid(index, "gap", gap, "must be finite and ≥ 0 (m, the void under the sleeper)".into()));
        }
        Ok(())
    }

    /// Whether it names sleeper `s`.
    pub fn covers(&self, s: usize) -> bool {
        (self.first..=self.last).contains(&s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;
    use crate::sleepers::Sleepers;

    #[test]
    fn the_last_exception_naming_a_sleeper_decides_and_bad_ones_are_named() {
        let voided = SleeperException {
            first: 2,
            last: 4,
            contact: BallastContact::Unilateral { gap: 1e-3 },
            ..SleeperException::default()
        };
        let soft = SleeperException { first: 4, last: 4, ballast_scale: 0.5, friction: 300.0, ..voided };
        let sleepers = Sleepers { exceptions: vec![voided, soft], ..Sleepers::default() };
        assert!(sleepers.support(1).is_linear());
        assert_eq!(sleepers.support(3).contact, BallastContact::Unilateral { gap: 1e-3 });
        assert_eq!(sleepers.support(3).bonded_stiffness(), 0.0);
        assert_eq!(sleepers.support(4).ballast.stiffness, 50e6);
        assert_eq!(sleepers.support(4).friction, 300.0);
        assert!(!sleepers.is_linear());
        let mesh = Mesh::new(6.0, 40).unwrap(); // 10 sleepers: 0 to 9
        assert!(sleepers.nodes(&mesh).is_ok());
        let beyond = Sleepers { exceptions: vec![SleeperException { first: 9, last: 10, ..voided }], ..sleepers };
        let error = beyond.nodes(&mesh).unwrap_err().to_string();
        assert!(error.contains("sleepers.exceptions[0].index = 10") && error.contains("0 to 9"), "{error}");
        let gap = SleeperException { contact: BallastContact::Unilateral { gap: -1e-3 }, ..voided };
        let error = gap.validate(1, 10).unwrap_err().to_string();
        assert!(error.contains("sleepers.exceptions[1].gap = -0.001"), "{error}");
        let pad = SleeperException { pad_scale: 0.0, ..voided }.validate(0, 10).unwrap_err().to_string();
        assert!(pad.contains("pad_scale = 0"), "{pad}");
    }
}
