//! The scenario as a run or a study reports it: every key it computed with, defaults included, and none it did not.
//! On a `[ground]` the ground replaces the Winkler `[foundation]` (a run in time takes a foundation fitted to the
//! ground, reported as its `ground_fit`), so the default `[foundation]` a scenario always holds is left out rather than
//! shown as if it had been under the track.

use crate::Scenario;
use serde::{Serialize, Serializer};

/// [`Scenario`] serialised as it ran: without the `[foundation]` a `[ground]` replaces.
#[derive(Debug, Clone, Copy)]
pub struct AsRan<'a>(pub &'a Scenario);

impl Serialize for AsRan<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let mut value = serde_json::to_value(self.0).map_err(serde::ser::Error::custom)?;
        if self.0.ground.is_some()
            && let Some(table) = value.as_object_mut()
        {
            table.remove("foundation");
        }
        value.serialize(serializer)
    }
}

#[cfg(test)]
mod tests {
    use super::AsRan;
    use crate::Scenario;

    /// The reference case keeps its `[foundation]`; on a `[ground]` it is left out and the ground kept.
    #[test]
    fn the_foundation_a_ground_replaces_is_left_out() {
        let winkler = serde_json::to_value(AsRan(&Scenario::default())).unwrap();
        assert!(winkler.get("foundation").is_some());
        let site = include_str!("../../../examples/soft-ground.toml");
        let grounded = Scenario::from_toml(site, "soft-ground.toml").unwrap();
        let value = serde_json::to_value(AsRan(&grounded)).unwrap();
        assert!(value.get("foundation").is_none() && value.get("ground").is_some(), "{value}");
    }
}
