//! The stationary wave and what an engineer reads from it (docs/theory.md §14): W(s) from the settled state at the
//! nodes, the bending moment EI W″, the soil's reaction, the peaks, the zones where the rail leaves the soil, the
//! deflection left behind, and the power balance of the steady state — the load's power F v W′(0) against the
//! dashpots' c_f v² ∫W′² ds (a conservative soil, linear or not, dissipates nothing over a cycle).

use crate::operator::MovingFrame;
use crate::problem::StationaryProblem;
use crate::reading;
pub use crate::reading::{END_SHARE, SETTLED, SlipZone};
use crate::status::Convergence;
use fem_beam::element::Element;
use fem_beam::{Extreme, LiftOffZone};

/// The steady state's balance, in the moving frame a balance of powers (W): what the load puts in against what the
/// dashpots and the ballast's friction take out and what the wave leaves behind — the stationary counterpart of a
/// run's energy balance.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PowerBalance {
    /// F v W′(0) (W).
    pub load: f64,
    /// c_f v² ∫W′² ds (W).
    pub viscous: f64,
    /// f_u v Σ_slip |W′| (W).
    pub friction: f64,
    /// v·e(W_behind) (W).
    pub left_behind: f64,
    /// (load − viscous − friction − left behind) / load: zero for the exact wave.
    pub imbalance: f64,
}

/// The stationary wave of a load at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct StationaryWave {
    /// v (m/s).
    pub speed: f64,
    /// F (N).
    pub load: f64,
    /// How the solve ended; a wave that did not converge is reported, never taken for the answer.
    pub convergence: Convergence,
    /// Node positions s (m), the load at s = 0.
    pub s: Vec<f64>,
    /// W − W_far at the nodes (m, upward positive): the deflection from the settled rail.
    pub deflection: Vec<f64>,
    /// W′ (rad): the mean of both elements' values at a node (a Timoshenko rail's slope jumps under the load).
    pub slope: Vec<f64>,
    /// The rotation DOF θ at the nodes (rad): W′ for Euler–Bernoulli, the cross-section's Ψ for Timoshenko.
    pub rotation: Vec<f64>,
    /// The bending moment EI W″ (EI Ψ′ for Timoshenko; N·m, sagging positive), the mean of both elements' values at
    /// a node.
    pub moment: Vec<f64>,
    /// The soil's spring force on the rail from the settled state (N/m, upward positive), at the nodes.
    pub soil_reaction: Vec<f64>,
    /// The settlement level W_far (m): −ρA·g/k_c on a nonlinear soil with self-weight, else 0.
    pub settlement: f64,
    /// The zones where the rail left the soil.
    pub lift_off: Vec<LiftOffZone>,
    /// The ballast's friction force at the nodes r (N/m, upward positive on the left-hand side: the rail feels −r);
    /// zero without friction.
    pub friction_force: Vec<f64>,
    /// The zones where the rail slides over the ballast.
    pub slip_zones: Vec<SlipZone>,
    /// F v W′(0) (W): the power the load puts in (W′ the mean of both sides for a Timoshenko rail).
    pub load_power: f64,
    /// c_f v² ∫W′² ds (W): what the dashpots take out, on the domain and on the far field beyond its transparent
    /// ends.
    pub viscous_power: f64,
    /// f_u v Σ |W′| over the slipping sections (W): what the ballast's friction takes out.
    pub friction_power: f64,
    /// v·e(W_behind) (W): the energy per unit length the wave leaves behind in the soil held by friction (e the
    /// soil's and the weight's stored energy from the settled state), deposited at the speed the wave advances.
    pub left_behind_power: f64,
    element_length: f64,
    element: Element,
    load_node: usize,
    sections_lifted_at_ends: (bool, bool),
    unsettled_at_ends: (bool, bool),
}

/// Below this share of F·v·max|W′| the wave's powers are round-off: no power flows (an undamped wave without friction).
pub const NO_POWER: f64 = 1e-9;

impl StationaryWave {
    pub(crate) fn new(problem: &StationaryProblem, frame: &MovingFrame, w: Vec<f64>, status: Convergence) -> Self {
        let nodes = frame.nodes.len();
        let level = problem.far_level();
        let deflection: Vec<f64> = (0..nodes).map(|i| w[2 * i] - level).collect();
        let rotation: Vec<f64> = (0..nodes).map(|i| w[2 * i + 1]).collect();
        let (moment, slope, slope_square) = reading::bending(problem, frame, &w);
        let f = &problem.foundation;
        let rest = f.reaction(level);
        let soil_reaction = (0..nodes).map(|i| f.reaction(w[2 * i]) - rest).collect();
        let friction = reading::FrictionReading::of(problem, frame, &w, &deflection);
        let v = problem.speed;
        // e(W) = P(W) − P(W_far) + q (W − W_far), P the soil's potential (Foundation::potential), q = −k_c W_far.
        let stored = |u: f64| f.potential(u) - f.potential(level) - f.stiffness * level * (u - level);
        Self {
            speed: v,
            load: problem.load,
            convergence: status,
            s: frame.nodes.clone(),
            load_power: problem.load * v * reading::slope_under_load(frame, &w),
            viscous_power: f.damping * v * v * slope_square,
            friction_power: friction.power,
            left_behind_power: if problem.has_friction() { v * stored(w[0]) } else { 0.0 },
            friction_force: friction.force,
            slip_zones: friction.slip_zones,
            unsettled_at_ends: friction.unsettled_at_ends,
            deflection,
            slope,
            rotation,
            moment,
            soil_reaction,
            settlement: level,
            lift_off: reading::lift_off_zones(frame, &w),
            element_length: frame.element_length,
            element: frame.element,
            load_node: frame.load_node,
            sections_lifted_at_ends: reading::lifted_at_ends(problem, frame, &w),
        }
    }

