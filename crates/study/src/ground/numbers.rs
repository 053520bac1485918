//! The ground's own numbers and the track's on it (docs/theory.md §19): what `frictrack ground` reports.
//!
//! - The soil's trapped Rayleigh modes at each frequency asked, the fundamental's least phase velocity (refined).
//! - The static strip stiffness k_w: the Winkler spring under which the beam deflects as much under one static load
//!   as on the ground (w₀ = Pβ/2k_w, β = (k_w/4EI)^¼, so k_w = (P/(2w₀(4EI)^¼))^{4/3}), and the Winkler control,
//!   the critical speed of the beam on it, (4k_w EI/m²)^¼ — what a spring fitted to the site would predict.
//! - The crossing of the beam's dispersion curve on k_w, c(ω) = ω/((mω² − k_w)/EI)^¼, with the soil's fundamental
//!   mode (Mezher et al. 2016): a quick estimate of the critical speed; and of the free beam's, k_w = 0 (on a soft
//!   site the curve on k_w stays above the soil's: its least phase velocity is the Winkler control).
//! - The critical speed of the track on the ground: the speed of the largest steady downward deflection under one
//!   load, from a curve over speeds refined by golden section — of the composite beam, or of the rail on the two-beam
//!   track (its linear, bonded track; the estimates above then take its whole-track twin, `whole_track`).
//! - k_eq(k_x, k_x v) of the strip along the load's line at a few speeds.

use crate::ground::speeds::{SpeedPoint, critical_speed, point};
use crate::ground::support::Support;
use analytic::ground::{GroundedBeam, LineSupport, StripGround, rayleigh_phase_velocities};
use runner::Runner;
use scenario::Scenario;
use scenario::error::{Result, StudyError, invalid};
use scenario::ground::GroundTrack;
use serde::Serialize;
use std::f64::consts::TAU;

/// Speeds of the curve the critical speed is found on, evenly up to 1.2 times the larger of the Winkler control and
/// the half-space's shear-wave speed (on a soft site the critical speed on the ground lies below both).
const SPEEDS: usize = 24;
/// The moving-load spectra [`GroundStudy::of`] samples: the static case, its speeds and ~12 to refine the peak.
pub const SPECTRA: usize = 1 + SPEEDS + 12;
/// Wavenumbers of each k_eq curve, log-spaced over [`WAVENUMBERS`] (rad/m): 140 a decade, so that the peaks of the
/// higher modes a fast load crosses above 0.5 rad/m (a peak and its dip 0.04 decades apart on the soft site) take
/// ≥ 6 points between them (at 81 they took 2: a sawtooth).
const STIFFNESS_POINTS: usize = 321;
const WAVENUMBERS: (f64, f64) = (0.01, 2.0);

/// What to compute: the frequencies (Hz) of the dispersion curves.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundRequest {
    /// f (Hz), > 0, increasing.
    pub frequencies: Vec<f64>,
}

impl Default for GroundRequest {
    /// 1 to 50 Hz by 1 Hz: a soft site's Rayleigh modes and the track's critical band.
    fn default() -> Self {
        Self { frequencies: (1..=50).map(f64::from).collect() }
    }
}

/// The fundamental mode at one frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DispersionPoint {
    /// f (Hz).
    pub frequency: f64,
    /// c (m/s).
    pub phase_velocity: f64,
}

/// Every trapped mode at one frequency.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModesPoint {
    /// f (Hz).
    pub frequency: f64,
    /// The modes' c (m/s), slowest (the fundamental) first.
    pub phase_velocities: Vec<f64>,
}

/// k_eq on the load's line ω = k_x v.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StiffnessPoint {
    /// v (m/s).
    pub speed: f64,
    /// k_x (rad/m).
    pub wavenumber: f64,
    /// k_x v/2π (Hz).
    pub frequency: f64,
    /// Re k_eq (N/m²).
    pub stiffness_real: f64,
    /// Im k_eq (N/m²): the ground's radiation and damping.
    pub stiffness_imaginary: f64,
}

