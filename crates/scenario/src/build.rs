//! From a scenario's sections to what the stepper runs: the beam model, the friction sections and the run
//! settings, every value checked on the way and errors renamed to their dotted path in the file.

use super::{
    Case, DistributedSection, FoundationLawKind, QuadratureKind, Scenario, SweepSection, VehicleSection, fnv1a,
};
use crate::error::{Result, StudyError, invalid};
use crate::number::number;
use fem_beam::{AbsorbingZones, BeamModel, Foundation, FoundationLaw, Mesh};
use nscd::SolverSettings;
use track::PlacedInteractions;
use track::simulation::{IntegrationSettings, MovingLoadSettings, RecordSettings, SpeedLimit};
use track::{BallastOnBeam, Devices, DistributedFriction, FoundationSections, Quadrature};
use track::{InitialState, Load, RunSettings};

fn finite_positive(path: &str, value: f64, unit: &str) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(invalid(path, value, format!("must be finite and > 0 ({unit})")))
    }
}

fn finite_non_negative(path: &str, value: f64, unit: &str) -> Result<()> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(invalid(path, value, format!("must be finite and ≥ 0 ({unit})")))
    }
}

impl Scenario {
    /// Check every value that the lower layers do not already name by its path.
    pub fn validate(&self) -> Result<()> {
        match &self.ground {
            Some(_) => self.track_and_ground().map(|_| ()),
            None => self.build().map(|_| ()),
        }
    }

    /// The assembled beam model (beam, mesh, foundation with its damping and absorbing zones, supports), checked;
    /// refuses degenerate meshes and mechanisms ([`crate::diagnostics::refuse_degenerate`]). On a `[ground]`, the
    /// model on the foundation fitted to it at `load.speed` ([`Scenario::on_fitted_foundation`]).
    pub fn model(&self) -> Result<BeamModel> {
        self.refuse_accuracy()?;
        if self.ground.is_some() {
            return self.on_fitted_foundation()?.0.model();
        }
        if let Some(embankment) = &self.embankment {
            return self.two_beam_model(embankment);
        }
        let beam = self.beam;
        beam.validate()?;
        let mesh = Mesh::new(self.mesh.length, self.mesh.elements)?;
        let foundation = self.soil(&beam)?;
        let supports = self.supports;
        // On sleepers the zones' dashpots are scaled to the support the rail feels in the long wave: the soil plus
        // the sleepers' equivalent k_eq (docs/theory.md §18).
        let support = Foundation { stiffness: foundation.stiffness + self.sleepers_equivalent()?, ..foundation };
        let damping = self.graded_damping(&mesh, foundation.damping, support.critical_damping(&beam))?;
        let mut model = BeamModel::with_element_damping(beam, foundation, mesh, supports, damping)?;
        if let Some(sleepers) = &self.sleepers {
            model = model.with_sleepers(sleepers.sleepers()?).map_err(|e| sleepers.misfit(e, &self.mesh))?;
        }
        if let Some(rayleigh) = &self.damping.rayleigh {
            model = model.with_rayleigh(rayleigh.rayleigh()?)?;
        }
        crate::diagnostics::refuse_degenerate(&model)?;
        Ok(model)
    }

    /// The sleepers' equivalent continuous support k_eq (N/m², 0 without sleepers), their values checked.
    fn sleepers_equivalent(&self) -> Result<f64> {
        let Some(section) = &self.sleepers else { return Ok(0.0) };
        Ok(section.sleepers()?.equivalent_stiffness())
    }

    /// The `[foundation]`'s soil, its values checked: its law, k_f, and c_f given or as a ratio of the critical
    /// damping of `beam` on it.
    pub(crate) fn soil(&self, beam: &fem_beam::Beam) -> Result<Foundation> {
        let f = &self.foundation;
        let law = self.foundation_law()?;
        let mut foundation = Foundation { stiffness: f.stiffness, damping: 0.0, law, loss_factor: f.loss_factor };
        foundation.validate()?;
        match (f.damping, f.damping_ratio) {
            (Some(_), Some(ratio)) => {
                return Err(invalid(
                    "foundation.damping_ratio",
                    ratio,
                    "give foundation.damping or damping_ratio, not both",
                ));
            }
            (Some(c), None) => {
                finite_non_negative("foundation.damping", c, "N·s/m²")?;
                foundation.damping = c;
            }
            (None, Some(ratio)) => {
                finite_non_negative("foundation.damping_ratio", ratio, "ratio of c_cr")?;
                foundation = foundation.with_damping_ratio(ratio, beam)?;
            }
            (None, None) => {}
        }
        Ok(foundation)
    }

