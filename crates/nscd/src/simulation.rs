//! A whole run: the beam under a load crossing it at constant speed, with friction, observed as it goes
//! (docs/theory.md §3, §6).
//!
//! The state is the perturbation from the self-weight equilibrium q₀ = K⁻¹P: with a linear foundation and
//! velocity-driven friction P drops out exactly, so deflections are reported relative to q₀. The load enters at
//! x = 0 (or at the start position of an analytic steady state) and the run ends when it leaves at x = L
//! (t_on), or at a later end time (free vibration). The step is h = Δx/v with the load advance Δx per step.
//!
//! Memory of a run is O(DOFs + sections) plus O(steps) per recorded section history.

use crate::error::{NscdError, Result};
use crate::forcing::MovingLoad;
use crate::solver::{FrictionProblem, SolverKind, SolverSettings, build_solver};
use crate::stepper::{EnergyLedger, Integration, MoreauJean, iteration_matrix};
use crate::system::LinearSystem;
use fem_beam::BeamModel;
use fem_beam::element::hermite;
use fem_beam::reference::InfiniteBeam;
use friction::ContactSet;
use std::time::Instant;

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
}

/// Settings of one run. Defaults: the reference case of docs/theory.md §2 at 200 m/s.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSettings {
    /// Load speed v (m/s) > 0. Default 200.
    pub speed: f64,
    /// Load magnitude F (N), acting downward, ≥ 0. Default 83.4 kN.
    pub load: f64,
    /// θ ∈ [½, 1]. Default ½.
    pub theta: f64,
    /// Load advance per step Δx (m) > 0, so h = Δx/v. Default 0.1 m; must not exceed one element.
    pub load_advance: f64,
    /// Initial state. Default rest.
    pub initial: InitialState,
    /// End time (s); None stops when the load leaves the beam. Must not be before that.
    pub end_time: Option<f64>,
    /// Friction solver settings.
    pub solver: SolverSettings,
    /// Positions (m) whose histories (w, M, friction impulse) are recorded. Default: none.
    pub record_sections: Vec<f64>,
    /// Also track the extremes while the load is inside this range of load positions [A, B] (m), reported in
    /// [`RunResult::window`] beside the whole-run extremes: away from the entry and exit transients they read the
    /// response of a long track. Default: none.
    pub extremes_window: Option<(f64, f64)>,
}

impl Default for RunSettings {
    fn default() -> Self {
        Self {
            speed: 200.0,
            load: 83.4e3,
            theta: 0.5,
            load_advance: 0.1,
            initial: InitialState::Rest,
            end_time: None,
            solver: SolverSettings::default(),
            record_sections: Vec::new(),
            extremes_window: None,
        }
    }
}

fn invalid(field: &'static str, value: f64, allowed: impl Into<String>) -> NscdError {
    NscdError::InvalidField { field, value, allowed: allowed.into() }
}

