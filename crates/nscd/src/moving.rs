//! Moving interactions (docs/theory.md §9): interactions whose row changes every step — a wheel rolling along the
//! rail touches the element under it with Ψ(x_c(t)) — rebuilt by the problem's update phase from (t_k, q_k) before
//! each solve (the pattern update → warm start → solve → write back).

use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

/// The state of a moving interaction for one step k → k+1, besides its row.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MovingState {
    /// The gap g_k (m, positive open) at (t_k, q_k), for a unilateral law's index set or penetration.
    pub gap: f64,
    /// The relative velocity U_k (m/s) at (t_k, q_k, v_k).
    pub velocity: f64,
    /// The rheonomic velocity b_r (m/s) at t_{k+1}, where the law holds: U_{k+1} = H v_{k+1} + b_r with the row
    /// written for t_{k+1} (for a wheel at speed v over a rail of height r: −v·Ψ′(x_c)ᵀq − v·r′(x_c)).
    pub rheonomic: f64,
}

/// An interaction whose row, gap and rheonomic velocity are set every step.
pub trait MovingInteraction: std::fmt::Debug + Send {
    /// Its law (the gap of a unilateral law is taken from [`MovingState::gap`], not from the law).
    fn law(&self) -> Law;
    /// What it is, for the energy ledger.
    fn kind(&self) -> InteractionKind;
    /// For the step from t_k = `time` (s) of length `step` (s), from q_k and v_k: write the row H(t_{k+1}) into `row`
    /// and return the state.
    fn update(&mut self, time: f64, step: f64, q: &[f64], v: &[f64], row: &mut InteractionRow) -> MovingState;
    /// The gap g (m) at `time` (s) from the displacement q, with the row H(`time`) written into `row`: g is affine in
    /// q at a fixed time (g = g₀(t) + H(t) q), so the position projection of a rigid contact ([`crate::position`])
    /// solves for it exactly.
    fn gap(&self, time: f64, q: &[f64], row: &mut InteractionRow) -> f64;
    /// Whether it can follow a co-moving window ([`crate::MoreauJean::shift`]): its place in the window moves back
    /// by the shift while its place on the track goes on. None can unless it says so.
    fn follows_shifts(&self) -> bool {
        false
    }
    /// The window has shifted `distance` (m) back under it: its place in the window moves back by that much, its
    /// place on the track (what it meets there, e.g. the rail's profile) does not.
    fn shift_back(&mut self, _distance: f64) {}
}

/// The interactions of a run: fixed ones with their once-per-run data, and moving ones rebuilt every step.
#[derive(Debug, Default)]
pub struct Interactions {
    /// Fixed interactions (devices, ballast sections, stops at fixed places).
    pub fixed: InteractionSet,
    /// Moving interactions, after the fixed ones in the problem's order.
    pub moving: Vec<Box<dyn MovingInteraction>>,
}

impl From<InteractionSet> for Interactions {
    fn from(fixed: InteractionSet) -> Self {
        Self { fixed, moving: Vec::new() }
    }
}
