//! Where a result folder came from: the command line that wrote it, frictrack's version and commit, and when (UTC).
//! Written into a run's `summary.json` and a study's `<study>.json` under the same names, so that `frictrack report`
//! can say how to reproduce either.

use serde::Serialize;
use std::time::{SystemTime, UNIX_EPOCH};

/// The command, version, commit and date of a result, flattened into the JSON that holds it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Provenance {
    /// The version that wrote it.
    pub frictrack_version: &'static str,
    /// The git commit frictrack was built from, where the build knew it (a wheel built from an sdist does not).
    pub git_revision: Option<String>,
    /// The command line as a shell takes it (`frictrack run case.toml --speed 180`), or the Python call.
    pub command: String,
    /// When it was written, UTC, ISO 8601 to the second (`2026-11-30T06:40:12Z`).
    pub date: String,
}

impl Provenance {
    /// The provenance of a result written now by `command`, from a build at `commit`.
    pub fn now(command: String, commit: Option<&str>) -> Self {
        Self {
            frictrack_version: env!("CARGO_PKG_VERSION"),
            git_revision: commit.map(str::to_string),
            command,
            date: utc_now(),
        }
    }
}

/// This instant, UTC, as [`utc_date_time`] writes it.
pub fn utc_now() -> String {
    utc_date_time(SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs()))
}

/// A command line's arguments as one line a shell runs again: an argument with anything but letters, digits and
/// `-_./:=,+@%` is single-quoted.
pub fn shell_line(args: &[String]) -> String {
    let quote = |arg: &String| {
        if !arg.is_empty() && arg.chars().all(|c| c.is_ascii_alphanumeric() || "-_./:=,+@%".contains(c)) {
            arg.clone()
        } else {
            format!("'{}'", arg.replace('\'', "'\\''"))
        }
    };
    args.iter().map(quote).collect::<Vec<_>>().join(" ")
}

/// `seconds` after 1970-01-01T00:00:00Z as `YYYY-MM-DDThh:mm:ssZ` (proleptic Gregorian calendar; the civil-from-days
/// algorithm of H. Hinnant, "chrono-Compatible Low-Level Date Algorithms", valid for every u64 second count here).
pub fn utc_date_time(seconds: u64) -> String {
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let day_of_era = z - era * 146_097;
    let year_of_era = (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let shifted_month = (5 * day_of_year + 2) / 153;
    let day = day_of_year - (153 * shifted_month + 2) / 5 + 1;
    let month = if shifted_month < 10 { shifted_month + 3 } else { shifted_month - 9 };
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    let (hour, minute, second) = (rest / 3600, rest % 3600 / 60, rest % 60);
    format!("{year:04}-{month:02}-{day:02}T{hour:02}:{minute:02}:{second:02}Z")
}

#[cfg(test)]
mod tests {
    use super::{shell_line, utc_date_time};

    #[test]
    fn a_command_line_is_quoted_where_a_shell_needs_it() {
        let args = ["frictrack", "run", "my case.toml", "--speed", "288km/h", "--title", "it's"].map(String::from);
        assert_eq!(shell_line(&args), "frictrack run 'my case.toml' --speed 288km/h --title 'it'\\''s'");
    }

    #[test]
    fn dates_match_known_instants() {
        assert_eq!(utc_date_time(0), "1970-01-01T00:00:00Z");
        // `date -u -d @951782400`: the leap day of a year divisible by 400.
        assert_eq!(utc_date_time(951_782_400), "2000-02-29T00:00:00Z");
        // `date -u -d @4107542399`: the last second of 2100, not a leap year.
        assert_eq!(utc_date_time(4_133_980_799), "2100-12-31T23:59:59Z");
        assert_eq!(utc_date_time(1_796_020_812), "2026-11-30T06:40:12Z");
    }
}
