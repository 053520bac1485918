//! `[output] deck_track`: the track on a bridge deck, which sets the deck-acceleration limit of EN 1990 Annex A2.

use crate::error::invalid;
use serde::{Deserialize, Serialize};

/// The track form on a bridge deck, as EN 1990 A2.4.4.2.1(4)P limits the deck's peak acceleration by it (to avoid
/// ballast instability, resp. loss of wheel–rail contact), in the frequency range up to max(30 Hz, 1.5 f₁, f₃).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DeckTrack {
    /// Ballasted track: γ_bt = 3.5 m/s².
    #[default]
    Ballasted,
    /// Direct-fastened deck (track and structure designed for high-speed traffic): γ_df = 5 m/s².
    DirectFastening,
}

impl DeckTrack {
    /// Both, in the order of their limits.
    pub const ALL: [DeckTrack; 2] = [DeckTrack::Ballasted, DeckTrack::DirectFastening];

    /// The peak deck acceleration EN 1990 A2.4.4.2.1(4)P allows (m/s²).
    pub fn acceleration_limit(self) -> f64 {
        match self {
            DeckTrack::Ballasted => 3.5,
            DeckTrack::DirectFastening => 5.0,
        }
    }

    /// The name in a scenario file and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            DeckTrack::Ballasted => "ballasted",
            DeckTrack::DirectFastening => "direct-fastening",
        }
    }

    /// "ballasted deck", "direct-fastened deck".
    pub fn describe(self) -> &'static str {
        match self {
            DeckTrack::Ballasted => "ballasted deck",
            DeckTrack::DirectFastening => "direct-fastened deck",
        }
    }

    pub(super) fn is_default(&self) -> bool {
        *self == DeckTrack::default()
    }
}

impl std::str::FromStr for DeckTrack {
    type Err = crate::StudyError;

    /// "ballasted" or "direct-fastening"; anything else is refused, naming both.
    fn from_str(text: &str) -> std::result::Result<Self, Self::Err> {
        Self::ALL.into_iter().find(|d| d.name() == text).ok_or_else(|| {
            invalid("output.deck_track", text, "must be \"ballasted\" (3.5 m/s²) or \"direct-fastening\" (5 m/s²)")
        })
    }
}
