//! Static response K q = f (docs/theory.md §3 without inertia): factor the banded K once, solve.

use crate::assembly::BeamModel;
use crate::error::Result;
use crate::load::LoadVector;

impl BeamModel {
    /// Full-DOF static displacement q = K⁻¹ f under `loads` (constrained DOFs are 0). Errors if K is not positive
    /// definite, e.g. a free–free beam without foundation.
    pub fn static_solve(&self, loads: &LoadVector) -> Result<Vec<f64>> {
        let mut q = loads.to_free(self.mesh(), self.dofs());
        self.stiffness().factor()?.solve_in_place(&mut q);
        Ok(self.dofs().expand(&q))
    }
}
