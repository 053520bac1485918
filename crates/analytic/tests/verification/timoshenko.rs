//! The Timoshenko element against closed forms (docs/theory.md §15): a cantilever's tip under an end force and a
//! uniform load (bending plus shear, exact on any mesh), the simply supported beam's natural frequencies from
//! Timoshenko's frequency equation, and Euler–Bernoulli as the limit G → ∞.

use fem_beam::{Beam, BeamModel, BeamTheory, Foundation, LoadVector, Mesh, Support, Supports};

/// UIC60 with steel's G = 81 GPa and κ = 0.4 (vertical bending).
fn uic60_timoshenko() -> Beam {
    Beam { theory: BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 }, ..Beam::default() }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Tip deflection PL³/3EI + PL/κGA and rotation PL²/2EI under an end force; qL⁴/8EI + qL²/2κGA under a uniform
/// load — on one element and on seven, for a short cantilever (L = 0.5 m: shear is a fifth of the deflection).
/// Round-off of a banded solve of at most 16 unknowns: 1e-12.
#[test]
fn a_cantilevers_tip_is_exact_with_shear() {
    let beam = uic60_timoshenko();
    let (ei, kga) = (beam.bending_stiffness(), beam.shear_stiffness().unwrap());
    let length = 0.5;
    for elements in [1, 7] {
        let mesh = Mesh::new(length, elements).unwrap();
        let supports = Supports { left: Support::Clamped, right: Support::Free };
        let model = BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, supports).unwrap();
        let p = -1e5;
        let q = model.static_solve(&LoadVector::point_force(&model.discretisation(), length, p).unwrap()).unwrap();
        let shear = p * length / kga;
        let expected = p * length.powi(3) / (3.0 * ei) + shear;
        assert!(shear.abs() > 0.2 * expected.abs(), "shear must matter in this test");
        let tip = model.deflection_at(&q, length).unwrap();
        assert!(rel(tip, expected) < 1e-12, "{elements} elements: {tip} vs {expected}");
        // The last DOF is the cross-section's rotation ψ, which shear does not change at the free end.
        let psi = q[q.len() - 1];
        assert!(rel(psi, p * length * length / (2.0 * ei)) < 1e-12, "ψ {psi}");
        let w = -2e5;
        let q = model.static_solve(&LoadVector::uniform(&mesh, w).unwrap()).unwrap();
        let expected = w * length.powi(4) / (8.0 * ei) + w * length * length / (2.0 * kga);
        let tip = model.deflection_at(&q, length).unwrap();
        assert!(rel(tip, expected) < 1e-12, "{elements} elements, uniform: {tip} vs {expected}");
    }
}

/// The lower root ω² of Timoshenko's frequency equation for a simply supported beam, mode n (k = nπ/L):
/// (κGA k² − ρA ω²)(EI k² + κGA − ρI ω²) = (κGA k)², i.e. ρAρI ω⁴ − (ρA(EI k² + κGA) + ρI κGA k²) ω² + EI κGA k⁴ = 0.
fn timoshenko_pinned_frequency(beam: &Beam, length: f64, n: usize) -> f64 {
    let k = n as f64 * std::f64::consts::PI / length;
    let (ei, kga, rho_a, rho_i) =
        (beam.bending_stiffness(), beam.shear_stiffness().unwrap(), beam.mass_per_length(), beam.rotary_inertia());
    let b = rho_a * (ei * k * k + kga) + rho_i * kga * k * k;
    let c = ei * kga * k.powi(4);
    let discriminant = b * b - 4.0 * rho_a * rho_i * c;
    // The smaller root as 2c/(b + √…): no cancellation.
    (2.0 * c / (b + discriminant.sqrt())).sqrt()
}

/// A rail span between two sleepers (L = 0.6 m, pinned, no soil): the pinned–pinned modes. The first five within
/// 0.1 % of the exact spectrum on 120 elements (the element converges as O(h²) in frequency; 0.1 % is the issue's
/// bound): the bending roots of the frequency equation for n = 1, 2, 3, … and, between them, the uniform shear mode
/// w = 0, ψ = const at √(κGA/ρI) (k = 0: pinned ends leave ψ free) — 32.3 krad/s, between n = 3 and n = 4. The first
/// lies well below Euler–Bernoulli's π²/L²·√(EI/ρA) (shear and rotary inertia soften it by a quarter).
#[test]
fn simply_supported_frequencies_follow_timoshenkos_equation() {
    let beam = uic60_timoshenko();
    let length = 0.6;
    let mesh = Mesh::new(length, 120).unwrap();
    let model = BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Pinned)).unwrap();
    let omega = model.natural_frequencies(5).unwrap();
    let mut exact: Vec<f64> = (1..=5).map(|n| timoshenko_pinned_frequency(&beam, length, n)).collect();
    exact.push((beam.shear_stiffness().unwrap() / beam.rotary_inertia()).sqrt());
    exact.sort_by(f64::total_cmp);
    for n in 0..5 {
        let error = rel(omega[n], exact[n]);
        assert!(error < 1e-3, "mode {}: {} vs {} rad/s ({error:e})", n + 1, omega[n], exact[n]);
    }
    let euler = (std::f64::consts::PI / length).powi(2) * (beam.bending_stiffness() / beam.mass_per_length()).sqrt();
    assert!(omega[0] < 0.8 * euler && omega[0] > 0.6 * euler, "{} vs Euler–Bernoulli {euler}", omega[0]);
}

