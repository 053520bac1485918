//! `[ground]`: a layered visco-elastic half-space under the track, in place of the Winkler `[foundation]`
//! (docs/theory.md §19). The track above it is the scenario's `[beam]`, a composite track-and-embankment beam.
//!
//! ```toml
//! [ground]
//! width = 3.0                      # 2b (m): the strip the track loads
//! [[ground.layers]]                # from the surface down
//! thickness = 1.1                  # m
//! shear_wave_speed = 72.0          # C_s (m/s)
//! compression_wave_speed = 500.0   # C_p (m/s), or poisson_ratio (not both)
//! density = 1500.0                 # kg/m³
//! damping_ratio = 0.04             # hysteretic ξ
//! [ground.half_space]              # required
//! shear_wave_speed = 100.0
//! poisson_ratio = 0.49
//! density = 1475.0
//! damping_ratio = 0.05
//! ```

use crate::error::{Result, invalid};
use analytic::ground::{GroundProfile, SoilLayer, SoilMaterial, StripGround};
use serde::{Deserialize, Serialize};

/// The widest strip (m) a track is taken to load.
pub const MAX_WIDTH: f64 = 100.0;

/// `[ground]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GroundSection {
    /// 2b (m): the width of the strip the track loads (required).
    pub width: Option<f64>,
    /// The layers from the surface down (none: a homogeneous half-space).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub layers: Vec<SoilSection>,
    /// What lies below the layers (required).
    pub half_space: Option<SoilSection>,
}

/// One `[[ground.layers]]` entry or `[ground.half_space]`: a material, and a layer's thickness.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SoilSection {
    /// h (m): a layer's (required there), never the half-space's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// C_s (m/s), required.
    pub shear_wave_speed: Option<f64>,
    /// C_p (m/s), or `poisson_ratio` (one of them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compression_wave_speed: Option<f64>,
    /// ν ∈ (−1, ½), or `compression_wave_speed` (one of them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub poisson_ratio: Option<f64>,
    /// ρ (kg/m³), required.
    pub density: Option<f64>,
    /// ξ ∈ [0, ½): hysteretic damping, μ* = ρC_s²(1 + 2iξ sgn ω). Default 0.
    #[serde(default)]
    pub damping_ratio: f64,
}

impl GroundSection {
    /// The strip on its layered ground, every value checked and named by its key.
    pub fn strip(&self) -> Result<StripGround> {
        let width =
            self.width.ok_or_else(|| missing("ground.width", "the width 2b of the strip the track loads (m)"))?;
        if width > MAX_WIDTH {
            return Err(invalid(
                "ground.width",
                width,
                format!(
                    "must be at most {MAX_WIDTH} m: a track and its embankment load a strip 2–15 m wide; a wider one \
                     is no track (its strip integrals then span the whole wave and no longer converge in time)"
                ),
            ));
        }
        let layers = self
            .layers
            .iter()
            .enumerate()
            .map(|(i, layer)| {
                let path = format!("ground.layers[{i}]");
                let thickness = layer
                    .thickness
                    .ok_or_else(|| missing(&format!("{path}.thickness"), "every layer needs its thickness (m)"))?;
                Ok(SoilLayer { thickness, material: layer.material(&path)? })
            })
            .collect::<Result<Vec<_>>>()?;
        let below = self.half_space.as_ref().ok_or_else(|| {
            missing("ground.half_space", "a [ground.half_space] table: what lies below the last layer")
        })?;
        if let Some(h) = below.thickness {
            return Err(invalid("ground.half_space.thickness", h, "a half-space has no thickness: remove the key"));
        }
        let half_space = below.material("ground.half_space")?;
        let strip = StripGround { width, profile: GroundProfile { layers, half_space } };
        strip.validate()?;
        Ok(strip)
    }
}

