//! Free waves of an infinite beam on a Winkler foundation and the critical speed they set (docs/theory.md §2, §15).
//!
//! A wave w = W e^{ik(x − vt)}, ψ = Ψ e^{ik(x − vt)} of a Timoshenko beam (ρA ẅ = κGA(w″ − ψ′) − k_f w,
//! ρI ψ̈ = EI ψ″ + κGA(w′ − ψ)) travels at ω = v k where
//!
//! ```text
//! (κGA k² + k_f − ρA ω²)(EI k² + κGA − ρI ω²) = (κGA k)²,
//! ```
//!
//! a quadratic in ω² whose lower root is the bending branch. A load moving at v resonates with the wave whose phase
//! velocity ω/k is v and equals its group velocity: the critical speed is the least phase velocity over k. For an
//! Euler–Bernoulli beam (κGA → ∞, ρI = 0) the branch is ρA ω² = EI k⁴ + k_f and the minimum is the closed form
//! v_cr = (4 k_f EI/(ρA)²)^{1/4} ([`crate::reference::InfiniteBeam::critical_speed`]).

use crate::golden::golden_section;
use crate::reference::InfiniteBeam;
use fem_beam::error::Result;
use fem_beam::properties::{Beam, Foundation};
use num_complex::Complex64;

/// The bending branch ω(k) (rad/s) of `beam` on a foundation of stiffness `k_f` (N/m²) at wavenumber k (rad/m).
pub fn bending_frequency(beam: &Beam, k_f: f64, k: f64) -> f64 {
    let (ei, rho_a) = (beam.bending_stiffness(), beam.mass_per_length());
    let Some(kga) = beam.shear_stiffness() else {
        return ((ei * k.powi(4) + k_f) / rho_a).sqrt();
    };
    let rho_i = beam.rotary_inertia();
    let (a, b) = (kga * k * k + k_f, ei * k * k + kga);
    // ρAρI ω⁴ − (ρA b + ρI a) ω² + (a b − (κGA k)²) = 0; the smaller root as 2c/(B + √(B² − 4AC)): no cancellation.
    let big_b = rho_a * b + rho_i * a;
    // a b − (κGA k)², expanded so that no large terms cancel when κGA is large.
    let c = kga * (ei * k.powi(4) + k_f) + ei * k * k * k_f;
    let discriminant = (big_b * big_b - 4.0 * rho_a * rho_i * c).max(0.0);
    (2.0 * c / (big_b + discriminant.sqrt())).sqrt()
}

/// ω_n (rad/s) of `beam` pinned at both ends of a span `length` m long on a foundation of stiffness `k_f` (N/m²),
/// whose modes are sin(nπx/L): the bending branch at k = nπ/L — ω_n² = (EI k⁴ + k_f)/(ρA) for Euler–Bernoulli, the
/// lower root of Timoshenko's frequency equation for a Timoshenko beam.
pub fn pinned_natural_frequency(beam: &Beam, k_f: f64, length: f64, n: usize) -> f64 {
    bending_frequency(beam, k_f, n as f64 * std::f64::consts::PI / length)
}

/// The pinned–pinned frequency (Hz) of a rail on supports `spacing` m apart: the free rail's bending wave of half a
/// wavelength per spacing, k = π/a, its nodes over the supports (π/(2a²)·√(EI/ρA) for Euler–Bernoulli).
pub fn pinned_pinned(beam: &Beam, spacing: f64) -> f64 {
    bending_frequency(beam, 0.0, std::f64::consts::PI / spacing) / std::f64::consts::TAU
}

/// The wave a load at the critical speed resonates with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalWave {
    /// k (rad/m).
    pub wavenumber: f64,
    /// v_cr = ω(k)/k, the least phase velocity (m/s).
    pub speed: f64,
}

/// The critical speed (m/s) of `beam` on `foundation`: the least phase velocity ω(k)/k of the bending branch
/// ([`critical_wave`]).
pub fn critical_speed(beam: &Beam, foundation: &Foundation) -> Result<f64> {
    critical_wave(beam, foundation).map(|wave| wave.speed)
}

