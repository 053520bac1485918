//! The report of the infinite beam's steady state over speeds (`frictrack analytic`'s text and JSON): the beam,
//! soil and load echoed, then the peaks per speed with where they are and the amplification over the static
//! deflection; one speed's JSON is its point, several speeds' the list.

use crate::steady_response::SteadyResponse;
use report::output::{Output, pretty};
use scenario::Scenario;
use std::fmt::{self, Formatter};

/// The steady response of `scenario`'s beam, as it is reported.
#[derive(Debug, Clone, Copy)]
pub struct SteadyReport<'a> {
    /// The scenario (its title, beam and how much of each axle the beam carries).
    pub scenario: &'a Scenario,
    /// The points over speeds.
    pub response: &'a SteadyResponse,
}

impl Output for SteadyReport<'_> {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let (scenario, response) = (self.scenario, self.response);
        let (points, train, inf, foundation) =
            (&response.points, &response.train, &response.beam, &response.foundation);
        let w0 = response.static_deflection;
        let beam = &response.rail;
        writeln!(
            f,
            "infinite {}{}, EI = {:.4} MN·m², ρA = {:.3} kg/m, k_f = {:.1} kN/m², {}, ζ = {:.4}, \
             v_cr = {:.2} m/s, static w₀ = {:.2} mm",
            scenario.beam.theory.unless_default().map_or("beam".to_string(), |t| format!("{t} beam")),
            if scenario.title.is_empty() { String::new() } else { format!(" ({})", scenario.title) },
            beam.bending_stiffness() / 1e6,
            beam.mass_per_length(),
            foundation.stiffness / 1e3,
            match &train {
                Some(t) => format!(
                    "train {} ({} axles, {:.3} m, {:.1} kN on the beam: {})",
                    t.name,
                    t.axles.len(),
                    t.length(),
                    t.total_force() / 1e3,
                    scenario.axle_share().describe()
                ),
                None => format!("F = {:.1} kN", response.load / 1e3),
            },
            foundation.damping / inf.critical_damping(),
            inf.critical_speed(),
            w0 * 1e3
        )?;
        writeln!(f, "  speed (m/s)  max down (mm)  at s (m)  max up (mm)  at s (m)   DAF down  DAF up")?;
        for p in points {
            writeln!(
                f,
                "  {:>10.2}  {:>13.3}  {:>8.2}  {:>11.3}  {:>8.2}  {:>8.3}  {:>6.3}",
                p.speed,
                p.deflection.max_downward.value * 1e3,
                p.deflection.max_downward.position.unwrap_or(f64::NAN),
                p.deflection.max_upward.value * 1e3,
                p.deflection.max_upward.position.unwrap_or(f64::NAN),
                p.amplification_downward,
                p.amplification_upward
            )?;
        }
        match &train {
            Some(_) => writeln!(f, "  (s = x − x_head: positive ahead of the first axle, axle i at s = −d_i)"),
            None => writeln!(f, "  (s = x − vt: positive ahead of the load)"),
        }
    }

    fn json(&self) -> serde_json::Result<String> {
        match self.response.points.as_slice() {
            [point] => pretty(point),
            points => pretty(points),
        }
    }
}
