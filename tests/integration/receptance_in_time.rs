//! The receptance against the same track struck in time (docs/theory.md §17): a short force pulse at mid-track,
//! the Moreau–Jean θ-method (θ = ½, no interactions: the trapezoidal rule) stepping the model's own M, C, K, and the
//! ratio of the Fourier transforms of the response and the force — two independent methods on one model.

use fem_beam::receptance::FrequencyResponse;
use nscd::solver::SolverSettings;
use nscd::stepper::Integration;
use nscd::{Forcing, MoreauJean};
use num_complex::Complex64;
use std::f64::consts::{PI, TAU};

/// F(t) = P sin²(πt/T) for 0 ≤ t ≤ T on one free DOF: a pulse whose spectrum is smooth up to ~2/T.
struct Pulse {
    dof: usize,
    amplitude: f64,
    duration: f64,
}

impl Pulse {
    fn at(&self, t: f64) -> f64 {
        if (0.0..=self.duration).contains(&t) { self.amplitude * (PI * t / self.duration).sin().powi(2) } else { 0.0 }
    }
}

impl Forcing for Pulse {
    fn add_to(&self, time: f64, scale: f64, out: &mut [f64]) {
        out[self.dof] += scale * self.at(time);
    }
    fn power(&self, time: f64, v: &[f64]) -> f64 {
        self.at(time) * v[self.dof]
    }
}

/// The reference rail on its soil with ζ = 0.2 and 40 m absorbing zones (viscous damping only: a run in time has no
/// loss factors), struck at 100 m by a 10 ms pulse and stepped for 2 s at h = 0.1 ms: |H − α| ≤ 0.5 % of |α| at
/// 5, 10.3 (the resonance), 20, 50 and 100 Hz (measured 4.0e-7, 1.3e-5, 2.6e-5, 1.5e-4, 1.2e-3). The trapezoidal
/// rule's and the sampled Fourier sums' errors are O((ωh)²), 4e-3 at 100 Hz; the response has died away long
/// before 2 s (the sums end with it). The issue asked for 1 %.
#[test]
fn the_receptance_is_the_struck_tracks_response() {
    let text =
        "[mesh]\nelements = 800\n[foundation]\ndamping_ratio = 0.2\n[foundation.absorbing_zones]\nlength = 40.0\n";
    let model = scenario::Scenario::from_toml(text, "struck").unwrap().model().unwrap();
    let dof = model.dofs().free_index(2 * model.mesh().nearest_node(100.0).unwrap()).unwrap();
    let pulse = Pulse { dof, amplitude: 1e4, duration: 0.01 };
    let h = 1e-4;
    let system = track::system::beam_system(&model);
    let n = model.dofs().free_len();
    let none = track::PlacedInteractions::new();
    let integration = Integration::theta(0.5, h);
    let mut stepper = MoreauJean::build(
        &system,
        none.interactions().clone(),
        integration,
        &SolverSettings::default(),
        vec![0.0; n],
        vec![0.0; n],
    )
    .unwrap();
    let steps = 20_000;
    let mut response = Vec::with_capacity(steps + 1);
    response.push(0.0);
    for _ in 0..steps {
        stepper.step(&pulse).unwrap();
        response.push(stepper.q()[dof]);
    }
    let frequency_response = FrequencyResponse::new(&model);
    for f in [5.0, 10.3, 20.0, 50.0, 100.0] {
        let omega = TAU * f;
        // Trapezoidal Fourier sums of the samples at t_k = k h (both end at zero).
        let transform = |values: &dyn Fn(usize) -> f64| -> Complex64 {
            (0..=steps).map(|k| values(k) * Complex64::from_polar(h, -omega * k as f64 * h)).sum()
        };
        let (w, force) = (transform(&|k| response[k]), transform(&|k| pulse.at(k as f64 * h)));
        let measured = w / force;
        let alpha = frequency_response.receptance(omega, 100.0, &[100.0]).unwrap()[0];
        let error = (measured - alpha).norm() / alpha.norm();
        assert!(error < 5e-3, "{f} Hz: in time {measured}, receptance {alpha} ({error:e})");
    }
}