/// The critical wave of `beam` on `foundation`: the closed form for Euler–Bernoulli (k = (k_f/EI)^{1/4}); for
/// Timoshenko a golden-section search in ln k around it. The speed is flat at its minimum, v ≈ v_cr(1 + O(δk²)), so
/// the search finds v_cr to round-off but k only to about √ε ≈ 1e-8 relative.
pub fn critical_wave(beam: &Beam, foundation: &Foundation) -> Result<CriticalWave> {
    let euler = InfiniteBeam::new(beam, foundation)?;
    let euler_k = (foundation.stiffness / beam.bending_stiffness()).powf(0.25);
    if beam.shear_stiffness().is_none() {
        return Ok(CriticalWave { wavenumber: euler_k, speed: euler.critical_speed() });
    }
    let k_f = foundation.stiffness;
    let mut phase = |ln_k: f64| {
        let k = ln_k.exp();
        Ok::<_, std::convert::Infallible>(bending_frequency(beam, k_f, k) / k)
    };
    // Shear and rotary inertia soften short waves: the minimum moves to shorter waves than Euler–Bernoulli's, never
    // by a factor of 100 for a rail on any soil (a 20-fold bracket either way is searched).
    let centre = euler_k.ln();
    let Ok((ln_k, speed)) = golden_section(&mut phase, centre - 20f64.ln(), centre + 20f64.ln(), 1e-12, false);
    Ok(CriticalWave { wavenumber: ln_k.exp(), speed })
}

/// The static deflection (m, magnitude) under a point force `force` (N) on `beam` resting on a foundation of
/// stiffness `k_f` (N/m²), infinite both ways, from its Fourier integral: with ω = 0 the wave equations give
/// W(k) = F (EI k² + κGA)/(κGA EI k⁴ + k_f EI k² + k_f κGA), so
///
/// ```text
/// w(0) = (F/π) ∫₀^∞ (EI k² + κGA)/(κGA EI k⁴ + k_f EI k² + k_f κGA) dk    (Euler–Bernoulli: (F/π)∫ dk/(EI k⁴ + k_f) = Fβ/2k_f)
/// ```
///
/// integrated after k = c·tan t (c = (k_f/EI)^{1/4}, t ∈ [0, π/2), a smooth integrand) by 4-point Gauss–Legendre
/// on 256 panels: to ~1e-14 relative. An independent reference for the finite elements in statics.
pub fn static_deflection(beam: &Beam, k_f: f64, force: f64) -> f64 {
    let ei = beam.bending_stiffness();
    let c = (k_f / ei).powf(0.25);
    let compliance = |k: f64| match beam.shear_stiffness() {
        None => 1.0 / (ei * k.powi(4) + k_f),
        Some(kga) => (ei * k * k + kga) / (kga * ei * k.powi(4) + k_f * ei * k * k + k_f * kga),
    };
    let panels = 256;
    let width = std::f64::consts::FRAC_PI_2 / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        for &(xi, w) in &fem_beam::element::hermite::GAUSS_4 {
            let t = (p as f64 + xi) * width;
            let k = c * t.tan();
            sum += w * width * compliance(k) * c / (t.cos() * t.cos());
        }
    }
    force * sum / std::f64::consts::PI
}

/// The point receptance α(ω) = w(0)/F (m/N) of `beam`, infinite both ways, on a foundation of complex dynamic
/// stiffness `soil` k̃ (N/m², e.g. k_f(1 + iη) + iωc_f) at circular frequency `omega` (rad/s), the rail's material
/// carrying a loss factor `rail_loss` (EI → EI(1 + iη_r), κGA → κGA(1 + iη_r)). With K = k̃ − ρAω², S = κGA − ρIω², the
/// wave equations give W(k) = F (EI k² + S)/(κGA EI k⁴ + (EI K − κGA ρI ω²) k² + K S) (Euler–Bernoulli: F/(EI k⁴ + K)),
/// a ratio of polynomials in k² = r with roots r₁, r₂. By partial fractions and ∫ dk/(k² − r) = iπ/√r (the root with
/// Im √r > 0: waves that decay away from the load),
///
/// ```text
/// α = (i/2)·(N(r₁)/(a(r₁ − r₂)√r₁) + N(r₂)/(a(r₂ − r₁)√r₂)),   N(r) = EI r + S,  a = κGA·EI
/// ```
///
/// — for Euler–Bernoulli 1/(8 EI λ³) with 4λ⁴ = K/EI (Knothe & Grassie 1993). Damping must be positive somewhere
/// (Im k̃ > 0 or η_r > 0) for a propagating wave to decay; undamped above the cut-off the limit is taken.
pub fn point_receptance(beam: &Beam, soil: Complex64, rail_loss: f64, omega: f64) -> Complex64 {
    let waves = Waves::of(beam, soil, rail_loss, omega);
    let [(r1, k1), (r2, k2)] = waves.roots;
    let term = |r: Complex64, other: Complex64, k: Complex64| waves.numerator(r) / (waves.leading * (r - other) * k);
    0.5 * Complex64::i() * (term(r1, r2, k1) + term(r2, r1, k2))
}

