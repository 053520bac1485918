//! What the nodal solution W of the moving-frame problem gives an engineer (docs/theory.md §14), read once when a
//! wave is made: the bending moment EI W″ at the nodes and the dashpots' ∫W′² ds (on the domain and beyond its
//! transparent ends), the zones where the rail leaves the soil, the ballast friction's force, slip zones and
//! dissipation with whether the wave has settled at the ends, and whether the rail lifts at an end.

use crate::friction::SectionState;
use crate::operator::MovingFrame;
use crate::problem::StationaryProblem;
use crate::rows::row_dot;
use fem_beam::element::hermite;
use fem_beam::{Extreme, LiftOffZone};

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

/// The share of each side of the domain next to its end over which a wave with friction must have settled.
pub const END_SHARE: f64 = 0.1;

/// How much of the peak the deflection may still vary there: the rail ahead must be at rest and the rail behind
/// held (or creeping to where friction holds it, a decay of rate k/(c_f v)), for the transparent front and the free
/// rear to be exact. 1e-5: the discretisation's share of the wave is ~1e-5–1e-4 of its peak on 0.25 m elements,
/// and an undamped track's tail behind the load decays only by friction (linearly, slowly).
pub const SETTLED: f64 = 1e-5;

/// The bending moment EI κ at the nodes (N·m, sagging positive; κ = W″, or Ψ′ for Timoshenko), W′ at the nodes
/// (rad) — each the mean of both elements' values at a node — and ∫W′² ds (rad²·m) over the domain by 4-point
/// Gauss, plus the transparent ends' tails beyond it, whose decaying modes continue the wave there.
pub(crate) fn bending(problem: &StationaryProblem, frame: &MovingFrame, w: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let nodes = frame.nodes.len();
    let element = frame.element;
    let ei = problem.beam.bending_stiffness();
    let mut moment = vec![0.0; nodes];
    let mut slope = vec![0.0; nodes];
    let mut count = vec![0.0; nodes];
    let mut slope_square = 0.0;
    for e in 0..nodes - 1 {
        let at = |row: [f64; 4]| row_dot(e, &row, w);
        moment[e] += ei * at(element.curvature(0.0));
        moment[e + 1] += ei * at(element.curvature(1.0));
        slope[e] += at(element.shape_dx(0.0));
        slope[e + 1] += at(element.shape_dx(1.0));
        count[e] += 1.0;
        count[e + 1] += 1.0;
        for &(xi, weight) in &hermite::GAUSS_4 {
            let dw = at(element.shape_dx(xi));
            slope_square += weight * element.length() * dw * dw;
        }
    }
    moment.iter_mut().zip(&count).for_each(|(m, c)| *m /= c);
    slope.iter_mut().zip(&count).for_each(|(m, c)| *m /= c);
    if let Some(far) = &frame.far_field {
        let level = problem.far_level();
        for (end, i) in [(&far.behind, 0), (&far.ahead, nodes - 1)] {
            slope_square += end.tail_slope_square(w[2 * i] - level, w[2 * i + 1]).unwrap_or(0.0);
        }
    }
    (moment, slope, slope_square)
}

/// W′ under the load (rad), the mean of its two sides, where the load's power F·v·W′ is taken. Euler–Bernoulli: the
/// rotation DOF there. Timoshenko: W′ = Ψ + γ jumps with the shear strain γ, which an element holds constant — its
/// value at the element's middle to second order — so each side's γ(0±) is extrapolated linearly from the two
/// elements that side, 3γ₁/2 − γ₂/2: the load's power converges at second order with the mesh, as the dashpots' does
/// (the element's own W′ at the node, first order, left the balance 5.6e-3 off on 0.1 m elements).
pub(crate) fn slope_under_load(frame: &MovingFrame, w: &[f64]) -> f64 {
    let (i, element) = (frame.load_node, frame.element);
    let row = element.shear_strain();
    let shear_strain = |e: usize| row_dot(e, &row, w);
    let elements = frame.nodes.len() - 1;
    let side = |near: Option<usize>, far: Option<usize>| match (near, far) {
        (Some(a), Some(b)) => 1.5 * shear_strain(a) - 0.5 * shear_strain(b),
        (Some(a), None) => shear_strain(a),
        _ => 0.0,
    };
    let within = |e: usize| (e < elements).then_some(e);
    let behind = side(i.checked_sub(1), i.checked_sub(2));
    let ahead = side(within(i), within(i + 1));
    let sides = if i == 0 || i == elements { 1.0 } else { 2.0 };
    w[2 * i + 1] + (behind + ahead) / sides
}

