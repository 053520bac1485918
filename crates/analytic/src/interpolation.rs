//! Reading a function between equally spaced samples: the cubic through the four nearest (Lagrange), error
//! ~h⁴|f⁗|/40 inside the middle interval.

/// The cubic through (−1, a), (0, b), (1, c), (2, d) at t (t in [0, 1] reads between b and c).
pub fn cubic_through_four([a, b, c, d]: [f64; 4], t: f64) -> f64 {
    let (before, after, two_after) = (t + 1.0, t - 1.0, t - 2.0);
    (-a * t * after * two_after + d * before * t * after) / 6.0
        + (b * before * after * two_after - c * before * t * two_after) / 2.0
}

/// The function sampled as `samples[i]` at `from + i·step` read at x by [`cubic_through_four`] (the end intervals
/// from the nearest four; x outside the samples is extrapolated from the end ones).
pub fn read_equally_spaced(samples: &[f64], from: f64, step: f64, x: f64) -> f64 {
    let u = (x - from) / step;
    let i = (u.floor().max(1.0) as usize).min(samples.len() - 3);
    cubic_through_four([samples[i - 1], samples[i], samples[i + 1], samples[i + 2]], u - i as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic is read exactly (1e-12), at the samples and between them, at the ends too.
    #[test]
    fn a_cubic_is_read_exactly() {
        let f = |x: f64| 0.3 * x.powi(3) - x * x + 2.0 * x - 5.0;
        let samples: Vec<f64> = (0..10).map(|i| f(-1.0 + 0.5 * i as f64)).collect();
        for k in 0..=90 {
            let x = -1.0 + 0.05 * k as f64;
            assert!((read_equally_spaced(&samples, -1.0, 0.5, x) - f(x)).abs() < 1e-12, "x = {x}");
        }
    }
}
