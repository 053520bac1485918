//! Where a figure's axes have their grid lines and labels, and how the labels read.
//!
//! A linear axis is labelled every 1, 2 or 5 × 10ᵏ (at most ten labels), with a light line half-way between. A log
//! axis is drawn in the exponent (log₁₀ of the value) and labelled at values a reader can use: 1, 2 and 5 × 10ᵏ over
//! up to three decades, the powers of ten alone over more (every second, third… decade beyond ten), with light lines
//! at 1…9 × 10ᵏ; a log axis spanning less than a factor of two (no 1-2-5 value twice inside) is labelled as a linear
//! axis of its values would be.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;

/// An axis's grid in the drawn coordinate (the value on a linear axis, its log₁₀ on a log axis): the labelled
/// positions, the light ones, and the spacing of the labelled values (for their decimals).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Labelled positions, increasing.
    pub bold: Vec<f64>,
    /// Unlabelled light positions, increasing.
    pub light: Vec<f64>,
    /// The spacing of the labelled values on a linear axis (the labels' resolution); 0 on a log axis.
    pub step: f64,
    /// On a log axis, whether its labels are written as plain numbers (every label between 0.01 and 10 000) rather
    /// than in scientific notation; one notation per axis.
    pub plain: bool,
}

impl Grid {
    /// No grid: the axis of an empty or degenerate range.
    const EMPTY: Grid = Grid { bold: Vec::new(), light: Vec::new(), step: 0.0, plain: true };
}

/// A plotters axis over a range of the drawn coordinate with its [`Grid`]: bold (labelled) lines where the grid has
/// them, light lines at its light positions, the linear mapping of plotters' own `f64` axis.
pub struct GridAxis {
    inner: RangedCoordf64,
    grid: Grid,
}

impl GridAxis {
    /// The axis over `range` with `grid`.
    pub fn new(range: std::ops::Range<f64>, grid: Grid) -> Self {
        Self { inner: range.into(), grid }
    }
}

impl Ranged for GridAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() { self.grid.light.clone() } else { self.grid.bold.clone() }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
}

/// Most labels on a linear axis.
const MAX_LABELS: f64 = 10.0;

/// The 1-2-5 step that puts at most [`MAX_LABELS`] labels on `span`.
fn nice_step(span: f64) -> f64 {
    let raw = span / MAX_LABELS;
    let decade = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0].into_iter().map(|m| m * decade).find(|&s| s >= raw).unwrap_or(10.0 * decade)
}

/// The multiples of `step` inside [lo, hi] (a hair of slack for round-off at the ends).
fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let slack = 1e-9 * step;
    let first = ((lo - slack) / step).ceil() as i64;
    let last = ((hi + slack) / step).floor() as i64;
    // Products, not a running sum: 0.1 + 0.1 + 0.1 would drift from 0.3.
    (first..=last).map(|k| k as f64 * step).collect()
}

/// The grid of a linear axis over [lo, hi].
pub fn linear(lo: f64, hi: f64) -> Grid {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return Grid::EMPTY;
    }
    let step = nice_step(hi - lo);
    Grid { bold: multiples(lo, hi, step), light: multiples(lo, hi, 0.5 * step), step, plain: true }
}

/// The grid of a log axis whose exponents (log₁₀ of the values) run over [lo, hi].
pub fn logarithmic(lo: f64, hi: f64) -> Grid {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return Grid::EMPTY;
    }
    let decades = hi - lo;
    let at = |mantissas: &[f64], every: i64| -> Vec<f64> {
        let (first, last) = (lo.floor() as i64, hi.ceil() as i64);
        (first..=last)
            .filter(|k| k.rem_euclid(every) == 0)
            .flat_map(|k| mantissas.iter().map(move |m| k as f64 + m.log10()))
            .filter(|&e| e >= lo - 1e-12 && e <= hi + 1e-12)
            .collect()
    };
    let mut bold =
        if decades <= 3.0 { at(&[1.0, 2.0, 5.0], 1) } else { at(&[1.0], (decades / MAX_LABELS).ceil() as i64) };
    if bold.len() < 2 {
        // Less than a factor of two: the values' own linear labels, placed at their logarithms.
        let values = linear(10f64.powf(lo), 10f64.powf(hi));
        bold = values.bold.iter().filter(|&&v| v > 0.0).map(|v| v.log10()).collect();
    }
    let light = if decades <= 6.0 { at(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0], 1) } else { at(&[1.0], 1) };
    let plain = bold.iter().all(|&e| (-2.0 - 1e-9..=4.0 + 1e-9).contains(&e));
    Grid { bold, light, step: 0.0, plain }
}

