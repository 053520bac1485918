//! What a run reports (docs/theory.md §6): extremes over the whole run and over a window of load positions,
//! histories at sections, solver statistics, and the state lent to observers after each step.

use fem_beam::{DeflectionExtremes, Extreme, LiftOffZone};
use nscd::stepper::EnergyLedger;

/// The extremes while the load was inside a range of positions (docs/theory.md §8: away from the entry and exit
/// transients of a finite beam started from rest).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WindowExtremes {
    /// The range of load positions [A, B] (m).
    pub load_range: (f64, f64),
    /// Largest downward and upward deflections over nodes and the steps with the load inside the range.
    pub deflection: DeflectionExtremes,
}

/// Histories at one section.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SectionHistory {
    /// Requested position (m).
    pub position: f64,
    /// Node whose bending moment is reported (m): the nearest node.
    pub moment_node: f64,
    /// Times t_k (s), starting at 0.
    pub time: Vec<f64>,
    /// Load position at t_k (m).
    pub load_position: Vec<f64>,
    /// Deflection w (m, upward).
    pub deflection: Vec<f64>,
    /// Velocity ẇ (m/s, upward) after each step.
    pub velocity: Vec<f64>,
    /// Mean acceleration of each step (ẇ_{k+1} − ẇ_k)/h (m/s², upward); 0 in the initial entry.
    pub acceleration: Vec<f64>,
    /// Bending moment at `moment_node` (N·m, sagging positive) from element end forces K_e q + C_e q̇ + M_e q̈ − f_e
    /// after each step, with q̈ the mean acceleration of the step; the initial entry omits inertia.
    pub moment: Vec<f64>,
    /// Friction impulse of the contact section at this position (N·s), if there is one.
    pub impulse: Option<Vec<f64>>,
}

/// The state after a step, lent to observers.
#[derive(Debug, Clone, Copy)]
pub struct StepView<'a> {
    /// Step index (1-based).
    pub step: usize,
    /// Time t_{k+1} (s).
    pub time: f64,
    /// Load position (m).
    pub load_position: f64,
    /// q_{k+1} (free DOFs).
    pub displacement: &'a [f64],
    /// v_{k+1}.
    pub velocity: &'a [f64],
    /// v_k.
    pub previous_velocity: &'a [f64],
    /// Friction impulses p (N·s).
    pub impulses: &'a [f64],
    /// Section velocities u_{k+1} = H v_{k+1} (m/s).
    pub section_velocities: &'a [f64],
    /// The step's law: impulse bounds (N·s; ±h·F_j for friction), compliance and drift.
    pub law: &'a nscd::StepLaw,
    /// The friction solver's report.
    pub report: nscd::solver::StepReport,
}

/// Solver statistics of a run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SolverStatistics {
    /// The friction solver the run used (resolved from `auto`); `None` without friction sections.
    pub solver: Option<nscd::solver::SolverKind>,
    /// Friction sections.
    pub sections: usize,
    /// Steps taken.
    pub steps: usize,
    /// Mean iterations per step (over steps with friction).
    pub mean_iterations: f64,
    /// Max iterations in one step.
    pub max_iterations: usize,
    /// Largest final law residual of a step (m/s).
    pub max_residual: f64,
    /// Mean number of sections re-solved per step (below `sections` with the interior point's moving window).
    pub mean_sections_solved: f64,
    /// The banded linear algebra and events per step ([`nscd::StepWork`]).
    pub work: WorkStatistics,
    /// Steps the run's solver could not solve, each solved by a fallback solver instead ([`nscd::fallback`]): the
    /// count per fallback, in the order they first took a step (empty when the run's solver solved every step).
    pub fallbacks: Vec<FallbackCount>,
    /// Wall time of the time loop (s).
    pub wall_time: f64,
}

/// The banded linear algebra and the homotopy's events of a run's steps ([`nscd::StepWork`]): means over the
/// steps and the largest in one step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct WorkStatistics {
    /// Banded factorisations per step, mean (0 for projection and Clarabel, which factor no banded matrix).
    pub mean_factorisations: f64,
    /// Most banded factorisations in one step.
    pub max_factorisations: usize,
    /// Banded solves per step, mean.
    pub mean_solves: f64,
    /// Events per step (sections changing between stick and slip along the homotopy's path), mean.
    pub mean_events: f64,
    /// Most events in one step.
    pub max_events: usize,
    /// The homotopy's repair rounds, over the run.
    pub repairs: usize,
}

