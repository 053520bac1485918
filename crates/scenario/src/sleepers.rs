//! The `[sleepers]` section (docs/theory.md §18): discrete supports under the rail — `spacing`, `first`, `mass` per
//! rail seat, `[sleepers.pad]` and `[sleepers.ballast]` each with `stiffness` (N/m), `damping` (N·s/m) and
//! `loss_factor`. What is left out takes a typical ballasted track's value (`fem_beam::Sleepers::default`).
//! `[sleepers.ballast] mass` (kg per rail seat) makes the ballast a body of its own on a subgrade (Zhai's two
//! layers), `[sleepers.subgrade]` its `stiffness`, `damping`, `loss_factor` (default k_g = 65 MN/m, c_g = 31.15 kN·s/m).
//! `[[sleepers.exceptions]]` change some sleepers: `index` (one sleeper, 0-based, or `[first, last]`), `gap` (m, a
//! voided sleeper), `law = "tensionless"`, `friction` (N), `pad_scale`, `ballast_scale`.

use crate::error::{Result, invalid};
use fem_beam::{BallastBody, BallastContact, Layer, SleeperException, Sleepers};
use serde::{Deserialize, Serialize};

/// `[sleepers]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SleepersSection {
    /// a (m).
    pub spacing: f64,
    /// The first sleeper's place (m); default half a spacing.
    pub first: Option<f64>,
    /// m_s (kg per rail seat).
    pub mass: f64,
    /// The rail pad: what is left out takes the typical pad's value.
    pub pad: LayerSection,
    /// The ballast: what is left out takes the typical ballast's value; a `mass` makes it a body on the subgrade.
    pub ballast: BallastSection,
    /// The subgrade under a ballast body: what is left out takes [`BallastBody::TYPICAL_SUBGRADE`]'s value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subgrade: Option<LayerSection>,
    /// Whether the track's weight (rail, sleepers, ballast bodies) rests on the ballast before the load comes: voids
    /// are measured under it, ballast that cannot pull is preloaded by it (docs/theory.md §18). Default true.
    pub self_weight: bool,
    /// Sleepers that differ from the rest (later entries over earlier ones).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub exceptions: Vec<ExceptionSection>,
}

/// Which sleepers an exception names: one index, or the first and last of a range (inclusive).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "must be one sleeper's index (a whole number from 0) or [first, last]")]
pub enum SleeperIndex {
    /// `index = 12`.
    One(usize),
    /// `index = [12, 14]`.
    Range([usize; 2]),
}

/// How the ballast under an exception's sleepers acts: `law = "linear"` (bonded) or `"tensionless"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BallastLawKind {
    /// Pushes and pulls.
    Linear,
    /// Pushes only.
    Tensionless,
}

/// `[[sleepers.exceptions]]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExceptionSection {
    /// The sleeper(s) (0-based; sleeper i at first + i·spacing).
    pub index: SleeperIndex,
    /// A void under the sleeper at rest (m): the ballast pushes once it has closed (implies tensionless).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap: Option<f64>,
    /// The ballast's law; default linear, tensionless where a gap is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub law: Option<BallastLawKind>,
    /// Coulomb friction at the sleeper–ballast interface (N).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
    /// The pad's stiffness times this.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_scale: Option<f64>,
    /// The ballast's stiffness times this (a soft spot; 0 for none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ballast_scale: Option<f64>,
}

