//! A run's result outside the model's validity (the limits and the input checks: `scenario::plausibility`): a
//! deflection beyond [`DEFLECTION_LIMIT`] of the beam's length, a rail thrown off a nonlinear soil, a wheel force
//! carrying the mesh's element ripple.

use crate::mesh_ripple::{RIPPLE_LIMIT, shorter_elements};
use crate::run_summary::RunSummary;
use crate::vehicle_output::WheelReport;
use scenario::Case;
use scenario::diagnostics::Warning;
use scenario::plausibility::DEFLECTION_LIMIT;

/// Warnings for a run's result outside the model's validity: a deflection beyond [`DEFLECTION_LIMIT`] of the beam's
/// length; on a nonlinear soil, the rail thrown off it by more than the load's static deflection where the results
/// are read (a weightless rail on a tensionless soil rose 827 mm on the reference track: nothing brings it back, and
/// the linear beam's small deflections no longer hold).
pub fn result_warnings(case: &Case, summary: &RunSummary) -> Vec<Warning> {
    let mut out = Vec::new();
    if let Some(soil) = &summary.soil
        && soil.largest_gap.value > summary.extremes.static_max_downward_deflection
        && summary.extremes.static_max_downward_deflection > 0.0
    {
        out.push(Warning {
            field: "result".into(),
            value: format!("lift-off {:.1} mm", soil.largest_gap.value * 1e3),
            message: format!(
                "the rail left the {} soil by more than the load's static deflection ({:.1} mm) at x = {:.1} m: it \
                 is thrown off the soil, not riding on it{}; the numbers are the model's",
                soil.law,
                summary.extremes.static_max_downward_deflection * 1e3,
                soil.largest_gap.position.unwrap_or(f64::NAN),
                if soil.settlement > 0.0 { "" } else { " (without self-weight nothing brings it back)" }
            ),
        });
    }
    out.extend(ripple_warning(case, summary));
    let length = case.model.mesh().length;
    let largest = summary.extremes.deflection.max_downward.value.max(summary.extremes.deflection.max_upward.value);
    if largest > DEFLECTION_LIMIT * length {
        out.push(Warning {
            field: "result".into(),
            value: format!("deflection {:.4e} m", largest),
            message: format!(
                "is {:.1} % of the beam's {length} m length, above {} %: beyond small deflections, where the linear \
                 beam the model is stops holding; check the loads and the model",
                100.0 * largest / length,
                100.0 * DEFLECTION_LIMIT
            ),
        });
    }
    out
}

/// The wheel whose force carries the largest element ripple relative to its static load, when that is above
/// [`RIPPLE_LIMIT`]: a mesh artefact, said with the element length (and element count) that removes it.
fn ripple_warning(case: &Case, summary: &RunSummary) -> Option<Warning> {
    let wheels = &summary.vehicles.as_ref()?.wheels;
    let relative = |w: &WheelReport| w.element_ripple.map_or(0.0, |r| r / w.static_force);
    let wheel = wheels.iter().max_by(|a, b| relative(a).total_cmp(&relative(b)))?;
    let ripple = wheel.element_ripple.filter(|_| relative(wheel) > RIPPLE_LIMIT)?;
    let mesh = case.model.mesh();
    let l = mesh.element_length();
    let (shorter, elements) = shorter_elements(ripple, wheel.static_force, l, mesh.elements);
    let advance = case.settings.integration.load_advance;
    let check = match advance > shorter / 4.0 {
        true => {
            format!(" and integration.load_advance ≤ {} m (four steps an element, to see the ripple)", shorter / 4.0)
        }
        false => String::new(),
    };
    Some(Warning {
        field: "mesh.elements".into(),
        value: mesh.elements.to_string(),
        message: format!(
            "wheel {}'s force carries a ripple of {:.0} N ({:.1} % of its static load {:.1} kN) with the element \
             period {l} m where results are read: a mesh artefact (the track is the same everywhere), above {} %; \
             elements of {shorter} m (mesh.elements = {elements}{check}) bring it below",
            wheel.wheel,
            ripple,
            100.0 * ripple / wheel.static_force,
            wheel.static_force / 1e3,
            100.0 * RIPPLE_LIMIT
        ),
    })
}
