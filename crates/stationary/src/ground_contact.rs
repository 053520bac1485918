//! Lift-off on the ground: the two-beam track whose ballast cannot pull the sleepers down onto the embankment
//! (docs/theory.md §19, "Lift-off on the ground"). The ground, the embankment, the pads and the rail stay linear and
//! exact ([`InterfaceSpectra`]); the ballast's spring k_b/a (N/m² per rail) acts on the sleepers' deflection less the
//! embankment's, d_tot = d₀ + d, only while it is pressed (d_tot ≤ 0), d₀ = −(ρA_r a + m_s) g/k_b its compression
//! under the rail's and the sleepers' weight (0 without weight). Where the ballast would pull, a pair of forces
//! across it cancels the linear spring's tension, p_j = −(k_b/a)⟨d₀ + d_j⟩₊ (positive pressing), at the points s_j
//! of a window around the train and linear between them, so at the points
//!
//! ```text
//! d_i = d_lin(s_i) + Σ_j P(s_i − s_j) p_j,        W = W_lin + Σ_j P_r(s − s_j) p_j
//! ```
//!
//! with P and P_r a hat pair's waves in d and in the rail (a Toeplitz matrix, applied by FFT). For the set of points
//! that lift, the equations are linear: with O the lifted points, (I + (k_b/a) P_OO) d_O = d_lin,O − (k_b/a) P_OO d₀,
//! one dense solve over the lifted points (a train's lift-off zones are metres long), the rest explicit. The sets are
//! found by the Winkler solver's Newton iteration with backtracking, shared (`newton::iterate`). The ballast's
//! dashpot and hysteresis act throughout, as a tensionless Winkler soil's do (§14): only its spring lets go.

use crate::control::Control;
use crate::error::{Result, invalid};
use crate::friction::FrictionSections;
use crate::ground::GroundWindow;
use crate::newton::{Evaluation, MAX_ITERATIONS, SetProblem, iterate};
use crate::operator::factor;
use crate::sets::Sets;
use crate::status::{ContactGuess, Convergence};
use crate::toeplitz::Toeplitz;
use analytic::ground::InterfaceSpectra;
use banded::general::GeneralBanded;
use fem_beam::Axle;

/// The most points that may lift at once (each Newton step solves over them densely: 2000 points, 96 MB): 500 m of
/// track at 0.25 m, far beyond a train's lift-off zones.
pub const MAX_LIFTED: usize = 2000;

/// A train moving on the two-beam track on the ground whose ballast cannot pull.
#[derive(Debug, Clone, Copy)]
pub struct GroundContactProblem<'a> {
    /// The track's spectra at this speed, for pairs spread over the window's spacing.
    pub spectra: &'a InterfaceSpectra,
    /// The axles (offsets behind the first, m; forces downward, N).
    pub axles: &'a [Axle],
    /// v (m/s), naming a singular solve.
    pub speed: f64,
    /// Where the ballast may let go and the wave is solved (its step the spectra's spacing).
    pub window: GroundWindow,
    /// k_b/a: the ballast's spring per metre of one rail (N/m²) > 0.
    pub ballast_stiffness: f64,
    /// d₀ ≤ 0: the sleepers' deflection less the embankment's under the track's weight (m; 0 without it).
    pub preload: f64,
}

/// The wave with lift-off at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundContactWave {
    /// s_i (m).
    pub s: Vec<f64>,
    /// The rail's W(s_i) (m, upward; the train's part, the weight's uniform settlement left out).
    pub deflection: Vec<f64>,
    /// d(s_i): the sleepers' deflection less the embankment's, the train's part (m).
    pub relative: Vec<f64>,
    /// (k_b/a)⟨−d₀ − d_i⟩₊: the ballast's elastic push per metre of rail, weight included (N/m, ≥ 0).
    pub ballast_force: Vec<f64>,
    /// Where the sleepers have lifted off the ballast.
    pub lifted: Vec<bool>,
    /// How the Newton iteration ended.
    pub convergence: Convergence,
    /// d₀ (m).
    pub preload: f64,
    /// The points.
    window: GroundWindow,
    /// The pairs p_j (N/m, positive pressing).
    pairs: Vec<f64>,
    /// P_r(d·h) (m per N/m) for d = −(n − 1) … n − 1: a hat pair's rail wave at the points' spacings.
    pair_rail: Vec<f64>,
    /// P(d·h): its d.
    pair_relative: Vec<f64>,
}

