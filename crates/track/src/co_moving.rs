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

use crate::error::{Result, Setting, invalid, invalid_choice};
use crate::placed::{PlacedInteractions, SectionKind};
use crate::simulation::setup::Setup;
use crate::simulation::{InitialState, Record, RunSettings, Simulation, StepState, Stepping};
use fem_beam::{BeamModel, DeflectionExtremes, Support};
use nscd::stepper::{ShiftedBlock, WindowShift};
use nscd::{EnergyLedger, SolverKind};
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
    /// Largest downward and upward deflections over the middle's nodes and the whole run (m, magnitudes), where on
    /// the track (m from where the window started) and when (s).
    pub deflection: DeflectionExtremes,
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
                Setting::Friction("devices"),
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
    let (per_element, steps) = check(model, settings, window)?;
    let blocks = blocks(model, placed)?;
    // The run's own set-up (the beam, or the beam and the vehicles with their wheels and weights), the loads
    // standing in static equilibrium at `load_at`, every wheel's extremes counted wherever it is in the window.
    let mut start = settings.clone();
    start.moving.initial = InitialState::Static { position: window.load_at };
    start.record.extremes_nodes = None;
    let setup = Simulation::new(model, placed, &start)?.set_up()?;
    let mut run = Stepping::new(model, placed, setup, false);
    let mut middle = Middle::new(model, window, per_element);
    let advance = settings.integration.load_advance;
    let mut shifter = Shifter::new(model, window, blocks, (per_element, advance), &middle, run.beam_state().0);
    let clock = Instant::now();
    run.run(steps, &mut [&mut middle], &mut |_| true, &mut |run, k| shifter.after_step(run, k))?;
    let wall_time = clock.elapsed().as_secs_f64();
    let Setup { stepper, load, vehicles, .. } = run.setup;
    let x_load = load.position(stepper.time);
    let wave = middle.all.iter().map(|&(d, x)| (x - x_load, stepper.q()[d])).collect();
    let solver = (!placed.is_empty() || vehicles.is_some()).then(|| stepper.solver_kind());
    Ok(CoMovingResult {
        wave,
        changes: shifter.changes,
        deflection: middle.deflection,
        vehicles: vehicles.map(|o| o.finish(&stepper.energy)),
        energy: stepper.energy,
        steps: stepper.steps,
        shifts: shifter.shifts,
        solver,
        wall_time,
    })
}

