//! What a run records after each step, each record behind the one [`Record`] trait: the deflection extremes, the
//! acceleration and W̄ ([`DeflectionRecord`]), the section histories ([`SectionRecords`]), the solver's statistics
//! ([`SolverTally`]) and the vehicles' wheels and bodies ([`super::vehicles::VehicleObserver`]).

use super::observers::{Buffers, DeflectionScan, InsideSection, NodalDeflections, Recorder, record};
use super::results::{SectionHistory, SolverStatistics, WindowExtremes, WorkStatistics};
use super::settings::RecordSettings;
use crate::error::Result;
use crate::moving_load::MovingLoad;
use crate::placed::PlacedInteractions;
use fem_beam::BeamModel;
use fem_beam::section::Motion;
use fem_beam::{DeflectionExtremes, Extreme};
use nscd::solver::StepReport;

/// The state after step k, as every record reads it.
pub(crate) struct StepState<'s> {
    /// Step index k (1-based).
    pub(crate) step: usize,
    /// t_{k+1} (s).
    pub(crate) time: f64,
    /// h (s).
    pub(crate) h: f64,
    /// q_{k+1}, v_{k+1} and v_k of the whole system (the beam's free DOFs first, `beam` of them).
    pub(crate) q: &'s [f64],
    pub(crate) v: &'s [f64],
    pub(crate) previous_v: &'s [f64],
    pub(crate) beam: usize,
    /// The step's impulses (N·s): the fixed interactions first, `fixed` of them, then the wheels.
    pub(crate) impulses: &'s [f64],
    pub(crate) fixed: usize,
    /// The moving forces, where they stand at `time`.
    pub(crate) load: &'s MovingLoad,
    /// The wheels' element loads on the beam (element, nodal forces), for the moments at recorded nodes.
    pub(crate) wheel_loads: &'s [(usize, [f64; 4])],
    /// The solver's report of the step.
    pub(crate) report: StepReport,
}

/// Something a run records after each step.
pub(crate) trait Record {
    /// Book the state after a step.
    fn record(&mut self, step: &StepState<'_>) -> Result<()>;
}

/// The extremes of the nodal deflections (whole run, and while the load is in the window), the largest nodal
/// acceleration and W̄'s integral over the crossing.
pub(super) struct DeflectionRecord {
    deflections: NodalDeflections,
    pub(super) extremes: DeflectionExtremes,
    pub(super) acceleration: Extreme,
    /// The extremes while the load is in the window of load positions, if one is set (its range with them).
    pub(super) window: Option<WindowExtremes>,
    /// ∫‖w‖ dt over the crossing (m²·s) and the last norm of it.
    pub(super) norm_integral: f64,
    previous_norm: f64,
    crossing_steps: usize,
}

impl DeflectionRecord {
    /// The record of `model`'s deflections from the beam's initial displacement `q0` with the load at `start` (m).
    pub(super) fn new(
        model: &BeamModel,
        record: &RecordSettings,
        q0: &[f64],
        start: f64,
        crossing_steps: usize,
    ) -> Self {
        let deflections = NodalDeflections::new(model.mesh(), model.dofs(), record.extremes_nodes);
        let mut this = Self {
            extremes: DeflectionExtremes::default(),
            acceleration: Extreme::default(),
            window: record.extremes_window.map(|load_range| WindowExtremes { load_range, ..Default::default() }),
            norm_integral: 0.0,
            previous_norm: 0.0,
            crossing_steps,
            deflections,
        };
        let scan = this.deflections.scan(q0);
        this.previous_norm = scan.norm;
        this.update(&scan, start, 0.0);
        this
    }

    /// Keep the whole-run extremes, and the window's when the load at `load_position` (m) is inside it.
    fn update(&mut self, scan: &DeflectionScan, load_position: f64, time: f64) {
        scan.update(&mut self.extremes, time);
        if let Some(w) = self.window.as_mut().filter(|w| (w.load_range.0..=w.load_range.1).contains(&load_position)) {
            scan.update_window(w, time);
        }
    }
}

impl Record for DeflectionRecord {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        let scan = self.deflections.scan(&s.q[..s.beam]);
        self.update(&scan, s.load.position(s.time), s.time);
        let (a, x) = self.deflections.largest_acceleration(s.v, s.previous_v, s.h);
        self.acceleration.raise(a, x, s.time);
        if s.step <= self.crossing_steps {
            self.norm_integral += 0.5 * (scan.norm + self.previous_norm) * s.h;
            self.previous_norm = scan.norm;
        }
        Ok(())
    }
}

/// The histories of the recorded sections: w, ẇ, ẅ (the step's mean), the bending moment at the nearest node and
/// the friction impulse of a section there.
pub(super) struct SectionRecords<'a> {
    model: &'a BeamModel,
    recorders: Vec<Recorder>,
    full: Buffers,
}

impl<'a> SectionRecords<'a> {
    /// Recorders at `sections` (m) of `model` with friction `interactions`, their series reserved for `steps` steps.
    pub(super) fn new(model: &'a BeamModel, interactions: &PlacedInteractions, sections: &[f64], steps: usize) -> Self {
        let (mesh, beam) = (model.mesh(), model.discretisation());
        let recorders = sections
            .iter()
            .map(|&x| {
                let node = mesh.nearest_node(x).unwrap_or(0);
                let contact = interactions.section_at(x, 1e-9 * mesh.length);
                let mut history = SectionHistory { position: x, moment_node: mesh.node_x(node), ..Default::default() };
                history.impulse = contact.map(|_| Vec::with_capacity(steps + 1));
                for series in [
                    &mut history.time,
                    &mut history.load_position,
                    &mut history.deflection,
                    &mut history.velocity,
                    &mut history.acceleration,
                    &mut history.moment,
                ] {
                    series.reserve(steps + 1);
                }
                Recorder { position: x, node, inside: inside_sections(&beam, interactions, node), contact, history }
            })
            .collect();
        Self { model, recorders, full: Buffers::new(model.dofs().full_len()) }
    }

