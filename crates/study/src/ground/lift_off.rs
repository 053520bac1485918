//! The two-beam track whose ballast cannot pull (`[embankment] interface = "tensionless"`; docs/theory.md §19,
//! "Lift-off on the ground"): at each speed the track's four moving-frame spectra, once, and the sleepers' lift-off
//! solved on the wave's window ([`stationary::solve_with_lift_off`]) — the rail's wave with what the lifted stretches
//! change, where the sleepers leave the ballast and how far.

use crate::ground::speeds::refined_extremes;
use crate::ground::wave_point::{
    BallastAlong, GroundWave, GroundWavePoint, LiftOffPoint, WAVE_STEP, WaveWindow, summary,
};
use analytic::ground::{GroundedBeam, StripGround, TrackOnEmbankment};
use fem_beam::{Extreme, Train};
use scenario::error::{Result, StudyError};

/// The rail's wave with lift-off: `grounded` the rail on its pads, sleepers and ballast over the embankment on the
/// strip, the ballast pressed `preload` (m, ≤ 0) by the track's weight; `stop` ends the Newton iteration.
pub(crate) struct LiftOff<'a> {
    pub(crate) grounded: GroundedBeam<'a, TrackOnEmbankment<'a, StripGround>>,
    pub(crate) preload: f64,
    pub(crate) stop: Option<&'a std::sync::atomic::AtomicBool>,
}

impl LiftOff<'_> {
    /// The wave at `speed` on the window's points (`positions`, spaced [`WAVE_STEP`]), from the linear wave; a wave
    /// whose iteration did not converge is an error naming the speed.
    pub(crate) fn wave(
        &self,
        train: &Train,
        speed: f64,
        positions: &[f64],
        window: WaveWindow,
    ) -> Result<(GroundWave, GroundWavePoint)> {
        let spectra = self.grounded.interface_spectra(speed, WAVE_STEP).map_err(StudyError::from)?;
        let sleepers = self.grounded.support.sleepers;
        let problem = stationary::GroundContactProblem {
            spectra: &spectra,
            axles: &train.axles,
            speed,
            window: stationary::GroundWindow { first: positions[0], step: WAVE_STEP, count: positions.len() },
            ballast_stiffness: sleepers.ballast.stiffness / sleepers.spacing,
            preload: self.preload,
        };
        let control = stationary::Control::new(self.stop);
        let mut guess = stationary::ContactGuess::default();
        let solved = stationary::solve_with_lift_off(&problem, &mut guess, &control).map_err(StudyError::from)?;
        if let stationary::Convergence::NotConverged { iterations, residual } = solved.convergence {
            return Err(StudyError::Beam(fem_beam::FemError::NotConverged {
                what: format!("the wave with lift-off at {speed} m/s ({iterations} Newton iterations)"),
                reached: residual,
                asked: stationary::newton::TOLERANCE,
            }));
        }
        let gap = solved.relative.iter().map(|d| (self.preload + d).max(0.0)).collect();
        let ballast = Some(BallastAlong { gap, ballast_force: solved.ballast_force.clone() });
        let wave = GroundWave { speed, s: positions.to_vec(), deflection: solved.deflection.clone(), ballast };
        let mut point = summary(&spectra.rail, train, &wave, window, &|s| solved.carried(s));
        let relative: Vec<(f64, f64)> = solved.s.iter().copied().zip(solved.relative.iter().copied()).collect();
        let at = |s: f64| spectra.relative.deflection_under(&train.axles, s) + solved.carried_relative(s);
        let highest = refined_extremes(&relative, &at).max_upward;
        let gap = self.preload + highest.value;
        let starts = solved.lifted.iter().enumerate().filter(|&(i, &l)| l && (i == 0 || !solved.lifted[i - 1]));
        point.lift_off = Some(LiftOffPoint {
            newton_iterations: solved.convergence.iterations(),
            lift_off_zones: starts.count(),
            lifted_length: solved.lifted_length(),
            largest_gap: match (gap > 0.0, highest.position) {
                (true, Some(s)) => Extreme::in_frame(gap, s),
                _ => Extreme::default(),
            },
            preload: self.preload,
        });
        Ok((wave, point))
    }
}
