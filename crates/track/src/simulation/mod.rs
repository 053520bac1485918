//! A whole run: the beam under a load crossing it at constant speed, with friction, observed as it goes
//! (docs/theory.md §3, §6).
//!
//! The state is the perturbation from the self-weight equilibrium q₀ = K⁻¹P: with a linear foundation and
//! velocity-driven friction P drops out exactly, so deflections are reported relative to q₀. The load enters at
//! x = 0 (or at the start position of an analytic steady state) and the run ends when it leaves at x = L
//! (t_on), or at a later end time (free vibration). The step is h = Δx/v with the load advance Δx per step.
//!
//! Memory of a run is O(DOFs + sections) plus O(steps) per recorded section history.

mod acceleration_checks;
mod band_record;
pub mod filtered_record;
mod integration_settings;
mod lift_off;
mod moving_settings;
mod observers;
mod records;
mod results;
mod settings;
pub(crate) mod setup;
mod sleeper_record;
mod stepping;
mod vehicles;
mod velocity_window;

pub use lift_off::LIFT_OFF_GAP;
pub use moving_settings::SpeedLimit;
pub use results::{
    BandAcceleration, BodyResult, FallbackCount, FilteredAcceleration, LiftOff, LossOfContact, RunResult,
    SectionHistory, SleeperHistory, SleeperPeaks, SleeperResults, SolverStatistics, StepView, VehicleResults,
    WheelHistory, WheelResult, WindowExtremes, WorkStatistics,
};
pub(crate) use settings::counts_for_extremes;
pub use settings::{InitialState, IntegrationSettings, Load, MovingLoadSettings, RecordSettings, RunSettings};
pub use vehicles::{IMPACT_WINDOW, LOSS_OF_CONTACT};

use crate::error::Result;
use crate::error::Setting;
use crate::placed::PlacedInteractions;
use analytic::moving_beam::MovingBeam;
use fem_beam::BeamModel;
use nscd::solver::SolverKind;
use records::{DeflectionRecord, SectionRecords, SolverTally};
pub(crate) use records::{Record, StepState};
use setup::Setup;
use std::time::Instant;
pub(crate) use stepping::Stepping;

/// The coupling length ℓ = (EI·h²θ²/ρA)^¼ (m): sections closer than this are strongly coupled in one step.
pub fn coupling_length(model: &BeamModel, step: f64, theta: f64) -> f64 {
    let beam = model.beam();
    (beam.bending_stiffness() * step * step * theta * theta / beam.mass_per_length()).powf(0.25)
}

/// At most this many fixed interactions are solved by projection however close they sit: their Delassus block is
/// a few numbers, each sweep costs nothing, and the interior point would factor the whole band every iteration
/// (measured: a quarter car over three voided sleepers 0.6 m apart, 4.1 sweeps a step and 0.023 s against 0.133 s by
/// the interior point; a stalled projection falls back to the interior point).
pub const FEW_SECTIONS: usize = 8;

/// Above this many entries of the dense Delassus matrix (m² for m interactions) per DOF, projection's sweeps cost
/// more than the interior point's active-set rounds even for sections spaced wider than twice the coupling length
/// (callgrind, 2000-step reference runs: 99 devices 2 m apart, m²/n = 25, projection 309 M instructions against
/// 337 M; 199 sections 1 m apart, m²/n = 99, 698 M against 480 M; BENCHMARKS.md).
pub const DENSE_DELASSUS_PER_DOF: usize = 50;

