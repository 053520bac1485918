//! What the time loop reads after each step: the nodal deflections (extremes and W̄ in one pass), the recorders
//! of section histories and their full-DOF scratch vectors.

use super::results::{SectionHistory, WindowExtremes};
use super::settings::counts_for_extremes;
use crate::error::Result;
use fem_beam::BeamModel;
use fem_beam::DeflectionExtremes;

pub(super) struct Recorder {
    pub(super) position: f64,
    pub(super) node: usize,
    pub(super) contact: Option<usize>,
    pub(super) inside: Vec<InsideSection>,
    pub(super) history: SectionHistory,
}

/// The nodal deflections of the free w DOFs, read in one pass per step for the extremes and for W̄ (constrained
/// nodes have w = 0: they never set an extreme and add nothing to the norm). The extremes are taken over the nodes
/// of the region only ([`crate::RecordSettings::extremes_nodes`]); W̄ over every node.
pub(super) struct NodalDeflections {
    /// (free DOF index, node x (m), trapezoid weight (m), inside the extremes region) of every node whose w is free.
    pub(super) nodes: Vec<(usize, f64, f64, bool)>,
}

/// What one pass over the deflections finds.
pub(super) struct DeflectionScan {
    /// Lowest w (m) and its node x, first such node.
    pub(super) lowest: (f64, f64),
    /// Highest w (m) and its node x, first such node.
    pub(super) highest: (f64, f64),
    /// ∫|w| dx by the trapezoid rule over the nodes (m²).
    pub(super) norm: f64,
}

impl NodalDeflections {
    /// The free deflection DOFs of `mesh`; extremes over the nodes in `region` (m, inclusive up to 1e-9·L), or all.
    pub(super) fn new(mesh: &fem_beam::Mesh, dofs: &fem_beam::DofMap, region: Option<(f64, f64)>) -> Self {
        let last = mesh.nodes() - 1;
        let l = mesh.element_length();
        let nodes = (0..=last)
            .filter_map(|i| {
                let weight = if i == 0 || i == last { 0.5 * l } else { l };
                let x = mesh.node_x(i);
                dofs.free_index(2 * i).map(|d| (d, x, weight, counts_for_extremes(region, x, mesh.length)))
            })
            .collect();
        Self { nodes }
    }

    /// The largest |(v − v_prev)/h| (m/s²) over the nodes and its node x.
    pub(super) fn largest_acceleration(&self, v: &[f64], v_prev: &[f64], h: f64) -> (f64, f64) {
        self.largest(|d| (v[d] - v_prev[d]) / h)
    }

    /// The largest |value(d)| over the deflection DOFs d of the nodes that count for the extremes, and its node x.
    pub(super) fn largest(&self, value: impl Fn(usize) -> f64) -> (f64, f64) {
        let mut largest = (0.0, 0.0);
        for &(d, x, _, _) in self.nodes.iter().filter(|n| n.3) {
            let a = value(d).abs();
            if a > largest.0 {
                largest = (a, x);
            }
        }
        largest
    }

    pub(super) fn scan(&self, q: &[f64]) -> DeflectionScan {
        let mut scan = DeflectionScan { lowest: (0.0, 0.0), highest: (0.0, 0.0), norm: 0.0 };
        for &(d, x, weight, inside) in &self.nodes {
            let w = q[d];
            if inside && w < scan.lowest.0 {
                scan.lowest = (w, x);
            }
            if inside && w > scan.highest.0 {
                scan.highest = (w, x);
            }
            scan.norm += weight * w.abs();
        }
        scan
    }
}

impl DeflectionScan {
    /// Keep the record extremes (downward, upward) up to date at `time`.
    pub(super) fn update(&self, extremes: &mut DeflectionExtremes, time: f64) {
        extremes.max_downward.raise(-self.lowest.0, self.lowest.1, time);
        extremes.max_upward.raise(self.highest.0, self.highest.1, time);
    }

    /// The same for the extremes of a load-position window.
    pub(super) fn update_window(&self, window: &mut WindowExtremes, time: f64) {
        self.update(&mut window.deflection, time);
    }
}

/// A friction section strictly inside an element next to a recorded node.
#[derive(Debug, Clone, Copy)]
pub(super) struct InsideSection {
    pub(super) element: usize,
    pub(super) contact: usize,
    pub(super) shape: [f64; 4],
}

pub(super) fn record(r: &mut Recorder, time: f64, load_position: f64, motion: [f64; 3], moment: f64, impulse: f64) {
    r.history.time.push(time);
    r.history.load_position.push(load_position);
    r.history.deflection.push(motion[0]);
    r.history.velocity.push(motion[1]);
    r.history.acceleration.push(motion[2]);
    r.history.moment.push(moment);
    if let Some(series) = r.history.impulse.as_mut() {
        series.push(impulse);
    }
}

/// Full-DOF scratch vectors for section results.
pub(super) struct Buffers {
    pub(super) q: Vec<f64>,
    pub(super) v: Vec<f64>,
    pub(super) a: Vec<f64>,
    pub(super) free: Vec<f64>,
}

impl Buffers {
    pub(super) fn new(n: usize) -> Self {
        Self { q: vec![0.0; n], v: vec![0.0; n], a: vec![0.0; n], free: Vec::new() }
    }

    pub(super) fn expand(&mut self, dofs: &fem_beam::DofMap, q: &[f64], v: &[f64]) {
        dofs.expand_into(q, &mut self.q);
        dofs.expand_into(v, &mut self.v);
        self.a.iter_mut().for_each(|a| *a = 0.0);
    }

    /// Deflection, velocity and acceleration at `x` (m, m/s, m/s²), interpolated with the Hermite shapes.
    pub(super) fn motion_at(&self, model: &BeamModel, x: f64) -> Result<[f64; 3]> {
        Ok([model.deflection_at(&self.q, x)?, model.deflection_at(&self.v, x)?, model.deflection_at(&self.a, x)?])
    }

    /// The state after a step: q_{k+1}, v_{k+1} and the mean acceleration (v_{k+1} − v_k)/h.
    pub(super) fn expand_step(&mut self, dofs: &fem_beam::DofMap, q: &[f64], v: &[f64], v_before: &[f64], h: f64) {
        dofs.expand_into(q, &mut self.q);
        dofs.expand_into(v, &mut self.v);
        self.free.resize(v.len(), 0.0);
        for i in 0..v.len() {
            self.free[i] = (v[i] - v_before[i]) / h;
        }
        dofs.expand_into(&self.free, &mut self.a);
    }
}