impl GroundContactWave {
    /// What the pairs add to the rail's linear wave at any s of the window (m), P_r read between its values at the
    /// points' spacings by the cubic through the four nearest.
    pub fn carried(&self, s: f64) -> f64 {
        self.by_pairs(&self.pair_rail, s)
    }

    /// What the pairs add to d's linear wave at any s of the window (m), read as [`Self::carried`].
    pub fn carried_relative(&self, s: f64) -> f64 {
        self.by_pairs(&self.pair_relative, s)
    }

    /// Σ_j K(s − s_j) p_j with K given at the points' spacings (`kernel`).
    fn by_pairs(&self, kernel: &[f64], s: f64) -> f64 {
        self.window.superposed(kernel, |j| self.pairs[j], s)
    }

    /// The length of track over which the sleepers have lifted (m).
    pub fn lifted_length(&self) -> f64 {
        let step = self.s[1] - self.s[0];
        self.lifted.iter().filter(|&&l| l).count() as f64 * step
    }

    /// The widest opening between the sleepers and the ballast at the points, max⟨d₀ + d_i⟩₊ (m).
    pub fn largest_gap(&self) -> f64 {
        self.relative.iter().fold(0.0f64, |m, d| m.max(self.preload + d))
    }
}

/// The equations on the window.
#[derive(Clone)]
struct ContactFrame {
    linear: Vec<f64>,
    /// P(d·h) for d = −(n − 1) … n − 1.
    diagonals: Vec<f64>,
    influence: Toeplitz,
    stiffness: f64,
    preload: f64,
    speed: f64,
    scale: f64,
}

impl ContactFrame {
    fn new(problem: &GroundContactProblem<'_>) -> Result<Self> {
        problem.window.validate()?;
        problem.window.check_pair_spacing(problem.spectra)?;
        if !(problem.ballast_stiffness.is_finite() && problem.ballast_stiffness > 0.0) {
            return Err(invalid(
                "ballast_stiffness",
                problem.ballast_stiffness,
                "must be finite and > 0 (N/m² of rail: k_b/a)",
            ));
        }
        if !(problem.preload.is_finite() && problem.preload <= 0.0) {
            return Err(invalid(
                "preload",
                problem.preload,
                "must be finite and ≤ 0 (m): the weight presses the ballast",
            ));
        }
        let positions = problem.window.positions();
        let linear = problem.spectra.relative.wave_under(problem.axles, &positions);
        let diagonals = problem.window.at_spacings(&problem.spectra.pair_relative);
        let scale = linear.iter().fold(0.0f64, |m, d| m.max(d.abs())).max(f64::MIN_POSITIVE);
        Ok(Self {
            influence: Toeplitz::new(&diagonals),
            diagonals,
            linear,
            stiffness: problem.ballast_stiffness,
            preload: problem.preload,
            speed: problem.speed,
            scale,
        })
    }

    /// p_j of `d` where `open` (the lifted points): −(k_b/a)(d₀ + d_j), else 0.
    fn pairs(&self, d: &[f64], open: &[bool]) -> Vec<f64> {
        d.iter().zip(open).map(|(d, &o)| if o { -self.stiffness * (self.preload + d) } else { 0.0 }).collect()
    }

    /// The points where the ballast would pull at `d`.
    fn lifted(&self, d: &[f64]) -> Vec<bool> {
        d.iter().map(|d| self.preload + d > 0.0).collect()
    }

