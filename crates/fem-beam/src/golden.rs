//! Golden-section search for the extremum of a unimodal function on an interval (Kiefer 1953): the one search the
//! workspace refines a peak or a minimum with — a critical wave here, critical speeds, optimal forces and resonances
//! above (`runner`, `study`).

/// How many times [`golden_section`] evaluates f to bring an interval of `width` down to `tolerance`: the first two
/// points, then one per shrinking of the interval by the golden ratio, ⌈ln(width/tolerance)/ln φ⌉ of them.
pub fn golden_section_evaluations(width: f64, tolerance: f64) -> usize {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let shrinkings = if width > tolerance { ((width / tolerance).ln() / phi.ln()).ceil() as usize } else { 0 };
    2 + shrinkings
}

/// Golden-section search for the maximum (`maximise`) or minimum of f on [a, b] to an interval width `tolerance`;
/// returns (argmax, max) — or (argmin, min) — among the evaluated points. An error of f ends the search with it.
pub fn golden_section<E>(
    f: &mut dyn FnMut(f64) -> Result<f64, E>,
    mut a: f64,
    mut b: f64,
    tolerance: f64,
    maximise: bool,
) -> Result<(f64, f64), E> {
    let sign = if maximise { 1.0 } else { -1.0 };
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (sign * f(c)?, sign * f(d)?);
    while (b - a).abs() > tolerance {
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = sign * f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = sign * f(d)?;
        }
    }
    Ok(if fc >= fd { (c, sign * fc) } else { (d, sign * fd) })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The count the estimate of a critical speed's refinement uses is the search's own.
    #[test]
    fn the_evaluations_are_counted_ahead() {
        for (width, tolerance) in [(40.0, 0.4), (20.0, 0.4), (1.0, 1e-3), (0.3, 1.0), (7.0, 0.01)] {
            let mut count = 0;
            let mut f = |x: f64| -> Result<f64, ()> {
                count += 1;
                Ok(-(x - 0.37 * width).powi(2))
            };
            golden_section(&mut f, 0.0, width, tolerance, true).unwrap();
            assert_eq!(count, golden_section_evaluations(width, tolerance), "{width} to {tolerance}");
        }
    }
}
