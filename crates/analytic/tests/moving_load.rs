//! A beam on a line support under a moving force by one Fourier integral (`GroundedBeam`, docs/theory.md §19),
//! against the closed forms on a Winkler foundation and its own limits on the ground.

use analytic::MovingBeam;
use analytic::ground::GroundedBeam;
use analytic::reference::uic60_on_soft_soil;
use fem_beam::properties::Foundation;

/// On a Winkler foundation the Fourier integral is the closed-form steady wave (`MovingBeam`, Frýba's residues), to
/// 1e-5 of the static deflection at every s from 12 m behind to 12 m ahead: at rest, below, near and above the
/// critical speed (damped 10 %). The spectrum's cubic predicts each sample to 1e-6 of max|G| (its error between
/// samples is smaller still, O(h⁴)); observed 7e-7.
#[test]
fn on_a_winkler_foundation_it_is_the_closed_form() {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { damping: 0.1 * case.foundation.critical_damping(&case.beam), ..case.foundation };
    let closed = MovingBeam::new(&case.beam, &foundation).unwrap();
    let grounded = GroundedBeam::new(&case.beam, &foundation).unwrap();
    let w0 = closed.static_deflection(1.0).unwrap();
    let mut worst = 0.0f64;
    for fraction in [0.0, 0.5, 0.95, 1.3] {
        let speed = fraction * closed.critical_speed();
        let exact = closed.steady_state(speed, 1.0).unwrap();
        let spectrum = grounded.spectrum(speed).unwrap();
        for s in [-12.0, -4.0, -1.0, -0.3, 0.0, 0.3, 1.0, 4.0, 12.0] {
            worst = worst.max((spectrum.deflection(s) - exact.deflection(s)).abs() / w0);
        }
    }
    assert!(worst < 1e-5, "worst difference {worst:.1e} of w₀");
}

/// A train on a Winkler foundation: the spectrum's superposition of shifted single-load waves is the closed form's
/// (`TrainSteadyState`, Frýba's wave summed over the axles) for HSLM-A1's 50 axles, 0.8 v_cr, 10 % damping — to
/// 1e-5 of the largest deflection at every s from 30 m ahead to 30 m behind the last axle (each axle's wave is
/// within 1e-5 of w₀ of the closed form, and neighbouring axles' errors do not add up: observed 1e-7).
#[test]
fn a_train_is_its_axles_waves_superposed() {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { damping: 0.1 * case.foundation.critical_damping(&case.beam), ..case.foundation };
    let closed = MovingBeam::new(&case.beam, &foundation).unwrap();
    let train = fem_beam::Train::hslm_a(1);
    let speed = 0.8 * closed.critical_speed();
    let exact = closed.train_steady_state(speed, &train).unwrap();
    let spectrum = GroundedBeam::new(&case.beam, &foundation).unwrap().spectrum(speed).unwrap();
    let positions: Vec<f64> = (0..=800).map(|i| 30.0 - i as f64 * (train.length() + 60.0) / 800.0).collect();
    let largest = positions.iter().map(|&s| exact.deflection(s).abs()).fold(0.0, f64::max);
    let worst = positions
        .iter()
        .map(|&s| (spectrum.deflection_under(&train.axles, s) - exact.deflection(s)).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-5 * largest, "worst difference {:.1e} of the largest deflection", worst / largest);
}

mod on_the_ground {
    use analytic::ground::{GroundProfile, GroundedBeam, SoilLayer, SoilMaterial, StripGround};
    use analytic::quadrature::{Tolerance, integrate};
    use fem_beam::properties::Beam;
    use num_complex::Complex64;
    use std::f64::consts::PI;

    /// A soft site (a crust over soft clay over a half-space) under a 3 m strip.
    fn site() -> StripGround {
        let soil = |shear_wave_speed: f64, density: f64, damping_ratio: f64| SoilMaterial {
            shear_wave_speed,
            compression_wave_speed: 500.0,
            density,
            damping_ratio,
        };
        let layers = vec![
            SoilLayer { thickness: 1.1, material: soil(72.0, 1500.0, 0.04) },
            SoilLayer { thickness: 3.0, material: soil(41.0, 1260.0, 0.02) },
        ];
        StripGround { width: 3.0, profile: GroundProfile { layers, half_space: soil(90.0, 1475.0, 0.05) } }
    }

