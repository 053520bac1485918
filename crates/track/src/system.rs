//! The beam on its foundation as the engine's linear system (docs/theory.md §3).

use fem_beam::BeamModel;
use nscd::LinearSystem;

/// M, C, K of the beam over its free DOFs.
pub fn beam_system(model: &BeamModel) -> LinearSystem {
    LinearSystem::new(model.mass().clone(), model.damping().clone(), model.stiffness().clone())
}
