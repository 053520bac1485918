//! The far field of the moving-frame beam equation (docs/theory.md §14): where the track is linear and at rest, the
//! wave W(s) = W_far + Σ a_i e^{r_i s} with r the roots of the characteristic quartic
//!
//! ```text
//! EI r⁴ + ρA v² r² − c_f v r + k = 0,
//! ```
//!
//! and only the decaying ones may appear: Re r < 0 ahead of the load (s → +∞), Re r > 0 behind it. With the two kept
//! roots r₁, r₂ (σ = r₁ + r₂, π = r₁r₂, real: a conjugate pair or two real roots; the infinite beam's, from
//! `fem_beam::reference`) every such W satisfies at the end
//!
//! ```text
//! W″ = −π (W − W_far) + σ W′,     W‴ = −πσ (W − W_far) + (σ² − π) W′,
//! ```
//!
//! the exact transparent (non-reflecting) condition of a finite domain. Undamped above the critical speed the
//! roots reach the imaginary axis: no root decays, and no end condition selects the outgoing wave — refused.

use crate::error::{Result, StationaryError};
use fem_beam::reference::InfiniteBeam;
use fem_beam::{Beam, FemError, Foundation};
use num_complex::Complex64;

/// W″ = second·(W − W_far, W′) and W‴ = third·(W − W_far, W′) at one end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndRelation {
    /// (−π, σ).
    pub second: [f64; 2],
    /// (−πσ, σ² − π).
    pub third: [f64; 2],
    /// The slowest decay rate min |Re r| of the kept roots (1/m).
    pub decay: f64,
    /// The kept roots r₁, r₂ (1/m).
    pub roots: [Complex64; 2],
}

impl EndRelation {
    /// The amplitudes (a₁, a₂) of the decaying modes that continue the wave past this end from its end values
    /// U = W − W_far and W′: U(t) = a₁e^{r₁t} + a₂e^{r₂t}, t the distance past the end (a₁ + a₂ = U,
    /// a₁r₁ + a₂r₂ = W′). None for a double root.
    fn tail_modes(&self, u: f64, slope: f64) -> Option<[Complex64; 2]> {
        let [r1, r2] = self.roots;
        let gap = r2 - r1;
        if gap.norm() <= 1e-12 * r1.norm().max(r2.norm()) {
            return None;
        }
        let a2 = (Complex64::new(slope, 0.0) - r1 * u) / gap;
        Some([Complex64::new(u, 0.0) - a2, a2])
    }

    /// ∫ W′² ds over the far field beyond this end (m), for the end values U = W − W_far and W′ (the wave continued
    /// by its decaying modes, `Self::tail_modes`): Σ_ij a_i a_j r_i r_j/|r_i + r_j| taken with the sign that makes
    /// each term the integral of a decaying exponential. None for a double root.
    pub fn tail_slope_square(&self, u: f64, slope: f64) -> Option<f64> {
        let a = self.tail_modes(u, slope)?;
        let mut sum = Complex64::new(0.0, 0.0);
        for i in 0..2 {
            for j in 0..2 {
                let rate = self.roots[i] + self.roots[j];
                // ∫₀^∞ e^{(r_i + r_j)t} dt = −1/(r_i + r_j) ahead (Re < 0); ∫_{−∞}^0 = 1/(r_i + r_j) behind (Re > 0).
                sum += a[i] * a[j] * self.roots[i] * self.roots[j] / (if rate.re < 0.0 { -rate } else { rate });
            }
        }
        Some(sum.re)
    }

    /// The largest U = W − W_far (m) of the wave continued past this end by its decaying modes,
    /// U(t) = a₁e^{r₁t} + a₂e^{r₂t} from the end values U and W′, t the distance past the end (t ≥ 0 ahead, ≤ 0
    /// behind): sampled every 0.1/|r|ₘₐₓ until the slower mode has decayed by e⁻⁸ (3e-4), at most [`TAIL_SAMPLES`]
    /// samples. A nonlinear soil's transparent end is exact only if this stays on the pressed side. None for a
    /// double root.
    pub fn tail_max(&self, u: f64, slope: f64) -> Option<f64> {
        let [a1, a2] = self.tail_modes(u, slope)?;
        let [r1, r2] = self.roots;
        // Ahead the kept roots have Re r < 0 and t runs forward; behind Re r > 0 and t runs backward.
        let direction = if r1.re < 0.0 { 1.0 } else { -1.0 };
        let step = 0.1 / r1.norm().max(r2.norm());
        let samples = ((8.0 / self.decay / step).ceil() as usize).min(TAIL_SAMPLES);
        let at = |t: f64| (a1 * (r1 * t).exp() + a2 * (r2 * t).exp()).re;
        Some((0..=samples).map(|i| at(direction * i as f64 * step)).fold(f64::NEG_INFINITY, f64::max))
    }
}

