//! What a run on sleepers records of them (docs/theory.md §18): for each sleeper the largest force in its pad and in
//! the ballast under it (N, compression positive), its lowest position, its largest acceleration (and a ballast
//! body's) and, where the ballast cannot pull, the
//! largest gap that opened under it; and the rail's deflection under the first load at every step, from which the
//! report reads its variation over a bay (above a sleeper against mid-span).
//!
//! Pad P = k_p(z − w) + c_p(ż − ẇ), ballast B = k_b·(−u) − c_b u̇ where bonded; where unilateral the force its law
//! carried in the step (its impulse over h: ⟨−k_b(u + g) − c_b u̇⟩₊ where it presses, nothing across an open gap)
//! less the weight's share k_b⟨−g⟩₊, with the law's gap g (the void, or under the track's weight the gap in the
//! settled state, negative where the weight presses the sleeper on), u = z − y the sleeper's place over the ballast (y = 0 on rigidly founded
//! ballast, the ballast body's DOF in Zhai's two layers), subgrade G = −k_g y − c_g ẏ; w the rail's deflection over
//! the sleeper, z the sleeper's (m, upward). Like the deflections, the forces are counted from the settled state:
//! the weight's share is not in them.

use super::records::{Record, StepState};
use super::results::{SleeperPeaks, SleeperResults};
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
}

/// The record; empty (and free) on a continuous track.
pub(super) struct SleeperRecord<'m> {
    model: &'m BeamModel,
    beam: Discretisation,
    sleepers: Vec<Followed>,
    results: SleeperResults,
}

impl<'m> SleeperRecord<'m> {
    /// The record of the sleepers of `model`, their unilateral laws as `placed` holds them.
    pub(super) fn new(model: &'m BeamModel, placed: &PlacedInteractions) -> Self {
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
                });
            }
        }
        Self { model, beam: model.discretisation(), sleepers, results }
    }

    /// The results; None on a continuous track.
    pub(super) fn finish(self) -> Option<SleeperResults> {
        if self.sleepers.is_empty() {
            return None;
        }
        Some(SleeperResults { sleepers: self.sleepers.into_iter().map(|s| s.peaks).collect(), ..self.results })
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

impl Record for SleeperRecord<'_> {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        if self.sleepers.is_empty() {
            return Ok(());
        }
        for f in &mut self.sleepers {
            let (w, dw) = f.w.map_or((0.0, 0.0), |d| (s.q[d], s.v[d]));
            let (z, dz) = (s.q[f.z], s.v[f.z]);
            let (y, dy) = f.y.map_or((0.0, 0.0), |d| (s.q[d], s.v[d]));
            let (u, du) = (z - y, dz - dy);
            let pad = f.support.pad.stiffness * (z - w) + f.support.pad.damping * (dz - dw);
            let (k, c) = (f.support.ballast.stiffness, f.support.ballast.damping);
            let ballast = match f.support.contact {
                BallastContact::Bonded => -k * u - c * du,
                BallastContact::Unilateral { .. } => {
                    let opening = u + f.gap;
                    if opening <= 0.0 && f.peaks.first_contact.is_none() {
                        f.peaks.first_contact = Some(s.time);
                    }
                    if let Some(largest) = f.peaks.largest_gap.as_mut() {
                        *largest = largest.max(opening);
                    }
                    let carried = f.law.map_or(0.0, |j| s.impulses[j] / s.h);
                    carried - k * (-f.gap).max(0.0)
                }
            };
            let p = &mut f.peaks;
            if let (Some(subgrade), Some(peak)) = (f.support.subgrade, p.subgrade_force.as_mut()) {
                let force = -subgrade.stiffness * y - subgrade.damping * dy;
                if force > peak.0 {
                    *peak = (force, s.time);
                }
            }
            if pad > p.pad_force.0 {
                p.pad_force = (pad, s.time);
            }
            if ballast > p.ballast_force.0 {
                p.ballast_force = (ballast, s.time);
            }
            p.lowest = p.lowest.max(-z);
            let acceleration = ((dz - s.previous_v[f.z]) / s.h).abs();
            if acceleration > p.acceleration.0 {
                p.acceleration = (acceleration, s.time);
            }
            if let (Some(d), Some(peak)) = (f.y, p.ballast_acceleration.as_mut()) {
                let acceleration = ((dy - s.previous_v[d]) / s.h).abs();
                if acceleration > peak.0 {
                    *peak = (acceleration, s.time);
                }
            }
        }
        let x = s.load.position(s.time);
        if let Some(w) = self.deflection_at(x, &s.q[..s.beam]) {
            self.results.under_load.push((x, w));
        }
        Ok(())
    }
}
