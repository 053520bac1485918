//! The two-beam track as the rail's line support (`TrackOnEmbankment`, docs/theory.md §19): its two limits — rigid
//! pads and ballast make one composite beam; a rigid embankment leaves the sleepers' twin on rigid ground — and its
//! passivity.

use analytic::ground::{Embankment, GroundedBeam, LineSupport, TrackOnEmbankment};
use fem_beam::error::Result;
use fem_beam::properties::{Beam, Foundation};
use fem_beam::sleepers::{Layer, Sleepers};
use num_complex::Complex64;

/// Half of a support: what one rail of two stands on.
struct Half<'a>(&'a dyn LineSupport);

impl LineSupport for Half<'_> {
    fn line_stiffness(&self, kx: f64, omega: f64) -> Result<Complex64> {
        Ok(0.5 * self.0.line_stiffness(kx, omega)?)
    }
    fn stiffness_bound(&self, kx: f64, omega: f64) -> f64 {
        0.5 * self.0.stiffness_bound(kx, omega)
    }
}

const EMBANKMENT: Embankment = Embankment { bending_stiffness: 2e8, mass_per_length: 7560.0, loss_factor: 0.1 };

/// A UIC60 rail with the embankment's loss factor.
fn rail() -> Beam {
    Beam { loss_factor: 0.1, ..Beam::default() }
}

/// With pads and ballast of 1e14 N/m (1e6 times the typical) and massless sleepers the rail moves with the
/// embankment: the rail on the two-beam track is one beam of EI_r + EI_e/2 and ρA_r + ρA_e/2 on half the support,
/// to 1e-5 of the largest deflection at rest, 30 and 60 m/s (the layers' compliance against half an embankment of
/// 20 MN·m², 1e7·k⁴ N/m², is 1e-7 at k = 1 rad/m and 1e-3 at 10 rad/m, where little of the wave is).
#[test]
fn rigid_layers_make_one_beam() {
    let ground = Foundation::linear(2e7, 3e5);
    let rigid = Layer { stiffness: 1e14, damping: 0.0, loss_factor: 0.0 };
    let sleepers = Sleepers { mass: 0.0, pad: rigid, ballast: rigid, ..Sleepers::default() };
    let embankment = Embankment { bending_stiffness: 2e7, ..EMBANKMENT };
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &ground };
    let rail = rail();
    let composite = Beam {
        youngs_modulus: 1.0,
        second_moment: rail.bending_stiffness() + 0.5 * embankment.bending_stiffness,
        area: 1.0,
        density: rail.mass_per_length() + 0.5 * embankment.mass_per_length,
        ..rail
    };
    let half = Half(&ground);
    for speed in [0.0, 30.0, 60.0] {
        let two_beams = GroundedBeam::new(&rail, &track).unwrap().spectrum(speed).unwrap();
        let one_beam = GroundedBeam::new(&composite, &half).unwrap().spectrum(speed).unwrap();
        let largest = one_beam.deflection(0.0).abs();
        for s in [-20.0, -5.0, -1.0, 0.0, 1.0, 5.0, 20.0] {
            let difference = (two_beams.deflection(s) - one_beam.deflection(s)).abs();
            assert!(difference < 1e-5 * largest, "{speed} m/s, s = {s}: {difference:e} of {largest:e}");
        }
    }
}

/// On an embankment 1e12 times stiffer than the track the rail's support is the sleepers' long-wave twin on rigid
/// ground (`Sleepers::dynamic_stiffness_per_metre`, written independently) to 1e-9, at any wavenumber and frequency.
#[test]
fn a_rigid_embankment_leaves_the_sleepers_twin() {
    let rigid = Foundation::linear(1e22, 0.0);
    let sleepers = Sleepers::default();
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment: EMBANKMENT, ground: &rigid };
    for (kx, omega) in [(0.01, 0.0), (0.5, 30.0), (2.0, 600.0), (10.0, 3000.0)] {
        let expected = sleepers.dynamic_stiffness_per_metre(omega);
        let got = track.line_stiffness(kx, omega).unwrap();
        assert!((got - expected).norm() < 1e-9 * expected.norm(), "({kx}, {omega}): {got} vs {expected}");
    }
}

/// A damped track is passive: Im k_rail > 0 at every ω > 0 (it takes energy from a wave), and real at rest but for
/// the embankment's loss factor; its bound holds (|k_rail| ≤ the bound) with the typical pads' damping.
#[test]
fn the_two_beam_track_is_passive() {
    let ground = Foundation::linear(2e7, 3e5);
    let sleepers = Sleepers::default();
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment: EMBANKMENT, ground: &ground };
    for i in 0..40 {
        let kx = 0.01 * 1.3f64.powi(i);
        for omega in [1.0, 50.0, 400.0, 2000.0] {
            let k = track.line_stiffness(kx, omega).unwrap();
            assert!(k.im > 0.0, "({kx}, {omega}): {k}");
            assert!(k.norm() <= track.stiffness_bound(kx, omega), "({kx}, {omega}): {k}");
        }
    }
}