    /// The soil's dashpot per element (N·s/m²): `base` throughout, graded up to `foundation.absorbing_zones`'
    /// `peak_ratio` × `critical` (N·s/m²) at the ends where it has them.
    pub(crate) fn graded_damping(&self, mesh: &Mesh, base: f64, critical: f64) -> Result<Vec<f64>> {
        let Some(z) = &self.foundation.absorbing_zones else { return Ok(vec![base; mesh.elements]) };
        finite_positive("foundation.absorbing_zones.length", z.length, "m")?;
        finite_non_negative("foundation.absorbing_zones.peak_ratio", z.peak_ratio, "ratio of c_cr")?;
        let zones = AbsorbingZones { length: z.length, peak_damping: z.peak_ratio * critical };
        zones.element_damping(mesh, base).map_err(|e| under("foundation", e.into()))
    }

    /// The soil's law from `foundation.law` and `tension_ratio` (given for a bilinear soil only).
    fn foundation_law(&self) -> Result<FoundationLaw> {
        let f = &self.foundation;
        match (f.law, f.tension_ratio) {
            (FoundationLawKind::Linear, None) => Ok(FoundationLaw::Linear),
            (FoundationLawKind::Tensionless, None) => Ok(FoundationLaw::Tensionless),
            (FoundationLawKind::Bilinear, Some(tension_ratio)) => Ok(FoundationLaw::Bilinear { tension_ratio }),
            (FoundationLawKind::Bilinear, None) => Err(invalid(
                "foundation.tension_ratio",
                "missing",
                "a bilinear soil needs α = k_t/k_c ∈ [0, 1], its stiffness in tension over that in compression",
            )),
            (_, Some(ratio)) => Err(invalid(
                "foundation.tension_ratio",
                ratio,
                "is the bilinear soil's: give it with law = \"bilinear\" only",
            )),
        }
    }

    /// Everything placed on `model`: the friction sections, then the soil's and the sleepers' unilateral laws (a
    /// window of the track, or the beam), settled together under the track's weight where it is kept
    /// (`foundation.self_weight`, `sleepers.self_weight`).
    pub fn placed_on(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        self.refuse_rail_rows_on_sleepers(model)?;
        let mut interactions = self.interactions(model)?;
        let mut springs = self.foundation_sections(model)?;
        springs.extend(track::sleeper_layout::sleeper_interactions(model));
        if self.keeps_weight(model)? && springs.has_springs() {
            springs = track::unilateral_statics::settle(model, springs, &model.self_weight()?)?.0;
        }
        interactions.extend(springs);
        Ok(interactions)
    }

    /// Refuse, by key, the homotopy on a track of sleepers with sections on its rail (ballast friction, a nonlinear
    /// soil): their rows span the sleeper's DOF between two rail nodes (w_i, θ_i, z_i, w_{i+1}, θ_{i+1}: four entries
    /// over five DOFs), which the homotopy's banded matrices do not take; the interior point (what `auto` picks),
    /// projection and Clarabel do.
    fn refuse_rail_rows_on_sleepers(&self, model: &BeamModel) -> Result<()> {
        if model.sleepers().is_none() || self.integration.solver != nscd::SolverKind::Homotopy {
            return Ok(());
        }
        let (key, value) = match (&self.friction.distributed, self.foundation.law) {
            (Some(d), _) => ("friction.distributed.force_per_length", format!("{}", d.force_per_length)),
            (None, FoundationLawKind::Linear) => return Ok(()),
            (None, law) => ("foundation.law", format!("{law:?}").to_lowercase()),
        };
        Err(invalid(
            key,
            value,
            "on sleepers its sections act on the rail between the sleepers, rows that span a sleeper's DOF, which \
             integration.solver = \"homotopy\" does not take; choose \"auto\" (the interior point takes them)",
        ))
    }

