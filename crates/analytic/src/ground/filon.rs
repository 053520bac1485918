//! The Fourier integral ∫ p(k) e^{iks} dk of a piecewise cubic p(k), exact for each cubic at any s (Filon's idea:
//! integrate the oscillation exactly, interpolate only the slowly varying factor). On a panel [k_a, k_a + w] with
//! p(k_a + tw) = Σ c_m t^m,
//!
//! ```text
//! ∫ p e^{iks} dk = w e^{ik_a s} Σ_m c_m μ_m(ws),      μ_m(θ) = ∫₀¹ t^m e^{iθt} dt,
//! ```
//!
//! μ_m by its power series Σ_j (iθ)^j/(j!(m + j + 1)) for |θ| ≤ 1 and by the recurrence
//! μ_m = (e^{iθ} − m μ_{m−1})/(iθ) above (stable there: each step multiplies an error by m/|θ| ≤ 3). The cost of
//! one s is a few operations a panel, whatever |s|: a Gauss rule needs points in proportion to the phase |s|·w.

use num_complex::Complex64;
use rayon::prelude::*;

/// A function of k ≥ 0 as cubics on consecutive panels.
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct PiecewiseCubic {
    panels: Vec<Panel>,
}

/// One panel: p(start + t·width) = Σ_m coefficients[m] t^m for t in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
struct Panel {
    start: f64,
    width: f64,
    coefficients: [Complex64; 4],
}

impl PiecewiseCubic {
    /// Append the panel [`start`, `end`] holding the cubic through `values` at its four equally spaced points
    /// t = 0, ⅓, ⅔, 1.
    pub(super) fn push(&mut self, start: f64, end: f64, values: [Complex64; 4]) {
        let [y0, y1, y2, y3] = values;
        let coefficients = [
            y0,
            (-11.0 * y0 + 18.0 * y1 - 9.0 * y2 + 2.0 * y3) / 2.0,
            9.0 * (2.0 * y0 - 5.0 * y1 + 4.0 * y2 - y3) / 2.0,
            9.0 * (-y0 + 3.0 * y1 - 3.0 * y2 + y3) / 2.0,
        ];
        self.panels.push(Panel { start, width: end - start, coefficients });
    }

    /// [`Self::fourier`] at s_m = `first` + m·`step`, m < `count`: each panel's phases e^{ik_a s} and e^{iws} carried
    /// from one point to the next by a complex product (a chunk of [`GRID_CHUNK`] points starting from its own sine and
    /// cosine, so the products' round-off stays ~1e-14), in parallel over the chunks.
    pub(super) fn fourier_on_grid(&self, first: f64, step: f64, count: usize) -> Vec<Complex64> {
        let chunk = |c: usize| {
            let start = c * GRID_CHUNK;
            let mut out = vec![Complex64::new(0.0, 0.0); GRID_CHUNK.min(count - start)];
            let s0 = first + start as f64 * step;
            for panel in &self.panels {
                let (mut phase, turn) = (
                    Complex64::from_polar(panel.width, panel.start * s0),
                    Complex64::from_polar(1.0, panel.start * step),
                );
                let (mut edge, edge_turn) =
                    (Complex64::from_polar(1.0, panel.width * s0), Complex64::from_polar(1.0, panel.width * step));
                for (m, value) in out.iter_mut().enumerate() {
                    let theta = panel.width * (first + (start + m) as f64 * step);
                    let moments = if theta.abs() <= 1.0 { series_moments(theta) } else { edge_moments(theta, edge) };
                    let sum: Complex64 = panel.coefficients.iter().zip(moments).map(|(c, mu)| c * mu).sum();
                    *value += sum * phase;
                    phase *= turn;
                    edge *= edge_turn;
                }
            }
            out
        };
        let chunks: Vec<Vec<Complex64>> = (0..count.div_ceil(GRID_CHUNK)).into_par_iter().map(chunk).collect();
        chunks.concat()
    }

    /// ∫ p(k) e^{iks} dk over all panels.
    pub(super) fn fourier(&self, s: f64) -> Complex64 {
        self.panels
            .iter()
            .map(|panel| {
                let moments = moments(panel.width * s);
                let sum: Complex64 = panel.coefficients.iter().zip(moments).map(|(c, mu)| c * mu).sum();
                sum * Complex64::from_polar(panel.width, panel.start * s)
            })
            .sum()
    }
}

/// Points of a grid whose phases one chunk carries by products (`PiecewiseCubic::fourier_on_grid`).
const GRID_CHUNK: usize = 256;

/// μ_0 … μ_3 at θ.
fn moments(theta: f64) -> [Complex64; 4] {
    match theta.abs() <= 1.0 {
        true => series_moments(theta),
        false => edge_moments(theta, Complex64::from_polar(1.0, theta)),
    }
}

