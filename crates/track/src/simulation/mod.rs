//! A whole run: the beam under a load crossing it at constant speed, with friction, observed as it goes
//! (docs/theory.md §3, §6).
//!
//! The state is the perturbation from the self-weight equilibrium q₀ = K⁻¹P: with a linear foundation and
//! velocity-driven friction P drops out exactly, so deflections are reported relative to q₀. The load enters at
//! x = 0 (or at the start position of an analytic steady state) and the run ends when it leaves at x = L
//! (t_on), or at a later end time (free vibration). The step is h = Δx/v with the load advance Δx per step.
//!
//! Memory of a run is O(DOFs + sections) plus O(steps) per recorded section history.

mod observers;
mod results;
mod settings;
mod vehicles;

pub use results::{
    BodyResult, Extreme, FallbackCount, LossOfContact, RunResult, SectionHistory, SolverStatistics, StepView,
    VehicleResults, WheelHistory, WheelResult, WindowExtremes,
};
pub(crate) use settings::counts_for_extremes;
pub use settings::{InitialState, IntegrationSettings, MovingLoadSettings, RecordSettings, RunSettings};
pub use vehicles::{IMPACT_WINDOW, LOSS_OF_CONTACT};

use crate::error::Result;
use crate::moving_load::MovingLoad;
use crate::system::beam_system;
use fem_beam::BeamModel;
use fem_beam::Train;
use fem_beam::element::hermite;
use fem_beam::reference::InfiniteBeam;
use fem_beam::section::Motion;
use friction::InteractionSet;
use nscd::solver::{SolverKind, SolverSettings};
use nscd::stepper::{Integration, MoreauJean};
use nscd::{Forcing, Interactions};
use observers::{Buffers, InsideSection, NodalDeflections, Recorder, record};
use std::time::Instant;
use vehicles::Coupling;

/// The coupling length ℓ = (EI·h²θ²/ρA)^¼ (m): sections closer than this are strongly coupled in one step.
pub fn coupling_length(model: &BeamModel, step: f64, theta: f64) -> f64 {
    let beam = model.beam();
    (beam.bending_stiffness() * step * step * theta * theta / beam.mass_per_length()).powf(0.25)
}

/// Resolve [`SolverKind::Auto`]: projection when the sections are spaced wider than twice the coupling length or
/// vehicles run (`moving`: their wheel contacts change rows every step, which the interior point does not take),
/// the banded interior point otherwise.
pub fn resolve_solver(
    kind: SolverKind,
    model: &BeamModel,
    interactions: &InteractionSet,
    (step, theta): (f64, f64),
    moving: bool,
) -> SolverKind {
    if kind != SolverKind::Auto {
        return kind;
    }
    if moving {
        return SolverKind::Projection;
    }
    let mut x = interactions.positions().to_vec();
    x.sort_by(f64::total_cmp);
    let spacing = x.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    if spacing < 2.0 * coupling_length(model, step, theta) { SolverKind::InteriorPoint } else { SolverKind::Projection }
}

/// A run of `model` with friction `interactions` under `settings`.
#[derive(Debug, Clone, Copy)]
pub struct Simulation<'a> {
    model: &'a BeamModel,
    interactions: &'a InteractionSet,
    settings: &'a RunSettings,
}

impl<'a> Simulation<'a> {
    /// Validate and prepare a run.
    pub fn new(model: &'a BeamModel, interactions: &'a InteractionSet, settings: &'a RunSettings) -> Result<Self> {
        settings.validate(model)?;
        Ok(Self { model, interactions, settings })
    }

