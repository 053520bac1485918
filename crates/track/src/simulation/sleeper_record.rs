//! What a run on sleepers records of them (docs/theory.md §18): for each sleeper the largest force in its pad and in
//! the ballast under it (N, compression positive), its lowest position, its largest acceleration (and a ballast
//! body's; filtered in time like the rail's where the run filters, [`super::velocity_window`]) and, where the ballast
//! cannot pull, the largest gap that opened under it; the histories of the sleepers under recorded sections; and the
//! rail's deflection under the first load at every step, from which the report reads its variation over a bay (above
//! a sleeper against mid-span).
//!
//! Pad P = k_p(z − w) + c_p(ż − ẇ), ballast B = k_b·(−u) − c_b u̇ where bonded; where unilateral the force its law
//! carried in the step (its impulse over h: ⟨−k_b(u + g) − c_b u̇⟩₊ where it presses, nothing across an open gap)
//! less the weight's share k_b⟨−g⟩₊, with the law's gap g (the void, or under the track's weight the gap in the
//! settled state, negative where the weight presses the sleeper on), u = z − y the sleeper's place over the ballast (y = 0 on rigidly founded
//! ballast, the ballast body's DOF in Zhai's two layers), subgrade G = −k_g y − c_g ẏ; w the rail's deflection over
//! the sleeper, z the sleeper's (m, upward). Like the deflections, the forces are counted from the settled state:
//! the weight's share is not in them.

use super::records::{Record, StepState};
use super::results::{SleeperHistory, SleeperPeaks, SleeperResults};
use super::velocity_window::VelocityWindow;
use crate::error::Result;
use crate::placed::{PlacedInteractions, SectionKind};
use fem_beam::{BallastContact, BeamModel, Discretisation, SleeperSupport};

/// A followed sleeper: its DOFs and layers.
struct Followed {
    w: Option<usize>,
    z: usize,
    /// What is under the ballast: a ballast body's y or an embankment's w_e, if any.
    y: Option<usize>,
    support: SleeperSupport,
    /// Unilateral ballast: its law's gap (m), the void or the settled state's, and its interaction's index.
    gap: f64,
    law: Option<usize>,
    peaks: SleeperPeaks,
    /// Its history, where a recorded section sits over it.
    history: Option<SleeperHistory>,
}

/// A sleeper after a step: its place and the forces on it (N, compression positive).
struct SleeperState {
    z: f64,
    pad: f64,
    ballast: f64,
    subgrade: Option<f64>,
}

/// The sleepers' (and ballast bodies') velocities over the filter's window: ż of sleeper i at 2i, ẏ at 2i + 1 (0
/// on rigidly founded ballast).
struct SleeperFilter {
    window: VelocityWindow,
    now: Vec<f64>,
}

/// The record; empty (and free) on a continuous track.
pub(super) struct SleeperRecord<'m> {
    model: &'m BeamModel,
    beam: Discretisation,
    sleepers: Vec<Followed>,
    filter: Option<SleeperFilter>,
    results: SleeperResults,
}