    /// Whether the track's weight rests on unilateral supports before the load comes: a nonlinear soil's
    /// `foundation.self_weight`, unilateral sleepers' `sleepers.self_weight` — one weight, so where both are there
    /// they must agree.
    fn keeps_weight(&self, model: &BeamModel) -> Result<bool> {
        let soil = (!model.foundation().law.is_linear()).then_some(self.foundation.self_weight);
        let sleepers = self
            .sleepers
            .as_ref()
            .filter(|_| model.sleepers().is_some_and(|(s, _)| s.has_unilateral_ballast()))
            .map(|s| s.self_weight);
        match (soil, sleepers) {
            (Some(a), Some(b)) if a != b => Err(invalid(
                "sleepers.self_weight",
                b,
                format!(
                    "differs from foundation.self_weight = {a}: the track has one weight, resting on its soil and \
                     its sleepers' ballast alike; give both the same value"
                ),
            )),
            (a, b) => Ok(a.or(b).unwrap_or(false)),
        }
    }

    /// Refuse a weightless rail on a tensionless soil with a free end: with the load near that end the rail bears on
    /// a few sections at the load and the rest of it, held by nothing, turns about them like a lever — no bounded
    /// static state (the static envelope of the free–free reference track reached 1.8e9 m; with its weight 4.3 w₀,
    /// pinned 1.08 w₀). A bilinear soil holds the rail in tension and is not refused.
    fn refuse_a_lever(&self, model: &BeamModel) -> Result<()> {
        let f = &self.foundation;
        let free_end = [self.supports.left, self.supports.right].contains(&fem_beam::Support::Free);
        if f.law == FoundationLawKind::Tensionless && !f.self_weight && free_end && model.foundation().stiffness > 0.0 {
            return Err(invalid(
                "foundation.self_weight",
                false,
                "with a tensionless soil and a free end the rail has no bounded static state: under a load near that \
                 end it tips about the few sections it bears on, the rest held by nothing; give the rail its weight \
                 (self_weight = true), pin or clamp the ends, or use law = \"bilinear\"",
            ));
        }
        Ok(())
    }

    /// The sections of a nonlinear soil (none for a linear one, which K holds whole).
    fn foundation_sections(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        let f = &self.foundation;
        if f.law == FoundationLawKind::Linear && (!f.self_weight || f.subdivisions != 1) {
            let key = if f.self_weight { "foundation.subdivisions" } else { "foundation.self_weight" };
            return Err(invalid(
                key,
                "given",
                "belongs to a tensionless or bilinear soil: a linear one needs no soil sections and no settlement",
            ));
        }
        if f.is_nonlinear_without_soil() {
            // No soil (said by the diagnostics): sections of zero stiffness would be stops that hold nothing.
            return Ok(PlacedInteractions::new());
        }
        // Unsettled: placed_on settles the soil with the sleepers under the one weight.
        let sections =
            FoundationSections { subdivisions: f.subdivisions, self_weight: false, ..FoundationSections::default() };
        Ok(sections.interactions(model)?)
    }

    /// Build the model, contact set and run settings, checking every value on the way; on a `[ground]`, on the
    /// foundation fitted to it at `load.speed`, the fit kept in [`Case::ground_fit`].
    pub fn build(&self) -> Result<Case> {
        if self.ground.is_some() {
            let (fitted, fit) = self.on_fitted_foundation()?;
            return Ok(Case { ground_fit: Some(fit), ..fitted.build()? });
        }
        let model = self.model()?;
        self.refuse_a_lever(&model)?;
        let interactions = self.placed_on(&model)?;
        finite_non_negative("load.force", self.load.force, "N")?;
        finite_positive("load.speed", self.load.speed, "m/s")?;
        if let Some([a, b]) = self.output.extremes_window {
            let length = model.mesh().length;
            if !(a.is_finite() && b.is_finite() && 0.0 <= a && a < b && b <= length) {
                return Err(invalid(
                    "output.extremes_window",
                    format!("[{a}, {b}]"),
                    format!("needs load positions 0 ≤ A < B ≤ L = {length} m"),
                ));
            }
        }
        let settings = self.run_settings(self.load.speed)?;
        settings.validate(&model)?;
        if let Some(sweep) = &self.sweep {
            sweep.validate("sweep")?;
        }
        let critical_speed = crate::speeds::SpeedScale::of(self)?.critical_speed;
        Ok(Case { model, interactions, settings, critical_speed, fingerprint: self.fingerprint(), ground_fit: None })
    }

    /// See [`Case::fingerprint`].
    pub fn fingerprint(&self) -> u64 {
        let mut physics = self.clone();
        physics.title.clear();
        physics.load.speed = 0.0;
        physics.output.sections.clear();
        physics.output.snapshot_times.clear();
        physics.output.snapshot_load_positions.clear();
        physics.sweep = None;
        fnv1a(
            format!("frictrack {} results {RESULT_FORMAT}\n{}", env!("CARGO_PKG_VERSION"), physics.to_toml())
                .as_bytes(),
        )
    }

