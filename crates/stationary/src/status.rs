//! How a stationary solve ended ([`Convergence`]) and what it leaves the next one to start from ([`ContactGuess`]:
//! continuation in speed, or the same speed on another mesh).

use crate::error::Result;
use crate::operator::MovingFrame;
use crate::problem::StationaryProblem;

/// How the iteration ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Convergence {
    /// The pressed set repeated: the wave solves the discrete equations to round-off.
    Converged {
        /// Newton iterations and path-search flips (each one factorisation).
        iterations: usize,
        /// ‖A W − p_soil(W) − f‖∞ / ‖f‖∞ of the wave.
        residual: f64,
    },
    /// The set kept changing (or cycled) for the iteration limit.
    NotConverged {
        /// Iterations and flips taken.
        iterations: usize,
        /// Relative residual of the last iterate.
        residual: f64,
    },
    /// The rail still left the soil at an end of the largest domain tried.
    DomainTooShort {
        /// The domain's length behind and ahead of the load then (m).
        behind: f64,
        /// Ahead (m).
        ahead: f64,
    },
}

impl Convergence {
    /// Whether the wave is the solution.
    pub fn is_converged(&self) -> bool {
        matches!(self, Convergence::Converged { .. })
    }

    /// The Newton iterations taken (0 for a domain too short).
    pub fn iterations(&self) -> usize {
        match self {
            Convergence::Converged { iterations, .. } | Convergence::NotConverged { iterations, .. } => *iterations,
            Convergence::DomainTooShort { .. } => 0,
        }
    }
}

/// The pressed set of one solve, to start the next speed's from (continuation in speed).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactGuess {
    pressed: Vec<bool>,
    wave: Vec<f64>,
    /// The same speed's wave on another mesh (not a neighbouring speed's): the friction stages start at the full
    /// stiffness from it.
    same_speed: bool,
}

impl ContactGuess {
    pub(crate) fn forget(&mut self) {
        self.pressed.clear();
        self.wave.clear();
        self.same_speed = false;
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.pressed.is_empty() && self.wave.is_empty()
    }

    /// A guess for `problem` from the DOFs `wave` (deflection and slope at each node of its domain, absolute): the
    /// soil sections it presses, and the wave to start the friction iteration from.
    pub fn started_at(problem: &StationaryProblem, wave: Vec<f64>) -> Result<Self> {
        let frame = MovingFrame::new(problem)?;
        let pressed = frame.sections.iter().map(|s| s.deflection(&wave) < 0.0).collect();
        Ok(Self { pressed, wave, same_speed: true })
    }

    /// Whether the wave is the same speed's (on another mesh), to be taken at the full friction stiffness.
    pub(crate) fn is_same_speed(&self) -> bool {
        self.same_speed
    }

    pub(crate) fn remember(&mut self, pressed: Vec<bool>, wave: &[f64]) {
        self.pressed = pressed;
        self.wave = wave.to_vec();
        self.same_speed = false;
    }

    /// Start the next solve from `wave` (its DOFs on a grown domain), keeping the pressed set.
    pub(crate) fn set_wave(&mut self, wave: Vec<f64>) {
        self.wave = wave;
    }

    /// The last wave's DOFs, if it fits a domain of `dofs`.
    pub(crate) fn wave(&self, dofs: usize) -> Option<&[f64]> {
        (self.wave.len() == dofs).then_some(&self.wave[..])
    }

    /// The last pressed set, if it fits `sections`.
    pub(crate) fn pressed(&self, sections: usize) -> Option<&[bool]> {
        (self.pressed.len() == sections).then_some(&self.pressed[..])
    }
}