impl SoilSection {
    /// The material, C_p from ν where ν is given: C_p = C_s·√(2(1 − ν)/(1 − 2ν)).
    fn material(&self, path: &str) -> Result<SoilMaterial> {
        let shear_wave_speed = self
            .shear_wave_speed
            .ok_or_else(|| missing(&format!("{path}.shear_wave_speed"), "C_s (m/s) of every material"))?;
        let density = self.density.ok_or_else(|| missing(&format!("{path}.density"), "ρ (kg/m³) of every material"))?;
        let compression_wave_speed = match (self.compression_wave_speed, self.poisson_ratio) {
            (Some(_), Some(nu)) => {
                return Err(invalid(
                    &format!("{path}.poisson_ratio"),
                    nu,
                    "give compression_wave_speed or poisson_ratio, not both",
                ));
            }
            (Some(cp), None) => cp,
            (None, Some(nu)) => {
                if !(nu.is_finite() && nu > -1.0 && nu < 0.5) {
                    return Err(invalid(&format!("{path}.poisson_ratio"), nu, "must lie in (−1, 0.5)"));
                }
                shear_wave_speed * (2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)).sqrt()
            }
            (None, None) => {
                return Err(missing(
                    &format!("{path}.compression_wave_speed"),
                    "C_p (m/s) or poisson_ratio of every material",
                ));
            }
        };
        Ok(SoilMaterial { shear_wave_speed, compression_wave_speed, density, damping_ratio: self.damping_ratio })
    }
}

/// What stands on a `[ground]`.
#[derive(Debug, Clone, PartialEq)]
pub enum GroundTrack {
    /// The `[beam]` is the composite track-and-embankment beam (whole axles by default).
    Composite,
    /// The `[beam]` is one rail on its pads, sleepers and ballast (per rail seat) over an embankment under both rails
    /// (half an axle by default).
    RailOnEmbankment {
        /// Pads, sleepers and ballast.
        sleepers: fem_beam::Sleepers,
        /// The embankment beam.
        embankment: analytic::ground::Embankment,
        /// How the ballast holds the sleepers on it.
        interface: Interface,
    },
}

/// The ballast between the sleepers and the embankment of the two-beam track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Interface {
    /// It pulls as it pushes: the track is linear.
    Bonded,
    /// It only pushes (docs/theory.md §19, "Lift-off on the ground").
    Tensionless {
        /// d₀ = −(ρA_r a + m_s) g / k_b ≤ 0: the sleepers' deflection less the embankment's under the rail's and the
        /// sleepers' weight (m; 0 where `[sleepers] self_weight = false`).
        preload: f64,
    },
}

impl crate::Scenario {
    /// The scenario's beam, its `[ground]`'s strip and what the beam is, checked: an Euler–Bernoulli beam, the ground
    /// in place of a `[foundation]`; the beam the composite track-and-embankment beam, or one rail on `[sleepers]`
    /// over an `[embankment]` (the two-beam track; the sleepers spread as their long-wave twin, so without
    /// exceptions).
    pub fn ground_track(&self) -> Result<(fem_beam::Beam, analytic::ground::StripGround, GroundTrack)> {
        if let Some(section) = &self.sleepers
            && self.embankment.is_some()
            && !section.exceptions.is_empty()
        {
            return Err(invalid(
                "sleepers.exceptions",
                format!("{} given", section.exceptions.len()),
                "on a [ground] the steady wave and the receptance spread the sleepers as their long-wave twin, which \
                 has no voided, tensionless, frictional or rescaled sleeper (a run in time, `frictrack run`, takes \
                 them)",
            ));
        }
        self.track_and_ground()
    }

