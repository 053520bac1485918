//! `[integration] accuracy`: the tolerance a single run refines to (docs/theory.md §6.2), kept in the scenario. A
//! single run takes it out before it builds anything ([`Scenario::take_accuracy`]); every other use of the scenario —
//! a sweep, a study, a solve in the moving frame or in frequency — runs at the resolution given and refuses the key
//! by name where it builds the model, rather than run at a resolution the scenario did not ask for.

use crate::Scenario;
use crate::error::{Result, invalid};

/// Whether `tolerance` (given as `name`) is a relative error a refinement can aim at: finite, in (0, 1).
pub fn validate_tolerance(name: &str, tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0 {
        Ok(())
    } else {
        Err(invalid(name, tolerance, "a relative error in (0, 1): 0.01 asks for every outcome within 1 %"))
    }
}

impl Scenario {
    /// The scenario's `integration.accuracy`, checked, and the scenario without it (what a single run's refinement
    /// runs); None where it has none.
    pub fn take_accuracy(&mut self) -> Result<Option<f64>> {
        let Some(tolerance) = self.integration.accuracy.take() else { return Ok(None) };
        validate_tolerance("integration.accuracy", tolerance)?;
        Ok(Some(tolerance))
    }

    /// The tolerance a single run refines to: `asked` (a flag's or keyword's, with its name), else the scenario's own,
    /// both checked; the scenario's is taken out of it either way. The scenario's beside `check` (the name of a check
    /// at the resolution given) is refused: the two ask for different runs.
    pub fn take_run_tolerance(&mut self, asked: Option<(f64, &str)>, check: Option<&str>) -> Result<Option<f64>> {
        let own = self.take_accuracy()?;
        if let Some((tolerance, name)) = asked {
            validate_tolerance(name, tolerance)?;
            return Ok(Some(tolerance));
        }
        match (own, check) {
            (Some(tolerance), Some(check)) => Err(invalid(
                "integration.accuracy",
                tolerance,
                format!("asks for a refinement, and {check} for a check at the resolution given: leave out one"),
            )),
            (own, _) => Ok(own),
        }
    }

    /// Refuse `integration.accuracy` where the scenario is not a single run's (every model built keeps to its
    /// resolution).
    pub(crate) fn refuse_accuracy(&self) -> Result<()> {
        match self.integration.accuracy {
            None => Ok(()),
            Some(tolerance) => Err(invalid(
                "integration.accuracy",
                tolerance,
                "asks a single run to refine until every outcome is within it; sweeps, studies and the solves in the \
                 moving frame and in frequency run at the resolution given (check theirs with a resolution check): \
                 remove the key for them",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tolerance_is_a_relative_error_between_zero_and_one() {
        assert!(validate_tolerance("accuracy", 0.01).is_ok());
        for bad in [0.0, 1.0, -0.5, f64::NAN, f64::INFINITY] {
            assert!(validate_tolerance("accuracy", bad).unwrap_err().to_string().contains("invalid accuracy"));
        }
    }

    #[test]
    fn a_single_run_takes_the_key_and_every_model_built_with_it_is_refused_by_name() {
        let mut s = Scenario::from_toml("[integration]\naccuracy = 0.02\n", "t.toml").unwrap();
        let refused = s.model().unwrap_err().to_string();
        assert!(refused.contains("integration.accuracy = 0.02"), "{refused}");
        assert_eq!(s.take_accuracy().unwrap(), Some(0.02));
        assert!(s.model().is_ok() && s.integration.accuracy.is_none());
        let mut bad = Scenario::from_toml("[integration]\naccuracy = 1.5\n", "t.toml").unwrap();
        assert!(bad.take_accuracy().unwrap_err().to_string().contains("invalid integration.accuracy = 1.5"));
        assert!(Scenario::from_toml("[integration]\naccuracy = \"1%\"\n", "t.toml").is_err());
    }

    #[test]
    fn a_run_s_own_tolerance_gives_way_to_the_one_asked_and_not_to_a_check() {
        let scenario = Scenario::from_toml("[integration]\naccuracy = 0.02\n", "t.toml").unwrap();
        let take = |asked, check| scenario.clone().take_run_tolerance(asked, check);
        assert_eq!(take(None, None).unwrap(), Some(0.02));
        assert_eq!(take(Some((0.1, "--accuracy")), None).unwrap(), Some(0.1));
        assert!(take(Some((2.0, "--accuracy")), None).unwrap_err().to_string().contains("invalid --accuracy = 2"));
        let refused = take(None, Some("--check-resolution")).unwrap_err().to_string();
        assert!(refused.contains("integration.accuracy = 0.02") && refused.contains("--check-resolution"), "{refused}");
        assert_eq!(Scenario::default().take_run_tolerance(None, Some("--check-resolution")).unwrap(), None);
    }
}
