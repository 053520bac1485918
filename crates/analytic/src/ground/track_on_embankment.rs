//! The rail's support when it rests on pads, sleepers and ballast over an embankment beam on the ground — the
//! two-beam track (docs/theory.md §19). Per rail and per metre, for a wave e^{i(ωt − k_x x)} (the sleepers spread
//! over their spacing a, their long-wave twin):
//!
//! ```text
//! k_rail = k̃_p/a ∥ (−ω²m_s/a + k̃_b/a ∥ Z/2),      Z = EI_e(1 + iη_e)k_x⁴ − ρA_e ω² + k_ground(k_x, ω),
//! ```
//!
//! a ∥ b = ab/(a + b) (springs in series), k̃ = k(1 + iη sgn ω) + iωc each layer's dynamic stiffness per rail seat, and Z
//! the whole embankment on the whole strip, of which each rail carries half. Rigid pads and ballast make the rail,
//! the sleepers and the embankment one beam; a rigid embankment leaves the sleepers' twin on rigid ground.

use super::line_support::LineSupport;
use fem_beam::error::Result;
use fem_beam::sleepers::Sleepers;
use fem_beam::{Beam, BeamTheory, Foundation};
use num_complex::Complex64;

/// The embankment as a beam under the whole track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Embankment {
    /// EI_e (N·m²).
    pub bending_stiffness: f64,
    /// ρA_e (kg/m).
    pub mass_per_length: f64,
    /// η_e ≥ 0: EI_e → EI_e(1 + iη_e sgn ω) (ω ≥ 0, as the moving load asks: elastic at rest).
    pub loss_factor: f64,
}

impl Embankment {
    /// The whole track over this embankment in the long wave, as one beam: both rails (`rail` each) with their
    /// `sleepers` spread and the embankment moving together, EI = 2EI_r + EI_e, ρA = 2(ρA_r + m_s/a) + ρA_e, the
    /// embankment's loss factor — the pads and ballast far stiffer than the ground, as `rigid_layers_make_one_beam`
    /// (tests) shows. Its critical speed on the whole soil k_f is one rail's share (half of each) on k_f/2.
    pub fn whole_track(&self, rail: &Beam, sleepers: &Sleepers) -> Beam {
        Beam {
            youngs_modulus: 2.0 * rail.bending_stiffness() + self.bending_stiffness,
            second_moment: 1.0,
            area: 1.0,
            density: 2.0 * (rail.mass_per_length() + sleepers.mass_per_length()) + self.mass_per_length,
            theory: BeamTheory::EulerBernoulli,
            loss_factor: self.loss_factor,
        }
    }
}

/// One rail's support: its pads, sleepers and ballast (per rail seat) on half the embankment on half the ground.
#[derive(Debug, Clone, Copy)]
pub struct TrackOnEmbankment<'a, S: LineSupport + ?Sized> {
    /// Pads, sleeper mass and ballast per rail seat, and their spacing.
    pub sleepers: &'a Sleepers,
    /// The embankment under both rails.
    pub embankment: Embankment,
    /// What carries the embankment (the ground's strip).
    pub ground: &'a S,
}