/// μ_0 … μ_3 at |θ| ≤ 1 by their power series.
fn series_moments(theta: f64) -> [Complex64; 4] {
    let mut mu = [Complex64::new(0.0, 0.0); 4];
    // (iθ)^j / j! falls below 1e-17 by j = 19 at |θ| = 1, sooner for smaller θ (a few terms for the long waves'
    // narrow panels).
    let mut term = Complex64::new(1.0, 0.0);
    for j in 0..20 {
        for (m, value) in mu.iter_mut().enumerate() {
            *value += term / (m + j + 1) as f64;
        }
        term *= Complex64::new(0.0, theta) / (j + 1) as f64;
        if term.norm_sqr() < 1e-34 {
            break;
        }
    }
    mu
}

/// μ_0 … μ_3 at |θ| > 1 by the recurrence, from `edge` = e^{iθ}.
fn edge_moments(theta: f64, edge: Complex64) -> [Complex64; 4] {
    let mut mu = [Complex64::new(0.0, 0.0); 4];
    let i_theta = Complex64::new(0.0, theta);
    let mut previous = (edge - 1.0) / i_theta;
    mu[0] = previous;
    for (m, value) in mu.iter_mut().enumerate().skip(1) {
        previous = (edge - m as f64 * previous) / i_theta;
        *value = previous;
    }
    mu
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Simpson's rule for f on [a, b] with n (even) panels.
    fn simpson(f: impl Fn(f64) -> Complex64, a: f64, b: f64, n: usize) -> Complex64 {
        let h = (b - a) / n as f64;
        let weight = |i: usize| {
            if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            }
        };
        (0..=n).map(|i| f(a + i as f64 * h) * weight(i)).sum::<Complex64>() * (h / 3.0)
    }

    /// μ_m against a 2000-panel Simpson rule of t^m e^{iθt} on both sides of the switch at |θ| = 1 and far above.
    #[test]
    fn the_moments_are_the_integrals() {
        for theta in [0.0, 0.3, -0.999, 1.001, 2.5, -7.0, 40.0] {
            let exact = moments(theta);
            for (m, value) in exact.iter().enumerate() {
                let reference = simpson(|t| Complex64::from_polar(t.powi(m as i32), theta * t), 0.0, 1.0, 2000);
                // Simpson's error h⁴|f⁗|/180 ≤ 1e-13·θ⁴ here.
                assert!((reference - value).norm() < 1e-12 * (1.0 + theta.powi(4)), "μ_{m}({theta})");
            }
        }
    }

    /// On a grid the phases carried by products are the single evaluations' to 1e-12 of the largest value, across the
    /// series' and the recurrence's ranges and over several chunks.
    #[test]
    fn a_grid_is_its_points_one_by_one() {
        let mut p = PiecewiseCubic::default();
        for i in 0..40 {
            let (a, b) = (0.01 * 1.2f64.powi(i), 0.01 * 1.2f64.powi(i + 1));
            let at = |t: f64| {
                let k = a + t * (b - a);
                Complex64::new(1.0 / (1.0 + k * k), -0.3 * k / (1.0 + k.powi(4)))
            };
            p.push(a, b, [at(0.0), at(1.0 / 3.0), at(2.0 / 3.0), at(1.0)]);
        }
        let (first, step, count) = (-260.0, 0.05, 10_401);
        let grid = p.fourier_on_grid(first, step, count);
        let single: Vec<Complex64> = (0..count).map(|m| p.fourier(first + m as f64 * step)).collect();
        let largest = single.iter().fold(0.0f64, |m, v| m.max(v.norm()));
        let worst = grid.iter().zip(&single).fold(0.0f64, |m, (a, b)| m.max((a - b).norm()));
        assert!(worst <= 1e-12 * largest, "{worst:e} of {largest:e}");
    }

    /// A cubic on one panel is integrated exactly: p(k) = k³ on [1, 2] against the closed form at several s.
    #[test]
    fn a_cubic_is_integrated_exactly() {
        let mut p = PiecewiseCubic::default();
        let values = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0].map(|t: f64| Complex64::new((1.0 + t).powi(3), 0.0));
        p.push(1.0, 2.0, values);
        for s in [0.0, 0.5, 3.0, -20.0] {
            // ∫₁² k³ e^{iks} dk by 20 000 Simpson panels (error ≤ 1e-12 for |s| ≤ 20).
            let reference = simpson(|k| Complex64::from_polar(k.powi(3), k * s), 1.0, 2.0, 20_000);
            assert!((p.fourier(s) - reference).norm() < 1e-10, "s = {s}");
        }
    }
}
