//! The reference case of docs/theory.md §2 and the closed-form results that tests, benches and the CLI share (§2, §8).
//!
//! # Infinite beam on a viscoelastic foundation under a moving load
//! For EI w'''' + ρA w_tt + c_f w_t + k_f w = F δ(x − vt) (w positive *downward* in this derivation only), in the
//! moving frame s = x − vt with ξ = βs, β = (k_f/4EI)^¼, α = v/v_cr, ζ = c_f/c_cr, w = (4Fβ/k_f)·G(ξ) and
//!
//! ```text
//! G'''' + 4α² G'' − 8αζ G' + 4G = δ(ξ)
//! ```
//!
//! (Frýba, *Vibration of solids and structures under moving loads*, §9; Esveld, *Modern railway track*, §5).
//! With r the roots of r⁴ + 4α²r² − 8αζr + 4 = 0, ahead of the load (ξ > 0) G = Σ Aₖ e^{rₖξ} over the two roots with
//! Re r < 0, behind it G = Σ Bₖ e^{rₖξ} over the two with Re r > 0; G, G′, G″ are continuous at ξ = 0 and G‴ jumps
//! by 1. Undamped at or above the critical speed some roots lie on the imaginary axis and no bounded steady state
//! exists ([`FemError::NoSteadyState`]). For α → 0 this is the static shape e^{−|ξ|}(cos ξ + sin|ξ|)/8.
//!
//! Results are returned in frictrack's convention: deflection positive **upward**, so the load's own dip is negative.

use crate::golden::golden_bracket;
use fem_beam::assembly::BeamModel;
use fem_beam::error::{FemError, Result, non_negative, positive};
use fem_beam::extreme::{DeflectionExtremes, Extreme};
use fem_beam::mesh::Mesh;
use fem_beam::properties::{Beam, Foundation};
use fem_beam::supports::Supports;
use nalgebra::{Matrix4, Vector4};
use num_complex::Complex64;
use std::f64::consts::PI;

/// The reference case: UIC60 rail, soft soil, 200 m pinned beam of 200 elements, F = 83.4 kN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceCase {
    /// The rail.
    pub beam: Beam,
    /// The soil.
    pub foundation: Foundation,
    /// Beam length and elements.
    pub mesh: Mesh,
    /// End supports.
    pub supports: Supports,
    /// Magnitude of the moving load F (N), acting downward. Default 83.4 kN (half a Thalys power-car axle).
    pub load: f64,
}

/// The reference case of docs/theory.md §2 (all defaults).
pub fn uic60_on_soft_soil() -> ReferenceCase {
    ReferenceCase {
        beam: Beam::default(),
        foundation: Foundation::default(),
        mesh: Mesh::default(),
        supports: Supports::default(),
        load: 83.4e3,
    }
}

impl ReferenceCase {
    /// The assembled finite-element model of this case.
    pub fn model(&self) -> Result<BeamModel> {
        BeamModel::new(self.beam, self.foundation, self.mesh, self.supports)
    }

    /// The infinite beam with the same section and foundation (closed-form references).
    pub fn infinite_beam(&self) -> Result<InfiniteBeam> {
        InfiniteBeam::new(&self.beam, &self.foundation)
    }
}

/// An infinite Euler–Bernoulli beam on a viscoelastic Winkler foundation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InfiniteBeam {
    /// EI (N·m²).
    pub bending_stiffness: f64,
    /// ρA (kg/m).
    pub mass_per_length: f64,
    /// k_f (N/m²), > 0.
    pub foundation_stiffness: f64,
    /// c_f (N·s/m²), ≥ 0.
    pub foundation_damping: f64,
}

impl InfiniteBeam {
    /// From a rail section and a foundation; errors if k_f = 0 (no static equilibrium on an infinite beam).
    pub fn new(beam: &Beam, foundation: &Foundation) -> Result<Self> {
        beam.validate()?;
        positive("foundation.stiffness", foundation.stiffness)?;
        non_negative("foundation.damping", foundation.damping)?;
        Ok(Self {
            bending_stiffness: beam.bending_stiffness(),
            mass_per_length: beam.mass_per_length(),
            foundation_stiffness: foundation.stiffness,
            foundation_damping: foundation.damping,
        })
    }

