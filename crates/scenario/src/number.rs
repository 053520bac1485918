//! Numbers in result files: the shortest decimal that reads back to the same f64 (Rust's `Debug` digits), with an
//! exponent for very small or large magnitudes instead of a hundred-digit decimal, no trailing `.0`, and no `-0`.

/// `x` as the shortest round-trip text: `0.1`, `-52.4`, `1e-20`, `3`, `0` (also for −0), `NaN`, `inf`.
pub fn number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let text = format!("{x:?}");
    match text.strip_suffix(".0") {
        Some(integer) => integer.to_string(),
        None => text,
    }
}

/// `x` rounded to `digits` significant digits, as [`number`]: a value computed back from an input (a damping ratio
/// from c_f = 2ζ√(k_f ρA)) reads as the input did, `0.1` rather than `0.09999999999999999`.
pub fn significant(x: f64, digits: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return number(x);
    }
    let scale = 10f64.powi(digits - 1 - x.abs().log10().floor() as i32);
    number((x * scale).round() / scale)
}

/// A CSV row of numbers, each as [`number`], comma-separated (no newline).
pub fn row(values: &[f64]) -> String {
    values.iter().map(|&x| number(x)).collect::<Vec<_>>().join(",")
}

/// A CSV row as [`row`], a missing value (NaN) as an empty field (read as missing by CSV readers).
pub fn row_with_gaps(values: &[f64]) -> String {
    values.iter().map(|&x| if x.is_nan() { String::new() } else { number(x) }).collect::<Vec<_>>().join(",")
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn shortest_round_trip_without_negative_zero() {
        for x in [0.1, -52.4e-3, 1e-20, 3.0, 1.1102230246251565e-16, 6.02e23, -1e300, 123456.789] {
            let text = number(x);
            assert_eq!(text.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{text}");
            assert!(text.len() <= 24, "{text}");
        }
        assert_eq!(number(-0.0), "0");
        assert_eq!(super::significant(0.09999999999999999, 12), "0.1");
        assert_eq!(super::significant(205.5731234, 4), "205.6");
        assert_eq!(number(3.0), "3");
        assert_eq!(number(1e-20), "1e-20");
        assert_eq!(number(-2.5), "-2.5");
    }
}