/// What stands on the ground, as the JSON's `track` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum TrackKind {
    /// The composite track-and-embankment beam.
    #[serde(rename = "composite beam")]
    CompositeBeam,
    /// One rail on sleepers over the embankment beam (the two-beam track): the critical speed is the rail's under the
    /// force, the quick estimates its whole-track twin's.
    #[serde(rename = "rail on sleepers over the embankment")]
    RailOnEmbankment,
}

/// The ground's numbers and the track's critical speed on it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroundStudy {
    /// The scenario's title.
    pub title: String,
    /// What the critical speed is of.
    pub track: TrackKind,
    /// The force the beam carries (N, downward): on the two-beam track one rail's.
    pub force: f64,
    /// EI (N·m²) of the beam the quick estimates take: the composite beam, or the two-beam track's whole-track twin
    /// (2EI_r + EI_e).
    pub bending_stiffness: f64,
    /// ρA (kg/m) of that beam (on the two-beam track 2(ρA_r + m_s/a) + ρA_e).
    pub mass_per_length: f64,
    /// 2b (m).
    pub width: f64,
    /// The profile in words.
    pub profile: String,
    /// The fundamental Rayleigh mode over frequency (where it is trapped).
    pub dispersion: Vec<DispersionPoint>,
    /// Every trapped mode over frequency.
    pub modes: Vec<ModesPoint>,
    /// The fundamental mode's least phase velocity (m/s): its lowest interior minimum, refined; on a homogeneous
    /// half-space its Rayleigh speed; `None` where the curve has no minimum inside the frequencies asked
    /// ([`super::phase_minimum::least_phase_velocity`]).
    pub minimum_phase_velocity: Option<f64>,
    /// Where (Hz); `None` on a non-dispersive ground (every frequency) or where the minimum is undefined.
    pub minimum_phase_velocity_frequency: Option<f64>,
    /// k_w (N/m²): the Winkler spring with the ground's static deflection under one load.
    pub static_strip_stiffness: f64,
    /// The static deflection under the force (m, downward): the composite beam's, or the rail's on the two-beam track
    /// (k_w is then its whole-track twin's under the same force: a Winkler spring does not depend on the force).
    pub static_deflection: f64,
    /// The critical speed of the beam on k_w (m/s).
    pub winkler_critical_speed: f64,
    /// Where the beam's dispersion curve on k_w meets the soil's fundamental mode (m/s); `None` if not in range.
    pub dispersion_crossing_speed: Option<f64>,
    /// Its frequency (Hz).
    pub dispersion_crossing_frequency: Option<f64>,
    /// Where the free beam's bending waves, c = (EI/m)^¼√ω, meet the soil's fundamental mode (m/s): the track's
    /// own waves against the soil's, with no stiffness under the beam; `None` if not in range.
    pub free_beam_crossing_speed: Option<f64>,
    /// Its frequency (Hz).
    pub free_beam_crossing_frequency: Option<f64>,
    /// The speed of the largest downward deflection (m/s), refined; `None` at an end of the speeds.
    pub critical_speed: Option<f64>,
    /// That deflection (m, downward).
    pub critical_deflection: Option<f64>,
    /// The steady wave's extremes over speeds.
    pub speeds: Vec<SpeedPoint>,
    /// k_eq(k_x, k_x v) at a few speeds.
    pub equivalent_stiffness: Vec<StiffnessPoint>,
    /// What makes a number undefined or doubtful.
    pub warnings: Vec<String>,
}

