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
//!   not change and its slope stays small) — the limit is here, the check of a run's result with the result
//!   (`study::result_warnings`).

use crate::number::number;
use crate::speeds::SpeedScale;
use crate::warning::Warning;
use crate::{Case, Scenario};
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
        out.extend(beyond_the_critical_speed(&case.settings.moving, v_cr));
    }
    out.extend(steep_rail(case));
    out
}

/// A speed above [`CRITICAL_SPEED_MULTIPLE`]·`v_cr` (m/s) anywhere in the run: an accelerating load's or a profile's
/// fastest (named by the key that sets it), not only its speed at x = 0.
fn beyond_the_critical_speed(moving: &track::simulation::MovingLoadSettings, v_cr: f64) -> Option<Warning> {
    let v = moving.largest_speed();
    if v <= CRITICAL_SPEED_MULTIPLE * v_cr {
        return None;
    }
    let (field, value, verb) = match (moving.speed_setting(), moving.acceleration) {
        (track::Setting::Acceleration, Some(a)) => {
            ("load.acceleration", format!("{} m/s²", number(a)), format!("brings the load to {} m/s,", number(v)))
        }
        (track::Setting::SpeedProfile, _) => {
            ("load.speed_profile", "given".into(), format!("brings the load to {} m/s,", number(v)))
        }
        _ => ("load.speed", format!("{} m/s", number(v)), "is".into()),
    };
    Some(Warning {
        field: field.into(),
        value,
        message: format!(
            "{verb} {:.1} × the critical speed v_cr = {v_cr:.1} m/s, above {CRITICAL_SPEED_MULTIPLE} v_cr: far beyond \
             railway speeds and beyond where a Winkler foundation (no inertia, no waves of its own) stands for a soil; \
             the numbers are the model's, not the track's",
            v / v_cr
        ),
    })
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