    /// Initial (q, v) over the free DOFs, per [`MovingLoadSettings::initial`]: a static start's deflection moves
    /// with the loads ([`convected_velocity`]).
    pub fn initial_state(&self) -> Result<(Vec<f64>, Vec<f64>)> {
        let dofs = self.model.dofs();
        let n = dofs.free_len();
        match self.settings.moving.initial {
            InitialState::Rest => Ok((vec![0.0; n], vec![0.0; n])),
            InitialState::Static { position } => {
                // K q = f of the loads standing there (the vehicles' static wheel loads with vehicles).
                let mesh = self.model.mesh();
                let mut q = self.settings.moving.train().load_vector(mesh, position).to_free(mesh, dofs);
                self.model.stiffness().factor()?.solve_in_place(&mut q);
                let v = convected_velocity(self.model, &q, self.settings.moving.speed);
                Ok((q, v))
            }
            InitialState::SteadyState { position } => {
                // The infinite beam is linear: a train's steady state is the sum of its axles' (docs/theory.md §8,
                // §10), each shifted by its offset. Patches have no closed form here.
                let train = self.settings.moving.train();
                if !train.patches.is_empty() {
                    return Err(crate::error::invalid(
                        "initial.position",
                        position,
                        "the steady-state start takes trains of axles only (no load patches)",
                    ));
                }
                let infinite = InfiniteBeam::new(self.model.beam(), self.model.foundation())?;
                let mesh = self.model.mesh();
                let mut q = vec![0.0; dofs.full_len()];
                let mut v = vec![0.0; dofs.full_len()];
                for axle in &train.axles {
                    let state = infinite.steady_state(self.settings.moving.speed, axle.force)?;
                    for i in 0..mesh.nodes() {
                        let s = mesh.node_x(i) - (position - axle.offset);
                        q[2 * i] += state.deflection(s);
                        q[2 * i + 1] += state.slope(s);
                        v[2 * i] += state.velocity(s);
                        v[2 * i + 1] += state.rotation_rate(s);
                    }
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
        let h = settings.integration.load_advance / settings.moving.speed;
        let integration = Integration { theta: settings.integration.theta, step: h };
        let theta = settings.integration.theta;
        let start = settings.start_position();
        let coupling = match &settings.moving.vehicles {
            Some(vehicles) => {
                let (beam_q0, beam_v0) = self.initial_state()?;
                let motion = (start, settings.moving.speed);
                let beam = (beam_q0.as_slice(), beam_v0.as_slice());
                Some(Coupling::new(model, vehicles, beam, motion, theta, settings.record.extremes_nodes)?)
            }
            None => None,
        };
        let moving = coupling.is_some();
        let kind = resolve_solver(settings.integration.solver.kind, model, self.interactions, (h, theta), moving);
        // Coupling through M̂⁻¹ decays like e^{−x/(√2ℓ)}: 30ℓ leaves ~6e-10, and a window that fails the final
        // check is retried wider. Instruction counts over 1000 steps (1, 5, 10 kN/m): 30ℓ is 4–11 % below 40ℓ,
        // 20ℓ and 15ℓ no better than 30ℓ.
        let margin = 30.0 * coupling_length(model, h, theta);
        // With vehicles the moving forces are none: the weights load the vehicles, the wheels the rail.
        let train = if moving {
            Train { name: String::new(), axles: Vec::new(), patches: Vec::new() }
        } else {
            settings.moving.train()
        };
        let load = MovingLoad::train(mesh, dofs, train, settings.moving.speed, start);
        let solver_settings = SolverSettings { kind, ..settings.integration.solver };
        let (mut stepper, mut vehicle_observer, weights) = match coupling {
            Some(c) => {
                let interactions = Interactions { fixed: self.interactions.clone(), moving: c.contacts };
                let stepper = MoreauJean::build(
                    &c.system,
                    interactions,
                    integration,
                    &solver_settings,
                    Some(margin),
                    c.q0,
                    c.v0,
                )?;
                (stepper, Some(c.observer), Some(c.weights))
            }
            None => {
                let (q0, v0) = self.initial_state()?;
                let system = beam_system(model);
                let interactions = self.interactions.clone();
                (
                    MoreauJean::build(&system, interactions, integration, &solver_settings, Some(margin), q0, v0)?,
                    None,
                    None,
                )
            }
        };
        let forcing: &dyn Forcing = match &weights {
            Some(w) => w,
            None => &load,
        };
        let nb = dofs.free_len();
        let fixed = self.interactions.len();

        let t_on = settings.crossing_time(mesh.length);
        let crossing_steps = (t_on / h).round() as usize;
        let total_steps = match settings.integration.end_time {
            Some(end) => crossing_steps.max((end / h - 1e-9).ceil() as usize),
            None => crossing_steps,
        };
        let deflections = NodalDeflections::new(&mesh, dofs, settings.record.extremes_nodes);
        let mut recorders: Vec<Recorder> = settings
            .record
            .sections
            .iter()
            .map(|&x| {
                let node = mesh.nearest_node(x).unwrap_or(0);
                let l = mesh.element_length();
                let inside = self
                    .interactions
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
                    contact: self.interactions.section_at(x, 1e-9 * mesh.length),
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
        let mut acceleration = Extreme::default();
        let mut window =
            settings.record.extremes_window.map(|load_range| WindowExtremes { load_range, ..Default::default() });
        let in_window = |x_load: f64| settings.record.extremes_window.is_some_and(|(a, b)| (a..=b).contains(&x_load));
        let scan = deflections.scan(&stepper.q()[..nb]);
        scan.update(&mut extremes, 0.0);
        if let Some(w) = window.as_mut().filter(|_| in_window(start)) {
            scan.update_window(w, 0.0);
        }
        let mut norm_integral = 0.0;
        let mut previous_norm = scan.norm;
        let mut full = Buffers::new(dofs.full_len());
        let mut wheel_loads: Vec<(usize, [f64; 4])> = Vec::new();
        if let Some(observer) = vehicle_observer.as_mut() {
            observer.reserve(total_steps);
        }
        for r in &mut recorders {
            full.expand(dofs, &stepper.q()[..nb], &stepper.v()[..nb]);
            let m0 = self.moment_at_node(r.node, &full, &load, 0.0, None, &[]);
            record(r, 0.0, start, full.motion_at(model, r.position)?, m0, 0.0);
        }

        let clock = Instant::now();
        let (mut iteration_sum, mut max_iterations, mut max_residual) = (0usize, 0usize, 0.0f64);
        let mut sections_sum = 0usize;
        let mut statistics = SolverStatistics::default();
        for k in 1..=total_steps {
            let report = stepper.step(forcing)?;
            statistics.count_fallback(&report);
            let keep_going = observer(&StepView {
                step: k,
                time: stepper.time,
                load_position: load.position(stepper.time),
                displacement: &stepper.q()[..nb],
                velocity: &stepper.v()[..nb],
                previous_velocity: &stepper.previous_v()[..nb],
                impulses: &stepper.p,
                section_velocities: &stepper.u,
                law: stepper.law(),
                report,
            });
            iteration_sum += report.iterations;
            sections_sum += report.sections;
            max_iterations = max_iterations.max(report.iterations);
            max_residual = max_residual.max(report.residual);
            let time = stepper.time;
            let scan = deflections.scan(&stepper.q()[..nb]);
            scan.update(&mut extremes, time);
            let (a, x) = deflections.largest_acceleration(stepper.v(), stepper.previous_v(), h);
            if a > acceleration.magnitude {
                acceleration = Extreme { magnitude: a, position: x, time };
            }
            if let Some(w) = window.as_mut().filter(|_| in_window(load.position(time))) {
                scan.update_window(w, time);
            }
            if k <= crossing_steps {
                norm_integral += 0.5 * (scan.norm + previous_norm) * h;
                previous_norm = scan.norm;
            }
            if let Some(observer) = vehicle_observer.as_mut() {
                let velocities = (stepper.v(), stepper.previous_v());
                observer.observe(time, h, &stepper.p[fixed..], stepper.q(), velocities);
                if !recorders.is_empty() {
                    wheel_loads.clear();
                    wheel_loads.extend(observer.element_loads(model, time, &stepper.p[fixed..], h));
                }
            }
            for r in &mut recorders {
                // State after the step with the mean acceleration over it, the load where it now is, and the
                // friction forces p/h of the step.
                full.expand_step(dofs, &stepper.q()[..nb], &stepper.v()[..nb], &stepper.previous_v()[..nb], h);
                let impulse = r.contact.map_or(0.0, |j| stepper.p[j]);
                let friction = Some((&stepper.p[..fixed], h, r.inside.as_slice()));
                let moment = self.moment_at_node(r.node, &full, &load, time, friction, &wheel_loads);
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
            max_acceleration: acceleration,
            window,
            energy: stepper.energy,
            global_norm: if t_on > 0.0 { norm_integral / t_on } else { 0.0 },
            histories: recorders.into_iter().map(|r| r.history).collect(),
            statistics: SolverStatistics {
                solver: (!self.interactions.is_empty() || moving).then(|| stepper.solver_kind()),
                sections: self.interactions.len(),
                steps,
                mean_iterations: if steps > 0 { iteration_sum as f64 / steps as f64 } else { 0.0 },
                max_iterations,
                max_residual,
                mean_sections_solved: if steps > 0 { sections_sum as f64 / steps as f64 } else { 0.0 },
                wall_time,
                ..statistics
            },
            step: h,
            section_positions: self.interactions.positions().to_vec(),
            final_displacement: stepper.q()[..nb].to_vec(),
            final_velocity: stepper.v()[..nb].to_vec(),
            vehicles: vehicle_observer.map(|o| o.finish(&stepper.energy)),
        })
    }

    /// Bending moment at `node` (N·m) from the end forces of its adjacent elements
    /// ([`BeamModel::element_end_forces`], docs/theory.md §6), averaged over the (one or two) adjacent elements. The
    /// element loads are the moving load where it stands at `time` and the friction forces p_j/h of the sections
    /// inside the element (`inside`, precomputed with their shape functions) and the wheels' contact forces
    /// (`wheels`: element, nodal forces); sections on nodes act on w only and leave the moments unchanged.
    fn moment_at_node(
        &self,
        node: usize,
        full: &Buffers,
        load: &MovingLoad,
        time: f64,
        friction: Option<(&[f64], f64, &[InsideSection])>,
        wheels: &[(usize, [f64; 4])],
    ) -> f64 {
        let model = self.model;
        let mesh = model.mesh();
        let motion = Motion { velocity: Some(&full.v), acceleration: Some(&full.a) };
        let mut sum = 0.0;
        let mut count = 0.0;
        for e in [node.wrapping_sub(1), node] {
            if e >= mesh.elements {
                continue;
            }
            let mut external = [0.0; 4];
            for point in load.element_loads(time).filter(|p| p.element == e) {
                (0..4).for_each(|k| external[k] += point.nodal[k]);
            }
            for (_, nodal) in wheels.iter().filter(|w| w.0 == e) {
                (0..4).for_each(|k| external[k] += nodal[k]);
            }
            if let Some((p, h, inside)) = friction {
                for section in inside.iter().filter(|s| s.element == e) {
                    (0..4).for_each(|k| external[k] += p[section.contact] / h * section.shape[k]);
                }
            }
            let f = model.element_end_forces(e, &full.q, motion, &external);
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

/// The velocity of a deflection `q` (free DOFs) carried along the beam at `speed` without changing shape, as the
/// static bowl under loads moving at that speed is (quasi-statically): ẇ = −V ∂w/∂x, θ̇ = −V ∂θ/∂x, with ∂w/∂x the
/// node's rotation θ and ∂θ/∂x by central differences of the rotations (one-sided at the ends). Started at rest
/// instead, the bowl would stand still while the loads leave it, and every wheel on its slopes would be thrown.
fn convected_velocity(model: &BeamModel, q: &[f64], speed: f64) -> Vec<f64> {
    let dofs = model.dofs();
    let mesh = model.mesh();
    let nodes = mesh.nodes();
    let value = |full: usize| dofs.free_index(full).map_or(0.0, |i| q[i]);
    let rotation: Vec<f64> = (0..nodes).map(|i| value(2 * i + 1)).collect();
    let l = mesh.element_length();
    let mut v = vec![0.0; q.len()];
    for i in 0..nodes {
        let (a, b) = (i.saturating_sub(1), (i + 1).min(nodes - 1));
        let curvature = (rotation[b] - rotation[a]) / ((b - a) as f64 * l);
        if let Some(k) = dofs.free_index(2 * i) {
            v[k] = -speed * rotation[i];
        }
        if let Some(k) = dofs.free_index(2 * i + 1) {
            v[k] = -speed * curvature;
        }
    }
    v
}