/// Steps of a run solved by one fallback solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FallbackCount {
    /// The fallback solver.
    pub solver: nscd::solver::SolverKind,
    /// Steps it solved.
    pub steps: usize,
}

impl SolverStatistics {
    /// The solver's name for reports, `none` without friction sections.
    pub fn solver_name(&self) -> &'static str {
        self.solver.map_or("none", nscd::solver::SolverKind::name)
    }

    /// Steps solved by a fallback solver, over all fallbacks.
    pub fn fallback_steps(&self) -> usize {
        self.fallbacks.iter().map(|f| f.steps).sum()
    }

    /// Count a step's fallback, if it had one.
    pub fn count_fallback(&mut self, report: &nscd::solver::StepReport) {
        let Some(solver) = report.fallback else { return };
        match self.fallbacks.iter_mut().find(|f| f.solver == solver) {
            Some(count) => count.steps += 1,
            None => self.fallbacks.push(FallbackCount { solver, steps: 1 }),
        }
    }
}

/// The largest band-limited acceleration over the nodes and steps: the step's mean nodal acceleration in the beam's
/// modes at or below `limit` (docs/theory.md §10.4) — EN 1990 A2's deck acceleration, and a defined number where the
/// nodal one is not (a point load on a Timoshenko rail).
#[derive(Debug, Clone, PartialEq)]
pub struct BandAcceleration {
    /// Its magnitude (m/s²), node and time.
    pub extreme: Extreme,
    /// The band's upper limit f_max (Hz).
    pub limit: f64,
    /// The natural frequencies of the modes kept (Hz), ascending.
    pub frequencies: Vec<f64>,
}

/// The largest acceleration filtered in time ([`crate::simulation::RecordSettings::acceleration_filter`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FilteredAcceleration {
    /// Its magnitude (m/s²), node and time (the middle of its window).
    pub extreme: Extreme,
    /// The band asked for (Hz).
    pub asked: f64,
    /// The band filtered to (Hz): the −3 dB point 0.443/T of the window used, the band asked for to within the
    /// rounding of T to whole steps — below it where the step is longer than the window asked.
    pub band: f64,
    /// The window T the velocity's difference is taken over (s): a whole number of steps, ≈ 0.443/band.
    pub window: f64,
}

/// What a run reports (docs/theory.md §6).
#[derive(Debug, Clone, PartialEq)]
pub struct RunResult {
    /// Largest downward and upward deflections over nodes and steps.
    pub deflection: DeflectionExtremes,
    /// Largest vertical acceleration magnitude over nodes and steps (m/s², the step's mean (v_{k+1} − v_k)/h, at the
    /// end of the step): the deck acceleration of a bridge (docs/theory.md §10). None where it is undefined — on a
    /// Timoshenko rail, whose nodal acceleration under a passing point force grows without bound under refinement
    /// ([`fem_beam::BeamTheory::bounds_point_load_acceleration`]); [`RunResult::band_acceleration`] is defined there.
    pub max_acceleration: Option<Extreme>,
    /// The largest band-limited acceleration, where [`crate::simulation::RecordSettings::acceleration_band`] asks.
    pub band_acceleration: Option<BandAcceleration>,
    /// The largest acceleration filtered in time, where [`crate::simulation::RecordSettings::acceleration_filter`]
    /// asks.
    pub filtered_acceleration: Option<FilteredAcceleration>,
    /// The extremes while the load was inside [`crate::simulation::RecordSettings::extremes_window`], if one was set.
    pub window: Option<WindowExtremes>,
    /// Energy terms.
    pub energy: EnergyLedger,
    /// W̄ = (1/t_on)∫₀^{t_on}∫₀^L |w| dx dt (m), trapezoid in x (nodes) and t (steps).
    pub global_norm: f64,
    /// Histories at the recorded sections.
    pub histories: Vec<SectionHistory>,
    /// Solver statistics.
    pub statistics: SolverStatistics,
    /// Step size h (s).
    pub step: f64,
    /// Positions of the friction sections (m), e.g. the snapped device positions.
    pub section_positions: Vec<f64>,
    /// Final state: displacement and velocity of the free DOFs.
    pub final_displacement: Vec<f64>,
    /// Final velocity of the free DOFs.
    pub final_velocity: Vec<f64>,
    /// The vehicles' wheels and bodies, in a run with vehicles.
    pub vehicles: Option<VehicleResults>,
    /// Where and when the rail left the soil, on a nonlinear foundation.
    pub lift_off: Option<LiftOff>,
    /// The sleepers' forces and the rail's deflection under the load, on sleepers.
    pub sleepers: Option<SleeperResults>,
}

