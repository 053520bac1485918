//! The rail on discrete supports (docs/theory.md §18) against closed forms: a rigid rail on two sleepers is a
//! two-degree-of-freedom system; sleepers closer and closer with the support per metre held are the Winkler track;
//! the pinned–pinned resonance of the rail between sleepers is the simply supported span's.

use analytic::dispersion::static_deflection;
use fem_beam::receptance::FrequencyResponse;
use fem_beam::{
    BallastBody, Beam, BeamModel, BeamTheory, Foundation, Layer, LoadVector, Mesh, Sleepers, Support, Supports,
};
use num_complex::Complex64;
use std::f64::consts::TAU;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// `beam`, 1.2 m long on 8 elements, free at both ends, on two of `sleepers` (0.3 and 0.9 m), on nothing else.
fn stiff_rail_on_two_sleepers(beam: Beam, sleepers: &Sleepers) -> BeamModel {
    let mesh = Mesh::new(1.2, 8).unwrap();
    BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Free))
        .unwrap()
        .with_sleepers(sleepers.clone())
        .unwrap()
}

/// A rail 10⁵ times stiffer than steel, 1.2 m long and free at both ends, on two sleepers (0.3 and 0.9 m), pushed at
/// its middle: it heaves as one mass ρAL on the two pads (2k_p, 2c_p, η_p) over the sleepers (2m_s) on the ballast
/// (2k_b, 2c_b, η_b). Its receptance is that of the two masses,
/// α = (K_p + K_b − ω²M_s)/((K_p − ω²M_r)(K_p + K_b − ω²M_s) − K_p²) with K = 2k(1 + iη) + 2iωc,
/// to 1e-4 (measured 1.6e-6: the rail's bending compliance, L³/48EI = 5.6e-14 m/N, is 2e-5 of the pads'
/// 1/2k_p; its rotation is not excited by a central force).
#[test]
fn a_rigid_rail_on_two_sleepers_is_a_two_mass_system() {
    let beam = Beam { youngs_modulus: 210e9 * 1e5, ..Beam::default() };
    let sleepers = Sleepers {
        pad: Layer { stiffness: 200e6, damping: 20e3, loss_factor: 0.2 },
        ballast: Layer { stiffness: 80e6, damping: 60e3, loss_factor: 0.5 },
        ..Sleepers::default()
    };
    let model = stiff_rail_on_two_sleepers(beam, &sleepers);
    assert_eq!(model.sleepers().unwrap().1, &[2, 6]);
    let response = FrequencyResponse::new(&model);
    for f in [5.0, 40.0, 150.0, 600.0, 2000.0] {
        let omega = TAU * f;
        let spring = |l: &Layer| 2.0 * Complex64::new(l.stiffness, l.stiffness * l.loss_factor + omega * l.damping);
        let (kp, kb) = (spring(&sleepers.pad), spring(&sleepers.ballast));
        let (mr, ms) = (beam.mass_per_length() * 1.2, 2.0 * sleepers.mass);
        let exact =
            (kp + kb - omega * omega * ms) / ((kp - omega * omega * mr) * (kp + kb - omega * omega * ms) - kp * kp);
        let fe = response.receptance(omega, 0.6, &[0.6]).unwrap()[0];
        assert!((fe - exact).norm() < 1e-4 * exact.norm(), "{f} Hz: {fe} vs {exact}");
    }
}