/// A linear axis's label rounded to the resolution of its labels (`step`): as many decimals as that step needs and
/// no more, so float noise (0.30000000000000004, −1.1e-16) never shows.
pub fn tick(value: f64, step: f64) -> String {
    if !value.is_finite() {
        return format!("{value}");
    }
    let decimals = if step > 0.0 && step.is_finite() { (-step.log10().floor()).clamp(0.0, 12.0) } else { 0.0 };
    let text = format!("{value:.*}", decimals as usize);
    // Trailing zeros after the point add nothing; "-0" is 0.
    let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text };
    if text.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { "0".into() } else { text }
}

/// A log axis's label of the value 10^`exponent`: plain digits (`plain`: "0.05", "200"), else "1e-8" at a power of ten
/// and two significant digits otherwise ("2e-8", "3.2e-8").
pub fn log_tick(exponent: f64, plain: bool) -> String {
    let value = 10f64.powf(exponent);
    if plain {
        // Three significant digits, the float noise of 10^log10(0.05) rounded away.
        return scenario::number::significant(value, 3);
    }
    // The mantissa to one decimal, written shortest ("2", "3.2"); one that rounds up to 10 moves to the next power.
    let power = exponent.floor() as i32;
    let mantissa = (value / 10f64.powi(power) * 10.0).round() / 10.0;
    if mantissa >= 10.0 { format!("1e{}", power + 1) } else { format!("{mantissa}e{power}") }
}

#[cfg(test)]
mod tests {
    use super::{linear, log_tick, logarithmic, tick};

    fn values(exponents: &[f64]) -> Vec<String> {
        exponents.iter().map(|&e| log_tick(e, true)).collect()
    }

    #[test]
    fn linear_axes_step_by_one_two_five() {
        assert_eq!(linear(0.0, 1.0).bold.len(), 11);
        assert_eq!(linear(10.0, 300.0).step, 50.0);
        assert_eq!(linear(10.0, 300.0).bold, vec![50.0, 100.0, 150.0, 200.0, 250.0, 300.0]);
        assert_eq!(linear(-0.013, 0.004).step, 0.002);
        assert!(linear(1.0, 1.0).bold.is_empty());
    }

    #[test]
    fn log_axes_label_one_two_five_values() {
        // Two decades: 1, 2, 5 in each.
        let grid = logarithmic(-1.0, 1.0);
        assert_eq!(values(&grid.bold), ["0.1", "0.2", "0.5", "1", "2", "5", "10"]);
        assert_eq!(grid.light.len(), 19);
        // Eight decades: powers of ten only.
        assert_eq!(values(&logarithmic(-8.0, 0.0).bold).len(), 9);
        assert!(!logarithmic(-8.0, 0.0).plain, "one notation per axis: 1e-8 … 1e0");
        assert_eq!(log_tick(-8.0, false), "1e-8");
        // Thirty decades: every third.
        assert_eq!(logarithmic(-30.0, 0.0).bold.len(), 11);
        // Within a factor of two: the linear labels of the values.
        assert_eq!(values(&logarithmic(3.1f64.log10(), 5.9f64.log10()).bold), ["3.5", "4", "4.5", "5", "5.5"]);
    }

    #[test]
    fn log_labels_read_plainly() {
        assert_eq!(log_tick(5f64.log10() - 2.0, true), "0.05");
        assert_eq!(log_tick(2f64.log10() - 8.0, false), "2e-8");
        assert_eq!(log_tick(3.16f64.log10() - 7.0, false), "3.2e-7");
        assert_eq!(log_tick(2.0, true), "100");
        assert_eq!(log_tick(5.0, false), "1e5");
        assert_eq!(log_tick(0.0, false), "1e0");
    }

    #[test]
    fn ticks_follow_the_axis_resolution() {
        assert_eq!(tick(-1.1102230246251565e-16, 0.2), "0");
        assert_eq!(tick(0.30000000000000004, 0.1), "0.3");
        assert_eq!(tick(150.0, 50.0), "150");
        assert_eq!(tick(0.0125, 0.0005), "0.0125");
        assert_eq!(tick(1e4, 1e4), "10000");
    }
}
