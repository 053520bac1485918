//! The track's receptance and mobility over frequency (docs/theory.md §17): the response at each frequency
//! ([`response`]), its resonances and the doubts about them ([`peaks`]), its report ([`text`]); the composite beam's
//! on a layered ground ([`on_the_ground`], §19).

pub mod on_the_ground;
pub mod peaks;
pub mod response;
pub mod text;

pub use response::{MAX_FREQUENCIES, ReceptancePoint, ReceptanceRequest, ReceptanceStudy, frequency_range};
