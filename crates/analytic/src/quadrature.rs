//! Adaptive Gauss–Kronrod quadrature of a complex function on an interval (Piessens et al. 1983, QUADPACK's QAG
//! with the 7–15 point pair): the interval with the largest error estimate is bisected until the sum of the
//! estimates is within the tolerance. Breakpoints (where the integrand has a kink or a near-singularity known in
//! advance) start the partition. Used for the ground's strip integral (docs/theory.md §19).

use num_complex::Complex64;

/// 15-point Kronrod abscissae on [−1, 1] (the non-negative half, descending to 0).
const KRONROD_NODES: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Their Kronrod weights.
const KRONROD_WEIGHTS: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// The 7-point Gauss weights of the odd-indexed Kronrod nodes (1, 3, 5) and of 0.
const GAUSS_WEIGHTS: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// What an adaptive quadrature reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Integral {
    /// The integral's value.
    pub value: Complex64,
    /// The sum of the intervals' error estimates (QUADPACK's scaled |K₁₅ − G₇|).
    pub error: f64,
    /// How many times the integrand was evaluated.
    pub evaluations: usize,
    /// Whether `error` met the tolerance within the interval budget.
    pub converged: bool,
}

/// When to stop: the error estimate ≤ max(absolute, relative·|value|), or `max_intervals` reached (not converged).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Relative to the integral's magnitude.
    pub relative: f64,
    /// In the integral's own units.
    pub absolute: f64,
    /// The most subintervals the partition may grow to.
    pub max_intervals: usize,
}

/// One interval of the partition with its Kronrod value and error estimate.
#[derive(Debug, Clone, Copy)]
struct Piece {
    from: f64,
    to: f64,
    value: Complex64,
    error: f64,
}

/// ∫ₐᵇ f(x) dx, the partition started at the `breakpoints` that lie inside (a, b).
pub fn integrate(f: impl Fn(f64) -> Complex64, a: f64, b: f64, breakpoints: &[f64], tolerance: Tolerance) -> Integral {
    let mut edges: Vec<f64> = breakpoints.iter().copied().filter(|&x| x > a && x < b).collect();
    edges.push(a);
    edges.push(b);
    edges.sort_by(f64::total_cmp);
    edges.dedup();
    let mut pieces: Vec<Piece> = edges.windows(2).map(|w| kronrod(&f, w[0], w[1])).collect();
    let mut evaluations = 15 * pieces.len();
    loop {
        let value: Complex64 = pieces.iter().map(|p| p.value).sum();
        let error: f64 = pieces.iter().map(|p| p.error).sum();
        let enough = error <= tolerance.absolute.max(tolerance.relative * value.norm());
        let worst = (0..pieces.len()).max_by(|&i, &j| pieces[i].error.total_cmp(&pieces[j].error));
        let splittable = worst.filter(|&i| {
            let p = pieces[i];
            let middle = 0.5 * (p.from + p.to);
            middle > p.from && middle < p.to
        });
        match splittable {
            Some(i) if !enough && pieces.len() < tolerance.max_intervals => {
                let p = pieces.swap_remove(i);
                let middle = 0.5 * (p.from + p.to);
                pieces.push(kronrod(&f, p.from, middle));
                pieces.push(kronrod(&f, middle, p.to));
                evaluations += 30;
            }
            _ => return Integral { value, error, evaluations, converged: enough },
        }
    }
}

