//! The moving point load of docs/theory.md §3 as a [`Forcing`] of the beam's free DOFs.

use fem_beam::load::ElementLoad;
use fem_beam::{DofMap, Mesh};
use nscd::Forcing;

/// A point force moving at constant speed: −F·Ψᵀ(x_c) at x_c = x₀ + v·t while 0 ≤ x_c ≤ L, zero otherwise
/// (the load enters at x₀ and leaves at L). Ψ are the Hermite shape functions of the element containing x_c, so the
/// load gives consistent nodal forces *and* moments.
#[derive(Debug, Clone)]
pub struct MovingLoad {
    mesh: Mesh,
    /// Free index of each full DOF (None if constrained).
    free: Vec<Option<usize>>,
    /// Load magnitude F (N), acting downward.
    pub force: f64,
    /// Speed v (m/s).
    pub speed: f64,
    /// Position at t = 0 (m).
    pub start: f64,
}

impl MovingLoad {
    /// A load of magnitude `force` (N, downward) at `start` (m) at t = 0 moving at `speed` (m/s).
    pub fn new(mesh: Mesh, dofs: &DofMap, force: f64, speed: f64, start: f64) -> Self {
        let free = (0..dofs.full_len()).map(|d| dofs.free_index(d)).collect();
        Self { mesh, free, force, speed, start }
    }

    /// Position of the load at time t (m), whether or not it is on the beam.
    pub fn position(&self, time: f64) -> f64 {
        self.start + self.speed * time
    }

    /// The element, its free DOFs and the nodal values −F·Ψ at time t, or None once the load is off the beam.
    fn nodal(&self, time: f64) -> Option<([Option<usize>; 4], [f64; 4])> {
        let x = self.position(time);
        // Round-off in t = k·h must not push the load off the end at the last step.
        let tol = 1e-9 * self.mesh.length;
        if x < -tol || x > self.mesh.length + tol {
            return None;
        }
        let load = ElementLoad::point_force(&self.mesh, x.clamp(0.0, self.mesh.length), -self.force).ok()?;
        let dofs = std::array::from_fn(|k| self.free[2 * load.element + k]);
        Some((dofs, load.nodal))
    }
}

impl Forcing for MovingLoad {
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]) {
        if let Some((dofs, values)) = self.nodal(time) {
            for k in 0..4 {
                if let Some(d) = dofs[k] {
                    out[d] += scale * values[k];
                }
            }
        }
    }

    fn power(&self, time: f64, v: &[f64]) -> f64 {
        self.nodal(time).map_or(0.0, |(dofs, values)| (0..4).filter_map(|k| dofs[k].map(|d| values[k] * v[d])).sum())
    }
}
