//! Ballast friction under a train on the ground (docs/theory.md §19, "Ballast friction on the ground"). The ground
//! is linear but non-local: the wave of a unit downward force is W₁(s) (the moving-load Fourier integral of
//! `analytic::ground`, exact through the ln k head of a strip whose static line stiffness vanishes at k = 0). The
//! friction forces act at the points s_i = s₀ + i h of a window around the train, each a Jenkins section of the play
//! operator marched from the front ([`crate::friction`], trapezoid weights h, h/2 at the ends), so the deflection at
//! the points is
//!
//! ```text
//! W_i = W_lin(s_i) + Σ_j W₁(s_i − s_j) h_j r_j(W)       (r_j upward on the ballast, so downward on the track)
//! ```
//!
//! with W_lin the train's linear wave. The matrix W₁(s_i − s_j) is Toeplitz, applied by FFT ([`crate::toeplitz`]).
//! For the sets of W (each section slipping or stuck, to which anchor) the equations are linear,
//! (I − W₁ H K) W = W_lin + W₁ H c, solved by GMRES ([`crate::krylov`]) preconditioned with the same equations on a
//! local operator: the beam on a Winkler foundation fitted to the ground at this speed, one banded factorisation with
//! the stuck springs and the anchors' couplings (`sets::SetSystem`): its inverse is
//! I − Eᵀ(A + E H K Eᵀ)⁻¹ E H K (E the points' deflection DOFs of the local mesh). The sets are found by the Newton
//! iteration and the continuation in the Jenkins stiffness of the Winkler solver, shared.
//!
//! On the two-beam track ([`FrictionTrack::RailOnEmbankment`]) the friction acts between the sleepers and the
//! embankment, on d = u_s − u_e in place of W: its forces are pairs across the ballast (downward on the sleepers,
//! upward on the embankment), each section's spread as a hat over the points' spacing, so W₁ becomes P/h (P the
//! spectra's wave in d of a hat pair pressing the sleepers down, per N/m) and the rail's wave gains
//! Σ_j P_r(s − s_j) h_j r_j / h (P_r its wave in the rail); the local operator is what a pair meets in the short
//! waves (`analytic::ground::TrackOnEmbankment::local_across_ballast`), and the κ continuation climbs by factors of
//! [`BALLAST_STAGE_FACTOR`].
//!
//! Beyond the window the ballast is taken to hold no force. Ahead the rail rests; behind the train the rail creeps
//! back up as the ground recovers and slips at f_u along the whole window, a tail whose weight grows like ln L on a
//! ground whose long waves are ln-soft (at Ledsgård the peak deepens by 0.02–0.03 % a doubling of the window
//! behind); [`GroundFrictionWave::end_forces`] says what the window's ends still hold.

use crate::continuation::{self, with_iterations};
use crate::control::Control;
use crate::error::{Result, invalid};
use crate::friction::FrictionSections;
use crate::krylov::gmres;
use crate::newton::{Evaluation, MAX_ITERATIONS, SetProblem, iterate};
use crate::operator::MovingFrame;
use crate::problem::{Domain, StationaryProblem};
use crate::sets::{SetSystem, Sets};
use crate::status::{ContactGuess, Convergence};
use crate::toeplitz::Toeplitz;
use analytic::ground::{InterfaceSpectra, MovingSpectrum};
use analytic::interpolation::read_equally_spaced;
use fem_beam::distributed::Quadrature;
use fem_beam::{Axle, Beam, DistributedFriction, Foundation};
use std::cell::Cell;
use std::rc::Rc;

