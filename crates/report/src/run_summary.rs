//! The summary of one run: what ran and what it gave, typed, with the names every output uses (`frictrack run
//! --format json`, `summary.json`, the text report). Absent values are absent: an extreme that never happened is
//! None (null), not a placeholder 0 at x = 0, t = 0. Deflections (m) are magnitudes, positions (m), times (s),
//! energies (J), forces (N), accelerations (m/s²).

use fem_beam::{DeflectionExtremes, Extreme};
use nscd::EnergyBalance;
use scenario::error::Result;
use scenario::{Case, Scenario};
use serde::Serialize;
use track::RunResult;
use track::SectionKind;
use track::vehicle::consist::VehicleSettings;

/// An extreme of the run while the load was in the extremes window, and where the load (the first axle) was then.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WindowExtreme {
    /// The deflection's magnitude (m), its node (m) and time (s).
    #[serde(flatten)]
    pub extreme: Extreme,
    /// Where the load was then (m); None if the extreme never happened.
    pub load_position: Option<f64>,
    /// The load's speed then (m/s), where the speed changes during the run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_speed: Option<f64>,
}

/// A run whose load changes speed (`[load] acceleration` or `speed_profile`): how (m/s, m/s²).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpeedChange {
    /// The constant acceleration (m/s², negative brakes), if given as one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub acceleration: Option<f64>,
    /// The speed at the start, t = 0 (m/s).
    pub start_speed: f64,
    /// The speed where the run ends: the first axle where the last leaves the beam (m/s).
    pub end_speed: f64,
    /// The smallest speed on the way (m/s).
    pub slowest: f64,
    /// The largest speed on the way (m/s); it sets the time step.
    pub fastest: f64,
}

/// One run, summarised. Deflections are positive magnitudes (m), relative to the self-weight state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunSummary {
    /// The scenario's title.
    pub title: String,
    /// Load speed v (m/s); where it changes, the speed at x = 0.
    pub speed: f64,
    /// How the speed changes, where it does.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_change: Option<SpeedChange>,
    /// The scenario's single load F (N).
    pub load: f64,
    /// The train of axles that crossed (as forces, or carrying the vehicles).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub train: Option<scenario::trains::TrainSummary>,
    /// With a train: what the beam carries of its axles (`[load] carries`), by which the train's forces were scaled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axle_share: Option<AxleShareSummary>,
    /// The infinite beam's critical speed v_cr (m/s) — on sleepers the equivalent continuous track's; None without a
    /// foundation, and on a `[ground]` (the fitted foundation's is not the ground's: `frictrack ground` gives it).
    pub critical_speed: Option<f64>,
    /// On a `[ground]`: the foundation fitted to it at the run's speed and its wave's error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ground_fit: Option<analytic::ground::FittedFoundation>,
    /// A Timoshenko rail in words ("Timoshenko (G = 81 GPa, κ = 0.4)"); absent for Euler–Bernoulli.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rail_theory: Option<String>,
    /// The foundation's damping ratio ζ = c_f / c_cr.
    pub damping_ratio: f64,
    /// Whether the sleepers' ballast rests on an embankment beam (the two-beam track): v_cr is then that of the rail,
    /// the sleepers and half the embankment as one beam on half the soil, ζ the embankment's soil's.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub over_embankment: bool,
    /// Friction devices placed (after merging on shared nodes).
    pub devices: usize,
    /// Force of one device F_u (N).
    pub device_force: f64,
    /// Where the devices sit (m).
    pub device_positions: Vec<f64>,
    /// Distributed friction f_u (N/m).
    pub distributed_friction: f64,
    /// The extremes of the run, the static envelope and the amplification over it.
    #[serde(flatten)]
    pub extremes: ExtremesSummary,
    /// The energy balance (J).
    pub energy: EnergyBalance,
    /// How the steps were solved.
    #[serde(flatten)]
    pub stepping: SteppingSummary,
    /// Wall time of the whole run (s): the scenario's build with its statics, the time loop, the static envelope.
    pub wall_time: f64,
    /// Wall time of the time loop alone (s).
    pub time_loop: f64,
    /// The vehicles' wheels and bodies, with vehicles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vehicles: Option<crate::vehicle_output::VehicleReport>,
    /// A tensionless or bilinear soil: its work, energy and where the rail lifted off it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub soil: Option<crate::soil_output::SoilSummary>,
    /// A rail on sleepers: their frequencies, forces and the deflection under the load over a bay.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sleepers: Option<crate::sleeper_output::SleepersSummary>,
    /// How the text report names the extremes window (words only: not in the JSON).
    #[serde(skip)]
    pub window: crate::window_wording::WindowWording,
    /// With `--check-resolution` or `--accuracy`: every outcome at three resolutions, with the run's estimated error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resolution_check: Option<crate::resolution_check::ResolutionCheck>,
    /// With `--accuracy`: the tolerance, whether it was reached and the resolutions run (this summary is the finest's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accuracy: Option<crate::resolution_check::accuracy::Accuracy>,
}

