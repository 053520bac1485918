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
pub use super::velocity_window::HALF_POWER;
use super::velocity_window::VelocityWindow;
use crate::error::Result;
use fem_beam::{BeamModel, Extreme};

/// The window's velocities and the largest filtered acceleration so far.
pub(super) struct FilteredRecord {
    nodes: NodalDeflections,
    /// The band asked for (Hz).
    band: f64,
    window: VelocityWindow,
    largest: Extreme,
}

impl FilteredRecord {
    /// The record of `model`'s accelerations filtered to `band` (Hz) over steps of `h` (s), over the nodes in
    /// `region` (m) or all.
    pub(super) fn new(model: &BeamModel, band: f64, h: f64, region: Option<(f64, f64)>) -> Self {
        Self {
            nodes: NodalDeflections::new(model.mesh(), model.dofs(), region),
            band,
            window: VelocityWindow::new(band, h),
            largest: Extreme::default(),
        }
    }

    /// The largest filtered acceleration with its band and window.
    pub(super) fn finish(self) -> FilteredAcceleration {
        let seconds = self.window.seconds();
        FilteredAcceleration { extreme: self.largest, asked: self.band, band: HALF_POWER / seconds, window: seconds }
    }
}

impl Record for FilteredRecord {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        let beam = s.beam;
        if let Some(difference) = self.window.push((s.time, s.h), &s.v[..beam], || s.previous_v[..beam].to_vec()) {
            let (a, x) = self.nodes.largest(|d| difference.acceleration(d));
            self.largest.raise(a, x, difference.middle);
        }
        Ok(())
    }
}
