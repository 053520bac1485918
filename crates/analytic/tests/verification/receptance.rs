//! The track's receptance from the finite elements against the infinite beam's (residues of its Fourier integral,
//! `analytic::dispersion::point_receptance`), Euler–Bernoulli and Timoshenko, with loss factors heavy enough that
//! the waves die before the ends of a 200 m track: what is left is the element's error.

use analytic::dispersion::point_receptance;
use fem_beam::receptance::FrequencyResponse;
use fem_beam::{Beam, BeamModel, BeamTheory, Foundation, Mesh, Support, Supports};
use num_complex::Complex64;

/// Loss factors of rail and soil: 0.3 each.
const LOSS: f64 = 0.3;

fn track(beam: Beam, elements: usize) -> BeamModel {
    let soil = Foundation { loss_factor: LOSS, ..Foundation::linear(2.5e5, 0.0) };
    let beam = Beam { loss_factor: LOSS, ..beam };
    BeamModel::new(beam, soil, Mesh::new(200.0, elements).unwrap(), Supports::both(Support::Clamped)).unwrap()
}

fn errors(beam: Beam, elements: usize, frequencies: &[f64]) -> Vec<f64> {
    let model = track(beam, elements);
    let response = FrequencyResponse::new(&model);
    frequencies
        .iter()
        .map(|&f| {
            let omega = std::f64::consts::TAU * f;
            let fe = response.receptance(omega, 100.0, &[100.0]).unwrap()[0];
            let exact = point_receptance(&beam, Complex64::new(2.5e5, 2.5e5 * LOSS), LOSS, omega);
            (fe - exact).norm() / exact.norm()
        })
        .collect()
}

/// Euler–Bernoulli on 0.1 m elements: within 1e-4 from 5 Hz to 1 kHz (measured 2.5e-9 below the 10.3 Hz cut-off,
/// 5.6e-7 at 50 Hz, 3.7e-5 at 1 kHz: Hermite's O(h⁴) with 14 elements a wave there; the reflections from the ends,
/// e^{−2·Im k·100 m} ≈ e^{−15} at 50 Hz where they are largest, lie far below with η_r = η_f = 0.3).
#[test]
fn euler_bernoulli_receptance_is_the_infinite_beams() {
    let e = errors(Beam::default(), 2000, &[5.0, 10.3, 50.0, 200.0, 1000.0]);
    assert!(e.iter().all(|&x| x < 1e-4), "{e:?}");
}

/// Timoshenko (G = 81 GPa, κ = 0.4): the element converges as O(h²) — halving 0.1 m elements divides the error at
/// 1 kHz by 4 ± 0.5 (measured 5.1e-3 → 1.3e-3) — and on 0.05 m elements is within 0.5 % up to 2 kHz (measured 1.2e-7
/// at 5 Hz, 3.4e-4 at 500 Hz, 4.3e-3 at 2 kHz): 12 elements a bay of 0.6 m resolve the pinned–pinned range only to a
/// few tenths of a percent.
#[test]
fn timoshenko_receptance_converges_to_the_infinite_beams() {
    let beam =
        Beam { theory: BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 }, ..Beam::default() };
    let coarse = errors(beam, 2000, &[1000.0])[0];
    let fine = errors(beam, 4000, &[5.0, 50.0, 500.0, 1000.0, 2000.0]);
    let ratio = coarse / fine[3];
    assert!((3.5..4.5).contains(&ratio), "{coarse:e} → {:e}", fine[3]);
    assert!(fine.iter().all(|&x| x < 5e-3), "{fine:?}");
}