impl GroundStudy {
    /// The numbers of `scenario`'s beam on its `[ground]` for `request`, on `runner`'s threads.
    pub fn of(scenario: &Scenario, request: &GroundRequest, runner: &Runner<'_>) -> Result<Self> {
        let (rail_or_beam, strip, track) = scenario.ground_track()?;
        let beam = whole_track(&rail_or_beam, &track);
        let support = Support::of(&track, &strip);
        crate::receptance::response::check_frequencies(&request.frequencies)?;
        let mut warnings: Vec<String> = scenario.ground_warnings().iter().map(ToString::to_string).collect();
        let (force, title) = one_load(scenario, &mut warnings)?;
        // Said before any work: the static case, the curve, ~12 to refine its peak (the soil's modes cost little
        // beside them).
        runner.announce(runner::cost::Estimate::ground(SPECTRA, strip.profile.layers.len(), runner.threads()));
        let (modes, dispersion) = soil_modes(&strip, &request.frequencies, runner)?;
        let minimum = super::phase_minimum::least_phase_velocity(&strip, &dispersion, &mut warnings)?;
        let grounded = GroundedBeam::new(&beam, &strip)?;
        let (ei, m) = (beam.bending_stiffness(), beam.mass_per_length());
        let twin_static = -grounded.spectrum(0.0)?.deflection(0.0) * force;
        let spring = (force / (2.0 * twin_static * (4.0 * ei).powf(0.25))).powf(4.0 / 3.0);
        let carried = GroundedBeam::new(&rail_or_beam, support.line())?;
        let static_deflection = match track {
            GroundTrack::Composite => twin_static,
            GroundTrack::RailOnEmbankment { .. } => -carried.spectrum(0.0)?.deflection(0.0) * force,
        };
        let winkler_critical_speed = (4.0 * spring * ei / (m * m)).powf(0.25);
        let crossing = dispersion_crossing(&strip, &dispersion, (ei, m, spring));
        if crossing.is_none() {
            warnings.push(format!(
                "the beam's dispersion curve on k_w (its least phase velocity is the Winkler control, \
                 {winkler_critical_speed:.1} m/s) does not meet the soil's fundamental mode within the frequencies \
                 asked"
            ));
        }
        let free_crossing = dispersion_crossing(&strip, &dispersion, (ei, m, 0.0));
        if free_crossing.is_none() {
            warnings.push(
                "the free beam's bending waves do not meet the soil's fundamental mode within the frequencies asked"
                    .into(),
            );
        }
        let top = 1.2 * winkler_critical_speed.max(strip.profile.half_space.shear_wave_speed);
        let (curve, critical) = speed_curve(&carried, top, force, runner)?;
        if critical.is_none() {
            warnings.push(format!(
                "the largest deflection lies at an end of the speeds computed (up to {top:.1} m/s): no critical \
                 speed inside them"
            ));
        }
        let reference = critical.map_or(winkler_critical_speed, |c| c.0);
        let equivalent_stiffness = stiffness_curves(&strip, reference, runner)?;
        Ok(Self {
            title,
            track: match track {
                GroundTrack::Composite => TrackKind::CompositeBeam,
                GroundTrack::RailOnEmbankment { .. } => TrackKind::RailOnEmbankment,
            },
            force,
            bending_stiffness: ei,
            mass_per_length: m,
            width: strip.width,
            profile: describe(&strip),
            dispersion,
            modes,
            minimum_phase_velocity: minimum.map(|p| p.1),
            minimum_phase_velocity_frequency: minimum.and_then(|p| p.0),
            static_strip_stiffness: spring,
            static_deflection,
            winkler_critical_speed,
            dispersion_crossing_speed: crossing.map(|p| p.1),
            dispersion_crossing_frequency: crossing.map(|p| p.0),
            free_beam_crossing_speed: free_crossing.map(|p| p.1),
            free_beam_crossing_frequency: free_crossing.map(|p| p.0),
            critical_speed: critical.map(|p| p.0),
            critical_deflection: critical.map(|p| p.1),
            speeds: curve,
            equivalent_stiffness,
            warnings,
        })
    }
}

