//! The two-beam track in time (docs/theory.md §19, "The two-beam track in time"): `[beam]` one rail on `[sleepers]`
//! whose ballast rests on the `[embankment]`, a second beam on the `[foundation]` — a Winkler soil, or the spring,
//! dashpot and co-vibrating mass a run fits to a `[ground]` ([`Scenario::on_fitted_foundation`]). The embankment and
//! its soil are the whole track's (as on the ground): each rail rests on half of them. The sleepers' exceptions — a
//! voided, tensionless or frictional sleeper, a rescaled pad or ballast — act between the sleeper and the embankment.

use crate::Scenario;
use crate::embankment::{EmbankmentSection, InterfaceKind};
use crate::error::{Result, invalid};
use fem_beam::{BeamModel, EmbankmentBeam, Foundation, Mesh};

impl Scenario {
    /// The rail on its sleepers over half the embankment on half the soil, every value checked by key.
    pub(crate) fn two_beam_model(&self, section: &EmbankmentSection) -> Result<BeamModel> {
        let Some(sleepers) = &self.sleepers else {
            return Err(invalid(
                "embankment",
                "given",
                "an [embankment] carries a rail on [sleepers]: give them, or fold the embankment into the composite \
                 [beam]",
            ));
        };
        if section.interface == InterfaceKind::Tensionless {
            return Err(Self::tensionless_interface_in_time());
        }
        if self.friction.distributed.is_some() {
            return Err(invalid(
                "friction.distributed",
                "given",
                "over an [embankment] the ballast's friction acts sleeper by sleeper: give it as \
                 [[sleepers.exceptions]] friction",
            ));
        }
        let rail = self.beam;
        rail.validate()?;
        let embankment = section.embankment()?;
        let mesh = Mesh::new(self.mesh.length, self.mesh.elements)?;
        // Half the embankment on half the soil under each rail.
        let share = fem_beam::Beam {
            youngs_modulus: 0.5 * embankment.bending_stiffness,
            second_moment: 1.0,
            area: 1.0,
            density: 0.5 * embankment.mass_per_length,
            ..fem_beam::Beam::default()
        };
        let whole = self.soil(&fem_beam::Beam { youngs_modulus: 2.0 * share.youngs_modulus, ..share })?;
        if !whole.law.is_linear() {
            return Err(invalid(
                "foundation.law",
                whole.law.name(),
                "must be linear under an [embankment]: the embankment rests on the soil throughout",
            ));
        }
        let soil = Foundation { stiffness: 0.5 * whole.stiffness, damping: 0.5 * whole.damping, ..whole };
        let damping = self.graded_damping(&mesh, soil.damping, soil.critical_damping(&share))?;
        let below = EmbankmentBeam::new(
            share.bending_stiffness(),
            share.mass_per_length(),
            embankment.loss_factor,
            soil,
            damping,
        )?;
        let nothing = Foundation::linear(0.0, 0.0);
        let model = BeamModel::with_element_damping(rail, nothing, mesh, self.supports, vec![0.0; mesh.elements])?;
        let mut model = model
            .with_sleepers_on_embankment(sleepers.sleepers()?, below)
            .map_err(|e| sleepers.misfit(e, &self.mesh))?;
        if let Some(rayleigh) = &self.damping.rayleigh {
            model = model.with_rayleigh(rayleigh.rayleigh()?)?;
        }
        crate::diagnostics::refuse_degenerate(&model)?;
        Ok(model)
    }

    /// The refusal of `embankment.interface = "tensionless"` in a run in time.
    pub(crate) fn tensionless_interface_in_time() -> crate::StudyError {
        invalid(
            "embankment.interface",
            "tensionless",
            "a run in time takes the ballast's law sleeper by sleeper: leave the interface bonded and give the sleepers \
             that cannot pull as [[sleepers.exceptions]] with law = \"tensionless\" (or a void)",
        )
    }
}
