//! The settings of one run, in three parts — what moves on the beam (speed, force, start), how it is integrated (θ,
//! load advance, end, solver) and what is recorded (sections, extremes window) — and the limits checked before
//! anything is allocated.

pub use super::integration_settings::IntegrationSettings;
pub use super::moving_settings::MovingLoadSettings;
use crate::error::{Refused, Result, Setting, TrackError, invalid, invalid_choice, invalid_count};
use crate::vehicle::consist::{MAX_CONTACT_STEP, VehicleSettings};
use crate::vehicle::wheel_rail::WheelRail;
use fem_beam::{BeamModel, Motion, Train};
use nscd::solver::SolverKind;
use nscd::stepper::Integration;

/// How the run starts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum InitialState {
    /// At rest in the self-weight equilibrium, the load entering at x = 0 (default).
    #[default]
    Rest,
    /// In the analytic steady state of the infinite beam (docs/theory.md §8) with the load at `position` (m):
    /// removes the entry transient. Needs damping > 0 at or above the critical speed.
    SteadyState {
        /// Load position at t = 0 (m).
        position: f64,
    },
    /// The static equilibrium of the loads standing with the first one at `position` (m): the beam deflected under
    /// them, the deflection moving with the loads (ẇ = −V ∂w/∂x: the bowl of loads moving at V), and with vehicles
    /// the vehicles at rest on the deflected rail. Removes the drop of vehicles entering a soft track from the rigid
    /// ground level with its unloaded rail, and the throw of wheels left on a standing bowl.
    Static {
        /// Load position at t = 0 (m).
        position: f64,
    },
}

impl InitialState {
    /// The first axle's position at t = 0 (m): 0 from rest (the load entering), else the position given.
    pub fn load_position(&self) -> f64 {
        match *self {
            InitialState::Rest => 0.0,
            InitialState::SteadyState { position } | InitialState::Static { position } => position,
        }
    }
}

/// What crosses the beam: one force, a train of moving forces, or vehicles.
#[derive(Debug, Clone, PartialEq)]
pub enum Load {
    /// One point force F (N), acting downward, ≥ 0.
    Force(f64),
    /// A train of axles and patches (docs/theory.md §10).
    Train(Train),
    /// Vehicles, which load the rail with their weights through their wheels (docs/theory.md §12).
    Vehicles {
        /// The vehicles, their wheel–rail contact and the rail's profile.
        vehicles: VehicleSettings,
        /// The train whose axles the vehicles stand on, when they were placed on one (for reports); None for
        /// vehicles given on their own.
        train: Option<Train>,
    },
}

impl Load {
    /// The train that moves as forces: the vehicles' static wheel loads ([`VehicleSettings::static_train`]), the
    /// train, or a single axle of the force.
    pub fn train(&self) -> Train {
        match self {
            Load::Force(force) => Train::single(*force),
            Load::Train(train) => train.clone(),
            // Valid vehicles always have a static train (checked by their `validate`).
            Load::Vehicles { vehicles, .. } => vehicles.static_train().unwrap_or_else(|_| Train::single(0.0)),
        }
    }

    /// The length behind the first axle (m; 0 for a single force), or the vehicles' from the first wheel to the
    /// last.
    pub fn length(&self) -> f64 {
        match self {
            Load::Force(_) => 0.0,
            Load::Train(train) => train.length(),
            Load::Vehicles { vehicles, .. } => vehicles.length(),
        }
    }

    /// The vehicles, if vehicles cross.
    pub fn vehicles(&self) -> Option<&VehicleSettings> {
        match self {
            Load::Vehicles { vehicles, .. } => Some(vehicles),
            Load::Force(_) | Load::Train(_) => None,
        }
    }

    /// The train of axles that crosses, as forces or carrying the vehicles; None for a single force.
    pub fn axles(&self) -> Option<&Train> {
        match self {
            Load::Train(train) => Some(train),
            Load::Vehicles { train, .. } => train.as_ref(),
            Load::Force(_) => None,
        }
    }

