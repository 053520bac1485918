//! Where `[friction.devices]` puts its devices: the layout it asks for, and the nodes they snap to on a mesh — the
//! positions a refined twin keeps (docs/theory.md §6.1), so that refining the mesh cannot move a device.

use crate::error::{Result, invalid};
use crate::sections::DevicesSection;
use fem_beam::Mesh;
use track::{DeviceLayout, Devices};

impl DevicesSection {
    /// The devices' placement on a beam `length` m long: `count` evenly spaced or the `positions` given (each on the
    /// beam), not both.
    pub fn layout(&self, length: f64) -> Result<DeviceLayout> {
        match (self.count, &self.positions) {
            (Some(count), None) => Ok(DeviceLayout::Uniform { count }),
            (None, Some(positions)) => {
                if let Some(&x) = positions.iter().find(|x| !(x.is_finite() && (0.0..=length).contains(*x))) {
                    return Err(invalid("friction.devices.positions", x, "every position must lie on the beam"));
                }
                Ok(DeviceLayout::Positions(positions.clone()))
            }
            (Some(count), Some(_)) => {
                Err(invalid("friction.devices.count", count, "give friction.devices.count or positions, not both"))
            }
            (None, None) => Err(invalid("friction.devices", "{}", "give count or positions")),
        }
    }

    /// The same devices at the positions (m) they snap to on `mesh`, one per device (devices that share a node
    /// keep sharing it): on any mesh that holds these nodes, the devices stay where they were.
    pub fn snapped_on(&self, mesh: &Mesh) -> Result<DevicesSection> {
        let devices = Devices { layout: self.layout(mesh.length)?, force: 0.0 };
        let positions = devices
            .requested_positions(mesh.length)
            .into_iter()
            .map(|x| mesh.nearest_node(x).map(|node| mesh.node_x(node)))
            .collect::<std::result::Result<Vec<f64>, _>>()
            .map_err(|e| invalid("friction.devices.positions", e, "positions on the beam"))?;
        Ok(DevicesSection { count: None, positions: Some(positions), force: self.force })
    }
}