/// The extremes of one run: over the whole run and every recorded node, over the window of load positions, the
/// static envelope of the same loads and the dynamic amplification over it, and W̄.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExtremesSummary {
    /// Largest downward and upward deflections (m, magnitudes), their nodes and times.
    #[serde(flatten)]
    pub deflection: DeflectionExtremes,
    /// Largest nodal acceleration, the step's mean (m/s²), its node and time; null where undefined (a Timoshenko
    /// rail: its nodal acceleration under a passing point force grows without bound under refinement).
    pub max_acceleration: Option<Extreme>,
    /// Largest acceleration in the beam's modes up to a band (EN 1990 A2's deck check on a span), where computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub band_acceleration: Option<BandAccelerationSummary>,
    /// Largest acceleration filtered in time (any model; a Timoshenko rail's by default), where computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub filtered_acceleration: Option<FilteredAccelerationSummary>,
    /// Largest downward deflection of the same loads standing at every position (m).
    pub static_max_downward_deflection: f64,
    /// max downward deflection over its static value.
    pub dynamic_amplification: f64,
    /// The window of load positions [A, B] (m) of the window extremes.
    pub extremes_window: (f64, f64),
    /// The nodes [a, b] (m) the extremes are taken over; None: every node.
    pub extremes_nodes: Option<(f64, f64)>,
    /// Largest downward and upward deflections while the load was in the window.
    #[serde(flatten, with = "fem_beam::extreme::in_window")]
    pub window_deflection: DeflectionExtremes<WindowExtreme>,
    /// W̄, the time mean of ∫|w| dx over the crossing (m²).
    pub global_norm: f64,
}

/// The largest band-limited acceleration of a run (docs/theory.md §10.4).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BandAccelerationSummary {
    /// Its magnitude (m/s²), node and time.
    #[serde(flatten)]
    pub extreme: Extreme,
    /// The band's upper limit f_max (Hz).
    pub band: f64,
    /// The natural frequencies of the modes in the band (Hz).
    pub mode_frequencies: Vec<f64>,
}

/// The largest acceleration filtered in time: the velocity's difference over a window (docs/theory.md §10.4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FilteredAccelerationSummary {
    /// Its magnitude (m/s²), node and time (the middle of its window).
    #[serde(flatten)]
    pub extreme: Extreme,
    /// The band filtered to (Hz): the −3 dB point of the window used.
    pub band: f64,
    /// The band asked for (Hz): the same but for the window's rounding to whole steps, or higher where the step is
    /// longer than the window asked.
    pub band_asked: f64,
    /// The window the velocity's difference is taken over (s).
    pub window: f64,
}

