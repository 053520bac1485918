//! A foundation fitted to a line support along the moving load's line (`GroundedBeam::fitted_foundation`, docs/theory.md
//! §19): exact where the support is a spring and a dashpot; on the ground its error is what the waves say, measured
//! again here by the closed form; good below the ground's critical speed, not at it.

use analytic::MovingBeam;
use analytic::ground::{GroundProfile, GroundedBeam, SoilLayer, SoilMaterial, StripGround};
use fem_beam::properties::{Beam, Foundation};

/// The composite beam of the soft-ground example: EI = 200 MN·m², 10 t/m.
fn embankment(loss_factor: f64) -> Beam {
    Beam { youngs_modulus: 2e8, second_moment: 1.0, area: 1.0, density: 1e4, loss_factor, ..Beam::default() }
}

/// The soft-ground example's site: 1.5 m of crust over 4 m of soft clay on a stiffer half-space.
fn site() -> StripGround {
    let soil = |shear_wave_speed: f64, poisson: f64, density: f64, damping_ratio: f64| SoilMaterial {
        shear_wave_speed,
        compression_wave_speed: shear_wave_speed * (2.0 * (1.0 - poisson) / (1.0 - 2.0 * poisson)).sqrt(),
        density,
        damping_ratio,
    };
    let layers = vec![
        SoilLayer { thickness: 1.5, material: soil(70.0, 0.45, 1500.0, 0.04) },
        SoilLayer { thickness: 4.0, material: soil(45.0, 0.48, 1300.0, 0.03) },
    ];
    StripGround { width: 3.0, profile: GroundProfile { layers, half_space: soil(110.0, 0.45, 1700.0, 0.05) } }
}

/// On a spring and a dashpot the fit is the spring and the dashpot (to 1e-9: the least squares of exact data) with no
/// mass, and its wave the exact one (the same spectrum twice: 1e-12), below and above the critical speed.
#[test]
fn a_spring_and_a_dashpot_are_fitted_exactly() {
    let beam = embankment(0.0);
    let winkler = Foundation::linear(1.2e7, 1.0e5);
    let grounded = GroundedBeam::new(&beam, &winkler).unwrap();
    for speed in [20.0, 60.0, 110.0] {
        let fit = grounded.fitted_foundation(speed).unwrap();
        assert!((fit.stiffness / winkler.stiffness - 1.0).abs() < 1e-9, "{fit:?}");
        assert!((fit.damping / winkler.damping - 1.0).abs() < 1e-9, "{fit:?}");
        assert!(fit.co_vibrating_mass < 1e-9 * beam.mass_per_length(), "{fit:?}");
        assert!(fit.wave_error < 1e-12 && fit.peak_error.abs() < 1e-12, "{fit:?}");
    }
}

/// The error the fit reports is the waves' own: the fitted beam's wave by Frýba's closed form (`MovingBeam`, an
/// independent method) against the exact one on the ground, on the same points, agrees with the reported error to
/// 1e-4 of it (the Fourier integral's 1e-6 of w₀ on each wave). Below the ground's critical speed (61.37 m/s on this
/// site) the fit is good — within 6 % of the peak at rest, 20 and 40 m/s (observed 5.0, 4.5 and 2.7 %; at rest one
/// spring cannot follow the static strip's stiffness, which grows with k_x) — and at it, it is not:
/// over 20 % (observed 32 %), the ground's waves being no spring's; the run warns above 10 %.
#[test]
fn the_fit_on_the_ground_and_its_error() {
    let (beam, strip) = (embankment(0.1), site());
    let grounded = GroundedBeam::new(&beam, &strip).unwrap();
    for (speed, within) in [(0.0, 0.06), (20.0, 0.06), (40.0, 0.06), (61.37, f64::INFINITY)] {
        let fit = grounded.fitted_foundation(speed).unwrap();
        let exact = grounded.spectrum(speed).unwrap();
        let fitted_beam = Beam { density: beam.density + fit.co_vibrating_mass / beam.area, loss_factor: 0.0, ..beam };
        let closed = MovingBeam::new(&fitted_beam, &Foundation::linear(fit.stiffness, fit.damping)).unwrap();
        let closed = closed.steady_state(speed, 1.0).unwrap();
        let positions = (0..=480).map(|i| -60.0 + 0.25 * i as f64);
        let (mut largest, mut difference) = (0.0f64, 0.0f64);
        for s in positions {
            let w = exact.deflection(s);
            largest = largest.max(w.abs());
            difference = difference.max((closed.deflection(s) - w).abs());
        }
        let measured = difference / largest;
        assert!((measured - fit.wave_error).abs() < 1e-4 * fit.wave_error, "{speed}: {measured} vs {fit:?}");
        assert!(fit.wave_error < within, "{speed}: {fit:?}");
        if within.is_infinite() {
            assert!(fit.wave_error > 0.2, "at the critical speed: {fit:?}");
        }
        assert!(fit.stiffness > 0.0 && fit.damping >= 0.0 && fit.co_vibrating_mass >= 0.0);
        // The wavenumbers carrying the response: around the beam's on the ground, (k_w/4EI)^¼ ≈ 0.5 rad/m here.
        assert!(0.0 < fit.wavenumbers.0 && fit.wavenumbers.0 < 0.5 && 0.3 < fit.wavenumbers.1, "{fit:?}");
        assert!(fit.wavenumbers.1 < 3.0, "{fit:?}");
        assert!(speed > 0.0 || (fit.damping == 0.0 && fit.co_vibrating_mass == 0.0));
    }
}