/// The two free waves of [`point_receptance`]'s beam at ω: their wavenumbers k (rad/m, Im k ≥ 0: each decays as
/// e^{−Im k·|x|} away from a load, and travels where Re k dominates).
pub fn wavenumbers(beam: &Beam, soil: Complex64, rail_loss: f64, omega: f64) -> [Complex64; 2] {
    Waves::of(beam, soil, rail_loss, omega).roots.map(|(_, k)| k)
}

/// The polynomial a r² + b r + c in r = k² of the wave equations, its roots and √ with Im ≥ 0.
struct Waves {
    /// a.
    leading: Complex64,
    /// EI(1 + iη_r).
    ei: Complex64,
    /// S = κGA − ρIω² (Timoshenko), None for Euler–Bernoulli (the numerator is 1).
    shear: Option<Complex64>,
    /// (r, k = √r with Im k ≥ 0) for both roots.
    roots: [(Complex64, Complex64); 2],
}

impl Waves {
    fn of(beam: &Beam, soil: Complex64, rail_loss: f64, omega: f64) -> Self {
        let ei = Complex64::new(beam.bending_stiffness(), beam.bending_stiffness() * rail_loss);
        let k = soil - beam.mass_per_length() * omega * omega;
        let upper = |r: Complex64| {
            let root = r.sqrt();
            (r, if root.im >= 0.0 { root } else { -root })
        };
        match beam.shear_stiffness() {
            None => {
                // EI r² + K = 0: r = ±i√(K/EI).
                let r = Complex64::i() * (k / ei).sqrt();
                Self { leading: ei, ei, shear: None, roots: [upper(r), upper(-r)] }
            }
            Some(kga) => {
                let kga = kga * Complex64::new(1.0, rail_loss);
                let s = kga - beam.rotary_inertia() * omega * omega;
                let (a, b, c) = (kga * ei, ei * k - kga * beam.rotary_inertia() * omega * omega, k * s);
                let disc = (b * b - 4.0 * a * c).sqrt();
                let roots = [upper((-b + disc) / (2.0 * a)), upper((-b - disc) / (2.0 * a))];
                Self { leading: a, ei, shear: Some(s), roots }
            }
        }
    }

