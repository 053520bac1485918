//! The one loop every run steps through (docs/theory.md §5–§6): a run across the finite beam and the co-moving
//! window alike step the integrator under the moving loads (or the vehicles' weights) plus the fixed interactions'
//! preload, lend the state to an observer, book it in their [`Record`]s — the vehicles' among them — and then do
//! what their kind of run does between two steps: nothing on a fixed track, the window's shift on the co-moving one.

use super::records::{Record, StepState};
use super::results::StepView;
use super::setup::Setup;
use crate::error::Result;
use crate::placed::PlacedInteractions;
use fem_beam::BeamModel;
use nscd::Forcing;
use nscd::forcing::{Constant, WithConstant};
use nscd::solver::StepReport;

/// A run set up and stepping: the integrator with what loads it, and what every step hands its records.
pub(crate) struct Stepping<'a> {
    /// The integrator, the moving load, the vehicles' weights and observer, the step and the step counts.
    pub(crate) setup: Setup,
    model: &'a BeamModel,
    preload: Constant,
    /// The fixed interactions (their impulses come first), the beam's free DOFs (first in the state).
    fixed: usize,
    beam: usize,
    /// Whether a record reads the wheels' element loads (the section histories' moments), and their buffer.
    wheel_loads_needed: bool,
    wheel_loads: Vec<(usize, [f64; 4])>,
}

impl<'a> Stepping<'a> {
    /// Step `setup` on `model` with its fixed `interactions`; `wheel_loads_needed` when a record reads the wheels'
    /// element loads.
    pub(crate) fn new(
        model: &'a BeamModel,
        interactions: &PlacedInteractions,
        setup: Setup,
        wheel_loads_needed: bool,
    ) -> Self {
        Self {
            setup,
            model,
            preload: Constant { force: interactions.preload().to_vec() },
            fixed: interactions.len(),
            beam: model.dofs().free_len(),
            wheel_loads_needed,
            wheel_loads: Vec::new(),
        }
    }

    /// The beam's free DOFs of the system's state (q, v).
    pub(crate) fn beam_state(&self) -> (&[f64], &[f64]) {
        let stepper = &self.setup.stepper;
        (&stepper.q()[..self.beam], &stepper.v()[..self.beam])
    }

    /// One step under the loads — the moving forces, or the vehicles' weights — and the interactions' preload.
    fn step(&mut self) -> Result<StepReport> {
        let Setup { stepper, load, weights, .. } = &mut self.setup;
        let loads: &dyn Forcing = match weights {
            Some(weights) => weights,
            None => load,
        };
        Ok(match self.preload.force.is_empty() {
            true => stepper.step(loads)?,
            false => stepper.step(&WithConstant { forcing: loads, constant: &self.preload })?,
        })
    }

    /// Steps 1..=`steps`: each lent to `observer` (which ends the run, after the step is booked, by returning
    /// false), booked by the vehicles' record and `records`, then handed to `between` (the run's own work between
    /// two steps, e.g. the window's shift).
    pub(crate) fn run(
        &mut self,
        steps: usize,
        records: &mut [&mut dyn Record],
        observer: &mut dyn FnMut(&StepView<'_>) -> bool,
        between: &mut dyn FnMut(&mut Self, usize) -> Result<()>,
    ) -> Result<()> {
        if let Some(vehicles) = self.setup.vehicles.as_mut() {
            vehicles.reserve(steps);
        }
        for k in 1..=steps {
            let report = self.step()?;
            let keep_going = self.book(k, report, records, observer)?;
            between(self, k)?;
            if !keep_going {
                break;
            }
        }
        Ok(())
    }

    /// Lend the state after step `k` to `observer` and book it; whether the observer wants more steps.
    fn book(
        &mut self,
        k: usize,
        report: StepReport,
        records: &mut [&mut dyn Record],
        observer: &mut dyn FnMut(&StepView<'_>) -> bool,
    ) -> Result<bool> {
        let Setup { stepper, load, vehicles, step: h, .. } = &mut self.setup;
        let (time, impulses, nb) = (stepper.time, stepper.p.as_slice(), self.beam);
        let keep_going = observer(&StepView {
            step: k,
            time,
            load_position: load.position(time),
            displacement: &stepper.q()[..nb],
            velocity: &stepper.v()[..nb],
            previous_velocity: &stepper.previous_v()[..nb],
            impulses,
            section_velocities: &stepper.u,
            law: stepper.law(),
            report,
        });
        if let Some(vehicles) = vehicles.as_ref().filter(|_| self.wheel_loads_needed) {
            self.wheel_loads.clear();
            self.wheel_loads.extend(vehicles.element_loads(self.model, time, &impulses[self.fixed..], *h));
        }
        let state = StepState {
            step: k,
            time,
            h: *h,
            q: stepper.q(),
            v: stepper.v(),
            previous_v: stepper.previous_v(),
            beam: nb,
            impulses,
            fixed: self.fixed,
            load,
            wheel_loads: &self.wheel_loads,
            report,
        };
        if let Some(vehicles) = vehicles.as_mut() {
            vehicles.record(&state)?;
        }
        for r in records.iter_mut() {
            r.record(&state)?;
        }
        Ok(keep_going)
    }
}
