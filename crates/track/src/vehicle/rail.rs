//! A wheel rolling along the beam at a constant or changing speed (docs/theory.md §9, §12): the moving interaction between a wheel
//! DOF z_w and the rail. At the wheel's place x_c(t) = x₀ + v t, on element e with shape functions Ψ(ξ):
//!
//!   gap g = z_w − Ψ(x_c)ᵀq − r(x_c),   U = ż_w − Ψ(x_c)ᵀq̇ − v·Ψ′(x_c)ᵀq − v·r′(x_c),
//!
//! so the row is [−Ψ(x_c)ᵀ on the element's free DOFs, +1 on the wheel] and the terms in q and r′ form the rheonomic
//! velocity. Both are taken where the wheel is at t_k + θh, the slope term with q_{k+θ} ≈ q_k + θh v_k: the impulse
//! of the step then loads the beam with Ψ(x_{k+θ}), which matches the θ-weighted consistent load
//! (1 − θ)Ψ(x_k) + θΨ(x_{k+1}) of a moving force to O(h²) — at the step's end the two would differ by O(h), 1.4 % of
//! the peak on the reference beam at 100 m/s. (With q_k in the slope term the gap drifted twice as much: measured by
//! the rigid contact's projection work, 539 J against 269 J over a quarter car's run at 30 m/s.)
//! Off the beam (x_c < 0 or x_c > L) the rail is rigid ground at the supports' level: row [+1], g = z_w − r, so a
//! vehicle enters and leaves smoothly. The impulse p ≥ 0 pushes the wheel up and the rail down (−Ψ p).
//!
//! The contact law ([`WheelRail`], docs/theory.md §9) is Hertz, a linear spring in series with the unilateral stop,
//! a glued spring, or rigid. A velocity-level constraint along a moving, deflecting rail drifts by O(h²) a step (the
//! row of the last step was written half a step back): a spring takes it up in its force; a rigid contact has its
//! positions projected after each step ([`nscd::position`]), whose strain-energy change — the drift's spurious work,
//! O(h) over a run — the energy ledger books apart.

use fem_beam::{BeamModel, Discretisation, Motion};
use friction::{InteractionKind, InteractionRow, Law};
use irregularity::WheelTrack;
use nscd::{MovingInteraction, MovingState};

use super::wheel_rail::WheelRail;
use crate::error::Result;

/// A wheel on the beam.
#[derive(Debug, Clone)]
pub struct WheelOnBeam {
    /// The wheel's DOF in the system.
    wheel: usize,
    /// The rail under the wheel.
    rail: RailPoints,
    /// Where the wheel is at t = 0 (m).
    start: f64,
    /// How it moves along the track.
    motion: Motion,
    /// The rail's profile and the wheel's flat.
    track: WheelTrack,
    /// The contact law (its gap field is not used).
    law: Law,
    /// θ of the integration: the row is written where the wheel is at t_k + θh.
    theta: f64,
    /// How far a co-moving window has shifted back under the wheel (m): its place on the beam is its place on the
    /// track less this.
    shifted: f64,
}

/// The beam under a point: (system DOFs of its element's four DOFs, Ψ, Ψ′), or None off the beam.
type Under = ([Option<usize>; 4], [f64; 4], [f64; 4]);

/// Points of the rail read from the system's state: the element under x, its system DOFs and the shape functions of
/// the beam's element there.
#[derive(Debug, Clone)]
pub(crate) struct RailPoints {
    beam: Discretisation,
    /// System DOF of each full beam DOF (None where a support fixes it).
    beam_dofs: Vec<Option<usize>>,
}

impl RailPoints {
    /// The rail of `model`, whose DOFs start at system DOF `beam_offset`.
    pub(crate) fn new(model: &BeamModel, beam_offset: usize) -> Self {
        let dofs = model.dofs();
        let beam_dofs = (0..dofs.full_len()).map(|d| dofs.free_index(d).map(|f| beam_offset + f)).collect();
        Self { beam: model.discretisation(), beam_dofs }
    }

    /// The system DOFs of the element under `x` and its local coordinate ξ ∈ [0, 1]; None off the beam.
    fn element_at(&self, x: f64) -> Option<([Option<usize>; 4], f64)> {
        let point = self.beam.mesh().locate(x).ok()?;
        let dofs = [0, 1, 2, 3].map(|i| self.beam_dofs[2 * point.element + i]);
        Some((dofs, point.xi))
    }

    /// The element's DOFs and Ψ, Ψ′ at `x`, None off the beam.
    fn under(&self, x: f64) -> Option<Under> {
        let (dofs, xi) = self.element_at(x)?;
        let element = self.beam.element();
        Some((dofs, element.shape(xi), element.shape_dx(xi)))
    }

