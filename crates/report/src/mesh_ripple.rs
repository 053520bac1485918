//! The wheel force's component with the element period: a mesh artefact on a track that is the same everywhere.
//!
//! A wheel rolling over Hermite elements meets a rail whose point receptance varies within each element (the cubic
//! interpolation is exact at the nodes only), so its contact force carries a ripple of spatial period l_e, the
//! element length, that the continuous uniform track does not have (docs/theory.md §12). Its amplitude is the Fourier
//! coefficient of the force at the wavenumber 2π/l_e over the wheel's positions x_k,
//!
//!   A = (2/N) |Σ_k (Q_k − Q̄) e^{−2πi x_k/l_e}|,
//!
//! taken over a whole number of element periods where results are read, so that the mean and slower motions
//! (irregularities, the track's own response) leave it alone to within their leakage.

/// A ripple above this fraction of the wheel's static load Q₀ is warned about (1 %: below what a wheel-force
/// measurement resolves, and below the dynamic increments the vehicle study compares).
pub const RIPPLE_LIMIT: f64 = 0.01;
/// Fewer samples per element period than this cannot resolve the ripple (four give its amplitude exactly for a pure
/// sinusoid; fewer alias it).
const MIN_SAMPLES_PER_PERIOD: usize = 4;
/// Fewer whole periods than this in the region leave too much leakage from slower motions.
const MIN_PERIODS: usize = 4;

/// The amplitude (N) of the component of period `element_length` (m) of the wheel force `force` (N) over the wheel
/// positions `position` (m, ascending) inside `region` [from, to] (m); None when the region holds fewer than
/// four periods or the samples are fewer than four a period.
pub fn element_ripple(position: &[f64], force: &[f64], element_length: f64, region: [f64; 2]) -> Option<f64> {
    let inside = |x: f64| x >= region[0] && x <= region[1];
    let first = position.iter().position(|&x| inside(x))?;
    let last = position.iter().rposition(|&x| inside(x))?;
    let periods = ((position[last] - position[first]) / element_length).floor() as usize;
    if periods < MIN_PERIODS {
        return None;
    }
    let end = position[first] + periods as f64 * element_length;
    let samples: Vec<(f64, f64)> =
        (first..=last).filter(|&k| position[k] < end).map(|k| (position[k], force[k])).collect();
    if samples.len() < MIN_SAMPLES_PER_PERIOD * periods {
        return None;
    }
    let n = samples.len() as f64;
    let mean = samples.iter().map(|s| s.1).sum::<f64>() / n;
    let wavenumber = std::f64::consts::TAU / element_length;
    let (re, im) = samples.iter().fold((0.0, 0.0), |(re, im), &(x, q)| {
        let (sin, cos) = (wavenumber * x).sin_cos();
        (re + (q - mean) * cos, im - (q - mean) * sin)
    });
    Some(2.0 / n * re.hypot(im))
}

/// The element length to run with so that a ripple of `ripple` (N) measured with `element_length` (m) falls below
/// [`RIPPLE_LIMIT`]·`static_force`: the element halved until a ripple falling like l_e would be below it, with the
/// number of elements (of `elements` now) that gives it. Conservative: the measured fall is first order or faster
/// (quarter car at 100 m/s: 2665, 1191, 643, 163 N on 2, 1, 0.5, 0.25 m elements; docs/theory.md §12).
pub fn shorter_elements(ripple: f64, static_force: f64, element_length: f64, elements: usize) -> (f64, usize) {
    let mut halvings = 0u32;
    while ripple / 2f64.powi(halvings as i32) > RIPPLE_LIMIT * static_force && halvings < 10 {
        halvings += 1;
    }
    (element_length / 2f64.powi(halvings as i32), elements << halvings)
}

#[cfg(test)]
mod tests {
    use super::{element_ripple, shorter_elements};

    /// 2665 N on 2 m elements over Q₀ = 83.4 kN (3.2 %) asks for a quarter of the length; 1191 N on 1 m for half.
    #[test]
    fn shorter_elements_halve_until_a_first_order_fall_is_below_the_limit() {
        assert_eq!(shorter_elements(2665.0, 83385.0, 2.0, 100), (0.5, 400));
        assert_eq!(shorter_elements(1191.0, 83385.0, 1.0, 200), (0.5, 400));
        assert_eq!(shorter_elements(500.0, 83385.0, 1.0, 200), (1.0, 200));
    }

    /// A force of 80 kN with a 2 kN ripple of period 1 m, a 5 kN swell of period 23 m and a slow trend, sampled every
    /// 0.1 m over 0–200 m: the ripple is read from 60–140 m to 2 % (the swell's leakage over 80 whole periods), and
    /// nothing is read from too short a region or too few samples a period.
    #[test]
    fn reads_the_ripple_of_the_element_period_and_not_the_slower_motions() {
        let x: Vec<f64> = (0..=2000).map(|k| 0.1 * k as f64).collect();
        let tau = std::f64::consts::TAU;
        let q: Vec<f64> =
            x.iter().map(|&x| 80e3 + 2e3 * (tau * x + 0.3).sin() + 5e3 * (tau * x / 23.0).sin() + 10.0 * x).collect();
        let ripple = element_ripple(&x, &q, 1.0, [60.0, 140.0]).unwrap();
        assert!((ripple - 2e3).abs() < 40.0, "{ripple}");
        let smooth: Vec<f64> = x.iter().map(|&x| 80e3 + 5e3 * (tau * x / 23.0).sin()).collect();
        assert!(element_ripple(&x, &smooth, 1.0, [60.0, 140.0]).unwrap() < 40.0);
        assert_eq!(element_ripple(&x, &q, 1.0, [60.0, 62.5]), None);
        assert_eq!(element_ripple(&x, &q, 0.3, [60.0, 140.0]), None);
    }
}
