//! The Rayleigh modes of a layered ground (docs/theory.md §19) by two independent methods: the roots of the exact
//! layered system's determinant (`rayleigh_phase_velocities`) and the thin-layer method's eigenproblem
//! (`thin_layer_phase_velocity`, finite elements in depth).

use analytic::ground::{
    GroundProfile, SoilLayer, SoilMaterial, ThinLayerMesh, rayleigh_phase_velocities, thin_layer_phase_velocity,
};
use std::f64::consts::PI;

fn soil(shear_wave_speed: f64, compression_wave_speed: f64, density: f64) -> SoilMaterial {
    SoilMaterial { shear_wave_speed, compression_wave_speed, density, damping_ratio: 0.03 }
}

/// A soft layer on a stiffer half-space (normally dispersive).
fn soft_over_stiff() -> GroundProfile {
    GroundProfile {
        layers: vec![SoilLayer { thickness: 5.0, material: soil(100.0, 300.0, 1800.0) }],
        half_space: soil(200.0, 600.0, 2000.0),
    }
}

/// A Ledsgård-like site: a stiff dry crust over soft organic clay over clay stiffening with depth (irregular: the
/// slowest layer is buried, and at high frequency the fundamental mode lives in it, under the crust).
fn crust_over_soft_clay() -> GroundProfile {
    let layers = [
        (1.1, 72.0, 500.0, 1500.0),
        (3.0, 41.0, 500.0, 1260.0),
        (4.5, 65.0, 1500.0, 1475.0),
        (6.0, 87.0, 1500.0, 1475.0),
    ]
    .map(|(thickness, cs, cp, rho)| SoilLayer { thickness, material: soil(cs, cp, rho) })
    .to_vec();
    GroundProfile { layers, half_space: soil(100.0, 1500.0, 1475.0) }
}

/// The root of Rayleigh's equation (2 − c²/C_s²)² = 4√(1 − c²/C_p²)√(1 − c²/C_s²) on (0, C_s), by bisection.
fn rayleigh_speed(m: &SoilMaterial) -> f64 {
    let (cs, cp) = (m.shear_wave_speed, m.compression_wave_speed);
    let f = |c: f64| {
        (2.0 - (c / cs).powi(2)).powi(2) - 4.0 * (1.0 - (c / cp).powi(2)).sqrt() * (1.0 - (c / cs).powi(2)).sqrt()
    };
    let (mut lo, mut hi) = (0.5 * cs, cs * (1.0 - 1e-12));
    for _ in 0..200 {
        let middle = 0.5 * (lo + hi);
        if f(lo) * f(middle) <= 0.0 { hi = middle } else { lo = middle }
    }
    0.5 * (lo + hi)
}

/// A homogeneous half-space has one trapped mode at every frequency, Rayleigh's, to 1e-9 (the bisections' round-off).
#[test]
fn a_homogeneous_half_space_has_rayleighs_wave_only() {
    let material = soil(100.0, 300.0, 1800.0);
    let c_r = rayleigh_speed(&material);
    for f in [1.0, 30.0] {
        let modes = rayleigh_phase_velocities(&GroundProfile::half_space(material), 2.0 * PI * f);
        assert!(modes.len() == 1 && (modes[0] / c_r - 1.0).abs() < 1e-9, "{f} Hz: {modes:?} vs {c_r}");
    }
}

/// The fundamental mode by the exact determinant and by the thin-layer method agree to 1e-4 on a coarse thin-layer
/// mesh (sublayers ≤ min(0.05/k, 0.25 m); the half-space continued 30 decay lengths down) and to 2e-6 on one 2.5×
/// finer, the difference falling ≥ 8× (Richardson's O(h⁴): the thin layers' error, not the exact method's) — on a
/// normally dispersive profile and on the Ledsgård-like one, whose fundamental mode at 32 Hz is trapped in the soft
/// clay under the crust (its root sits beside a pole of the surface stiffness alone).
#[test]
fn the_fundamental_mode_is_the_thin_layer_methods() {
    for (name, profile) in [("soft over stiff", soft_over_stiff()), ("crust over soft clay", crust_over_soft_clay())] {
        for f in [4.0, 8.0, 16.0, 32.0] {
            let omega = 2.0 * PI * f;
            let c = rayleigh_phase_velocities(&profile, omega)[0];
            let k = omega / c;
            let decay = k * (1.0 - (c / profile.half_space.shear_wave_speed).powi(2)).sqrt();
            let depth = profile.layers.iter().map(|layer| layer.thickness).sum::<f64>() + 30.0 / decay;
            let difference = |sublayer: f64| {
                let tlm = thin_layer_phase_velocity(&profile, k, ThinLayerMesh { sublayer, depth }).unwrap();
                (tlm / c - 1.0).abs()
            };
            let (coarse, fine) = (difference((0.05 / k).min(0.25)), difference((0.02 / k).min(0.1)));
            assert!(coarse < 1e-4 && fine < 2e-6, "{name}, {f} Hz: c = {c}, {coarse:.1e} then {fine:.1e}");
            assert!(coarse < 1e-8 || coarse > 8.0 * fine, "{name}, {f} Hz: {coarse:.1e} then {fine:.1e}");
        }
    }
}

/// The soft-over-stiff profile's fundamental mode runs from near the half-space's Rayleigh speed (long waves see the
/// half-space) down to the layer's (short waves see the layer), and the Ledsgård-like site's fundamental falls below
/// its crust's and clay's Rayleigh speeds toward the buried soft clay's shear-wave speed.
#[test]
fn the_fundamental_mode_runs_between_its_limits() {
    let profile = soft_over_stiff();
    let fundamental = |f: f64| rayleigh_phase_velocities(&profile, 2.0 * PI * f)[0];
    let (deep, shallow) = (rayleigh_speed(&profile.half_space), rayleigh_speed(&profile.layers[0].material));
    assert!((fundamental(0.5) / deep - 1.0).abs() < 0.02, "{} vs {deep}", fundamental(0.5));
    assert!((fundamental(100.0) / shallow - 1.0).abs() < 1e-3, "{} vs {shallow}", fundamental(100.0));
    let site = crust_over_soft_clay();
    let c = rayleigh_phase_velocities(&site, 2.0 * PI * 60.0)[0];
    assert!(c > 41.0 * 0.9 && c < 41.0 * 1.03, "{c}");
}