/// GMRES's relative tolerance in a Newton step: well below [`crate::newton::ROUND_OFF`], at which the sets' solution
/// counts as the wave.
const KRYLOV_TOLERANCE: f64 = 1e-12;
/// The Jenkins sections' give f_u/κ as a share of the linear wave's peak: κ = f_u/(1e-6·max|W_lin|) moves a stuck
/// point by at most 1e-6 of the peak (capped at the Winkler solver's 1e6·k_f of the local foundation, meant to match
/// a run's rigid Coulomb law, which gives ~1e-8 here at twice the Newton iterations). Measured at Ledsgård, 185 km/h:
/// the deepest point moves by 8e-7 (1 kN/m) to 6.5e-6 (5 kN/m) of itself against 1e-8.
pub const JENKINS_GIVE: f64 = 1e-6;
/// The most points of a window (checked before anything is allocated): GMRES keeps up to 400 vectors
/// of them, 64 MB at this size.
pub const MAX_POINTS: usize = 20_000;
/// The most GMRES steps of one Newton step (measured 10–40 on the Ledsgård site).
const KRYLOV_LIMIT: usize = 400;
/// The factor between the κ stages of the friction across the ballast of the two-beam track: its stages at high κ
/// take 20–30 Newton steps even a factor 1.5 apart, and a factor of ten fails twice on the way (100 steps each).
/// Measured at Ledsgård (X2000, 185 km/h, 2 kN/m, from cold, with a near twin of today's preconditioner): 157 Newton
/// steps at 2, 167 at 2.5, 176 at 1.7, 200 at 1.5, 339 at √10, 410 at 10 — where the composite beam takes 96 at 10
/// and 126 at 2 (BENCHMARKS.md).
pub const BALLAST_STAGE_FACTOR: f64 = 2.0;

/// The points of the window: s_i = `first` + i·`step`, i < `count` (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundWindow {
    /// s₀ (m).
    pub first: f64,
    /// h (m) > 0.
    pub step: f64,
    /// How many points, ≥ 3.
    pub count: usize,
}

impl GroundWindow {
    /// The positions s_i (m).
    pub fn positions(&self) -> Vec<f64> {
        (0..self.count).map(|i| self.first + i as f64 * self.step).collect()
    }

    /// The step finite and > 0 (`domain.element_length`), 3 to [`MAX_POINTS`] points from a finite s₀ (`domain`):
    /// checked before anything is allocated.
    pub fn validate(&self) -> Result<()> {
        if !(self.step.is_finite() && self.step > 0.0) {
            return Err(invalid("domain.element_length", self.step, "must be finite and > 0 (m)"));
        }
        if !(3..=MAX_POINTS).contains(&self.count) || !self.first.is_finite() {
            let allowed = format!("must hold 3 to {MAX_POINTS} points (5 km at 0.25 m) from a finite s₀");
            return Err(invalid("domain", self.count as f64, allowed));
        }
        Ok(())
    }

    /// The step is the spacing `spectra`'s pairs are spread over (`domain.element_length`, to 1e-12 of itself).
    pub(crate) fn check_pair_spacing(&self, spectra: &InterfaceSpectra) -> Result<()> {
        if (self.step - spectra.spacing).abs() > 1e-12 * self.step {
            let allowed = "must be the spacing the spectra's pairs are spread over";
            return Err(invalid("domain.element_length", self.step, allowed));
        }
        Ok(())
    }

    /// Σ_j K(s − s_j) a_j over the points for the amplitudes `amplitude(j)` (skipping zeros), with K given at the
    /// points' spacings (`kernel`, from [`Self::at_spacings`]) and read between them by the cubic through the four
    /// nearest (the points' own values exact).
    pub(crate) fn superposed(&self, kernel: &[f64], amplitude: impl Fn(usize) -> f64, s: f64) -> f64 {
        let reach = -((self.count - 1) as f64) * self.step;
        (0..self.count)
            .map(|j| (j, amplitude(j)))
            .filter(|&(_, a)| a != 0.0)
            .map(|(j, a)| read_equally_spaced(kernel, reach, self.step, s - (self.first + j as f64 * self.step)) * a)
            .sum()
    }

