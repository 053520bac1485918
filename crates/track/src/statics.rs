//! The static response of a train standing at every position along its crossing (docs/theory.md §10): the
//! reference of a dynamic amplification factor φ = max dynamic deflection / max static deflection.

use crate::error::Result;
use crate::error::{Setting, invalid};
use crate::placed::PlacedInteractions;
use crate::simulation::counts_for_extremes;
use crate::unilateral_statics::StaticSolver;
use fem_beam::{BeamModel, Train};

/// The largest static downward deflection of the train over its crossing, where and with the first axle where.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StaticEnvelope {
    /// Largest static downward deflection (m, magnitude).
    pub max_downward: f64,
    /// Node position where it occurs (m).
    pub position: f64,
    /// First axle's position then (m).
    pub head: f64,
}

/// Largest number of train positions stepped through (each a banded solve with K factored once).
pub const MAX_POSITIONS: usize = 1_000_000;

/// The static envelope of `train` with its first axle at 0, `advance`, 2·`advance`, … up to L + its length (m):
/// K factored once, one banded solve per position — or, with unilateral springs (a nonlinear soil's sections, a
/// sleeper's tensionless or voided ballast, in `placed`), its static deflection per position by one
/// [`crate::unilateral_statics::StaticSolver`], each position starting from the last one's contact set and
/// refactoring only when the set changes. Deflections are from the
/// self-weight state, as a run's. The largest deflection is taken over the nodes in `nodes` (m, as
/// [`crate::simulation::RecordSettings::extremes_nodes`]), or over every node.
pub fn static_envelope(
    model: &BeamModel,
    placed: &PlacedInteractions,
    train: &Train,
    advance: f64,
    nodes: Option<(f64, f64)>,
) -> Result<StaticEnvelope> {
    let (mesh, beam) = (model.mesh(), model.discretisation());
    let span = mesh.length + train.length();
    let positions = (span / advance).ceil() as usize + 1;
    if !(advance.is_finite() && advance > 0.0) || positions > MAX_POSITIONS {
        return Err(invalid(
            Setting::LoadAdvance,
            advance,
            format!("must be > 0 and give at most {MAX_POSITIONS} train positions"),
        ));
    }
    // K alone holds a linear track; a nonlinear soil's sections, or a sleeper's unilateral ballast, are springs of
    // `placed` (friction is not: the envelope is the frictionless static line).
    let factor = match placed.has_springs() {
        false => Some(model.stiffness().factor()?),
        true => None,
    };
    let mut unilateral = StaticSolver::new(model, placed);
    let dofs = model.dofs();
    let counted: Vec<(usize, f64)> = (0..mesh.nodes())
        .filter_map(|node| Some((dofs.free_index(2 * node)?, mesh.node_x(node))))
        .filter(|&(_, x)| counts_for_extremes(nodes, x, mesh.length))
        .collect();
    let mut envelope = StaticEnvelope::default();
    for i in 0..positions {
        let head = (i as f64 * advance).min(span);
        let mut q = train.load_vector(&beam, head).to_free(mesh, dofs);
        match &factor {
            Some(factor) => factor.solve_in_place(&mut q),
            None => q = unilateral.solve(&q)?,
        }
        for &(d, x) in &counted {
            if -q[d] > envelope.max_downward {
                envelope = StaticEnvelope { max_downward: -q[d], position: x, head };
            }
        }
    }
    Ok(envelope)
}