/// Resolve [`SolverKind::Auto`]: projection when there are at most [`FEW_SECTIONS`] fixed interactions, or they are
/// spaced wider than twice the coupling length and their dense Delassus matrix has at most
/// [`DENSE_DELASSUS_PER_DOF`] entries a DOF or there are `vehicles` (whose wheel rows keep the interior point's
/// active set out: every row of it must be fixed) — or there are none (wheel contacts alone); the banded interior point
/// otherwise — vehicles' wheel contacts included, whose rows it takes by a low-rank correction (measured: a quarter
/// car on 2 kN/m of ballast friction at 100 m/s, 1.2 s against 150 s by projection; BENCHMARKS.md).
pub fn resolve_solver(
    kind: SolverKind,
    model: &BeamModel,
    interactions: &PlacedInteractions,
    (step, theta): (f64, f64),
    vehicles: bool,
) -> SolverKind {
    if kind != SolverKind::Auto {
        return kind;
    }
    if interactions.len() <= FEW_SECTIONS {
        return SolverKind::Projection;
    }
    let mut x = interactions.positions().to_vec();
    x.sort_by(f64::total_cmp);
    let spacing = x.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    let m = interactions.len();
    let dense = !vehicles && m.saturating_mul(m) > DENSE_DELASSUS_PER_DOF.saturating_mul(model.dofs().free_len());
    if spacing < 2.0 * coupling_length(model, step, theta) || dense {
        SolverKind::InteriorPoint
    } else {
        SolverKind::Projection
    }
}

/// A run of `model` with friction `interactions` under `settings`.
#[derive(Debug, Clone, Copy)]
pub struct Simulation<'a> {
    model: &'a BeamModel,
    interactions: &'a PlacedInteractions,
    settings: &'a RunSettings,
}

impl<'a> Simulation<'a> {
    /// Validate and prepare a run.
    pub fn new(model: &'a BeamModel, interactions: &'a PlacedInteractions, settings: &'a RunSettings) -> Result<Self> {
        settings.validate(model)?;
        Ok(Self { model, interactions, settings })
    }