/// How the steps of one run were solved.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SteppingSummary {
    /// Time steps.
    pub steps: usize,
    /// The step h (s).
    pub time_step: f64,
    /// The scheme, e.g. "generalized-α (ρ∞ = 0.5)" or "θ-method (θ = 0.5)".
    pub scheme: String,
    /// Friction sections.
    pub sections: usize,
    /// Mean solver iterations per step.
    pub mean_iterations: f64,
    /// Most solver iterations in a step.
    pub max_iterations: usize,
    /// Largest final law residual of a step (m/s).
    pub max_residual: f64,
    /// Mean sections re-solved per step.
    pub mean_sections_solved: f64,
    /// The banded factorisations and solves and the homotopy's events per step.
    #[serde(flatten)]
    pub work: track::simulation::WorkStatistics,
    /// The solver the run used (`none` without interactions).
    pub solver: String,
    /// Steps solved by a fallback solver.
    pub fallback_steps: usize,
    /// The fallbacks, each with the steps it solved.
    pub fallbacks: Vec<FallbackSummary>,
}

/// What the beam carries of a train's axles.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxleShareSummary {
    /// `one-rail` or `whole-axle`.
    pub carries: &'static str,
    /// The factor on the axle loads (½ or 1).
    pub factor: f64,
    /// In words.
    #[serde(skip)]
    pub meaning: &'static str,
}

impl AxleShareSummary {
    /// The summary of `share`.
    pub fn of(share: scenario::AxleShare) -> Self {
        Self { carries: share.name(), factor: share.factor(), meaning: share.describe() }
    }
}

/// Steps of the run solved by one fallback solver (the run's solver failed on them).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FallbackSummary {
    /// The fallback solver.
    pub solver: &'static str,
    /// Steps it solved.
    pub steps: usize,
}

/// The run in words, for the text report and the figures' subtitles.
impl RunSummary {
    /// The fallback solver that solved most of the run's steps, when the run's own solver failed on more than half.
    pub fn mostly_solved_by(&self) -> Option<&'static str> {
        let s = &self.stepping;
        let most = s.fallbacks.iter().max_by_key(|f| f.steps)?;
        (2 * s.fallback_steps > s.steps).then_some(most.solver)
    }

    /// The warning a run gives when its own solver failed on most steps ([`Self::mostly_solved_by`]).
    pub fn fallback_warning(&self) -> Option<String> {
        let (solver, fallback) = (&self.stepping.solver, self.mostly_solved_by()?);
        Some(format!("--solver {solver} could not solve most steps of this run; --solver {fallback} solved them"))
    }

    /// What ran, in words: the load, train or vehicles.
    pub fn load_description(&self) -> String {
        match (&self.vehicles, &self.train) {
            (Some(v), _) => {
                let total: f64 = v.wheels.iter().map(|w| w.static_force).sum();
                let plural = if v.bodies.len() == 1 { "" } else { "s" };
                format!("{} vehicle{plural} ({}) weighing {:.1} kN", v.bodies.len(), v.bodies[0].name, total / 1e3)
            }
            (None, Some(t)) => format!(
                "train {} ({} axles, {} patches, {:.3} m, {:.1} kN on the beam{})",
                t.name,
                t.axles,
                t.patches,
                t.length,
                t.total_force / 1e3,
                self.axle_share.as_ref().map_or(String::new(), |s| format!(": {}", s.meaning))
            ),
            (None, None) => format!("load {:.1} kN", self.load / 1e3),
        }
    }

    /// The friction that ran, in words.
    pub fn friction_description(&self) -> String {
        let devices =
            (self.devices > 0).then(|| format!("{} devices × {:.1} kN", self.devices, self.device_force / 1e3));
        let distributed =
            (self.distributed_friction > 0.0).then(|| format!("{:.1} N/m distributed", self.distributed_friction));
        let sleepers = self
            .sleepers
            .as_ref()
            .filter(|s| s.sliders > 0)
            .map(|s| format!("{} sleepers on the ballast, {:.1} kN in all", s.sliders, s.slider_force / 1e3));
        match (devices, distributed, sleepers) {
            (None, None, None) => "none".into(),
            (a, b, c) => [a, b, c].into_iter().flatten().collect::<Vec<_>>().join(" and "),
        }
    }

    /// The subtitle of the run's figures: what ran, at which speed, with which friction, on which fitted ground.
    pub fn figure_subtitle(&self) -> String {
        let (load, speed, friction) = (self.load_description(), self.speed_description(), self.friction_description());
        // A run on a [ground] ran on a fitted foundation: its figures say so, and how far its wave is from the exact.
        let fitted = self.ground_fit.map_or(String::new(), |fit| {
            format!(
                "; on a foundation fitted to the ground (its wave within {:.1} % of the exact)",
                100.0 * fit.wave_error
            )
        });
        format!("{load} {speed}; friction: {friction}{fitted}")
    }

    /// "at 100.00 m/s (360 km/h)", or where the speed changes "from 100.00 to 80.00 m/s (braking at 2 m/s²)".
    pub fn speed_description(&self) -> String {
        match &self.speed_change {
            None => format!("at {:.2} m/s ({:.0} km/h)", self.speed, self.speed * scenario::units::KMH),
            Some(c) => {
                let how = match c.acceleration {
                    Some(a) if a < 0.0 => format!("braking at {} m/s²", scenario::number::significant(-a, 6)),
                    Some(a) => format!("accelerating at {} m/s²", scenario::number::significant(a, 6)),
                    None => format!("speed profile, {:.2}–{:.2} m/s on the way", c.slowest, c.fastest),
                };
                format!("from {:.2} to {:.2} m/s ({how})", c.start_speed, c.end_speed)
            }
        }
    }
}

