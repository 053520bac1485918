//! Discrete friction devices (FDD) on mesh nodes (docs/theory.md §4).
//!
//! N devices at x_i = i·L/(N+1), i = 1..N, each snapped to the nearest mesh node, a tie going to the node of larger
//! x (N = 15 on 1 m elements: 12.5 m → 13 m); or devices at explicit positions, snapped the same way. Each device
//! has the row selecting its node's w DOF and the bound F_u. Devices snapped to the same node merge (bounds add).

use crate::error::{Result, TrackError};
use crate::error::{Setting, invalid, invalid_count};
use crate::placed::{PlacedInteractions, SectionKind};
use fem_beam::BeamModel;
use friction::{InteractionRow, Law};

/// Where the devices go.
#[derive(Debug, Clone, PartialEq)]
pub enum DeviceLayout {
    /// `count` devices evenly spaced at i·L/(count+1).
    Uniform {
        /// Number of devices N (0 = none); at most the number of interior nodes.
        count: usize,
    },
    /// Devices at these positions (m), each snapped to its nearest node.
    Positions(Vec<f64>),
}

/// A set of identical friction devices.
#[derive(Debug, Clone, PartialEq)]
pub struct Devices {
    /// Placement.
    pub layout: DeviceLayout,
    /// Maximal friction force of one device F_u (N), ≥ 0. The reference studies use 10–100 kN.
    pub force: f64,
}

impl Devices {
    /// `count` evenly spaced devices of force `force` (N).
    pub fn uniform(count: usize, force: f64) -> Self {
        Self { layout: DeviceLayout::Uniform { count }, force }
    }

    /// Check the parameters against the mesh of `model`.
    pub fn validate(&self, model: &BeamModel) -> Result<()> {
        if !(self.force.is_finite() && self.force >= 0.0) {
            return Err(invalid(Setting::Friction("devices.force"), self.force, "must be finite and ≥ 0 (N)"));
        }
        let interior = model.mesh().elements - 1;
        if let DeviceLayout::Uniform { count } = self.layout
            && count > interior
        {
            return Err(invalid_count(
                Setting::Friction("devices.count"),
                count,
                format!("at most {interior}, the number of interior nodes of the mesh"),
            ));
        }
        Ok(())
    }

    /// Requested (unsnapped) positions (m).
    pub fn requested_positions(&self, length: f64) -> Vec<f64> {
        match &self.layout {
            DeviceLayout::Uniform { count } => {
                (1..=*count).map(|i| i as f64 * length / (*count as f64 + 1.0)).collect()
            }
            DeviceLayout::Positions(x) => x.clone(),
        }
    }

    /// Node indices the devices snap to, in order of the requested positions (duplicates possible).
    pub fn snapped_nodes(&self, model: &BeamModel) -> Result<Vec<usize>> {
        self.validate(model)?;
        let mesh = model.mesh();
        self.requested_positions(mesh.length)
            .into_iter()
            .map(|x| mesh.nearest_node(x).map_err(TrackError::from))
            .collect()
    }

    /// Snapped positions (m), sorted, one per distinct node.
    pub fn snapped_positions(&self, model: &BeamModel) -> Result<Vec<f64>> {
        let mut nodes = self.snapped_nodes(model)?;
        nodes.sort_unstable();
        nodes.dedup();
        Ok(nodes.into_iter().map(|n| model.mesh().node_x(n)).collect())
    }

    /// The contact set: one row per distinct node (devices on the same node merged, bounds added).
    pub fn interactions(&self, model: &BeamModel) -> Result<PlacedInteractions> {
        let mut nodes = self.snapped_nodes(model)?;
        nodes.sort_unstable();
        let mut set = PlacedInteractions::new();
        let mut i = 0;
        while i < nodes.len() {
            let node = nodes[i];
            let same = nodes[i..].iter().take_while(|&&n| n == node).count();
            let row = InteractionRow::from_entries(model.dofs().free_index(2 * node).map(|d| (d, 1.0)));
            let law = Law::Coulomb { capacity: self.force * same as f64 };
            set.push(row, law, model.mesh().node_x(node), SectionKind::Device);
            i += same;
        }
        Ok(set)
    }
}
