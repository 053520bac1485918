//! The far field of the moving-frame beam equation (docs/theory.md §14): where the track is linear and at rest, the
//! wave W(s) = W_far + Σ a_i e^{r_i s} with r the roots of the characteristic quartic
//!
//! ```text
//! EI r⁴ + ρA v² r² − c_f v r + k = 0,
//! ```
//!
//! and only the decaying ones may appear: Re r < 0 ahead of the load (s → +∞), Re r > 0 behind it. With the two kept
//! roots r₁, r₂ (σ = r₁ + r₂, π = r₁r₂, real: a conjugate pair or two real roots) every such W satisfies at the end
//!
//! ```text
//! W″ = −π (W − W_far) + σ W′,     W‴ = −πσ (W − W_far) + (σ² − π) W′,
//! ```
//!
//! the exact transparent (non-reflecting) condition of a finite domain. Undamped above the critical speed the
//! roots reach the imaginary axis: no root decays, and no end condition selects the outgoing wave — refused.

use crate::error::{Result, StationaryError};
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
    /// ∫ W′² ds over the far field beyond this end (m), for the end values U = W − W_far and W′ (the wave continued
    /// by its decaying modes U = a₁e^{r₁t} + a₂e^{r₂t}, t the distance past the end): Σ_ij a_i a_j r_i r_j/|r_i + r_j|
    /// taken with the sign that makes each term the integral of a decaying exponential. None for a double root.
    pub fn tail_slope_square(&self, u: f64, slope: f64) -> Option<f64> {
        let [r1, r2] = self.roots;
        let gap = r2 - r1;
        if gap.norm() <= 1e-12 * r1.norm().max(r2.norm()) {
            return None;
        }
        let a2 = (Complex64::new(slope, 0.0) - r1 * u) / gap;
        let a = [Complex64::new(u, 0.0) - a2, a2];
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
}

/// The transparent relations ahead of and behind the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FarField {
    /// At the front end (s → +∞).
    pub ahead: EndRelation,
    /// At the rear end (s → −∞).
    pub behind: EndRelation,
}

/// The four roots of r⁴ + a r² + b r + c = 0 (c > 0) by the Durand–Kerner (Weierstrass) iteration: simultaneous
/// Newton steps r_i ← r_i − p(r_i)/Π_{j≠i}(r_i − r_j) from four points on the circle of radius max(c^¼, √|a|,
/// |b|^⅓), to round-off (a fixed number of sweeps well past convergence; measured ≤ 30 on the tracks of the tests).
fn quartic_roots(a: f64, b: f64, c: f64) -> [Complex64; 4] {
    let p = |r: Complex64| ((r * r + a) * r + b) * r + c;
    let radius = c.powf(0.25).max(a.abs().sqrt()).max(b.abs().cbrt());
    let seed = Complex64::new(0.4, 0.9);
    let mut roots: [Complex64; 4] = std::array::from_fn(|i| seed.powi(i as i32 + 1) * radius);
    for _ in 0..DURAND_KERNER_SWEEPS {
        let mut largest_step = 0.0f64;
        for i in 0..4 {
            let mut denominator = Complex64::new(1.0, 0.0);
            for j in (0..4).filter(|&j| j != i) {
                denominator *= roots[i] - roots[j];
            }
            let step = p(roots[i]) / denominator;
            roots[i] -= step;
            largest_step = largest_step.max(step.norm());
        }
        if largest_step <= 1e-15 * radius {
            break;
        }
    }
    roots
}

/// Sweeps of the Durand–Kerner iteration at most.
const DURAND_KERNER_SWEEPS: usize = 500;

impl FarField {
    /// The relations for bending stiffness `ei` (N·m²), mass per length `rho_a` (kg/m), damping `damping` (N·s/m²),
    /// far-field soil stiffness `stiffness` (N/m², > 0) at speed `speed` (m/s).
    pub fn new(ei: f64, rho_a: f64, damping: f64, stiffness: f64, speed: f64) -> Result<Self> {
        let roots = quartic_roots(rho_a * speed * speed / ei, -damping * speed / ei, stiffness / ei);
        let scale = roots.iter().map(|r| r.norm()).fold(0.0, f64::max);
        // A root within 1e-9 of the imaginary axis (relative to the largest) neither decays nor grows: the
        // undamped supercritical case.
        let floor = 1e-9 * scale;
        let pick = |decaying: &dyn Fn(&Complex64) -> bool| -> Result<EndRelation> {
            let kept: Vec<Complex64> = roots.iter().copied().filter(|r| decaying(r) && r.re.abs() > floor).collect();
            if kept.len() != 2 {
                return Err(StationaryError::NoRadiationCondition { speed });
            }
            let (sigma, pi) = ((kept[0] + kept[1]).re, (kept[0] * kept[1]).re);
            Ok(EndRelation {
                second: [-pi, sigma],
                third: [-pi * sigma, sigma * sigma - pi],
                decay: kept[0].re.abs().min(kept[1].re.abs()),
                roots: [kept[0], kept[1]],
            })
        };
        Ok(Self { ahead: pick(&|r| r.re < 0.0)?, behind: pick(&|r| r.re > 0.0)? })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kept roots solve the quartic, and a decaying mode satisfies the end relations exactly.
    #[test]
    fn the_relations_hold_for_every_decaying_mode() {
        let (ei, rho_a, c, k) = (6.4e6, 60.0, 774.0, 250e3);
        for v in [0.0, 50.0, 200.0, 400.0] {
            let far = FarField::new(ei, rho_a, c, k, v).unwrap();
            let roots = quartic_roots(rho_a * v * v / ei, -c * v / ei, k / ei);
            for r in roots {
                let p = ((r * r + rho_a * v * v / ei) * r - c * v / ei) * r + k / ei;
                assert!(p.norm() <= 1e-12 * (k / ei), "v {v}: {p}");
                let end = if r.re < 0.0 { far.ahead } else { far.behind };
                // W = e^{rs} at s = 0: W = 1, W′ = r, W″ = r², W‴ = r³.
                let second = end.second[0] + end.second[1] * r;
                let third = end.third[0] + end.third[1] * r;
                assert!((second - r * r).norm() <= 1e-10 * r.norm().powi(2), "v {v}: {second} vs {}", r * r);
                assert!((third - r * r * r).norm() <= 1e-10 * r.norm().powi(3));
            }
        }
    }

    #[test]
    fn undamped_above_the_critical_speed_no_end_condition_selects_the_wave() {
        // v_cr = (4kEI/ρA²)^¼ = 205.6 m/s for the reference track.
        assert!(FarField::new(6.4e6, 60.0, 0.0, 250e3, 150.0).is_ok());
        assert!(matches!(
            FarField::new(6.4e6, 60.0, 0.0, 250e3, 300.0),
            Err(StationaryError::NoRadiationCondition { .. })
        ));
    }
}