/// Ledsgård's two-beam track per rail (examples/ledsgard/ledsgard-two-beam.toml): pads 120 MN/m, 20 kN·s/m; sleepers
/// 125 kg every 0.65 m; ballast 140 MN/m, 80 kN·s/m; the embankment EI_e = 200 MN·m², 7.56 t/m, η_e = 0.1.
fn two_beam_sleepers() -> fem_beam::sleepers::Sleepers {
    use fem_beam::sleepers::{Layer, Sleepers};
    Sleepers {
        spacing: 0.65,
        first: 0.325,
        mass: 125.0,
        pad: Layer { stiffness: 1.2e8, damping: 2.0e4, loss_factor: 0.0 },
        ballast: Layer { stiffness: 1.4e8, damping: 8.0e4, loss_factor: 0.0 },
        ..Sleepers::default()
    }
}

/// The two-beam track's ground fitted to what the rail feels (`TrackOnEmbankment::fitted_ground`): on a spring and
/// a dashpot under an elastic embankment it is that spring and dashpot with no mass (1e-9) and the rail's wave the
/// exact one (1e-12, the same spectrum twice); an embankment's loss factor goes into the dashpot (the fitted c then
/// exceeds the soil's).
#[test]
fn the_two_beam_tracks_ground_on_a_spring_is_that_spring() {
    use analytic::ground::{Embankment, TrackOnEmbankment};
    let sleepers = two_beam_sleepers();
    let winkler = Foundation::linear(2.4e7, 2.0e5);
    let elastic = Embankment { bending_stiffness: 2e8, mass_per_length: 7560.0, loss_factor: 0.0 };
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment: elastic, ground: &winkler };
    for speed in [0.0, 30.0, 60.0] {
        let fit = track.fitted_ground(&Beam::default(), speed).unwrap();
        assert!((fit.stiffness / winkler.stiffness - 1.0).abs() < 1e-9, "{speed}: {fit:?}");
        if speed > 0.0 {
            assert!((fit.damping / winkler.damping - 1.0).abs() < 1e-9, "{speed}: {fit:?}");
        }
        assert!(fit.co_vibrating_mass < 1e-6, "{speed}: {fit:?}");
        assert!(fit.wave_error < 1e-12 && fit.peak_error.abs() < 1e-12, "{speed}: {fit:?}");
    }
    let lossy = Embankment { loss_factor: 0.1, ..elastic };
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment: lossy, ground: &winkler };
    let fit = track.fitted_ground(&Beam::default(), 30.0).unwrap();
    assert!(fit.damping > 1.05 * winkler.damping, "{fit:?}");
}

/// On Ledsgård's layered site (ledsgard.toml's profile) the two-beam track's fitted ground at 70 and 185 km/h: its
/// error measured, not assumed. Observed: the rail's wave within 3.7 % at 70 km/h (k_f = 8.6 MN/m², c = 172 kN·s/m²,
/// no mass) and 6.3 % at 185 km/h (7.95 MN/m², 98.6 kN·s/m², 11.8 t/m), the peak 2.9 and 4.2 % deeper; bounded at
/// 5 and 8 % (the observed values and a third), below the 10 % where a run warns.
#[test]
fn the_two_beam_tracks_ground_at_ledsgard() {
    use analytic::ground::{Embankment, TrackOnEmbankment};
    let soil =
        |thickness: f64, shear_wave_speed: f64, compression_wave_speed: f64, density: f64, damping_ratio: f64| {
            SoilLayer {
                thickness,
                material: SoilMaterial { shear_wave_speed, compression_wave_speed, density, damping_ratio },
            }
        };
    let layers = vec![
        soil(1.1, 72.0, 500.0, 1500.0, 0.04),
        soil(3.0, 40.0, 500.0, 1260.0, 0.02),
        soil(4.5, 53.0, 1500.0, 1475.0, 0.05),
        soil(6.0, 82.0, 1500.0, 1475.0, 0.05),
    ];
    let half_space =
        SoilMaterial { shear_wave_speed: 100.0, compression_wave_speed: 1500.0, density: 1475.0, damping_ratio: 0.05 };
    let strip = StripGround { width: 3.0, profile: GroundProfile { layers, half_space } };
    let sleepers = two_beam_sleepers();
    let embankment = Embankment { bending_stiffness: 2e8, mass_per_length: 7560.0, loss_factor: 0.1 };
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &strip };
    for (speed, within) in [(70.0 / 3.6, 0.05), (185.0 / 3.6, 0.08)] {
        let fit = track.fitted_ground(&Beam::default(), speed).unwrap();
        assert!(fit.stiffness > 0.0 && fit.damping > 0.0 && fit.co_vibrating_mass >= 0.0, "{fit:?}");
        assert!(fit.wave_error > 0.0 && fit.wave_error < within && fit.peak_error.abs() < within, "{fit:?}");
    }
}
