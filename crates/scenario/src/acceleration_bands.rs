//! The accelerations a run reports besides the nodal one, as a scenario sets them (docs/theory.md §10.4): the modal
//! band (EN 1990's deck check on a span) and the filter in time (any model; by default a Timoshenko rail's and a
//! track's under ballast friction).

use crate::Scenario;
use crate::error::{Result, invalid};
use fem_beam::modal_band::BandLimit;

/// The band (Hz) the acceleration is filtered to by default where the step's does not converge: the upper end of the
/// band railway vibration is assessed in. On a Timoshenko rail it lies below the shear modes; under ballast friction
/// the step's acceleration grows with every halving (stick and slip starting within a step excite the mesh's
/// highest modes: 1793, 1891, 1983, 4279 m/s² on the reference case with 5 kN/m at 400 to 3200 elements), while
/// filtered to this band it settles (1770, 1751, 1749, 1746 m/s²; docs/theory.md §10.4).
pub const DEFAULT_ACCELERATION_FILTER: f64 = 1000.0;

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
    /// the band given (finite and > 0), else on a Timoshenko rail or under ballast friction
    /// [`DEFAULT_ACCELERATION_FILTER`], else none.
    pub fn acceleration_filter(&self) -> Result<Option<f64>> {
        match self.output.acceleration_filter {
            Some(band) if !(band.is_finite() && band > 0.0) => {
                Err(invalid("output.acceleration_filter", band, "must be finite and > 0 (Hz)"))
            }
            Some(band) => Ok(Some(band)),
            None => {
                let timoshenko = !self.beam.theory.bounds_point_load_acceleration();
                let ballast_friction = self.friction.distributed.as_ref().is_some_and(|d| d.force_per_length > 0.0);
                Ok((timoshenko || ballast_friction).then_some(DEFAULT_ACCELERATION_FILTER))
            }
        }
    }
}
