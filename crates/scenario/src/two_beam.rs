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
        // The soil under the whole embankment (a damping ratio is of the whole embankment on it), half of each under
        // each rail.
        let embankment_beam = |share: f64| fem_beam::Beam {
            youngs_modulus: share * embankment.bending_stiffness,
            second_moment: 1.0,
            area: 1.0,
            density: share * embankment.mass_per_length,
            ..fem_beam::Beam::default()
        };
        let share = embankment_beam(0.5);
        let whole = self.soil(&embankment_beam(1.0))?;
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

#[cfg(test)]
mod tests {
    use crate::Scenario;

    /// A rail on sleepers over an embankment of 200 MN·m² and 7.56 t/m on a Winkler soil of 8.6 MN/m².
    const TRACK: &str = r#"
[mesh]
length = 65.0
elements = 400
[sleepers]
spacing = 0.65
mass = 125.0
[embankment]
bending_stiffness = 2.0e8
mass_per_length = 7560.0
[foundation]
stiffness = 8.6e6
"#;

    /// Each rail carries half the embankment on half the soil; a damping ratio is the whole embankment's on the whole
    /// soil, ζ·2√(k_f ρA_e), halved under each rail like the spring.
    #[test]
    fn each_rail_rests_on_half_the_embankment_on_half_the_soil() {
        let text = format!("{TRACK}damping_ratio = 0.1\n");
        let model = Scenario::from_toml(&text, "t.toml").unwrap().model().unwrap();
        let below = model.embankment().unwrap();
        assert_eq!((below.beam.bending_stiffness(), below.beam.mass_per_length()), (1.0e8, 3780.0));
        assert_eq!(below.foundation.stiffness, 4.3e6);
        let whole = 0.1 * 2.0 * (8.6e6f64 * 7560.0).sqrt();
        assert!((below.foundation.damping / (0.5 * whole) - 1.0).abs() < 1e-12, "{}", below.foundation.damping);
        assert_eq!(model.foundation().stiffness, 0.0);
    }

    /// Refused by key: an embankment without sleepers, a tensionless interface or distributed friction in time, a
    /// soil that is not linear under it.
    #[test]
    fn what_a_run_over_an_embankment_cannot_take_is_refused_by_key() {
        let refused = |text: &str| Scenario::from_toml(text, "t.toml").unwrap().model().unwrap_err().to_string();
        let start = TRACK.find("[sleepers]").unwrap();
        let end = TRACK.find("[embankment]").unwrap();
        let bare = format!("{}{}", &TRACK[..start], &TRACK[end..]);
        assert!(refused(&bare).contains("embankment = given"), "{}", refused(&bare));
        let lifting =
            TRACK.replace("mass_per_length = 7560.0", "mass_per_length = 7560.0\ninterface = \"tensionless\"");
        assert!(refused(&lifting).contains("embankment.interface = tensionless"));
        let friction = format!("{TRACK}[friction.distributed]\nforce_per_length = 1000.0\n");
        assert!(refused(&friction).contains("friction.distributed = given"));
        let soil = format!("{TRACK}law = \"tensionless\"\n");
        assert!(refused(&soil).contains("foundation.law = tensionless"), "{}", refused(&soil));
    }
}