    /// P at the offset i − j.
    fn at(&self, i: usize, j: usize) -> f64 {
        self.diagonals[i + self.linear.len() - 1 - j]
    }
}

impl SetProblem for ContactFrame {
    fn evaluate(&self, d: &[f64]) -> Evaluation {
        let lifted = self.lifted(d);
        let carried = self.influence.apply(&self.pairs(d, &lifted));
        let residual: Vec<f64> = (0..d.len()).map(|i| d[i] - self.linear[i] - carried[i]).collect();
        let norm = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
        let relative = residual.iter().fold(0.0f64, |m, r| m.max(r.abs())) / self.scale;
        let pressed = lifted.iter().map(|l| !l).collect();
        Evaluation { norm, relative, sets: Sets { pressed, friction: None } }
    }

    fn newton_point(&self, sets: &Sets, _speed: f64) -> Result<Vec<f64>> {
        let open: Vec<usize> = (0..sets.pressed.len()).filter(|&i| !sets.pressed[i]).collect();
        let mut d = self.linear.clone();
        if open.is_empty() {
            return Ok(d);
        }
        if open.len() > MAX_LIFTED {
            let allowed = format!("at most {MAX_LIFTED} points of the window may lift at once: the track floats");
            return Err(invalid("lifted points", open.len() as f64, allowed));
        }
        let m = open.len();
        let mut matrix = GeneralBanded::zeros(m, m - 1, m - 1);
        let mut rhs = vec![0.0; m];
        for (a, &i) in open.iter().enumerate() {
            for (b, &j) in open.iter().enumerate() {
                let coupling = self.stiffness * self.at(i, j);
                matrix.add(a, b, coupling + if a == b { 1.0 } else { 0.0 });
                rhs[a] -= coupling * self.preload;
            }
            rhs[a] += self.linear[i];
        }
        factor(matrix, self.speed)?.solve_in_place(&mut rhs);
        open.iter().zip(&rhs).for_each(|(&i, v)| d[i] = *v);
        let open_set: Vec<bool> = sets.pressed.iter().map(|p| !p).collect();
        let carried = self.influence.apply(&self.pairs(&d, &open_set));
        Ok(self.linear.iter().zip(&carried).map(|(l, c)| l + c).collect())
    }

    fn friction_mut(&mut self) -> Option<&mut FrictionSections> {
        None
    }

    fn has_friction(&self) -> bool {
        false
    }
}

/// The wave of `problem` with lift-off, from `guess` (the previous speed's d on the same window, if it fits) or
/// from the linear wave, within `control`.
pub fn solve_with_lift_off(
    problem: &GroundContactProblem<'_>,
    guess: &mut ContactGuess,
    control: &Control<'_>,
) -> Result<GroundContactWave> {
    let frame = ContactFrame::new(problem)?;
    let start = guess.wave(problem.window.count).map_or_else(|| frame.linear.clone(), <[f64]>::to_vec);
    let (d, convergence) = iterate(&frame, problem.speed, start, (guess, control), MAX_ITERATIONS)?;
    let lifted = frame.lifted(&d);
    let pairs = frame.pairs(&d, &lifted);
    let positions = problem.window.positions();
    let rail_linear = problem.spectra.rail.wave_under(problem.axles, &positions);
    let pair_rail = problem.window.at_spacings(&problem.spectra.pair_rail);
    let carried = Toeplitz::new(&pair_rail).apply(&pairs);
    let ballast_force = d.iter().map(|d| frame.stiffness * (-(frame.preload + d)).max(0.0)).collect();
    Ok(GroundContactWave {
        s: positions,
        deflection: rail_linear.iter().zip(&carried).map(|(l, c)| l + c).collect(),
        relative: d,
        ballast_force,
        lifted,
        convergence,
        preload: frame.preload,
        window: problem.window,
        pairs,
        pair_rail,
        pair_relative: frame.diagonals,
    })
}
