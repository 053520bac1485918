//! The two-beam track's interface between the sleepers and the embankment, in the moving frame (docs/theory.md §19,
//! "Lift-off on the ground"): what a tensionless ballast needs beyond the rail's own wave. Per rail and per metre, with
//! the sleepers spread as their long-wave twin, the rail u_r, the sleepers u_s and half the embankment u_e carry a
//! wave e^{i(ωt − k_x x)} through the symmetric dynamic stiffness
//!
//! ```text
//!     ⎡ B_r + k̃_p    −k̃_p                    0        ⎤      B_r = EI(1 + iη)k_x⁴ − ρAω²,
//! D = ⎢ −k̃_p         k̃_p + k̃_b − ω²m_s/a     −k̃_b     ⎥      k̃_p, k̃_b the pad's and the ballast's per metre (÷ a),
//!     ⎣ 0            −k̃_b                    k̃_b + Z/2 ⎦      Z/2 half the embankment on half the ground,
//! ```
//!
//! the moving frame taking D's conjugate at ω = k v ([`super::moving_load`]). With H = D⁻¹ and the relative
//! deflection d = u_s − u_e (negative where the ballast is pressed), four spectra answer, each upward per downward
//! newton: the rail per rail load (H_rr, the rail's own wave of [`GroundedBeam::spectrum`]), d per rail load
//! (H_sr − H_er), and — per newton of a **pair** of forces across the ballast (down on the sleepers, up on the
//! embankment, spread as a hat of half-width h around its point) — d (H_ss − 2H_se + H_ee) and the rail (H_rs − H_re),
//! each times the hat's transform h·sinc²(k_x h/2). The hat matters: the sleeper layer has no bending stiffness, so a
//! pair at one point is a delta at rest and a kink ~v/√(k_b/m_s) wide (a few cm) at speed, which the window's points
//! could not resolve; a force piecewise linear between the points is integrated exactly.

use super::line_support::LineSupport;
use super::moving_load::{GroundedBeam, MovingSpectrum, sample_channels};
use super::track_on_embankment::{TrackOnEmbankment, hysteretic};
use fem_beam::error::Result;
use num_complex::Complex64;

/// The moving frame's spectra of the two-beam track at one speed, on one window's point spacing.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceSpectra {
    /// The rail's deflection per newton on the rail (m/N).
    pub rail: MovingSpectrum,
    /// The sleepers' deflection less the embankment's, d, per newton on the rail (m/N).
    pub relative: MovingSpectrum,
    /// d per newton of a pair across the ballast spread as a hat of half-width `spacing` (m/N).
    pub pair_relative: MovingSpectrum,
    /// The rail's deflection per newton of that pair (m/N).
    pub pair_rail: MovingSpectrum,
    /// The hat's half-width h (m): the points' spacing.
    pub spacing: f64,
}

impl<S: LineSupport + ?Sized> GroundedBeam<'_, TrackOnEmbankment<'_, S>> {
    /// The four spectra at `speed` (m/s, ≥ 0) for pairs spread over `spacing` (m, > 0), sampled together on the rail's
    /// wavenumber range.
    pub fn interface_spectra(&self, speed: f64, spacing: f64) -> Result<InterfaceSpectra> {
        let channels = |k: f64| -> Result<[Complex64; 4]> {
            let h = self.flexibility(k, k * speed)?;
            let hat = spacing * sinc(0.5 * k * spacing).powi(2);
            let (r, s, e) = (0, 1, 2);
            Ok([
                -h[r][r],
                -(h[s][r] - h[e][r]),
                -hat * (h[s][s] - h[s][e] - h[e][s] + h[e][e]),
                -hat * (h[r][s] - h[r][e]),
            ])
        };
        let [rail, relative, pair_relative, pair_rail] = sample_channels(self.range(speed), speed, &channels)?;
        Ok(InterfaceSpectra { rail, relative, pair_relative, pair_rail, spacing })
    }

    /// H = D⁻¹ of the moving frame at (`k`, `omega` = k v): D conjugated (see the module doc), the ground left out of
    /// Z where the embankment's EI_e k⁴ is 1e4 times its bound (as the rail's spectrum leaves its support out).
    fn flexibility(&self, k: f64, omega: f64) -> Result<[[Complex64; 3]; 3]> {
        let track = self.support;
        let a = track.sleepers.spacing;
        let loss = if omega > 0.0 { self.loss_factor } else { 0.0 };
        let bending = self.bending_stiffness * k.powi(4);
        let rail = Complex64::new(bending - self.mass_per_length * omega * omega, loss * bending);
        let pad = hysteretic(&track.sleepers.pad, omega) / a;
        let ballast = hysteretic(&track.sleepers.ballast, omega) / a;
        let sleeper = -omega * omega * track.sleepers.mass / a;
        let embankment = track.embankment.bending_stiffness * k.powi(4);
        let half = match embankment > 1e4 * track.ground.stiffness_bound(k, omega) {
            true => 0.5 * track.embankment_beam(k, omega),
            false => track.half_embankment(k, omega)?,
        };
        let zero = Complex64::new(0.0, 0.0);
        let d = [[rail + pad, -pad, zero], [-pad, pad + ballast + sleeper, -ballast], [zero, -ballast, ballast + half]]
            .map(|row| row.map(|x| x.conj()));
        Ok(inverse(&d))
    }
}

/// sin x / x.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 { 1.0 - x * x / 6.0 } else { x.sin() / x }
}

/// The inverse of a 3 × 3 complex matrix by its adjugate (D is well conditioned where it is sampled: its diagonal
/// holds the pad's and the ballast's stiffness at every k).
fn inverse(d: &[[Complex64; 3]; 3]) -> [[Complex64; 3]; 3] {
    let cofactor = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        d[r0][c0] * d[r1][c1] - d[r0][c1] * d[r1][c0]
    };
    let det = d[0][0] * cofactor(0, 0) + d[0][1] * cofactor(0, 1) + d[0][2] * cofactor(0, 2);
    std::array::from_fn(|i| std::array::from_fn(|j| cofactor(j, i) / det))
}
