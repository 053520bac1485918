//! The far field of the moving-frame beam equations (docs/theory.md §14, §16): where the track is linear and at
//! rest, the wave W(s) = W_far + Σ a_i e^{r_i s} with r the roots of the characteristic quartic — Euler–Bernoulli's
//!
//! ```text
//! EI r⁴ + ρA v² r² − c_f v r + k = 0,
//! ```
//!
//! or the Timoshenko beam's (`analytic::MovingBeam`, whose κGA → ∞ case is the first) — and only the decaying ones may appear: Re r < 0 ahead
//! of the load (s → +∞), Re r > 0 behind it. Each mode carries the rotation DOF θ = β(r) W (β = r, the slope, for
//! Euler–Bernoulli; the cross-section's Ψ = κGA r/(κGA + D r²) W for Timoshenko, D = ρIv² − EI), so the two kept
//! modes' amplitudes follow from an end's values U = W − W_far and θ, and with them what the end's boundary terms
//! need: the weak form's
//!
//! ```text
//! [(ρA v² W′ − Q) φ + (ρI v² − EI) Ψ′ χ]_ends,    Q = D Ψ″ (the shear force κGA(W′ − Ψ); −EI W‴ for Euler–Bernoulli)
//! ```
//!
//! become, per mode, ρAv² r − D r² β on the W row and D r β on the θ row: a 2×2 "traction" T with
//! (row forces) = T·(U, θ), the exact transparent (non-reflecting) condition of a finite domain. Undamped above the
//! critical speed the roots reach the imaginary axis: no root decays, and no end condition selects the outgoing
//! wave — refused.

use crate::error::{Result, StationaryError};
use analytic::MovingBeam;
use fem_beam::{Beam, FemError, Foundation};
use num_complex::Complex64;

/// What one end of the domain needs of the far field beyond it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndRelation {
    /// T: the boundary terms' forces on the end node's (W, θ) rows = T·(W − W_far, θ) (N/m, N; N, N·m).
    pub traction: [[f64; 2]; 2],
    /// The slowest decay rate min |Re r| of the kept roots (1/m).
    pub decay: f64,
    /// The kept roots r₁, r₂ (1/m).
    pub roots: [Complex64; 2],
    /// β(r₁), β(r₂): θ = β W in each mode.
    pub rotation_per_deflection: [Complex64; 2],
}

impl EndRelation {
    /// The relation of the modes `roots`, whose rotation per deflection and its derivative in r are `beta`(r) =
    /// (β, dβ/dr), for ρAv² (N) and D = ρIv² − EI (N·m²). With f(r) the row forces of the mode e^{rs} (W row
    /// ρAv² r − D r² β, θ row D r β), T·(1, β_i) = f(r_i): T's θ column is (f(r₂) − f(r₁))/(β₂ − β₁) and its U column
    /// f(r₁) − β₁·that — for roots closer than √ε (a double root, where both differences vanish) their limits
    /// f′/β′ and f − β f′/β′ at the mean root.
    fn new(roots: [Complex64; 2], beta: impl Fn(Complex64) -> (Complex64, Complex64), rho_v2: f64, d: f64) -> Self {
        let force = |r: Complex64| {
            let (b, db) = beta(r);
            let value = [r * rho_v2 - r * r * b * d, r * b * d];
            let derivative = [-(r * b * 2.0 + r * r * db) * d + rho_v2, (b + r * db) * d];
            (value, derivative, b, db)
        };
        let (f1, _, b1, _) = force(roots[0]);
        let (f2, _, b2, _) = force(roots[1]);
        let close = (roots[1] - roots[0]).norm() <= 1e-8 * roots[0].norm().max(roots[1].norm());
        let mut traction = [[0.0; 2]; 2];
        for row in 0..2 {
            let (theta, u) = if close {
                let (f, df, b, db) = force(0.5 * (roots[0] + roots[1]));
                (df[row] / db, f[row] - b * df[row] / db)
            } else {
                let theta = (f2[row] - f1[row]) / (b2 - b1);
                (theta, f1[row] - b1 * theta)
            };
            traction[row] = [u.re, theta.re];
        }
        let decay = roots[0].re.abs().min(roots[1].re.abs());
        Self { traction, decay, roots, rotation_per_deflection: [b1, b2] }
    }

