//! How the text report names the extremes window of a run: words, not numbers (the numbers are in
//! [`report::run_summary::RunSummary`]).

use scenario::{Case, Scenario};

/// What the text report says of the extremes window, true for the run: whose position it is (the load, a train's
/// first axle, the vehicles' first wheel), why it is there (the default middle third, or given), and what lies around it.
#[derive(Debug, Default)]
pub(crate) struct WindowWording {
    /// "load", "first axle" or "first wheel" ([`report::run_output::position_noun`]).
    pub(crate) load: &'static str,
    /// Why the window is where it is.
    pub(crate) why: &'static str,
}

impl WindowWording {
    pub(crate) fn of(scenario: &Scenario, case: &Case) -> Self {
        let load = report::run_output::position_noun(&case.settings.moving.load);
        let span = scenario.foundation.stiffness == 0.0;
        let why = match (scenario.output.extremes_window.is_some(), span) {
            (true, _) => "the window given by [output] extremes_window or --extremes-window",
            (false, true) => "the middle third of the span",
            (false, false) => "the middle third, away from the ends: the response of a long track",
        };
        Self { load, why }
    }
}
