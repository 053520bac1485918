//! The continuous track a scenario on sleepers stands for in the long wave (docs/theory.md §18): what the closed
//! forms and the stationary wave — models of a uniform support — take of sleepers, said so, or refused by key where
//! the sleepers hold what a uniform support cannot (exceptions: voids, tensionless or frictional sleepers).

use crate::Scenario;
use crate::error::{Result, invalid};
use crate::sections::FoundationLawKind;

impl Scenario {
    /// The continuous track this scenario on sleepers stands for in the long wave
    /// ([`fem_beam::Sleepers::equivalent_track`]): its soil plus the pads and ballast (and subgrade) in series spread
    /// over a spacing, k_eq, their dashpots in series to first order in frequency, c_eq
    /// ([`fem_beam::Sleepers::equivalent_damping`]), and the sleepers' (and ballast bodies') mass spread on the rail
    /// as the long wave moves it. The scenario itself without sleepers.
    pub fn continuous_twin(&self) -> Result<Scenario> {
        let mut twin = self.clone();
        let Some(section) = twin.sleepers.take() else { return Ok(twin) };
        let sleepers = section.sleepers()?;
        let (beam, stiffness) = sleepers.equivalent_track(&self.beam, self.foundation.stiffness);
        let soil = self.model()?.foundation().damping;
        twin.beam = beam;
        twin.foundation.stiffness = stiffness;
        twin.foundation.damping = Some(soil + sleepers.equivalent_damping());
        twin.foundation.damping_ratio = None;
        Ok(twin)
    }

    /// What a model of a uniform support (`what`: "the stationary wave", "the closed form") takes of this scenario:
    /// itself without sleepers, or on sleepers their [`Scenario::continuous_twin`] with a note saying so. Refused, by
    /// key, for sleepers a uniform support cannot hold — exceptions, or a soil beside them that is not linear — and
    /// for a changing speed (these are steady states at one speed).
    pub fn uniform_support(&self, what: &str) -> Result<(Scenario, Option<String>)> {
        self.load.refuse_changing_speed(what)?;
        if self.embankment.is_some() && self.ground.is_none() {
            return Err(invalid(
                "embankment",
                "given",
                format!(
                    "{what} takes the rail on sleepers over an [embankment] on a [ground] only (its exact line \
                     support); on a Winkler [foundation] run the finite track (frictrack run)"
                ),
            ));
        }
        let Some(section) = &self.sleepers else { return Ok((self.clone(), None)) };
        if !section.exceptions.is_empty() {
            return Err(invalid(
                "sleepers.exceptions",
                format!("{} given", section.exceptions.len()),
                format!(
                    "{what} takes a uniform support: sleepers as their long-wave continuous twin, which has no voided, \
                     tensionless, frictional or rescaled sleeper; run the finite track across them"
                ),
            ));
        }
        if self.foundation.law != FoundationLawKind::Linear {
            return Err(invalid(
                "foundation.law",
                format!("{:?}", self.foundation.law).to_lowercase(),
                format!(
                    "{what} takes sleepers as their long-wave continuous twin only on a linear soil (the twin would \
                     make the pads and ballast unilateral too); run the finite track"
                ),
            ));
        }
        let sleepers = section.sleepers()?;
        let twin = self.continuous_twin()?;
        let note = format!(
            "sleepers taken as their long-wave continuous twin: k = {:.4} MN/m² ({:.4} MN/m² from pads and ballast in \
             series over {} m), c = {:.4} kN·s/m², ρA = {:.3} kg/m with the sleepers' mass as the long wave moves it; \
             the sleeper-passing excitation (v/a) and the bay's resonances are not in {what} — run the finite track \
             for them",
            twin.foundation.stiffness / 1e6,
            sleepers.equivalent_stiffness() / 1e6,
            sleepers.spacing,
            twin.model()?.foundation().damping / 1e3,
            twin.beam.mass_per_length(),
        );
        Ok((twin, Some(note)))
    }
}
