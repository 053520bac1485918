//! What a run steps, set up once before its loop: the solver chosen for the interactions, the system (the beam, or
//! the beam coupled to the vehicles) with its integrator, what loads it (the moving forces, or the vehicles'
//! weights) and how many steps the run takes.

use super::vehicles::{Coupling, VehicleObserver};
use super::{Simulation, resolve_solver};
use crate::error::Result;
use crate::moving_load::MovingLoad;
use crate::system::beam_system;
use fem_beam::Train;
use nscd::Interactions;
use nscd::solver::SolverSettings;
use nscd::stepper::{Integration, MoreauJean};

/// A run ready to step.
pub(crate) struct Setup {
    /// The integrator, holding the state of the whole system.
    pub(crate) stepper: MoreauJean,
    /// The moving forces (none with vehicles, whose weights load the system); its position is the load's.
    pub(crate) load: MovingLoad,
    /// The vehicles' weights, with vehicles: then they, not `load`, load the system.
    pub(crate) weights: Option<nscd::forcing::Constant>,
    /// What the vehicles record, with vehicles.
    pub(crate) vehicles: Option<VehicleObserver>,
    /// The step h (s).
    pub(crate) step: f64,
    /// Where the load (the first axle or wheel) is at t = 0 (m).
    pub(crate) start: f64,
    /// Steps until the load has crossed (W̄ is taken over them), and steps of the whole run.
    pub(crate) crossing_steps: usize,
    pub(crate) total_steps: usize,
}

impl Simulation<'_> {
    /// Set the run up: with vehicles the coupled system starting from the beam's initial state, else the beam; the
    /// solver resolved from `auto`; the step counts.
    pub(crate) fn set_up(&self) -> Result<Setup> {
        let (model, settings) = (self.model, self.settings);
        let mesh = *model.mesh();
        let h = settings.time_step();
        let integration = Integration { scheme: settings.integration.scheme(), step: h };
        // θ_e: the weight of v_{n+1} in the step's displacement (θ of the θ-method), where a wheel's row is taken.
        let theta = integration.coefficients().position_weight();
        let start = settings.start_position();
        let (q0, v0) = self.initial_state()?;
        let motion = settings.motion();
        let coupling = match settings.moving.load.vehicles() {
            Some(vehicles) => {
                let beam = (q0.as_slice(), v0.as_slice());
                Some(Coupling::new(model, vehicles, beam, &motion, theta, settings.record.extremes_nodes)?)
            }
            None => None,
        };
        let moving = coupling.is_some();
        let kind = resolve_solver(settings.integration.solver.kind, model, self.interactions, (h, theta), moving);
        // With vehicles the moving forces are none: the weights load the vehicles, the wheels the rail.
        let train = if moving {
            Train { name: String::new(), axles: Vec::new(), patches: Vec::new() }
        } else {
            settings.moving.load.train()
        };
        let load = MovingLoad::moving(model, train, motion);
        let solver = SolverSettings { kind, ..settings.integration.solver };
        let fixed = self.interactions.interactions().clone();
        let (stepper, weights, vehicles) = match coupling {
            Some(c) => {
                let interactions = Interactions { fixed, moving: c.contacts };
                let stepper = MoreauJean::build(&c.system, interactions, integration, &solver, c.q0, c.v0)?;
                (stepper, Some(c.weights), Some(c.observer))
            }
            None => (MoreauJean::build(&beam_system(model), fixed, integration, &solver, q0, v0)?, None, None),
        };
        let crossing_steps = (settings.crossing_time(mesh.length) / h).round() as usize;
        let total_steps = match settings.integration.end_time {
            Some(end) => crossing_steps.max((end / h - 1e-9).ceil() as usize),
            None => crossing_steps,
        };
        Ok(Setup { stepper, load, weights, vehicles, step: h, start, crossing_steps, total_steps })
    }
}