impl RunSummary {
    /// The summary of `result`, a run of `case` built from `scenario` from `started` on (the scenario's build — the
    /// settled statics — included): what ran, the extremes, the static envelope of the same loads and the dynamic
    /// amplification over it, the energy ledger, the solver's statistics and, with vehicles, theirs. Its wall time
    /// is the whole cost up to now: set-up, statics, stepping and the static envelope (the time loop's own is
    /// `stepping.statistics`'s).
    pub fn of(scenario: &Scenario, case: &Case, result: &RunResult, started: std::time::Instant) -> Result<Self> {
        let settings = &case.settings;
        let placed = &case.interactions;
        // Where results are read: the extremes' nodes, else the extremes window.
        let mesh = case.model.mesh();
        let read = scenario.output.extremes_nodes.unwrap_or_else(|| {
            let (a, b) = scenario.output.extremes_window(mesh.length);
            [a, b]
        });
        let device_positions: Vec<f64> = (placed.positions().iter().zip(placed.kinds()))
            .filter_map(|(&x, &kind)| (kind == SectionKind::Device).then_some(x))
            .collect();
        Ok(Self {
            title: scenario.title.clone(),
            speed: settings.moving.speed,
            speed_change: settings.moving.changes_speed().then(|| {
                let motion = settings.motion();
                let end = settings.travel_end(mesh.length);
                let (fastest, slowest) = motion.speed_range(end);
                let (start_speed, end_speed) = (motion.speed(0.0), motion.speed_at(end));
                SpeedChange { acceleration: scenario.load.acceleration, start_speed, end_speed, slowest, fastest }
            }),
            load: scenario.load.force,
            train: settings.moving.load.axles().map(scenario::trains::TrainSummary::of),
            axle_share: settings
                .moving
                .load
                .axles()
                .filter(|t| t.name != "single")
                .map(|_| AxleShareSummary::of(scenario.axle_share())),
            critical_speed: case.critical_speed.filter(|_| case.ground_fit.is_none()),
            ground_fit: case.ground_fit,
            rail_theory: scenario.beam.theory.unless_default(),
            damping_ratio: match case.model.embankment() {
                Some(below) => below.foundation.damping_ratio(&below.beam),
                None => case.model.foundation().damping_ratio(case.model.beam()),
            },
            over_embankment: case.model.embankment().is_some(),
            devices: device_positions.len(),
            device_force: scenario.friction.devices.as_ref().and_then(|d| d.force).unwrap_or(0.0),
            device_positions,
            distributed_friction: scenario.friction.distributed.as_ref().map_or(0.0, |d| d.force_per_length),
            extremes: ExtremesSummary::of(case, result)?,
            energy: result.energy.balance(),
            stepping: SteppingSummary::of(result, settings),
            wall_time: started.elapsed().as_secs_f64(),
            time_loop: result.statistics.wall_time,
            vehicles: result.vehicles.as_ref().map(|v| {
                let contact = settings.moving.load.vehicles().map_or("", VehicleSettings::contact_name);
                crate::vehicle_output::VehicleReport::of(v, contact, Some((mesh.element_length(), read)))
            }),
            soil: crate::soil_output::SoilSummary::of(&case.model, scenario.foundation.self_weight, result, read),
            sleepers: crate::sleeper_output::SleepersSummary::of(
                &case.model,
                placed,
                result.sleepers.as_ref(),
                settings.moving.speed,
                read,
            ),
            window: crate::window_wording::WindowWording::of(scenario, case),
            resolution_check: None,
            accuracy: None,
        })
    }
}