    /// Record the initial state: the beam's q₀, v₀ (free DOFs) with `load` at `start` (m), at rest in acceleration.
    pub(super) fn start(&mut self, (q, v): (&[f64], &[f64]), load: &MovingLoad, start: f64) -> Result<()> {
        let dofs = self.model.dofs();
        for r in &mut self.recorders {
            self.full.expand(dofs, q, v);
            let m0 = moment_at_node(self.model, r.node, &self.full, load, 0.0, None, &[]);
            record(r, 0.0, start, self.full.motion_at(self.model, r.position)?, m0, 0.0);
        }
        Ok(())
    }

    /// The histories, in the order of the sections.
    pub(super) fn finish(self) -> Vec<SectionHistory> {
        self.recorders.into_iter().map(|r| r.history).collect()
    }
}

impl Record for SectionRecords<'_> {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        let (dofs, nb) = (self.model.dofs(), s.beam);
        for r in &mut self.recorders {
            // State after the step with the mean acceleration over it, the load where it now is, and the
            // friction forces p/h of the step.
            self.full.expand_step(dofs, &s.q[..nb], &s.v[..nb], &s.previous_v[..nb], s.h);
            let impulse = r.contact.map_or(0.0, |j| s.impulses[j]);
            let friction = Some((&s.impulses[..s.fixed], s.h, r.inside.as_slice()));
            let moment = moment_at_node(self.model, r.node, &self.full, s.load, s.time, friction, s.wheel_loads);
            let motion = self.full.motion_at(self.model, r.position)?;
            record(r, s.time, s.load.position(s.time), motion, moment, impulse);
        }
        Ok(())
    }
}

/// The friction sections strictly inside the elements next to `node`, with their shape functions there.
fn inside_sections(
    beam: &fem_beam::Discretisation,
    interactions: &PlacedInteractions,
    node: usize,
) -> Vec<InsideSection> {
    let (mesh, element_shape) = (beam.mesh(), beam.element());
    let l = mesh.element_length();
    let elements = [node.wrapping_sub(1), node].into_iter().filter(|&e| e < mesh.elements);
    let inside = |(contact, &xs): (usize, &f64)| {
        elements.clone().find_map(|element| {
            let x_a = mesh.node_x(element);
            (xs > x_a && xs < x_a + l).then(|| InsideSection {
                element,
                contact,
                shape: element_shape.shape((xs - x_a) / l),
            })
        })
    };
    interactions.positions().iter().enumerate().filter_map(inside).collect()
}

/// Bending moment at `node` (N·m) from the end forces of its adjacent elements
/// ([`BeamModel::element_end_forces`], docs/theory.md §6), averaged over the (one or two) adjacent elements. The
/// element loads are the moving load where it stands at `time` and the friction forces p_j/h of the sections
/// inside the element (`inside`, precomputed with their shape functions) and the wheels' contact forces
/// (`wheels`: element, nodal forces); sections on nodes act on w only and leave the moments unchanged.
fn moment_at_node(
    model: &BeamModel,
    node: usize,
    full: &Buffers,
    load: &MovingLoad,
    time: f64,
    friction: Option<(&[f64], f64, &[InsideSection])>,
    wheels: &[(usize, [f64; 4])],
) -> f64 {
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

/// The solver's statistics over the steps: iterations, sections re-solved, the largest residual, fallbacks.
#[derive(Default)]
pub(super) struct SolverTally {
    iterations: usize,
    max_iterations: usize,
    /// The work summed over the steps, and the largest factorisations and events of one step.
    work: nscd::StepWork,
    max_factorisations: usize,
    max_events: usize,
    sections: usize,
    max_residual: f64,
    statistics: SolverStatistics,
}

impl Record for SolverTally {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        let report = &s.report;
        self.statistics.count_fallback(report);
        self.iterations += report.iterations;
        self.sections += report.sections;
        self.max_iterations = self.max_iterations.max(report.iterations);
        self.work += report.work;
        self.max_factorisations = self.max_factorisations.max(report.work.factorisations);
        self.max_events = self.max_events.max(report.work.events);
        self.max_residual = self.max_residual.max(report.residual);
        Ok(())
    }
}

impl SolverTally {
    /// The statistics of `steps` steps by `solver` on `sections` fixed sections, the loop having taken `wall_time`
    /// (s).
    pub(super) fn finish(
        self,
        solver: Option<nscd::solver::SolverKind>,
        sections: usize,
        steps: usize,
        wall_time: f64,
    ) -> SolverStatistics {
        let mean = |sum: usize| if steps > 0 { sum as f64 / steps as f64 } else { 0.0 };
        SolverStatistics {
            solver,
            sections,
            steps,
            mean_iterations: mean(self.iterations),
            max_iterations: self.max_iterations,
            max_residual: self.max_residual,
            mean_sections_solved: mean(self.sections),
            work: WorkStatistics {
                mean_factorisations: mean(self.work.factorisations),
                max_factorisations: self.max_factorisations,
                mean_solves: mean(self.work.solves),
                mean_events: mean(self.work.events),
                max_events: self.max_events,
                repairs: self.work.repairs,
            },
            wall_time,
            ..self.statistics
        }
    }
}