    /// `spectrum`'s wave at the points' spacings, W(d·h) for d = −(n − 1) … n − 1: the diagonals of the Toeplitz
    /// influence between the points.
    pub fn at_spacings(&self, spectrum: &MovingSpectrum) -> Vec<f64> {
        let reach = (self.count - 1) as f64 * self.step;
        spectrum.deflections_on_grid(-reach, self.step, 2 * self.count - 1)
    }
}

/// The track the ballast's friction acts in, and on what.
#[derive(Debug, Clone, Copy)]
pub enum FrictionTrack<'a> {
    /// The composite beam: the friction acts on its deflection W against the ground beneath; one unit downward
    /// force's spectrum at the speed (its wave W₁, m/N).
    Composite(&'a MovingSpectrum),
    /// The rail on sleepers over the embankment: the friction acts on d = u_s − u_e across the ballast; the track's
    /// spectra at the speed, their pairs spread over the window's spacing.
    RailOnEmbankment(&'a InterfaceSpectra),
}

impl FrictionTrack<'_> {
    /// The friction's field at the points under the axles alone (W or d, m) and its wave per newton of friction
    /// force at the points' spacings (m/N: W₁, or P/h for a hat pair of 1/h N/m pressing the sleepers down).
    fn field(&self, axles: &[Axle], window: &GroundWindow) -> Result<(Vec<f64>, Vec<f64>)> {
        let positions = window.positions();
        match self {
            Self::Composite(spectrum) => Ok((spectrum.wave_under(axles, &positions), window.at_spacings(spectrum))),
            Self::RailOnEmbankment(spectra) => {
                window.check_pair_spacing(spectra)?;
                let per_newton = window.at_spacings(&spectra.pair_relative).iter().map(|p| p / window.step).collect();
                Ok((spectra.relative.wave_under(axles, &positions), per_newton))
            }
        }
    }

    /// The rail's wave at the points under the axles alone (m); None on the composite beam, whose rail is the field.
    fn rail_under(&self, axles: &[Axle], window: &GroundWindow) -> Option<Vec<f64>> {
        let Self::RailOnEmbankment(spectra) = self else { return None };
        Some(spectra.rail.wave_under(axles, &window.positions()))
    }

    /// The rail's wave per newton of friction force at the points' spacings (m/N: P_r/h); None on the composite beam.
    fn rail_per_newton(&self, window: &GroundWindow) -> Option<Vec<f64>> {
        let Self::RailOnEmbankment(spectra) = self else { return None };
        Some(window.at_spacings(&spectra.pair_rail).iter().map(|p| p / window.step).collect())
    }
}

/// A train moving on a track on the ground with ballast friction.
#[derive(Debug, Clone, Copy)]
pub struct GroundFrictionProblem<'a> {
    /// The track and what the friction acts on.
    pub track: FrictionTrack<'a>,
    /// The axles (offsets behind the first, m; forces downward, N).
    pub axles: &'a [Axle],
    /// v (m/s).
    pub speed: f64,
    /// Where the friction acts and the wave is solved.
    pub window: GroundWindow,
    /// f_u (N/m) > 0 (its sections are the window's points; `subdivisions` and `quadrature` are not used).
    pub friction_force: f64,
    /// The local operator's beam (the track's EI; its mass with the fitted co-vibrating mass) and Winkler
    /// foundation — on the two-beam track `TrackOnEmbankment::local_across_ballast`'s twin: the Newton steps'
    /// preconditioner only, the wave does not depend on it.
    pub local: (Beam, Foundation),
}

/// The wave with friction on the ground at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundFrictionWave {
    /// s_i (m).
    pub s: Vec<f64>,
    /// The rail's W(s_i) (m, upward).
    pub deflection: Vec<f64>,
    /// On the two-beam track d(s_i) = u_s − u_e, what the friction acts on (m); None on the composite beam (W).
    pub relative: Option<Vec<f64>>,
    /// r_i (N/m, upward on the ballast: the track — the sleepers — feels −r_i).
    pub friction_force: Vec<f64>,
    /// The ballast length each point stands for (m).
    pub weights: Vec<f64>,
    /// Where the rail slides over the ballast.
    pub slipping: Vec<bool>,
    /// How the Newton iteration ended.
    pub convergence: Convergence,
    /// GMRES steps over all Newton steps.
    pub krylov_iterations: usize,
    /// The points.
    window: GroundWindow,
    /// The rail's wave per newton of friction force at the points' spacings (m/N), d·h for d = −(n − 1) … n − 1.
    influence: Vec<f64>,
}

