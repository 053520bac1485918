//! Golden-section search for the extremum of a unimodal function on an interval (Kiefer 1953): the one search the
//! workspace refines a peak or a minimum with — a critical wave and a steady wave's extremes here, critical speeds,
//! optimal forces, stationary peaks and resonances above (`runner`, `study`) — and [`refine_peak`], the one way a
//! sampled peak is refined between its neighbours.

/// How many times [`golden_section`] evaluates f to bring an interval of `width` down to `tolerance`: the first two
/// points, then one per shrinking of the interval by the golden ratio, ⌈ln(width/tolerance)/ln φ⌉ of them.
pub fn golden_section_evaluations(width: f64, tolerance: f64) -> usize {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let shrinkings = if width > tolerance { ((width / tolerance).ln() / phi.ln()).ceil() as usize } else { 0 };
    2 + shrinkings
}

/// The interval a golden-section search ended on: [lower, upper] of width ≤ its tolerance, and the better of its
/// two interior points (argument, value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoldenBracket {
    /// The interval's lower end.
    pub lower: f64,
    /// The interval's upper end.
    pub upper: f64,
    /// The best evaluated interior point (argument, value of f).
    pub best: (f64, f64),
}

/// Golden-section search for the maximum (`maximise`) or minimum of f on [a, b] down to an interval of width
/// `tolerance`: the interval it ended on and its best point (on equal values it keeps the upper point). An error of f
/// ends the search with it.
pub fn golden_bracket<E>(
    f: &mut dyn FnMut(f64) -> Result<f64, E>,
    mut a: f64,
    mut b: f64,
    tolerance: f64,
    maximise: bool,
) -> Result<GoldenBracket, E> {
    let sign = if maximise { 1.0 } else { -1.0 };
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (sign * f(c)?, sign * f(d)?);
    while (b - a).abs() > tolerance {
        if fc > fd {
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
    let best = if fc > fd { (c, sign * fc) } else { (d, sign * fd) };
    Ok(GoldenBracket { lower: a, upper: b, best })
}

/// Golden-section search for the maximum (`maximise`) or minimum of f on [a, b] to an interval width `tolerance`;
/// returns (argmax, max) — or (argmin, min) — among the evaluated points ([`golden_bracket`]'s best).
pub fn golden_section<E>(
    f: &mut dyn FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    tolerance: f64,
    maximise: bool,
) -> Result<(f64, f64), E> {
    golden_bracket(f, a, b, tolerance, maximise).map(|bracket| bracket.best)
}

/// A sampled peak refined: golden section for the maximum of f between the sample's neighbours `bracket`, to
/// `tolerance`; the sample `(x, f(x))` itself where the search found less (f not unimodal in the bracket, or a
/// sample at a kink). A refinement never reports less than it was given.
pub fn refine_peak<E>(
    f: &mut dyn FnMut(f64) -> Result<f64, E>,
    bracket: (f64, f64),
    sample: (f64, f64),
    tolerance: f64,
) -> Result<(f64, f64), E> {
    let refined = golden_section(f, bracket.0, bracket.1, tolerance, true)?;
    Ok(if refined.1 >= sample.1 { refined } else { sample })
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

    /// A smooth peak is refined above its sample; where the bracket holds a taller spike golden section misses (f
    /// is not unimodal there), the sample stands rather than a lower value.
    #[test]
    fn a_refined_peak_is_never_below_its_sample() {
        let mut smooth = |x: f64| Ok::<_, ()>(1.0 - (x - 0.3).powi(2));
        let (x, value) = refine_peak(&mut smooth, (0.0, 1.0), (0.25, 1.0 - 0.05f64.powi(2)), 1e-9).unwrap();
        assert!((x - 0.3).abs() < 1e-8 && value > 1.0 - 1e-15, "{x} {value}");
        let sample = (0.5, 2.0);
        let mut spiky = |x: f64| Ok::<_, ()>(if (x - 0.5).abs() < 1e-3 { 2.0 } else { 1.0 - (x - 0.9).powi(2) });
        assert_eq!(refine_peak(&mut spiky, (0.0, 1.0), sample, 1e-9).unwrap(), sample);
    }
}