    /// Check what crosses: a force finite and ≥ 0, a valid train, valid vehicles.
    pub fn validate(&self) -> Result<()> {
        match self {
            Load::Force(force) if !(force.is_finite() && *force >= 0.0) => {
                Err(invalid(Setting::Load, *force, "must be finite and ≥ 0 (N, acting downward)"))
            }
            Load::Force(_) => Ok(()),
            Load::Train(train) => Ok(train.validate()?),
            Load::Vehicles { vehicles, .. } => vehicles.validate(),
        }
    }
}

impl Default for Load {
    /// The reference case's load: 83.4 kN, half a Thalys power-car axle.
    fn default() -> Self {
        Load::Force(83.4e3)
    }
}

/// What a run records besides its whole-run extremes, energy and W̄.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RecordSettings {
    /// Positions (m) whose histories (w, ẇ, ẅ, M, friction force) are recorded. Default: none.
    pub sections: Vec<f64>,
    /// Also track the extremes while the load is inside this range of load positions [A, B] (m), reported in
    /// `RunResult::window` beside the whole-run extremes: away from the entry and exit transients they read the
    /// response of a long track. Default: none.
    pub extremes_window: Option<(f64, f64)>,
    /// Take the extremes (deflections, whole-run and window, and the acceleration) over the nodes in [a, b] (m)
    /// only: on a finite track, the nodes away from its ends, where loads entering and leaving over the supports
    /// set off transients (a train longer than the beam is always crossing one). W̄ stays a whole-beam norm.
    /// Default: every node.
    pub extremes_nodes: Option<(f64, f64)>,
    /// Also the largest band-limited acceleration over those nodes: the part of the nodal accelerations in the
    /// beam's modes within this band, EN 1990 A2's deck check ([`fem_beam::modal_band`]; the beam's free DOFs
    /// within [`fem_beam::BeamModel::MAX_MODAL_DOFS`]). Default: none.
    pub acceleration_band: Option<fem_beam::modal_band::BandLimit>,
    /// Also the largest acceleration low-pass filtered in time to this band (Hz), on any size of model: the velocity's
    /// difference over a window of 0.443/band s ([`super::filtered_record`]). Default: none.
    pub acceleration_filter: Option<f64>,
}

/// Whether a node at `x` (m) counts for the extremes of `nodes` ([`RecordSettings::extremes_nodes`]) on a beam of
/// `length` (m): inside [a, b] up to 1e-9·L, or every node when no range is set.
pub(crate) fn counts_for_extremes(nodes: Option<(f64, f64)>, x: f64, length: f64) -> bool {
    let slack = 1e-9 * length;
    nodes.is_none_or(|(a, b)| x >= a - slack && x <= b + slack)
}

/// Settings of one run, in three parts: what moves on the beam, how it is integrated, what is recorded. Defaults:
/// the reference case of docs/theory.md §2 at 200 m/s.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RunSettings {
    /// The moving load.
    pub moving: MovingLoadSettings,
    /// The time integration.
    pub integration: IntegrationSettings,
    /// What is recorded.
    pub record: RecordSettings,
}

impl RunSettings {
    /// Check the settings against the model, in order: what moves, how it is integrated, where it starts, what is
    /// recorded, and the run's size (before anything is allocated).
    pub fn validate(&self, model: &BeamModel) -> Result<()> {
        self.validate_moving(model)?;
        self.validate_integration(model)?;
        self.validate_start(model)?;
        self.validate_record(model)?;
        self.validate_size(model.mesh().length)
    }