/// Where and when the rail left the soil of a nonlinear foundation over a run (docs/theory.md §13).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LiftOff {
    /// Foundation sections followed.
    pub sections: usize,
    /// The zones of neighbouring sections that lifted at some time in the run, in order of x.
    pub zones: Vec<LiftOffZone>,
}

impl LiftOff {
    /// The zone with the largest gap, if the rail ever lifted.
    pub fn largest(&self) -> Option<&LiftOffZone> {
        fem_beam::extreme::largest_zone(&self.zones)
    }

    /// Sections that lifted at some time, over all zones.
    pub fn lifted_sections(&self) -> usize {
        self.zones.iter().map(|z| z.sections).sum()
    }
}

/// A wheel's loss of contact with the rail: where and when it lifted off, where it landed, and the impact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LossOfContact {
    /// Wheel position at the end of the first step without contact force (m).
    pub lift_off_position: f64,
    /// Time at the end of that step (s).
    pub lift_off_time: f64,
    /// Wheel position at the end of the first step with contact force again (m); None if still flying at the end.
    pub landing_position: Option<f64>,
    /// Time without contact (s), to the landing or to the end of the run.
    pub duration: f64,
    /// Largest contact force within [`crate::simulation::IMPACT_WINDOW`] of the landing (N).
    pub impact_force: f64,
}

/// One wheel's contact force (docs/theory.md §12): the mean force of each step p/h (N, compressive positive).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelHistory {
    /// Time t_{k+1} (s).
    pub time: Vec<f64>,
    /// Wheel position at t_{k+1} (m).
    pub position: Vec<f64>,
    /// Contact force Q of the step (N).
    pub force: Vec<f64>,
    /// Rail deflection under the wheel at t_{k+1} (m, upward; 0 off the beam, where the rail is rigid ground).
    pub rail_deflection: Vec<f64>,
    /// Bending moment EI·w″ of the rail under the wheel (N·m, sagging positive; the element's cubic, whose w″ jumps
    /// at nodes: docs/theory.md §12).
    pub moment: Vec<f64>,
}

/// What a run reports of one wheel.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelResult {
    /// Its vehicle (index).
    pub vehicle: usize,
    /// Its index within the vehicle.
    pub wheel: usize,
    /// Offset behind the first wheel (m).
    pub offset: f64,
    /// Static wheel load Q₀ (N).
    pub static_force: f64,
    /// Smallest contact force (N; 0 when the wheel lost contact).
    pub min_force: f64,
    /// Largest contact force (N).
    pub max_force: f64,
    /// Largest downward rail deflection under the wheel (m).
    pub max_rail_deflection: f64,
    /// Largest |bending moment| of the rail under the wheel (N·m).
    pub max_moment: f64,
    /// The losses of contact, in order.
    pub losses: Vec<LossOfContact>,
    /// Step by step.
    pub history: WheelHistory,
}

impl WheelResult {
    /// max |Q − Q₀|/Q₀ over the run: the dynamic wheel-load factor ΔQ/Q₀.
    pub fn dynamic_increment(&self) -> f64 {
        (self.max_force - self.static_force).max(self.static_force - self.min_force) / self.static_force
    }

    /// Total time without contact (s): 0 without losses (a fold from +0, where `Sum` starts at −0.0 and the JSON said
    /// `-0.0`).
    pub fn time_off_rail(&self) -> f64 {
        self.losses.iter().fold(0.0, |total, l| total + l.duration)
    }
}

/// What a run reports of one vehicle's body (its [`crate::vehicle::Vehicle::body`] DOF), while all its wheels are
/// inside the extremes region ([`crate::simulation::RecordSettings::extremes_nodes`]; the whole run without one).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BodyResult {
    /// The vehicle's name.
    pub name: String,
    /// Largest |acceleration| (m/s², the step's mean (v_{k+1} − v_k)/h).
    pub max_acceleration: f64,
    /// RMS acceleration over the run (m/s²): comfort.
    pub rms_acceleration: f64,
    /// Time over which the RMS is taken (s): 0 if the vehicle never was wholly inside the region.
    pub duration: f64,
}