/// The one load the critical speed is of (N, downward, as the beam carries it) and the title its figures take: the
/// scenario's `load.force`, or on a scenario whose loads are a train its heaviest axle — said in a warning, and in
/// the title, so that no figure names a train that did not run.
fn one_load(scenario: &Scenario, warnings: &mut Vec<String>) -> Result<(f64, String)> {
    let train = match scenario.vehicle {
        None => scenario::trains::resolve(&scenario.load)?.map(|t| scenario.on_the_beam(t)),
        Some(_) => None,
    };
    let heaviest = train.as_ref().and_then(|t| t.axles.iter().map(|a| a.force).reduce(f64::max));
    let (Some(train), Some(force)) = (train.as_ref().filter(|t| t.axles.len() > 1), heaviest) else {
        let force = heaviest.unwrap_or(scenario.load.force);
        if !(force.is_finite() && force > 0.0) {
            return Err(invalid("load.force", force, "must be finite and > 0 (N)"));
        }
        return Ok((force, scenario.title.clone()));
    };
    warnings.push(format!(
        "the critical speed and the speed curve are of one load, the heaviest axle of the scenario's train {} \
         ({:.1} kN as the beam carries it): the train's own steady wave is the stationary wave's",
        train.name,
        force / 1e3
    ));
    let title = match scenario.title.is_empty() {
        true => format!("one {:.0} kN axle", force / 1e3),
        false => format!("{}: one {:.0} kN axle, not the train", scenario.title, force / 1e3),
    };
    Ok((force, title))
}

/// The beam the quick estimates take (the static strip stiffness, the Winkler control, the dispersion crossings): the
/// composite beam itself or, over the two-beam track, its long-wave twin for the whole track
/// (`Embankment::whole_track`).
fn whole_track(rail_or_beam: &fem_beam::Beam, track: &GroundTrack) -> fem_beam::Beam {
    match track {
        GroundTrack::Composite => *rail_or_beam,
        GroundTrack::RailOnEmbankment { sleepers, embankment, .. } => embankment.whole_track(rail_or_beam, sleepers),
    }
}

/// A refined peak: (speed m/s, deflection m).
type Peak = (f64, f64);

/// The steady extremes at [`SPEEDS`] speeds up to `top` (m/s) under `force` (N), and the critical speed refined
/// from them (speed, deflection), `None` at an end of the range.
fn speed_curve(
    grounded: &GroundedBeam<'_, dyn LineSupport + '_>,
    top: f64,
    force: f64,
    runner: &Runner<'_>,
) -> Result<(Vec<SpeedPoint>, Option<Peak>)> {
    let speeds: Vec<f64> = (1..=SPEEDS).map(|i| top * i as f64 / SPEEDS as f64).collect();
    let curve = runner.map(&speeds, |&v| match runner.is_stopped() {
        true => Err(StudyError::Interrupted),
        false => point(grounded, v, force),
    })?;
    let mut evaluate = |v: f64| point(grounded, v, force).map(|p| p.deflection.max_downward);
    let critical = critical_speed(&curve, &mut evaluate)?;
    Ok((curve, critical))
}

/// The soil's trapped modes at each of `frequencies` (Hz), and the fundamental where it is trapped.
fn soil_modes(
    strip: &StripGround,
    frequencies: &[f64],
    runner: &Runner<'_>,
) -> Result<(Vec<ModesPoint>, Vec<DispersionPoint>)> {
    let modes: Vec<ModesPoint> = runner.map(frequencies, |&frequency| {
        let phase_velocities = rayleigh_phase_velocities(&strip.profile, TAU * frequency);
        Ok(ModesPoint { frequency, phase_velocities })
    })?;
    let dispersion = modes
        .iter()
        .filter_map(|m| {
            m.phase_velocities.first().map(|&c| DispersionPoint { frequency: m.frequency, phase_velocity: c })
        })
        .collect();
    Ok((modes, dispersion))
}