    /// The scenario's beam, foundation (with its damping), mesh, supports and load force as the closed-form
    /// reference case (`frictrack reference` and `analytic` on a scenario); on sleepers their long-wave continuous
    /// twin ([`Scenario::uniform_support`]).
    pub fn reference_case(&self) -> Result<analytic::reference::ReferenceCase> {
        if self.ground.is_some() {
            // The closed forms are of a beam on a Winkler spring; a spring fitted to the ground at one speed would
            // answer another speed (and the static load) wrongly without saying so.
            return Err(invalid(
                "ground",
                "given",
                "the closed forms take a Winkler [foundation], not a layered [ground]: for the exact steady wave on \
                 the ground use `frictrack stationary SCENARIO --speed V`, for its critical speed `frictrack ground \
                 SCENARIO`",
            ));
        }
        finite_non_negative("load.force", self.load.force, "N")?;
        let model = self.uniform_support("the closed form")?.0.model()?;
        Ok(analytic::reference::ReferenceCase {
            beam: *model.beam(),
            foundation: *model.foundation(),
            mesh: *model.mesh(),
            supports: model.supports(),
            load: self.load.force,
        })
    }

    /// The speeds of a sweep: `[sweep]` if given, else the default range around the critical speed.
    pub fn speed_range(&self) -> Result<SweepSection> {
        match &self.sweep {
            Some(sweep) => Ok(sweep.clone()),
            None => Ok(crate::speeds::SpeedScale::of(self)?.default_range()),
        }
    }

    fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        let mut interactions = PlacedInteractions::new();
        if let Some(d) = &self.friction.devices {
            let layout = d.layout(model.mesh().length)?;
            // The layout's own checks (e.g. the count against the mesh) come first, then the force.
            let mut devices = Devices { layout, force: 0.0 };
            devices.validate(model)?;
            devices.force = d.force.ok_or_else(|| {
                invalid("friction.devices.force", "missing", "give the maximal force of one device F_u (N)")
            })?;
            finite_non_negative("friction.devices.force", devices.force, "N")?;
            interactions.extend(devices.interactions(model)?);
        }
        if let Some(d) = &self.friction.distributed {
            interactions.extend(d.friction()?.interactions(model)?);
        }
        Ok(interactions)
    }

    /// What the beam carries of a train's axles ([`crate::LoadSection::share_on`] for this scenario's foundation and
    /// sleepers: a rail on either is a track, one rail carrying half of each axle; on a `[ground]` the composite beam
    /// is the whole track and carries whole axles, a rail on sleepers half, unless `load.carries` says otherwise).
    pub fn axle_share(&self) -> crate::AxleShare {
        match (&self.ground, &self.sleepers) {
            (Some(_), None) => self.load.carries.unwrap_or(crate::AxleShare::WholeAxle),
            (Some(_), Some(_)) => self.load.carries.unwrap_or(crate::AxleShare::OneRail),
            (None, _) => self.load.share_on(self.foundation.stiffness, self.sleepers.is_some()),
        }
    }

    /// `train` as the beam carries it: its axle loads times the [`Scenario::axle_share`] factor (the catalogue's
    /// `single` is the beam's own load, never scaled).
    pub fn on_the_beam(&self, train: fem_beam::Train) -> fem_beam::Train {
        if train.name == "single" { train } else { train.scaled(self.axle_share().factor()) }
    }

    /// The scheme `(θ, ρ∞)` this scenario's runs are integrated with ([`crate::IntegrationSection::scheme`] for its
    /// rail and its wheels).
    pub fn scheme(&self) -> (f64, Option<f64>) {
        let timoshenko = matches!(self.beam.theory, fem_beam::BeamTheory::Timoshenko { .. });
        let rigid_contact = self.vehicle.as_ref().is_some_and(VehicleSection::has_rigid_contact);
        self.integration.scheme(timoshenko, rigid_contact)
    }

    /// The engine's scheme of [`Self::scheme`], as a report names it.
    pub fn scheme_used(&self) -> nscd::integrator::Scheme {
        let (theta, spectral_radius) = self.scheme();
        IntegrationSettings { theta, spectral_radius, ..IntegrationSettings::default() }.scheme()
    }

    /// Run settings for a load speed `speed` (m/s), with the train resolved ([`crate::trains::resolve`]) but not yet
    /// validated (see [`Scenario::build`]).
    pub fn run_settings(&self, speed: f64) -> Result<RunSettings> {
        self.run_settings_reaching(speed, self.mesh.length)
    }

    /// [`Self::run_settings`] for a run whose first wheel covers `reach` m of track (a co-moving window's length
    /// plus the track it travels): a random rail's period, when not given, covers it, so the rail does not repeat.
    pub fn run_settings_reaching(&self, speed: f64, reach: f64) -> Result<RunSettings> {
        let train = crate::trains::resolve(&self.load)?.map(|t| self.on_the_beam(t));
        let i = &self.integration;
        let (theta, spectral_radius) = self.scheme();
        let initial = match (i.steady_start, i.static_start) {
            (Some(_), Some(x)) => {
                return Err(invalid("integration.static_start", x, "give steady_start or static_start, not both"));
            }
            (Some(position), None) => InitialState::SteadyState { position },
            (None, Some(position)) => InitialState::Static { position },
            (None, None) => InitialState::Rest,
        };
        let solver = SolverSettings {
            kind: i.solver,
            tolerance: i.tolerance,
            max_iterations: i.max_iterations,
            moving_window: i.moving_window,
        };
        if self.vehicle.is_none() && !self.rail.is_empty() {
            return Err(invalid(
                "rail.irregularities",
                "given",
                "the rail's irregularities act under [vehicle] wheels only",
            ));
        }
        // `load.force` is checked even where a train or vehicles carry the load instead: a bad value is refused,
        // never silently unused.
        Load::Force(self.load.force).validate()?;
        let load = match (&self.vehicle, train) {
            (Some(v), train) => {
                let vehicles = v.settings(train.as_ref(), |behind| self.rail.profile(reach + behind))?;
                Load::Vehicles { vehicles, train }
            }
            (None, Some(train)) => Load::Train(train),
            (None, None) => Load::Force(self.load.force),
        };
        let travel = (initial.load_position(), reach + load.length());
        let speed_limit = self.fastest_ground_wave.map_or(SpeedLimit::BarWave, SpeedLimit::FastestGroundWave);
        let moving = MovingLoadSettings { speed, profile: Vec::new(), acceleration: None, load, initial, speed_limit };
        Ok(RunSettings {
            moving: self.load.speed_change(moving, travel)?,
            integration: IntegrationSettings {
                theta,
                spectral_radius,
                load_advance: i.load_advance,
                max_step: i.max_step,
                end_time: i.end_time,
                solver,
            },
            record: RecordSettings {
                sections: self.output.sections.clone(),
                extremes_window: Some(self.output.extremes_window(self.mesh.length)),
                extremes_nodes: self.output.extremes_nodes.map(|[a, b]| (a, b)),
                acceleration_band: self.acceleration_band()?,
                acceleration_filter: self.acceleration_filter()?,
            },
        })
    }
}

/// A field error of a lower layer, whose name is relative to the scenario section `section` (e.g. `devices.count` in
/// `[friction]`), renamed to its full path; other errors unchanged.
fn under(section: &str, error: StudyError) -> StudyError {
    use fem_beam::FemError as F;
    match error {
        StudyError::Beam(F::InvalidField { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), number(value), allowed)
        }
        StudyError::Beam(F::InvalidCount { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), value, allowed)
        }
        other => other,
    }
}

impl DistributedSection {
    /// The ballast friction this section describes, checked and its errors named by their path in the file: the one
    /// check that a run and the stationary solver share, so that both refuse the same value in the same words.
    pub fn friction(&self) -> Result<DistributedFriction> {
        let quadrature = match self.quadrature {
            QuadratureKind::Trapezoid => Quadrature::Trapezoid,
            QuadratureKind::Simpson => Quadrature::Simpson,
        };
        let friction = DistributedFriction {
            force_per_length: self.force_per_length,
            subdivisions: self.subdivisions,
            quadrature,
        };
        friction.validate().map_err(track::TrackError::friction)?;
        Ok(friction)
    }
}

/// Version of what a run reports (the sweep points a journal holds: their extremes, energy balance and columns),
/// part of every fingerprint and of a journal's first line, so that results of an older format are refused, never
/// read back as results of this one. 6: extremes as `{value, position, time}` and the energy balance as one object.
pub const RESULT_FORMAT: u32 = 6;
