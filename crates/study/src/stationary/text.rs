//! The report of the stationary wave over speeds (`frictrack stationary`'s text, JSON and CSV): a table of the peaks
//! per speed with where they are, what lies behind the load, the zones and each speed's status; one speed's JSON
//! is its point, several speeds' the list; the CSV is one speed's wave or the points over speeds.

use crate::stationary::output::{POINT_COLUMNS, StationaryStudy, WAVE_COLUMNS, points_csv, wave_csv};
use report::columns::{Column, units_line};
use report::output::{Output, pretty};
use std::fmt::{self, Formatter};

/// The stationary study of a scenario titled `title` (empty: none), as it is reported.
#[derive(Debug, Clone, Copy)]
pub struct StationaryReport<'a> {
    /// The scenario's title.
    pub title: &'a str,
    /// The points and waves.
    pub study: &'a StationaryStudy,
}

/// A table of the stationary study: its file name, CSV text and columns.
#[derive(Debug, Clone, PartialEq)]
pub struct StationaryTable {
    /// "wave.csv" for one speed's wave, "speeds.csv" for the points over speeds.
    pub name: &'static str,
    /// The CSV text.
    pub csv: String,
    /// Its columns with their units.
    pub columns: &'static [Column],
}

impl StationaryReport<'_> {
    /// One found wave's shape when the study has one speed, else the points over speeds.
    pub fn table(&self) -> StationaryTable {
        match self.study.waves.as_slice() {
            [Some(wave)] => StationaryTable { name: "wave.csv", csv: wave_csv(wave), columns: &WAVE_COLUMNS },
            _ => StationaryTable { name: "speeds.csv", csv: points_csv(&self.study.points), columns: &POINT_COLUMNS },
        }
    }
}

impl Output for StationaryReport<'_> {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let (title, study) = (self.title, self.study);
        let weight = match study.settlement > 0.0 {
            true => format!(", settled {:.3} mm by the rail's weight", study.settlement * 1e3),
            false => String::new(),
        };
        let friction = match study.friction > 0.0 {
            true => format!(", ballast friction {:.2} kN/m", study.friction / 1e3),
            false => String::new(),
        };
        writeln!(
            f,
            "stationary wave on the infinite track{}: {}F = {:.1} kN, {} soil{weight}{friction}",
            if title.is_empty() { String::new() } else { format!(" ({title})") },
            study.rail_theory.as_ref().map_or(String::new(), |t| format!("{t} rail, ")),
            study.load / 1e3,
            study.law
        )?;
        writeln!(
            f,
            "  speed (m/s)  max down (mm)  at s (m)  max up (mm)  at s (m)  max M (kN·m)  behind (mm)  lift-off zones  \
             slip zones  status"
        )?;
        // To the micrometre, without a "-0.000" for a rail left 1e-12 m below where it was.
        let mm = |x: Option<f64>| {
            x.map_or("—".to_string(), |x| format!("{:.3}", if x.abs() < 5e-7 { 0.0 } else { x * 1e3 }))
        };
        // Positions to 0.01 m, without a "-0.00" for a trough a millimetre behind the load.
        let at =
            |x: Option<f64>| x.map_or("—".to_string(), |x| format!("{:.2}", if x.abs() < 0.005 { 0.0 } else { x }));
        for p in &study.points {
            let status = match p.status {
                "converged" => String::new(),
                "not converged" => format!("not converged (residual {:.1e})", p.residual),
                other => other.to_string(),
            };
            writeln!(
                f,
                "  {:>10.2}  {:>13}  {:>8}  {:>11}  {:>8}  {:>12}  {:>11}  {:>14}  {:>10}  {status}",
                p.speed,
                mm(p.deflection.max_downward.map(|e| e.value)),
                at(p.deflection.max_downward.and_then(|e| e.position)),
                mm(p.deflection.max_upward.map(|e| e.value)),
                at(p.deflection.max_upward.and_then(|e| e.position)),
                p.max_moment.map_or("—".to_string(), |m| format!("{:.2}", m.value / 1e3)),
                mm(p.deflection_behind),
                p.lift_off_zones.len(),
                p.slip_zones.len(),
            )?;
        }
        writeln!(
            f,
            "  (s = x − vt: positive ahead of the load; deflections from the settled rail, signed behind: what is left \
             there)"
        )?;
        if let Some(note) = crate::stationary::output::branch_note(study.law) {
            writeln!(f, "  {note}")?;
        }
        if let Some((point, error)) = study.largest_error() {
            let speed = point.speed;
            writeln!(
                f,
                "  discretisation error of the peaks (deflection, moment), estimated from one halving of the elements: \
                 at most {:.2} % (at {speed} m/s)",
                100.0 * error
            )?;
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        match self.study.points.as_slice() {
            [point] => pretty(point),
            points => pretty(points),
        }
    }

    fn csv(&self) -> Option<String> {
        let table = self.table();
        Some(format!("{}# {}\n", table.csv, units_line(table.columns.iter().copied())))
    }
}
