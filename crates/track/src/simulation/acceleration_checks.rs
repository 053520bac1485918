//! The checks of the accelerations a run is asked to record besides the nodal one, before anything is allocated:
//! the modal band's dense eigenproblem within [`BeamModel::MAX_MODAL_DOFS`], the filter in time's band, window and
//! the velocities it keeps ([`super::velocity_window`]).

use super::settings::RunSettings;
use crate::error::{Result, Setting, invalid};
use fem_beam::BeamModel;

impl RunSettings {
    /// The most velocities (numbers) the filtered acceleration's window may keep: 400 MB.
    pub const MAX_FILTER_VALUES: usize = 50_000_000;

    /// The modal band within the dense eigenproblem's size, the filter's band ([`Self::validate_filter`]).
    pub(super) fn validate_accelerations(&self, model: &BeamModel) -> Result<()> {
        if let Some(band) = self.record.acceleration_filter {
            self.validate_filter(model, band)?;
        }
        if let Some(band) = self.record.acceleration_band
            && model.mass().order() > BeamModel::MAX_MODAL_DOFS
        {
            // The band's eigenproblem is dense: refused before the run, with the filter that takes any size.
            return Err(crate::TrackError::Beam(fem_beam::FemError::InvalidBand {
                value: band.to_string(),
                allowed: format!(
                    "its modes are solved densely, for at most {} free DOFs, and this model has {}: use fewer \
                     elements, or output.acceleration_filter (a filter in time, any size)",
                    BeamModel::MAX_MODAL_DOFS,
                    model.mass().order()
                ),
            }));
        }
        Ok(())
    }

    /// The filter's band (finite, > 0), its window within the run, and the velocities it keeps within
    /// [`Self::MAX_FILTER_VALUES`] — checked before anything is allocated.
    fn validate_filter(&self, model: &BeamModel, band: f64) -> Result<()> {
        if !(band.is_finite() && band > 0.0) {
            return Err(invalid(Setting::AccelerationFilter, band, "must be finite and > 0 (Hz)"));
        }
        let window = super::velocity_window::HALF_POWER / band;
        let run = self.crossing_time(model.mesh().length);
        if window > run {
            let allowed =
                format!("filters over a window of 0.443/band = {window:.4e} s, longer than the run ({run:.4e} s)");
            return Err(invalid(Setting::AccelerationFilter, band, allowed));
        }
        let kept = super::velocity_window::VelocityWindow::kept(band, self.time_step());
        // The rail's window keeps every free DOF, the sleepers' their own and their ballast bodies' ([`super::sleeper_record`]).
        let sleepers = model.sleepers().map_or(0, |(_, nodes)| 2 * nodes.len());
        let values = kept.saturating_mul(model.dofs().free_len() + sleepers);
        if values > Self::MAX_FILTER_VALUES {
            let allowed = format!(
                "keeps {kept} steps' velocities of {} DOFs over its window ({values} numbers, at most {}): raise \
                 the band or lengthen the load advance",
                model.dofs().free_len() + sleepers,
                Self::MAX_FILTER_VALUES
            );
            return Err(invalid(Setting::AccelerationFilter, band, allowed));
        }
        Ok(())
    }
}
