//! The Rayleigh modes of a layered ground (docs/theory.md §19): the free waves its surface carries, at phase
//! velocities c where the surface stiffness is singular, det K(ω/c, ω) = 0, on the elastic profile (damping set
//! aside: a dispersion curve is the undamped profile's). Only the trapped modes are found, those slower than the
//! half-space's shear wave (faster ones leak into it and have complex wavenumbers); the fundamental mode is the
//! slowest at a given frequency.
//!
//! At such c, with the horizontal DOF's factor i taken out, every stiffness block is real. det K of the surface alone
//! has poles too (where a condensation step is singular) and, for a mode trapped in a soft layer under a stiff crust,
//! a pole right beside its root: a scan would see no sign change. The determinant of the whole layered system's
//! stiffness, det K_surface·Π det(K₂₂ + K_below) over the condensation's pivots (Schur's formula), has the roots
//! without the poles; its sign alone brackets the modes (it does not change with the sublayering: no sublayer has a
//! clamped mode below ω, the Wittrick–Williams count), and bisection on the sign narrows each to round-off.

use super::flexibility::condensed;
use super::profile::GroundProfile;

/// How many phase velocities the bracket scan samples between the slowest material's half shear-wave speed and
/// the half-space's shear-wave speed.
const SCAN_POINTS: usize = 600;
/// Bisection steps on a bracket: its width falls by 2⁻⁶⁰, below round-off.
const BISECTIONS: usize = 60;

/// The phase velocities (m/s), slowest (the fundamental mode) first, of the trapped Rayleigh modes of `profile` at
/// circular frequency `omega` (rad/s, > 0). Empty if none is slower than the half-space's shear wave.
pub fn rayleigh_phase_velocities(profile: &GroundProfile, omega: f64) -> Vec<f64> {
    let elastic = profile.undamped();
    let sign = |c: f64| system_determinant_sign(&elastic, omega / c, omega);
    let (low, high) = (0.5 * elastic.slowest_shear_wave_speed(), elastic.half_space.shear_wave_speed * (1.0 - 1e-9));
    let grid: Vec<(f64, f64)> =
        (0..=SCAN_POINTS).map(|i| low + (high - low) * i as f64 / SCAN_POINTS as f64).map(|c| (c, sign(c))).collect();
    grid.windows(2).filter(|w| w[0].1 * w[1].1 < 0.0).map(|w| bisect(&sign, w[0], w[1].0)).collect()
}

/// The sign (±1) of the determinant of the whole layered system's stiffness at (k, ω), undamped.
fn system_determinant_sign(elastic: &GroundProfile, k: f64, omega: f64) -> f64 {
    let mut sign = 1.0;
    let surface = condensed(elastic, k, omega, |block| sign *= block.determinant().re.signum());
    sign * surface.determinant().re.signum()
}

/// Bisection of the sign change of `sign` between `a` = (c, sign(c)) and `b`.
fn bisect(sign: &impl Fn(f64) -> f64, a: (f64, f64), b: f64) -> f64 {
    let ((mut lo, s_lo), mut hi) = (a, b);
    for _ in 0..BISECTIONS {
        let middle = 0.5 * (lo + hi);
        if sign(middle) == s_lo {
            lo = middle;
        } else {
            hi = middle;
        }
    }
    0.5 * (lo + hi)
}