impl<'m> SleeperRecord<'m> {
    /// The record of the sleepers of `model`, their unilateral laws as `placed` holds them, the histories of those
    /// under the recorded `sections` (m) reserved for `steps` steps, their accelerations filtered to `filter` = (band
    /// Hz, h s) where given.
    pub(super) fn new(
        model: &'m BeamModel,
        placed: &PlacedInteractions,
        (sections, steps): (&[f64], usize),
        filter: Option<(f64, f64)>,
    ) -> Self {
        let mut results = SleeperResults::default();
        let mut sleepers = Vec::new();
        if let Some((s, nodes)) = model.sleepers() {
            let (mesh, dofs) = (model.mesh(), model.dofs());
            (results.spacing, results.first) = (s.spacing, s.first);
            let law_at = |x: f64| {
                let mut at = placed.positions().iter().zip(placed.kinds());
                at.position(|(&p, &k)| k == SectionKind::SleeperBallast && p == x)
            };
            for (i, &node) in nodes.iter().enumerate() {
                let support = s.support(i);
                let law = law_at(mesh.node_x(node));
                let gap = match support.contact {
                    BallastContact::Unilateral { gap } => {
                        law.and_then(|j| placed.interactions().laws()[j].gap()).unwrap_or(gap)
                    }
                    BallastContact::Bonded => 0.0,
                };
                let unilateral = matches!(support.contact, BallastContact::Unilateral { .. });
                sleepers.push(Followed {
                    w: dofs.free_index(2 * node),
                    z: dofs.sleeper(i),
                    y: dofs.under_ballast(i, node),
                    support,
                    gap,
                    law,
                    peaks: SleeperPeaks {
                        x: mesh.node_x(node),
                        pad_force: (0.0, f64::NAN),
                        ballast_force: (0.0, f64::NAN),
                        subgrade_force: support.subgrade.map(|_| (0.0, f64::NAN)),
                        lowest: 0.0,
                        acceleration: (0.0, f64::NAN),
                        ballast_acceleration: support.subgrade.map(|_| (0.0, f64::NAN)),
                        largest_gap: unilateral.then_some(0.0),
                        first_contact: None,
                    },
                    history: recorded_over(model, sections, node).map(|section| SleeperHistory {
                        section,
                        index: i,
                        x: mesh.node_x(node),
                        ballast_acceleration: support.subgrade.map(|_| Vec::with_capacity(steps)),
                        ..SleeperHistory::reserved(steps)
                    }),
                });
            }
        }
        let filter = filter.filter(|_| !sleepers.is_empty()).map(|(band, h)| SleeperFilter {
            window: VelocityWindow::new(band, h),
            now: vec![0.0; 2 * sleepers.len()],
        });
        results.acceleration_window = filter.as_ref().map(|f| f.window.seconds());
        Self { model, beam: model.discretisation(), sleepers, filter, results }
    }

    /// The results; None on a continuous track.
    pub(super) fn finish(self) -> Option<SleeperResults> {
        if self.sleepers.is_empty() {
            return None;
        }
        let (peaks, histories) =
            self.sleepers.into_iter().map(|s| (s.peaks, s.history)).unzip::<_, _, Vec<_>, Vec<_>>();
        Some(SleeperResults { sleepers: peaks, histories: histories.into_iter().flatten().collect(), ..self.results })
    }

    /// The rail's deflection at `x` (m) from the beam's free DOFs `q`; None off the rail.
    fn deflection_at(&self, x: f64, q: &[f64]) -> Option<f64> {
        if !(0.0..=self.model.mesh().length).contains(&x) {
            return None;
        }
        let (point, shape) = self.beam.shape_at(x).ok()?;
        let free = self.model.dofs().element_free(point.element);
        Some(free.into_iter().zip(shape).filter_map(|(d, n)| Some(q[d?] * n)).sum())
    }
}

impl Followed {
    /// Its place and forces after the step `s`; on unilateral ballast its first contact and largest gap kept.
    fn state(&mut self, s: &StepState<'_>) -> SleeperState {
        let (w, dw) = self.w.map_or((0.0, 0.0), |d| (s.q[d], s.v[d]));
        let (z, dz) = (s.q[self.z], s.v[self.z]);
        let (y, dy) = self.y.map_or((0.0, 0.0), |d| (s.q[d], s.v[d]));
        let (u, du) = (z - y, dz - dy);
        let pad = self.support.pad.stiffness * (z - w) + self.support.pad.damping * (dz - dw);
        let (k, c) = (self.support.ballast.stiffness, self.support.ballast.damping);
        let ballast = match self.support.contact {
            BallastContact::Bonded => -k * u - c * du,
            BallastContact::Unilateral { .. } => {
                let opening = u + self.gap;
                if opening <= 0.0 && self.peaks.first_contact.is_none() {
                    self.peaks.first_contact = Some(s.time);
                }
                if let Some(largest) = self.peaks.largest_gap.as_mut() {
                    *largest = largest.max(opening);
                }
                let carried = self.law.map_or(0.0, |j| s.impulses[j] / s.h);
                carried - k * (-self.gap).max(0.0)
            }
        };
        let subgrade = self.support.subgrade.map(|g| -g.stiffness * y - g.damping * dy);
        SleeperState { z, pad, ballast, subgrade }
    }