/// The most samples [`EndRelation::tail_max`] takes of a tail.
pub const TAIL_SAMPLES: usize = 200_000;

/// The transparent relations ahead of and behind the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FarField {
    /// At the front end (s → +∞).
    pub ahead: EndRelation,
    /// At the rear end (s → −∞).
    pub behind: EndRelation,
}

impl FarField {
    /// The relations for `beam` on a far-field soil of damping `damping` (N·s/m²) and stiffness `stiffness` (N/m², > 0)
    /// at speed `speed` (m/s): the decaying roots of the infinite beam's quartic ([`InfiniteBeam::steady_state`]).
    pub fn new(beam: &Beam, damping: f64, stiffness: f64, speed: f64) -> Result<Self> {
        // The roots are the infinite beam's (fem_beam::reference), in ξ = βs: r_s = β r_ξ.
        let foundation = Foundation::linear(stiffness, damping);
        let infinite = InfiniteBeam::new(beam, &foundation)?;
        let state = infinite.steady_state(speed, 1.0).map_err(|e| match e {
            FemError::NoSteadyState { .. } => StationaryError::NoRadiationCondition { speed },
            other => other.into(),
        })?;
        let roots = state.roots().map(|r| r * infinite.beta());
        let pick = |kept: [Complex64; 2]| EndRelation {
            second: [-(kept[0] * kept[1]).re, (kept[0] + kept[1]).re],
            third: [
                -((kept[0] * kept[1]) * (kept[0] + kept[1])).re,
                ((kept[0] + kept[1]).powu(2) - kept[0] * kept[1]).re,
            ],
            decay: kept[0].re.abs().min(kept[1].re.abs()),
            roots: kept,
        };
        Ok(Self { ahead: pick([roots[0], roots[1]]), behind: pick([roots[2], roots[3]]) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beam() -> Beam {
        Beam::default()
    }

    /// The kept roots solve the quartic, and a decaying mode satisfies the end relations exactly.
    #[test]
    fn the_relations_hold_for_every_decaying_mode() {
        let (rho_a, c, k) = (beam().mass_per_length(), 774.0, 250e3);
        let ei = beam().bending_stiffness();
        for v in [0.0, 50.0, 200.0, 400.0] {
            let far = FarField::new(&beam(), c, k, v).unwrap();
            for (end, sign) in [(far.ahead, -1.0), (far.behind, 1.0)] {
                for r in end.roots {
                    assert!(r.re * sign > 0.0, "v {v}: {r} decays the wrong way");
                    let p = ((r * r + rho_a * v * v / ei) * r - c * v / ei) * r + k / ei;
                    assert!(p.norm() <= 1e-10 * (k / ei), "v {v}: {p}");
                    // W = e^{rs} at s = 0: W = 1, W′ = r, W″ = r², W‴ = r³.
                    let second = end.second[0] + end.second[1] * r;
                    let third = end.third[0] + end.third[1] * r;
                    assert!((second - r * r).norm() <= 1e-10 * r.norm().powi(2), "v {v}: {second} vs {}", r * r);
                    assert!((third - r * r * r).norm() <= 1e-10 * r.norm().powi(3));
                }
            }
        }
    }

    #[test]
    fn undamped_above_the_critical_speed_no_end_condition_selects_the_wave() {
        // v_cr = (4kEI/ρA²)^¼ = 205.6 m/s for the reference track.
        assert!(FarField::new(&beam(), 0.0, 250e3, 150.0).is_ok());
        assert!(matches!(FarField::new(&beam(), 0.0, 250e3, 300.0), Err(StationaryError::NoRadiationCondition { .. })));
    }
}
