//! A co-moving window (docs/theory.md §15): the load crosses an endless uniform track of any length at a cost per
//! step independent of that length. The model is a short window of the track (its soil, friction and absorbing
//! zones); the load advances through it from `load_at`, and each time it has advanced one element the
//! state shifts back by one node ([`nscd::MoreauJean::shift`]): the rear element leaves with its energy (booked as
//! transported), a fresh element at rest in the settled state enters ahead, and the load steps back by an element.
//! Every matrix and every interaction's layout is translation-invariant, so the shifted system is the same system;
//! nothing but the window is ever stored. The rear end is free, the front end clamped in the settled state: the
//! track ahead is at rest, and the element that enters ahead joins the clamped node at rest, so a shift adds no
//! energy there (a free front end took in a step of the wave at every shift, and the window blew up within 50 m).
//! Absorbing zones (graded foundation damping) at both ends keep what leaves from coming back.
//!
//! The run reports the wave in the frame, W(s) at the nodes with s = x − x_load, how much it changed over each
//! window length travelled (the stationary state's convergence measure), the extremes over the window's middle
//! (between its absorbing zones) and the energy ledger.

use crate::error::{Result, TrackError, invalid};
use crate::placed::{PlacedInteractions, SectionKind};
use crate::simulation::{InitialState, RunSettings, Simulation};
use fem_beam::{BeamModel, Extreme, Support};
use nscd::forcing::{Constant, WithConstant};
use nscd::stepper::{ShiftedBlock, WindowShift};
use nscd::{EnergyLedger, Forcing, SolverKind};
use std::time::Instant;

/// What a co-moving run is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoMovingSettings {
    /// Where the load stands in the window at the start and after every shift (m from the window's rear end).
    pub load_at: f64,
    /// The distance the load travels (m) > 0: any length of track.
    pub track_length: f64,
    /// The window's middle, between its absorbing zones (m from its rear end): where extremes are taken.
    pub middle: (f64, f64),
}

/// The most steps of a co-moving run (checked before anything is allocated).
pub const MAX_STEPS: usize = 50_000_000;

/// What a co-moving run gives.
#[derive(Debug, Clone, PartialEq)]
pub struct CoMovingResult {
    /// The wave in the frame at the end: (s, W) at the window's nodes, s = x − x_load (m), W from the settled rail (m).
    pub wave: Vec<(f64, f64)>,
    /// After each window length travelled: (distance travelled, max |W − W a window length earlier| over the
    /// middle's nodes relative to the wave's peak there) — the stationary state's convergence measure.
    pub changes: Vec<(f64, f64)>,
    /// Largest downward deflection over the middle's nodes and the whole run (m, magnitude), where on the track (m
    /// from where the window started) and when (s).
    pub max_downward: Extreme,
    /// Largest upward deflection (m), where and when.
    pub max_upward: Extreme,
    /// The energy ledger, with the energy carried out of the window as `transported`.
    pub energy: EnergyLedger,
    /// Steps taken, shifts made.
    pub steps: usize,
    /// Shifts of the window.
    pub shifts: usize,
    /// The solver that ran, if any.
    pub solver: Option<SolverKind>,
    /// Wall time of the loop (s).
    pub wall_time: f64,
    /// With vehicles: each wheel's contact forces and losses of contact and each body's accelerations over the
    /// run (positions on the track, m from where the window started).
    pub vehicles: Option<crate::simulation::VehicleResults>,
}

/// The fixed interactions as blocks that shift with the state: each kind's sections must repeat every element.
fn blocks(model: &BeamModel, placed: &PlacedInteractions) -> Result<Vec<ShiftedBlock>> {
    let l = model.mesh().element_length();
    let (kinds, x) = (placed.kinds(), placed.positions());
    let mut blocks = Vec::new();
    let mut start = 0;
    while start < kinds.len() {
        let kind = kinds[start];
        let len = kinds[start..].iter().take_while(|&&k| k == kind).count();
        let per_shift = x[start..start + len].iter().filter(|&&p| p < x[start] + l - 1e-9 * l).count();
        let repeats = (start..start + len - per_shift).all(|j| (x[j + per_shift] - x[j] - l).abs() <= 1e-9 * l);
        if kind == SectionKind::Device || !repeats {
            return Err(invalid(
                "friction.devices",
                len as f64,
                "takes friction distributed along the track and nonlinear soils, which repeat every element; \
                 devices at chosen places do not travel with a window",
            ));
        }
        blocks.push(ShiftedBlock { start, len, per_shift });
        start += len;
    }
    Ok(blocks)
}

