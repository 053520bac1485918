//! Vehicles in a run (docs/theory.md §12): the beam and the vehicles as one system (the beam's block first, so the
//! friction sections' rows keep their DOFs), a compliant wheel–rail interaction per wheel after the friction
//! sections, the weights as a constant force, the vehicles' start in static equilibrium on the rail as the run's
//! initial state leaves it (unloaded, or deflected by a static start), and what is observed of each wheel and body
//! after every step.

use super::counts_for_extremes;
use super::results::{BodyResult, LossOfContact, VehicleResults, WheelResult};
use crate::error::Result;
use crate::system::beam_system;
use crate::vehicle::consist::{RunWheel, VehicleSettings};
use crate::vehicle::rail::{RailPoints, WheelOnBeam};
use fem_beam::{BeamModel, Motion};
use nscd::forcing::Constant;
use nscd::{LinearSystem, MovingInteraction};

/// A wheel counts as off the rail when its mean contact force of a step is below this fraction of its static load:
/// the projection solver puts a separating contact's impulse at exactly 0; the interior point and Clarabel leave
/// ~1e-9 of it.
pub const LOSS_OF_CONTACT: f64 = 1e-6;

/// How long after landing the impact force is looked for (s): the P1 (~0.5 ms) and P2 (~5 ms, the wheel bouncing on
/// the rail's contact stiffness) forces of a wheel–rail impact both fall inside it.
pub const IMPACT_WINDOW: f64 = 0.01;

/// The coupled system of the beam and the vehicles, and how it starts.
pub(super) struct Coupling {
    /// M, C, K of beam and vehicles.
    pub(super) system: LinearSystem,
    /// One wheel–rail interaction per wheel, in [`VehicleSettings::wheels`] order.
    pub(super) contacts: Vec<Box<dyn MovingInteraction>>,
    /// The vehicles' weights over the whole system (zero on the beam).
    pub(super) weights: Constant,
    /// Initial displacement and velocity of the whole system (the beam's part from the run's initial state).
    pub(super) q0: Vec<f64>,
    pub(super) v0: Vec<f64>,
    /// What is observed.
    pub(super) observer: VehicleObserver,
}

impl Coupling {
    /// Couple `vehicles` to the beam of `model`, whose free DOFs start at `beam_q0`: the first wheel moving as
    /// `motion` says, every other at its offset behind it, integrated with `theta`. The vehicles start in static
    /// equilibrium with each wheel on the rail under it (its profile plus the beam's deflection there, 0 off the
    /// beam), pressed into the contact by its static load (two passes: the heights less the penetrations of the first
    /// pass's loads; exact for vehicles whose wheel loads do not depend on the wheels' heights, such as every vehicle
    /// with one wheel).
    pub(super) fn new(
        model: &BeamModel,
        vehicles: &VehicleSettings,
        (beam_q0, beam_v0): (&[f64], &[f64]),
        motion: &Motion,
        theta: f64,
        region: Option<(f64, f64)>,
    ) -> Result<Self> {
        let blocks: Vec<LinearSystem> = vehicles.vehicles.iter().map(|p| p.vehicle.system()).collect();
        let beam = beam_system(model);
        let all: Vec<&LinearSystem> = std::iter::once(&beam).chain(&blocks).collect();
        let (system, layout) = LinearSystem::from_blocks(&all);
        let n = system.dofs();
        let lead = vehicles.lead();
        let wheels: Vec<RunWheel> = vehicles.wheels().collect();
        // How each wheel moves: the first wheel's motion, its offset further back.
        let motions: Vec<Motion> = wheels
            .iter()
            .map(|w| {
                let mut m = motion.clone();
                m.shift_back(w.offset - lead);
                m
            })
            .collect();
        // Where each wheel is at t = 0 (m).
        let starts: Vec<f64> = motions.iter().map(|m| m.position(0.0)).collect();
        let (mut q0, mut weight) = (vec![0.0; n], vec![0.0; n]);
        let mut static_forces = vec![0.0; wheels.len()];
        q0[..beam_q0.len()].copy_from_slice(beam_q0);
        // The beam's block comes first: its DOFs are the system's from 0.
        let rail = RailPoints::new(model, 0);
        let mut bodies = Vec::with_capacity(vehicles.vehicles.len());
        let mut first = 0;
        for (v, placed) in vehicles.vehicles.iter().enumerate() {
            let vehicle = &placed.vehicle;
            let count = vehicle.wheels.len();
            let heights: Vec<f64> = (first..first + count)
                .map(|i| {
                    let deflection = rail.deflection_curvature(&q0, starts[i]).map_or(0.0, |(w, _)| w);
                    vehicles.track(i).height_slope(starts[i], 0.0).0 + deflection
                })
                .collect();
            let (_, forces) = vehicle.static_state(&heights)?;
            let contact = vehicles.contact_of(placed);
            let pressed: Vec<f64> =
                heights.iter().zip(&forces).map(|(h, f)| h - contact.static_penetration(*f)).collect();
            let (x, forces) = vehicle.static_state(&pressed)?;
            let offset = layout.offset(v + 1);
            q0[offset..offset + vehicle.dofs()].copy_from_slice(&x);
            weight[offset..offset + vehicle.dofs()].copy_from_slice(&vehicle.weight);
            static_forces[first..first + count].copy_from_slice(&forces);
            bodies.push((layout.dof(v + 1, vehicle.body), first..first + count));
            first += count;
        }
        let mut contacts: Vec<Box<dyn MovingInteraction>> = Vec::with_capacity(wheels.len());
        for (i, w) in wheels.iter().enumerate() {
            let dof = layout.dof(w.vehicle + 1, w.dof);
            let track = vehicles.track(i);
            let law = vehicles.contact_of(&vehicles.vehicles[w.vehicle]);
            let contact = WheelOnBeam::new(model, (0, dof), motions[i].clone(), track, law, theta)?;
            contacts.push(Box::new(contact));
        }
        let observer = VehicleObserver::new(
            vehicles,
            &wheels,
            static_forces,
            (motions, lead),
            bodies,
            (rail, model.beam().bending_stiffness()),
            (region, model.mesh().length),
        );
        // The beam's initial velocity (a static start's bowl moving with the loads); the vehicles start at rest, as
        // wheels riding a bowl that moves with them do.
        let mut v0 = vec![0.0; n];
        v0[..beam_v0.len()].copy_from_slice(beam_v0);
        Ok(Self { system, contacts, weights: Constant { force: weight }, q0, v0, observer })
    }
}

