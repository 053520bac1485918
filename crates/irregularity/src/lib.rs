//! # irregularity: rail irregularities r(x) (docs/theory.md §11)
//!
//! The vertical profile a wheel rides over, upward positive, in metres: deterministic shapes (harmonic corrugation,
//! ramp, dipped joint), a measured table, random profiles drawn from the German (ORE B176) and FRA track-quality
//! spectra by spectral representation, sums of them ([`Profile`]), and wheel flats, which belong to a wheel
//! ([`WheelFlat`]). Each gives the height and the slope r′ (the drift of a moving wheel–rail contact, MODEL §9).
//! Random profiles are identical on every machine for a seed: integer random numbers ([`rng`]) and sine and cosine
//! computed here ([`trig`]), not by the platform's libm. [`periodogram`] estimates a sample's PSD against its target.
//!
//! The bottom of the stack: no dependency on the beam or the engine.

pub mod error;
pub mod periodogram;
pub mod profile;
pub mod random;
pub mod rng;
pub mod spectrum;
pub mod trig;

pub use error::{IrregularityError, Result};
pub use profile::{Profile, WheelFlat, WheelTrack};
pub use random::{Harmonic, RandomProfile, RandomSettings};
pub use spectrum::Spectrum;