    /// A track-and-embankment beam: EI = 200 MN·m², 10 t/m, loss factor 0.1.
    fn embankment() -> Beam {
        Beam { youngs_modulus: 2e8, second_moment: 1.0, area: 1.0, density: 1e4, loss_factor: 0.1, ..Beam::default() }
    }

    /// At rest the deflection under the load is (1/π)∫₀^∞ dk/(EIk⁴ + k_eq(k, 0)): the same integral by adaptive
    /// Gauss–Kronrod directly over k ∈ [1e-7, 1e3] (breakpoints at decades, no sampled spectrum; below 1e-7 rad/m the
    /// stiffness method's F_zz loses digits as 1e-16/(k·depth), and the piece is ~1e-7 of the whole) agrees to 1e-6
    /// (the spectrum's cubic is good to 1e-6 of max|G| at its samples; its head and its tail add ≲ 1e-6).
    #[test]
    fn at_rest_the_deflection_is_the_direct_integral() {
        let ground = site();
        let beam = embankment();
        let spectrum = GroundedBeam::new(&beam, &ground).unwrap().spectrum(0.0).unwrap();
        let grounded = GroundedBeam::new(&beam, &ground).unwrap();
        let integrand = |k: f64| -grounded.response(k, 0.0).unwrap();
        let decades: Vec<f64> = (-6..=2).map(|e| 10f64.powi(e)).collect();
        let tolerance = Tolerance { relative: 1e-9, absolute: 0.0, max_intervals: 2000 };
        let direct = integrate(integrand, 1e-7, 1e3, &decades, tolerance);
        let (a, b) = (-spectrum.deflection(0.0), direct.value.re / PI);
        assert!(direct.converged && (a / b - 1.0).abs() < 1e-6, "{a:e} vs {b:e}");
        // Hysteretic damping, the beam's η as the ground's ξ, is iη sgn ω: at rest the beam and the ground are
        // elastic, G is real and the deflection symmetric (to the sampled spectrum's 1e-6).
        for k in [1e-3, 0.1, 0.5, 3.0] {
            assert_eq!(grounded.response(k, 0.0).unwrap().im, 0.0, "k = {k}");
        }
        for s in [0.5, 3.0, 10.0] {
            assert!((spectrum.deflection(s) - spectrum.deflection(-s)).abs() < 1e-6 * a, "s = {s}");
        }
    }

    /// The power the moving force puts in, P v W′(0) from the deflection's slope under the load (a central
    /// difference of the Fourier integral in s, step 1 mm: O(h²) ~ 1e-7), equals the power the beam's loss factor and
    /// the ground (its radiation and its soil's damping) take out, (P²v/π)∫₀^∞ k·(−Im D(k))·|G(k)|² dk by adaptive
    /// quadrature over k (not the sampled spectrum), to 1e-4 — at 40 m/s (below the site's waves) and 60 m/s (the
    /// wave behind the load) — each part positive.
    #[test]
    fn the_power_put_in_is_the_power_taken_out() {
        let ground = site();
        let beam = embankment();
        let grounded = GroundedBeam::new(&beam, &ground).unwrap();
        for speed in [40.0, 60.0] {
            let spectrum = grounded.spectrum(speed).unwrap();
            let h = 1e-3;
            let slope = (spectrum.deflection(h) - spectrum.deflection(-h)) / (2.0 * h);
            let put_in = speed * slope;
            // With D = −1/G = EI(1 − iη)k⁴ − ρAv²k² + conj(k_eq): the beam takes ηEIk⁴, the ground −Im D − ηEIk⁴.
            let taken_out = |k: f64| {
                let g = grounded.response(k, speed).unwrap();
                let loss = -(-1.0 / g).im;
                let beam_loss = beam.loss_factor * beam.bending_stiffness() * k.powi(4);
                Complex64::new(beam_loss, loss - beam_loss) * (k * g.norm_sqr())
            };
            let tolerance = Tolerance { relative: 1e-8, absolute: 0.0, max_intervals: 4000 };
            let decades: Vec<f64> = (-6..=2).map(|e| 10f64.powi(e)).collect();
            let out = integrate(taken_out, 1e-7, 1e3, &decades, tolerance).value * (speed / PI);
            let total = out.re + out.im;
            assert!((put_in / total - 1.0).abs() < 1e-4, "{speed} m/s: {put_in:e} in, {total:e} out");
            assert!(out.re > 0.0 && out.im > 0.0, "{speed} m/s: beam {:e}, ground {:e}", out.re, out.im);
        }
    }
}

