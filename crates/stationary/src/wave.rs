//! The stationary wave and what an engineer reads from it (docs/theory.md §14): W(s) from the settled state at the
//! nodes, the bending moment EI W″, the soil's reaction, the peaks, the zones where the rail leaves the soil, the
//! deflection left behind, and the power balance of the steady state — the load's power F v W′(0) against the
//! dashpots' c_f v² ∫W′² ds (a conservative soil, linear or not, dissipates nothing over a cycle).

use crate::friction::SectionState;
use crate::operator::MovingFrame;
use crate::problem::StationaryProblem;
use crate::solve::Convergence;
use fem_beam::element::hermite;
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

/// Neighbouring friction sections where the rail slides over the ballast the same way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipZone {
    /// From (s, m).
    pub from: f64,
    /// To (s, m).
    pub to: f64,
    /// +1 where the rail rises (W′ < 0 as the load comes), −1 where it sinks.
    pub direction: f64,
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
    /// W′ (rad).
    pub slope: Vec<f64>,
    /// EI W″ (N·m, sagging positive), the mean of both elements' values at a node.
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
    /// F v W′(0) (W): the power the load puts in.
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
    load_node: usize,
    sections_lifted_at_ends: (bool, bool),
    unsettled_at_ends: (bool, bool),
}

/// The share of each side of the domain next to its end over which a wave with friction must have settled.
pub const END_SHARE: f64 = 0.1;

/// How much of the peak the deflection may still vary there: the rail ahead must be at rest and the rail behind
/// held (or creeping to where friction holds it, a decay of rate k/(c_f v)), for the transparent front and the free
/// rear to be exact. 1e-5: the discretisation's share of the wave is ~1e-5–1e-4 of its peak on 0.25 m elements,
/// and an undamped track's tail behind the load decays only by friction (linearly, slowly).
pub const SETTLED: f64 = 1e-5;

