//! The moving-frame beam's contract (docs/theory.md §8, §16): each rail theory answers the same questions, and
//! Euler–Bernoulli is the κGA → ∞ limit of the Timoshenko quartic.

use analytic::MovingBeam;
use analytic::reference::uic60_on_soft_soil;
use fem_beam::{Beam, BeamTheory, Foundation, Sleepers};
use num_complex::Complex64;

/// A Timoshenko rail whose shear is `stiffer` times UIC60's.
fn timoshenko(stiffer: f64) -> Beam {
    let theory = BeamTheory::Timoshenko { shear_modulus: 81e9 * stiffer, shear_coefficient: 0.4 };
    Beam { theory, ..uic60_on_soft_soil().beam }
}

/// At rest (where ρI v² = 0) a Timoshenko rail of 10⁶-fold shear stiffness is Euler–Bernoulli's: the wave, its
/// decay agree to the shear's share EI k²/κGA ~ 1e-9 (the tolerances hold 10–100× that).
/// Moving, they differ by the rotary inertia's ρv²/E as well (1.5e-3 at 200 m/s): checked at 1 m/s.
#[test]
fn euler_bernoulli_is_the_stiff_shear_limit_of_timoshenko() {
    let case = uic60_on_soft_soil();
    let soil = Foundation::linear(case.foundation.stiffness, 774.0);
    let euler = MovingBeam::new(&case.beam, &soil).unwrap();
    let stiff = MovingBeam::new(&timoshenko(1e6), &soil).unwrap();
    // Rotary inertia adds ρI k² to ρA: v² = (EI k² + k_f/k²)/(ρA + ρI k²), lower by (I/A)k² = ρv²/(2E) at the
    // critical wave k² = √(k_f/EI), so v_cr is lower by ρv²/(4E) = 3.9e-4, to first order (the second, ~1e-7, and
    // the shear's 1e-9 stay well inside 4 %).
    let v = euler.critical_speed();
    let rotary = case.beam.density * v * v / case.beam.youngs_modulus;
    let lower = 1.0 - stiff.critical_speed() / v;
    assert!((lower / (0.25 * rotary) - 1.0).abs() < 0.04, "{lower} vs ρv²/E = {rotary}");
    assert_eq!(stiff.critical_damping(), euler.critical_damping());
    let w0 = euler.static_deflection(1.0).unwrap();
    assert!((stiff.static_deflection(1.0).unwrap() / w0 - 1.0).abs() < 1e-8);
    let (a, b) = (euler.steady_state(1.0, 1.0).unwrap(), stiff.steady_state(1.0, 1.0).unwrap());
    for s in [-20.0, -3.0, -0.5, 0.0, 0.7, 4.0, 15.0] {
        assert!((a.deflection(s) - b.deflection(s)).abs() < 1e-7 * w0, "s {s}");
    }
    let (ra, rb) = (a.decay_rates(), b.decay_rates());
    assert!((ra.0 / rb.0 - 1.0).abs() < 1e-7 && (ra.1 / rb.1 - 1.0).abs() < 1e-7, "{ra:?} {rb:?}");
}

/// Each decaying root solves the polynomial its rail gives, the rotation's derivative is the derivative of Ψ/W
/// (central difference, h = 1e-6 |r|: error ~h² ≈ 1e-12, bounded at 1e-7), and the limits are the bar and shear waves.
#[test]
fn roots_rotations_and_limits_hold_for_both_rails() {
    let case = uic60_on_soft_soil();
    let soil = Foundation::linear(case.foundation.stiffness, 774.0);
    for beam in [case.beam, timoshenko(1.0)] {
        let moving = MovingBeam::new(&beam, &soil).unwrap();
        let v = 150.0;
        let roots = moving.decaying_wavenumbers(v).unwrap();
        assert!(roots[0].re < 0.0 && roots[1].re < 0.0 && roots[2].re > 0.0 && roots[3].re > 0.0);
        let all = moving.wavenumbers(v);
        for r in roots {
            assert!(all.iter().any(|q| (q - r).norm() <= 1e-9 * r.norm()), "{r} not among {all:?}");
            let h = Complex64::new(1e-6 * r.norm(), 0.0);
            let (_, derivative) = moving.rotation_per_deflection(r, v);
            let difference =
                (moving.rotation_per_deflection(r + h, v).0 - moving.rotation_per_deflection(r - h, v).0) / (h * 2.0);
            assert!((derivative - difference).norm() <= 1e-7 * derivative.norm(), "{derivative} vs {difference}");
        }
        let expected = match beam.shear_stiffness() {
            None => (beam.youngs_modulus / beam.density).sqrt(),
            Some(g) => (g / beam.mass_per_length()).sqrt(),
        };
        assert_eq!(moving.wave_speed_limit(), expected);
        assert!(moving.critical_speed() < expected);
    }
}

/// On sleepers the track's critical speed is its long-wave twin's; the twin is softer and heavier than the rail on
/// the soil alone, so slower: 0 < v_cr(sleepers) < v_cr(rail on k_f + k_eq), and a Timoshenko rail's is lower still.
#[test]
fn the_critical_speed_of_a_sleeper_track_is_its_long_wave_twins() {
    let case = uic60_on_soft_soil();
    let sleepers = Sleepers::default();
    let soil = Foundation::linear(case.foundation.stiffness, 0.0);
    let on_sleepers = MovingBeam::of_track(&case.beam, &soil, Some(&sleepers)).unwrap();
    let (twin, k) = sleepers.equivalent_track(&case.beam, soil.stiffness);
    let direct = MovingBeam::new(&twin, &Foundation::linear(k, 0.0)).unwrap();
    assert_eq!(on_sleepers.critical_speed(), direct.critical_speed());
    let bare = MovingBeam::new(&case.beam, &Foundation::linear(k, 0.0)).unwrap();
    assert!(on_sleepers.critical_speed() < bare.critical_speed());
    let shear = MovingBeam::of_track(&timoshenko(1.0), &soil, Some(&sleepers)).unwrap();
    assert!(0.0 < shear.critical_speed() && shear.critical_speed() < on_sleepers.critical_speed());
    assert_eq!(MovingBeam::of_track(&case.beam, &soil, None).unwrap(), MovingBeam::new(&case.beam, &soil).unwrap());
}
