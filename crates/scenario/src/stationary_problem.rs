//! The stationary problem of a scenario (docs/theory.md §14): what the infinite track takes of a scenario file, built
//! once for `frictrack stationary`, its Python twin, the stationary-wave study and the cost estimate.

use crate::error::{Result, invalid};
use crate::{QuadratureKind, Scenario};
use stationary::{Domain, StationaryProblem};

impl Scenario {
    /// The stationary problem of this scenario at `speed` (m/s) on `domain`: its beam, its soil (stiffness, damping
    /// and law; absorbing zones do not apply on an infinite track), its single load, its self-weight; on sleepers
    /// their long-wave continuous twin ([`Scenario::uniform_support`]). Refused, by key, for what the infinite track
    /// cannot take: devices, Simpson sections, trains, vehicles, sleepers with exceptions.
    pub fn stationary_problem(&self, speed: f64, domain: Domain) -> Result<StationaryProblem> {
        let (twin, _) = self.uniform_support("the stationary wave")?;
        let scenario = &twin;
        if scenario.friction.devices.is_some() {
            return Err(invalid(
                "friction.devices",
                "given",
                "the stationary solver takes friction distributed along the track (`[friction.distributed]`), not \
                 devices at fixed places of a finite track: run devices across the finite track",
            ));
        }
        let friction = match &scenario.friction.distributed {
            None => fem_beam::DistributedFriction::default(),
            Some(d) if d.quadrature != QuadratureKind::Trapezoid => {
                return Err(invalid(
                    "friction.distributed.quadrature",
                    "simpson",
                    "the stationary solver takes the trapezoid sections (the default) of a time-domain run",
                ));
            }
            Some(d) => d.friction()?,
        };
        if scenario.load.train.is_some() || !scenario.load.axles.is_empty() || !scenario.load.patches.is_empty() {
            return Err(invalid("load.train", "given", "the stationary solver takes the single load `load.force`"));
        }
        if scenario.vehicle.is_some() {
            return Err(invalid("vehicle", "given", "the stationary solver takes the moving force, not vehicles"));
        }
        let model = scenario.model()?;
        Ok(StationaryProblem {
            beam: *model.beam(),
            // The soil's own damping: the absorbing zones of a finite track have no place on an infinite one.
            foundation: *model.foundation(),
            load: scenario.load.force,
            speed,
            self_weight: scenario.foundation.self_weight,
            friction,
            domain,
        })
    }
}