impl ExceptionSection {
    /// The exception (its values checked when the model places the sleepers); the `position`-th in the file.
    fn exception(&self, position: usize) -> Result<SleeperException> {
        let (first, last) = match self.index {
            SleeperIndex::One(i) => (i, i),
            SleeperIndex::Range([a, b]) => (a, b),
        };
        let changes = [self.gap, self.friction, self.pad_scale, self.ballast_scale];
        if self.law.is_none() && changes.iter().all(Option::is_none) {
            return Err(invalid(
                &format!("sleepers.exceptions[{position}]"),
                "an index alone",
                "names sleepers but changes nothing: give gap, law, friction, pad_scale or ballast_scale",
            ));
        }
        let contact = match (self.law, self.gap) {
            (Some(BallastLawKind::Linear), Some(gap)) => {
                return Err(invalid(
                    &format!("sleepers.exceptions[{position}].gap"),
                    gap,
                    "a void needs ballast that cannot pull: leave law out or give law = \"tensionless\"",
                ));
            }
            (None | Some(BallastLawKind::Linear), None) => BallastContact::Bonded,
            (_, gap) => BallastContact::Unilateral { gap: gap.unwrap_or(0.0) },
        };
        let typical = SleeperException::default();
        Ok(SleeperException {
            first,
            last,
            pad_scale: self.pad_scale.unwrap_or(typical.pad_scale),
            ballast_scale: self.ballast_scale.unwrap_or(typical.ballast_scale),
            contact,
            friction: self.friction.unwrap_or(0.0),
        })
    }
}

/// `[sleepers.pad]` or `[sleepers.ballast]`: each key left out takes the layer's typical value.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LayerSection {
    /// k (N/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// c (N·s/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping: Option<f64>,
    /// η (frequency domain only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss_factor: Option<f64>,
}

impl LayerSection {
    /// The layer, what is left out taken from `typical`.
    fn layer(&self, typical: Layer) -> Layer {
        Layer {
            stiffness: self.stiffness.unwrap_or(typical.stiffness),
            damping: self.damping.unwrap_or(typical.damping),
            loss_factor: self.loss_factor.unwrap_or(typical.loss_factor),
        }
    }
}

/// `[sleepers.ballast]`: a layer, and the mass of the ballast body under a rail seat (two layers) if given.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BallastSection {
    /// k (N/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// c (N·s/m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping: Option<f64>,
    /// η (frequency domain only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss_factor: Option<f64>,
    /// m_b (kg per rail seat): the ballast as a body on the subgrade.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
}

impl BallastSection {
    /// The ballast layer, what is left out taken from `typical`.
    fn layer(&self, typical: Layer) -> Layer {
        LayerSection { stiffness: self.stiffness, damping: self.damping, loss_factor: self.loss_factor }.layer(typical)
    }
}

impl Default for SleepersSection {
    fn default() -> Self {
        let s = Sleepers::default();
        Self {
            spacing: s.spacing,
            first: None,
            mass: s.mass,
            pad: LayerSection::default(),
            ballast: BallastSection::default(),
            subgrade: None,
            self_weight: true,
            exceptions: Vec::new(),
        }
    }
}

impl SleepersSection {
    /// A sleeper off the mesh's nodes named by the key the user wrote: the first sleeper's default (spacing/2) off a
    /// node means a bay of an odd number of elements, and the default spacing off the nodes elements that do not
    /// divide it — both `mesh.elements`'s doing.
    pub(crate) fn misfit(&self, error: fem_beam::FemError, mesh: &fem_beam::Mesh) -> crate::StudyError {
        match error {
            fem_beam::FemError::InvalidField { field: "sleepers.first", .. } if self.first.is_none() => {
                let per_bay = self.spacing / (mesh.length / mesh.elements as f64);
                invalid(
                    "mesh.elements",
                    mesh.elements,
                    format!(
                        "puts {per_bay:.3} elements in a sleeper bay of {} m: the first sleeper, at spacing/2 by \
                         default, falls between nodes; give an even number of elements a bay, or sleepers.first",
                        self.spacing
                    ),
                )
            }
            fem_beam::FemError::InvalidField { field: "sleepers.spacing", .. }
                if self.spacing == SleepersSection::default().spacing =>
            {
                invalid(
                    "mesh.elements",
                    mesh.elements,
                    format!(
                        "makes elements of {} m, which do not divide the sleepers' default spacing of {} m: give \
                         elements that put a whole number of them in a bay (four a bay is typical), or \
                         sleepers.spacing",
                        mesh.length / mesh.elements as f64,
                        self.spacing
                    ),
                )
            }
            other => other.into(),
        }
    }

