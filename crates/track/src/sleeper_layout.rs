//! The nonlinear part of the sleepers placed on the track as the engine's interactions (docs/theory.md §18): under
//! a sleeper whose ballast cannot pull (tensionless, or voided by a gap g) a unilateral spring and dashpot on the
//! sleeper's place relative to the ballast, u = z (z − y on a ballast body y, z − w_e on an embankment), force ⟨−k_b(u + g) − c_b u̇⟩₊
//! ([`Law::Soil`]: the linear spring and dashpot step for step while it presses, nothing across an open gap); where
//! the sleeper rubs on the ballast a Coulomb slider on u̇ with maximal force F, in parallel with the ballast's
//! spring. The linear rest — pads, bonded ballast, subgrade, their dashpots, the masses — is in the model's M, C, K.

use crate::placed::{PlacedInteractions, SectionKind};
use fem_beam::{BallastContact, BeamModel, Layer};
use friction::{InteractionRow, Law};

/// The sleepers' unilateral ballast and friction of `model` (none on a continuous track or linear sleepers), each
/// placed at its sleeper (m).
pub fn sleeper_interactions(model: &BeamModel) -> PlacedInteractions {
    let mut set = PlacedInteractions::new();
    let Some((sleepers, nodes)) = model.sleepers() else { return set };
    let mesh = model.mesh();
    for (s, &node) in nodes.iter().enumerate() {
        let support = sleepers.support(s);
        let (z, y) = (model.dofs().sleeper(s), model.dofs().under_ballast(s, node));
        let row = || InteractionRow::from_entries(std::iter::once((z, 1.0)).chain(y.map(|y| (y, -1.0))));
        let x = mesh.node_x(node);
        if let BallastContact::Unilateral { gap } = support.contact
            && support.ballast.stiffness > 0.0
        {
            let Layer { stiffness, damping, .. } = support.ballast;
            set.push(row(), Law::Soil { gap, stiffness, damping }, x, SectionKind::SleeperBallast);
        }
        if support.friction > 0.0 {
            set.push(row(), Law::Coulomb { capacity: support.friction }, x, SectionKind::SleeperFriction);
        }
    }
    set
}