impl GroundFrictionWave {
    /// The friction forces as point loads on the track (offset −s_i behind the first axle, h_i r_i downward, N):
    /// with the axles, what a linear wave of the ground carries to give this one at any s.
    pub fn loads(&self) -> Vec<Axle> {
        let forces = self.s.iter().zip(&self.weights).zip(&self.friction_force);
        forces.filter(|(_, r)| **r != 0.0).map(|((s, h), r)| Axle { offset: -s, force: h * r }).collect()
    }

    /// The power the slipping ballast dissipates, f_u v Σ_slipping h_i |W′(s_i)| (W per rail line; d′ on the
    /// two-beam track), the slope by central differences between the points.
    pub fn dissipated_power(&self, friction_force: f64, speed: f64) -> f64 {
        let n = self.s.len();
        let field = self.relative.as_ref().unwrap_or(&self.deflection);
        (0..n)
            .filter(|&i| self.slipping[i])
            .map(|i| {
                let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
                let slope = (field[b] - field[a]) / (self.s[b] - self.s[a]);
                friction_force * speed * self.weights[i] * slope.abs()
            })
            .sum()
    }

    /// W(s) − W_lin(s) (m): what the friction forces carry into the rail at any s of the window, Σ_j W₁(s − s_j) h_j
    /// r_j (P_r/h in place of W₁ on the two-beam track) read between its values at the points' spacings by the cubic
    /// through the four nearest (the points' own values exact; between them ~h⁴|W₁⁗|/40, and h³/(20 EI) per newton
    /// beside s_j, where W₁‴ jumps).
    pub fn carried(&self, s: f64) -> f64 {
        self.window.superposed(&self.influence, |j| self.weights[j] * self.friction_force[j], s)
    }

    /// The largest |r| over the last tenth of the window behind and the first tenth ahead, over f_u: near 0 where the
    /// window holds all the friction the wave needs.
    pub fn end_forces(&self, friction_force: f64) -> (f64, f64) {
        let n = self.s.len();
        let tenth = (n / 10).max(1);
        let largest = |range: std::ops::Range<usize>| {
            self.friction_force[range].iter().fold(0.0f64, |m, r| m.max(r.abs())) / friction_force
        };
        (largest(0..tenth), largest(n - tenth..n))
    }
}

/// The equations on the window: the local frame (its mesh's nodes are the window's points), the linear wave, the
/// ground's Toeplitz influence and the scale of the residual.
#[derive(Clone)]
struct GroundFrame {
    local: MovingFrame,
    /// The local foundation's k_f (N/m²).
    local_stiffness: f64,
    linear: Vec<f64>,
    diagonals: Vec<f64>,
    influence: Toeplitz,
    scale: f64,
    /// GMRES steps taken, shared by the continuation's copies.
    krylov: Rc<Cell<usize>>,
    /// The factor between the κ continuation's first stages.
    stage_factor: f64,
}