/// Whether the window can travel: a free rear end and a clamped front one, whole load advances per element, the
/// load inside, a track length of a finite number of steps; the load advances per element and the steps.
fn check(model: &BeamModel, settings: &RunSettings, window: &CoMovingSettings) -> Result<(usize, usize)> {
    let mesh = model.mesh();
    let supports = model.supports();
    let wrong = match (supports.left, supports.right) {
        (Support::Free, Support::Clamped) => None,
        (Support::Free, right) => Some((Setting::RightSupport, right)),
        (left, _) => Some((Setting::LeftSupport, left)),
    };
    if let Some((setting, support)) = wrong {
        let allowed = "a co-moving window has a free rear end and a clamped front end (the track ahead at rest)";
        return Err(invalid_choice(setting, support.name(), allowed));
    }
    if settings.moving.changes_speed() {
        let allowed = "a co-moving window follows a load at constant speed (its window moves one element per fixed \
                       number of steps): leave the speed profile out, or run the whole track";
        return Err(invalid(settings.moving.speed_setting(), settings.moving.largest_speed(), allowed));
    }
    if settings.record.acceleration_band.is_some() {
        let allowed = "a co-moving window has no modes of its own to project onto (its mesh moves with the load): \
                       leave the band out, or run the whole track";
        return Err(invalid_choice(Setting::AccelerationBand, "given", allowed));
    }
    if settings.record.acceleration_filter.is_some() {
        let allowed = "a co-moving window's nodes move with the load, so a node's velocity over a window of steps is \
                       not one point's: leave the filter out, or run the whole track";
        return Err(invalid_choice(Setting::AccelerationFilter, "given", allowed));
    }
    let l = mesh.element_length();
    let advance = settings.integration.load_advance;
    if settings.step_is_capped() {
        return Err(invalid(
            Setting::MaxStep,
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
        return Err(invalid(Setting::LoadAdvance, advance, format!("must divide the element length {l} m")));
    }
    let train_length = settings.moving.load.length();
    if !(window.load_at >= train_length && window.load_at + l <= mesh.length) {
        return Err(invalid(
            Setting::CoMovingLoadAt,
            window.load_at,
            format!("must leave the train ({train_length} m) and an element inside the {} m window", mesh.length),
        ));
    }
    let steps = (window.track_length / advance).round();
    if !(window.track_length.is_finite() && window.track_length > 0.0 && steps <= MAX_STEPS as f64) {
        return Err(invalid(
            Setting::CoMovingTrackLength,
            window.track_length,
            format!("must be > 0 and take at most {MAX_STEPS} steps of {advance} m"),
        ));
    }
    Ok((per_element as usize, steps as usize))
}

/// The window's record: the extremes over the nodes of its middle (between the absorbing zones), placed on the
/// track — a node's x in the window plus the distance the window has travelled.
struct Middle {
    /// Every node's deflection DOF and x in the window (m), and those of the middle.
    all: Vec<(usize, f64)>,
    middle: Vec<(usize, f64)>,
    element_length: f64,
    per_element: usize,
    deflection: DeflectionExtremes,
}

impl Middle {
    fn new(model: &BeamModel, window: &CoMovingSettings, per_element: usize) -> Self {
        let (mesh, dofs) = (model.mesh(), model.dofs());
        let all: Vec<(usize, f64)> =
            (0..mesh.nodes()).filter_map(|i| Some((dofs.free_index(2 * i)?, mesh.node_x(i)))).collect();
        let middle = all.iter().copied().filter(|(_, x)| (window.middle.0..=window.middle.1).contains(x)).collect();
        Self {
            all,
            middle,
            element_length: mesh.element_length(),
            per_element,
            deflection: DeflectionExtremes::default(),
        }
    }
}

/// The deflections at `dofs` in `q` (m).
fn deflections(dofs: &[usize], q: &[f64]) -> Vec<f64> {
    dofs.iter().map(|&d| q[d]).collect()
}

impl Record for Middle {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        // The window shifts after every `per_element` steps' records: before step k's, (k − 1)/per_element times.
        let travelled = ((s.step - 1) / self.per_element) as f64 * self.element_length;
        for &(d, x) in &self.middle {
            let w = s.q[d];
            self.deflection.max_downward.raise(-w, x + travelled, s.time);
            self.deflection.max_upward.raise(w, x + travelled, s.time);
        }
        Ok(())
    }
}

/// What the co-moving run does between two steps: after every element the load has advanced, the state shifts
/// back by a node and the load (and the vehicles) by an element; after every window length, the wave's change.
struct Shifter {
    blocks: Vec<ShiftedBlock>,
    per_element: usize,
    element_length: f64,
    advance: f64,
    chain: usize,
    shifts: usize,
    shifts_per_window: usize,
    /// The middle's deflections a window length ago, its nodes' DOFs, and the changes so far.
    previous: Vec<f64>,
    dofs: Vec<usize>,
    changes: Vec<(f64, f64)>,
}

impl Shifter {
    fn new(
        model: &BeamModel,
        window: &CoMovingSettings,
        blocks: Vec<ShiftedBlock>,
        (per_element, advance): (usize, f64),
        middle: &Middle,
        q0: &[f64],
    ) -> Self {
        let l = model.mesh().element_length();
        let dofs: Vec<usize> = middle.middle.iter().map(|(d, _)| *d).collect();
        Self {
            blocks,
            per_element,
            element_length: l,
            advance,
            chain: model.dofs().free_len(),
            shifts: 0,
            shifts_per_window: ((window.middle.1 - window.middle.0) / l).round().max(1.0) as usize,
            previous: deflections(&dofs, q0),
            dofs,
            changes: Vec::new(),
        }
    }

    fn after_step(&mut self, run: &mut Stepping<'_>, k: usize) -> Result<()> {
        if !k.is_multiple_of(self.per_element) {
            return Ok(());
        }
        let l = self.element_length;
        let Setup { stepper, load, vehicles, .. } = &mut run.setup;
        stepper.shift(&WindowShift { dofs: 2, chain: self.chain, blocks: &self.blocks, distance: l })?;
        load.step_back(l);
        if let Some(vehicles) = vehicles.as_mut() {
            vehicles.shift_back(l);
        }
        self.shifts += 1;
        if self.shifts.is_multiple_of(self.shifts_per_window) {
            let now = deflections(&self.dofs, stepper.q());
            let peak = now.iter().fold(0.0f64, |m, w| m.max(w.abs())).max(f64::MIN_POSITIVE);
            let change = now.iter().zip(&self.previous).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / peak;
            self.changes.push((k as f64 * self.advance, change));
            self.previous = now;
        }
        Ok(())
    }
}
