//! How the text report names the extremes window of a run: words, not numbers (the numbers are in
//! [`crate::run_summary::RunSummary`]).

use scenario::{Case, Scenario};

/// What the text report says of the extremes window, true for the run: whose position it is (the load, a train's
/// first axle, the vehicles' first wheel), why it is there (the default middle third, or given), and what lies around it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WindowWording {
    /// "load", "first axle" or "first wheel" ([`crate::run_output::position_noun`]).
    pub load: &'static str,
    /// Why the window is where it is.
    pub why: &'static str,
}

impl WindowWording {
    /// The wording of `scenario`'s window for its built `case`.
    pub fn of(scenario: &Scenario, case: &Case) -> Self {
        let load = crate::run_output::position_noun(&case.settings.moving.load);
        let span = scenario.foundation.stiffness == 0.0;
        let why = match (scenario.output.extremes_window.is_some(), span) {
            (true, _) => "the window given by [output] extremes_window or its override",
            (false, true) => "the middle third of the span",
            (false, false) => "the middle third, away from the ends: the response of a long track",
        };
        Self { load, why }
    }
}