    /// Keep the peaks of `state` after the step `s`, with the accelerations of sleeper and ballast body (m/s²)
    /// booked at `when` (s).
    fn keep(&mut self, s: &StepState<'_>, state: &SleeperState, (sleeper, body, when): (f64, Option<f64>, f64)) {
        let p = &mut self.peaks;
        let raise = |peak: &mut (f64, f64), value: f64, time: f64| {
            if value > peak.0 {
                *peak = (value, time);
            }
        };
        if let (Some(force), Some(peak)) = (state.subgrade, p.subgrade_force.as_mut()) {
            raise(peak, force, s.time);
        }
        raise(&mut p.pad_force, state.pad, s.time);
        raise(&mut p.ballast_force, state.ballast, s.time);
        p.lowest = p.lowest.max(-state.z);
        raise(&mut p.acceleration, sleeper.abs(), when);
        if let (Some(a), Some(peak)) = (body, p.ballast_acceleration.as_mut()) {
            raise(peak, a.abs(), when);
        }
        if let Some(h) = self.history.as_mut() {
            h.time.push(s.time);
            h.load_position.push(s.load.position(s.time));
            h.deflection.push(state.z);
            let step_mean = |d: usize| (s.v[d] - s.previous_v[d]) / s.h;
            h.acceleration.push(step_mean(self.z));
            h.pad_force.push(state.pad);
            h.ballast_force.push(state.ballast);
            if let (Some(series), Some(d)) = (h.ballast_acceleration.as_mut(), self.y) {
                series.push(step_mean(d));
            }
        }
    }
}

/// The recorded section (m) whose nearest node is `node`, if any.
fn recorded_over(model: &BeamModel, sections: &[f64], node: usize) -> Option<f64> {
    sections.iter().copied().find(|&x| model.mesh().nearest_node(x).ok() == Some(node))
}

impl SleeperHistory {
    /// An empty history with room for `steps` steps.
    fn reserved(steps: usize) -> Self {
        let series = || Vec::with_capacity(steps);
        Self {
            time: series(),
            load_position: series(),
            deflection: series(),
            acceleration: series(),
            pad_force: series(),
            ballast_force: series(),
            ..Self::default()
        }
    }
}

impl Record for SleeperRecord<'_> {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        if self.sleepers.is_empty() {
            return Ok(());
        }
        let step_mean = |d: usize| (s.v[d] - s.previous_v[d]) / s.h;
        let filtering = self.filter.is_some();
        let difference = self.filter.as_mut().and_then(|f| {
            for (i, sleeper) in self.sleepers.iter().enumerate() {
                f.now[2 * i] = s.v[sleeper.z];
                f.now[2 * i + 1] = sleeper.y.map_or(0.0, |d| s.v[d]);
            }
            let sleepers = &self.sleepers;
            let previous = || {
                let at = |d: Option<usize>| d.map_or(0.0, |d| s.previous_v[d]);
                sleepers.iter().flat_map(|f| [at(Some(f.z)), at(f.y)]).collect()
            };
            f.window.push((s.time, s.h), &f.now, previous)
        });
        for (i, f) in self.sleepers.iter_mut().enumerate() {
            let state = f.state(s);
            // Filtered: booked at the window's middle, and only once the window is full.
            let accelerations = match (&difference, filtering) {
                (Some(d), _) => Some((d.acceleration(2 * i), f.y.map(|_| d.acceleration(2 * i + 1)), d.middle)),
                (None, true) => None,
                (None, false) => Some((step_mean(f.z), f.y.map(step_mean), s.time)),
            };
            f.keep(s, &state, accelerations.unwrap_or((0.0, None, s.time)));
        }
        let x = s.load.position(s.time);
        if let Some(w) = self.deflection_at(x, &s.q[..s.beam]) {
            self.results.under_load.push((x, w));
        }
        Ok(())
    }
}
