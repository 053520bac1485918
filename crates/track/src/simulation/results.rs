//! What a run reports (docs/theory.md §6): extremes over the whole run and over a window of load positions,
//! histories at sections, solver statistics, and the state lent to observers after each step.

use nscd::stepper::EnergyLedger;

/// An extreme deflection over the run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Extreme {
    /// Magnitude (m, ≥ 0).
    pub magnitude: f64,
    /// Node position (m).
    pub position: f64,
    /// Time (s).
    pub time: f64,
}

/// The extremes while the load was inside a range of positions (docs/theory.md §8: away from the entry and exit
/// transients of a finite beam started from rest).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WindowExtremes {
    /// The range of load positions [A, B] (m).
    pub load_range: (f64, f64),
    /// Largest downward deflection over nodes and the steps with the load inside the range.
    pub max_downward: Extreme,
    /// Largest upward deflection over the same steps.
    pub max_upward: Extreme,
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
    /// Wall time of the time loop (s).
    pub wall_time: f64,
}

impl SolverStatistics {
    /// The solver's name for reports, `none` without friction sections.
    pub fn solver_name(&self) -> &'static str {
        self.solver.map_or("none", nscd::solver::SolverKind::name)
    }
}

/// What a run reports (docs/theory.md §6).
#[derive(Debug, Clone, PartialEq)]
pub struct RunResult {
    /// Largest downward deflection over nodes and steps.
    pub max_downward: Extreme,
    /// Largest upward deflection over nodes and steps.
    pub max_upward: Extreme,
    /// Largest vertical acceleration magnitude over nodes and steps (m/s², the step's mean (v_{k+1} − v_k)/h, at the
    /// end of the step): the deck acceleration of a bridge (docs/theory.md §10).
    pub max_acceleration: Extreme,
    /// The extremes while the load was inside [`RunSettings::extremes_window`], if one was set.
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
}