/// Per wheel and per body, what every step adds.
pub(crate) struct VehicleObserver {
    wheels: Vec<WheelResult>,
    /// How each wheel moves along the track.
    motions: Vec<Motion>,
    /// How far a co-moving window has shifted back under the wheels (m): their places on the beam are their places
    /// on the track less this.
    shifted: f64,
    /// The body DOF ([`crate::vehicle::Vehicle::body`]) of each vehicle in the system and the range of its wheels in
    /// `wheels`; its largest |acceleration| and Σ a²·h while all its wheels are inside the region.
    bodies: Vec<(usize, std::ops::Range<usize>)>,
    body_results: Vec<BodyResult>,
    body_square_integral: Vec<f64>,
    /// Index of each wheel's ongoing loss of contact in its `losses`, if flying.
    flying: Vec<Option<usize>>,
    /// Whether each wheel's contact law lets it leave the rail ([`crate::vehicle::WheelRail::separates`]): a glued
    /// wheel's tensile force is tension, never a loss of contact.
    separates: Vec<bool>,
    /// The rail under the wheels, read from the system's state, and its EI (N·m²) for the moment.
    rail: RailPoints,
    bending_stiffness: f64,
    /// The wheels' extremes and losses of contact count while they are inside this range (m), with the beam's
    /// length for the slack ([`crate::RecordSettings::extremes_nodes`]): away from the ends, where a wheel passes
    /// from the rail onto rigid ground over a pinned support's slope.
    region: (Option<(f64, f64)>, f64),
}

impl VehicleObserver {
    fn new(
        vehicles: &VehicleSettings,
        wheels: &[RunWheel],
        static_forces: Vec<f64>,
        (motions, lead): (Vec<Motion>, f64),
        bodies: Vec<(usize, std::ops::Range<usize>)>,
        (rail, bending_stiffness): (RailPoints, f64),
        region: (Option<(f64, f64)>, f64),
    ) -> Self {
        let results = wheels
            .iter()
            .zip(&static_forces)
            .map(|(w, &q0)| WheelResult {
                vehicle: w.vehicle,
                wheel: w.index,
                offset: w.offset - lead,
                static_force: q0,
                min_force: f64::INFINITY,
                max_force: f64::NEG_INFINITY,
                ..WheelResult::default()
            })
            .collect();
        let body_results = vehicles
            .vehicles
            .iter()
            .map(|p| BodyResult { name: p.vehicle.name.clone(), ..BodyResult::default() })
            .collect();
        Self {
            wheels: results,
            motions,
            shifted: 0.0,
            body_square_integral: vec![0.0; bodies.len()],
            bodies,
            body_results,
            flying: vec![None; wheels.len()],
            separates: wheels.iter().map(|w| vehicles.contact_of(&vehicles.vehicles[w.vehicle]).separates()).collect(),
            region,
            rail,
            bending_stiffness,
        }
    }

    /// Reserve the histories for `steps` more entries.
    pub(super) fn reserve(&mut self, steps: usize) {
        for w in &mut self.wheels {
            let h = &mut w.history;
            for series in [&mut h.time, &mut h.position, &mut h.force, &mut h.rail_deflection, &mut h.moment] {
                series.reserve(steps);
            }
        }
    }

    /// Where wheel `i` is on the beam at `time` (m).
    pub(super) fn position(&self, i: usize, time: f64) -> f64 {
        self.motions[i].position(time) - self.shifted
    }

