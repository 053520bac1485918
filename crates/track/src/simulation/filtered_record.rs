//! The largest acceleration of a run low-pass filtered in time, on a model of any size (docs/theory.md §10.4): the
//! nodal velocity's difference over a window of T seconds,
//!
//!   a_T(t) = (v(t + T/2) − v(t − T/2)) / T,
//!
//! the mean acceleration over the window (a boxcar average of a, zero-phase), booked at the window's middle. Its
//! transfer function is sinc(π f T) = sin(π f T)/(π f T): 1 at f = 0, −3 dB at f = 0.443/T, 0 at 1/T. A band f_b
//! sets T = 0.443/f_b, held exactly whatever the step: v(t − T) is interpolated linearly between the steps around it,
//! so that runs refined in h filter alike — the window the result states. A step h longer than T cannot be filtered
//! finer: the window is then h, and the band the step's (0.443/h), said. Unlike the modal band (`band_record`,
//! [`fem_beam::modal_band`]) it needs no eigenproblem, so it is defined on every track: on a Timoshenko rail, whose
//! nodal acceleration under a passing point force grows without bound as the step shrinks, the velocity stays
//! bounded and a_T converges under refinement with T held. At T = h it is the step's mean acceleration, exactly.

use super::observers::NodalDeflections;
use super::records::{Record, StepState};
use super::results::FilteredAcceleration;
use crate::error::Result;
use fem_beam::{BeamModel, Extreme};
use std::collections::VecDeque;

/// The −3 dB point of sinc(π f T) in units of 1/T: sin(πx)/(πx) = 1/√2 at x = 0.443.
pub const HALF_POWER: f64 = 0.442_946_470_689_452_3;

/// The window's velocities and the largest filtered acceleration so far.
pub(super) struct FilteredRecord {
    nodes: NodalDeflections,
    /// The band asked for (Hz), and the window's steps K.
    band: f64,
    steps: usize,
    /// The last K + 1 (time, free velocities of the beam), oldest first.
    window: VecDeque<(f64, Vec<f64>)>,
    largest: Extreme,
    /// The window actually used (s): K h of the first step.
    seconds: f64,
}

impl FilteredRecord {
    /// The record of `model`'s accelerations filtered to `band` (Hz) over steps of `h` (s), over the nodes in
    /// `region` (m) or all.
    pub(super) fn new(model: &BeamModel, band: f64, h: f64, region: Option<(f64, f64)>) -> Self {
        let seconds = (HALF_POWER / band).max(h);
        let steps = Self::kept(band, h) - 1;
        Self {
            nodes: NodalDeflections::new(model.mesh(), model.dofs(), region),
            band,
            steps,
            window: VecDeque::with_capacity(steps + 1),
            largest: Extreme::default(),
            seconds,
        }
    }

    /// How many velocity vectors the record keeps: ⌈T/h⌉ + 1, for the run's size check.
    pub fn kept(band: f64, h: f64) -> usize {
        // T a whole number of steps up to round-off needs no step more.
        ((HALF_POWER / band) / h * (1.0 - 1e-12)).ceil().max(1.0) as usize + 1
    }

    /// The largest filtered acceleration with its band and window.
    pub(super) fn finish(self) -> FilteredAcceleration {
        FilteredAcceleration {
            extreme: self.largest,
            asked: self.band,
            band: HALF_POWER / self.seconds,
            window: self.seconds,
        }
    }
}

impl Record for FilteredRecord {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        if self.window.is_empty() {
            self.window.push_back((s.time - s.h, s.previous_v[..s.beam].to_vec()));
        }
        // The oldest vector is reused for the newest once the window is full: no allocation after it fills.
        let mut newest = match self.window.len() > self.steps {
            true => self.window.pop_front().map(|(_, v)| v).unwrap_or_default(),
            false => Vec::with_capacity(s.beam),
        };
        newest.clear();
        newest.extend_from_slice(&s.v[..s.beam]);
        self.window.push_back((s.time, newest));
        if self.window.len() > self.steps
            && let (Some((t0, v0)), Some((t1, v1)), Some((t, v))) =
                (self.window.front(), self.window.get(1), self.window.back())
        {
            // v(t − T) between the two oldest steps (t0 ≤ t − T ≤ t1).
            let weight = ((t - self.seconds - t0) / (t1 - t0)).clamp(0.0, 1.0);
            let span = self.seconds;
            let (a, x) = self.nodes.largest(|d| (v[d] - (v0[d] + weight * (v1[d] - v0[d]))) / span);
            self.largest.raise(a, x, t - 0.5 * span);
        }
        Ok(())
    }
}
