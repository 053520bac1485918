//! The point receptance of a beam on a line support (docs/theory.md §19): on a Winkler foundation the closed form,
//! on the ground a passive response.

use analytic::dispersion::point_receptance;
use analytic::ground::{GroundProfile, GroundedBeam, SoilLayer, SoilMaterial, StripGround};
use analytic::reference::uic60_on_soft_soil;
use fem_beam::properties::{Beam, Foundation};
use num_complex::Complex64;

/// On a damped Winkler foundation with a rail loss factor the integral over k is the closed form by residues
/// (Knothe & Grassie's 1/(8EIλ³) generalised), to 1e-6, below, at and above the cut-off √(k_f/ρA).
#[test]
fn on_a_winkler_foundation_it_is_the_closed_form() {
    let case = uic60_on_soft_soil();
    let foundation = Foundation {
        damping: 0.1 * case.foundation.critical_damping(&case.beam),
        loss_factor: 0.05,
        ..case.foundation
    };
    let beam = Beam { loss_factor: 0.02, ..case.beam };
    let grounded = GroundedBeam::new(&beam, &foundation).unwrap();
    let cut_off = (foundation.stiffness / beam.mass_per_length()).sqrt();
    for share in [0.0, 0.5, 1.0, 2.0, 10.0] {
        let omega = share * cut_off;
        let ours = grounded.point_receptance(omega, &[]).unwrap();
        let exact = point_receptance(&beam, foundation.dynamic_stiffness(omega), beam.loss_factor, omega);
        assert!((ours - exact).norm() < 1e-6 * exact.norm(), "ω {omega}: {ours} vs {exact}");
    }
}

/// On the ground the receptance is passive (Im α < 0: the force does work on the track, which the ground radiates
/// and damps) and, at 0.5 Hz, within 3 % of the static deflection per newton in its real part (the soil's hysteretic
/// 2iξ takes hold at any ω > 0, so the dynamic stiffness differs from the static one at O(ξ²) in magnitude).
#[test]
fn on_the_ground_it_is_passive_and_tends_to_the_static_deflection() {
    let soil = |shear_wave_speed: f64, damping_ratio: f64| SoilMaterial {
        shear_wave_speed,
        compression_wave_speed: 4.0 * shear_wave_speed,
        density: 1600.0,
        damping_ratio,
    };
    let strip = StripGround {
        width: 3.0,
        profile: GroundProfile {
            layers: vec![SoilLayer { thickness: 3.0, material: soil(60.0, 0.03) }],
            half_space: soil(120.0, 0.03),
        },
    };
    let beam =
        Beam { youngs_modulus: 2e8, second_moment: 1.0, area: 1.0, density: 1e4, loss_factor: 0.05, ..Beam::default() };
    let grounded = GroundedBeam::new(&beam, &strip).unwrap();
    let speeds = strip.profile.wave_speeds();
    let static_deflection = -grounded.spectrum(0.0).unwrap().deflection(0.0);
    let slow = grounded.point_receptance(std::f64::consts::TAU * 0.5, &speeds).unwrap();
    assert!((slow.re / static_deflection - 1.0).abs() < 0.03, "{slow} vs {static_deflection:e}");
    for f in [0.5, 5.0, 20.0] {
        let alpha: Complex64 = grounded.point_receptance(std::f64::consts::TAU * f, &speeds).unwrap();
        assert!(alpha.im < 0.0, "{f} Hz: {alpha}");
    }
}
