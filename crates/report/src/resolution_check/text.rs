//! A resolution check's lines in a run's text report: the resolutions, then each outcome's three values and the run's
//! estimated error, or why it has none.

use super::ResolutionCheck;
use super::estimate::{Convergence, Sequence};
use std::fmt::{Formatter, Result};

/// The check's lines of a run's text report.
pub(crate) fn write_check(f: &mut Formatter<'_>, c: &ResolutionCheck) -> Result {
    let resolutions: Vec<String> = c
        .resolutions
        .iter()
        .enumerate()
        .map(|(i, r)| match i == c.run {
            true => format!("{} × {} m (the run)", r.elements, r.load_advance),
            false => format!("{} × {} m ({:.2} s)", r.elements, r.load_advance, r.wall_time),
        })
        .collect();
    writeln!(f, "  resolution check: each outcome at three resolutions and the run's error (docs/theory.md §6.1)")?;
    writeln!(f, "    elements × load advance: {}", resolutions.join(", "))?;
    for o in &c.outcomes {
        let values: Vec<String> = o.values.iter().map(|v| format!("{v:.6e}")).collect();
        let verdict = match o.error {
            None => "undefined (not converging at these resolutions)".to_string(),
            Some(e) => {
                let relative = o.relative.map_or(String::new(), |r| format!(" ({:.2} %)", 100.0 * r));
                let how = match o.convergence {
                    Convergence::Settled => "settled to round-off".to_string(),
                    Convergence::Monotone { order } if Sequence(o.values).asymptotic() => {
                        format!("order {order:.2}, Richardson × 1.25")
                    }
                    Convergence::Monotone { order } => format!("order {order:.2}, 3 × the spread"),
                    _ => "alternating, 3 × the spread".to_string(),
                };
                format!("error ≈ {e:.2e} {}{relative}: {how}", o.unit)
            }
        };
        writeln!(f, "    {:<30} {} {}, {verdict}", o.name, values.join(" → "), o.unit)?;
    }
    Ok(())
}