/// G → ∞ is Euler–Bernoulli in statics: the same stiffness to round-off, the same deflection under a point load on a
/// soil.
#[test]
fn infinite_shear_stiffness_is_euler_bernoulli() {
    let stiff =
        Beam { theory: BeamTheory::Timoshenko { shear_modulus: 1e30, shear_coefficient: 1.0 }, ..Beam::default() };
    let mesh = Mesh::new(30.0, 60).unwrap();
    let soil = Foundation::linear(2.5e5, 0.0);
    let supports = Supports::both(Support::Pinned);
    let timoshenko = BeamModel::new(stiff, soil, mesh, supports).unwrap();
    let euler = BeamModel::new(Beam::default(), soil, mesh, supports).unwrap();
    // Between nodes, each beam's load takes its own element's shape functions.
    let load = |model: &BeamModel| LoadVector::point_force(&model.discretisation(), 15.1, -1e5).unwrap();
    let (a, b) = (timoshenko.static_solve(&load(&timoshenko)).unwrap(), euler.static_solve(&load(&euler)).unwrap());
    let scale = b.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    // φ ≈ 1e-20: the matrices differ by round-off only.
    assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12 * scale));
}

/// A Timoshenko beam without G or with κ outside (0, 1] is refused by name.
#[test]
fn bad_shear_parameters_are_named() {
    let mesh = Mesh::new(1.0, 2).unwrap();
    let build = |theory| {
        let beam = Beam { theory, ..Beam::default() };
        BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Pinned))
            .unwrap_err()
            .to_string()
    };
    let no_g = build(BeamTheory::Timoshenko { shear_modulus: 0.0, shear_coefficient: 0.4 });
    assert!(no_g.contains("beam.shear_modulus"), "{no_g}");
    let kappa = build(BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 1.5 });
    assert!(kappa.contains("beam.shear_coefficient = 1.5") && kappa.contains("(0, 1]"), "{kappa}");
}

/// A Timoshenko rail's static deflection under a load at mid-track (200 m, clamped far from it) converges to the
/// infinite beam's Fourier integral ([`analytic::dispersion::static_deflection`]) at second order in the element
/// length (each halving divides the error by 4 ± 0.5; measured 1.8e-5, 4.1e-6, 9.9e-7 on the reference soil from
/// 0.5 m elements, 6.9e-3 … 3.8e-4 on a stiff one, k_f = 100 MN/m², whose waves are 20 times shorter) — the O(h²) of
/// this element with a distributed soil, where Hermite's is O(h⁴). Shear adds 0.38 % to Euler–Bernoulli's Fβ/2k_f on
/// the reference soil, 7.5 % on the stiff one.
#[test]
fn static_deflection_on_a_soil_converges_to_the_fourier_integral() {
    let beam = uic60_timoshenko();
    for (k_f, shear) in [(2.5e5, 3.81e-3), (1e8, 7.47e-2)] {
        let integral = analytic::dispersion::static_deflection(&beam, k_f, 83.4e3);
        let errors: Vec<f64> = [400, 800, 1600]
            .into_iter()
            .map(|elements| {
                let mesh = Mesh::new(200.0, elements).unwrap();
                let model =
                    BeamModel::new(beam, Foundation::linear(k_f, 0.0), mesh, Supports::both(Support::Clamped)).unwrap();
                let load = LoadVector::point_force(&model.discretisation(), 100.0, -83.4e3).unwrap();
                let q = model.static_solve(&load).unwrap();
                rel(-model.deflection_at(&q, 100.0).unwrap(), integral)
            })
            .collect();
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!((3.5..4.5).contains(&ratio), "k_f = {k_f}: errors {errors:?}");
        }
        let euler = analytic::dispersion::static_deflection(&Beam::default(), k_f, 83.4e3);
        assert!(rel(integral / euler - 1.0, shear) < 1e-2, "k_f = {k_f}: {}", integral / euler - 1.0);
    }
}
