//! The steady wave of a train (or one load) on the ground (`frictrack stationary` on a `[ground]`; docs/theory.md
//! §19): at each speed the moving-load spectrum of the composite beam (or of the rail on sleepers over the
//! embankment), once, and the wave along the train's frame as the superposition of its axles' shifted single-load
//! waves, W(s) = Σ_j P_j W₁(s + d_j) — under and behind the train,
//! its peaks (refined by golden section) and the upward wake behind it above the ground's wave speeds. Deflections in
//! m (upward positive, peaks as magnitudes), positions s = x − x_head in m (positive ahead of the first axle). With
//! ballast friction (under the composite beam, or between the two-beam track's sleepers and embankment) each speed's
//! wave is a Newton iteration from the last speed's (`friction`); with a tensionless ballast on the
//! two-beam track the sleepers' lift-off is solved at each speed ([`crate::ground::lift_off`]).

use crate::ground::comparison::Comparison;
use crate::ground::friction::{Friction, FrictionOn};
use crate::ground::lift_off::LiftOff;
use crate::ground::shared_spectra::SiteSpectra;
use crate::ground::support::Support;
pub use crate::ground::wave_point::{
    BallastAlong, FrictionPoint, GroundWave, GroundWavePoint, LiftOffPoint, WAVE_STEP, WaveWindow,
};
use crate::ground::wave_point::{summary, wave_of};
use analytic::ground::{GroundedBeam, StripGround, TrackOnEmbankment};
use fem_beam::Train;
use rayon::prelude::*;
use scenario::Scenario;
use scenario::error::{Result, StudyError, invalid};
use scenario::ground::{GroundTrack, Interface};

/// The steady waves of the scenario's axles on its ground over speeds.
#[derive(Debug, Clone)]
pub struct GroundWaveStudy {
    /// The scenario's title.
    pub title: String,
    /// The beam's EI (N·m²) and ρA (kg/m): the composite beam's, or the rail's.
    pub beam: (f64, f64),
    /// The strip of ground under it.
    pub strip: StripGround,
    /// The composite beam, or one rail on sleepers over an embankment.
    pub track: GroundTrack,
    /// The axles as the beam carries them.
    pub train: Train,
    /// One point per speed.
    pub points: Vec<GroundWavePoint>,
    /// The waves, one per speed.
    pub waves: Vec<GroundWave>,
    /// A measured record beside the wave (one speed only), where one was given.
    pub comparison: Option<Comparison>,
    /// The scenario's ground outside what a site is ([`Scenario::ground_warnings`]), as the command line prints them.
    pub input_warnings: Vec<String>,
    /// The ballast's friction f_u (N/m), where it has any: under the composite beam, or between the sleepers and the
    /// embankment.
    pub friction: Option<f64>,
}

impl GroundWaveStudy {
    /// The waves at `speeds` (m/s, each ≥ 0) of the scenario's axles ([`Scenario::axles_on_the_ground`]) on
    /// `window`; stops with [`StudyError::Interrupted`] before the next speed once `stop` is raised, telling
    /// `progress` the speeds done. A speed costs a spectrum (0.1–0.5 s on a soft site, 2 threads) and the wave's
    /// points (a train's read from one load's wave every 5 cm: 0.5 s for the X2000 at Ledsgård in all).
    pub fn of(
        scenario: &Scenario,
        speeds: &[f64],
        window: WaveWindow,
        stop: Option<&std::sync::atomic::AtomicBool>,
        progress: &dyn Fn(usize),
    ) -> Result<Self> {
        Self::sharing(scenario, speeds, window, (stop, progress), &SiteSpectra::new(scenario))
    }

    /// As [`GroundWaveStudy::of`], taking the spectra at each speed from `spectra` (sampling and keeping those it
    /// lacks) where `scenario` is its site but for the friction, so that curves of one site at several frictions
    /// sample each speed once.
    pub fn sharing(
        scenario: &Scenario,
        speeds: &[f64],
        window: WaveWindow,
        (stop, progress): (Option<&std::sync::atomic::AtomicBool>, &dyn Fn(usize)),
        spectra: &SiteSpectra,
    ) -> Result<Self> {
        if !spectra.fits(scenario) {
            return Self::sharing(scenario, speeds, window, (stop, progress), &SiteSpectra::new(scenario));
        }
        let (beam, strip, track) = scenario.ground_track()?;
        scenario.check_speeds_on_the_ground("speed", speeds)?;
        let train = scenario.axles_on_the_ground()?;
        let positions = window.positions(train.length())?;
        let support = Support::of(&track, &strip);
        let grounded = GroundedBeam::new(&beam, support.line()).map_err(StudyError::from)?;
        let friction = friction_on(scenario, &track)?;
        let (mut points, mut waves) = (Vec::with_capacity(speeds.len()), Vec::with_capacity(speeds.len()));
        let interrupted = || stop.is_some_and(|s| s.load(std::sync::atomic::Ordering::Relaxed));
        let on_embankment = on_embankment(&track, &strip);
        let lift_off = match (&track, &on_embankment) {
            (GroundTrack::RailOnEmbankment { interface: Interface::Tensionless { preload }, .. }, Some(on)) => {
                let grounded = GroundedBeam::new(&beam, on).map_err(StudyError::from)?;
                Some(LiftOff { grounded, preload: *preload, stop })
            }
            _ => None,
        };
        match friction {
            // Linear, or lifting from the linear wave: the speeds are independent, so as many run at once as there
            // are threads (a spectrum's last rounds of sampling leave threads idle that a second speed takes up).
            None => {
                let at = |speed: f64| -> Result<(GroundWave, GroundWavePoint)> {
                    if let Some(lift_off) = &lift_off {
                        return lift_off.wave(&train, speed, &positions, window);
                    }
                    let spectrum = spectra.line(speed, || grounded.spectrum(speed).map_err(StudyError::from))?;
                    let wave = wave_of(&spectrum, &train, speed, &positions);
                    let point = summary(&spectrum, &train, &wave, window, &|_| 0.0);
                    Ok((wave, point))
                };
                for group in speeds.chunks(rayon::current_num_threads().max(1)) {
                    if interrupted() {
                        return Err(StudyError::Interrupted);
                    }
                    let done: Vec<Result<(GroundWave, GroundWavePoint)>> = group.par_iter().map(|&v| at(v)).collect();
                    for result in done {
                        let (wave, point) = result?;
                        points.push(point);
                        waves.push(wave);
                        progress(points.len());
                    }
                }
            }
            // With friction each speed starts from the last one's wave.
            Some(force) => {
                let mut guess = stationary::ContactGuess::default();
                let track = match &on_embankment {
                    Some(on) => FrictionOn::RailOnEmbankment(GroundedBeam::new(&beam, on).map_err(StudyError::from)?),
                    None => FrictionOn::Composite(&grounded),
                };
                let on = Friction { track, beam: &beam, force, stop, spectra };
                for &speed in speeds {
                    if interrupted() {
                        return Err(StudyError::Interrupted);
                    }
                    let (wave, point) = on.wave(&train, speed, &positions, window, &mut guess)?;
                    points.push(point);
                    waves.push(wave);
                    progress(points.len());
                }
            }
        }
        let beam = (beam.bending_stiffness(), beam.mass_per_length());
        let (title, strip, track, comparison) = (scenario.title.clone(), strip.clone(), track.clone(), None);
        let input_warnings = scenario.ground_warnings().iter().map(ToString::to_string).collect();
        Ok(Self { title, beam, strip, track, train, points, waves, comparison, friction, input_warnings })
    }
}

