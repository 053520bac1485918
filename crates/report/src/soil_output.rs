//! What a run on a nonlinear foundation reports of its soil (docs/theory.md §13): the law, the self-weight
//! settlement, the soil's work and stored energy from the ledger, and where and when the rail lifted off it.
//! Lengths and gaps in m, times in s, energies in J.

use fem_beam::LiftOffZone;
use fem_beam::extreme::{Extreme, largest_zone};
use serde::Serialize;
use track::RunResult;

/// A tensionless or bilinear soil under one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SoilSummary {
    /// "tensionless" or "bilinear".
    pub law: &'static str,
    /// α = k_t/k_c (0 tensionless).
    pub tension_ratio: f64,
    /// k_c (N/m²).
    pub compression_stiffness: f64,
    /// The rail's self-weight settlement ρA·g/k_c far from supports (m); 0 without self-weight.
    pub settlement: f64,
    /// Foundation sections (Gauss points).
    pub sections: usize,
    /// Work of the soil's unilateral part on the rail over the run (J; the linear part k_t is in the strain energy).
    pub soil_work: f64,
    /// Energy its springs hold at the end (J, from the soil's surface: includes the self-weight's settlement).
    pub soil_energy: f64,
    /// Sections that lifted off at some time where the results are read.
    pub lifted_sections: usize,
    /// The largest gap between rail and soil over the run where the results are read (m), where and when; 0 if the
    /// rail never left the soil there.
    pub largest_gap: Extreme,
    /// The zones of neighbouring sections that lifted where the results are read, in order of x (the largest gap
    /// above is theirs).
    pub lift_off_zones: Vec<LiftOffZone>,
    /// Where the results are read (m): `[output] extremes_nodes`, else the extremes window of load positions.
    pub read_region: [f64; 2],
    /// The zones wholly outside that region: end effects of the supports, the absorbing zones and the load's entry
    /// and exit, not the response of a long track.
    pub end_effect_zones: Vec<LiftOffZone>,
}

impl SoilSummary {
    /// The soil of `model` under `result`, its lift-off read over `read` = [a, b] (m); None on a linear foundation.
    pub fn of(model: &fem_beam::BeamModel, self_weight: bool, result: &RunResult, read: [f64; 2]) -> Option<Self> {
        let lift = result.lift_off.as_ref()?;
        let foundation = model.foundation();
        if foundation.law.is_linear() {
            return None;
        }
        let law = foundation.law.name();
        let (zones, ends): (Vec<LiftOffZone>, Vec<LiftOffZone>) =
            lift.zones.iter().cloned().partition(|z| z.to >= read[0] && z.from <= read[1]);
        let largest_gap = largest_zone(&zones).map_or(Extreme::default(), |z| z.largest_gap);
        let settlement = match self_weight {
            true => foundation.settlement(model.beam()),
            false => 0.0,
        };
        Some(Self {
            law,
            tension_ratio: foundation.law.tension_ratio(),
            compression_stiffness: foundation.stiffness,
            settlement,
            sections: lift.sections,
            soil_work: result.energy.support_work,
            soil_energy: result.energy.spring_energy,
            lifted_sections: zones.iter().map(|z| z.sections).sum(),
            largest_gap,
            lift_off_zones: zones,
            read_region: read,
            end_effect_zones: ends,
        })
    }
}
