//! What the beam of a scenario on the `[ground]` stands on, as one line support: the strip itself under the composite
//! beam, or — the two-beam track — the rail's pads, sleepers and ballast over the embankment beam on the strip
//! (`TrackOnEmbankment`, docs/theory.md §19).

use analytic::ground::{LineSupport, StripGround, TrackOnEmbankment};
use scenario::ground::GroundTrack;

/// The line support `track` makes of `strip`.
pub enum Support<'a> {
    /// The strip under the composite beam.
    Strip(&'a StripGround),
    /// The rail's support on the two-beam track.
    OnEmbankment(TrackOnEmbankment<'a, StripGround>),
}

impl<'a> Support<'a> {
    /// What `track` stands on over `strip`.
    pub fn of(track: &'a GroundTrack, strip: &'a StripGround) -> Self {
        match track {
            GroundTrack::Composite => Support::Strip(strip),
            GroundTrack::RailOnEmbankment { sleepers, embankment, .. } => {
                Support::OnEmbankment(TrackOnEmbankment { sleepers, embankment: *embankment, ground: strip })
            }
        }
    }

    /// As a line support.
    pub fn line(&self) -> &dyn LineSupport {
        match self {
            Support::Strip(strip) => *strip,
            Support::OnEmbankment(track) => track,
        }
    }
}

/// The beam and what carries it, in words (a receptance's labels).
pub fn track_in_words(track: &GroundTrack, width: f64) -> (&'static str, String) {
    match track {
        GroundTrack::Composite => {
            ("Euler–Bernoulli composite beam", format!("a {width} m strip of a layered ground (theory §19)"))
        }
        GroundTrack::RailOnEmbankment { sleepers, embankment, .. } => (
            "Euler–Bernoulli rail",
            format!(
                "pads, {:.0} kg sleepers every {} m and ballast over an embankment beam of EI = {:.3e} N·m², {:.0} \
                 kg/m on a {width} m strip of a layered ground (theory §19)",
                sleepers.mass, sleepers.spacing, embankment.bending_stiffness, embankment.mass_per_length
            ),
        ),
    }
}