impl GroundFrame {
    fn new(problem: &GroundFrictionProblem<'_>) -> Result<Self> {
        problem.window.validate()?;
        let GroundWindow { step, count, .. } = problem.window;
        if problem.friction_force.is_nan() || problem.friction_force <= 0.0 {
            return Err(invalid("friction.distributed.force_per_length", problem.friction_force, "must be > 0 (N/m)"));
        }
        // The local mesh: count − 1 elements of length h (lengths half an element off the ceilings that count
        // them); its nodes stand for the points, whatever s they are at.
        let domain = Domain { behind: (count as f64 - 2.5) * step, ahead: 0.5 * step, element_length: step };
        let local = StationaryProblem {
            beam: problem.local.0,
            foundation: problem.local.1,
            load: 0.0,
            speed: problem.speed,
            self_weight: false,
            friction: DistributedFriction {
                force_per_length: problem.friction_force,
                subdivisions: 1,
                quadrature: Quadrature::Trapezoid,
            },
            domain,
        };
        let mut local = MovingFrame::new(&local)?;
        let (linear, diagonals) = problem.track.field(problem.axles, &problem.window)?;
        // The rail's peak sets the Jenkins give and the residual's scale: on the two-beam track d is ~30× smaller
        // than the rail's deflection it changes, and holding it to 1e-6 of itself cost 5× the Newton steps.
        let peak = |values: &[f64]| values.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        let rail = problem.track.rail_under(problem.axles, &problem.window);
        let scale = peak(rail.as_deref().unwrap_or(&linear)).max(f64::MIN_POSITIVE);
        if let Some(sections) = local.friction.as_mut() {
            sections.stiffness = sections.stiffness.min(problem.friction_force / (JENKINS_GIVE * scale));
        }
        let influence = Toeplitz::new(&diagonals);
        Ok(Self {
            local,
            local_stiffness: problem.local.1.stiffness,
            linear,
            diagonals,
            influence,
            scale,
            krylov: Rc::new(Cell::new(0)),
            stage_factor: match problem.track {
                FrictionTrack::Composite(_) => crate::newton::STAGE_FACTOR,
                FrictionTrack::RailOnEmbankment(_) => BALLAST_STAGE_FACTOR,
            },
        })
    }

    /// The continuation's first stage from the linear wave, as a fraction of κ: the local foundation's stiffness.
    fn first_stage(&self) -> f64 {
        (self.local_stiffness / self.sections().stiffness).min(1.0)
    }

    fn sections(&self) -> &FrictionSections {
        self.local.friction.as_ref().expect("the local frame has friction")
    }

    /// The local mesh's DOFs of the points' deflections `w` (slopes 0: the sections at the nodes read none).
    fn dofs(w: &[f64]) -> Vec<f64> {
        w.iter().flat_map(|&w| [w, 0.0]).collect()
    }

    /// Σ_j W₁(s_i − s_j) h_j f_j at each point.
    fn influence_of(&self, forces: &[f64]) -> Vec<f64> {
        let weighted: Vec<f64> = self.sections().sections.iter().zip(forces).map(|(s, f)| s.weight * f).collect();
        self.influence.apply(&weighted)
    }
}

impl SetProblem for GroundFrame {
    fn evaluate(&self, w: &[f64]) -> Evaluation {
        let state = self.sections().march(&Self::dofs(w));
        let carried = self.influence_of(&state.force);
        let residual: Vec<f64> = (0..w.len()).map(|i| w[i] - self.linear[i] - carried[i]).collect();
        let norm = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
        let relative = residual.iter().fold(0.0f64, |m, r| m.max(r.abs())) / self.scale;
        Evaluation { norm, relative, sets: Sets { pressed: Vec::new(), friction: Some(state) } }
    }

    fn newton_point(&self, sets: &Sets, speed: f64) -> Result<Vec<f64>> {
        let state = sets.friction.as_ref().expect("a wave with friction has friction states");
        let sections = self.sections();
        let constant: Vec<f64> = (0..sections.sections.len()).map(|i| sections.constant_force(state, i)).collect();
        let carried = self.influence_of(&constant);
        let rhs: Vec<f64> = self.linear.iter().zip(&carried).map(|(a, b)| a + b).collect();
        let apply = |x: &[f64]| -> Vec<f64> {
            let carried = self.influence_of(&sections.stuck_forces(state, &Self::dofs(x)));
            x.iter().zip(&carried).map(|(x, c)| x - c).collect()
        };
        let system = SetSystem::new(&self.local, sets, speed)?;
        let precondition = |y: &[f64]| -> Vec<f64> {
            let mut forces = vec![0.0; 2 * y.len()];
            sections.add_forces(&sections.stuck_forces(state, &Self::dofs(y)), &mut forces);
            system.solve_in_place(&mut forces);
            y.iter().enumerate().map(|(i, y)| y - forces[2 * i]).collect()
        };
        let (w, outcome) = gmres(&apply, &precondition, &rhs, KRYLOV_TOLERANCE, KRYLOV_LIMIT);
        self.krylov.set(self.krylov.get() + outcome.iterations);
        Ok(w)
    }