impl StationaryWave {
    pub(crate) fn new(problem: &StationaryProblem, frame: &MovingFrame, w: Vec<f64>, status: Convergence) -> Self {
        let nodes = frame.nodes.len();
        let l = frame.element_length;
        let level = problem.far_level();
        let ei = problem.beam.bending_stiffness();
        let deflection: Vec<f64> = (0..nodes).map(|i| w[2 * i] - level).collect();
        let slope: Vec<f64> = (0..nodes).map(|i| w[2 * i + 1]).collect();
        let mut moment = vec![0.0; nodes];
        let mut count = vec![0.0; nodes];
        let mut viscous = 0.0;
        for e in 0..nodes - 1 {
            let q = &w[2 * e..2 * e + 4];
            let curvature = |xi: f64| hermite::shape_dxx(xi, l).iter().zip(q).map(|(n, q)| n * q).sum::<f64>();
            moment[e] += ei * curvature(0.0);
            moment[e + 1] += ei * curvature(1.0);
            count[e] += 1.0;
            count[e + 1] += 1.0;
            for &(xi, weight) in &hermite::GAUSS_4 {
                let dw: f64 = hermite::shape_dx(xi, l).iter().zip(q).map(|(n, q)| n * q).sum();
                viscous += weight * l * dw * dw;
            }
        }
        moment.iter_mut().zip(&count).for_each(|(m, c)| *m /= c);
        let f = &problem.foundation;
        let rest = f.reaction(level);
        let soil_reaction = (0..nodes).map(|i| f.reaction(w[2 * i]) - rest).collect();
        let mut lift_off: Vec<LiftOffZone> = Vec::new();
        let mut previous = false;
        for section in &frame.sections {
            let gap = section.deflection(&w);
            let lifted = gap > 0.0;
            if lifted {
                let zone = LiftOffZone {
                    from: section.s,
                    to: section.s,
                    sections: 1,
                    largest_gap: Extreme::in_frame(gap, section.s),
                    ..LiftOffZone::default()
                };
                match lift_off.last_mut().filter(|_| previous) {
                    Some(open) => open.absorb(&zone),
                    None => lift_off.push(zone),
                }
            }
            previous = lifted;
        }
        let (mut friction_force, mut slip_zones, mut friction_power) = (vec![0.0; nodes], Vec::<SlipZone>::new(), 0.0);
        let mut unsettled_at_ends = (false, false);
        if let Some(friction) = &frame.friction {
            let state = friction.march(&w);
            let j = problem.friction.subdivisions;
            (0..nodes).for_each(|i| friction_force[i] = state.force[i * j]);
            friction_power = friction.dissipation(&state, &w, l, problem.speed);
            for (section, state) in friction.sections.iter().zip(&state.states) {
                let SectionState::Slipping { sign } = *state else { continue };
                let spacing = l / j as f64;
                match slip_zones.last_mut() {
                    Some(zone) if zone.direction == sign && section.s - zone.to <= 1.5 * spacing => zone.to = section.s,
                    _ => slip_zones.push(SlipZone { from: section.s, to: section.s, direction: sign }),
                }
            }
            // Settled: the deflection varies by at most SETTLED of the peak over the last END_SHARE of each side.
            let peak = deflection.iter().fold(0.0f64, |m, w| m.max(w.abs()));
            let spread = |nodes: &mut dyn Iterator<Item = usize>, end: usize| {
                nodes.map(|i| (deflection[i] - deflection[end]).abs()).fold(0.0f64, f64::max) > SETTLED * peak
            };
            let (rear_nodes, front_nodes) = (
                (frame.load_node as f64 * END_SHARE).ceil() as usize,
                ((nodes - 1 - frame.load_node) as f64 * END_SHARE).ceil() as usize,
            );
            unsettled_at_ends =
                (spread(&mut (0..=rear_nodes), 0), spread(&mut (nodes - 1 - front_nodes..nodes), nodes - 1));
        }
        let stored = |u: f64| {
            // e(W) = P(W) − P(W_far) + q (W − W_far), P the soil's potential (Foundation::potential), q = −k_c W_far.
            f.potential(u) - f.potential(level) - f.stiffness * level * (u - level)
        };
        let last = nodes - 2;
        let at_end = |element: usize| frame.sections.iter().any(|s| s.element == element && s.deflection(&w) > 0.0);
        // A nonlinear soil's transparent end holds only where the wave continued past it stays pressed: W_far + U < 0
        // for every U of the tail (lift-off zones 2 m inside a ±60 m domain at 196 m/s had 30 mm gaps beyond it).
        let tail_lifts = |i: usize| {
            let far = frame.far_field.as_ref().filter(|_| problem.is_nonlinear());
            let end = far.map(|f| if i == 0 { &f.behind } else { &f.ahead });
            end.and_then(|end| end.tail_max(w[2 * i] - level, w[2 * i + 1])).is_some_and(|u| level + u > 0.0)
        };
        let v = problem.speed;
        // The dashpots work beyond the ends too, where the transparent ends continue the wave by its decaying modes.
        if let Some(far) = &frame.far_field {
            for (end, i) in [(&far.behind, 0), (&far.ahead, nodes - 1)] {
                viscous += end.tail_slope_square(w[2 * i] - level, w[2 * i + 1]).unwrap_or(0.0);
            }
        }
        Self {
            speed: v,
            load: problem.load,
            convergence: status,
            s: frame.nodes.clone(),
            load_power: problem.load * v * slope[frame.load_node],
            viscous_power: f.damping * v * v * viscous,
            friction_power,
            left_behind_power: if problem.has_friction() { v * stored(w[0]) } else { 0.0 },
            friction_force,
            slip_zones,
            unsettled_at_ends,
            deflection,
            slope,
            moment,
            soil_reaction,
            settlement: level,
            lift_off,
            element_length: l,
            load_node: frame.load_node,
            sections_lifted_at_ends: (at_end(0) || tail_lifts(0), at_end(last) || tail_lifts(nodes - 1)),
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
    /// vanishes inside (a damped wave's trough lies between nodes, 0.07 m behind the load at 120 m/s).
    fn deflection_extreme(&self, sign: f64) -> Extreme {
        let l = self.element_length;
        let mut best = self.extreme(&self.deflection, sign);
        for e in 0..self.s.len() - 1 {
            let q = [self.deflection[e], self.slope[e], self.deflection[e + 1], self.slope[e + 1]];
            let a = 6.0 * (q[0] - q[2]) / l + 3.0 * (q[1] + q[3]);
            let b = -6.0 * (q[0] - q[2]) / l - 4.0 * q[1] - 2.0 * q[3];
            let c = q[1];
            let discriminant = b * b - 4.0 * a * c;
            if a == 0.0 || discriminant < 0.0 {
                continue;
            }
            for xi in [(-b - discriminant.sqrt()) / (2.0 * a), (-b + discriminant.sqrt()) / (2.0 * a)] {
                if xi > 0.0 && xi < 1.0 {
                    let w: f64 = hermite::shape(xi, l).iter().zip(&q).map(|(n, q)| n * q).sum();
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
    /// the infinite track; here the discretisation's and the ends' share (0 when no power flows).
    pub fn power_imbalance(&self) -> f64 {
        let out = self.viscous_power + self.friction_power + self.left_behind_power;
        if self.load_power.abs() > 0.0 { (self.load_power - out) / self.load_power } else { 0.0 }
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