/// The rail's point receptance on the two-beam track over a rigid embankment is the rail's on the sleepers' twin on
/// rigid ground: the integral over k (`GroundedBeam::point_receptance`, adaptive Gauss–Kronrod to 1e-7) against the
/// closed form of a beam on a complex spring (`dispersion::point_receptance`, Knothe & Grassie's 1/(8EIλ³)), to
/// 1e-6 of |α| at 10 Hz – 1 kHz (through the rail-on-ballast and the pad resonances).
#[test]
fn the_receptance_over_a_rigid_embankment_is_the_rail_on_the_sleepers_twin() {
    let rigid = Foundation::linear(1e22, 0.0);
    let sleepers = Sleepers::default();
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment: EMBANKMENT, ground: &rigid };
    let rail = rail();
    let grounded = GroundedBeam::new(&rail, &track).unwrap();
    for frequency in [10.0, 50.0, 100.0, 300.0, 1000.0] {
        let omega = std::f64::consts::TAU * frequency;
        let integral = grounded.point_receptance(omega, &[]).unwrap();
        let support = sleepers.dynamic_stiffness_per_metre(omega);
        let closed = analytic::dispersion::point_receptance(&rail, support, rail.loss_factor, omega);
        assert!((integral - closed).norm() < 1e-6 * closed.norm(), "{frequency} Hz: {integral} vs {closed}");
    }
}

/// The friction's preconditioner across the ballast (`local_across_ballast`) is built to equal what a pair across
/// the ballast meets in the short waves, k_b/a + (k_p/a ∥ EI_r k_x⁴), at rest and at the points' Nyquist
/// wavenumber π/h: k_l + EI_l k_x⁴ does at both to round-off (1e-12), for the typical pads (then φ = 0.2 % of the
/// rail bends with the sleepers at h = 0.25 m) and for pads 5e11 times as stiff (the rail itself on the ballast: its
/// EI_r, and its mass with the sleepers', to 1e-6 — φ = 1 − 4e-8 at h = 0.1 m).
#[test]
fn the_local_twin_across_the_ballast_meets_the_pairs_support_at_rest_and_at_nyquist() {
    let ground = Foundation::linear(2e7, 3e5);
    let typical = Sleepers::default();
    let rigid_pads = Sleepers { pad: Layer { stiffness: 1e20, ..typical.pad }, ..Sleepers::default() };
    let rail = rail();
    for (sleepers, spacing) in [(&typical, 0.25), (&rigid_pads, 0.1)] {
        let track = TrackOnEmbankment { sleepers, embankment: EMBANKMENT, ground: &ground };
        let (beam, foundation) = track.local_across_ballast(&rail, spacing);
        let a = sleepers.spacing;
        let (pad, ballast) = (sleepers.pad.stiffness / a, sleepers.ballast.stiffness / a);
        assert_eq!((foundation.stiffness, foundation.damping), (ballast, sleepers.ballast.damping / a));
        let nyquist = std::f64::consts::PI / spacing;
        let bending = rail.bending_stiffness() * nyquist.powi(4);
        let support = ballast + pad * bending / (pad + bending);
        let twin = foundation.stiffness + beam.bending_stiffness() * nyquist.powi(4);
        assert!((twin - support).abs() <= 1e-12 * support, "h = {spacing}: {twin} vs {support}");
        assert!(beam.wave_speed_limit() == rail.wave_speed_limit(), "the rail's material");
        if sleepers.pad.stiffness > 1e19 {
            assert!((beam.bending_stiffness() / rail.bending_stiffness() - 1.0).abs() < 1e-6);
            let mass = sleepers.mass / a + rail.mass_per_length();
            assert!((beam.mass_per_length() / mass - 1.0).abs() < 1e-6);
        } else {
            let share = beam.bending_stiffness() / rail.bending_stiffness();
            assert!(share > 1e-3 && share < 3e-3, "φ = {share}");
        }
    }
}

