//! What the ground tests share: the soft trial site of the CLI's tests.

use analytic::ground::{GroundProfile, SoilLayer, SoilMaterial, StripGround};

/// A 3 m strip on a crust (1.5 m, C_s 70 m/s) over soft clay (4 m, 45 m/s) on a stiffer half-space (110 m/s), ν
/// 0.45, 3–5 % damping.
pub fn soft_strip() -> StripGround {
    let soil = |shear_wave_speed: f64, density: f64, damping_ratio: f64| SoilMaterial {
        shear_wave_speed,
        compression_wave_speed: shear_wave_speed * (2.0 * 0.55 / 0.1f64).sqrt(),
        density,
        damping_ratio,
    };
    let layers = vec![
        SoilLayer { thickness: 1.5, material: soil(70.0, 1500.0, 0.04) },
        SoilLayer { thickness: 4.0, material: soil(45.0, 1300.0, 0.03) },
    ];
    StripGround { width: 3.0, profile: GroundProfile { layers, half_space: soil(110.0, 1700.0, 0.05) } }
}
