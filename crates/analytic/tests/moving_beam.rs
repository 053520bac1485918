//! The moving-frame beam's contract (docs/theory.md §8, §16): each rail theory answers the same questions, and
//! Euler–Bernoulli is the κGA → ∞ limit of the Timoshenko quartic, held to Frýba's closed form.

use analytic::MovingBeam;
use analytic::dispersion::static_deflection;
use analytic::reference::{InfiniteBeam, uic60_on_soft_soil};
use fem_beam::{Beam, BeamTheory, FemError, Foundation, Sleepers};
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

/// Euler–Bernoulli through the one quartic (q = 1/κGA = 0) is Frýba's closed form in ξ = βs (an independent
/// derivation: a 4 × 4 solve of the jump conditions, roots of the scaled depressed quartic) to round-off: the wave,
/// its slope, rates and extremes within 1e-11 of w₀ (the roots' own error is ~1e-15 relative, the sums of four
/// complex terms lose a few digits where they cancel), the decay rates to 1e-11, the static limits Fβ/2k and F/4β
/// to 1e-12 — below, near and above the critical speed (damped), where the roots approach the imaginary axis.
#[test]
fn euler_bernoulli_is_frybas_closed_form() {
    let case = uic60_on_soft_soil();
    for zeta in [0.0, 0.05, 0.3] {
        let frame = MovingBeam::new(&case.beam, &Foundation::linear(case.foundation.stiffness, 0.0)).unwrap();
        let soil = Foundation::linear(case.foundation.stiffness, zeta * frame.critical_damping());
        let (moving, fryba) =
            (MovingBeam::new(&case.beam, &soil).unwrap(), InfiniteBeam::new(&case.beam, &soil).unwrap());
        assert_eq!(moving.critical_speed(), fryba.critical_speed());
        let w0 = fryba.static_deflection(83.4e3);
        assert!((moving.static_deflection(83.4e3).unwrap() / w0 - 1.0).abs() < 1e-12);
        let m0 = fryba.static_moment(83.4e3);
        assert!((moving.static_moment(83.4e3).unwrap() / m0 - 1.0).abs() < 1e-12);
        let speeds: &[f64] = if zeta > 0.0 { &[0.0, 60.0, 180.0, 205.0, 260.0, 400.0] } else { &[0.0, 60.0, 180.0] };
        for &v in speeds {
            let (a, b) = (moving.steady_state(v, 83.4e3).unwrap(), fryba.steady_state(v, 83.4e3).unwrap());
            let close = |x: f64, y: f64, scale: f64| (x - y).abs() <= 1e-11 * scale;
            for s in [-40.0, -7.3, -1.0, -1e-9, 0.0, 0.4, 3.1, 12.0, 35.0] {
                assert!(close(a.deflection(s), b.deflection(s), w0), "ζ {zeta} v {v} s {s}");
                assert!(close(a.rotation(s), b.slope(s), w0), "ζ {zeta} v {v} s {s}");
                assert!(close(a.moment(s), case.beam.bending_stiffness() * b.curvature(s), m0), "ζ {zeta} v {v} s {s}");
                assert!(close(a.velocity(s), b.velocity(s), w0 * v.max(1.0)), "ζ {zeta} v {v} s {s}");
                assert!(close(a.rotation_rate(s), b.rotation_rate(s), w0 * v.max(1.0)), "ζ {zeta} v {v} s {s}");
            }
            let (ra, rb) = (a.decay_rates(), b.decay_rates());
            assert!((ra.0 / rb.0 - 1.0).abs() < 1e-11 && (ra.1 / rb.1 - 1.0).abs() < 1e-11, "{ra:?} {rb:?}");
            let (ea, eb) = (a.extremes(), b.extremes());
            assert!(close(ea.max_downward.value, eb.max_downward.value, w0), "ζ {zeta} v {v}");
            assert!(close(ea.max_upward.value, eb.max_upward.value, w0), "ζ {zeta} v {v}");
        }
        if zeta == 0.0 {
            let above = 1.05 * moving.critical_speed();
            assert!(matches!(moving.steady_state(above, 1.0), Err(FemError::NoSteadyState { .. })));
            assert!(matches!(fryba.steady_state(above, 1.0), Err(FemError::NoSteadyState { .. })));
        }
    }
}