    /// [`Self::ground_track`] with the sleepers' exceptions kept (a run in time takes them; the long-wave twin leaves
    /// them out).
    pub(crate) fn track_and_ground(&self) -> Result<(fem_beam::Beam, analytic::ground::StripGround, GroundTrack)> {
        self.refuse_accuracy()?;
        let Some(ground) = &self.ground else {
            return Err(missing("ground", "a [ground] section: the layered ground under the track"));
        };
        if self.foundation != crate::FoundationSection::default() {
            return Err(foundation_beside_ground());
        }
        self.beam.validate()?;
        if self.beam.shear_stiffness().is_some() {
            return Err(invalid(
                "beam.theory",
                "timoshenko",
                "must be euler-bernoulli on a [ground]: the composite track-and-embankment beam, or the rail",
            ));
        }
        let track = match (&self.sleepers, &self.embankment) {
            (None, None) => GroundTrack::Composite,
            (Some(section), Some(embankment)) => {
                if let Some(mass) = section.ballast.mass {
                    return Err(invalid(
                        "sleepers.ballast.mass",
                        mass,
                        "on a [ground] the ballast is the layer between the sleepers and the [embankment] (which is \
                         the mass below it): leave the ballast body out",
                    ));
                }
                let sleepers = section.sleepers()?;
                let interface = match embankment.interface {
                    crate::embankment::InterfaceKind::Bonded => Interface::Bonded,
                    crate::embankment::InterfaceKind::Tensionless => {
                        let weight = self.beam.mass_per_length() * sleepers.spacing + sleepers.mass;
                        let preload = if section.self_weight {
                            -weight * fem_beam::GRAVITY / sleepers.ballast.stiffness
                        } else {
                            0.0
                        };
                        Interface::Tensionless { preload }
                    }
                };
                GroundTrack::RailOnEmbankment { sleepers, embankment: embankment.embankment()?, interface }
            }
            (Some(_), None) => {
                return Err(missing(
                    "embankment",
                    "the embankment beam the sleepers' ballast rests on, under both rails: bending_stiffness (N·m²), \
                     mass_per_length (kg/m)",
                ));
            }
            (None, Some(_)) => {
                return Err(invalid(
                    "embankment",
                    "given",
                    "an [embankment] carries a rail on [sleepers]: give them, or fold the embankment into the \
                     composite [beam]",
                ));
            }
        };
        Ok((self.beam, ground.strip()?, track))
    }

    /// The axles the composite beam on the `[ground]` carries, a train in its frame (offsets behind the first axle,
    /// forces downward, N): the `[load]` train, whole axles unless `load.carries` says otherwise (the composite beam
    /// is the whole track, both rails), or the single `load.force` at the head. Refused by key: load patches, a
    /// `[vehicle]` and a changing speed (the moving frame's steady state holds for axles at one constant speed).
    pub fn axles_on_the_ground(&self) -> Result<fem_beam::Train> {
        self.load.refuse_changing_speed("the steady wave on the ground")?;
        if self.vehicle.is_some() {
            return Err(invalid(
                "vehicle",
                "given",
                "on a [ground] the steady wave takes moving forces: drop [vehicle] (the train's axles, or the single \
                 load, are used)",
            ));
        }
        let Some(train) = crate::trains::resolve(&self.load)? else {
            return Ok(fem_beam::Train::single(self.load.force));
        };
        if !train.patches.is_empty() {
            return Err(invalid(
                "load.patches",
                train.patches.len(),
                "on a [ground] the steady wave takes axles only: give the train as axles",
            ));
        }
        Ok(self.on_the_beam(train))
    }

    /// The refusal of a sweep on a `[ground]` (key `ground`): a run in time takes a foundation fitted at one speed.
    pub fn sweep_on_the_ground(value: impl std::fmt::Display) -> crate::StudyError {
        invalid(
            "ground",
            value,
            "a sweep over speeds on a [ground] would run every speed on one speed's fitted foundation: run each speed \
             alone (`frictrack run --speed V`), or take the exact linear wave over speeds (`frictrack stationary \
             --speeds A:B:STEP`) and the critical speed (`frictrack ground`)",
        )
    }

    /// Refuse a sweep of this scenario where it has a `[ground]` (see [`Self::sweep_on_the_ground`]).
    pub fn refuse_sweep_on_the_ground(&self) -> Result<()> {
        match self.ground {
            Some(_) => Err(Self::sweep_on_the_ground("given")),
            None => Ok(()),
        }
    }

