//! Ballast friction on the ground (docs/theory.md §19, "Ballast friction on the ground"): each speed's wave a Newton
//! iteration from the last speed's ([`stationary::solve_on_ground`]) — under the composite beam, on its deflection
//! against the ground beneath; on the two-beam track, between the sleepers and the embankment.

use crate::ground::shared_spectra::SiteSpectra;
use crate::ground::wave_point::{FrictionPoint, GroundWave, GroundWavePoint, WAVE_STEP, WaveWindow, summary};
use analytic::ground::{GroundedBeam, LineSupport, MovingSpectrum, StripGround, TrackOnEmbankment};
use fem_beam::{Beam, Foundation, Train};
use scenario::error::{Result, StudyError};
use stationary::{FrictionTrack, GroundFrictionWave};

/// The track the friction acts in.
pub(crate) enum FrictionOn<'a> {
    /// The composite beam on its line support.
    Composite(&'a GroundedBeam<'a, dyn LineSupport + 'a>),
    /// One rail on its pads, sleepers and ballast over the embankment on the strip.
    RailOnEmbankment(GroundedBeam<'a, TrackOnEmbankment<'a, StripGround>>),
}

/// The wave with ballast friction of strength `force` (N/m) on `track`, whose beam is `beam` (the composite beam or
/// the rail); `stop` ends the Newton iteration.
pub(crate) struct Friction<'a> {
    pub(crate) track: FrictionOn<'a>,
    pub(crate) beam: &'a Beam,
    pub(crate) force: f64,
    pub(crate) stop: Option<&'a std::sync::atomic::AtomicBool>,
    /// The site's spectra, shared with its other curves.
    pub(crate) spectra: &'a SiteSpectra,
}

impl Friction<'_> {
    /// The wave at `speed` on the window's points (`positions`, spaced [`WAVE_STEP`]), from `guess` (the last
    /// speed's) and leaving this one there; a wave whose iteration did not converge is an error naming the speed.
    pub(crate) fn wave(
        &self,
        train: &Train,
        speed: f64,
        positions: &[f64],
        window: WaveWindow,
        guess: &mut stationary::ContactGuess,
    ) -> Result<(GroundWave, GroundWavePoint)> {
        match &self.track {
            FrictionOn::Composite(grounded) => {
                let spectrum = self.spectra.line(speed, || grounded.spectrum(speed).map_err(StudyError::from))?;
                let local = grounded.local_fit(self.beam, &spectrum, speed).map_err(StudyError::from)?;
                let track = FrictionTrack::Composite(&spectrum);
                self.solved(track, &spectrum, local, (train, speed, positions, window), guess)
            }
            FrictionOn::RailOnEmbankment(grounded) => {
                let spectra = self
                    .spectra
                    .interface(speed, || grounded.interface_spectra(speed, WAVE_STEP).map_err(StudyError::from))?;
                let local = grounded.support.local_across_ballast(self.beam, WAVE_STEP);
                let track = FrictionTrack::RailOnEmbankment(&spectra);
                self.solved(track, &spectra.rail, local, (train, speed, positions, window), guess)
            }
        }
    }

    /// The wave on `track` (the rail's own spectrum `rail`) with the preconditioner's `local` beam and foundation,
    /// and its point.
    fn solved(
        &self,
        track: FrictionTrack<'_>,
        rail: &MovingSpectrum,
        local: (Beam, Foundation),
        (train, speed, positions, window): (&Train, f64, &[f64], WaveWindow),
        guess: &mut stationary::ContactGuess,
    ) -> Result<(GroundWave, GroundWavePoint)> {
        let problem = stationary::GroundFrictionProblem {
            track,
            axles: &train.axles,
            speed,
            window: stationary::GroundWindow { first: positions[0], step: WAVE_STEP, count: positions.len() },
            friction_force: self.force,
            local,
        };
        let control = stationary::Control::new(self.stop);
        let solved = stationary::solve_on_ground(&problem, guess, &control).map_err(StudyError::from)?;
        if let stationary::Convergence::NotConverged { iterations, residual } = solved.convergence {
            return Err(StudyError::Beam(fem_beam::FemError::NotConverged {
                what: format!("the wave with ballast friction at {speed} m/s ({iterations} Newton iterations)"),
                reached: residual,
                asked: stationary::newton::ROUND_OFF,
            }));
        }
        let wave = GroundWave { speed, s: positions.to_vec(), deflection: solved.deflection.clone(), ballast: None };
        let mut point = summary(rail, train, &wave, window, &|s| solved.carried(s));
        point.friction = Some(friction_point(&solved, self.force, speed));
        Ok((wave, point))
    }
}

/// What the friction did at one speed.
fn friction_point(solved: &GroundFrictionWave, force: f64, speed: f64) -> FrictionPoint {
    let slipping_length = solved.slipping.iter().zip(&solved.weights).filter(|(s, _)| **s).map(|(_, h)| h).sum();
    FrictionPoint {
        newton_iterations: solved.convergence.iterations(),
        krylov_iterations: solved.krylov_iterations,
        friction_power: solved.dissipated_power(force, speed),
        slipping_length,
        rear_force_ratio: solved.end_forces(force).0,
    }
}