    /// (w, κ) of the rail at `x` from the system's displacement `q` (m, 1/m): the deflection and the curvature
    /// whose EI-fold is the bending moment (w″, or ψ′ for a Timoshenko rail); None off the beam.
    pub(crate) fn deflection_curvature(&self, q: &[f64], x: f64) -> Option<(f64, f64)> {
        let (dofs, xi) = self.element_at(x)?;
        let element = self.beam.element();
        let (n, ddn) = (element.shape(xi), element.curvature(xi));
        Some((combine(&dofs, &n, q), combine(&dofs, &ddn, q)))
    }
}

/// Σ N_i y_i over the element's free DOFs.
fn combine(dofs: &[Option<usize>; 4], n: &[f64; 4], y: &[f64]) -> f64 {
    dofs.iter().zip(n).filter_map(|(d, n)| d.map(|d| n * y[d])).sum()
}

impl WheelOnBeam {
    /// A wheel on system DOF `wheel`, over the beam of `model` whose DOFs start at system DOF `beam_offset`, rolling
    /// along the track as `motion` says over `track` with the contact law `contact`, integrated with `theta`.
    pub fn new(
        model: &BeamModel,
        (beam_offset, wheel): (usize, usize),
        motion: Motion,
        track: WheelTrack,
        contact: WheelRail,
        theta: f64,
    ) -> Result<Self> {
        contact.validate()?;
        let law = contact.law();
        let rail = RailPoints::new(model, beam_offset);
        Ok(Self { wheel, rail, start: motion.position(0.0), motion, track, law, theta, shifted: 0.0 })
    }

    /// Where the wheel is on the track at `time` (m).
    pub fn position(&self, time: f64) -> f64 {
        self.motion.position(time)
    }

    /// Where the wheel is on the beam at `time` (m): on the track less what a co-moving window shifted.
    fn on_beam(&self, time: f64) -> f64 {
        self.position(time) - self.shifted
    }

    /// The rail's height and slope (m, rad) under the wheel at track position `x` (m).
    fn profile_at(&self, x: f64) -> (f64, f64) {
        self.track.height_slope(x, x - self.start)
    }

    /// Write the contact's row at `x` into `row` — [−Ψ(x)ᵀ on the element's free DOFs, +1 on the wheel], or [+1] off
    /// the beam — and return the element under x.
    fn write_row(&self, x: f64, row: &mut InteractionRow) -> Option<Under> {
        let under = self.rail.under(x);
        match under {
            Some((dofs, n, _)) => {
                let beam = dofs.into_iter().zip(n).filter_map(|(d, n)| d.map(|d| (d, -n)));
                row.set_entries(beam.chain([(self.wheel, 1.0)]));
            }
            None => row.set_entries([(self.wheel, 1.0)]),
        }
        under
    }
}

impl MovingInteraction for WheelOnBeam {
    fn law(&self) -> Law {
        self.law
    }

    fn kind(&self) -> InteractionKind {
        InteractionKind::Contact
    }

    fn update(&mut self, time: f64, step: f64, q: &[f64], v: &[f64], row: &mut InteractionRow) -> MovingState {
        let (x, next) = (self.position(time), self.position(time + self.theta * step));
        // The wheel's speed along the track now and where the row is written (equal at constant speed).
        let (speed, next_speed) = (self.motion.speed(time), self.motion.speed(time + self.theta * step));
        let (r, slope) = self.profile_at(x);
        let (mut gap, mut velocity) = (q[self.wheel] - r, v[self.wheel] - speed * slope);
        if let Some((dofs, n, dn)) = self.rail.under(x - self.shifted) {
            gap -= combine(&dofs, &n, q);
            velocity -= combine(&dofs, &n, v) + speed * combine(&dofs, &dn, q);
        }
        let mut rheonomic = -next_speed * self.profile_at(next).1;
        if let Some((dofs, _, dn)) = self.write_row(next - self.shifted, row) {
            // −v·Ψ′(x_{k+θ})ᵀq_{k+θ} with q_{k+θ} ≈ q_k + θh v_k: second order, as the row.
            let slope = combine(&dofs, &dn, q) + self.theta * step * combine(&dofs, &dn, v);
            rheonomic -= next_speed * slope;
        }
        MovingState { gap, velocity, rheonomic }
    }

    fn gap(&self, time: f64, q: &[f64], row: &mut InteractionRow) -> f64 {
        let x = self.position(time);
        let beam = self.write_row(self.on_beam(time), row).map_or(0.0, |(dofs, n, _)| combine(&dofs, &n, q));
        q[self.wheel] - self.profile_at(x).0 - beam
    }

    fn follows_shifts(&self) -> bool {
        true
    }

    fn shift_back(&mut self, distance: f64) {
        self.shifted += distance;
    }
}
