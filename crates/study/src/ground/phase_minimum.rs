//! The least phase velocity of the soil's fundamental Rayleigh mode (docs/theory.md §19): the slowest wave a load
//! can run with on the ground, the quick estimate of a soft site's critical speed.
//!
//! A layered site's fundamental mode is dispersive: its phase velocity falls from the half-space's Rayleigh speed at
//! low frequency towards the top layer's at high. Where a stiffer crust lies over a softer layer it has an interior
//! minimum (Ledsgård's 45.0 m/s near 6 Hz) and may fall again, lower, at frequencies that only the buried layer's
//! short waves reach — those waves decay within metres of the track and are not what a train excites, so the interior
//! minimum is the one reported, with a warning that the curve falls lower at the end of the range. A homogeneous
//! half-space is not dispersive: its Rayleigh speed is the least phase velocity at every frequency.

use crate::ground::numbers::{DispersionPoint, fundamental};
use analytic::golden::golden_section;
use analytic::ground::StripGround;
use scenario::error::Result;

/// Relative spread of the sampled phase velocities below which the curve is flat (a homogeneous half-space to
/// round-off: its computed Rayleigh speed agrees with the closed form to 4e-16).
const FLAT: f64 = 1e-9;

/// The fundamental's least phase velocity (frequency Hz, c m/s) over the sampled `dispersion` of `strip`: the lowest
/// interior local minimum, refined by golden section between its neighbours to 1e-3 Hz; on a non-dispersive
/// ground the constant Rayleigh speed (frequency `None`). `None` where the curve has no interior minimum, with a
/// warning saying whether widening the frequencies can help; a warning too where the curve falls below the interior
/// minimum at an end of the range.
pub fn least_phase_velocity(
    strip: &StripGround,
    dispersion: &[DispersionPoint],
    warnings: &mut Vec<String>,
) -> Result<Option<(Option<f64>, f64)>> {
    let c: Vec<f64> = dispersion.iter().map(|p| p.phase_velocity).collect();
    let low = c.iter().copied().fold(f64::INFINITY, f64::min);
    let Some(&first) = c.first() else { return Ok(None) };
    // One material from the surface down: the Rayleigh wave is not dispersive (the samples agree to round-off).
    let mut materials = strip.profile.materials();
    let homogeneous = materials.next().is_some_and(|top| materials.all(|m| m == top));
    if homogeneous && c.iter().all(|&v| (v - first).abs() <= FLAT * first) {
        return Ok(Some((None, low)));
    }
    if c.len() < 3 {
        warnings.push(format!(
            "the fundamental mode's least phase velocity needs its curve at three frequencies or more (given {}): \
             undefined",
            c.len()
        ));
        return Ok(None);
    }
    let interior =
        (1..c.len() - 1).filter(|&i| c[i] <= c[i - 1] && c[i] <= c[i + 1]).min_by(|&i, &j| c[i].total_cmp(&c[j]));
    let Some(i) = interior else {
        let end = if c[0] < c[c.len() - 1] { "lowest" } else { "highest" };
        warnings.push(format!(
            "the fundamental mode's phase velocity falls monotonically towards the {end} frequency asked, with no \
             minimum inside them: its least phase velocity lies beyond them; widen them"
        ));
        return Ok(None);
    };
    let (lo, hi) = (dispersion[i - 1].frequency, dispersion[i + 1].frequency);
    let mut f = |frequency: f64| -> Result<f64> { Ok(fundamental(strip, frequency)) };
    let found = golden_section(&mut f, lo, hi, 1e-3, false)?;
    let (frequency, least) =
        if found.1 <= c[i] { found } else { (dispersion[i].frequency, dispersion[i].phase_velocity) };
    if low < least {
        let at = dispersion[c.iter().position(|&v| v == low).unwrap_or(0)].frequency;
        warnings.push(format!(
            "the fundamental mode's phase velocity falls below its interior minimum ({least:.2} m/s at {frequency:.2} \
             Hz) to {low:.2} m/s at {at:.2} Hz, an end of the frequencies asked: the short waves of a softer layer \
             below, which decay within metres of the surface; the interior minimum is the one reported"
        ));
    }
    Ok(Some((Some(frequency), least)))
}

#[cfg(test)]
mod tests {
    use super::least_phase_velocity;
    use crate::ground::numbers::DispersionPoint;
    use analytic::ground::{GroundProfile, SoilMaterial, StripGround};

    fn points(values: &[(f64, f64)]) -> Vec<DispersionPoint> {
        values.iter().map(|&(frequency, phase_velocity)| DispersionPoint { frequency, phase_velocity }).collect()
    }

    fn half_space() -> StripGround {
        let soil = SoilMaterial {
            shear_wave_speed: 100.0,
            compression_wave_speed: 200.0,
            density: 1800.0,
            damping_ratio: 0.02,
        };
        StripGround { width: 3.0, profile: GroundProfile::half_space(soil) }
    }

    /// A flat curve of a homogeneous half-space is its own minimum at every frequency, with no warning; one sample
    /// of a layered ground is no curve to find a minimum on; a curve still falling at an end has none inside, and
    /// says widening helps.
    #[test]
    fn flat_and_monotone_curves() {
        let mut warnings = Vec::new();
        let flat = points(&[(1.0, 93.5), (2.0, 93.5), (3.0, 93.5)]);
        assert_eq!(least_phase_velocity(&half_space(), &flat, &mut warnings).unwrap(), Some((None, 93.5)));
        assert!(warnings.is_empty(), "{warnings:?}");
        let mut layered = half_space();
        let crust = SoilMaterial { shear_wave_speed: 150.0, ..layered.profile.half_space };
        layered.profile.layers.push(analytic::ground::SoilLayer { thickness: 2.0, material: crust });
        assert_eq!(least_phase_velocity(&layered, &points(&[(5.0, 93.5)]), &mut warnings).unwrap(), None);
        assert!(warnings[0].contains("three frequencies or more (given 1)"), "{warnings:?}");
        warnings.clear();
        let falling = points(&[(1.0, 93.0), (2.0, 80.0), (3.0, 70.0)]);
        assert_eq!(least_phase_velocity(&half_space(), &falling, &mut warnings).unwrap(), None);
        assert!(warnings[0].contains("highest frequency asked") && warnings[0].contains("widen them"), "{warnings:?}");
    }
}