    /// β = (k_f/4EI)^¼ (1/m); 0.31417 m⁻¹ for the reference case.
    pub fn beta(&self) -> f64 {
        (self.foundation_stiffness / (4.0 * self.bending_stiffness)).powf(0.25)
    }

    /// Static deflection magnitude under a point load F: w₀ = Fβ/(2k_f) (m); 52.40 mm for the reference case.
    pub fn static_deflection(&self, force: f64) -> f64 {
        force * self.beta() / (2.0 * self.foundation_stiffness)
    }

    /// Static bending moment under a point load F: M₀ = F/(4β) (N·m); 66.37 kN·m for the reference case.
    pub fn static_moment(&self, force: f64) -> f64 {
        force / (4.0 * self.beta())
    }

    /// Critical speed v_cr = (4 k_f EI/(ρA)²)^¼ (m/s); 205.57 m/s for the reference case.
    pub fn critical_speed(&self) -> f64 {
        (4.0 * self.foundation_stiffness * self.bending_stiffness / self.mass_per_length.powi(2)).powf(0.25)
    }

    /// Critical damping c_cr = 2√(k_f ρA) (N·s/m²).
    pub fn critical_damping(&self) -> f64 {
        2.0 * (self.foundation_stiffness * self.mass_per_length).sqrt()
    }

    /// Damping ratio ζ = c_f/c_cr.
    pub fn damping_ratio(&self) -> f64 {
        self.foundation_damping / self.critical_damping()
    }

    /// Foundation cut-off frequency √(k_f/ρA) (rad/s); 64.585 rad/s for the reference case.
    pub fn cutoff_frequency(&self) -> f64 {
        (self.foundation_stiffness / self.mass_per_length).sqrt()
    }

    /// The wavenumbers r (1/m) of the moving-frame equation EI r⁴ + ρA v² r² − c_f v r + k_f = 0 at `speed` (m/s):
    /// every solution of the unloaded track in s = x − vt is a sum of e^{rs}. Unlike [`Self::steady_state`] they exist
    /// at every speed (undamped above v_cr some lie on the imaginary axis); their largest modulus sets the shortest
    /// length 1/|r| any wave of the track varies on, which a mesh must resolve.
    pub fn wavenumbers(&self, speed: f64) -> [Complex64; 4] {
        let alpha = speed / self.critical_speed();
        quartic_roots(4.0 * alpha * alpha, -8.0 * alpha * self.damping_ratio(), 4.0).map(|r| r * self.beta())
    }

    /// The steady-state response to a load of magnitude `force` (N, downward) moving at `speed` (m/s, ≥ 0).
    pub fn steady_state(&self, speed: f64, force: f64) -> Result<SteadyState> {
        non_negative("speed", speed)?;
        if !force.is_finite() {
            return Err(FemError::InvalidField { field: "force", value: force, allowed: "must be finite" });
        }
        let alpha = speed / self.critical_speed();
        let zeta = self.damping_ratio();
        let roots = quartic_roots(4.0 * alpha * alpha, -8.0 * alpha * zeta, 4.0);
        // A root on (or numerically at) the imaginary axis means no decay on one side: no bounded steady state.
        let scale = roots.iter().map(|r| r.norm()).fold(1.0, f64::max);
        let no_state = || FemError::NoSteadyState { speed, damping_ratio: zeta, critical_speed: self.critical_speed() };
        if roots.iter().any(|r| r.re.abs() <= 1e-9 * scale) {
            return Err(no_state());
        }
        let ahead: Vec<Complex64> = roots.iter().copied().filter(|r| r.re < 0.0).collect();
        let behind: Vec<Complex64> = roots.iter().copied().filter(|r| r.re > 0.0).collect();
        if ahead.len() != 2 || behind.len() != 2 {
            return Err(no_state());
        }
        // Σ Aₖ aₖ^m − Σ Bₖ bₖ^m = 0 for m = 0, 1, 2 and = 1 for m = 3.
        let matrix = Matrix4::from_fn(|m, j| {
            let (r, sign) = if j < 2 { (ahead[j], 1.0) } else { (behind[j - 2], -1.0) };
            r.powu(m as u32) * sign
        });
        let rhs = Vector4::new(0.0, 0.0, 0.0, 1.0).map(Complex64::from);
        let coef = matrix.lu().solve(&rhs).ok_or_else(no_state)?;
        let beta = self.beta();
        Ok(SteadyState {
            speed,
            beta,
            amplitude: 4.0 * force * beta / self.foundation_stiffness,
            ahead: [(ahead[0], coef[0]), (ahead[1], coef[1])],
            behind: [(behind[0], coef[2]), (behind[1], coef[3])],
        })
    }
}