    /// With friction: whether the wave has not settled (to [`SETTLED`] of its peak) over the last [`END_SHARE`] of
    /// the domain behind the load, and ahead of it.
    pub fn unsettled_at_ends(&self) -> (bool, bool) {
        self.unsettled_at_ends
    }

    /// Whether the rail leaves the soil in the last element behind, and ahead — or would beyond that end, the wave
    /// continued by its far-field modes ([`crate::far_field::EndRelation::tail_max`]).
    pub fn lifted_at_ends(&self) -> (bool, bool) {
        self.sections_lifted_at_ends
    }

    /// The largest downward deflection (magnitude) and where.
    pub fn max_downward(&self) -> Extreme {
        self.deflection_extreme(-1.0)
    }

    /// The largest upward deflection and where.
    pub fn max_upward(&self) -> Extreme {
        self.deflection_extreme(1.0)
    }

    /// The extreme of sign·W over the whole cubic of every element, not only its nodes: where W′ = aξ² + bξ + c
    /// vanishes inside (a damped wave's trough lies between nodes, 0.07 m behind the load at 120 m/s); the quadratic
    /// from W′ (times l) at ξ = 0, ½, 1.
    fn deflection_extreme(&self, sign: f64) -> Extreme {
        let l = self.element_length;
        let mut best = self.extreme(&self.deflection, sign);
        let element = self.element;
        for e in 0..self.s.len() - 1 {
            let q = [self.deflection[e], self.rotation[e], self.deflection[e + 1], self.rotation[e + 1]];
            let at = |n: [f64; 4]| n.iter().zip(&q).map(|(n, q)| n * q).sum::<f64>();
            let slope = |xi: f64| l * at(element.shape_dx(xi));
            let (start, middle, end) = (slope(0.0), slope(0.5), slope(1.0));
            let (a, b, c) = (2.0 * (start + end) - 4.0 * middle, 4.0 * middle - 3.0 * start - end, start);
            let discriminant = b * b - 4.0 * a * c;
            if a == 0.0 || discriminant < 0.0 {
                continue;
            }
            for xi in [(-b - discriminant.sqrt()) / (2.0 * a), (-b + discriminant.sqrt()) / (2.0 * a)] {
                if xi > 0.0 && xi < 1.0 {
                    let w = at(element.shape(xi));
                    if sign * w > best.value {
                        best = Extreme::in_frame(sign * w, self.s[e] + xi * l);
                    }
                }
            }
        }
        best
    }

    /// The largest sagging moment and where.
    pub fn max_moment(&self) -> Extreme {
        self.extreme(&self.moment, 1.0)
    }

    /// The largest hogging moment (magnitude) and where.
    pub fn min_moment(&self) -> Extreme {
        self.extreme(&self.moment, -1.0)
    }

    fn extreme(&self, values: &[f64], sign: f64) -> Extreme {
        values
            .iter()
            .zip(&self.s)
            .map(|(v, s)| Extreme::in_frame((sign * v).max(0.0), *s))
            .fold(Extreme::default(), |best, p| if p.value > best.value { p } else { best })
    }

    /// The deflection under the load (m).
    pub fn under_load(&self) -> f64 {
        self.deflection[self.load_node]
    }

    /// The deflection left at the rear end of the domain (m): the wave's tail, or what friction holds.
    pub fn behind(&self) -> f64 {
        self.deflection[0]
    }

    /// (load power − viscous − friction − left-behind power) / load power: zero for the exact stationary wave on
    /// the infinite track; here the discretisation's and the ends' share. 0 when no power flows: an undamped wave
    /// without friction is symmetric, W′(0) = 0, and its load power is round-off — below [`NO_POWER`] of
    /// F·v·max|W′| — whose ratio to the others' would read as a 100 % imbalance.
    pub fn power_imbalance(&self) -> f64 {
        let out = self.viscous_power + self.friction_power + self.left_behind_power;
        let scale = (self.load * self.speed).abs() * self.slope.iter().fold(0.0f64, |m, d| m.max(d.abs()));
        if self.load_power.abs().max(out.abs()) > NO_POWER * scale {
            (self.load_power - out) / self.load_power
        } else {
            0.0
        }
    }

    /// The wave's power balance as it is reported.
    pub fn power_balance(&self) -> PowerBalance {
        PowerBalance {
            load: self.load_power,
            viscous: self.viscous_power,
            friction: self.friction_power,
            left_behind: self.left_behind_power,
            imbalance: self.power_imbalance(),
        }
    }

    /// Element length of the domain (m).
    pub fn element_length(&self) -> f64 {
        self.element_length
    }
}
