//! The keys of a `[beam]` section (scenario files, JSON): E, I, A, ρ, the loss factor (left out when 0) and the theory — `theory = "timoshenko"` with
//! `shear_modulus` (G, Pa) and `shear_coefficient` (κ), or `"euler-bernoulli"` (the default, left out when written).
//! A Timoshenko beam without G or κ, or G or κ given to an Euler–Bernoulli beam, is refused when read, naming the
//! keys; their values are checked by [`Beam::validate`].

use crate::properties::{Beam, BeamTheory};
use serde::{Deserialize, Serialize};

/// The theory's name in a file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum TheoryName {
    #[default]
    EulerBernoulli,
    Timoshenko,
}

impl TheoryName {
    fn is_default(&self) -> bool {
        *self == TheoryName::EulerBernoulli
    }
}

/// A `[beam]` section as written.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub(crate) struct BeamKeys {
    youngs_modulus: f64,
    second_moment: f64,
    area: f64,
    density: f64,
    #[serde(skip_serializing_if = "TheoryName::is_default")]
    theory: TheoryName,
    #[serde(skip_serializing_if = "Option::is_none")]
    shear_modulus: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    shear_coefficient: Option<f64>,
    #[serde(skip_serializing_if = "is_zero")]
    loss_factor: f64,
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

impl Default for BeamKeys {
    fn default() -> Self {
        Beam::default().into()
    }
}

impl From<Beam> for BeamKeys {
    fn from(beam: Beam) -> Self {
        let (theory, shear_modulus, shear_coefficient) = match beam.theory {
            BeamTheory::EulerBernoulli => (TheoryName::EulerBernoulli, None, None),
            BeamTheory::Timoshenko { shear_modulus, shear_coefficient } => {
                (TheoryName::Timoshenko, Some(shear_modulus), Some(shear_coefficient))
            }
        };
        let Beam { youngs_modulus, second_moment, area, density, loss_factor, .. } = beam;
        Self { youngs_modulus, second_moment, area, density, theory, shear_modulus, shear_coefficient, loss_factor }
    }
}

impl TryFrom<BeamKeys> for Beam {
    type Error = String;

    fn try_from(keys: BeamKeys) -> Result<Self, String> {
        let theory = match (keys.theory, keys.shear_modulus, keys.shear_coefficient) {
            (TheoryName::Timoshenko, Some(shear_modulus), Some(shear_coefficient)) => {
                BeamTheory::Timoshenko { shear_modulus, shear_coefficient }
            }
            (TheoryName::Timoshenko, g, _) => {
                let missing = if g.is_none() { "shear_modulus (G, Pa)" } else { "shear_coefficient (κ)" };
                return Err(format!("theory = \"timoshenko\" needs {missing}"));
            }
            (TheoryName::EulerBernoulli, None, None) => BeamTheory::EulerBernoulli,
            (TheoryName::EulerBernoulli, g, _) => {
                let given = if g.is_some() { "shear_modulus" } else { "shear_coefficient" };
                return Err(format!(
                    "{given} is used only by a Timoshenko beam: add theory = \"timoshenko\", or remove it"
                ));
            }
        };
        let BeamKeys { youngs_modulus, second_moment, area, density, loss_factor, .. } = keys;
        Ok(Beam { youngs_modulus, second_moment, area, density, theory, loss_factor })
    }
}
