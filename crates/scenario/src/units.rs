//! Speeds in the unit the user thinks in: m/s (the default, and the unit of every output) or km/h, written after the
//! number — on the command line (`--speed 360km/h`, `--speeds 140:420:20km/h`) and in Python (`speed="360km/h"`);
//! other numbers of the command line bare or followed by their own SI unit (`--acceleration -0.5m/s2`).

/// The units a speed may carry, with their factor to m/s.
/// km/h in one m/s.
pub const KMH: f64 = 3.6;

const SPEED_UNITS: [(&str, f64); 2] = [("km/h", 1.0 / KMH), ("m/s", 1.0)];

/// `text` without a trailing speed unit, and the unit's factor to m/s (1 without a unit).
pub fn split_speed_unit(text: &str) -> (&str, f64) {
    let text = text.trim();
    SPEED_UNITS
        .iter()
        .find_map(|&(unit, factor)| text.strip_suffix(unit).map(|number| (number.trim_end(), factor)))
        .unwrap_or((text, 1.0))
}

/// A speed in m/s from `100`, `100m/s` or `360km/h`.
pub fn parse_speed(text: &str) -> Result<f64, String> {
    let (number, factor) = split_speed_unit(text);
    number
        .parse::<f64>()
        .map(|v| v * factor)
        .map_err(|_| format!("`{text}` is not a speed: give m/s (`100`, `100m/s`) or km/h (`360km/h`)"))
}

/// A number given in `unit` (its SI unit), written bare (`-60`) or followed by that unit (`-60m/s²`, and with a
/// digit for a superscript: `-60m/s2`).
pub fn parse_in(text: &str, unit: &str) -> Result<f64, String> {
    let trimmed = text.trim();
    let ascii = unit.replace('²', "2").replace('³', "3");
    let number = [unit, ascii.as_str()]
        .iter()
        .filter(|u| !u.is_empty())
        .find_map(|u| trimmed.strip_suffix(u).map(str::trim_end))
        .unwrap_or(trimmed);
    number.parse::<f64>().map_err(|_| match unit {
        "" => format!("`{text}` is not a number"),
        _ => format!("`{text}` is not a number in {unit}: give e.g. `-0.5` or `-0.5{ascii}`"),
    })
}

#[cfg(test)]
mod tests {
    use super::{parse_in, parse_speed, split_speed_unit};

    #[test]
    fn numbers_with_or_without_their_unit() {
        assert_eq!(parse_in("-60", "m/s²"), Ok(-60.0));
        assert_eq!(parse_in("-60m/s2", "m/s²"), Ok(-60.0));
        assert_eq!(parse_in("-60 m/s²", "m/s²"), Ok(-60.0));
        assert!(parse_in("-60km/h", "m/s²").unwrap_err().contains("m/s²"));
    }

    #[test]
    fn speeds_in_m_per_s_and_km_per_h() {
        assert_eq!(parse_speed("100"), Ok(100.0));
        assert_eq!(parse_speed("100m/s"), Ok(100.0));
        assert_eq!(parse_speed("360km/h"), Ok(100.0));
        assert_eq!(parse_speed("360 km/h"), Ok(100.0));
        assert!(parse_speed("fast").unwrap_err().contains("km/h"));
        assert_eq!(split_speed_unit("140:420:20km/h"), ("140:420:20", 1.0 / 3.6));
    }
}