    /// Initial (q, v) over the free DOFs, per [`MovingLoadSettings::initial`]: a static start's deflection moves
    /// with the loads (`convected_velocity`).
    pub fn initial_state(&self) -> Result<(Vec<f64>, Vec<f64>)> {
        let dofs = self.model.dofs();
        let n = dofs.free_len();
        match self.settings.moving.initial {
            InitialState::Rest => Ok((vec![0.0; n], vec![0.0; n])),
            InitialState::Static { position } => {
                // K q = f of the loads standing there (the vehicles' static wheel loads with vehicles), with the
                // unilateral springs (a nonlinear soil's sections, sleepers' tensionless ballast) where there are.
                let mesh = self.model.mesh();
                let beam = self.model.discretisation();
                let mut q = self.settings.moving.load.train().load_vector(&beam, position).to_free(mesh, dofs);
                if self.interactions.has_springs() {
                    q = crate::unilateral_statics::static_deflection(self.model, self.interactions, &q)?;
                } else {
                    self.model.stiffness().factor()?.solve_in_place(&mut q);
                }
                let v = convected_velocity(self.model, &q, self.settings.motion().speed(0.0));
                Ok((q, v))
            }
            InitialState::SteadyState { position } => {
                // The infinite beam is linear: a train's steady state is the sum of its axles' (docs/theory.md §8,
                // §10), each shifted by its offset. Patches have no closed form here.
                let train = self.settings.moving.load.train();
                if !train.patches.is_empty() {
                    return Err(crate::error::invalid(
                        Setting::SteadyStart,
                        position,
                        "the steady-state start takes trains of axles only (no load patches)",
                    ));
                }
                let infinite = MovingBeam::new(self.model.beam(), self.model.foundation())?;
                let mesh = self.model.mesh();
                let mut q = vec![0.0; dofs.full_len()];
                let mut v = vec![0.0; dofs.full_len()];
                for axle in &train.axles {
                    let state = infinite.steady_state(self.settings.motion().speed(0.0), axle.force)?;
                    for i in 0..mesh.nodes() {
                        let s = mesh.node_x(i) - (position - axle.offset);
                        q[2 * i] += state.deflection(s);
                        q[2 * i + 1] += state.rotation(s);
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
        let setup = self.set_up()?;
        let (h, start, crossing_steps, total_steps) =
            (setup.step, setup.start, setup.crossing_steps, setup.total_steps);
        let record = &self.settings.record;
        let mut run = Stepping::new(self.model, self.interactions, setup, !record.sections.is_empty());
        let (q0, v0) = run.beam_state();
        let mut deflections = DeflectionRecord::new(self.model, record, q0, start, crossing_steps);
        let mut sections = SectionRecords::new(self.model, self.interactions, &record.sections, total_steps);
        let mut lift_off = lift_off::LiftOffRecord::new(self.interactions);
        let filter = record.acceleration_filter.map(|band| (band, h));
        let recorded = (record.sections.as_slice(), total_steps);
        let mut sleepers = sleeper_record::SleeperRecord::new(self.model, self.interactions, recorded, filter);
        sections.start((q0, v0), &run.setup.load, start)?;
        let mut band = record
            .acceleration_band
            .map(|limit| band_record::BandRecord::new(self.model, limit, record.extremes_nodes))
            .transpose()?;
        let mut filtered = record
            .acceleration_filter
            .map(|band| filtered_record::FilteredRecord::new(self.model, band, h, record.extremes_nodes));
        let mut tally = SolverTally::default();
        let clock = Instant::now();
        let mut records: Vec<&mut dyn Record> =
            vec![&mut tally, &mut deflections, &mut sections, &mut lift_off, &mut sleepers];
        if let Some(band) = band.as_mut() {
            records.push(band);
        }
        if let Some(filtered) = filtered.as_mut() {
            records.push(filtered);
        }
        run.run(total_steps, &mut records, observer, &mut |_, _| Ok(()))?;
        let wall_time = clock.elapsed().as_secs_f64();
        let Setup { stepper, vehicles, .. } = run.setup;
        let (fixed, nb) = (self.interactions.len(), self.model.dofs().free_len());
        let t_on = self.settings.crossing_time(self.model.mesh().length);
        let solver = (!self.interactions.is_empty() || vehicles.is_some()).then(|| stepper.solver_kind());
        Ok(RunResult {
            deflection: deflections.extremes,
            max_acceleration: self
                .model
                .beam()
                .theory
                .bounds_point_load_acceleration()
                .then_some(deflections.acceleration),
            band_acceleration: band.map(band_record::BandRecord::finish),
            filtered_acceleration: filtered.map(filtered_record::FilteredRecord::finish),
            window: deflections.window,
            energy: stepper.energy,
            global_norm: if t_on > 0.0 { deflections.norm_integral / t_on } else { 0.0 },
            histories: sections.finish(),
            statistics: tally.finish(solver, fixed, stepper.steps, wall_time),
            step: h,
            section_positions: self.interactions.positions().to_vec(),
            final_displacement: stepper.q()[..nb].to_vec(),
            final_velocity: stepper.v()[..nb].to_vec(),
            vehicles: vehicles.map(|o| o.finish(&stepper.energy)),
            lift_off: lift_off.finish(),
            sleepers: sleepers.finish(),
        })
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
    let l = mesh.element_length();
    let mut v = vec![0.0; q.len()];
    // The rail's (w, θ) from full DOF 0, and the embankment's under the ballast where the track has one.
    for start in std::iter::once(0).chain(dofs.embankment_start()) {
        let rotation: Vec<f64> = (0..nodes).map(|i| value(start + 2 * i + 1)).collect();
        for i in 0..nodes {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(nodes - 1));
            let curvature = (rotation[b] - rotation[a]) / ((b - a) as f64 * l);
            if let Some(k) = dofs.free_index(start + 2 * i) {
                v[k] = -speed * rotation[i];
            }
            if let Some(k) = dofs.free_index(start + 2 * i + 1) {
                v[k] = -speed * curvature;
            }
        }
    }
    // A sleeper (and the ballast body under it) follows its rail node in the same ratio as in the static state, z/w
    // (k_p/(k_p + k_b) on bonded, rigidly founded ballast, 1 hanging): ż = (z/w) ẇ, exact for the bowl carried along
    // quasi-statically.
    if let Some((_, sleeper_nodes)) = model.sleepers() {
        for (s, &node) in sleeper_nodes.iter().enumerate() {
            if let Some(w) = dofs.free_index(2 * node).filter(|&w| q[w] != 0.0) {
                for d in std::iter::once(dofs.sleeper(s)).chain(dofs.ballast_body(s)) {
                    v[d] = v[w] * q[d] / q[w];
                }
            }
        }
    }
    v
}