impl GroundWaveStudy {
    /// The scenario's ground outside what a site is, then the speeds whose largest downward or upward deflection lies
    /// at an end of the window (within a point's spacing
    /// of it), one sentence each: the wave there is still growing towards the end, so the window's extreme is not the
    /// wave's — widen the window on that side (`domain`).
    pub fn warnings(&self) -> Vec<String> {
        let mut out = self.input_warnings.clone();
        for (point, wave) in self.points.iter().zip(&self.waves) {
            let (Some(&first), Some(&last)) = (wave.s.first(), wave.s.last()) else { continue };
            for (what, extreme) in
                [("downward", &point.deflection.max_downward), ("upward", &point.deflection.max_upward)]
            {
                let Some(s) = extreme.position.filter(|_| extreme.value > 0.0) else { continue };
                let side = if s - first < WAVE_STEP {
                    "behind the train (the domain's first number)"
                } else if last - s < WAVE_STEP {
                    "ahead of the train (the domain's second number)"
                } else {
                    continue;
                };
                out.push(format!(
                    "at {} m/s the largest {what} deflection, {:.3} mm, lies at the window's end s = {s:.2} m: the \
                     wave still grows towards it, so the wave's own extreme lies beyond; widen the window {side}",
                    scenario::number::number(point.speed),
                    extreme.value * 1e3
                ));
            }
        }
        out
    }
}

/// What [`GroundWaveStudy::of`] costs `scenario` at `speeds` speeds on `threads` threads: a spectrum a speed, and with
/// ballast friction the Newton iteration on top ([`runner::cost::Estimate::ground_waves`]); a speed with the sleepers'
/// lift-off (four spectra and the pair kernels, 2.1× a bonded one at Ledsgård) counts as one with friction.
pub fn cost(scenario: &Scenario, speeds: usize, threads: usize) -> runner::cost::Estimate {
    let friction = scenario.friction.distributed.as_ref().is_some_and(|d| d.force_per_length > 0.0);
    let lifting =
        matches!(&scenario.embankment, Some(e) if e.interface == scenario::embankment::InterfaceKind::Tensionless);
    let (linear, nonlinear) = if friction || lifting { (0, speeds) } else { (speeds, 0) };
    let layers = scenario.ground.as_ref().map_or(0, |g| g.layers.len());
    runner::cost::Estimate::ground_waves(linear, nonlinear, layers, threads)
}

/// The ballast's f_u (N/m) of `scenario` on `track`, if it has any: under the composite beam, or between the
/// sleepers and the embankment of the two-beam track — there not together with a tensionless ballast (refused by
/// key: the two laws at one interface are not built).
pub fn friction_on(scenario: &Scenario, track: &GroundTrack) -> Result<Option<f64>> {
    let Some(distributed) = &scenario.friction.distributed else { return Ok(None) };
    let force = distributed.friction()?.force_per_length;
    if force > 0.0 && matches!(track, GroundTrack::RailOnEmbankment { interface: Interface::Tensionless { .. }, .. }) {
        return Err(invalid(
            "embankment.interface",
            "tensionless",
            "is solved without ballast friction (friction.distributed): friction and lift-off at one interface are \
             not built yet — leave one of them out",
        ));
    }
    Ok((force > 0.0).then_some(force))
}

/// The two-beam track's rail on its sleepers over the embankment on `strip`; None under the composite beam.
fn on_embankment<'a>(track: &'a GroundTrack, strip: &'a StripGround) -> Option<TrackOnEmbankment<'a, StripGround>> {
    match track {
        GroundTrack::RailOnEmbankment { sleepers, embankment, .. } => {
            Some(TrackOnEmbankment { sleepers, embankment: *embankment, ground: strip })
        }
        GroundTrack::Composite => None,
    }
}