/// The 15-point Kronrod value on [from, to] and its error estimate: QUADPACK's (QK15), |K₁₅ − G₇| scaled as
/// I_asc·min(1, (200|K₁₅ − G₇|/I_asc)^{3/2}) with I_asc = ∫|f − mean| by the Kronrod rule — |K₁₅ − G₇| alone is
/// G₇'s error, far above K₁₅'s on a smooth piece — and never below 50ε·∫|f|.
fn kronrod(f: &impl Fn(f64) -> Complex64, from: f64, to: f64) -> Piece {
    let (centre, half) = (0.5 * (from + to), 0.5 * (to - from));
    let mut values = [Complex64::new(0.0, 0.0); 15];
    values[7] = f(centre);
    for (j, &x) in KRONROD_NODES[..7].iter().enumerate() {
        values[j] = f(centre - half * x);
        values[14 - j] = f(centre + half * x);
    }
    let weight = |i: usize| KRONROD_WEIGHTS[i.min(14 - i)];
    let kronrod: Complex64 = (0..15).map(|i| values[i] * weight(i)).sum();
    let gauss: Complex64 =
        (1..7).step_by(2).map(|j| (values[j] + values[14 - j]) * GAUSS_WEIGHTS[j / 2]).sum::<Complex64>()
            + values[7] * GAUSS_WEIGHTS[3];
    let mean = kronrod * 0.5;
    let absolute: f64 = (0..15).map(|i| values[i].norm() * weight(i)).sum::<f64>() * half;
    let spread: f64 = (0..15).map(|i| (values[i] - mean).norm() * weight(i)).sum::<f64>() * half;
    let mut error = ((kronrod - gauss) * half).norm();
    if spread > 0.0 && error > 0.0 {
        error = spread * (200.0 * error / spread).powf(1.5).min(1.0);
    }
    Piece { from, to, value: kronrod * half, error: error.max(50.0 * f64::EPSILON * absolute) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tight() -> Tolerance {
        Tolerance { relative: 1e-12, absolute: 0.0, max_intervals: 500 }
    }

    /// A polynomial of degree 13 is integrated exactly by both rules (G₇ to degree 13, K₁₅ to 22), so one interval
    /// suffices; one of degree 20 only by K₁₅, whose estimate against G₇ then asks for a few bisections; both to
    /// round-off.
    #[test]
    fn polynomials_are_exact() {
        let f = |x: f64| Complex64::new(x.powi(13), -x.powi(3));
        let out = integrate(f, 0.0, 1.0, &[], tight());
        assert!((out.value - Complex64::new(1.0 / 14.0, -0.25)).norm() < 1e-15, "{out:?}");
        assert_eq!(out.evaluations, 15);
        let out = integrate(|x| Complex64::new(x.powi(20), 0.0), 0.0, 1.0, &[], tight());
        assert!((out.value.re - 1.0 / 21.0).abs() < 1e-15 && out.converged, "{out:?}");
    }

    /// A Lorentzian peak 1/(x − x₀ − iε) of width 1e-3, as a damped Rayleigh pole is, integrates to its closed form
    /// ln((1 − x₀ − iε)/(−x₀ − iε)) to 1e-10, and the error estimate is honest (above the true error).
    #[test]
    fn a_sharp_damped_pole_is_resolved() {
        let (x0, eps) = (0.37, 1e-3);
        let pole = Complex64::new(x0, eps);
        let f = |x: f64| 1.0 / (Complex64::new(x, 0.0) - pole);
        let exact = ((Complex64::new(1.0, 0.0) - pole) / (-pole)).ln();
        let out = integrate(f, 0.0, 1.0, &[], tight());
        let error = (out.value - exact).norm();
        assert!(out.converged && error < 1e-10 * exact.norm() && error <= out.error, "{out:?} vs {exact}");
    }

    /// A log singularity at an end (∫₀¹ ln x = −1) converges by bisection; a budget too small says it did not.
    #[test]
    fn an_end_singularity_converges_and_a_short_budget_says_so() {
        let f = |x: f64| Complex64::new(x.ln(), 0.0);
        let out = integrate(f, 0.0, 1.0, &[], Tolerance { relative: 1e-10, ..tight() });
        assert!(out.converged && (out.value.re + 1.0).abs() < 1e-10, "{out:?}");
        let short = integrate(f, 0.0, 1.0, &[], Tolerance { relative: 1e-10, absolute: 0.0, max_intervals: 3 });
        assert!(!short.converged && short.error > 1e-10, "{short:?}");
    }

    /// A kink at a breakpoint is exact with it (|x − ⅓| on [0, 1] is 5/18).
    #[test]
    fn a_kink_at_a_breakpoint_is_exact() {
        let f = |x: f64| Complex64::new((x - 1.0 / 3.0).abs(), 0.0);
        let out = integrate(f, 0.0, 1.0, &[1.0 / 3.0, 7.0], tight());
        assert!((out.value.re - 5.0 / 18.0).abs() < 1e-15 && out.evaluations == 30, "{out:?}");
    }
}
