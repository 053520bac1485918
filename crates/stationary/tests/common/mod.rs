//! What the ground tests share: the soft trial site of the CLI's tests, and the two-beam track that is a rail on a
//! Winkler soil.
#![allow(dead_code)] // Each test file uses its part.

use analytic::ground::{Embankment, GroundProfile, SoilLayer, SoilMaterial, StripGround};
use fem_beam::sleepers::{Layer, Sleepers};
use fem_beam::{Beam, DistributedFriction, Foundation};
use stationary::{Domain, StationaryProblem, StationaryWave, solve};

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

/// The two-beam track that is the reference rail on its soil `foundation` (law as given, 5 % of critical damping):
/// massless sleepers every 0.6 m on rigid pads and a ballast of k_f·a, c_f·a, over an embankment without stiffness
/// or mass on a rigid ground (1e13 N/m²). Returns the rail, the soil, the sleepers, the embankment and the ground.
pub fn rail_on_rigid_embankment(mut foundation: Foundation) -> (Beam, Foundation, Sleepers, Embankment, Foundation) {
    let beam = Beam::default();
    foundation.damping = 0.05 * foundation.critical_damping(&beam);
    let spacing = 0.6;
    let sleepers = Sleepers {
        spacing,
        mass: 0.0,
        pad: Layer { stiffness: 1e14, damping: 0.0, loss_factor: 0.0 },
        ballast: Layer {
            stiffness: foundation.stiffness * spacing,
            damping: foundation.damping * spacing,
            loss_factor: 0.0,
        },
        ..Sleepers::default()
    };
    let embankment = Embankment { bending_stiffness: 1.0, mass_per_length: 0.0, loss_factor: 0.0 };
    (beam, foundation, sleepers, embankment, Foundation::linear(1e13, 0.0))
}

/// The finite-element stationary wave of `beam` on `foundation` under `force` (N) at `speed` with ballast friction
/// `friction` (N/m, one section per node), 60 m each way on `element_length` m elements: the independent reference
/// of the ground's friction solver. Its Newton iteration must have converged.
pub fn fe_friction_wave(
    (beam, foundation): (Beam, Foundation),
    (force, speed, friction): (f64, f64, f64),
    element_length: f64,
) -> StationaryWave {
    let fe = solve(&StationaryProblem {
        beam,
        foundation,
        load: force,
        speed,
        self_weight: false,
        friction: DistributedFriction { force_per_length: friction, subdivisions: 1, ..Default::default() },
        domain: Domain { behind: 60.0, ahead: 60.0, element_length },
    })
    .unwrap();
    assert!(fe.convergence.is_converged(), "{:?}", fe.convergence);
    fe
}
