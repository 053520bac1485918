//! A measured record set beside a computed wave, as numbers (`measured` computes it; the wave study holds it).

use serde::Serialize;

/// The measured record against the computed wave.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// The record's file.
    pub record: String,
    /// d: +1 where the record's x runs the way s does (forward along the train), −1 where it runs backward.
    pub direction: f64,
    /// c (m): s = d·x + c.
    pub shift: f64,
    /// √(mean (W_computed − W_measured)²) over the record (m).
    pub rms_misfit: f64,
    /// √(mean W_measured²) (m): the scale the misfit is read against.
    pub rms_measured: f64,
    /// The record's largest downward and upward deflections (m, magnitudes).
    pub measured_max_downward: f64,
    /// See `measured_max_downward`.
    pub measured_max_upward: f64,
    /// The computed wave's at the record's points (m, magnitudes): sampled as the record is.
    pub computed_max_downward: f64,
    /// See `computed_max_downward`.
    pub computed_max_upward: f64,
}