    /// The sleepers, their values checked (the exceptions' indices are, once the model places them on its mesh).
    pub fn sleepers(&self) -> Result<Sleepers> {
        let typical = Sleepers::default();
        let ballast_body = match (self.ballast.mass, &self.subgrade) {
            (Some(mass), subgrade) => {
                Some(BallastBody { mass, subgrade: subgrade.unwrap_or_default().layer(BallastBody::TYPICAL_SUBGRADE) })
            }
            (None, Some(subgrade)) => {
                return Err(invalid(
                    "sleepers.subgrade.stiffness",
                    subgrade.stiffness.unwrap_or(BallastBody::TYPICAL_SUBGRADE.stiffness),
                    "a subgrade carries a ballast body: give its mass as sleepers.ballast.mass (kg per rail seat), \
                     or leave [sleepers.subgrade] out for ballast on rigid ground",
                ));
            }
            (None, None) => None,
        };
        let sleepers = Sleepers {
            spacing: self.spacing,
            first: self.first.unwrap_or(0.5 * self.spacing),
            mass: self.mass,
            pad: self.pad.layer(typical.pad),
            ballast: self.ballast.layer(typical.ballast),
            ballast_body,
            exceptions: self.exceptions.iter().enumerate().map(|(i, e)| e.exception(i)).collect::<Result<_>>()?,
        };
        sleepers.validate()?;
        Ok(sleepers)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A key left out of `[sleepers.ballast]` takes the ballast's typical value, not the pad's.
    #[test]
    fn each_layer_takes_its_own_defaults() {
        let section: SleepersSection =
            toml::from_str("[ballast]\nloss_factor = 1.0\n[pad]\nstiffness = 5e8\n").unwrap();
        let (s, typical) = (section.sleepers().unwrap(), Sleepers::default());
        assert_eq!(s.ballast, Layer { loss_factor: 1.0, ..typical.ballast });
        assert_eq!(s.pad, Layer { stiffness: 5e8, ..typical.pad });
        assert_eq!(s.first, 0.3);
    }

    #[test]
    fn a_ballast_mass_puts_the_ballast_on_the_subgrade() {
        let section: SleepersSection = toml::from_str("[ballast]\nmass = 500.0\n[subgrade]\ndamping = 1e4\n").unwrap();
        let body = section.sleepers().unwrap().ballast_body.unwrap();
        assert_eq!(body.mass, 500.0);
        assert_eq!(body.subgrade, Layer { damping: 1e4, ..BallastBody::TYPICAL_SUBGRADE });
        let back: SleepersSection = toml::from_str(&toml::to_string(&section).unwrap()).unwrap();
        assert_eq!(back, section);
        let lonely: SleepersSection = toml::from_str("[subgrade]\nstiffness = 5e7\n").unwrap();
        let error = lonely.sleepers().unwrap_err().to_string();
        assert!(error.contains("sleepers.subgrade.stiffness = 50000000") && error.contains("sleepers.ballast.mass"));
        let light: SleepersSection = toml::from_str("[ballast]\nmass = -5.0\n").unwrap();
        assert!(light.sleepers().unwrap_err().to_string().contains("sleepers.ballast.mass = -5"));
        assert!(toml::from_str::<SleepersSection>("[pad]\nmass = 5.0\n").is_err(), "a pad has no mass");
    }

    #[test]
    fn exceptions_read_one_index_or_a_range_and_a_gap_means_tensionless() {
        let text = "[[exceptions]]\nindex = 3\ngap = 0.002\n[[exceptions]]\nindex = [5, 7]\nfriction = 500.0\n\
                    ballast_scale = 0.3\n[[exceptions]]\nindex = 9\nlaw = \"tensionless\"\n";
        let section: SleepersSection = toml::from_str(text).unwrap();
        let s = section.sleepers().unwrap();
        assert_eq!((s.exceptions[0].first, s.exceptions[0].last), (3, 3));
        assert_eq!(s.exceptions[0].contact, BallastContact::Unilateral { gap: 0.002 });
        assert_eq!((s.exceptions[1].first, s.exceptions[1].last), (5, 7));
        assert_eq!((s.exceptions[1].friction, s.exceptions[1].ballast_scale), (500.0, 0.3));
        assert_eq!(s.exceptions[1].contact, BallastContact::Bonded);
        assert_eq!(s.exceptions[2].contact, BallastContact::Unilateral { gap: 0.0 });
        let linear_gap: SleepersSection =
            toml::from_str("[[exceptions]]\nindex = 1\nlaw = \"linear\"\ngap = 0.001\n").unwrap();
        let error = linear_gap.sleepers().unwrap_err().to_string();
        assert!(error.contains("sleepers.exceptions[0].gap = 0.001"), "{error}");
        assert!(toml::from_str::<SleepersSection>("[[exceptions]]\nindex = 1\nvoid = 0.1\n").is_err());
        // Written back as read.
        let back: SleepersSection = toml::from_str(&toml::to_string(&section).unwrap()).unwrap();
        assert_eq!(back, section);
    }

    /// What a new user wrote wrong, named as written: an index that is not one whole number or a pair, an exception
    /// that changes nothing, a loss factor no solid has, a friction force of a unit slip, a mesh whose bays put the
    /// default first sleeper between nodes (it named `sleepers.first = 0.3`, a default the user never wrote).
    #[test]
    fn bad_sleeper_keys_are_named_as_written() {
        for index in ["-1", "1.5", "[50]", "[40, 45, 50]"] {
            let error = toml::from_str::<SleepersSection>(&format!("[[exceptions]]\nindex = {index}\ngap = 0.001\n"))
                .unwrap_err()
                .to_string();
            assert!(error.contains("one sleeper's index") && error.contains("[first, last]"), "{index}: {error}");
        }
        let error = |text: &str| toml::from_str::<SleepersSection>(text).unwrap().sleepers().unwrap_err().to_string();
        assert!(error("[[exceptions]]\nindex = 3\n").contains("sleepers.exceptions[0] = an index alone"));
        assert!(error("[pad]\nloss_factor = 5.0\n").contains("sleepers.pad.loss_factor = 5"));
        let model = |text: &str| crate::Scenario::from_toml(text, "t.toml").unwrap().model().map(|_| ());
        let friction = model(
            "[foundation]\nstiffness = 0.0\n[mesh]\nlength = 6.0\nelements = 40\n[sleepers]\n\
             [[sleepers.exceptions]]\nindex = 2\nfriction = 1e12\n",
        );
        assert!(friction.unwrap_err().to_string().contains("sleepers.exceptions[0].friction = 1000000000000"));
        let odd = model("[foundation]\nstiffness = 0.0\n[mesh]\nlength = 6.0\nelements = 30\n[sleepers]\n");
        let odd = odd.unwrap_err().to_string();
        assert!(odd.contains("mesh.elements = 30") && odd.contains("3.000 elements in a sleeper bay"), "{odd}");
        let misfit =
            model("[foundation]\nstiffness = 0.0\n[mesh]\nlength = 6.0\nelements = 40\n[sleepers]\nspacing = 0.5\n");
        assert!(misfit.unwrap_err().to_string().contains("sleepers.spacing = 0.5"));
    }

    /// The track has one weight: a tensionless soil and tensionless sleepers must agree on keeping it (solved by
    /// projection: the soil's rows beside sleepers are refused under `auto`).
    #[test]
    fn soil_and_sleepers_share_one_weight() {
        let text = |weight: bool| {
            format!(
                "[foundation]\nlaw = \"tensionless\"\n[sleepers]\nself_weight = {weight}\n[[sleepers.exceptions]]\n\
                 index = [0, 9]\nlaw = \"tensionless\"\n[mesh]\nlength = 6.0\nelements = 40\n\
                 [integration]\nsolver = \"projection\"\n"
            )
        };
        assert!(crate::Scenario::from_toml(&text(true), "t.toml").unwrap().build().is_ok());
        let error = crate::Scenario::from_toml(&text(false), "t.toml").unwrap().build().unwrap_err().to_string();
        assert!(error.contains("sleepers.self_weight = false") && error.contains("foundation.self_weight"), "{error}");
    }
}
