//! Whole-beam snapshots of a run at chosen instants: nodal deflection w_i and bending moment M_i (docs/theory.md §6).
//!
//! An observer for [`crate::Simulation::run_observed`]. Each request — a time t or a load position x_c — is taken
//! at the first step whose time reaches it (t_{k+1} ≥ t, or t_{k+1} ≥ (x_c − x₀)/v), so it lies within one step h
//! after the instant asked for and the snapshot reports the time and load position it was taken at. The moments
//! are the nodal moments from element end forces f = K_e q_e + C_e q̇_e + M_e q̈_e − f_e
//! ([`fem_beam::BeamModel::nodal_moments`]), with q̈ the step's mean acceleration (v_{k+1} − v_k)/h and f_e the
//! moving load where it stands plus the friction forces p_j/h of the step at their sections.

use crate::error::Result;
use crate::error::{Setting, invalid};
use crate::placed::PlacedInteractions;
use crate::simulation::{RunSettings, StepView};
use fem_beam::section::Motion;
use fem_beam::{BeamModel, Train};

/// When a snapshot is taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SnapshotAt {
    /// At time t (s).
    Time(f64),
    /// When the load reaches this position (m).
    LoadPosition(f64),
}

/// The beam at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// What was asked for.
    pub requested: SnapshotAt,
    /// Time it was taken at (s).
    pub time: f64,
    /// Load position then (m).
    pub load_position: f64,
    /// Node abscissae (m).
    pub x: Vec<f64>,
    /// Nodal deflections w (m, upward).
    pub deflection: Vec<f64>,
    /// Nodal bending moments (N·m, sagging positive).
    pub moment: Vec<f64>,
}

/// Takes the requested snapshots as a run goes.
#[derive(Debug)]
pub struct SnapshotTaker<'a> {
    model: &'a BeamModel,
    interactions: &'a PlacedInteractions,
    train: Train,
    step: f64,
    /// (trigger time, request), sorted by trigger time.
    pending: Vec<(f64, SnapshotAt)>,
    next: usize,
    taken: Vec<Snapshot>,
    error: Option<crate::TrackError>,
}

impl<'a> SnapshotTaker<'a> {
    /// The requests for a run of `model` with `interactions` under `settings`; each must fall within the run (times in
    /// [0, end], load positions between the start position and L).
    pub fn new(
        model: &'a BeamModel,
        interactions: &'a PlacedInteractions,
        settings: &RunSettings,
        requests: &[SnapshotAt],
    ) -> Result<Self> {
        let length = model.mesh().length;
        let step = settings.time_step();
        let start = settings.start_position();
        let end = settings.step_count(length) * step;
        let mut pending = Vec::with_capacity(requests.len());
        for &request in requests {
            let trigger = match request {
                SnapshotAt::Time(t) => {
                    if !(t.is_finite() && (0.0..=end).contains(&t)) {
                        let allowed = format!("a snapshot time must lie in the run, [0, {end}] s");
                        return Err(invalid(Setting::Snapshots, t, allowed));
                    }
                    t
                }
                SnapshotAt::LoadPosition(x) => {
                    // The first axle's position: up to L plus the train's length (the last axle then leaves).
                    let last = settings.travel_end(length);
                    if !(x.is_finite() && (start..=last).contains(&x)) {
                        let allowed = format!("a snapshot load (first axle) position must lie in [{start}, {last}] m");
                        return Err(invalid(Setting::Snapshots, x, allowed));
                    }
                    settings.motion().time_at(x)
                }
            };
            pending.push((trigger, request));
        }
        pending.sort_by(|a, b| a.0.total_cmp(&b.0));
        let train = settings.moving.load.train();
        Ok(Self { model, interactions, train, step, pending, next: 0, taken: Vec::new(), error: None })
    }

    /// Observe one step; returns false (stop the run) only after an error, kept for [`SnapshotTaker::finish`].
    pub fn observe(&mut self, view: &StepView<'_>) -> bool {
        // A millionth of a step of slack against round-off in the accumulated time t_{k+1}.
        while self.next < self.pending.len() && view.time >= self.pending[self.next].0 - 1e-6 * self.step {
            let requested = self.pending[self.next].1;
            match self.take(view, requested) {
                Ok(snapshot) => self.taken.push(snapshot),
                Err(e) => {
                    self.error = Some(e);
                    return false;
                }
            }
            self.next += 1;
        }
        true
    }

    fn take(&self, view: &StepView<'_>, requested: SnapshotAt) -> Result<Snapshot> {
        let (model, mesh) = (self.model, *self.model.mesh());
        let dofs = model.dofs();
        let q = dofs.expand(view.displacement);
        let v = dofs.expand(view.velocity);
        let mean: Vec<f64> =
            view.velocity.iter().zip(view.previous_velocity).map(|(a, b)| (a - b) / self.step).collect();
        let a = dofs.expand(&mean);
        // The train where the step left its first axle (the position the view reports).
        let beam = model.discretisation();
        let mut loads = self.train.load_vector(&beam, view.load_position);
        for (&x, &p) in self.interactions.positions().iter().zip(view.impulses) {
            loads.add_point_force(&beam, x, p / self.step)?;
        }
        let moments = model.nodal_moments(&q, &loads, Motion { velocity: Some(&v), acceleration: Some(&a) })?;
        Ok(Snapshot {
            requested,
            time: view.time,
            load_position: view.load_position,
            x: (0..mesh.nodes()).map(|i| mesh.node_x(i)).collect(),
            deflection: model.nodal_deflections(&q)?,
            moment: moments.values().to_vec(),
        })
    }

    /// The snapshots taken, in time order; the first error met while taking them, if any.
    pub fn finish(self) -> Result<Vec<Snapshot>> {
        match self.error {
            Some(e) => Err(e),
            None => Ok(self.taken),
        }
    }
}
