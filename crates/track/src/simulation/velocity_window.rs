//! The window of velocities behind an acceleration filtered in time (docs/theory.md §10.4): the velocities of the
//! last steps kept, and the mean acceleration over the last T seconds,
//!
//!   a_T(t − T/2) = (v(t) − v(t − T)) / T,
//!
//! with v(t − T) interpolated linearly between the two steps around it, so that runs refined in h filter alike. A
//! band f_b sets T = 0.443/f_b (the −3 dB point of the boxcar's sinc(π f T)); a step h longer than T sets T = h, the
//! step's mean acceleration. The rail's nodes ([`super::filtered_record`]) and the sleepers
//! ([`super::sleeper_record`]) are filtered by it alike.

use std::collections::VecDeque;

/// The −3 dB point of sinc(π f T) in units of 1/T: sin(πx)/(πx) = 1/√2 at x = 0.443.
pub const HALF_POWER: f64 = 0.442_946_470_689_452_3;

/// The last K + 1 (time, velocities), oldest first, K h ≥ T.
pub(super) struct VelocityWindow {
    steps: usize,
    seconds: f64,
    window: VecDeque<(f64, Vec<f64>)>,
}

/// The window's difference once it is full: the filtered acceleration of each entry, booked at `middle` (s).
pub(super) struct WindowedDifference<'a> {
    newest: &'a [f64],
    before: &'a [f64],
    after: &'a [f64],
    weight: f64,
    seconds: f64,
    /// The window's middle t − T/2 (s).
    pub(super) middle: f64,
}

impl WindowedDifference<'_> {
    /// (v_i(t) − v_i(t − T)) / T (m/s² for velocities in m/s).
    pub(super) fn acceleration(&self, i: usize) -> f64 {
        let old = self.before[i] + self.weight * (self.after[i] - self.before[i]);
        (self.newest[i] - old) / self.seconds
    }
}

impl VelocityWindow {
    /// The window filtering to `band` (Hz) over steps of `h` (s).
    pub(super) fn new(band: f64, h: f64) -> Self {
        let steps = Self::kept(band, h) - 1;
        Self { steps, seconds: (HALF_POWER / band).max(h), window: VecDeque::with_capacity(steps + 1) }
    }

    /// How many velocity vectors a window keeps: ⌈T/h⌉ + 1, for the run's size check.
    pub fn kept(band: f64, h: f64) -> usize {
        // T a whole number of steps up to round-off needs no step more.
        ((HALF_POWER / band) / h * (1.0 - 1e-12)).ceil().max(1.0) as usize + 1
    }

    /// The window T (s): 0.443/band, or h where the step is longer.
    pub(super) fn seconds(&self) -> f64 {
        self.seconds
    }

    /// Keep the velocities `now` after the step of `h` (s) ending at `time` (s) — on the first call also those
    /// before it, `previous()` — and the difference over the window once it is full.
    pub(super) fn push(
        &mut self,
        (time, h): (f64, f64),
        now: &[f64],
        previous: impl FnOnce() -> Vec<f64>,
    ) -> Option<WindowedDifference<'_>> {
        if self.window.is_empty() {
            self.window.push_back((time - h, previous()));
        }
        // The oldest vector is reused for the newest once the window is full: no allocation after it fills.
        let mut newest = match self.window.len() > self.steps {
            true => self.window.pop_front().map(|(_, v)| v).unwrap_or_default(),
            false => Vec::with_capacity(now.len()),
        };
        newest.clear();
        newest.extend_from_slice(now);
        self.window.push_back((time, newest));
        if self.window.len() <= self.steps {
            return None;
        }
        let ((t0, before), (t1, after), (t, newest)) = (self.window.front()?, self.window.get(1)?, self.window.back()?);
        // v(t − T) between the two oldest steps (t0 ≤ t − T ≤ t1).
        let weight = ((t - self.seconds - t0) / (t1 - t0)).clamp(0.0, 1.0);
        Some(WindowedDifference {
            newest,
            before,
            after,
            weight,
            seconds: self.seconds,
            middle: t - 0.5 * self.seconds,
        })
    }
}