    /// The amplitudes (a₁, a₂) of the decaying modes that continue the wave past this end from its end values
    /// U = W − W_far and θ: U(t) = a₁e^{r₁t} + a₂e^{r₂t}, t the distance past the end (a₁ + a₂ = U,
    /// a₁β₁ + a₂β₂ = θ). None for a double root.
    fn tail_modes(&self, u: f64, theta: f64) -> Option<[Complex64; 2]> {
        let [b1, b2] = self.rotation_per_deflection;
        let gap = b2 - b1;
        if gap.norm() <= 1e-12 * b1.norm().max(b2.norm()) {
            return None;
        }
        let a2 = (Complex64::new(theta, 0.0) - b1 * u) / gap;
        Some([Complex64::new(u, 0.0) - a2, a2])
    }

    /// ∫ W′² ds over the far field beyond this end (m), for the end values U = W − W_far and θ (the wave continued
    /// by its decaying modes, `Self::tail_modes`): Σ_ij a_i a_j r_i r_j/|r_i + r_j| taken with the sign that makes
    /// each term the integral of a decaying exponential. None for a double root.
    pub fn tail_slope_square(&self, u: f64, theta: f64) -> Option<f64> {
        let a = self.tail_modes(u, theta)?;
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
    /// U(t) = a₁e^{r₁t} + a₂e^{r₂t} from the end values U and θ, t the distance past the end (t ≥ 0 ahead, ≤ 0
    /// behind): sampled every 0.1/|r|ₘₐₓ until the slower mode has decayed by e⁻⁸ (3e-4), at most [`TAIL_SAMPLES`]
    /// samples. A nonlinear soil's transparent end is exact only if this stays on the pressed side. None for a
    /// double root.
    pub fn tail_max(&self, u: f64, theta: f64) -> Option<f64> {
        let [a1, a2] = self.tail_modes(u, theta)?;
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
    /// at speed `speed` (m/s): the decaying roots of the moving-frame beam and the rotation each carries
    /// ([`MovingBeam::decaying_wavenumbers`], [`MovingBeam::rotation_per_deflection`]).
    pub fn new(beam: &Beam, damping: f64, stiffness: f64, speed: f64) -> Result<Self> {
        let foundation = Foundation::linear(stiffness, damping);
        let no_condition = |e: FemError| match e {
            FemError::NoSteadyState { .. } => StationaryError::NoRadiationCondition { speed },
            other => other.into(),
        };
        let rho_v2 = beam.mass_per_length() * speed * speed;
        let d = beam.rotary_inertia() * speed * speed - beam.bending_stiffness();
        let moving = MovingBeam::new(beam, &foundation)?;
        let roots = moving.decaying_wavenumbers(speed).map_err(no_condition)?;
        let rotation = |r: Complex64| moving.rotation_per_deflection(r, speed);
        let end = |i: usize| EndRelation::new([roots[i], roots[i + 1]], rotation, rho_v2, d);
        let (ahead, behind) = (end(0), end(2));
        Ok(Self { ahead, behind })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beam() -> Beam {
        Beam::default()
    }

    /// The kept roots solve the quartic, and a decaying mode e^{rs} meets the end's traction exactly: on the W row
    /// ρAv² r + EI r³ (ρAv² W′ − Q with Q = −EI W‴), on the θ row −EI r² (−EI W″).
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
                    // W = e^{rs} at s = 0: U = 1, θ = W′ = r.
                    let t = end.traction;
                    let w_row = Complex64::new(t[0][0], 0.0) + r * t[0][1];
                    let theta_row = Complex64::new(t[1][0], 0.0) + r * t[1][1];
                    let exact = r * rho_a * v * v + r * r * r * ei;
                    assert!((w_row - exact).norm() <= 1e-9 * exact.norm(), "v {v}: {w_row} vs {exact}");
                    assert!((theta_row + r * r * ei).norm() <= 1e-9 * (r * r * ei).norm());
                }
            }
        }
    }

    /// The same for a Timoshenko rail: each kept root solves its quartic P, and its mode (W = e^{rs}, Ψ = βW) meets
    /// the traction: ρAv² r − D r² β on the W row, D r β on the θ row, with D = ρIv² − EI.
    #[test]
    fn the_relations_hold_for_a_timoshenko_rail() {
        let beam = Beam {
            theory: fem_beam::BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 },
            ..Beam::default()
        };
        let moving = analytic::MovingBeam::new(&beam, &Foundation::linear(250e3, 774.0)).unwrap();
        for v in [0.0, 50.0, 200.0, 400.0] {
            let far = FarField::new(&beam, 774.0, 250e3, v).unwrap();
            let p = moving.characteristic(v);
            let d = beam.rotary_inertia() * v * v - beam.bending_stiffness();
            for end in [far.ahead, far.behind] {
                for (r, beta) in end.roots.into_iter().zip(end.rotation_per_deflection) {
                    let value = (((r * p[0] + p[1]) * r + p[2]) * r + p[3]) * r + p[4];
                    assert!(value.norm() <= 1e-9 * p[4], "v {v}: P({r}) = {value}");
                    let t = end.traction;
                    let w_row = Complex64::new(t[0][0], 0.0) + beta * t[0][1];
                    let theta_row = Complex64::new(t[1][0], 0.0) + beta * t[1][1];
                    let exact = r * beam.mass_per_length() * v * v - r * r * beta * d;
                    assert!((w_row - exact).norm() <= 1e-9 * exact.norm(), "v {v}: {w_row} vs {exact}");
                    assert!((theta_row - r * beta * d).norm() <= 1e-9 * (r * beta * d).norm());
                }
            }
        }
    }

    /// A double root (the two kept modes merging) has the limit of the distinct roots' relation: for
    /// Euler–Bernoulli W″ = −π U + σ W′ and W‴ = −πσ U + (σ² − π) W′ with σ = 2r, π = r², so
    /// T = [[−2EI r³, 3EI r² + ρAv²], [EI r², −2EI r]]; and roots 1e-5 apart lie within 1e-4 of it.
    #[test]
    fn a_double_root_takes_the_limit() {
        let (ei, rho_v2, r) = (6.4e6, 3e5, Complex64::new(-0.7, 0.0));
        let slope = |r: Complex64| (r, Complex64::new(1.0, 0.0));
        let exact =
            [[-2.0 * ei * r.re.powi(3), 3.0 * ei * r.re.powi(2) + rho_v2], [ei * r.re.powi(2), -2.0 * ei * r.re]];
        let double = EndRelation::new([r, r], slope, rho_v2, -ei);
        let apart = EndRelation::new([r, r + 1e-5], slope, rho_v2, -ei);
        for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            let scale = exact[i][j].abs();
            assert!((double.traction[i][j] - exact[i][j]).abs() <= 1e-12 * scale, "{i}{j}: {:?}", double.traction);
            assert!((apart.traction[i][j] - exact[i][j]).abs() <= 1e-4 * scale, "{i}{j}: {:?}", apart.traction);
        }
    }

    #[test]
    fn undamped_above_the_critical_speed_no_end_condition_selects_the_wave() {
        // v_cr = (4kEI/ρA²)^¼ = 205.6 m/s for the reference track.
        assert!(FarField::new(&beam(), 0.0, 250e3, 150.0).is_ok());
        assert!(matches!(FarField::new(&beam(), 0.0, 250e3, 300.0), Err(StationaryError::NoRadiationCondition { .. })));
    }
}
