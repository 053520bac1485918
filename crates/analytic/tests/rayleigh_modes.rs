//! The Rayleigh modes of a layered ground (docs/theory.md §19) by two independent methods: the roots of the exact
//! layered system's determinant (`rayleigh_phase_velocities`) and the thin-layer method's eigenproblem
//! (`thin_layer_phase_velocity`, finite elements in depth); and against an independent code's (TrainCritSpeed's
//! Fast Delta Matrix, `tests/data/traincritspeed/`).

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

/// The rows of a reference file: ω (rad/s), then the modes' phase velocities (m/s).
fn reference(name: &str) -> Vec<(f64, Vec<f64>)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/traincritspeed").join(name);
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|line| {
            let values: Vec<f64> = line.split_whitespace().map(|v| v.parse().unwrap()).collect();
            (values[0], values[1..].to_vec())
        })
        .collect()
}

/// Every mode the independent code found (up to ten, Fast Delta Matrix, Buchen & Ben-Hador 1996) is ours to 1e-9 —
/// both are root searches to round-off, so they agree to ~1e-14 — on Foti et al.'s four-layer profile (1 to 10 modes
/// from 10 to 300 rad/s) and Mezher et al.'s soft three-layer one; we find no mode they did not below their tenth.
#[test]
fn the_modes_are_an_independent_codes() {
    let soil = |cs: f64, cp: f64, density: f64| SoilMaterial {
        shear_wave_speed: cs,
        compression_wave_speed: cp,
        density,
        damping_ratio: 0.0,
    };
    let foti = GroundProfile {
        layers: [(5.0, 100.0), (10.0, 200.0), (15.0, 300.0)]
            .map(|(thickness, cs)| SoilLayer { thickness, material: soil(cs, 2.0 * cs, 1900.0) })
            .to_vec(),
        half_space: soil(400.0, 800.0, 1900.0),
    };
    // E and ν as the source gives them: C_s = √(E/(2(1 + ν)ρ)), C_p = C_s√(2(1 − ν)/(1 − 2ν)).
    let of = |e: f64, nu: f64| {
        let cs = (e / (2.0 * (1.0 + nu) * 2000.0)).sqrt();
        soil(cs, cs * (2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)).sqrt(), 2000.0)
    };
    let mezher = GroundProfile {
        layers: vec![
            SoilLayer { thickness: 2.0, material: of(30e6, 0.35) },
            SoilLayer { thickness: 4.0, material: of(40e6, 0.35) },
        ],
        half_space: of(75e6, 0.40),
    };
    for (profile, file) in [(&foti, "foti.csv"), (&mezher, "mezher.csv")] {
        for (omega, expected) in reference(file) {
            let ours = rayleigh_phase_velocities(profile, omega);
            // The source lists at most ten modes (and only the fundamental for Mezher's profile).
            let listed_all = file == "foti.csv" && expected.len() < 10;
            assert!(
                ours.len() >= expected.len() && (!listed_all || ours.len() == expected.len()),
                "{file}, ω {omega}: {ours:?} vs {expected:?}"
            );
            for (a, b) in ours.iter().zip(&expected) {
                assert!((a / b - 1.0).abs() < 1e-9, "{file}, ω {omega}: {a} vs {b}");
            }
        }
    }
}