/// On no soil (k_f = 0, lifted) either rail has a critical speed of 0 and its free bending waves: for
/// Euler–Bernoulli P = r²(EI r² + ρAv²), so the fastest mode is r = ±iv√(ρA/EI) (to 1e-12).
#[test]
fn a_free_rail_has_its_bending_waves() {
    let beam = uic60_on_soft_soil().beam;
    let free = MovingBeam::new(&beam, &Foundation::linear(0.0, 0.0)).unwrap();
    assert_eq!(free.critical_speed(), 0.0);
    let v = 120.0;
    let fastest = free.wavenumbers(v).iter().map(|r| r.norm()).fold(0.0, f64::max);
    let expected = v * (beam.mass_per_length() / beam.bending_stiffness()).sqrt();
    assert!((fastest / expected - 1.0).abs() < 1e-12, "{fastest} vs {expected}");
    assert!(free.steady_state(v, 1.0).is_err());
}

/// At rest the Timoshenko rail's residues give the Fourier integral's static deflection under the load (an
/// independent quadrature, ~1e-14) to 1e-10, for a stiff soil where shear adds ~1 % to the deflection.
#[test]
fn at_rest_the_timoshenko_wave_is_the_static_deflection() {
    let (beam, k) = (timoshenko(1.0), 100e6);
    let wave = MovingBeam::new(&beam, &Foundation::linear(k, 0.0)).unwrap().steady_state(0.0, 83.4e3).unwrap();
    let exact = static_deflection(&beam, k, 83.4e3);
    assert!((-wave.deflection(0.0) / exact - 1.0).abs() < 1e-10, "{} vs {exact}", wave.deflection(0.0));
    let euler = static_deflection(&uic60_on_soft_soil().beam, k, 83.4e3);
    assert!(exact > 1.005 * euler, "shear must show: {exact} vs {euler}");
}

/// The Timoshenko wave solves the equations across the load: W, Ψ and the moment continuous, W′ jumping by
/// F/(κGA − ρAv²) (Eq. 1 integrated across s = 0), to 1e-9 of their scales; and it decays both ways. Undamped it has
/// a steady state below v_cr and none above.
#[test]
fn across_the_load_the_shear_force_jumps_by_the_force() {
    let beam = timoshenko(1.0);
    let moving = MovingBeam::new(&beam, &Foundation::linear(250e3, 774.0 * 10.0)).unwrap();
    for v in [0.0, 100.0, 250.0] {
        let wave = moving.steady_state(v, 83.4e3).unwrap();
        let (before, after) = (-1e-13, 0.0);
        let w = wave.deflection(0.0).abs();
        assert!((wave.deflection(after) - wave.deflection(before)).abs() < 1e-9 * w, "v {v}");
        let psi = wave.rotation(1.0).abs();
        assert!((wave.rotation(after) - wave.rotation(before)).abs() < 1e-9 * psi, "v {v}");
        let m = wave.moment(0.0).abs();
        assert!((wave.moment(after) - wave.moment(before)).abs() < 1e-9 * m, "v {v}");
        let jump = wave.slope(after) - wave.slope(before);
        let expected = 83.4e3 / (beam.shear_stiffness().unwrap() - beam.mass_per_length() * v * v);
        assert!((jump / expected - 1.0).abs() < 1e-6, "v {v}: {jump} vs {expected}");
        assert!(wave.deflection(300.0).abs() < 1e-6 * w && wave.deflection(-300.0).abs() < 1e-6 * w);
    }
    let undamped = MovingBeam::new(&beam, &Foundation::linear(250e3, 0.0)).unwrap();
    let v_cr = undamped.critical_speed();
    assert!(undamped.steady_state(0.9 * v_cr, 1.0).is_ok());
    assert!(matches!(undamped.steady_state(1.1 * v_cr, 1.0), Err(FemError::NoSteadyState { .. })));
}
