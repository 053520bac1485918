//! The discretisation error of a wave's peaks (docs/theory.md §14): the same problem solved again on elements half as
//! long, started from the wave interpolated onto them (its Hermite cubics at the new mid-nodes), so that the second
//! solve is a few Newton steps. Richardson's estimate of the error of a peak P_h that converges at order p is
//! |P_h − P_{h/2}|·2ᵖ/(2ᵖ − 1); [`ERROR_FACTOR`] takes p = 1, an upper estimate for the peaks' orders measured here
//! (moment 2, deflection 4 on a linear soil; lift-off and slip edges inside elements lower them towards 2).

use crate::control::Control;
use crate::error::Result;
use crate::problem::{Domain, StationaryProblem};
use crate::solve::solve_within;
use crate::status::ContactGuess;
use crate::wave::StationaryWave;

/// 2ᵖ/(2ᵖ − 1) for p = 1: the factor on |P_h − P_{h/2}| that estimates the error of P_h.
pub const ERROR_FACTOR: f64 = 2.0;

/// The wave of `problem` on the domain `wave` ended on (its length grown, if it grew), in elements half as long,
/// started from `wave`, within `control` ([`crate::solve_within`]).
pub fn solve_halved(
    problem: &StationaryProblem,
    wave: &StationaryWave,
    control: &Control<'_>,
) -> Result<StationaryWave> {
    let l = wave.element_length();
    // The same nodes and one between each two: a quarter element short of each end, so that the element counts,
    // rounded up (Domain::elements), are exactly twice the wave's whatever the round-off of its s.
    let (behind, ahead) = (-wave.s[0] - 0.25 * l, wave.s[wave.s.len() - 1] - 0.25 * l);
    let halved = StationaryProblem { domain: Domain { behind, ahead, element_length: 0.5 * l }, ..*problem };
    let level = wave.settlement;
    let n = wave.s.len();
    let mut w = Vec::with_capacity(4 * n - 2);
    // The element's W and rotation θ at ξ = ½ (its shape functions there: for Euler–Bernoulli θ = W′).
    let element = fem_beam::element::Element::of(&problem.beam, l);
    let (middle, middle_rotation) = (element.shape(0.5), element.rotation(0.5));
    for i in 0..n {
        let (w0, t0) = (wave.deflection[i] + level, wave.rotation[i]);
        w.extend([w0, t0]);
        if i + 1 < n {
            let q = [w0, t0, wave.deflection[i + 1] + level, wave.rotation[i + 1]];
            let at = |n: &[f64; 4]| n.iter().zip(&q).map(|(n, q)| n * q).sum::<f64>();
            w.extend([at(&middle), at(&middle_rotation)]);
        }
    }
    solve_within(&halved, &mut ContactGuess::started_at(&halved, w)?, control)
}