/// The same rigid rail on two sleepers each on a ballast body (Zhai's two layers: the ballast a mass m_b on a
/// subgrade k_g, c_g, η_g): three masses in a chain, whose receptance at the rail is, with
/// D_r = K_p − ω²M_r, D_s = K_p + K_b − ω²M_s, D_b = K_b + K_g − ω²M_b (every K = 2k(1 + iη) + 2iωc, M = 2m),
/// α = (D_s D_b − K_b²)/(D_r (D_s D_b − K_b²) − K_p² D_b), to 1e-4 as above (measured ~1e-6, the rail's bending).
#[test]
fn a_rigid_rail_on_sleepers_on_ballast_bodies_is_a_three_mass_system() {
    let beam = Beam { youngs_modulus: 210e9 * 1e5, ..Beam::default() };
    let body = BallastBody { mass: 500.0, subgrade: Layer { stiffness: 65e6, damping: 31e3, loss_factor: 0.3 } };
    let sleepers = Sleepers {
        pad: Layer { stiffness: 200e6, damping: 20e3, loss_factor: 0.2 },
        ballast: Layer { stiffness: 180e6, damping: 60e3, loss_factor: 0.5 },
        ballast_body: Some(body),
        ..Sleepers::default()
    };
    let model = stiff_rail_on_two_sleepers(beam, &sleepers);
    assert_eq!(model.stiffness().bandwidth(), 5, "w, θ, z, y of a node, then the next node's w and θ");
    let response = FrequencyResponse::new(&model);
    for f in [3.0, 25.0, 80.0, 150.0, 600.0, 2000.0] {
        let omega = TAU * f;
        let spring = |l: &Layer| 2.0 * Complex64::new(l.stiffness, l.stiffness * l.loss_factor + omega * l.damping);
        let (kp, kb, kg) = (spring(&sleepers.pad), spring(&sleepers.ballast), spring(&body.subgrade));
        let w2 = omega * omega;
        let dr = kp - w2 * beam.mass_per_length() * 1.2;
        let ds = kp + kb - w2 * 2.0 * sleepers.mass;
        let db = kb + kg - w2 * 2.0 * body.mass;
        let below = ds * db - kb * kb;
        let exact = below / (dr * below - kp * kp * db);
        let fe = response.receptance(omega, 0.6, &[0.6]).unwrap()[0];
        assert!((fe - exact).norm() < 1e-4 * exact.norm(), "{f} Hz: {fe} vs {exact}");
    }
}

/// A ballast body on a subgrade 10⁶ times stiffer than the ballast is the ballast on rigid ground: the static
/// deflection and the receptance of a 36 m track agree with the one-layer model's to 1e-5 (the subgrade's share of
/// the compliance, k_b/k_g = 1e-6, and m_b barely moves); the equivalent continuous support and the bay's lumped
/// resonances agree likewise, and the body adds a third resonance between them.
#[test]
fn a_ballast_body_on_a_rigid_subgrade_is_the_one_layer_track() {
    let one = Sleepers::default();
    let body = BallastBody { mass: 500.0, subgrade: Layer { stiffness: 1e14, damping: 0.0, loss_factor: 0.0 } };
    let two = Sleepers { ballast_body: Some(body), ..one.clone() };
    let model = |s: &Sleepers| {
        let mesh = Mesh::new(36.0, 240).unwrap();
        BeamModel::new(Beam::default(), Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Clamped))
            .unwrap()
            .with_sleepers(s.clone())
            .unwrap()
    };
    let (a, b) = (model(&one), model(&two));
    let static_w = |m: &BeamModel| {
        let q = m.static_solve(&LoadVector::point_force(&m.discretisation(), 18.0, -83.4e3).unwrap()).unwrap();
        m.deflection_at(&q, 18.0).unwrap()
    };
    assert!(rel(static_w(&b), static_w(&a)) < 1e-5);
    for f in [50.0, 300.0, 1000.0] {
        let r = |m: &BeamModel| FrequencyResponse::new(m).receptance(TAU * f, 18.0, &[18.0]).unwrap()[0];
        assert!((r(&b) - r(&a)).norm() < 1e-5 * r(&a).norm(), "{f} Hz");
    }
    assert!(rel(two.equivalent_stiffness(), one.equivalent_stiffness()) < 1e-5);
    let (lumped1, lumped2) = (one.bay_resonances(60.0), two.bay_resonances(60.0));
    assert!(rel(lumped2.track, lumped1.track) < 1e-5 && rel(lumped2.rail_on_pads, lumped1.rail_on_pads) < 1e-5);
    assert!(lumped1.sleeper_on_ballast.is_none() && lumped2.sleeper_on_ballast.unwrap() > lumped2.rail_on_pads);
}

