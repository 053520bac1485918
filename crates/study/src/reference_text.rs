//! The report of the reference check (`frictrack reference`'s text and JSON): the FE beam against the closed forms
//! — static deflection and moment under the load, the critical speed, the natural frequencies of the pinned beam.

use crate::reference_check::ReferenceCheck;
use report::output::{Output, pretty};
use serde::Serialize;
use std::fmt::{self, Formatter};

/// The reference check and how long it took.
#[derive(Debug, Clone, Serialize)]
pub struct ReferenceReport {
    /// The FE and closed-form values.
    #[serde(flatten)]
    pub check: ReferenceCheck,
    /// Wall time (s).
    pub wall_time: f64,
}

impl Output for ReferenceReport {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let r = &self.check;
        writeln!(
            f,
            "frictrack — {}: {} m {}beam ({} ends), {} elements ({} DOFs)",
            r.title,
            r.length,
            r.rail_theory.as_ref().map_or(String::new(), |t| format!("{t} ")),
            r.supports,
            r.elements,
            r.dofs
        )?;
        writeln!(
            f,
            "static load {:.1} kN at mid-span                  FE            closed form (infinite beam)",
            r.load / 1e3
        )?;
        writeln!(
            f,
            "  deflection under the load           {:>10.3} mm   {:>10.3} mm",
            r.midspan_deflection * 1e3,
            r.midspan_deflection_closed_form * 1e3
        )?;
        writeln!(
            f,
            "  bending moment under the load       {:>10.3} kN·m {:>10.3} kN·m",
            r.midspan_moment / 1e3,
            r.midspan_moment_closed_form / 1e3
        )?;
        writeln!(
            f,
            "critical speed v_cr = {:.2} m/s ({:.0} km/h)",
            r.critical_speed,
            r.critical_speed * scenario::units::KMH
        )?;
        writeln!(f, "natural circular frequencies (pinned beam)     FE            closed form")?;
        for m in &r.modes {
            writeln!(
                f,
                "  ω{:<3}                               {:>10.4} rad/s {:>10.4} rad/s",
                m.n, m.omega, m.omega_closed_form
            )?;
        }
        writeln!(f, "wall time {:.3} s", self.wall_time)
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(self)
    }
}
