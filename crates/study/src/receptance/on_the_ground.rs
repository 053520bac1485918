//! The receptance of the track on a `[ground]` (`frictrack receptance` on a ground scenario, docs/theory.md §19): the
//! infinite beam's point receptance α(ω) on the strip's k_eq(k, ω) — the composite beam's, or the rail's on pads,
//! sleepers and ballast over the embankment beam — one integral over k per frequency, its resonances refined as the
//! finite track's are.

use crate::ground::support::{Support, track_in_words};
use crate::receptance::response::sampled;
use crate::receptance::{ReceptanceRequest, ReceptanceStudy};
use analytic::ground::GroundedBeam;
use num_complex::Complex64;
use runner::Runner;
use scenario::Scenario;
use scenario::error::{Result, invalid};
use std::f64::consts::TAU;

impl ReceptanceStudy {
    /// The point receptance of `scenario`'s composite beam (or rail, on the two-beam track) on its `[ground]` at
    /// `request`'s frequencies, on `runner`'s threads. The beam is infinite: the response is read under the force (`at` and `excite` are
    /// refused where they differ — a transfer receptance on the ground is not built).
    pub fn on_the_ground(scenario: &Scenario, request: &ReceptanceRequest, runner: &Runner<'_>) -> Result<Self> {
        let (beam, strip, track) = scenario.ground_track()?;
        crate::receptance::response::check_frequencies(&request.frequencies)?;
        if request.at != request.excite {
            return Err(invalid(
                "at",
                request.at,
                "on a [ground] the receptance is the point receptance of the infinite beam: give no place, or the \
                 same for at and excite",
            ));
        }
        let support = Support::of(&track, &strip);
        let grounded = GroundedBeam::new(&beam, support.line())?;
        let speeds = strip.profile.wave_speeds();
        let alpha = |f: f64| -> Result<Complex64> { Ok(grounded.point_receptance(TAU * f, &speeds)?) };
        runner.announce(runner::cost::Estimate::ground_receptance(
            request.frequencies.len(),
            strip.profile.layers.len(),
            runner.threads(),
        ));
        let (points, resonances) = sampled(&request.frequencies, runner, &alpha)?;
        let (rail, on) = track_in_words(&track, strip.width);
        Ok(Self {
            title: scenario.title.clone(),
            excite: request.excite,
            at: request.at,
            kind: "point",
            rail: rail.into(),
            loss_factors: [beam.loss_factor, 0.0],
            support: on,
            place: crate::receptance::text::ON_THE_INFINITE_BEAM.into(),
            points,
            resonances,
            warnings: Vec::new(),
        })
    }
}