impl RunSettings {
    /// Check the settings against the model.
    pub fn validate(&self, model: &BeamModel) -> Result<()> {
        let length = model.mesh().length;
        if !(self.speed.is_finite() && self.speed > 0.0) {
            return Err(invalid("speed", self.speed, "must be finite and > 0 (m/s)"));
        }
        if !(self.load.is_finite() && self.load >= 0.0) {
            return Err(invalid("load", self.load, "must be finite and ≥ 0 (N, acting downward)"));
        }
        let l = model.mesh().element_length();
        if !(self.load_advance.is_finite() && self.load_advance > 0.0 && self.load_advance <= l) {
            return Err(invalid(
                "load_advance",
                self.load_advance,
                format!("must be > 0 and ≤ the element length {l} m"),
            ));
        }
        Integration { theta: self.theta, step: self.load_advance / self.speed }.validate()?;
        if !(self.solver.tolerance.is_finite() && self.solver.tolerance > 0.0 && self.solver.tolerance <= 1e-2) {
            return Err(invalid("solver.tolerance", self.solver.tolerance, "must lie in (0, 1e-2]"));
        }
        if self.solver.max_iterations == 0 {
            return Err(invalid("solver.max_iterations", 0.0, "must be ≥ 1"));
        }
        if let InitialState::SteadyState { position } = self.initial
            && !(position.is_finite() && (0.0..length).contains(&position))
        {
            return Err(invalid("initial.position", position, format!("must lie in [0, {length}) m")));
        }
        for &x in &self.record_sections {
            if !(x.is_finite() && (0.0..=length).contains(&x)) {
                return Err(invalid("record_sections", x, format!("must lie on the beam, in [0, {length}] m")));
            }
        }
        if let Some((a, b)) = self.extremes_window
            && !(a.is_finite() && b.is_finite() && a < b)
        {
            let allowed = format!("needs finite load positions A < B (m), got {a}:{b}");
            return Err(invalid("extremes_window", if a.is_finite() { b } else { a }, allowed));
        }
        if let Some(end) = self.end_time
            && !(end.is_finite() && end >= self.crossing_time(length) * (1.0 - 1e-12))
        {
            return Err(invalid(
                "end_time",
                end,
                format!("must be ≥ the crossing time {} s", self.crossing_time(length)),
            ));
        }
        let steps = self.step_count(length);
        if steps > Self::MAX_STEPS as f64 {
            let h = self.load_advance / self.speed;
            let allowed = format!(
                "gives {steps:.3e} time steps of {h:.3e} s; at most {} are allowed (shorten the run or lengthen the \
                 load advance)",
                Self::MAX_STEPS
            );
            return match self.end_time {
                Some(end) => Err(invalid("end_time", end, allowed)),
                None => Err(invalid("load_advance", self.load_advance, allowed)),
            };
        }
        let samples = (steps + 1.0) * self.record_sections.len() as f64;
        if samples > Self::MAX_RECORDED_SAMPLES as f64 {
            return Err(invalid(
                "record_sections",
                self.record_sections.len() as f64,
                format!(
                    "{} sections × {steps:.3e} steps exceed {} recorded samples; record fewer sections",
                    self.record_sections.len(),
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
        let h = self.load_advance / self.speed;
        let crossing = (self.crossing_time(length) / h).round();
        match self.end_time {
            Some(end) => crossing.max((end / h - 1e-9).ceil()),
            None => crossing,
        }
    }

    /// Load position at t = 0 (m).
    pub fn start_position(&self) -> f64 {
        match self.initial {
            InitialState::Rest => 0.0,
            InitialState::SteadyState { position } => position,
        }
    }

    /// Time for the load to reach x = L (s).
    pub fn crossing_time(&self, length: f64) -> f64 {
        (length - self.start_position()) / self.speed
    }
}

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
    /// Impulse bounds a_j = h·F_j (N·s).
    pub bounds: &'a [f64],
    /// The friction solver's report.
    pub report: crate::solver::StepReport,
}

/// Solver statistics of a run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SolverStatistics {
    /// Solver used.
    pub solver: &'static str,
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

/// What a run reports (docs/theory.md §6).
#[derive(Debug, Clone, PartialEq)]
pub struct RunResult {
    /// Largest downward deflection over nodes and steps.
    pub max_downward: Extreme,
    /// Largest upward deflection over nodes and steps.
    pub max_upward: Extreme,
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

/// The coupling length ℓ = (EI·h²θ²/ρA)^¼ (m): sections closer than this are strongly coupled in one step.
pub fn coupling_length(model: &BeamModel, step: f64, theta: f64) -> f64 {
    let beam = model.beam();
    (beam.bending_stiffness() * step * step * theta * theta / beam.mass_per_length()).powf(0.25)
}

/// Resolve [`SolverKind::Auto`]: projection when the sections are spaced wider than twice the coupling length,
/// the banded interior point otherwise.
pub fn resolve_solver(kind: SolverKind, model: &BeamModel, contacts: &ContactSet, step: f64, theta: f64) -> SolverKind {
    if kind != SolverKind::Auto {
        return kind;
    }
    let mut x = contacts.positions().to_vec();
    x.sort_by(f64::total_cmp);
    let spacing = x.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    if spacing < 2.0 * coupling_length(model, step, theta) { SolverKind::InteriorPoint } else { SolverKind::Projection }
}

/// A run of `model` with friction `contacts` under `settings`.
#[derive(Debug, Clone, Copy)]
pub struct Simulation<'a> {
    model: &'a BeamModel,
    contacts: &'a ContactSet,
    settings: &'a RunSettings,
}

struct Recorder {
    position: f64,
    node: usize,
    contact: Option<usize>,
    inside: Vec<InsideSection>,
    history: SectionHistory,
}

impl<'a> Simulation<'a> {
    /// Validate and prepare a run.
    pub fn new(model: &'a BeamModel, contacts: &'a ContactSet, settings: &'a RunSettings) -> Result<Self> {
        settings.validate(model)?;
        Ok(Self { model, contacts, settings })
    }

    /// Initial (q, v) over the free DOFs, per [`RunSettings::initial`].
    pub fn initial_state(&self) -> Result<(Vec<f64>, Vec<f64>)> {
        let dofs = self.model.dofs();
        let n = dofs.free_len();
        match self.settings.initial {
            InitialState::Rest => Ok((vec![0.0; n], vec![0.0; n])),
            InitialState::SteadyState { position } => {
                let infinite = InfiniteBeam::new(self.model.beam(), self.model.foundation())?;
                let state = infinite.steady_state(self.settings.speed, self.settings.load)?;
                let mesh = self.model.mesh();
                let mut q = vec![0.0; dofs.full_len()];
                let mut v = vec![0.0; dofs.full_len()];
                for i in 0..mesh.nodes() {
                    let s = mesh.node_x(i) - position;
                    q[2 * i] = state.deflection(s);
                    q[2 * i + 1] = state.slope(s);
                    v[2 * i] = state.velocity(s);
                    v[2 * i + 1] = state.rotation_rate(s);
                }
                Ok((dofs.reduce(&q), dofs.reduce(&v)))
            }
        }
    }

    /// Integrate and observe.
    pub fn run(&self) -> Result<RunResult> {
        self.run_observed(&mut |_| true)
    }

    /// Integrate, calling `observer` with the borrowed state after every step; the run stops early (with the
    /// results so far) when it returns false.
    pub fn run_observed(&self, observer: &mut dyn FnMut(&StepView<'_>) -> bool) -> Result<RunResult> {
        let (model, settings) = (self.model, self.settings);
        let mesh = *model.mesh();
        let dofs = model.dofs();
        let h = settings.load_advance / settings.speed;
        let integration = Integration { theta: settings.theta, step: h };
        let system = LinearSystem::from_beam(model);
        let m_hat = iteration_matrix(&system, integration);
        let factor = m_hat.factor()?;
        let kind = resolve_solver(settings.solver.kind, model, self.contacts, h, settings.theta);
        let problem = FrictionProblem::new(self.contacts, &m_hat, &factor, h);
        // Coupling through M̂⁻¹ decays like e^{−x/(√2ℓ)}: 30ℓ leaves ~6e-10, and a window that fails the final
        // check is retried wider. Instruction counts over 1000 steps (1, 5, 10 kN/m): 30ℓ is 4–11 % below 40ℓ,
        // 20ℓ and 15ℓ no better than 30ℓ.
        let margin = 30.0 * coupling_length(model, h, settings.theta);
        let solver = build_solver(kind, &problem, &settings.solver, Some(margin))?;
        let (q0, v0) = self.initial_state()?;
        let start = settings.start_position();
        let load = MovingLoad::new(mesh, dofs, settings.load, settings.speed, start);
        let mut stepper = MoreauJean::new(&system, self.contacts, integration, problem, solver, q0, v0);

        let t_on = settings.crossing_time(mesh.length);
        let crossing_steps = (t_on / h).round() as usize;
        let total_steps = match settings.end_time {
            Some(end) => crossing_steps.max((end / h - 1e-9).ceil() as usize),
            None => crossing_steps,
        };
        let deflections = NodalDeflections::new(&mesh, dofs);
        let mut recorders: Vec<Recorder> = settings
            .record_sections
            .iter()
            .map(|&x| {
                let node = mesh.nearest_node(x).unwrap_or(0);
                let l = mesh.element_length();
                let inside = self
                    .contacts
                    .positions()
                    .iter()
                    .enumerate()
                    .filter_map(|(contact, &xs)| {
                        [node.wrapping_sub(1), node].into_iter().filter(|&e| e < mesh.elements).find_map(|element| {
                            let x_a = mesh.node_x(element);
                            (xs > x_a && xs < x_a + l).then(|| InsideSection {
                                element,
                                contact,
                                shape: hermite::shape((xs - x_a) / l, l),
                            })
                        })
                    })
                    .collect();
                Recorder {
                    position: x,
                    node,
                    inside,
                    contact: self.contacts.section_at(x, 1e-9 * mesh.length),
                    history: SectionHistory { position: x, moment_node: mesh.node_x(node), ..Default::default() },
                }
            })
            .collect();
        for r in &mut recorders {
            r.history.impulse = r.contact.map(|_| Vec::with_capacity(total_steps + 1));
            let h = &mut r.history;
            for series in [
                &mut h.time,
                &mut h.load_position,
                &mut h.deflection,
                &mut h.velocity,
                &mut h.acceleration,
                &mut h.moment,
            ] {
                series.reserve(total_steps + 1);
            }
        }
        let mut extremes = (Extreme::default(), Extreme::default());
        let mut window = settings.extremes_window.map(|load_range| WindowExtremes { load_range, ..Default::default() });
        let in_window = |x_load: f64| settings.extremes_window.is_some_and(|(a, b)| (a..=b).contains(&x_load));
        let scan = deflections.scan(stepper.q());
        scan.update(&mut extremes, 0.0);
        if let Some(w) = window.as_mut().filter(|_| in_window(start)) {
            scan.update_window(w, 0.0);
        }
        let mut norm_integral = 0.0;
        let mut previous_norm = scan.norm;
        let mut full = Buffers::new(dofs.full_len());
        for r in &mut recorders {
            full.expand(dofs, stepper.q(), stepper.v());
            let m0 = self.moment_at_node(r.node, &full, &load, &[(0.0, 1.0)], None);
            record(r, 0.0, start, full.motion_at(model, r.position)?, m0, 0.0);
        }

        let clock = Instant::now();
        let (mut iteration_sum, mut max_iterations, mut max_residual) = (0usize, 0usize, 0.0f64);
        let mut sections_sum = 0usize;
        for k in 1..=total_steps {
            let report = stepper.step(&load)?;
            let keep_going = observer(&StepView {
                step: k,
                time: stepper.time,
                load_position: load.position(stepper.time),
                displacement: stepper.q(),
                velocity: stepper.v(),
                previous_velocity: stepper.previous_v(),
                impulses: &stepper.p,
                section_velocities: &stepper.u,
                bounds: stepper.bounds(),
                report,
            });
            iteration_sum += report.iterations;
            sections_sum += report.sections;
            max_iterations = max_iterations.max(report.iterations);
            max_residual = max_residual.max(report.residual);
            let time = stepper.time;
            let scan = deflections.scan(stepper.q());
            scan.update(&mut extremes, time);
            if let Some(w) = window.as_mut().filter(|_| in_window(load.position(time))) {
                scan.update_window(w, time);
            }
            if k <= crossing_steps {
                norm_integral += 0.5 * (scan.norm + previous_norm) * h;
                previous_norm = scan.norm;
            }
            for r in &mut recorders {
                // State after the step with the mean acceleration over it, the load where it now is, and the
                // friction forces p/h of the step.
                full.expand_step(dofs, stepper.q(), stepper.v(), stepper.previous_v(), h);
                let impulse = r.contact.map_or(0.0, |j| stepper.p[j]);
                let moment =
                    self.moment_at_node(r.node, &full, &load, &[(time, 1.0)], Some((&stepper.p, h, &r.inside)));
                record(r, time, load.position(time), full.motion_at(model, r.position)?, moment, impulse);
            }
            if !keep_going {
                break;
            }
        }
        let wall_time = clock.elapsed().as_secs_f64();
        let steps = stepper.steps;
        Ok(RunResult {
            max_downward: extremes.0,
            max_upward: extremes.1,
            window,
            energy: stepper.energy,
            global_norm: if t_on > 0.0 { norm_integral / t_on } else { 0.0 },
            histories: recorders.into_iter().map(|r| r.history).collect(),
            statistics: SolverStatistics {
                solver: if self.contacts.is_empty() { "none" } else { stepper.solver_name() },
                sections: self.contacts.len(),
                steps,
                mean_iterations: if steps > 0 { iteration_sum as f64 / steps as f64 } else { 0.0 },
                max_iterations,
                max_residual,
                mean_sections_solved: if steps > 0 { sections_sum as f64 / steps as f64 } else { 0.0 },
                wall_time,
            },
            step: h,
            section_positions: self.contacts.positions().to_vec(),
            final_displacement: stepper.q().to_vec(),
            final_velocity: stepper.v().to_vec(),
        })
    }

    /// Bending moment at `node` (N·m) from the end forces of its adjacent elements,
    /// f = K_e q_e + C_e q̇_e + M_e q̈_e − f_e (docs/theory.md §6), averaged over the (one or two) adjacent elements. The
    /// element loads f_e are the moving load at the weighted `load_times` and the friction forces p_j/h of the
    /// sections inside the element (`inside`, precomputed with their shape functions); sections on nodes act on w
    /// only and leave the moments unchanged.
    fn moment_at_node(
        &self,
        node: usize,
        full: &Buffers,
        load: &MovingLoad,
        load_times: &[(f64, f64)],
        friction: Option<(&[f64], f64, &[InsideSection])>,
    ) -> f64 {
        let model = self.model;
        let mesh = model.mesh();
        let l = mesh.element_length();
        let ke = model.element_stiffness();
        let me = model.element_mass();
        let mut sum = 0.0;
        let mut count = 0.0;
        for e in [node.wrapping_sub(1), node] {
            if e >= mesh.elements {
                continue;
            }
            let pick = |v: &[f64]| [v[2 * e], v[2 * e + 1], v[2 * e + 2], v[2 * e + 3]];
            let mut f = hermite::apply(&ke, &pick(&full.q));
            let cv = hermite::apply(&model.element_damping_matrix(e), &pick(&full.v));
            let ma = hermite::apply(&me, &pick(&full.a));
            let (x_a, x_b) = (mesh.node_x(e), mesh.node_x(e + 1));
            let mut external = [0.0; 4];
            for &(time, weight) in load_times {
                let x_load = load.position(time);
                // The element owning the load, as Mesh::locate decides: [x_a, x_b), the last one closed.
                let owns = (x_a..x_b).contains(&x_load) || (e + 1 == mesh.elements && x_load == x_b);
                if weight != 0.0 && owns {
                    let n = hermite::shape((x_load - x_a) / l, l);
                    (0..4).for_each(|k| external[k] -= weight * load.force * n[k]);
                }
            }
            if let Some((p, h, inside)) = friction {
                for section in inside.iter().filter(|s| s.element == e) {
                    (0..4).for_each(|k| external[k] += p[section.contact] / h * section.shape[k]);
                }
            }
            (0..4).for_each(|k| f[k] += cv[k] + ma[k] - external[k]);
            if e + 1 == node {
                sum += f[3];
            } else {
                sum -= f[1];
            }
            count += 1.0;
        }
        sum / count
    }
}

/// The nodal deflections of the free w DOFs, read in one pass per step for the extremes and for W̄ (constrained
/// nodes have w = 0: they never set an extreme and add nothing to the norm).
struct NodalDeflections {
    /// (free DOF index, node x (m), trapezoid weight (m)) of every node whose w is free.
    nodes: Vec<(usize, f64, f64)>,
}

/// What one pass over the deflections finds.
struct DeflectionScan {
    /// Lowest w (m) and its node x, first such node.
    lowest: (f64, f64),
    /// Highest w (m) and its node x, first such node.
    highest: (f64, f64),
    /// ∫|w| dx by the trapezoid rule over the nodes (m²).
    norm: f64,
}

impl NodalDeflections {
    fn new(mesh: &fem_beam::Mesh, dofs: &fem_beam::DofMap) -> Self {
        let last = mesh.nodes() - 1;
        let l = mesh.element_length();
        let nodes = (0..=last)
            .filter_map(|i| {
                let weight = if i == 0 || i == last { 0.5 * l } else { l };
                dofs.free_index(2 * i).map(|d| (d, mesh.node_x(i), weight))
            })
            .collect();
        Self { nodes }
    }

    fn scan(&self, q: &[f64]) -> DeflectionScan {
        let mut scan = DeflectionScan { lowest: (0.0, 0.0), highest: (0.0, 0.0), norm: 0.0 };
        for &(d, x, weight) in &self.nodes {
            let w = q[d];
            if w < scan.lowest.0 {
                scan.lowest = (w, x);
            }
            if w > scan.highest.0 {
                scan.highest = (w, x);
            }
            scan.norm += weight * w.abs();
        }
        scan
    }
}

impl DeflectionScan {
    /// Keep the record extremes (downward, upward) up to date at `time`.
    fn update(&self, extremes: &mut (Extreme, Extreme), time: f64) {
        if -self.lowest.0 > extremes.0.magnitude {
            extremes.0 = Extreme { magnitude: -self.lowest.0, position: self.lowest.1, time };
        }
        if self.highest.0 > extremes.1.magnitude {
            extremes.1 = Extreme { magnitude: self.highest.0, position: self.highest.1, time };
        }
    }

    /// The same for the extremes of a load-position window.
    fn update_window(&self, window: &mut WindowExtremes, time: f64) {
        let mut pair = (window.max_downward, window.max_upward);
        self.update(&mut pair, time);
        (window.max_downward, window.max_upward) = pair;
    }
}

/// A friction section strictly inside an element next to a recorded node.
#[derive(Debug, Clone, Copy)]
struct InsideSection {
    element: usize,
    contact: usize,
    shape: [f64; 4],
}

fn record(r: &mut Recorder, time: f64, load_position: f64, motion: [f64; 3], moment: f64, impulse: f64) {
    r.history.time.push(time);
    r.history.load_position.push(load_position);
    r.history.deflection.push(motion[0]);
    r.history.velocity.push(motion[1]);
    r.history.acceleration.push(motion[2]);
    r.history.moment.push(moment);
    if let Some(series) = r.history.impulse.as_mut() {
        series.push(impulse);
    }
}

/// Full-DOF scratch vectors for section results.
struct Buffers {
    q: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    free: Vec<f64>,
}

impl Buffers {
    fn new(n: usize) -> Self {
        Self { q: vec![0.0; n], v: vec![0.0; n], a: vec![0.0; n], free: Vec::new() }
    }

    fn expand(&mut self, dofs: &fem_beam::DofMap, q: &[f64], v: &[f64]) {
        dofs.expand_into(q, &mut self.q);
        dofs.expand_into(v, &mut self.v);
        self.a.iter_mut().for_each(|a| *a = 0.0);
    }

    /// Deflection, velocity and acceleration at `x` (m, m/s, m/s²), interpolated with the Hermite shapes.
    fn motion_at(&self, model: &BeamModel, x: f64) -> Result<[f64; 3]> {
        Ok([model.deflection_at(&self.q, x)?, model.deflection_at(&self.v, x)?, model.deflection_at(&self.a, x)?])
    }

    /// The state after a step: q_{k+1}, v_{k+1} and the mean acceleration (v_{k+1} − v_k)/h.
    fn expand_step(&mut self, dofs: &fem_beam::DofMap, q: &[f64], v: &[f64], v_before: &[f64], h: f64) {
        dofs.expand_into(q, &mut self.q);
        dofs.expand_into(v, &mut self.v);
        self.free.resize(v.len(), 0.0);
        for i in 0..v.len() {
            self.free[i] = (v[i] - v_before[i]) / h;
        }
        dofs.expand_into(&self.free, &mut self.a);
    }
}
