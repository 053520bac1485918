//! The accelerations a run reports besides the nodal one, as a scenario sets them (docs/theory.md §10.4): the modal
//! band (EN 1990's deck check on a span) and the filter in time (any model; a Timoshenko rail's by default).

use crate::Scenario;
use crate::error::{Result, invalid};
use fem_beam::modal_band::BandLimit;

/// The band (Hz) a Timoshenko rail's acceleration is filtered to by default: the upper end of the band railway
/// vibration is assessed in, below the rail's shear modes.
pub const TIMOSHENKO_FILTER: f64 = 1000.0;

impl Scenario {
    /// The band of the band-limited acceleration its runs report ([`crate::OutputSection::acceleration_band`]): the
    /// frequency given (finite and > 0), else on a span EN 1990's deck band of its own modes, else none.
    pub fn acceleration_band(&self) -> Result<Option<BandLimit>> {
        if let Some(limit) = self.output.acceleration_band {
            if !(limit.is_finite() && limit > 0.0) {
                return Err(invalid("output.acceleration_band", limit, "must be finite and > 0 (Hz)"));
            }
            return Ok(Some(BandLimit::Frequency(limit)));
        }
        let (k_f, sleepers) = (self.foundation.stiffness, self.sleepers.is_some());
        let span = crate::diagnostics::span_of(&self.beam, &self.supports, k_f, sleepers, self.mesh.length);
        Ok(span.map(|_| BandLimit::Deck))
    }

    /// The band (Hz) of the acceleration its runs report filtered in time ([`crate::OutputSection::acceleration_filter`]):
    /// the band given (finite and > 0), else on a Timoshenko rail [`TIMOSHENKO_FILTER`], else none.
    pub fn acceleration_filter(&self) -> Result<Option<f64>> {
        match self.output.acceleration_filter {
            Some(band) if !(band.is_finite() && band > 0.0) => {
                Err(invalid("output.acceleration_filter", band, "must be finite and > 0 (Hz)"))
            }
            Some(band) => Ok(Some(band)),
            None => Ok((!self.beam.theory.bounds_point_load_acceleration()).then_some(TIMOSHENKO_FILTER)),
        }
    }
}