impl<S: LineSupport + ?Sized> TrackOnEmbankment<'_, S> {
    /// Z/2 (N/m²): half the embankment on half the ground.
    pub(super) fn half_embankment(&self, kx: f64, omega: f64) -> Result<Complex64> {
        Ok(0.5 * (self.embankment_beam(kx, omega) + self.ground.line_stiffness(kx, omega)?))
    }

    /// A local operator near the one that maps a pair of forces across the ballast to what it does there,
    /// d = u_s − u_e — the Newton steps' preconditioner of the ballast's friction on a window of points `spacing` h
    /// (m) apart, whose short waves decide how many GMRES steps a Newton step takes. Quasi-statically a pair f (N/m)
    /// gives d = −f/(k_b + R ∥ S), R = k_p ∥ EI_r k_x⁴ what the rail holds the sleepers with through the pads and
    /// S = EI_e k_x⁴ + k_ground the embankment on the ground (per metre; k_p, k_b per rail seat over a): S is the
    /// stiffer in the short waves, so there d = −f/(k_b + R), which rises from k_b to k_b + k_p and no further where
    /// the pads are soft. Its twin, a beam (EI_l, ρA_l) on a Winkler foundation (k_l = k_b/a, c_l = c_b/a):
    /// k_l + EI_l k_x⁴ equal to k_b + R at rest and at the points' Nyquist wavenumber k_N = π/h,
    /// EI_l = φ EI_r with φ = k_p/(k_p + EI_r k_N⁴) — the rail itself over rigid pads (φ = 1), a bending of
    /// ≈ k_p (h/π)⁴ over soft ones — and the mass that moves with the sleepers, ρA_l = m_s/a + φ ρA_r. The section
    /// carries the rail's material (its bar wave √(E/ρ) the speed limit, as on the track). Measured at Ledsgård
    /// (X2000, 185 km/h, 2 kN/m; φ = 0.0018): 22 GMRES steps a Newton step, against 148 with the rail on k_b/a.
    pub fn local_across_ballast(&self, rail: &Beam, spacing: f64) -> (Beam, Foundation) {
        let a = self.sleepers.spacing;
        let pad = self.sleepers.pad.stiffness / a;
        let nyquist = std::f64::consts::PI / spacing;
        let share = pad / (pad + rail.bending_stiffness() * nyquist.powi(4));
        let mass = self.sleepers.mass / a + share * rail.mass_per_length();
        let beam = Beam {
            second_moment: share * rail.second_moment,
            area: mass / rail.density,
            theory: BeamTheory::EulerBernoulli,
            loss_factor: 0.0,
            ..*rail
        };
        (beam, Foundation::linear(self.sleepers.ballast.stiffness / a, self.sleepers.ballast.damping / a))
    }

    /// EI_e(1 + iη_e sgn ω)k_x⁴ − ρA_e ω² (N/m²): the whole embankment as a beam, without the ground.
    pub(super) fn embankment_beam(&self, kx: f64, omega: f64) -> Complex64 {
        let e = &self.embankment;
        let bending = e.bending_stiffness * kx.powi(4);
        let loss = if omega > 0.0 { e.loss_factor } else { 0.0 };
        Complex64::new(bending - e.mass_per_length * omega * omega, loss * bending)
    }
}

/// A layer's k(1 + iη sgn ω) + iωc: elastic at rest, as the ground is (`Layer::dynamic_stiffness` keeps iη at ω = 0,
/// the receptance's convention, where ω > 0).
pub(super) fn hysteretic(layer: &fem_beam::sleepers::Layer, omega: f64) -> Complex64 {
    match omega > 0.0 {
        true => layer.dynamic_stiffness(omega),
        false => Complex64::new(layer.stiffness, 0.0),
    }
}

/// a ∥ b = ab/(a + b).
fn series(a: Complex64, b: Complex64) -> Complex64 {
    a * b / (a + b)
}

impl<S: LineSupport + ?Sized> LineSupport for TrackOnEmbankment<'_, S> {
    fn line_stiffness(&self, kx: f64, omega: f64) -> Result<Complex64> {
        let a = self.sleepers.spacing;
        let pad = hysteretic(&self.sleepers.pad, omega) / a;
        let ballast = hysteretic(&self.sleepers.ballast, omega) / a;
        let sleeper = Complex64::new(-omega * omega * self.sleepers.mass / a, 0.0);
        Ok(series(pad, sleeper + series(ballast, self.half_embankment(kx, omega)?)))
    }

    /// Ten times the pad's |k̃_p|/a, and the sleepers' inertia ω²m_s/a: the series never exceeds |k̃_p|/a at rest,
    /// and where the sleeper's mass resonates between the pad and what is below it reaches |k̃_p|²/Im k̃_p — within
    /// ten times |k̃_p| for pads damped by 10 % or more at that frequency (the typical pad's 30 kN·s/m is 25 % at
    /// the rail-on-pad resonance near 400 Hz). The embankment and the ground below never raise it.
    fn stiffness_bound(&self, _kx: f64, omega: f64) -> f64 {
        let a = self.sleepers.spacing;
        10.0 * self.sleepers.pad.dynamic_stiffness(omega).norm() / a + omega * omega * self.sleepers.mass / a
    }
}