/// The vehicles' part of a run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VehicleResults {
    /// Every wheel, vehicle by vehicle.
    pub wheels: Vec<WheelResult>,
    /// Every vehicle's body.
    pub bodies: Vec<BodyResult>,
    /// Work of the contact forces on beam and vehicles Σ U_θᵀp (J), U without the rheonomic part: a wheel rolling
    /// onto a deflecting rail does work on it through the traction that keeps its speed (the convective v·w′ of the
    /// gap), so this is not a loss (docs/theory.md §12).
    pub contact_work: f64,
    /// Energy in the contact springs at the end (J).
    pub spring_energy: f64,
    /// Energy the contacts dissipated (J, ≥ 0): landing impacts and the implicit contact law
    /// ([`nscd::EnergyLedger::contact_loss`]).
    pub contact_loss: f64,
    /// Strain energy changed by the position projection of rigid contacts (J, either sign; 0 without rigid
    /// contacts): the O(h) drift of the velocity-level constraint along the moving rail, removed
    /// ([`nscd::EnergyLedger::projection_work`]).
    pub projection_work: f64,
}

/// One sleeper over a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeperPeaks {
    /// Where it sits (m).
    pub x: f64,
    /// Largest pad force (N, compression) and when (s).
    pub pad_force: (f64, f64),
    /// Largest ballast force (N, compression) and when (s).
    pub ballast_force: (f64, f64),
    /// Under a ballast body: the largest subgrade force (N, compression) and when (s); None on rigidly founded
    /// ballast.
    pub subgrade_force: Option<(f64, f64)>,
    /// The sleeper's lowest position (m, downward positive).
    pub lowest: f64,
    /// The sleeper's largest |acceleration| (m/s²) and when (s): filtered in time like the rail's where the run
    /// filters it ([`SleeperResults::acceleration_window`]), else the step's mean (ż_{k+1} − ż_k)/h.
    pub acceleration: (f64, f64),
    /// Under a ballast body: its largest |acceleration| (m/s², as `acceleration`) and when (s); None on rigidly
    /// founded ballast.
    pub ballast_acceleration: Option<(f64, f64)>,
    /// Where the ballast cannot pull: the largest gap under the sleeper (m; a voided sleeper's starts at its void, a
    /// tensionless one's stays 0 while it presses). None for bonded ballast.
    pub largest_gap: Option<f64>,
    /// Where the ballast cannot pull: when the sleeper first pressed on it (s; None if never).
    pub first_contact: Option<f64>,
}

/// The sleepers over a run, and the rail's deflection under the first load.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SleeperResults {
    /// Each sleeper, first to last.
    pub sleepers: Vec<SleeperPeaks>,
    /// The sleepers' spacing a (m) and where the first sits (m).
    pub spacing: f64,
    /// See `spacing`.
    pub first: f64,
    /// (first load's position (m), the rail's deflection under it (m, upward)) after every step it was on the rail.
    pub under_load: Vec<(f64, f64)>,
    /// The window T (s) the sleepers' accelerations are filtered over — the rail's filter in time
    /// ([`crate::simulation::RecordSettings::acceleration_filter`]) —, None where the run does not filter (then they
    /// are the step's mean).
    pub acceleration_window: Option<f64>,
    /// The histories of the sleepers under recorded sections (a section whose nearest node carries a sleeper).
    pub histories: Vec<SleeperHistory>,
}

/// One sleeper's history under a recorded section, after every step (from t = h; forces as [`SleeperPeaks`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SleeperHistory {
    /// The recorded section's position (m), and the sleeper's number (0-based) and place (m).
    pub section: f64,
    /// See `section`.
    pub index: usize,
    /// See `section`.
    pub x: f64,
    /// Times t_k (s) and the first load's position then (m).
    pub time: Vec<f64>,
    /// See `time`.
    pub load_position: Vec<f64>,
    /// The sleeper's displacement z (m, upward) and its step's mean acceleration (ż_{k+1} − ż_k)/h (m/s², upward).
    pub deflection: Vec<f64>,
    /// See `deflection`.
    pub acceleration: Vec<f64>,
    /// The pad and ballast forces (N, compression positive, from the settled state).
    pub pad_force: Vec<f64>,
    /// See `pad_force`.
    pub ballast_force: Vec<f64>,
    /// Under a ballast body: its step's mean acceleration (m/s², upward); None on rigidly founded ballast.
    pub ballast_acceleration: Option<Vec<f64>>,
}