    /// The speed (positive, below the bar wave speed) and what crosses; vehicles' own limits.
    fn validate_moving(&self, model: &BeamModel) -> Result<()> {
        if !(self.moving.speed.is_finite() && self.moving.speed > 0.0) {
            return Err(invalid(Setting::Speed, self.moving.speed, "must be finite and > 0 (m/s)"));
        }
        self.moving.validate_profile()?;
        // Faster than the beam's bar wave speed √(E/ρ) (or a composite beam's ground's fastest wave) no model holds,
        // and the step h = Δx/v would shrink towards round-off: refused, not answered.
        let (limit, what) = self.moving.speed_limit.on(model.beam());
        let fastest = self.moving.largest_speed();
        if fastest >= limit {
            // A changing speed is named by its key and value; the speed it reaches is said beside them.
            let value = match (self.moving.speed_setting(), self.moving.acceleration) {
                (Setting::Acceleration, Some(a)) => Refused::Number(a),
                (Setting::SpeedProfile, _) => Refused::Choice("given"),
                _ => Refused::Number(fastest),
            };
            let reaches = match !self.moving.profile.is_empty() {
                true => format!("brings the load to {fastest:.0} m/s, which "),
                false => String::new(),
            };
            return Err(TrackError::Invalid {
                setting: self.moving.speed_setting(),
                value,
                allowed: format!(
                    "{reaches}must be below {what} = {limit:.0} m/s: beyond it no beam theory holds (railway speeds \
                     are below 200 m/s)"
                ),
            });
        }
        self.moving.load.validate()?;
        if self.moving.load.vehicles().is_some() {
            let kind = self.integration.solver.kind;
            if kind == SolverKind::Homotopy {
                return Err(invalid_choice(
                    Setting::Solver,
                    kind.name(),
                    "the homotopy takes fixed friction sections only: runs with vehicles need auto, \
                              interior-point, projection or clarabel",
                ));
            }
            if let InitialState::SteadyState { position } = self.moving.initial {
                return Err(invalid(
                    Setting::SteadyStart,
                    position,
                    "vehicles start at rest in static equilibrium (on the unloaded rail, or on the loaded one with a \
                     static start): no steady-state start",
                ));
            }
        }
        Ok(())
    }

    /// The load advance (at most an element, and short enough for the wheel–rail contact mode), θ and h, the solver.
    fn validate_integration(&self, model: &BeamModel) -> Result<()> {
        let l = model.mesh().element_length();
        if !(self.integration.load_advance.is_finite()
            && self.integration.load_advance > 0.0
            && self.integration.load_advance <= l)
        {
            return Err(invalid(
                Setting::LoadAdvance,
                self.integration.load_advance,
                format!("must be > 0 and ≤ the element length {l} m"),
            ));
        }
        if let Some(h_max) = self.integration.max_step
            && !(h_max.is_finite() && h_max > 0.0)
        {
            return Err(invalid(Setting::MaxStep, h_max, "must be a time step > 0 (s)"));
        }
        if self.integration.spectral_radius.is_some() && self.integration.theta != 0.5 {
            return Err(invalid(
                Setting::Theta,
                self.integration.theta,
                "must stay 0.5 when integration.spectral_radius chooses the generalized-α: give one of the two",
            ));
        }
        // The engine's own check of the scheme and h, named as this crate's settings: h = Δx/v is the load
        // advance's (its speed checked above).
        Integration { scheme: self.integration.scheme(), step: self.time_step() }.validate().map_err(|e| match e {
            nscd::NscdError::InvalidField { field: "integration.theta", value, allowed } => {
                invalid(Setting::Theta, value, allowed)
            }
            nscd::NscdError::InvalidField { field: "integration.spectral_radius", value, allowed } => {
                invalid(Setting::SpectralRadius, value, allowed)
            }
            nscd::NscdError::InvalidField { value, allowed, .. } => invalid(Setting::LoadAdvance, value, allowed),
            other => other.into(),
        })?;
        self.validate_vehicle_steps()?;
        self.validate_solver()
    }