/// The zones of neighbouring soil sections where the rail is above the soil's surface, in the moving frame.
pub(crate) fn lift_off_zones(frame: &MovingFrame, w: &[f64]) -> Vec<LiftOffZone> {
    let mut zones: Vec<LiftOffZone> = Vec::new();
    let mut previous = false;
    for section in &frame.sections {
        let gap = section.deflection(w);
        let lifted = gap > 0.0;
        if lifted {
            let zone = LiftOffZone {
                from: section.s,
                to: section.s,
                sections: 1,
                largest_gap: Extreme::in_frame(gap, section.s),
                ..LiftOffZone::default()
            };
            match zones.last_mut().filter(|_| previous) {
                Some(open) => open.absorb(&zone),
                None => zones.push(zone),
            }
        }
        previous = lifted;
    }
    zones
}

/// What the ballast's friction does in the wave; all zero without friction.
pub(crate) struct FrictionReading {
    /// The force r at the nodes (N/m).
    pub(crate) force: Vec<f64>,
    /// Neighbouring sections slipping the same way.
    pub(crate) slip_zones: Vec<SlipZone>,
    /// f_u v Σ |W′| over the slipping sections (W).
    pub(crate) power: f64,
    /// Whether the deflection still varies by more than [`SETTLED`] of its peak over the last [`END_SHARE`] of the
    /// domain behind the load, and ahead.
    pub(crate) unsettled_at_ends: (bool, bool),
}

impl FrictionReading {
    /// The reading of W (nodal values `w`, deflection from the settled rail `deflection`).
    pub(crate) fn of(problem: &StationaryProblem, frame: &MovingFrame, w: &[f64], deflection: &[f64]) -> Self {
        let nodes = frame.nodes.len();
        let mut this =
            Self { force: vec![0.0; nodes], slip_zones: Vec::new(), power: 0.0, unsettled_at_ends: (false, false) };
        let Some(friction) = &frame.friction else { return this };
        let l = frame.element_length;
        let state = friction.march(w);
        let j = problem.friction.subdivisions;
        (0..nodes).for_each(|i| this.force[i] = state.force[i * j]);
        this.power = friction.dissipation(&state, w, &frame.element, problem.speed);
        let spacing = l / j as f64;
        for (section, state) in friction.sections.iter().zip(&state.states) {
            let SectionState::Slipping { sign } = *state else { continue };
            match this.slip_zones.last_mut() {
                Some(zone) if zone.direction == sign && section.s - zone.to <= 1.5 * spacing => zone.to = section.s,
                _ => this.slip_zones.push(SlipZone { from: section.s, to: section.s, direction: sign }),
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
        this.unsettled_at_ends =
            (spread(&mut (0..=rear_nodes), 0), spread(&mut (nodes - 1 - front_nodes..nodes), nodes - 1));
        this
    }
}

/// Whether the rail leaves the soil in the last element behind, and ahead — or, on a nonlinear soil, would beyond
/// that end, the wave continued by its far-field modes: a transparent end holds only where the wave continued past
/// it stays pressed, W_far + U < 0 for every U of the tail (lift-off zones 2 m inside a ±60 m domain at 196 m/s had
/// 30 mm gaps beyond it).
pub(crate) fn lifted_at_ends(problem: &StationaryProblem, frame: &MovingFrame, w: &[f64]) -> (bool, bool) {
    let nodes = frame.nodes.len();
    let level = problem.far_level();
    let at_end = |element: usize| frame.sections.iter().any(|s| s.element == element && s.deflection(w) > 0.0);
    let tail_lifts = |i: usize| {
        let far = frame.far_field.as_ref().filter(|_| problem.is_nonlinear());
        let end = far.map(|f| if i == 0 { &f.behind } else { &f.ahead });
        end.and_then(|end| end.tail_max(w[2 * i] - level, w[2 * i + 1])).is_some_and(|u| level + u > 0.0)
    };
    (at_end(0) || tail_lifts(0), at_end(nodes - 2) || tail_lifts(nodes - 1))
}
