//! What a scenario's numbers mean for the model, before anything runs: refusals for inputs that cannot give an
//! answer, and warnings for legitimate but suspicious ones (docs/theory.md §2–§4).
//!
//! - Refused: a mesh with no free deflection DOF (one pinned element: the load has nothing to bend), and a beam
//!   without foundation whose supports leave a rigid-body motion (free–free, pinned–free: a mechanism).
//! - Warned: elements longer than a quarter of the deflection bowl π/β (β = (k_f/4EI)^¼; 10 m for the reference
//!   case, so elements over 2.5 m cannot represent it and the peaks come out wrong), and friction devices that snap
//!   to the same node and merge (their forces add) or sit on a support (dropped).

use crate::error::{Result, invalid};
use crate::scenario::{Case, Scenario};
use fem_beam::reference::InfiniteBeam;
use fem_beam::{BeamModel, Support};
use friction::InteractionKind;
use std::fmt;

/// A suspicious input: the field, its value, and what is wrong with it against which limit.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// Dotted path in the scenario.
    pub field: String,
    /// The value, as text.
    pub value: String,
    /// What it means and the limit it crosses.
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}: {}", self.field, self.value, self.message)
    }
}

/// Refuse models that cannot give an answer (see the module documentation).
pub fn refuse_degenerate(model: &BeamModel) -> Result<()> {
    let mesh = model.mesh();
    let free_deflections = (0..mesh.nodes()).filter(|&i| model.dofs().free_index(2 * i).is_some()).count();
    if free_deflections == 0 {
        return Err(invalid(
            "mesh.elements",
            mesh.elements,
            "leaves no node free to deflect between the supports; use at least 2 elements (and enough to resolve \
             the deflection bowl)",
        ));
    }
    let supports = model.supports();
    let held = |s: Support| match s {
        Support::Free => 0,
        Support::Pinned => 1,
        Support::Clamped => 2,
    };
    if model.foundation().stiffness == 0.0 && held(supports.left) + held(supports.right) < 2 {
        return Err(invalid(
            "supports",
            format!("{:?}/{:?}", supports.left, supports.right).to_lowercase(),
            "without a foundation (k_f = 0) these supports leave a rigid-body motion (a mechanism); pin both ends, \
             clamp one, or give foundation.stiffness > 0",
        ));
    }
    Ok(())
}

/// Warnings for `scenario` built into `case`.
pub fn warnings(scenario: &Scenario, case: &Case) -> Vec<Warning> {
    let mut out = Vec::new();
    let model = &case.model;
    // β of the infinite beam on this foundation (none without one: k_f = 0 has no deflection bowl).
    if let Ok(infinite) = InfiniteBeam::new(model.beam(), model.foundation()) {
        let bowl = std::f64::consts::PI / infinite.beta();
        let l = model.mesh().element_length();
        if l > 0.25 * bowl {
            let needed = (4.0 * model.mesh().length / bowl).ceil();
            out.push(Warning {
                field: "mesh.elements".into(),
                value: model.mesh().elements.to_string(),
                message: format!(
                    "elements of {l:.3} m are longer than a quarter of the deflection bowl π/β = {bowl:.3} m (limit \
                     {:.3} m): the deflection under the load is not resolved; use at least {needed} elements",
                    0.25 * bowl
                ),
            });
        }
    }
    if let Some(devices) = &scenario.friction.devices {
        let requested = match (devices.count, &devices.positions) {
            (Some(n), _) => n,
            (None, Some(x)) => x.len(),
            (None, None) => 0,
        };
        let kinds = case.interactions.kinds();
        let placed = kinds.iter().filter(|k| **k == InteractionKind::Device).count();
        if placed < requested {
            out.push(Warning {
                field: "friction.devices".into(),
                value: format!("{requested} devices"),
                message: format!(
                    "they occupy only {placed} distinct free node(s) of the {} m mesh: devices snapped to one node \
                     merge (their forces add) and devices on a support are dropped; refine the mesh or space them \
                     at least one element ({:.3} m) apart",
                    model.mesh().length,
                    model.mesh().element_length()
                ),
            });
        }
    }
    out
}