    fn friction_mut(&mut self) -> Option<&mut FrictionSections> {
        self.local.friction.as_mut()
    }

    fn has_friction(&self) -> bool {
        true
    }

    fn stage_factor(&self) -> f64 {
        self.stage_factor
    }
}

/// The wave of `problem`, from `guess` (the previous speed's wave on the same window, if it fits) and leaving this
/// one there, within `control`: from a warm start one Newton iteration at the full Jenkins stiffness (a neighbouring
/// speed's slip and stick zones are often this one's), then the continuation in it from the warm start's
/// [`continuation::WARM_STAGE`], else from the linear wave. Measured over 100–280 km/h by 20 at Ledsgård (X2000,
/// 2 kN/m, composite beam): 11.8 s against 16.2 s with the continuation alone (the full stiffness converging at 7
/// of 9 warm speeds in 49–82 Newton steps); on the two-beam track, 160–210 km/h by 10: 1–21 steps a warm speed
/// against 153–427, 11.7 s against 20.0 s.
pub fn solve_on_ground(
    problem: &GroundFrictionProblem<'_>,
    guess: &mut ContactGuess,
    control: &Control<'_>,
) -> Result<GroundFrictionWave> {
    let frame = GroundFrame::new(problem)?;
    let speed = problem.speed;
    let mut spent = 0;
    let mut outcome = None;
    if let Some(warm) = guess.wave(problem.window.count).map(<[f64]>::to_vec) {
        // A neighbouring speed's slip and stick zones are often this one's: one iteration at the full κ first.
        let (w, status) = iterate(&frame, speed, warm.clone(), (guess, control), MAX_ITERATIONS)?;
        spent += status.iterations();
        outcome = status.is_converged().then_some((w, status));
        if outcome.is_none() && !control.exhausted() {
            let (w, status) = continuation::stages(&frame, speed, warm, continuation::WARM_STAGE, (guess, control))?;
            spent += status.iterations();
            outcome = status.is_converged().then_some((w, status));
        }
    }
    let (w, status) = match outcome {
        Some(found) => found,
        None => {
            let cold = frame.linear.clone();
            let (w, status) = continuation::stages(&frame, speed, cold, frame.first_stage(), (guess, control))?;
            spent += status.iterations();
            (w, status)
        }
    };
    let state = frame.sections().march(&GroundFrame::dofs(&w));
    let sections = &frame.sections().sections;
    let weights: Vec<f64> = sections.iter().map(|s| s.weight).collect();
    let rail =
        problem.track.rail_under(problem.axles, &problem.window).zip(problem.track.rail_per_newton(&problem.window));
    let (deflection, relative, influence) = match rail {
        None => (w, None, frame.diagonals),
        Some((linear, per_newton)) => {
            let weighted: Vec<f64> = weights.iter().zip(&state.force).map(|(h, r)| h * r).collect();
            let carried = Toeplitz::new(&per_newton).apply(&weighted);
            (linear.iter().zip(&carried).map(|(l, c)| l + c).collect(), Some(w), per_newton)
        }
    };
    Ok(GroundFrictionWave {
        s: problem.window.positions(),
        weights,
        slipping: state.states.iter().map(|s| matches!(s, crate::friction::SectionState::Slipping { .. })).collect(),
        friction_force: state.force,
        deflection,
        relative,
        convergence: with_iterations(status, spent),
        krylov_iterations: frame.krylov.get(),
        window: problem.window,
        influence,
    })
}