/// Roots of the monic quartic r⁴ + c₂r² + c₁r + c₀ (Durand–Kerner iteration, then Newton polishing).
fn quartic_roots(c2: f64, c1: f64, c0: f64) -> [Complex64; 4] {
    monic_quartic_roots([0.0, c2, c1, c0])
}

/// Roots of the monic quartic r⁴ + c₃r³ + c₂r² + c₁r + c₀, `c` = [c₃, c₂, c₁, c₀] (Durand–Kerner iteration, then
/// three Newton steps each). With c₃ = 0 every operation is the depressed quartic's, bit for bit.
pub(crate) fn monic_quartic_roots(c: [f64; 4]) -> [Complex64; 4] {
    let [c3, c2, c1, c0] = c;
    let p = |z: Complex64| ((z * z + z * c3 + c2) * z + c1) * z + c0;
    let dp = |z: Complex64| (z * z * 4.0 + z * (3.0 * c3) + 2.0 * c2) * z + c1;
    let seed = Complex64::new(0.4, 0.9);
    let mut z = [seed, seed * seed, seed.powu(3), seed.powu(4)];
    let size = 1.0 + c3.abs().max(c2.abs()).max(c1.abs()).max(c0.abs());
    for _ in 0..2000 {
        let mut change: f64 = 0.0;
        for i in 0..4 {
            let denom: Complex64 = (0..4).filter(|&j| j != i).map(|j| z[i] - z[j]).product();
            let step = p(z[i]) / denom;
            z[i] -= step;
            change = change.max(step.norm());
        }
        if change <= 1e-15 * size {
            break;
        }
    }
    for r in &mut z {
        for _ in 0..3 {
            let d = dp(*r);
            if d.norm() > 0.0 {
                *r -= p(*r) / d;
            }
        }
    }
    z
}

/// The steady-state deflection of an infinite beam under a moving load, as a function of s = x − vt.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyState {
    speed: f64,
    beta: f64,
    amplitude: f64,
    ahead: [(Complex64, Complex64); 2],
    behind: [(Complex64, Complex64); 2],
}

impl SteadyState {
    /// The dimensionless G⁽ᵐ⁾(ξ), m-th derivative in ξ (positive downward).
    fn g(&self, xi: f64, derivative: u32) -> f64 {
        let terms = if xi >= 0.0 { &self.ahead } else { &self.behind };
        terms.iter().map(|(r, c)| (c * r.powu(derivative) * (r * xi).exp()).re).sum()
    }

    /// Load speed (m/s).
    pub fn speed(&self) -> f64 {
        self.speed
    }

    /// The slowest decay rates of the wave ahead of and behind the load (1/m): β·min |Re r| over each pair of roots,
    /// so that the wave falls to a fraction ε of its size within ln(1/ε)/rate of the load.
    pub fn decay_rates(&self) -> (f64, f64) {
        let slowest = |pair: &[(Complex64, Complex64); 2]| self.beta * pair[0].0.re.abs().min(pair[1].0.re.abs());
        (slowest(&self.ahead), slowest(&self.behind))
    }

    /// The roots r of the characteristic quartic (ahead pair first), for reports and cross-checks.
    pub fn roots(&self) -> [Complex64; 4] {
        [self.ahead[0].0, self.ahead[1].0, self.behind[0].0, self.behind[1].0]
    }

