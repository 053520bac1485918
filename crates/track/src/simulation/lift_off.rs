//! Where and when the rail leaves the soil of a nonlinear foundation (docs/theory.md §13): after each step the gap
//! g_s = g₀ₛ + H_s q of every foundation section (m, positive where the rail is above the soil's undeformed
//! surface — in tension, where a tensionless soil lets go and a bilinear one softens), and, over the run, the zones
//! of neighbouring sections that lifted, when, and by how much.

use super::records::{Record, StepState};
use super::results::LiftOff;
use crate::error::Result;
use crate::placed::{PlacedInteractions, SectionKind};
use banded::BlockRows;
use fem_beam::{Extreme, LiftOffZone};
use friction::InteractionRow;

/// A gap above this (m) counts as lifted: far above the round-off of deflections of millimetres (~1e-19 m) and far
/// below anything a track engineer reads.
pub const LIFT_OFF_GAP: f64 = 1e-12;

/// One foundation section as the record follows it.
struct Followed {
    gap: f64,
    x: f64,
    /// First and last time lifted (s), and the largest gap (m) and when (s).
    first: f64,
    last: f64,
    largest: (f64, f64),
}

/// The record of the foundation sections' gaps; empty (and free) without a nonlinear foundation.
pub(super) struct LiftOffRecord {
    sections: Vec<Followed>,
    /// Their rows: packed where each is short and on consecutive DOFs (a soil's sections), else one by one.
    rows: Rows,
    /// H q of the step.
    deflections: Vec<f64>,
}

/// The followed sections' rows, for H q.
enum Rows {
    Packed(BlockRows),
    Each(Vec<InteractionRow>),
}

impl LiftOffRecord {
    /// Follow the foundation sections of `placed` (their rows, gaps and places).
    pub(super) fn new(placed: &PlacedInteractions) -> Self {
        let set = placed.interactions();
        let followed: Vec<(usize, f64)> = (0..placed.len())
            .filter(|&j| placed.kinds()[j] == SectionKind::Foundation)
            .filter_map(|j| Some((j, set.laws()[j].gap()?)))
            .collect();
        let sections = followed
            .iter()
            .map(|&(j, gap)| {
                let x = placed.positions()[j];
                Followed { gap, x, first: f64::NAN, last: f64::NAN, largest: (0.0, f64::NAN) }
            })
            .collect();
        let rows = followed.iter().map(|&(j, _)| &set.rows()[j]);
        let rows = match nscd::pack_rows(rows.clone()) {
            Some(packed) => Rows::Packed(packed),
            None => Rows::Each(rows.cloned().collect()),
        };
        Self { sections, rows, deflections: vec![0.0; followed.len()] }
    }

    /// The zones and extremes; None without foundation sections.
    pub(super) fn finish(self) -> Option<LiftOff> {
        if self.sections.is_empty() {
            return None;
        }
        let mut sections: Vec<&Followed> = self.sections.iter().collect();
        sections.sort_by(|a, b| a.x.total_cmp(&b.x));
        let mut zones: Vec<LiftOffZone> = Vec::new();
        let mut previous_lifted = false;
        for s in sections {
            let lifted = !s.first.is_nan();
            if lifted {
                let zone = LiftOffZone {
                    from: s.x,
                    to: s.x,
                    first_time: Some(s.first),
                    last_time: Some(s.last),
                    largest_gap: Extreme::at(s.largest.0, s.x, s.largest.1),
                    sections: 1,
                };
                match zones.last_mut().filter(|_| previous_lifted) {
                    Some(open) => open.absorb(&zone),
                    None => zones.push(zone),
                }
            }
            previous_lifted = lifted;
        }
        Some(LiftOff { sections: self.sections.len(), zones })
    }
}

impl Record for LiftOffRecord {
    fn record(&mut self, step: &StepState<'_>) -> Result<()> {
        match &self.rows {
            Rows::Packed(rows) => rows.mul(step.q, &mut self.deflections),
            Rows::Each(rows) => rows.iter().zip(&mut self.deflections).for_each(|(r, d)| *d = r.dot(step.q)),
        }
        for (s, hq) in self.sections.iter_mut().zip(&self.deflections) {
            let gap = s.gap + hq;
            if gap > LIFT_OFF_GAP {
                if s.first.is_nan() {
                    s.first = step.time;
                }
                s.last = step.time;
                if gap > s.largest.0 {
                    s.largest = (gap, step.time);
                }
            }
        }
        Ok(())
    }
}