/// The fundamental mode's phase velocity at `frequency` (Hz), or +∞ where it is not trapped.
pub(super) fn fundamental(strip: &StripGround, frequency: f64) -> f64 {
    rayleigh_phase_velocities(&strip.profile, TAU * frequency).first().copied().unwrap_or(f64::INFINITY)
}

/// Where the beam's free waves on the spring k_w, c_b(ω) = ω/((mω² − k_w)/EI)^¼ (above its cut-on √(k_w/m); the
/// free beam's (EI/m)^¼√ω for k_w = 0), first meet the soil's fundamental mode, from either side: (frequency, c),
/// bisected to 1e-6 Hz.
fn dispersion_crossing(
    strip: &StripGround,
    dispersion: &[DispersionPoint],
    (ei, m, spring): (f64, f64, f64),
) -> Option<(f64, f64)> {
    let beam = |frequency: f64| beam_phase_velocity(ei, m, spring, frequency);
    let above = |p: &DispersionPoint| beam(p.frequency) > p.phase_velocity;
    let i = dispersion.windows(2).position(|w| above(&w[0]) != above(&w[1]))?;
    let (mut lo, mut hi) = (dispersion[i].frequency, dispersion[i + 1].frequency);
    let starts_above = above(&dispersion[i]);
    while hi - lo > 1e-6 {
        let middle = 0.5 * (lo + hi);
        if (beam(middle) > fundamental(strip, middle)) == starts_above { lo = middle } else { hi = middle }
    }
    let frequency = 0.5 * (lo + hi);
    Some((frequency, fundamental(strip, frequency)))
}

/// The phase velocity (m/s) of the free waves of a beam (EI, m) on a spring k_w (N/m²) at `frequency` (Hz):
/// c = ω/k with EI k⁴ = mω² − k_w, +∞ below the cut-on √(k_w/m) (no free wave there).
pub fn beam_phase_velocity(ei: f64, m: f64, spring: f64, frequency: f64) -> f64 {
    let omega = TAU * frequency;
    let excess = m * omega * omega - spring;
    if excess <= 0.0 { f64::INFINITY } else { omega / (excess / ei).powf(0.25) }
}

/// k_eq along the load's line at 0, ½, 1 and 1½ times `reference` (m/s).
fn stiffness_curves(strip: &StripGround, reference: f64, runner: &Runner<'_>) -> Result<Vec<StiffnessPoint>> {
    let (low, high) = WAVENUMBERS;
    let grid: Vec<(f64, f64)> = [0.0, 0.5, 1.0, 1.5]
        .iter()
        .flat_map(|&share| {
            (0..STIFFNESS_POINTS).map(move |i| {
                let k = low * (high / low).powf(i as f64 / (STIFFNESS_POINTS - 1) as f64);
                (share * reference, k)
            })
        })
        .collect();
    runner.map(&grid, |&(speed, wavenumber)| {
        let k_eq = strip.equivalent_stiffness(wavenumber, wavenumber * speed)?;
        Ok(StiffnessPoint {
            speed,
            wavenumber,
            frequency: wavenumber * speed / TAU,
            stiffness_real: k_eq.re,
            stiffness_imaginary: k_eq.im,
        })
    })
}

/// The profile in words: "2 layers (1.1 m C_s 72 m/s, 3 m C_s 41 m/s) on a half-space of C_s 100 m/s".
pub(crate) fn describe(strip: &StripGround) -> String {
    let layers: Vec<String> = strip
        .profile
        .layers
        .iter()
        .map(|l| format!("{} m C_s {} m/s", l.thickness, l.material.shear_wave_speed))
        .collect();
    let below = format!("a half-space of C_s {} m/s", strip.profile.half_space.shear_wave_speed);
    match layers.len() {
        0 => below,
        n => format!("{n} layer{} ({}) on {below}", if n == 1 { "" } else { "s" }, layers.join(", ")),
    }
}
