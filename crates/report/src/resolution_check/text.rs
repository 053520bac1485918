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
                    Convergence::Monotone { order } if order < super::estimate::MIN_ORDER => {
                        format!("order {order:.2}, the smaller of Richardson × 1.25 and 3 × the spread")
                    }
                    Convergence::Monotone { order } => format!("order {order:.2}, 3 × the spread"),
                    Convergence::Scattered { earlier } => {
                        format!("within the change from {earlier:.6e} before them (a floor), 3 × the spread")
                    }
                    _ => "alternating, 3 × the spread".to_string(),
                };
                format!("error ≈ {e:.2e} {}{relative}: {how}", o.unit)
            }
        };
        writeln!(f, "    {:<30} {} {}, {verdict}", o.name, values.join(" → "), o.unit)?;
    }
    Ok(())
}

/// The line of `run --accuracy`: reached or not, at which resolution, after how many.
pub(crate) fn write_accuracy(f: &mut Formatter<'_>, a: &super::accuracy::Accuracy) -> Result {
    let finest = a.resolutions.last().map_or(String::new(), |r| format!("{} × {} m", r.elements, r.load_advance));
    let tolerance = format!("{} %", 100.0 * a.tolerance);
    let runs = format!("{} resolutions, {:.1} s in all", a.resolutions.len(), a.wall_time);
    if let Some(law) = &a.law {
        write_law(f, law)?;
    }
    if !a.diverging.is_empty() {
        writeln!(
            f,
            "  diverging under refinement (undefined; their differences grow with each halving, left out of the \
             tolerance): {}",
            a.diverging.join(", ")
        )?;
    }
    match &a.status {
        super::accuracy::AccuracyStatus::Reached => writeln!(
            f,
            "  accuracy {tolerance}: reached at {finest} ({runs}): every outcome's estimated error is within {tolerance}"
        ),
        super::accuracy::AccuracyStatus::Interrupted { outcomes } => writeln!(
            f,
            "  accuracy {tolerance}: NOT reached — interrupted after {finest} ({runs}); above {tolerance} or \
             undefined there: {}",
            outcomes.join(", ")
        ),
        super::accuracy::AccuracyStatus::NotReached { why, outcomes } => writeln!(
            f,
            "  accuracy {tolerance}: NOT reached — stopped at {finest} ({runs}): {why}; above {tolerance} or \
             undefined: {}",
            outcomes.join(", ")
        ),
    }
}

/// The line naming the ballast friction's law a refinement ran, and why.
fn write_law(f: &mut Formatter<'_>, law: &scenario::accuracy_law::AccuracyLaw) -> Result {
    let name = match (law.subdivisions, law.quadrature) {
        (1, _) => "one section a node (J = 1)".to_string(),
        (j, scenario::QuadratureKind::Simpson) => format!("J = {j} sections an element, Simpson"),
        (j, _) => format!("J = {j} sections an element"),
    };
    let share = law.friction_share.map_or("undefined".to_string(), |r| format!("{r:.2}"));
    let limit = scenario::accuracy_law::ONE_SECTION_A_NODE_UP_TO;
    let why = match law.chosen {
        true => format!(
            "chosen for the accuracy: light friction, ρ_f = 2f_u/(βF) = {share} ≤ {limit}: as accurate as \
                         J = 4 and cheaper (a fifth to a tenth of the cost to 800 elements, half at 1600)"
        ),
        false => format!(
            "the scenario's own (ρ_f = 2f_u/(βF) = {share}; one section a node is taken only for the \
                          default law and ρ_f ≤ {limit})"
        ),
    };
    writeln!(f, "  ballast friction's law: {name}, {why}")
}

impl std::fmt::Display for super::ResolutionCheck {
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        write_check(f, self)
    }
}

#[cfg(test)]
mod tests {
    use super::super::estimate::Sequence;
    use super::super::{OutcomeCheck, Resolution, ResolutionCheck};

    fn outcome(name: &str, values: [f64; 3]) -> OutcomeCheck {
        let s = Sequence(values);
        let error = s.error_of(1);
        OutcomeCheck {
            name: name.into(),
            unit: "m",
            values,
            convergence: s.convergence(),
            error,
            relative: error.map(|e| e / values[1]),
        }
    }

    #[test]
    fn each_outcome_says_which_rule_gave_its_error_or_that_it_has_none() {
        let resolution = |elements| Resolution { elements, load_advance: 0.1, wall_time: 0.5 };
        let check = ResolutionCheck {
            resolutions: [resolution(50), resolution(100), resolution(200)],
            run: 1,
            outcomes: vec![
                outcome("first_order", [1.4, 1.2, 1.1]),
                outcome("slow", [1.0, 1.1, 1.187]),
                outcome("alternating", [1.1, 0.95, 1.025]),
                outcome("growing", [1.0, 1.1, 1.3]),
            ],
        };
        let text = check.to_string();
        let line = |name: &str| text.lines().find(|l| l.contains(name)).unwrap().to_string();
        assert!(line("first_order").ends_with("order 1.00, Richardson × 1.25"), "{text}");
        assert!(line("slow").contains("the smaller of Richardson × 1.25 and 3 × the spread"), "{text}");
        assert!(line("alternating").ends_with("alternating, 3 × the spread"), "{text}");
        assert!(line("growing").ends_with("undefined (not converging at these resolutions)"), "{text}");
        assert!(text.contains("50 × 0.1 m (0.50 s), 100 × 0.1 m (the run)"), "{text}");
    }
}
