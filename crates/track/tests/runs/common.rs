//! Shared set-ups.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{BeamModel, Mesh};

/// The reference beam with `elements` elements on `length` m (pinned ends).
pub fn beam(length: f64, elements: usize) -> BeamModel {
    let case = uic60_on_soft_soil();
    BeamModel::new(case.beam, case.foundation, Mesh::new(length, elements).unwrap(), case.supports).unwrap()
}

/// The reference model of docs/theory.md §2.
pub fn reference() -> BeamModel {
    uic60_on_soft_soil().model().unwrap()
}

/// max |a − b| / max |b| over two vectors.
pub fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}