    /// This scenario for a run in time: its `[ground]` replaced by a foundation fitted to the strip's k_eq along the
    /// load's line ω = kv at `load.speed`, and the fit with its wave's error against the exact moving-frame solution.
    /// Under the composite beam (`GroundedBeam::fitted_foundation`) a spring and a dashpot under the beam, the ground's
    /// co-vibrating mass added to the beam's; under the two-beam track (`TrackOnEmbankment::fitted_ground`, fitted to
    /// what the rail feels) the `[foundation]` under the `[embankment]`, the mass added to the embankment's, whose
    /// loss factor the fitted dashpot takes over. The train is carried as on the ground (whole axles on the composite
    /// beam, half on a rail, unless `load.carries` says otherwise); a changing speed is refused (the fit holds at one
    /// speed).
    pub fn on_fitted_foundation(&self) -> Result<(Self, analytic::ground::FittedFoundation)> {
        let (beam, strip, track) = self.track_and_ground()?;
        self.load.refuse_changing_speed("a foundation fitted to the ground")?;
        let speed = self.load.speed;
        if !(speed.is_finite() && speed >= 0.0) {
            return Err(invalid("load.speed", speed, "must be finite and ≥ 0 (m/s)"));
        }
        Self::check_speed_on(&strip, "load.speed", speed)?;
        let mut fitted = self.clone();
        fitted.ground = None;
        fitted.load.carries = Some(self.axle_share());
        if track == GroundTrack::Composite {
            fitted.fastest_ground_wave = Some(fastest_wave(&strip));
        }
        if let GroundTrack::RailOnEmbankment { interface: Interface::Tensionless { .. }, .. } = track {
            return Err(Self::tensionless_interface_in_time());
        }
        // Every key of the run checked before the fit (seconds on a soft site): the run on a stand-in spring in the
        // fit's place, built and dropped — a bad sleeper spacing is refused at once, not after the fit.
        let stand_in = crate::FoundationSection { stiffness: 1e6, damping: Some(0.0), ..fitted.foundation.clone() };
        Self { foundation: stand_in, ..fitted.clone() }.build()?;
        let fit = match track {
            GroundTrack::Composite => {
                let fit = analytic::ground::GroundedBeam::new(&beam, &strip)?.fitted_foundation(speed)?;
                fitted.beam.density += fit.co_vibrating_mass / beam.area;
                fit
            }
            GroundTrack::RailOnEmbankment { sleepers, embankment, .. } => {
                let twin = fem_beam::Sleepers { exceptions: Vec::new(), ..sleepers };
                let track = analytic::ground::TrackOnEmbankment { sleepers: &twin, embankment, ground: &strip };
                let fit = track.fitted_ground(&beam, speed)?;
                if let Some(section) = fitted.embankment.as_mut() {
                    section.mass_per_length += fit.co_vibrating_mass;
                    section.loss_factor = 0.0;
                }
                fit
            }
        };
        fitted.foundation.stiffness = fit.stiffness;
        fitted.foundation.damping = Some(fit.damping);
        Ok((fitted, fit))
    }
}

impl crate::Scenario {
    /// Refuse, by `key`, any of `speeds` (m/s) on this scenario's ground that no load can mean: at or above the
    /// ground's fastest wave ([`fastest_wave`]). Checked before any spectrum or fit is computed.
    pub fn check_speeds_on_the_ground(&self, key: &str, speeds: &[f64]) -> Result<()> {
        let (_, strip, _) = self.track_and_ground()?;
        speeds.iter().try_for_each(|&speed| Self::check_speed_on(&strip, key, speed))
    }

    fn check_speed_on(strip: &StripGround, key: &str, speed: f64) -> Result<()> {
        let fastest = fastest_wave(strip);
        if speed >= fastest {
            return Err(invalid(
                key,
                speed,
                format!(
                    "must be below the ground's fastest wave, its largest compression wave speed C_p = {fastest:.0} \
                     m/s: faster than every wave of the model no train is meant (railway speeds are below 200 m/s)"
                ),
            ));
        }
        Ok(())
    }
}

/// The fastest wave of `strip`'s ground (m/s): the largest compression wave speed C_p of its layers and half-space.
pub fn fastest_wave(strip: &StripGround) -> f64 {
    strip.profile.materials().map(|m| m.compression_wave_speed).fold(0.0, f64::max)
}

/// The refusal, by key, of a `[foundation]` table written beside a `[ground]` in the scenario's `text` — even one
/// that repeats the defaults, which [`crate::Scenario`] could not tell from no table at all: the ground replaces the
/// Winkler foundation, so a table there would be ignored.
pub(crate) fn refuse_tables_beside_ground(text: &str) -> Result<()> {
    let Ok(table) = text.parse::<toml::Table>() else { return Ok(()) };
    if table.contains_key("foundation") {
        return Err(foundation_beside_ground());
    }
    Ok(())
}

