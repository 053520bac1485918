//! The co-moving window (docs/theory.md §15): the load crosses an endless track through a short window that shifts
//! with it; its wave against the closed form, the stationary solve and the energy identity.

use analytic::reference::{InfiniteBeam, SteadyState, uic60_on_soft_soil};
use fem_beam::{AbsorbingZones, BeamModel, Foundation, FoundationLaw, Mesh, Supports};
use track::co_moving::{CoMovingResult, CoMovingSettings, run_co_moving};
use track::{BallastOnBeam, DistributedFriction, PlacedInteractions, RunSettings};

/// A free window of `length` m in 0.25 m elements with absorbing zones of `zones` m (up to c_cr at the ends).
fn window(law: FoundationLaw, zeta: f64, length: f64, zones: f64) -> BeamModel {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { law, ..case.foundation.with_damping_ratio(zeta, &case.beam).unwrap() };
    let mesh = Mesh::new(length, (length / 0.25) as usize).unwrap();
    let zones = AbsorbingZones { length: zones, peak_damping: foundation.critical_damping(&case.beam) };
    let damping = zones.element_damping(&mesh, foundation.damping).unwrap();
    BeamModel::with_element_damping(
        case.beam,
        foundation,
        mesh,
        Supports { left: fem_beam::Support::Free, right: fem_beam::Support::Clamped },
        damping,
    )
    .unwrap()
}

fn co_moving(model: &BeamModel, placed: &PlacedInteractions, speed: f64, track: f64) -> CoMovingResult {
    let mut settings = RunSettings::default();
    settings.moving.speed = speed;
    settings.integration.load_advance = 0.05;
    let length = model.mesh().length;
    let at = CoMovingSettings { load_at: 0.5 * length, track_length: track, middle: (0.25 * length, 0.75 * length) };
    run_co_moving(model, placed, &settings, &at).unwrap()
}

/// The infinite beam's steady state under the reference load at `speed` (m/s) on the window's soil.
fn steady_state(model: &BeamModel, speed: f64) -> SteadyState {
    let beam = uic60_on_soft_soil().beam;
    InfiniteBeam::new(&beam, model.foundation()).unwrap().steady_state(speed, 83.4e3).unwrap()
}

/// max |W − the closed form| over the nodes within 30 m of the load (m).
fn error_within_30_m(r: &CoMovingResult, closed: &SteadyState) -> f64 {
    r.wave.iter().filter(|(s, _)| s.abs() <= 30.0).map(|(s, w)| (w - closed.deflection(*s)).abs()).fold(0.0, f64::max)
}

/// A damped linear track: after a few window lengths the wave in the frame is the closed form of the infinite beam
/// (docs/theory.md §8) below the critical speed, to 1e-4 of the peak (measured 1.1e-5 at 100 m/s after 600 m; the
/// change per window length falls by ~8× each window), and the energy identity closes with what the window
/// carried out.
#[test]
fn the_co_moving_wave_is_the_closed_form() {
    let model = window(FoundationLaw::Linear, 0.05, 120.0, 30.0);
    let r = co_moving(&model, &PlacedInteractions::new(), 100.0, 600.0);
    let closed = steady_state(&model, 100.0);
    let peak = closed.deflection(0.0).abs();
    let error = error_within_30_m(&r, &closed);
    assert!(error <= 1e-4 * peak, "{:e} of the peak", error / peak);
    let (first, last) = (r.changes[0].1, r.changes.last().unwrap().1);
    assert!(last <= 1e-5 && last < first / 1e3, "changes per window length {:?}", r.changes);
    assert_eq!((r.steps, r.shifts), (12_000, 2_400));
    let e = &r.energy;
    // Round-off of 12 000 steps of O(1e3 J) sums; the transported energy (~0.1 J) is booked, not lost.
    assert!(e.residual().abs() <= 1e-9 * e.load_work, "{:e} of {:e}", e.residual(), e.load_work);
    assert!(e.transported < 0.0);
    // The run's extremes are placed on the track, not in the window: the largest downward deflection moves with the
    // load (x_load = 60 m + v t on the track) and sits within an element or two of it (the closed form's trough at
    // 100 m/s is 0.07 m behind the load; 0.5 m elements). Over the whole run it is the start's transient (the load
    // set moving from its static bowl: at t = 0.08 s), at least the steady trough.
    let (x, t) = r.deflection.max_downward.place().unwrap();
    assert!((x - (60.0 + 100.0 * t)).abs() <= 1.0, "at x = {x} m, t = {t} s");
    assert!(
        r.deflection.max_downward.value >= (1.0 - 1e-4) * peak,
        "{} against {peak}",
        r.deflection.max_downward.value
    );
}