    /// N(r) = EI r + S (Timoshenko) or 1.
    fn numerator(&self, r: Complex64) -> Complex64 {
        self.shear.map_or(Complex64::new(1.0, 0.0), |s| self.ei * r + s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fem_beam::properties::BeamTheory;

    #[test]
    fn the_pinned_pinned_frequency_of_uic60_on_sleepers_0_6_m_apart_is_1428_hz() {
        // Euler–Bernoulli: π/(2a²)·√(EI/ρA).
        let beam = Beam::default();
        let closed = std::f64::consts::PI / (2.0 * 0.36) * (beam.bending_stiffness() / beam.mass_per_length()).sqrt();
        assert!((pinned_pinned(&beam, 0.6) / closed - 1.0).abs() < 1e-12);
        assert!((closed - 1428.0).abs() < 1.0, "{closed} Hz");
    }

    fn timoshenko(shear_modulus: f64) -> Beam {
        Beam { theory: BeamTheory::Timoshenko { shear_modulus, shear_coefficient: 0.4 }, ..Beam::default() }
    }

    /// G → ∞ leaves the Rayleigh beam (rotary inertia kept): ρ(A + I k²) ω² = EI k⁴ + k_f at every k (to 1e-9,
    /// round-off of a quadratic's root with κGA = 4e17 N); its critical speed within 0.1 % of Euler–Bernoulli's (long
    /// waves barely rotate). A real rail's shear lowers it a little more, and more on a stiff soil, whose critical
    /// wave is shorter.
    #[test]
    fn critical_speed_tends_to_rayleigh_and_euler_bernoulli() {
        let soil = Foundation::linear(2.5e5, 0.0);
        let rayleigh = timoshenko(1e20);
        let (ei, rho_a, rho_i) = (rayleigh.bending_stiffness(), rayleigh.mass_per_length(), rayleigh.rotary_inertia());
        for k in [0.1_f64, 1.0, 10.0, 50.0] {
            let expected = ((ei * k.powi(4) + 2.5e5) / (rho_a + rho_i * k * k)).sqrt();
            let omega = bending_frequency(&rayleigh, 2.5e5, k);
            assert!((omega - expected).abs() < 1e-9 * expected, "k = {k}: {omega} vs {expected}");
        }
        let euler = critical_speed(&Beam::default(), &soil).unwrap();
        let stiff = critical_speed(&rayleigh, &soil).unwrap();
        assert!(stiff < euler && stiff > 0.999 * euler, "{stiff} vs {euler}");
        let rail = critical_speed(&timoshenko(81e9), &soil).unwrap();
        assert!(rail < stiff && rail > 0.99 * euler, "{rail} vs {euler}");
        let hard = Foundation::linear(1e8, 0.0);
        let (rail_hard, euler_hard) =
            (critical_speed(&timoshenko(81e9), &hard).unwrap(), critical_speed(&Beam::default(), &hard).unwrap());
        assert!(1.0 - rail_hard / euler_hard > 1.0 - rail / euler, "{rail_hard} vs {euler_hard}");
    }

    /// The Fourier integral is the closed form Fβ/(2k_f) for Euler–Bernoulli (to 1e-12: the quadrature's error), and a
    /// real rail's shear adds to it (the shear compliance, a fraction of a percent on soft soil, more on stiff soil).
    #[test]
    fn static_deflection_is_the_closed_form_for_euler_bernoulli() {
        for k_f in [2.5e5, 1e8] {
            let soil = Foundation::linear(k_f, 0.0);
            let closed = InfiniteBeam::new(&Beam::default(), &soil).unwrap().static_deflection(83.4e3);
            let integral = static_deflection(&Beam::default(), k_f, 83.4e3);
            assert!((integral - closed).abs() < 1e-12 * closed, "{integral} vs {closed}");
            let rail = static_deflection(&timoshenko(81e9), k_f, 83.4e3);
            assert!(rail > closed && rail < 1.1 * closed, "{rail} vs {closed}");
        }
    }

    /// The receptance at ω → 0 is the static deflection per newton (the Fourier integral, an independent method: to
    /// 1e-10); for Euler–Bernoulli it is 1/(8EIλ³) at any frequency; both are causal (Im α < 0 with damping: the
    /// response lags the force).
    #[test]
    fn receptance_is_static_at_zero_frequency_and_the_closed_form_for_euler_bernoulli() {
        for beam in [Beam::default(), timoshenko(81e9)] {
            for k_f in [2.5e5, 1e8] {
                let alpha = point_receptance(&beam, Complex64::new(k_f, 1e-12 * k_f), 0.0, 0.0);
                let statics = static_deflection(&beam, k_f, 1.0);
                assert!((alpha.re - statics).abs() < 1e-10 * statics, "{alpha} vs {statics}");
            }
        }
        let beam = Beam::default();
        for (omega, eta) in [(100.0, 0.1), (2000.0, 0.02), (20000.0, 0.01)] {
            let soil = Complex64::new(2.5e5, 2.5e5 * 0.3);
            let alpha = point_receptance(&beam, soil, eta, omega);
            let ei = Complex64::new(beam.bending_stiffness(), beam.bending_stiffness() * eta);
            let lambda = ((soil - beam.mass_per_length() * omega * omega) / (4.0 * ei)).powf(0.25);
            let closed = 1.0 / (8.0 * ei * lambda * lambda * lambda);
            assert!((alpha - closed).norm() < 1e-12 * closed.norm(), "ω = {omega}: {alpha} vs {closed}");
            assert!(alpha.im < 0.0, "{alpha}");
            assert!(point_receptance(&timoshenko(81e9), soil, eta, omega).im < 0.0);
        }
    }

    /// At the critical wave the group velocity dω/dk equals the phase velocity ω/k (the definition of the minimum).
    /// Their difference is k·dv/dk ≈ k²v″·δk: with the search's k good to ~1e-8 (√ε, see [`critical_wave`]) and a
    /// central difference of relative step 1e-5 (error ~1e-10), they agree to 1e-7.
    #[test]
    fn at_the_critical_wave_group_and_phase_velocities_agree() {
        for (beam, k_f) in [(timoshenko(81e9), 2e7), (timoshenko(81e9), 2.5e5), (Beam::default(), 2e7)] {
            let wave = critical_wave(&beam, &Foundation::linear(k_f, 0.0)).unwrap();
            let (k, v) = (wave.wavenumber, wave.speed);
            assert!((bending_frequency(&beam, k_f, k) / k - v).abs() < 1e-12 * v);
            let dk = 1e-5 * k;
            let group = (bending_frequency(&beam, k_f, k + dk) - bending_frequency(&beam, k_f, k - dk)) / (2.0 * dk);
            assert!((group - v).abs() < 1e-7 * v, "group {group} vs phase {v} at k = {k}");
        }
    }
}