/// Run the load of `settings` (moving forces, one or a train; or vehicles, whose wheels ride the window while the
/// rail's profile under them is the track's) across `window.track_length` m of endless track through the window
/// `model` (free rear end, clamped front end, uniform mesh) with its `placed` interactions (ballast friction and
/// soil sections, which repeat every element).
pub fn run_co_moving(
    model: &BeamModel,
    placed: &PlacedInteractions,
    settings: &RunSettings,
    window: &CoMovingSettings,
) -> Result<CoMovingResult> {
    let mesh = *model.mesh();
    let supports = model.supports();
    let wrong = match (supports.left, supports.right) {
        (Support::Free, Support::Clamped) => None,
        (Support::Free, right) => Some(("supports.right", right)),
        (left, _) => Some(("supports.left", left)),
    };
    if let Some((field, support)) = wrong {
        return Err(TrackError::InvalidChoice {
            field,
            value: support.name(),
            allowed: "a co-moving window has a free rear end and a clamped front end (the track ahead at rest)".into(),
        });
    }
    let l = mesh.element_length();
    let advance = settings.integration.load_advance;
    if settings.step_is_capped() {
        return Err(invalid(
            "max_step",
            settings.time_step(),
            format!(
                "a co-moving window moves by whole load advances: give a load advance of at most {} m (that divides \
                 the element length) instead of a longest step below Δx/v",
                settings.time_step() * settings.moving.speed
            ),
        ));
    }
    let per_element = (l / advance).round();
    if (per_element * advance - l).abs() > 1e-9 * l {
        return Err(invalid("load_advance", advance, format!("must divide the element length {l} m")));
    }
    let train_length = settings.moving.load.length();
    if !(window.load_at >= train_length && window.load_at + l <= mesh.length) {
        return Err(invalid(
            "co_moving.load_at",
            window.load_at,
            format!("must leave the train ({train_length} m) and an element inside the {} m window", mesh.length),
        ));
    }
    let steps = (window.track_length / advance).round();
    if !(window.track_length.is_finite() && window.track_length > 0.0 && steps <= MAX_STEPS as f64) {
        return Err(invalid(
            "co_moving.track_length",
            window.track_length,
            format!("must be > 0 and take at most {MAX_STEPS} steps of {advance} m"),
        ));
    }
    let blocks = blocks(model, placed)?;
    // The run's own set-up (the beam, or the beam and the vehicles with their wheels and weights), the loads
    // standing in static equilibrium at `load_at`, every wheel's extremes counted wherever it is in the window.
    let mut start = settings.clone();
    start.moving.initial = InitialState::Static { position: window.load_at };
    start.record.extremes_nodes = None;
    let setup = Simulation::new(model, placed, &start)?.set_up()?;
    let (mut stepper, mut load, weights, mut observer, h) =
        (setup.stepper, setup.load, setup.weights, setup.vehicles, setup.step);
    let (fixed_count, nb) = (placed.len(), model.dofs().free_len());
    let preload = Constant { force: placed.preload().to_vec() };
    let dofs = model.dofs();
    let nodes: Vec<(usize, f64)> =
        (0..mesh.nodes()).filter_map(|i| Some((dofs.free_index(2 * i)?, mesh.node_x(i)))).collect();
    let middle: Vec<&(usize, f64)> =
        nodes.iter().filter(|(_, x)| (window.middle.0..=window.middle.1).contains(x)).collect();
    let snapshot = |q: &[f64]| -> Vec<f64> { middle.iter().map(|(d, _)| q[*d]).collect() };
    let shifts_per_window = ((window.middle.1 - window.middle.0) / l).round().max(1.0) as usize;
    let mut previous = snapshot(stepper.q());
    let (mut max_downward, mut max_upward) = (Extreme::default(), Extreme::default());
    let mut changes = Vec::new();
    let mut shifts = 0;
    let clock = Instant::now();
    for k in 1..=steps as usize {
        {
            let loads: &dyn Forcing = match &weights {
                Some(weights) => weights,
                None => &load,
            };
            let preloaded = WithConstant { forcing: loads, constant: &preload };
            let forcing: &dyn Forcing = if preload.force.is_empty() { loads } else { &preloaded };
            stepper.step(forcing)?;
        }
        if let Some(observer) = observer.as_mut() {
            let (q, v, previous) = (stepper.q(), stepper.v(), stepper.previous_v());
            observer.observe(stepper.time, h, &stepper.p[fixed_count..], q, (v, previous));
        }
        let travelled = shifts as f64 * l;
        for &&(d, x) in &middle {
            let w = stepper.q()[d];
            max_downward.raise(-w, x + travelled, stepper.time);
            max_upward.raise(w, x + travelled, stepper.time);
        }
        if k % per_element as usize == 0 {
            stepper.shift(&WindowShift { dofs: 2, chain: nb, blocks: &blocks, distance: l })?;
            load.step_back(l);
            if let Some(observer) = observer.as_mut() {
                observer.shift_back(l);
            }
            shifts += 1;
            if shifts % shifts_per_window == 0 {
                let now = snapshot(stepper.q());
                let peak = now.iter().fold(0.0f64, |m, w| m.max(w.abs())).max(f64::MIN_POSITIVE);
                let change = now.iter().zip(&previous).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / peak;
                changes.push((k as f64 * advance, change));
                previous = now;
            }
        }
    }
    let wall_time = clock.elapsed().as_secs_f64();
    let x_load = load.position(stepper.time);
    let wave = nodes.iter().map(|&(d, x)| (x - x_load, stepper.q()[d])).collect();
    let solver = (!placed.is_empty() || observer.is_some()).then(|| stepper.solver_kind());
    let vehicles = observer.map(|o| o.finish(&stepper.energy));
    Ok(CoMovingResult {
        wave,
        changes,
        max_downward,
        max_upward,
        energy: stepper.energy,
        steps: stepper.steps,
        shifts,
        solver,
        wall_time,
        vehicles,
    })
}
