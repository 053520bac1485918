//! The layered ground's surface flexibility (docs/theory.md §19) against what is known without it: identical layers
//! are the half-space, the static half-space is Boussinesq's, a homogeneous half-space's Rayleigh wave is the root
//! of Rayleigh's equation, and bad profiles are refused by key.

use analytic::ground::{GroundProfile, SoilLayer, SoilMaterial, half_space_stiffness, surface_flexibility};

fn clay(damping_ratio: f64) -> SoilMaterial {
    SoilMaterial { shear_wave_speed: 72.0, compression_wave_speed: 500.0, density: 1500.0, damping_ratio }
}

/// Three layers of the half-space's own material (1, 2.5 and 7 m: 1 to 70 sublayers at these (k, ω)) on it are the
/// half-space, to 1e-9: below and above the shear wave, at rest, damped and not, short and long waves.
#[test]
fn identical_layers_are_the_half_space() {
    for damping in [0.0, 0.04] {
        let soil = clay(damping);
        let layered = GroundProfile {
            layers: [1.0, 2.5, 7.0].map(|thickness| SoilLayer { thickness, material: soil }).to_vec(),
            half_space: soil,
        };
        let alone = GroundProfile::half_space(soil);
        for (k, omega) in [(0.05, 0.0), (0.5, 10.0), (0.5, 30.0), (2.0, 100.0), (10.0, 300.0), (0.3, 60.0)] {
            let (a, b) = (surface_flexibility(&layered, k, omega), surface_flexibility(&alone, k, omega));
            assert!((a - b).norm() <= 1e-9 * b.norm(), "ξ {damping}, k {k}, ω {omega}: {a} vs {b}");
        }
    }
}

/// At rest the layered path gives Boussinesq's (1 − ν)/(μk) for a homogeneous ground too (1e-10), and a stiff crust
/// over it lowers the flexibility of long waves less than of short ones (the crust carries the short ones).
#[test]
fn at_rest_a_homogeneous_ground_is_boussinesqs_and_a_crust_stiffens_short_waves() {
    let soil = clay(0.0);
    let layered = GroundProfile { layers: vec![SoilLayer { thickness: 3.0, material: soil }], half_space: soil };
    for k in [0.01, 0.3, 4.0] {
        let exact = (1.0 - soil.poisson_ratio()) / (soil.shear_modulus(0.0).re * k);
        let f = surface_flexibility(&layered, k, 0.0);
        assert!((f.re / exact - 1.0).abs() < 1e-10 && f.im.abs() < 1e-10 * exact, "k {k}: {f} vs {exact}");
    }
    let crust = SoilMaterial { shear_wave_speed: 200.0, compression_wave_speed: 600.0, ..soil };
    let crusted = GroundProfile { layers: vec![SoilLayer { thickness: 1.0, material: crust }], half_space: soil };
    let ratio = |k: f64| {
        surface_flexibility(&crusted, k, 0.0).re / surface_flexibility(&GroundProfile::half_space(soil), k, 0.0).re
    };
    assert!(
        ratio(0.01) > 0.95 && ratio(5.0) < 0.3 && ratio(5.0) < ratio(0.5),
        "{} {} {}",
        ratio(0.01),
        ratio(0.5),
        ratio(5.0)
    );
}

/// Rayleigh's equation (2 − c²/C_s²)² = 4√(1 − c²/C_p²)√(1 − c²/C_s²), solved by bisection on (0, C_s): the half-space's
/// stiffness is singular there (det/(μk)² < 1e-9) and changes sign across it, and the flexibility grows as
/// 1/|c − c_R| (×10 per decade closer).
#[test]
fn the_surface_wave_of_a_homogeneous_half_space_is_rayleighs() {
    let soil = clay(0.0);
    let (cs, cp) = (soil.shear_wave_speed, soil.compression_wave_speed);
    let rayleigh = |c: f64| {
        (2.0 - (c / cs).powi(2)).powi(2) - 4.0 * (1.0 - (c / cp).powi(2)).sqrt() * (1.0 - (c / cs).powi(2)).sqrt()
    };
    let (mut lo, mut hi) = (0.5 * cs, 0.999_999 * cs);
    assert!(rayleigh(lo) * rayleigh(hi) < 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if rayleigh(lo) * rayleigh(mid) <= 0.0 { hi = mid } else { lo = mid }
    }
    let c_r = 0.5 * (lo + hi);
    // Viktorov's estimate (0.862 + 1.14ν)/(1 + ν)·C_s is within 0.5 % of the root.
    let nu = soil.poisson_ratio();
    assert!((c_r / ((0.862 + 1.14 * nu) / (1.0 + nu) * cs) - 1.0).abs() < 5e-3, "c_R = {c_r}");
    let k = 0.7;
    let mu_k = soil.shear_modulus(0.0).re * k;
    let det = |c: f64| half_space_stiffness(&soil, k, k * c).determinant() / (mu_k * mu_k);
    assert!(det(c_r).norm() < 1e-9, "{}", det(c_r));
    assert!(det(c_r * (1.0 - 1e-4)).re * det(c_r * (1.0 + 1e-4)).re < 0.0);
    let flexibility = |c: f64| surface_flexibility(&GroundProfile::half_space(soil), k, k * c).norm();
    let growth = flexibility(c_r * (1.0 - 1e-6)) / flexibility(c_r * (1.0 - 1e-5));
    assert!((growth / 10.0 - 1.0).abs() < 1e-3, "{growth}");
}

/// A profile's bad values are refused by key, with the value and what is allowed.
#[test]
fn bad_profiles_are_refused_by_key() {
    let good =
        GroundProfile { layers: vec![SoilLayer { thickness: 1.1, material: clay(0.04) }], half_space: clay(0.05) };
    assert!(good.validate().is_ok());
    let refused = |profile: GroundProfile| profile.validate().unwrap_err().to_string();
    let mut thin = good.clone();
    thin.layers[0].thickness = 0.0;
    assert!(refused(thin).contains("ground.layers[0].thickness = 0"));
    let mut slow_p = good.clone();
    slow_p.layers[0].material.compression_wave_speed = 60.0;
    assert!(refused(slow_p).contains("ground.layers[0].compression_wave_speed = 60"));
    let mut negative = good.clone();
    negative.half_space.damping_ratio = -0.01;
    assert!(refused(negative).contains("ground.half_space.damping_ratio = -0.01"));
    let many = GroundProfile { layers: vec![good.layers[0]; 5000], half_space: good.half_space };
    assert!(refused(many).contains("at most 200 layers"));
}
