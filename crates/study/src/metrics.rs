//! Metrics of docs/theory.md §6 beyond what a run reports: the static mid-span references and the dynamic amplification
//! factors φ_w(τ) = w(τ)/w_sta and φ_M(τ) = M(τ)/M_sta at mid-span, τ = x_c/L the load's relative position.

use fem_beam::LoadVector;
use fem_beam::section::Motion;
use scenario::Case;
use scenario::error::Result;
use serde::{Deserialize, Serialize};
use track::simulation::SectionHistory;

/// Static mid-span response with the load at mid-span and no friction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StaticReference {
    /// w_sta (m, negative: downward).
    pub deflection: f64,
    /// M_sta (N·m, from element end forces).
    pub moment: f64,
}

/// w_sta and M_sta of `case` under its heaviest axle (the force of a single load) standing at mid-span.
pub fn static_midspan(case: &Case) -> Result<StaticReference> {
    let model = &case.model;
    let mid = model.mesh().length / 2.0;
    let heaviest = case.settings.moving.load.train().axles.iter().fold(0.0f64, |m, a| m.max(a.force));
    let load = LoadVector::point_force(&model.discretisation(), mid, -heaviest)?;
    let q = model.static_solve(&load)?;
    let moments = model.nodal_moments(&q, &load, Motion::default())?;
    Ok(StaticReference { deflection: model.deflection_at(&q, mid)?, moment: moments.at(mid) })
}

/// One sample of the dynamic amplification at a section.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Amplification {
    /// τ = x_c/L.
    pub tau: f64,
    /// φ_w = w/w_sta.
    pub deflection: f64,
    /// φ_M = M/M_sta.
    pub moment: f64,
}

/// φ_w(τ), φ_M(τ) along a recorded history (one sample per step, only while the load is on the beam).
pub fn amplification(history: &SectionHistory, reference: StaticReference, length: f64) -> Vec<Amplification> {
    (0..history.time.len())
        .filter(|&k| (0.0..=length).contains(&history.load_position[k]))
        .map(|k| Amplification {
            tau: history.load_position[k] / length,
            deflection: history.deflection[k] / reference.deflection,
            moment: history.moment[k] / reference.moment,
        })
        .collect()
}
