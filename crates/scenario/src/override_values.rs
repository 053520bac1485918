//! An override's value read by its kind ([`OverrideKind`]): a number (a speed or another quantity, bare or with its
//! unit), a count, text, a solver's name, a pair; each wrong value refused by the override's name with what it takes.

use crate::error::{Result, invalid};
use crate::overrides::{OverrideKind, OverrideSpec, OverrideValue};
use crate::units::parse_speed;
use nscd::SolverKind;

impl OverrideSpec {
    /// A number (m/s for a speed, which may also be text with its unit).
    pub(crate) fn number(&self, value: &OverrideValue) -> Result<f64> {
        match (self.kind, value) {
            (_, OverrideValue::Number(x)) => Ok(*x),
            (_, OverrideValue::Count(n)) => Ok(*n as f64),
            (OverrideKind::Speed, OverrideValue::Text(t)) => parse_speed(t)
                .map_err(|_| invalid(self.name, value, "must be a speed: m/s (100, \"100m/s\") or km/h (\"360km/h\")")),
            (OverrideKind::Number { unit }, OverrideValue::Text(t)) if !unit.is_empty() => {
                crate::units::parse_in(t, unit).map_err(|_| invalid(self.name, value, self.takes()))
            }
            _ => Err(invalid(self.name, value, self.takes())),
        }
    }

    /// What the override's value must be, in words (for an error about a value of another kind).
    pub fn takes(&self) -> String {
        match self.kind {
            OverrideKind::Speed => {
                "must be a speed: a number (m/s) or text with its unit (\"100m/s\", \"360km/h\")".into()
            }
            OverrideKind::Number { unit: "" } => "must be a number".into(),
            OverrideKind::Number { unit } => {
                format!("must be a number in {unit}, or text with that unit (\"-0.5{}\")", unit.replace('²', "2"))
            }
            OverrideKind::Count => "must be a whole number ≥ 0".into(),
            OverrideKind::Text => "must be text".into(),
            OverrideKind::Solver => format!("must be one of {}", SolverKind::ALL.map(SolverKind::name).join(", ")),
            OverrideKind::Pair { unit } => format!("must be two numbers [A, B] ({unit})"),
        }
    }

    /// A whole number ≥ 0 (one beyond `usize` becomes `usize::MAX`, which the scenario's own check refuses by its
    /// path with the limit).
    pub(crate) fn count(&self, value: &OverrideValue) -> Result<usize> {
        if let OverrideValue::Count(n) = value {
            return Ok(*n);
        }
        let x = self.number(value)?;
        match x >= 0.0 && x.fract() == 0.0 {
            true => Ok(x as usize),
            false => Err(invalid(self.name, x, "must be a whole number ≥ 0")),
        }
    }

    /// Text.
    pub(crate) fn text(&self, value: &OverrideValue) -> Result<String> {
        match value {
            OverrideValue::Text(t) => Ok(t.clone()),
            other => Err(invalid(self.name, other, "must be text")),
        }
    }

    /// A solver by its name.
    pub(crate) fn solver(&self, value: &OverrideValue) -> Result<SolverKind> {
        let given = self.text(value)?;
        let names = SolverKind::ALL.map(SolverKind::name);
        given
            .parse::<SolverKind>()
            .map_err(|_| invalid(self.name, &given, format!("must be one of {}", names.join(", "))))
    }

    /// Two numbers.
    pub(crate) fn pair(&self, value: &OverrideValue) -> Result<[f64; 2]> {
        match value {
            OverrideValue::Pair(pair) => Ok(*pair),
            other => Err(invalid(self.name, other, "must be two load positions [A, B] (m)")),
        }
    }
}