    /// Deflection w (m, positive upward) at s = x − vt (m).
    pub fn deflection(&self, s: f64) -> f64 {
        -self.amplitude * self.g(self.beta * s, 0)
    }

    /// Slope ∂w/∂x (rad) at s.
    pub fn slope(&self, s: f64) -> f64 {
        -self.amplitude * self.beta * self.g(self.beta * s, 1)
    }

    /// Curvature ∂²w/∂x² (1/m) at s; the bending moment is EI times it (sagging positive).
    pub fn curvature(&self, s: f64) -> f64 {
        -self.amplitude * self.beta * self.beta * self.g(self.beta * s, 2)
    }

    /// Velocity ∂w/∂t = −v·∂w/∂s (m/s) at s.
    pub fn velocity(&self, s: f64) -> f64 {
        -self.speed * self.slope(s)
    }

    /// Rotation rate ∂θ/∂t = −v·∂²w/∂s² (rad/s) at s.
    pub fn rotation_rate(&self, s: f64) -> f64 {
        self.speed * self.amplitude * self.beta * self.beta * self.g(self.beta * s, 2)
    }

    /// Largest downward and upward deflections and their positions: dense sampling over the region where the
    /// response is above ~e⁻⁴⁰ of its scale, then golden-section refinement to 1e-12 in ξ.
    pub fn extremes(&self) -> DeflectionExtremes {
        let (step, reach) = self.sampling_in_xi();
        let count = (reach / step).ceil() as i64;
        let (down, up) = scan_extremes(|xi| self.g(xi, 0), (-count..=count).map(|i| i as f64 * step), step);
        DeflectionExtremes {
            max_downward: Extreme::in_frame(self.amplitude * down.1.max(0.0), down.0 / self.beta),
            max_upward: Extreme::in_frame(self.amplitude * up.1.max(0.0), up.0 / self.beta),
        }
    }
}

impl SteadyState {
    /// A step resolving the shortest wave (a 64th of it, at most 0.05) and the reach beyond which the wave is below
    /// e⁻⁴⁰ of its scale (at most 4000), in ξ = βs.
    fn sampling_in_xi(&self) -> (f64, f64) {
        let decay = self.roots().iter().map(|r| r.re.abs()).fold(f64::INFINITY, f64::min);
        let wave = self.roots().iter().map(|r| r.im.abs()).fold(1.0, f64::max);
        ((2.0 * PI / wave / 64.0).min(0.05), (40.0 / decay).min(4000.0))
    }

    /// The same sampling in s (m): (step, reach).
    pub fn sampling(&self) -> (f64, f64) {
        let (step, reach) = self.sampling_in_xi();
        (step / self.beta, reach / self.beta)
    }
}

/// The largest values of f (downward) and of −f (upward) over `samples` (spaced `step`), each refined by golden
/// section within a step of its best sample: ((x, f), (x, −f)) at the maxima. One scan for a single load and for a
/// train ([`crate::steady_train`]).
pub(crate) fn scan_extremes(
    f: impl Fn(f64) -> f64,
    samples: impl Iterator<Item = f64>,
    step: f64,
) -> ((f64, f64), (f64, f64)) {
    let (mut best_down, mut best_up) = ((0.0, f64::NEG_INFINITY), (0.0, f64::NEG_INFINITY));
    for x in samples {
        let value = f(x);
        if value > best_down.1 {
            best_down = (x, value);
        }
        if -value > best_up.1 {
            best_up = (x, -value);
        }
    }
    // The bracket's midpoint, to 1e-12 m.
    let refine = |centre: f64, sign: f64| {
        let mut signed = |x: f64| Ok::<_, std::convert::Infallible>(sign * f(x));
        let Ok(bracket) = golden_bracket(&mut signed, centre - step, centre + step, 1e-12, true);
        let x = 0.5 * (bracket.lower + bracket.upper);
        (x, sign * f(x))
    };
    (refine(best_down.0, 1.0), refine(best_up.0, -1.0))
}
