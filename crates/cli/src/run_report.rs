//! The report of one `frictrack run`: what ran and what it gave, typed for the JSON (`--format json`,
//! `summary.json`) and the text report ([`crate::run_text`]). Absent values are absent: an extreme that never
//! happened is None (null), not a placeholder 0 at x = 0, t = 0.

use anyhow::Result;
use friction::InteractionKind;
use serde::Serialize;
use study::{Case, Scenario};
use track::RunResult;
use track::vehicle::consist::VehicleSettings;

/// Extremes in the JSON report (m, m, s; magnitudes).
#[derive(Debug, Serialize)]
pub(crate) struct ExtremeReport {
    pub(crate) deflection: f64,
    pub(crate) position: f64,
    pub(crate) time: f64,
    pub(crate) load_position: f64,
}

/// What the text report says of the extremes window, true for the run: whose position it is (the load, or a
/// train's first axle), why it is there (the default middle third, or given), and what lies around it.
#[derive(Debug, Default)]
pub(crate) struct WindowWording {
    /// "load" or "first axle".
    pub(crate) load: &'static str,
    /// Why the window is where it is.
    pub(crate) why: &'static str,
}

impl WindowWording {
    fn of(scenario: &Scenario, case: &Case) -> Self {
        let load = if matches!(case.settings.moving.load, track::Load::Train(_)) { "first axle" } else { "load" };
        let span = scenario.foundation.stiffness == 0.0;
        let why = match (scenario.output.extremes_window.is_some(), span) {
            (true, _) => "the window given by [output] extremes_window or --extremes-window",
            (false, true) => "the middle third of the span",
            (false, false) => "the middle third, away from the ends: the response of a long track",
        };
        Self { load, why }
    }
}

/// The JSON report of `frictrack run`. Deflections are positive magnitudes (m), relative to the self-weight state.
#[derive(Debug, Serialize)]
pub(crate) struct RunReport {
    pub(crate) title: String,
    pub(crate) speed: f64,
    pub(crate) load: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) train: Option<crate::trains::TrainSummary>,
    /// With a train: what the beam carries of its axles (`[load] carries`), by which the train's forces were scaled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) axle_share: Option<AxleShareReport>,
    pub(crate) critical_speed: Option<f64>,
    pub(crate) damping_ratio: f64,
    pub(crate) devices: usize,
    pub(crate) device_force: f64,
    pub(crate) device_positions: Vec<f64>,
    pub(crate) distributed_friction: f64,
    pub(crate) max_downward_deflection: f64,
    pub(crate) max_downward_deflection_position: Option<f64>,
    pub(crate) max_downward_deflection_time: Option<f64>,
    pub(crate) max_upward_deflection: f64,
    pub(crate) max_upward_deflection_position: Option<f64>,
    pub(crate) max_upward_deflection_time: Option<f64>,
    pub(crate) max_acceleration: f64,
    pub(crate) max_acceleration_position: Option<f64>,
    pub(crate) max_acceleration_time: Option<f64>,
    pub(crate) static_max_downward_deflection: f64,
    pub(crate) dynamic_amplification: f64,
    pub(crate) extremes_window: (f64, f64),
    pub(crate) extremes_nodes: Option<(f64, f64)>,
    pub(crate) window_max_downward: Option<ExtremeReport>,
    pub(crate) window_max_upward: Option<ExtremeReport>,
    /// How the text names the extremes window (not in JSON: the numbers are).
    #[serde(skip)]
    pub(crate) window_wording: WindowWording,
    pub(crate) global_norm: f64,
    pub(crate) load_work: f64,
    pub(crate) friction_work: f64,
    pub(crate) friction_dissipation: f64,
    pub(crate) viscous_dissipation: f64,
    pub(crate) dissipated_energy: f64,
    pub(crate) numerical_dissipation: f64,
    pub(crate) energy_residual: f64,
    pub(crate) steps: usize,
    pub(crate) time_step: f64,
    pub(crate) sections: usize,
    pub(crate) mean_iterations: f64,
    pub(crate) max_iterations: usize,
    pub(crate) max_residual: f64,
    pub(crate) mean_sections_solved: f64,
    pub(crate) solver: String,
    pub(crate) fallback_steps: usize,
    pub(crate) fallbacks: Vec<FallbackReport>,
    pub(crate) wall_time: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) vehicles: Option<study::vehicle_output::VehicleReport>,
}

/// What the beam carries of a train's axles.
#[derive(Debug, Serialize)]
pub(crate) struct AxleShareReport {
    /// `one-rail` or `whole-axle`.
    pub(crate) carries: &'static str,
    /// The factor on the axle loads (½ or 1).
    pub(crate) factor: f64,
    /// In words.
    #[serde(skip)]
    pub(crate) meaning: &'static str,
}

