//! Inputs and results outside the model's validity: a linear Euler–Bernoulli beam with small deflections and
//! slopes, loaded by railway loads at railway speeds (docs/theory.md §2–§4). Each is decided once, here:
//!
//! - **Refused** where no answer can be given: a speed at or above the beam's bar wave speed √(E/ρ) (the step
//!   h = Δx/v collapses and no beam theory holds; `track`'s run settings), a vehicle whose weight lifts a wheel off a
//!   level rail (a unilateral contact cannot start in tension; `track`'s vehicles).
//! - **Warned** where the model runs but the answer is outside its validity — said with the value and the limit:
//!   a single load, axle or static wheel load above [`LOAD_LIMIT`] (the heaviest railway axles weigh 0.34 MN);
//!   a speed above [`CRITICAL_SPEED_MULTIPLE`]·v_cr (far beyond where the Winkler foundation, without its own
//!   inertia and wave propagation, describes a soil, and beyond any railway speed on it); a rail irregularity steeper
//!   than [`SLOPE_LIMIT`] (the contact laws take small slopes; a dipped joint reaches ~5 %); and, after a run, a
//!   deflection beyond [`DEFLECTION_LIMIT`] of the beam's length (small-deflection theory: the beam's length does
//!   not change and its slope stays small).

use crate::diagnostics::Warning;
use crate::mesh_ripple::{RIPPLE_LIMIT, shorter_elements};
use crate::number::number;
use crate::scenario::{Case, Scenario};
use crate::speeds::SpeedScale;
use track::Load;

/// A point load (N) above which the load is no railway load: 1 MN, about three of the heaviest axles (35 t).
pub const LOAD_LIMIT: f64 = 1e6;
/// Speeds above this multiple of v_cr are warned about.
pub const CRITICAL_SPEED_MULTIPLE: f64 = 3.0;
/// Rail slopes (dh/dx) above this are warned about.
pub const SLOPE_LIMIT: f64 = 0.1;
/// Deflections above this fraction of the beam's length are warned about.
pub const DEFLECTION_LIMIT: f64 = 0.01;

/// Warnings for inputs outside the model's validity (see the module documentation).
pub fn input_warnings(scenario: &Scenario, case: &Case) -> Vec<Warning> {
    let mut out = Vec::new();
    out.extend(heavy_loads(case));
    if let Ok(SpeedScale { critical_speed: Some(v_cr), .. }) = SpeedScale::of(scenario) {
        let v = case.settings.moving.speed;
        if v > CRITICAL_SPEED_MULTIPLE * v_cr {
            out.push(Warning {
                field: "load.speed".into(),
                value: format!("{} m/s", number(v)),
                message: format!(
                    "is {:.1} × the critical speed v_cr = {v_cr:.1} m/s, above {CRITICAL_SPEED_MULTIPLE} v_cr: far \
                     beyond railway speeds and beyond where a Winkler foundation (no inertia, no waves of its own) \
                     stands for a soil; the numbers are the model's, not the track's",
                    v / v_cr
                ),
            });
        }
    }
    out.extend(steep_rail(case));
    out
}

/// Loads above [`LOAD_LIMIT`]: the single load, a train's axles as the beam carries them, vehicles' static wheel
/// loads.
fn heavy_loads(case: &Case) -> Option<Warning> {
    let moving = &case.settings.moving;
    let heaviest = |train: &fem_beam::Train| train.axles.iter().map(|a| a.force).fold(0.0, f64::max);
    let (field, what, largest) = match &moving.load {
        Load::Vehicles { vehicles, .. } => ("vehicle", "static wheel load", heaviest(&vehicles.static_train().ok()?)),
        Load::Train(train) => ("load.train", "axle load", heaviest(train)),
        Load::Force(force) => ("load.force", "load", *force),
    };
    (largest > LOAD_LIMIT).then(|| Warning {
        field: field.into(),
        value: format!("{what} {largest:.4e} N"),
        message: format!(
            "puts {:.3e} N on the beam at one point, above {:.0e} N: no railway load (the heaviest axles, 35 t, \
             weigh 0.34 MN); expect deflections outside the linear model",
            largest, LOAD_LIMIT
        ),
    })
}

/// The rail's largest slope over the beam above [`SLOPE_LIMIT`], sampled every centimetre (every 1e-5 of the length
/// on beams over a kilometre) — unless the profile's slope bound already keeps below it (a random rail's 100 000
/// samples of ~300 harmonics took 65 % of a 200 m vehicle run).
fn steep_rail(case: &Case) -> Option<Warning> {
    let vehicles = case.settings.moving.load.vehicles()?;
    if vehicles.profile.slope_bound() <= SLOPE_LIMIT {
        return None;
    }
    let length = case.model.mesh().length;
    let dx = (0.01f64).max(length * 1e-5);
    let samples = (length / dx).ceil() as usize;
    let (slope, at) = (0..=samples)
        .map(|i| {
            let x = i as f64 * dx;
            (vehicles.profile.height_slope(x).1.abs(), x)
        })
        .fold((0.0, 0.0), |best, s| if s.0 > best.0 { s } else { best });
    (slope > SLOPE_LIMIT).then(|| Warning {
        field: "rail.irregularities".into(),
        value: format!("slope {slope:.3} at x = {at:.2} m"),
        message: format!(
            "the rail is steeper than {SLOPE_LIMIT} (dh/dx) there: the wheel–rail contact takes small slopes \
             (a dipped joint reaches ~0.05), and a wheel following such a rail is thrown by forces no track carries; \
             check the amplitude against the wavelength"
        ),
    })
}

/// Warnings for a run's result outside the model's validity: a deflection beyond [`DEFLECTION_LIMIT`] of the beam's
/// length; on a nonlinear soil, the rail thrown off it by more than the load's static deflection where the results
/// are read (a weightless rail on a tensionless soil rose 827 mm on the reference track: nothing brings it back, and
/// the linear beam's small deflections no longer hold).
pub fn result_warnings(case: &Case, summary: &crate::run_summary::RunSummary) -> Vec<Warning> {
    let mut out = Vec::new();
    if let Some(soil) = &summary.soil
        && soil.largest_gap > summary.extremes.static_max_downward_deflection
        && summary.extremes.static_max_downward_deflection > 0.0
    {
        out.push(Warning {
            field: "result".into(),
            value: format!("lift-off {:.1} mm", soil.largest_gap * 1e3),
            message: format!(
                "the rail left the {} soil by more than the load's static deflection ({:.1} mm) at x = {:.1} m: it \
                 is thrown off the soil, not riding on it{}; the numbers are the model's",
                soil.law,
                summary.extremes.static_max_downward_deflection * 1e3,
                soil.largest_gap_position.unwrap_or(f64::NAN),
                if soil.settlement > 0.0 { "" } else { " (without self-weight nothing brings it back)" }
            ),
        });
    }
    out.extend(ripple_warning(case, summary));
    let length = case.model.mesh().length;
    let largest = summary.extremes.max_downward_deflection.max(summary.extremes.max_upward_deflection);
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
fn ripple_warning(case: &Case, summary: &crate::run_summary::RunSummary) -> Option<Warning> {
    let wheels = &summary.vehicles.as_ref()?.wheels;
    let relative = |w: &crate::vehicle_output::WheelReport| w.element_ripple.map_or(0.0, |r| r / w.static_force);
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