/// A light beam on a homogeneous half-space resonates at the half-space's Rayleigh speed (Dieterman & Metrikine
/// 1996: as the beam's EI and mass vanish the critical speed tends to c_R; a finite beam lowers it slightly, damping
/// broadens the peak): the largest downward deflection at 0.99 c_R exceeds those at 0.95 and 1.03 c_R, which brackets
/// the critical speed within [0.95, 1.03]·c_R.
#[test]
fn a_light_beam_on_a_half_space_resonates_at_the_rayleigh_speed() {
    use analytic::ground::{GroundProfile, SoilMaterial, StripGround, rayleigh_phase_velocities};
    use fem_beam::properties::Beam;
    let soil =
        SoilMaterial { shear_wave_speed: 100.0, compression_wave_speed: 200.0, density: 1800.0, damping_ratio: 0.02 };
    let ground = StripGround { width: 3.0, profile: GroundProfile::half_space(soil) };
    let c_r = rayleigh_phase_velocities(&ground.profile, 10.0)[0];
    let beam = Beam { youngs_modulus: 1e7, second_moment: 1.0, area: 1.0, density: 1e3, ..Beam::default() };
    let grounded = GroundedBeam::new(&beam, &ground).unwrap();
    let peak = |share: f64| {
        let spectrum = grounded.spectrum(share * c_r).unwrap();
        (-300..=40).map(|j| -spectrum.deflection(j as f64 * 0.05)).fold(0.0, f64::max)
    };
    let (below, at, above) = (peak(0.95), peak(0.99), peak(1.03));
    assert!(at > below && at > above, "{below:e} {at:e} {above:e}");
}

/// A train's wave read from one load's wave on a 5 cm grid (`wave_under`, the cubic through the four nearest points)
/// is the direct superposition (`deflection_under`) to 1e-6 of the largest deflection — the grid's error, h⁴|W⁗|/40
/// on the bowls and h³/(20EI) per newton at the load's kink — for HSLM-A1 at 0.8 v_cr every 0.25 m along it (observed
/// 9.5e-8, on a rail whose bowl, ~3 m, is shorter than an embankment's).
#[test]
fn a_trains_wave_read_from_one_loads() {
    let case = uic60_on_soft_soil();
    let foundation = Foundation { damping: 0.1 * case.foundation.critical_damping(&case.beam), ..case.foundation };
    let speed = 0.8 * MovingBeam::new(&case.beam, &foundation).unwrap().critical_speed();
    let spectrum = GroundedBeam::new(&case.beam, &foundation).unwrap().spectrum(speed).unwrap();
    let train = fem_beam::Train::hslm_a(1);
    let positions: Vec<f64> = (0..=1200).map(|i| 30.0 - 0.25 * i as f64).collect();
    let read = spectrum.wave_under(&train.axles, &positions);
    let direct: Vec<f64> = positions.iter().map(|&s| spectrum.deflection_under(&train.axles, s)).collect();
    let largest = direct.iter().fold(0.0f64, |a, w| a.max(w.abs()));
    let worst = read.iter().zip(&direct).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(worst < 1e-6 * largest, "worst difference {:.1e} of the largest deflection", worst / largest);
}