    /// A co-moving window shifted `distance` (m) back under the wheels.
    pub(crate) fn shift_back(&mut self, distance: f64) {
        self.shifted += distance;
    }

    /// The wheels' element loads at `time` from their impulses `p` of a step `h` (the contact forces −p/h·Ψ on the
    /// rail), for the moments at recorded nodes: (element, nodal forces) of each wheel on the beam.
    pub(super) fn element_loads<'a>(
        &'a self,
        model: &BeamModel,
        time: f64,
        impulses: &'a [f64],
        h: f64,
    ) -> impl Iterator<Item = (usize, [f64; 4])> + 'a {
        let beam = model.discretisation();
        impulses.iter().enumerate().filter_map(move |(i, &p)| {
            let (point, n) = beam.shape_at(self.position(i, time)).ok()?;
            Some((point.element, n.map(|n| -p / h * n)))
        })
    }

    /// Book step k → k+1 ending at `time`: the wheels' impulses `p` (N·s) of the step `h`, the system's
    /// displacement `q` and its velocities after and before the step.
    pub(crate) fn observe(&mut self, time: f64, h: f64, impulses: &[f64], q: &[f64], (v, v_prev): (&[f64], &[f64])) {
        for (i, &p) in impulses.iter().enumerate() {
            // On the beam for the rail under the wheel, on the track for what is reported (the same without a window).
            let (on_beam, x) = (self.position(i, time), self.position(i, time) + self.shifted);
            let force = p / h;
            // Off the beam the rail is rigid ground.
            let (deflection, curvature) = self.rail.deflection_curvature(q, on_beam).unwrap_or((0.0, 0.0));
            let moment = self.bending_stiffness * curvature;
            let w = &mut self.wheels[i];
            let history = &mut w.history;
            history.time.push(time);
            history.position.push(x);
            history.force.push(force);
            history.rail_deflection.push(deflection);
            history.moment.push(moment);
            if !counts_for_extremes(self.region.0, on_beam, self.region.1) {
                continue;
            }
            w.min_force = w.min_force.min(force);
            w.max_force = w.max_force.max(force);
            w.max_rail_deflection = w.max_rail_deflection.max(-deflection);
            w.max_moment = w.max_moment.max(moment.abs());
            let off = self.separates[i] && force < LOSS_OF_CONTACT * w.static_force;
            match (self.flying[i], off) {
                (None, true) => {
                    self.flying[i] = Some(w.losses.len());
                    w.losses.push(LossOfContact { lift_off_position: x, lift_off_time: time, ..Default::default() });
                }
                (Some(k), false) => {
                    let loss = &mut w.losses[k];
                    loss.landing_position = Some(x);
                    loss.duration = time - loss.lift_off_time;
                    loss.impact_force = force;
                    self.flying[i] = None;
                }
                (Some(k), true) => w.losses[k].duration = time - w.losses[k].lift_off_time,
                (None, false) => {
                    if let Some(loss) = w.losses.last_mut()
                        && let Some(landing) = loss.landing_position
                        && (x - landing) <= IMPACT_WINDOW * self.motions[i].speed(time)
                    {
                        loss.impact_force = loss.impact_force.max(force);
                    }
                }
            }
        }
        for (b, (dof, wheels)) in self.bodies.iter().enumerate() {
            let inside =
                wheels.clone().all(|i| counts_for_extremes(self.region.0, self.position(i, time), self.region.1));
            if !inside {
                continue;
            }
            let a = (v[*dof] - v_prev[*dof]) / h;
            let body = &mut self.body_results[b];
            body.max_acceleration = body.max_acceleration.max(a.abs());
            self.body_square_integral[b] += a * a * h;
            body.duration += h;
        }
    }

    /// The results (a wheel that never was inside the region has no extremes: 0), with the contacts' terms of the
    /// run's ledger `energy`.
    pub(crate) fn finish(mut self, energy: &nscd::EnergyLedger) -> VehicleResults {
        for (result, integral) in self.body_results.iter_mut().zip(&self.body_square_integral) {
            result.rms_acceleration = if result.duration > 0.0 { (integral / result.duration).sqrt() } else { 0.0 };
        }
        for w in self.wheels.iter_mut().filter(|w| w.min_force > w.max_force) {
            (w.min_force, w.max_force) = (0.0, 0.0);
        }
        VehicleResults {
            wheels: self.wheels,
            bodies: self.body_results,
            contact_work: energy.contact_work,
            spring_energy: energy.spring_energy,
            contact_loss: energy.contact_loss,
            projection_work: energy.projection_work,
        }
    }
}

impl super::records::Record for VehicleObserver {
    fn record(&mut self, s: &super::records::StepState<'_>) -> Result<()> {
        self.observe(s.time, s.h, &s.impulses[s.fixed..], s.q, (s.v, s.previous_v));
        Ok(())
    }
}
