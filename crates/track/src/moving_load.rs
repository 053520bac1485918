//! The moving loads of docs/theory.md §3 and §10 as a [`Forcing`] of the beam's free DOFs: a train of axles and
//! uniform patches moving along the beam at a constant or changing speed (one axle: the reference case's single load).

use fem_beam::load::ElementLoad;
use fem_beam::{BeamModel, Discretisation, Motion, Train};
use nscd::Forcing;
use std::cell::RefCell;

/// A train moving with its first axle at x_c(t) ([`Motion`]: x₀ + v·t at constant speed). Axle i (offset d_i) is at x_c − d_i and
/// loads the beam with −P_i·Ψᵀ(x) while 0 ≤ x ≤ L (Ψ the shape functions of the beam's element containing it:
/// consistent nodal forces *and* moments); a patch loads the part of it on the beam with −q∫Ψᵀdx. Each axle enters
/// and leaves on its own.
#[derive(Debug, Clone)]
pub struct MovingLoad {
    beam: Discretisation,
    /// Free index of each full DOF (None if constrained).
    free: Vec<Option<usize>>,
    /// The train.
    pub train: Train,
    /// How the first axle moves.
    pub motion: Motion,
    /// The element loads at the last two times asked for: a step asks for t_{k+1} and t_k (the force, then its power
    /// for the ledger) and the next step's t_k is this step's t_{k+1}, so each time's loads are assembled once (the
    /// same values in the same order: the same bits). A new time replaces the earlier of the two.
    cache: RefCell<[(f64, Vec<ElementLoad>); 2]>,
}

impl MovingLoad {
    /// A single load of magnitude `force` (N, downward) on `model` at `start` (m) at t = 0 moving at `speed` (m/s).
    pub fn new(model: &BeamModel, force: f64, speed: f64, start: f64) -> Self {
        Self::train(model, Train::single(force), speed, start)
    }

    /// `train` on `model` with its first axle at `start` (m) at t = 0, moving at `speed` (m/s).
    pub fn train(model: &BeamModel, train: Train, speed: f64, start: f64) -> Self {
        Self::moving(model, train, Motion::constant(start, speed))
    }

    /// `train` on `model`, its first axle following `motion`.
    pub fn moving(model: &BeamModel, train: Train, motion: Motion) -> Self {
        let (beam, dofs) = (model.discretisation(), model.dofs());
        let mesh = *beam.mesh();
        let free = (0..dofs.full_len()).map(|d| dofs.free_index(d)).collect();
        // Room for every element load the train can make at once, so that no step allocates: one per axle, and per
        // patch one per element it can cover.
        let l = mesh.element_length();
        let room = train.axles.len()
            + train.patches.iter().map(|p| ((p.length / l).ceil() as usize + 2).min(mesh.elements)).sum::<usize>();
        let cache = RefCell::new([(f64::NAN, Vec::with_capacity(room)), (f64::NAN, Vec::with_capacity(room))]);
        Self { beam, free, train, motion, cache }
    }

    /// Move the train back by `distance` (m) at every time: the co-moving window's shift, after which the load stands
    /// an element further back in the shifted window. The cached loads are of the old positions and are dropped.
    pub fn step_back(&mut self, distance: f64) {
        self.motion.shift_back(distance);
        for (t, loads) in self.cache.get_mut().iter_mut() {
            *t = f64::NAN;
            loads.clear();
        }
    }

    /// Position of the first axle at time t (m), whether or not it is on the beam.
    pub fn position(&self, time: f64) -> f64 {
        self.motion.position(time)
    }

    /// The consistent element loads of everything on the beam at time t ([`Train::element_loads`]).
    pub fn element_loads(&self, time: f64) -> impl Iterator<Item = ElementLoad> + '_ {
        self.train.element_loads(&self.beam, self.position(time))
    }

    /// `f` of the element loads at `time`, from the cache when that time was asked for last or the time before.
    fn with_loads<R>(&self, time: f64, f: impl FnOnce(&[ElementLoad]) -> R) -> R {
        let mut cache = self.cache.borrow_mut();
        let slot = match cache.iter().position(|(t, _)| *t == time) {
            Some(slot) => slot,
            None => {
                // An empty slot (NaN) first, else the earlier time.
                let (a, b) = (cache[0].0, cache[1].0);
                let slot = if a.is_nan() || (!b.is_nan() && a < b) { 0 } else { 1 };
                let (t, loads) = &mut cache[slot];
                *t = time;
                loads.clear();
                loads.extend(self.element_loads(time));
                slot
            }
        };
        f(&cache[slot].1)
    }

    fn free_dofs(&self, element: usize) -> [Option<usize>; 4] {
        std::array::from_fn(|k| self.free[2 * element + k])
    }
}

impl Forcing for MovingLoad {
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]) {
        self.with_loads(time, |loads| {
            for load in loads {
                let dofs = self.free_dofs(load.element);
                for k in 0..4 {
                    if let Some(d) = dofs[k] {
                        out[d] += scale * load.nodal[k];
                    }
                }
            }
        })
    }

    fn power(&self, time: f64, v: &[f64]) -> f64 {
        self.with_loads(time, |loads| {
            let mut power = 0.0;
            for load in loads {
                let dofs = self.free_dofs(load.element);
                power += (0..4).filter_map(|k| dofs[k].map(|d| load.nodal[k] * v[d])).sum::<f64>();
            }
            power
        })
    }
}