/// The finite-element two-beam track of the next two tests: a UIC60 rail on sleepers every 0.2 m (Ledsgård's layers
/// per metre, with their dashpots where `damped`) over half of Ledsgård's embankment on half of a 8.6 MN/m² soil
/// (c = 172 kN·s/m² where damped), 200 m pinned at both ends, 0.1 m elements; and the same track for the moving
/// frame (the sleepers spread).
fn finite_two_beam_track(damped: bool) -> (fem_beam::BeamModel, Sleepers, Embankment, Foundation) {
    use fem_beam::{BeamModel, EmbankmentBeam, Mesh, Supports};
    let spacing = 0.2;
    let per_seat = spacing / 0.65;
    let on = if damped { 1.0 } else { 0.0 };
    let layer = |stiffness: f64, damping: f64| Layer {
        stiffness: stiffness * per_seat,
        damping: on * damping * per_seat,
        loss_factor: 0.0,
    };
    let sleepers = Sleepers {
        spacing,
        first: 0.1,
        mass: 125.0 * per_seat,
        pad: layer(1.2e8, 2.0e4),
        ballast: layer(1.4e8, 8.0e4),
        ..Sleepers::default()
    };
    let soil = Foundation::linear(8.6e6, on * 1.72e5);
    let embankment = Embankment { loss_factor: 0.0, ..EMBANKMENT };
    let mesh = Mesh::new(200.0, 2000).unwrap();
    let share = EmbankmentBeam::new(
        0.5 * embankment.bending_stiffness,
        0.5 * embankment.mass_per_length,
        0.0,
        Foundation::linear(0.5 * soil.stiffness, 0.5 * soil.damping),
        vec![0.5 * soil.damping; mesh.elements],
    )
    .unwrap();
    let model = BeamModel::new(Beam::default(), Foundation::linear(0.0, 0.0), mesh, Supports::default())
        .unwrap()
        .with_sleepers_on_embankment(sleepers.clone(), share)
        .unwrap();
    (model, sleepers, embankment, soil)
}

/// The finite-element two-beam track (`BeamModel::with_sleepers_on_embankment`: the rail on discrete sleepers whose
/// ballast rests on a second Hermite beam, half the embankment, on half the soil) against the moving-frame solution
/// at rest (`TrackOnEmbankment`, the sleepers spread): a 100 kN force on a sleeper in the middle of the track of
/// [`finite_two_beam_track`], undamped, with sleepers every 0.2 m so that the spread twin holds. The rail's deflection under
/// the force and 5 m away (where the embankment carries the wave) agree to 1e-4 of the largest (observed 6.3e-6 and
/// 1.4e-8: what is left is the sleepers' discreteness under the force).
#[test]
fn the_finite_element_two_beam_track_at_rest_is_the_moving_frames() {
    let (model, sleepers, embankment, soil) = finite_two_beam_track(false);
    let (rail, mesh) = (*model.beam(), *model.mesh());
    let x0 = 100.1;
    let force = -1e5;
    let q =
        model.static_solve(&fem_beam::LoadVector::point_force(&model.discretisation(), x0, force).unwrap()).unwrap();
    let node = (x0 / mesh.element_length()).round() as usize;
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &soil };
    let exact = GroundedBeam::new(&rail, &track).unwrap().spectrum(0.0).unwrap();
    let largest = exact.deflection(0.0).abs();
    for offset in [0.0, 5.0] {
        let fe = q[2 * (node + (offset / mesh.element_length()).round() as usize)];
        let moving_frame = -force * exact.deflection(offset);
        let difference = (fe - moving_frame).abs() / (-force * largest);
        assert!(difference < 1e-4, "rail at {offset} m: FE {fe:e}, moving frame {moving_frame:e}");
    }
}

/// The finite-element two-beam track's receptance (`FrequencyResponse`, the embankment's elements in the dynamic
/// stiffness) against the moving frame's (`GroundedBeam::point_receptance` on `TrackOnEmbankment`, the sleepers
/// spread): the damped track of [`finite_two_beam_track`] driven on a sleeper in its middle at 5, 20 and 60 Hz — the
/// embankment bouncing on the soil, and the rail on its sleepers above — agree to 5e-3 (observed 5.5e-6, 5.4e-4 and
/// 1.9e-3, growing with frequency: the sleepers' discreteness, and what the pinned ends 100 m away reflect).
#[test]
fn the_finite_element_two_beam_receptance_is_the_moving_frames() {
    let (model, sleepers, embankment, soil) = finite_two_beam_track(true);
    let track = TrackOnEmbankment { sleepers: &sleepers, embankment, ground: &soil };
    let exact = GroundedBeam::new(model.beam(), &track).unwrap();
    let response = fem_beam::receptance::FrequencyResponse::new(&model);
    for hz in [5.0, 20.0, 60.0] {
        let omega = std::f64::consts::TAU * hz;
        let fe = response.receptance(omega, 100.1, &[100.1]).unwrap()[0];
        let moving_frame = exact.point_receptance(omega, &[]).unwrap();
        let difference = (fe - moving_frame).norm() / moving_frame.norm();
        assert!(difference < 5e-3, "{hz} Hz: FE {fe}, moving frame {moving_frame}");
    }
}