/// Sleepers a = 0.6, 0.3, 0.15, 0.075 m apart, their pads and ballast scaled with a so that the support per metre,
/// k_eq = (k_p k_b/(k_p + k_b))/a = 111 MN/m², is held: the static deflection under a load above a sleeper tends to
/// the Winkler track's Fβ/2k_eq (its Fourier integral), the error falling at least tenfold per halving (measured
/// 5.5e-3, 2.7e-4, 1.6e-5, 9.6e-7: fourth order in aβ, β = 1.44 /m, the discrete supports' and the mesh's alike).
#[test]
fn closer_sleepers_are_the_winkler_track() {
    let beam = Beam::default();
    let reference = Sleepers::default();
    let k_eq = reference.equivalent_stiffness();
    let winkler = static_deflection(&beam, k_eq, 83.4e3);
    let errors: Vec<f64> = [0.6, 0.3, 0.15, 0.075]
        .into_iter()
        .map(|a| {
            let scale = a / reference.spacing;
            let layer = |l: Layer| Layer { stiffness: l.stiffness * scale, ..l };
            let sleepers = Sleepers {
                spacing: a,
                first: 0.0,
                pad: layer(reference.pad),
                ballast: layer(reference.ballast),
                ..reference.clone()
            };
            let mesh = Mesh::new(36.0, (36.0 / a).round() as usize * 2).unwrap();
            let model = BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Clamped))
                .unwrap()
                .with_sleepers(sleepers)
                .unwrap();
            let q =
                model.static_solve(&LoadVector::point_force(&model.discretisation(), 18.0, -83.4e3).unwrap()).unwrap();
            rel(-model.deflection_at(&q, 18.0).unwrap(), winkler)
        })
        .collect();
    for pair in errors.windows(2) {
        assert!(pair[1] < pair[0] / 10.0, "{errors:?}");
    }
    assert!(errors[3] < 1e-5, "{errors:?}");
}

/// The pinned–pinned resonance: at mid-span between sleepers the receptance of a 30 m track (default sleepers,
/// damped pads and ballast) peaks where the rail's span between two sleepers has its first simply supported mode —
/// 1428 Hz for an Euler–Bernoulli UIC60 rail at a = 0.6 m, 1072 Hz for the Timoshenko rail (κ = 0.4) — to 2 % on a
/// 5 Hz grid (measured 1415 and 1070 Hz: the pads give a little, and the Timoshenko element on 16 elements a bay is
/// good to ~0.3 %).
#[test]
fn the_pinned_pinned_resonance_is_the_span_between_sleepers() {
    let sleepers = Sleepers {
        pad: Layer { stiffness: 200e6, damping: 0.0, loss_factor: 0.25 },
        ballast: Layer { stiffness: 100e6, damping: 0.0, loss_factor: 1.0 },
        ..Sleepers::default()
    };
    let timoshenko =
        Beam { theory: BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 }, ..Beam::default() };
    for (beam, expected) in
        [(Beam { loss_factor: 0.01, ..Beam::default() }, 1428.0), (Beam { loss_factor: 0.01, ..timoshenko }, 1072.0)]
    {
        let mesh = Mesh::new(30.0, 800).unwrap();
        let model = BeamModel::new(beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Free))
            .unwrap()
            .with_sleepers(sleepers.clone())
            .unwrap();
        let response = FrequencyResponse::new(&model);
        let frequencies: Vec<f64> = (0..=160).map(|i| 800.0 + 5.0 * i as f64).collect();
        let magnitudes: Vec<f64> =
            frequencies.iter().map(|&f| response.receptance(TAU * f, 15.0, &[15.0]).unwrap()[0].norm()).collect();
        let (i, _) =
            magnitudes.iter().enumerate().fold((0, 0.0), |best, (i, &m)| if m > best.1 { (i, m) } else { best });
        let peak = frequencies[i];
        assert!(rel(peak, expected) < 2e-2, "peak at {peak} Hz, the span's {expected} Hz");
    }
}