impl ExtremesSummary {
    /// The extremes of `result`, a run of `case`, with the static envelope of the same loads (a static solve per
    /// load position) and the amplification over it.
    pub fn of(case: &Case, result: &RunResult) -> Result<Self> {
        let settings = &case.settings;
        let window = result.window.unwrap_or_default();
        let motion = settings.motion();
        let changes = settings.moving.changes_speed();
        let in_window = |x: Extreme| WindowExtreme {
            extreme: x,
            load_position: x.time.map(|t| motion.position(t)),
            load_speed: x.time.filter(|_| changes).map(|t| motion.speed(t)),
        };
        let statics = track::statics::static_envelope(
            &case.model,
            &case.interactions,
            &settings.moving.load.train(),
            settings.integration.load_advance,
            settings.record.extremes_nodes,
        )?;
        Ok(Self {
            deflection: result.deflection,
            max_acceleration: result.max_acceleration,
            band_acceleration: result.band_acceleration.as_ref().map(|b| BandAccelerationSummary {
                extreme: b.extreme,
                band: b.limit,
                mode_frequencies: b.frequencies.clone(),
            }),
            filtered_acceleration: result.filtered_acceleration.as_ref().map(|f| FilteredAccelerationSummary {
                extreme: f.extreme,
                band: f.band,
                band_asked: f.asked,
                window: f.window,
            }),
            static_max_downward_deflection: statics.max_downward,
            dynamic_amplification: if statics.max_downward > 0.0 {
                result.deflection.max_downward.value / statics.max_downward
            } else {
                0.0
            },
            extremes_window: window.load_range,
            extremes_nodes: settings.record.extremes_nodes,
            window_deflection: window.deflection.map(in_window),
            global_norm: result.global_norm,
        })
    }
}

impl SteppingSummary {
    /// The solver statistics of `result`, run under `settings`.
    pub fn of(result: &RunResult, settings: &track::RunSettings) -> Self {
        let s = &result.statistics;
        Self {
            steps: s.steps,
            time_step: result.step,
            scheme: settings.integration.scheme().to_string(),
            sections: s.sections,
            mean_iterations: s.mean_iterations,
            max_iterations: s.max_iterations,
            max_residual: s.max_residual,
            mean_sections_solved: s.mean_sections_solved,
            work: s.work,
            solver: s.solver_name().to_string(),
            fallback_steps: s.fallback_steps(),
            fallbacks: s
                .fallbacks
                .iter()
                .map(|f| FallbackSummary { solver: f.solver.name(), steps: f.steps })
                .collect(),
        }
    }
}