/// Cost per step does not depend on the length of track: the window is all that is ever stored or stepped.
#[test]
fn a_longer_track_is_more_steps_of_the_same_window() {
    let model = window(FoundationLaw::Linear, 0.05, 60.0, 15.0);
    let short = co_moving(&model, &PlacedInteractions::new(), 100.0, 100.0);
    let long = co_moving(&model, &PlacedInteractions::new(), 100.0, 2000.0);
    assert_eq!(long.steps, 20 * short.steps);
    assert_eq!(long.wave.len(), short.wave.len());
}

/// Friction in the ballast travels with the window: with a huge f_u the rail never moves — the static bowl it started
/// in stays where it was and leaves the window behind, and the load crosses rail that stays at rest (W ≡ 0 to the
/// solver's tolerance); with 5 kN/m the wave settles (its change per window length falls below 1e-3).
#[test]
fn friction_travels_with_the_window() {
    let model = window(FoundationLaw::Linear, 0.05, 60.0, 15.0);
    let stuck = DistributedFriction::new(1e8).interactions(&model).unwrap();
    let r = co_moving(&model, &stuck, 150.0, 90.0);
    let linear = co_moving(&model, &PlacedInteractions::new(), 150.0, 90.0);
    let largest = |r: &CoMovingResult| r.wave.iter().fold(0.0f64, |m, (_, w)| m.max(w.abs()));
    assert!(largest(&r) <= 1e-6 * largest(&linear), "{:e} vs {:e}", largest(&r), largest(&linear));
    let ballast = DistributedFriction::new(5e3).interactions(&model).unwrap();
    let r = co_moving(&model, &ballast, 150.0, 300.0);
    assert!(r.changes.last().unwrap().1 <= 1e-3, "{:?}", r.changes);
    // Behind the wave friction holds the rail still with a residual deflection W_res, |W_res| ≤ f_u/k (docs/theory.md
    // §13: k|W| ≤ f_u where the rail sticks), here 20 mm; read between the wave and the rear absorbing zone.
    let bound = 5e3 / model.foundation().stiffness;
    let behind: Vec<f64> = r.wave.iter().filter(|(s, _)| (-14.0..=-10.0).contains(s)).map(|(_, w)| *w).collect();
    assert!(!behind.is_empty() && behind.iter().all(|w| w.abs() <= bound), "{behind:?} against ±{bound} m");
    assert!(behind.iter().any(|w| w.abs() > 1e-2 * bound), "friction leaves a deflection behind: {behind:?}");
    assert!(r.energy.friction_work < 0.0);
    assert!(r.energy.residual().abs() <= 1e-9 * r.energy.load_work);
}

/// Above the critical speed the damped wave reaches far from the load, and the window must hold it and the step
/// resolve it: at 250 m/s (ζ = 5 %, load in the middle) the wave around the load differs from the closed form by
/// 7.3e-3 of the peak with a 120 m window, 1.6e-3 with 240 m and 6.0e-4 with 480 m or 960 m at Δx = 0.05 m — there
/// the θ-method's O(h²) error: 1.5e-4 at 0.025 m, and below the stated 1e-4 at 0.0125 m.
#[test]
#[ignore = "a 480 m window over 1.5 km in 0.0125 m steps: ~10 s; run with --ignored"]
fn above_the_critical_speed_a_long_enough_window_carries_the_closed_form() {
    let model = window(FoundationLaw::Linear, 0.05, 480.0, 30.0);
    let mut settings = RunSettings::default();
    settings.moving.speed = 250.0;
    settings.integration.load_advance = 0.0125;
    let at = CoMovingSettings { load_at: 240.0, track_length: 1500.0, middle: (120.0, 360.0) };
    let r = run_co_moving(&model, &PlacedInteractions::new(), &settings, &at).unwrap();
    let peak = r.deflection.max_downward.value;
    let error = error_within_30_m(&r, &steady_state(&model, 250.0));
    assert!(error <= 1e-4 * peak, "{:e} of the peak", error / peak);
}

/// A window whose ends are not free behind and clamped ahead is refused naming the end and its support as they are
/// (the message once read `supports = 0`).
#[test]
fn a_window_with_other_supports_is_refused_naming_the_end() {
    let case = uic60_on_soft_soil();
    let mesh = Mesh::new(60.0, 240).unwrap();
    let at = CoMovingSettings { load_at: 30.0, track_length: 100.0, middle: (15.0, 45.0) };
    let mut settings = RunSettings::default();
    settings.integration.load_advance = 0.05;
    for (supports, said) in [
        (Supports::default(), "invalid supports.left = pinned: a co-moving window has a free rear end"),
        (
            Supports { left: fem_beam::Support::Free, right: fem_beam::Support::Free },
            "invalid supports.right = free: a co-moving window has a free rear end",
        ),
    ] {
        let model = BeamModel::new(case.beam, case.foundation, mesh, supports).unwrap();
        let error = run_co_moving(&model, &PlacedInteractions::new(), &settings, &at).unwrap_err().to_string();
        assert!(error.starts_with(said), "{error}");
    }
}