/// A `[foundation]` given beside a `[ground]`, refused by its key.
fn foundation_beside_ground() -> crate::StudyError {
    invalid("foundation", "given", "a [ground] replaces the Winkler [foundation]: remove one of the two tables")
}

/// A required key that is not there.
fn missing(path: &str, what: &str) -> crate::StudyError {
    invalid(path, "missing", format!("required: {what}"))
}

#[cfg(test)]
mod tests {
    use crate::Scenario;

    const SITE: &str = r#"
[ground]
width = 3.0
[[ground.layers]]
thickness = 1.1
shear_wave_speed = 72.0
compression_wave_speed = 500.0
density = 1500.0
damping_ratio = 0.04
[ground.half_space]
shear_wave_speed = 100.0
poisson_ratio = 0.4
density = 1475.0
damping_ratio = 0.05
"#;

    fn refused(text: &str) -> String {
        let scenario = Scenario::from_toml(text, "site.toml").unwrap();
        scenario.ground.as_ref().unwrap().strip().unwrap_err().to_string()
    }

    /// A site reads into its strip; ν = 0.4 gives C_p = C_s·√6.
    #[test]
    fn a_site_reads_into_its_strip() {
        let scenario = Scenario::from_toml(SITE, "site.toml").unwrap();
        let strip = scenario.ground.unwrap().strip().unwrap();
        assert_eq!((strip.width, strip.profile.layers.len()), (3.0, 1));
        let cp = strip.profile.half_space.compression_wave_speed;
        assert!((cp - 100.0 * 6f64.sqrt()).abs() < 1e-12, "{cp}");
    }

    /// Bad profiles are refused by key: a layer without thickness, C_p ≤ C_s, a Poisson ratio ≥ ½, ξ < 0, no
    /// half-space, both C_p and ν, a thickness under the half-space, no width, thousands of layers.
    #[test]
    fn bad_profiles_are_refused_by_key() {
        let cases = [
            ("thickness = 1.1\n", "", "ground.layers[0].thickness = missing"),
            (
                "compression_wave_speed = 500.0",
                "compression_wave_speed = 60.0",
                "ground.layers[0].compression_wave_speed = 60",
            ),
            ("poisson_ratio = 0.4", "poisson_ratio = 0.5", "ground.half_space.poisson_ratio = 0.5"),
            ("damping_ratio = 0.04", "damping_ratio = -0.01", "ground.layers[0].damping_ratio = -0.01"),
            ("[ground.half_space]", "[ground.not_half_space]", "unknown field `not_half_space`"),
            ("poisson_ratio = 0.4", "poisson_ratio = 0.4\ncompression_wave_speed = 300.0", "not both"),
            ("poisson_ratio = 0.4", "poisson_ratio = 0.4\nthickness = 3.0", "ground.half_space.thickness = 3"),
            ("width = 3.0", "", "ground.width = missing"),
        ];
        for (from, to, expected) in cases {
            let text = SITE.replacen(from, to, 1);
            let message = match Scenario::from_toml(&text, "site.toml") {
                Ok(scenario) => scenario.ground.as_ref().unwrap().strip().unwrap_err().to_string(),
                Err(e) => e.to_string(),
            };
            assert!(message.contains(expected), "{from} → {to}: {message}");
        }
        let no_half_space = SITE.split("[ground.half_space]").next().unwrap();
        assert!(refused(no_half_space).contains("ground.half_space = missing"));
        let layer =
            "[[ground.layers]]\nthickness = 0.1\nshear_wave_speed = 80.0\npoisson_ratio = 0.3\ndensity = 1800.0\n";
        let many = format!(
            "[ground]\nwidth = 3.0\n{}[ground.half_space]\nshear_wave_speed = 90.0\npoisson_ratio = 0.3\ndensity = 1800.0\n",
            layer.repeat(3000)
        );
        assert!(refused(&many).contains("at most 200 layers"), "{}", refused(&many));
    }
}
