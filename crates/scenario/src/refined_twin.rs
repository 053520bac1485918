//! A scenario's twins at other resolutions (`run --check-resolution`, docs/theory.md §6.1): the same track, loads and
//! friction on elements 2^level times shorter and with a load advance (and longest step) 2^level times shorter — the
//! runs a run's estimate of its own discretisation error is measured from.

use crate::Scenario;
use crate::error::{Result, invalid};
use fem_beam::Mesh;

impl Scenario {
    /// The twin `level` halvings finer (−1: one coarser): 2^level times as many elements over the same length, the
    /// load advance and the longest step divided by 2^level. Devices stay on the nodes they snap to on this
    /// scenario's mesh (a twin's nodes hold them when it is finer; a coarser twin must hold them too); everything
    /// else — the loads, the soil, the friction laws, the sections recorded — is the scenario's. A coarser twin needs
    /// an even number of elements.
    pub fn twin(&self, level: i32) -> Result<Scenario> {
        let elements = self.mesh.elements;
        let twin_elements = if level >= 0 {
            elements.checked_mul(1usize << level.min(30))
        } else {
            let divisor = 1usize << (-level).min(30);
            elements.is_multiple_of(divisor).then_some(elements / divisor)
        };
        let twin_elements = twin_elements.filter(|&n| n > 0).ok_or_else(|| {
            invalid(
                "mesh.elements",
                elements,
                format!("a twin {level} halvings finer needs a whole number of elements"),
            )
        })?;
        let factor = 2f64.powi(level);
        let mut twin = self.clone();
        if let Some(devices) = &self.friction.devices {
            let mesh =
                Mesh::new(self.mesh.length, elements).map_err(|e| invalid("mesh.elements", elements, e.to_string()))?;
            let snapped = devices.snapped_on(&mesh)?;
            if level < 0 {
                let coarse = Mesh::new(self.mesh.length, twin_elements)
                    .map_err(|e| invalid("mesh.elements", twin_elements, e.to_string()))?;
                if snapped.snapped_on(&coarse)? != snapped {
                    return Err(invalid(
                        "friction.devices",
                        "placed on the run's nodes",
                        "a coarser twin whose nodes hold every device",
                    ));
                }
            }
            twin.friction.devices = Some(snapped);
        }
        twin.mesh.elements = twin_elements;
        twin.integration.load_advance = self.integration.load_advance / factor;
        twin.integration.max_step = self.integration.max_step.map(|h| h / factor);
        Ok(twin)
    }
}

#[cfg(test)]
mod tests {
    use crate::Scenario;
    use crate::sections::DevicesSection;

    #[test]
    fn a_finer_twin_halves_the_element_and_the_step_and_keeps_the_rest() {
        let mut s = Scenario::default();
        s.integration.max_step = Some(1e-3);
        let twin = s.twin(1).unwrap();
        assert_eq!(twin.mesh.elements, 2 * s.mesh.elements);
        assert_eq!(twin.integration.load_advance, 0.5 * s.integration.load_advance);
        assert_eq!(twin.integration.max_step, Some(5e-4));
        assert_eq!((twin.mesh.length, twin.load.speed, &twin.friction), (s.mesh.length, s.load.speed, &s.friction));
        assert_eq!(s.twin(2).unwrap().mesh.elements, 4 * s.mesh.elements);
        let coarse = s.twin(-1).unwrap();
        assert_eq!(coarse.mesh.elements, s.mesh.elements / 2);
        assert_eq!(coarse.integration.load_advance, 2.0 * s.integration.load_advance);
    }

    #[test]
    fn a_coarser_twin_of_an_odd_mesh_is_refused_by_key() {
        let mut s = Scenario::default();
        s.mesh.elements = 201;
        let message = s.twin(-1).unwrap_err().to_string();
        assert!(message.contains("mesh.elements") && message.contains("201"), "{message}");
    }

    #[test]
    fn devices_stay_on_the_nodes_they_snapped_to() {
        // 31 devices at i·L/32 on 200 elements of 0.5 m snap to nodes 6, 12, 19, …; on 400 elements they would
        // snap to 12, 25, 37, … (3.125 m → node 12.5 rounds up): the twin keeps the run's nodes.
        let mut s = Scenario::default();
        s.friction.devices = Some(DevicesSection { count: Some(31), positions: None, force: Some(2e4) });
        let run_positions = s.twin(0).unwrap().friction.devices.unwrap().positions.unwrap();
        let finer = s.twin(1).unwrap().friction.devices.unwrap().positions.unwrap();
        assert_eq!(run_positions, finer);
        assert_eq!(run_positions.len(), 31);
        let element = s.mesh.length / s.mesh.elements as f64;
        assert!(run_positions.iter().all(|x| ((x / element) - (x / element).round()).abs() < 1e-9));
        assert!(s.twin(-1).is_err(), "31 devices on 100 elements cannot keep the run's nodes");
    }
}
