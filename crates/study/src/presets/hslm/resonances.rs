//! The resonance speeds of a span under a train of coaches of length D: v = f_j·D/i (EN 1991-2 §6.4.4), from the
//! span's lowest natural frequencies f_j — where the HSLM study adds runs, because its peaks are there.

use fem_beam::BeamModel;

/// The natural frequencies whose resonance speeds are listed (f₁ … f₃).
const MODES: usize = 3;
/// Harmonics listed per frequency, at most.
const MAX_ORDER: usize = 20;

/// A resonance speed v = f_j·D/i.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Resonance {
    /// j (1 = the lowest natural frequency).
    pub mode: usize,
    /// i.
    pub order: usize,
    /// f_j (Hz).
    pub frequency: f64,
    /// v (m/s).
    pub speed: f64,
}

/// The resonance speeds of coach length `d` (m) for `frequencies` (Hz, ascending) inside [from, to] (m/s). A
/// frequency within 1 % of a lower one gives the same speeds and is left out (modes that crowd, as the lowest ones
/// of a beam on a foundation do; the study lists resonances of spans only, whose frequencies grow as n²).
pub(in crate::presets) fn resonances(frequencies: &[f64], d: f64, (from, to): (f64, f64)) -> Vec<Resonance> {
    let mut out = Vec::new();
    for (j, &frequency) in frequencies.iter().enumerate() {
        if frequencies[..j].iter().any(|&f| (frequency - f).abs() <= 0.01 * f) {
            continue;
        }
        for order in 1..=MAX_ORDER {
            let speed = frequency * d / order as f64;
            if (from..=to).contains(&speed) {
                out.push(Resonance { mode: j + 1, order, frequency, speed });
            }
        }
    }
    out
}

/// f₁ … f₃ (Hz) of `model`, None where its dense eigenproblem is refused (over 2000 free DOFs: a span of more than
/// 1000 elements, then without resonance speeds).
pub(in crate::presets) fn natural_frequencies(model: &BeamModel) -> Option<Vec<f64>> {
    let count = MODES.min(model.dofs().free_len());
    let omegas = model.natural_frequencies(count).ok()?;
    Some(omegas.into_iter().map(|w| w / std::f64::consts::TAU).collect())
}