/// Steps of the run solved by one fallback solver (the run's solver failed on them).
#[derive(Debug, Serialize)]
pub(crate) struct FallbackReport {
    pub(crate) solver: &'static str,
    pub(crate) steps: usize,
}

pub(crate) fn report(scenario: &Scenario, case: &Case, result: &RunResult, wall_time: f64) -> Result<RunReport> {
    let e = &result.energy;
    let s = &result.statistics;
    let settings = &case.settings;
    let device_positions: Vec<f64> = (0..case.interactions.len())
        .filter(|&j| case.interactions.kinds()[j] == InteractionKind::Device)
        .map(|j| case.interactions.positions()[j])
        .collect();
    let window = result.window.unwrap_or_default();
    let x0 = settings.start_position();
    let extreme = |x: &track::simulation::Extreme| {
        x.happened().map(|x| ExtremeReport {
            deflection: x.magnitude,
            position: x.position,
            time: x.time,
            load_position: x0 + settings.moving.speed * x.time,
        })
    };
    let critical = study::speeds::SpeedScale::of(scenario)?.critical_speed;
    let statics = track::statics::static_envelope(
        &case.model,
        &settings.moving.load.train(),
        settings.integration.load_advance,
        settings.record.extremes_nodes,
    )?;
    let foundation = case.model.foundation();
    Ok(RunReport {
        title: scenario.title.clone(),
        speed: settings.moving.speed,
        load: scenario.load.force,
        train: settings.moving.load.axles().map(crate::trains::TrainSummary::of),
        axle_share: settings.moving.load.axles().filter(|t| t.name != "single").map(|_| {
            let share = scenario.axle_share();
            AxleShareReport { carries: share.name(), factor: share.factor(), meaning: share.describe() }
        }),
        critical_speed: critical,
        damping_ratio: foundation.damping_ratio(case.model.beam()),
        devices: device_positions.len(),
        device_force: scenario.friction.devices.as_ref().and_then(|d| d.force).unwrap_or(0.0),
        device_positions,
        distributed_friction: scenario.friction.distributed.as_ref().map_or(0.0, |d| d.force_per_length),
        max_downward_deflection: result.max_downward.magnitude,
        max_downward_deflection_position: result.max_downward.happened().map(|x| x.position),
        max_downward_deflection_time: result.max_downward.happened().map(|x| x.time),
        max_upward_deflection: result.max_upward.magnitude,
        max_upward_deflection_position: result.max_upward.happened().map(|x| x.position),
        max_upward_deflection_time: result.max_upward.happened().map(|x| x.time),
        max_acceleration: result.max_acceleration.magnitude,
        max_acceleration_position: result.max_acceleration.happened().map(|x| x.position),
        max_acceleration_time: result.max_acceleration.happened().map(|x| x.time),
        static_max_downward_deflection: statics.max_downward,
        dynamic_amplification: if statics.max_downward > 0.0 {
            result.max_downward.magnitude / statics.max_downward
        } else {
            0.0
        },
        extremes_window: window.load_range,
        extremes_nodes: settings.record.extremes_nodes,
        window_max_downward: extreme(&window.max_downward),
        window_max_upward: extreme(&window.max_upward),
        window_wording: WindowWording::of(scenario, case),
        global_norm: result.global_norm,
        load_work: e.load_work,
        friction_work: e.friction_work,
        // Positive, as `viscous_dissipation` and `dissipated_energy`: the energy friction removed (0 − W, not −W:
        // no "-0" without friction).
        friction_dissipation: 0.0 - e.friction_work,
        viscous_dissipation: e.viscous_dissipation,
        dissipated_energy: e.dissipated(),
        numerical_dissipation: e.numerical_dissipation,
        energy_residual: e.residual(),
        steps: s.steps,
        time_step: result.step,
        sections: s.sections,
        mean_iterations: s.mean_iterations,
        max_iterations: s.max_iterations,
        max_residual: s.max_residual,
        mean_sections_solved: s.mean_sections_solved,
        solver: s.solver_name().to_string(),
        fallback_steps: s.fallback_steps(),
        fallbacks: s.fallbacks.iter().map(|f| FallbackReport { solver: f.solver.name(), steps: f.steps }).collect(),
        wall_time,
        vehicles: result.vehicles.as_ref().map(|v| {
            let contact = settings.moving.load.vehicles().map_or("", VehicleSettings::contact_name);
            study::vehicle_output::VehicleReport::of(v, contact)
        }),
    })
}