    /// With vehicles: a scheme their contact's impact law takes, and a step short enough for the wheel–rail contact
    /// mode.
    fn validate_vehicle_steps(&self) -> Result<()> {
        if let (Some(vehicles), Some(rho)) = (self.moving.load.vehicles(), self.integration.spectral_radius)
            && vehicles.vehicles.iter().any(|p| matches!(vehicles.contact_of(p), WheelRail::Rigid { .. }))
        {
            // A rigid contact's impact law needs the velocity before the impact; the generalized-α's laws see the
            // rates' average (docs/theory.md §5.4).
            return Err(invalid(
                Setting::SpectralRadius,
                rho,
                "is not taken with a rigid wheel–rail contact (its impact law needs the θ-method): use \
                 vehicle.contact = \"hertz\" or \"linear\", or leave integration.spectral_radius out",
            ));
        }
        if let Some(vehicles) = self.moving.load.vehicles() {
            let omega = vehicles.contact_frequency()?;
            let largest = MAX_CONTACT_STEP / omega * self.moving.largest_speed();
            if omega * self.time_step() > MAX_CONTACT_STEP {
                return Err(invalid(
                    Setting::LoadAdvance,
                    self.integration.load_advance,
                    format!(
                        "must be ≤ {largest:.4e} m at {} m/s (the largest speed) with these vehicles: the wheel–rail contact mode at \
                         {:.4e} Hz needs at least π steps per period (a stiffer contact needs a shorter step; check \
                         vehicle.contact_stiffness or hertz_coefficient; or give integration.max_step ≤ {:.4e} s)",
                        self.moving.largest_speed(),
                        omega / std::f64::consts::TAU,
                        MAX_CONTACT_STEP / omega
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The solver's tolerance (the homotopy's floor among it) and iterations.
    fn validate_solver(&self) -> Result<()> {
        if !(self.integration.solver.tolerance.is_finite()
            && self.integration.solver.tolerance > 0.0
            && self.integration.solver.tolerance <= 1e-2)
        {
            return Err(invalid(Setting::Tolerance, self.integration.solver.tolerance, "must lie in (0, 1e-2]"));
        }
        let minimum = nscd::solver::homotopy::MIN_TOLERANCE;
        if self.integration.solver.kind == SolverKind::Homotopy && self.integration.solver.tolerance < minimum {
            return Err(invalid(
                Setting::Tolerance,
                self.integration.solver.tolerance,
                format!(
                    "must be at least {minimum:e} with the homotopy solver (its band of width ε = 0.4·tol·U \
                     amplifies round-off by 1/ε); take the interior point for tighter tolerances"
                ),
            ));
        }
        if self.integration.solver.max_iterations == 0 {
            return Err(invalid_count(Setting::MaxIterations, 0, "must be ≥ 1"));
        }
        Ok(())
    }

    /// A steady or static start's position on the beam of `length` (m).
    fn validate_start(&self, model: &BeamModel) -> Result<()> {
        let length = model.mesh().length;
        if let InitialState::SteadyState { position } = self.moving.initial
            && !model.foundation().law.is_linear()
        {
            return Err(invalid(
                Setting::SteadyStart,
                position,
                "the steady-state start is the closed form of a linear foundation: a tensionless or bilinear one \
                 starts at rest or from a static start",
            ));
        }
        if let InitialState::SteadyState { position } = self.moving.initial
            && model.sleepers().is_some()
        {
            return Err(invalid(
                Setting::SteadyStart,
                position,
                "the steady-state start is the closed form of a rail on a continuous foundation: a rail on sleepers \
                 starts at rest or from a static start",
            ));
        }
        if let InitialState::SteadyState { position } | InitialState::Static { position } = self.moving.initial
            && !(position.is_finite() && (0.0..length).contains(&position))
        {
            let field = if matches!(self.moving.initial, InitialState::Static { .. }) {
                Setting::StaticStart
            } else {
                Setting::SteadyStart
            };
            return Err(invalid(field, position, format!("must lie in [0, {length}) m")));
        }
        Ok(())
    }

    /// The recorded sections, the extremes window and the extremes' nodes.
    fn validate_record(&self, model: &BeamModel) -> Result<()> {
        let length = model.mesh().length;
        for &x in &self.record.sections {
            if !(x.is_finite() && (0.0..=length).contains(&x)) {
                return Err(invalid(Setting::RecordSections, x, format!("must lie on the beam, in [0, {length}] m")));
            }
        }
        if let Some((a, b)) = self.record.extremes_window
            && !(a.is_finite() && b.is_finite() && a < b)
        {
            let allowed = format!("needs finite load positions A < B (m), got {a}:{b}");
            return Err(invalid(Setting::ExtremesWindow, if a.is_finite() { b } else { a }, allowed));
        }
        if let Some((a, b)) = self.record.extremes_nodes {
            let mesh = model.mesh();
            let has_node = (0..mesh.nodes()).any(|i| {
                model.dofs().free_index(2 * i).is_some()
                    && counts_for_extremes(self.record.extremes_nodes, mesh.node_x(i), length)
            });
            if !(a.is_finite() && b.is_finite() && a <= b && has_node) {
                let allowed = format!("needs positions a ≤ b (m) with a free node between them, got {a}:{b}");
                return Err(invalid(Setting::ExtremesNodes, if a.is_finite() { b } else { a }, allowed));
            }
        }
        self.validate_accelerations(model)
    }

    /// The end time, and the steps and recorded samples the run would take on a beam of `length` (m).
    fn validate_size(&self, length: f64) -> Result<()> {
        if let Some(end) = self.integration.end_time
            && !(end.is_finite() && end >= self.crossing_time(length) * (1.0 - 1e-12))
        {
            return Err(invalid(
                Setting::EndTime,
                end,
                format!("must be ≥ the crossing time {} s", self.crossing_time(length)),
            ));
        }
        let steps = self.step_count(length);
        if steps > Self::MAX_STEPS as f64 {
            let h = self.time_step();
            let travel = self.travel_end(length) - self.start_position();
            let allowed = format!(
                "gives {steps:.3e} time steps of {h:.3e} s over the {travel:.4e} m the load travels (beam length \
                 {length:.4e} m plus the train); at most {} are allowed: shorten the beam (mesh.length) or the run, \
                 or lengthen the load advance",
                Self::MAX_STEPS
            );
            return match self.integration.end_time {
                Some(end) => Err(invalid(Setting::EndTime, end, allowed)),
                None => Err(invalid(Setting::LoadAdvance, self.integration.load_advance, allowed)),
            };
        }
        let wheels = self.moving.load.vehicles().map_or(0, |v| v.wheels().count());
        let samples = (steps + 1.0) * (self.record.sections.len() + wheels) as f64;
        if samples > Self::MAX_RECORDED_SAMPLES as f64 {
            return Err(invalid(
                Setting::RecordSections,
                self.record.sections.len() as f64,
                format!(
                    "{} sections and {wheels} wheels × {steps:.3e} steps exceed {} recorded samples; record fewer \
                     sections or run fewer vehicles",
                    self.record.sections.len(),
                    Self::MAX_RECORDED_SAMPLES
                ),
            ));
        }
        Ok(())
    }

    /// The most time steps a run may take (checked before anything is allocated): 2·10⁷, about 100 s without
    /// friction and over an hour with distributed friction on the reference mesh.
    pub const MAX_STEPS: usize = 20_000_000;

    /// The most history samples (steps × recorded sections) a run may keep: 5·10⁷, about 2 GB.
    pub const MAX_RECORDED_SAMPLES: usize = 50_000_000;

    /// Number of time steps of the run (as a float, so that absurd inputs do not overflow).
    pub fn step_count(&self, length: f64) -> f64 {
        let h = self.time_step();
        let crossing = (self.crossing_time(length) / h).round();
        match self.integration.end_time {
            Some(end) => crossing.max((end / h - 1e-9).ceil()),
            None => crossing,
        }
    }

    /// Load position at t = 0 (m).
    pub fn start_position(&self) -> f64 {
        self.moving.initial.load_position()
    }

    /// The time step h = min(Δx/v, h_max) (s): the load advance Δx at the speed v (the largest a speed profile
    /// reaches), shortened to the longest step h_max where one is given.
    pub fn time_step(&self) -> f64 {
        let h = self.advance_step();
        self.integration.max_step.map_or(h, |h_max| h.min(h_max))
    }

    /// Whether the longest step h_max shortens the step below Δx/v at this speed.
    pub fn step_is_capped(&self) -> bool {
        self.integration.max_step.is_some_and(|h_max| h_max < self.advance_step())
    }

    /// Δx/v (s): the step the load advance gives at this speed, before any longest step.
    fn advance_step(&self) -> f64 {
        self.integration.load_advance / self.moving.largest_speed()
    }

    /// Time for the load — the last axle of a train — to reach x = L (s).
    pub fn crossing_time(&self, length: f64) -> f64 {
        self.motion().time_at(self.travel_end(length))
    }

    /// Where the first axle is when the last leaves a beam of `length` (m): L plus the train's length.
    pub fn travel_end(&self, length: f64) -> f64 {
        length + self.moving.load.length()
    }

    /// How the first axle moves from its start ([`MovingLoadSettings::motion`]).
    pub fn motion(&self) -> Motion {
        self.moving.motion(self.start_position())
    }
}
